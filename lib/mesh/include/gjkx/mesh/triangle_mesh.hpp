/// @file
/// @brief Triangle meshes read the way users have them (OBJ, OFF, PLY, STL), validated where they enter (§6).
///
/// §6 runs on nonconvex bones and a nonconvex plant given as triangulated surfaces.
/// Reading the file formats is not the subject of the paper, so a kept library (Assimp)
/// reads them; this stage only checks what it got, so that a bad file fails here, with
/// the file's name and what is wrong, and never later as a NaN or a crash in GJK.
#pragma once

#include <Eigen/Core>

#include <array>
#include <string>
#include <vector>

namespace gjkx {

/// A triangle mesh: shared vertices and triangles indexing them (counter-clockwise seen
/// from outside for a closed surface).
struct TriangleMesh {
  /// The vertices (welded: two vertices never share a position after `readMesh`).
  std::vector<Eigen::Vector3d> vertices;
  /// The triangles, three indices into `vertices` each.
  std::vector<std::array<int, 3>> triangles;
  /// Triangles of the file left out because their corners coincide (no area); see `readMesh`.
  int droppedTriangles = 0;
  /// Where it came from (a file name, or a name given by the caller), used in error messages.
  std::string source;
};

/// What a mesh must satisfy to be accepted.
struct MeshRequirements {
  /// A closed surface: every edge is shared by exactly two triangles (needed for a volume,
  /// hence for the volume excess of a decomposition and for mass properties).
  bool closed = false;
  /// Apply the file's node transforms to its meshes (Assimp's pre-transform: a file whose
  /// parts are placed, scaled or turned by its scene graph comes in as it is drawn). Off
  /// by default, so that the project's own figures read their meshes as they always did.
  bool applyNodeTransforms = false;
};

/// Reads a triangle mesh from an OBJ, OFF, PLY or STL file (any format Assimp reads).
/// All meshes of the file are merged; polygons are triangulated; vertices at the same
/// position are welded, and triangles whose corners then coincide (no area) are left out
/// and counted in `droppedTriangles`. Throws std::runtime_error naming the file when it cannot be read
/// (missing, empty, not a mesh format Assimp understands), and std::invalid_argument
/// naming the file and the fault when its content is wrong (see `validateMesh`).
TriangleMesh readMesh(const std::string& path, const MeshRequirements& requirements = {});

/// Checks a mesh, throwing std::invalid_argument "<source>: <what is wrong>" for: no
/// vertices or no triangles, a coordinate that is not finite (vertex index given), a
/// triangle index out of range (triangle and index given), and, when
/// `requirements.closed`, an edge not shared by exactly two triangles (the edge given).
/// Degenerate triangles (two equal indices) are rejected as well.
void validateMesh(const TriangleMesh& mesh, const MeshRequirements& requirements = {});

/// The signed volume enclosed by a closed, outward-oriented mesh (divergence theorem:
/// the sum over triangles of \f$\frac16\,a\cdot(b\times c)\f$, corners taken relative to the
/// vertices' centroid). For an open mesh: the volume of the cones from the centroid.
double enclosedVolume(const TriangleMesh& mesh);

}  // namespace gjkx
