/// @file
/// @brief Triangle meshes drawn in the paper's 3D figures (polytopes, boxes).
#pragma once

#include <Eigen/Core>

#include <array>
#include <utility>
#include <vector>

namespace gjkx::render {

/// A triangle mesh: vertex positions and triangles as triples of vertex
/// indices. The 3D figures draw convex polytopes (bodies P and Q, V_Q - V_P)
/// as such meshes; the winding of the triangles does not matter (shading is
/// two-sided).
struct Mesh {
  std::vector<Eigen::Vector3d> vertices;     ///< Vertex positions in world coordinates.
  std::vector<std::array<int, 3>> triangles;  ///< Triangles as indices into vertices.
};

/// An axis-aligned box with corners @p lo and @p hi as 12 outward-facing
/// triangles (a test body of the 3D figures). Throws std::invalid_argument if
/// lo is not below hi in every coordinate.
/// @param lo The corner with the smallest coordinates.
/// @param hi The corner with the largest coordinates.
/// @return The box mesh.
Mesh makeBox(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi);

/// The feature edges of @p mesh as pairs of vertex indices: edges of only one
/// triangle, and edges whose two triangles meet at an angle above
/// @p angleDegrees. For a triangulated polytope these are the polytope's true
/// edges (the diagonals of flat faces are left out), as drawn in the 3D figures.
/// Throws std::invalid_argument if a triangle index is out of range.
/// @param mesh The mesh.
/// @param angleDegrees Smallest dihedral bend (in degrees) that counts as an edge.
/// @return The feature edges, each as (smaller, larger) vertex index.
std::vector<std::pair<int, int>> featureEdges(const Mesh& mesh, double angleDegrees = 1.0);

/// Throws std::invalid_argument if a triangle of @p mesh refers to a missing
/// vertex; the Canvas checks every mesh of a 3D figure with it.
/// @param mesh The mesh to check.
void validateMesh(const Mesh& mesh);

}  // namespace gjkx::render
