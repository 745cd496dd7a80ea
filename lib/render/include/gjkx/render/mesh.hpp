/// @file
/// @brief Triangle meshes drawn in the paper's 3D figures (polytopes, pieces, bones).
#pragma once

#include <Eigen/Core>

#include <array>
#include <utility>
#include <vector>

namespace gjkx::render {

/// A triangle mesh: vertex positions and triangles as triples of vertex indices (either
/// winding; shading is two-sided).
struct Mesh {
  std::vector<Eigen::Vector3d> vertices;      ///< Vertex positions in world coordinates.
  std::vector<std::array<int, 3>> triangles;  ///< Triangles as indices into vertices.
};

/// The feature edges of @p mesh as (smaller, larger) vertex indices: edges of one triangle
/// only, and edges whose two triangles meet at more than @p angleDegrees. For a
/// triangulated polytope these are its true edges (the diagonals of flat faces are left
/// out). Throws std::invalid_argument if a triangle index is out of range.
std::vector<std::pair<int, int>> featureEdges(const Mesh& mesh, double angleDegrees = 1.0);

/// Throws std::invalid_argument naming the triangle if one refers to a missing vertex.
void validateMesh(const Mesh& mesh);

}  // namespace gjkx::render
