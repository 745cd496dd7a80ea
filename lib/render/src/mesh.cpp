// Triangle meshes of the 3D figures: their check and their feature edges.
#include <gjkx/render/mesh.hpp>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>
#include <string>

namespace gjkx::render {

void validateMesh(const Mesh& mesh) {
  const int n = static_cast<int>(mesh.vertices.size());
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
    for (int i : mesh.triangles[t])
      if (i < 0 || i >= n)
        throw std::invalid_argument("Mesh: triangle " + std::to_string(t) + " refers to vertex " + std::to_string(i) +
                                    " of " + std::to_string(n));
}

std::vector<std::pair<int, int>> featureEdges(const Mesh& mesh, double angleDegrees) {
  validateMesh(mesh);
  // Normal of each triangle at an edge, flipped so that both triangles of an
  // edge are oriented consistently (they then traverse it in opposite senses).
  std::map<std::pair<int, int>, std::vector<Eigen::Vector3d>> normals;
  for (const auto& t : mesh.triangles) {
    const Eigen::Vector3d& a = mesh.vertices[static_cast<std::size_t>(t[0])];
    const Eigen::Vector3d& b = mesh.vertices[static_cast<std::size_t>(t[1])];
    const Eigen::Vector3d& c = mesh.vertices[static_cast<std::size_t>(t[2])];
    Eigen::Vector3d n = (b - a).cross(c - a);
    if (n.norm() > 0.0) n.normalize();
    for (int k = 0; k < 3; ++k) {
      const int u = t[static_cast<std::size_t>(k)], v = t[static_cast<std::size_t>((k + 1) % 3)];
      if (u != v) normals[{std::min(u, v), std::max(u, v)}].push_back(u < v ? n : Eigen::Vector3d(-n));
    }
  }
  const double cosLimit = std::cos(angleDegrees * 3.14159265358979323846 / 180.0);
  std::vector<std::pair<int, int>> edges;
  for (const auto& [edge, ns] : normals) {
    bool feature = ns.size() != 2;
    // Consistent windings traverse the edge in opposite senses: one normal got flipped above.
    if (!feature) feature = -ns[0].dot(ns[1]) < cosLimit;
    if (feature) edges.push_back(edge);
  }
  return edges;
}

}  // namespace gjkx::render
