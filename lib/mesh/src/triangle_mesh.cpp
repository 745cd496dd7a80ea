// Triangle meshes through Assimp, checked where they enter (gjkx/mesh/triangle_mesh.hpp).
#include <gjkx/mesh/triangle_mesh.hpp>

#include <Eigen/Geometry>

#include <assimp/cimport.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <string>

namespace gjkx {
namespace {

[[noreturn]] void invalid(const std::string& source, const std::string& what) {
  throw std::invalid_argument(source + ": " + what);
}

std::string show(const Eigen::Vector3d& p) {
  return "(" + std::to_string(p.x()) + ", " + std::to_string(p.y()) + ", " + std::to_string(p.z()) + ")";
}

// Assimp reports some faults of the content itself (an index past the vertex list, seen by
// its validation step) as a failure to read. Those are the caller's data, not a missing
// reader, so they get the same kind of error as our own checks.
bool assimpSaysIndexOutOfRange(const std::string& message) {
  return message.find("out of range") != std::string::npos || message.find("Invalid index") != std::string::npos;
}

// Some of Assimp's readers repair a bad file silently but say so in the log: the OFF reader
// clamps a face index past the vertex list to the last vertex and logs "Vertex index out of
// range". We listen to the log while reading, so that such a file is refused instead.
std::mutex logMutex;
std::string* logSink = nullptr;
void collectLog(const char* message, char* /*user*/) {
  if (logSink) logSink->append(message);
}

}  // namespace

TriangleMesh readMesh(const std::string& path, const MeshRequirements& requirements) {
  {
    std::ifstream file(path, std::ios::binary | std::ios::ate);
    if (!file) throw std::runtime_error(path + ": cannot open the file");
    if (file.tellg() == 0) invalid(path, "the file is empty");
  }
  // Triangulate polygons; ValidateDataStructure first, so that a face index past the
  // vertex list is caught before any other step reads through it. No vertex welding by
  // Assimp: we weld across all meshes of the file below, by exact position.
  const unsigned flags = aiProcess_ValidateDataStructure | aiProcess_Triangulate | aiProcess_SortByPType |
                         (requirements.applyNodeTransforms ? unsigned(aiProcess_PreTransformVertices) : 0u);
  std::string log;
  const aiScene* imported = nullptr;
  {
    std::lock_guard<std::mutex> lock(logMutex);
    aiLogStream stream{collectLog, nullptr};
    logSink = &log;
    aiAttachLogStream(&stream);
    imported = aiImportFile(path.c_str(), flags);
    aiDetachLogStream(&stream);
    logSink = nullptr;
  }
  std::unique_ptr<const aiScene, void (*)(const aiScene*)> scene(imported, [](const aiScene* s) { aiReleaseImport(s); });
  if (scene && log.find("out of range") != std::string::npos) {
    const size_t at = log.find("out of range");
    const size_t begin = log.rfind('\n', at);
    const size_t end = log.find('\n', at);
    invalid(path, "a face index is out of range (Assimp: " +
                      log.substr(begin == std::string::npos ? 0 : begin + 1,
                                 (end == std::string::npos ? log.size() : end) - (begin == std::string::npos ? 0 : begin + 1)) +
                      ")");
  }
  if (!scene) {
    const std::string message = aiGetErrorString();
    if (assimpSaysIndexOutOfRange(message)) invalid(path, "a face index is out of range (Assimp: " + message + ")");
    throw std::runtime_error(path + ": Assimp could not read it: " + message);
  }
  TriangleMesh mesh;
  mesh.source = path;
  // Weld by exact position, so that formats storing each triangle's corners apart (STL)
  // give a connected surface whose closure can be checked.
  std::map<std::array<double, 3>, int> indexOf;
  for (unsigned m = 0; m < scene->mNumMeshes; ++m) {
    const aiMesh* part = scene->mMeshes[m];
    std::vector<int> welded(part->mNumVertices);
    for (unsigned v = 0; v < part->mNumVertices; ++v) {
      const aiVector3D& p = part->mVertices[v];
      const Eigen::Vector3d point(p.x, p.y, p.z);
      if (!point.allFinite())
        invalid(path, "vertex " + std::to_string(v) + " of mesh " + std::to_string(m) + " has a coordinate that is not finite " +
                          show(point));
      const std::array<double, 3> key{point.x(), point.y(), point.z()};
      auto [it, inserted] = indexOf.emplace(key, static_cast<int>(mesh.vertices.size()));
      if (inserted) mesh.vertices.push_back(point);
      welded[v] = it->second;
    }
    for (unsigned f = 0; f < part->mNumFaces; ++f) {
      const aiFace& face = part->mFaces[f];
      if (face.mNumIndices != 3) continue;  // points and lines (SortByPType keeps them apart)
      std::array<int, 3> tri{};
      for (int k = 0; k < 3; ++k) {
        const unsigned index = face.mIndices[k];
        if (index >= part->mNumVertices)
          invalid(path, "face " + std::to_string(f) + " of mesh " + std::to_string(m) + " has index " +
                            std::to_string(index) + ", out of range (" + std::to_string(part->mNumVertices) +
                            " vertices)");
        tri[k] = welded[index];
      }
      // A triangle whose corners weld to fewer than three vertices has no area and no
      // edges to share; real files have them (Assimp's Spider.stl), so it is left out, counted.
      if (tri[0] == tri[1] || tri[1] == tri[2] || tri[0] == tri[2]) {
        ++mesh.droppedTriangles;
        continue;
      }
      mesh.triangles.push_back(tri);
    }
  }
  validateMesh(mesh, requirements);
  return mesh;
}

void validateMesh(const TriangleMesh& mesh, const MeshRequirements& requirements) {
  const std::string& source = mesh.source.empty() ? std::string("mesh") : mesh.source;
  if (mesh.vertices.empty()) invalid(source, "the mesh has no vertices");
  if (mesh.triangles.empty()) invalid(source, "the mesh has no triangles");
  for (size_t v = 0; v < mesh.vertices.size(); ++v)
    if (!mesh.vertices[v].allFinite())
      invalid(source, "vertex " + std::to_string(v) + " has a coordinate that is not finite " + show(mesh.vertices[v]));
  const int n = static_cast<int>(mesh.vertices.size());
  for (size_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto& tri = mesh.triangles[t];
    for (int k = 0; k < 3; ++k)
      if (tri[k] < 0 || tri[k] >= n)
        invalid(source, "triangle " + std::to_string(t) + " has index " + std::to_string(tri[k]) + ", out of range (" +
                            std::to_string(n) + " vertices)");
    if (tri[0] == tri[1] || tri[1] == tri[2] || tri[0] == tri[2])
      invalid(source, "triangle " + std::to_string(t) + " repeats a vertex (" + std::to_string(tri[0]) + ", " +
                          std::to_string(tri[1]) + ", " + std::to_string(tri[2]) + ")");
  }
  if (!requirements.closed) return;
  // A closed (watertight, manifold) surface: every undirected edge lies on exactly two
  // triangles, and they run along it in opposite directions (consistent orientation).
  std::map<std::pair<int, int>, std::pair<int, int>> edges;  // (min, max) -> (a->b count, b->a count)
  for (const auto& tri : mesh.triangles)
    for (int k = 0; k < 3; ++k) {
      const int a = tri[k], b = tri[(k + 1) % 3];
      auto& count = edges[{std::min(a, b), std::max(a, b)}];
      (a < b ? count.first : count.second) += 1;
    }
  for (const auto& [edge, count] : edges) {
    const int total = count.first + count.second;
    if (total != 2)
      invalid(source, "the mesh is not closed: edge (" + std::to_string(edge.first) + ", " + std::to_string(edge.second) +
                          ") between " + show(mesh.vertices[edge.first]) + " and " + show(mesh.vertices[edge.second]) +
                          " lies on " + std::to_string(total) + " triangle(s), a closed surface needs 2");
    if (count.first != 1)
      invalid(source, "the mesh is not consistently oriented: edge (" + std::to_string(edge.first) + ", " +
                          std::to_string(edge.second) + ") is run the same way by both its triangles");
  }
}

double enclosedVolume(const TriangleMesh& mesh) {
  // About the vertices' centroid c rather than the origin: the same for a closed mesh,
  // less round-off far from the origin, and independent of the frame for an open one.
  Eigen::Vector3d c = Eigen::Vector3d::Zero();
  for (const auto& v : mesh.vertices) c += v;
  c /= double(mesh.vertices.size());
  double volume = 0;
  for (const auto& tri : mesh.triangles) {
    const Eigen::Vector3d a = mesh.vertices[tri[0]] - c;
    volume += a.dot((mesh.vertices[tri[1]] - c).cross(mesh.vertices[tri[2]] - c)) / 6.0;
  }
  return volume;
}

}  // namespace gjkx
