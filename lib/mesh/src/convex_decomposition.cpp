// Convex decomposition through HACD, hulls through Qhull, and the on-disk cache
// (gjkx/mesh/convex_decomposition.hpp).
#include <gjkx/mesh/convex_decomposition.hpp>

#include <gjkx/support_mapping/convex_hull.hpp>

#include <Eigen/Geometry>

#include <HACD/hacdHACD.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <set>
#include <cstdlib>
#include <sstream>
#include <stdexcept>

#include <unistd.h>

namespace gjkx {
namespace {

// Bump when the cache file's layout or the way pieces are built changes.
constexpr int kCacheVersion = 1;

struct Fnv1a {
  std::uint64_t value = 1469598103934665603ull;
  void add(const void* data, size_t size) {
    const auto* bytes = static_cast<const unsigned char*>(data);
    for (size_t i = 0; i < size; ++i) {
      value ^= bytes[i];
      value *= 1099511628211ull;
    }
  }
  template <typename T>
  void add(const T& x) {
    add(&x, sizeof(T));
  }
};

std::string hex(std::uint64_t key) {
  char text[17];
  std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(key));
  return text;
}

// The cache file: a text header, then each piece's hull vertices at full precision
// (%.17g reads back to the same double), then the partition.
void writeCache(const std::string& file, const ConvexDecomposition& d) {
  // A name of this process's own: two programs filling the cache at once never share one.
  const std::string temporary = file + ".tmp" + std::to_string(::getpid());
  {
    std::ofstream out(temporary);
    if (!out) return;  // a cache that cannot be written costs only time
    out << "gjkx-pieces " << kCacheVersion << "\n" << d.pieces.size() << " " << d.pieceOfTriangle.size() << "\n";
    char number[40];
    for (const auto& piece : d.pieces) {
      out << piece.size() << "\n";
      for (const auto& p : piece) {
        for (int k = 0; k < 3; ++k) {
          std::snprintf(number, sizeof number, "%.17g", p[k]);
          out << number << (k < 2 ? ' ' : '\n');
        }
      }
    }
    for (int piece : d.pieceOfTriangle) out << piece << "\n";
  }
  std::error_code error;
  std::filesystem::rename(temporary, file, error);  // atomic: a reader never sees half a file
}

bool readCache(const std::string& file, ConvexDecomposition& d, size_t triangleCount) {
  std::ifstream in(file);
  if (!in) return false;
  std::string magic;
  int version = 0;
  size_t pieces = 0, triangles = 0;
  if (!(in >> magic >> version >> pieces >> triangles) || magic != "gjkx-pieces" || version != kCacheVersion ||
      triangles != triangleCount)
    return false;
  d.pieces.assign(pieces, {});
  for (auto& piece : d.pieces) {
    size_t n = 0;
    if (!(in >> n) || n < 4) return false;
    piece.resize(n);
    for (auto& p : piece)
      if (!(in >> p.x() >> p.y() >> p.z()) || !p.allFinite()) return false;
  }
  d.pieceOfTriangle.resize(triangles);
  for (int& piece : d.pieceOfTriangle)
    if (!(in >> piece) || piece < 0 || piece >= static_cast<int>(pieces)) return false;
  return true;
}

// The hull of a cluster's vertices; a flat cluster (all in one plane) is thickened along
// its normal by `thickness` so that it keeps a solid hull.
std::vector<Eigen::Vector3d> clusterHull(std::vector<Eigen::Vector3d> points, const Eigen::Vector3d& normal,
                                         double thickness) {
  try {
    return convexHull3d(points, "piece").vertices;
  } catch (const std::invalid_argument&) {
    const size_t n = points.size();
    for (size_t i = 0; i < n; ++i) points.push_back(points[i] - thickness * normal);
    return convexHull3d(points, "piece").vertices;
  }
}

}  // namespace

void DecompositionSettings::validate() const {
  auto positive = [](double value, const char* field) {
    if (!std::isfinite(value) || !(value > 0))
      throw std::invalid_argument(std::string("decomposition.") + field + ": must be finite and positive");
  };
  if (minClusters < 1) throw std::invalid_argument("decomposition.minClusters: must be at least 1");
  if (maxVerticesPerHull < 4) throw std::invalid_argument("decomposition.maxVerticesPerHull: must be at least 4");
  positive(concavity, "concavity");
  positive(scale, "scale");
  if (!std::isfinite(compacityWeight) || compacityWeight < 0)
    throw std::invalid_argument("decomposition.compacityWeight: must be finite and not negative");
  if (!std::isfinite(volumeWeight) || volumeWeight < 0)
    throw std::invalid_argument("decomposition.volumeWeight: must be finite and not negative");
}

std::string defaultDecompositionCacheDir() {
  if (const char* chosen = std::getenv("GJKX_MESH_CACHE")) return chosen;
  if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg) return std::string(xdg) + "/gjkx";
  if (const char* home = std::getenv("HOME"); home && *home) return std::string(home) + "/.cache/gjkx";
  return "";
}

std::uint64_t decompositionKey(const TriangleMesh& mesh, const DecompositionSettings& s) {
  Fnv1a h;
  h.add(kCacheVersion);
  h.add(mesh.vertices.size());
  for (const auto& v : mesh.vertices) h.add(v.data(), 3 * sizeof(double));
  h.add(mesh.triangles.size());
  for (const auto& t : mesh.triangles) h.add(t.data(), 3 * sizeof(int));
  h.add(s.minClusters);
  h.add(s.concavity);
  h.add(s.scale);
  h.add(s.maxVerticesPerHull);
  h.add(s.compacityWeight);
  h.add(s.volumeWeight);
  h.add(s.addExtraDistPoints);
  h.add(s.addFacesPoints);
  return h.value;
}

double hullVolume(const std::vector<Eigen::Vector3d>& points) {
  const ConvexHull hull = convexHull3d(points, "hull");
  double volume = 0;
  const Eigen::Vector3d c = hull.vertices[0];
  for (const auto& t : hull.triangles)
    volume += (hull.vertices[t[0]] - c).dot((hull.vertices[t[1]] - c).cross(hull.vertices[t[2]] - c)) / 6.0;
  return volume;
}

ConvexDecomposition decompose(const TriangleMesh& mesh, const DecompositionSettings& settings,
                              const std::string& cacheDir) {
  settings.validate();
  validateMesh(mesh, MeshRequirements{false});
  ConvexDecomposition d;
  std::string cacheFile;
  if (!cacheDir.empty()) {
    std::error_code error;
    std::filesystem::create_directories(cacheDir, error);
    if (::access(cacheDir.c_str(), W_OK) == 0) {
      cacheFile = (std::filesystem::path(cacheDir) / (hex(decompositionKey(mesh, settings)) + ".pieces")).string();
    } else {  // read-only or missing: no cache, said once
      static bool warned = false;
      if (!warned) std::fprintf(stderr, "gjkx: the mesh cache folder %s cannot be written: decompositions are not cached\n", cacheDir.c_str());
      warned = true;
    }
  }
  if (!cacheFile.empty() && readCache(cacheFile, d, mesh.triangles.size())) {
    d.report.fromCache = true;
  } else {
    d = ConvexDecomposition{};
    const auto start = std::chrono::steady_clock::now();
    // HACD scales and shifts its input points in place (NormalizeData), so it gets copies.
    std::vector<HACD::Vec3<HACD::Real>> points;
    std::vector<HACD::Vec3<long>> triangles;
    for (const auto& v : mesh.vertices) points.emplace_back(v.x(), v.y(), v.z());
    for (const auto& t : mesh.triangles) triangles.emplace_back(t[0], t[1], t[2]);
    HACD::HACD hacd;
    hacd.SetPoints(points.data());
    hacd.SetNPoints(points.size());
    hacd.SetTriangles(triangles.data());
    hacd.SetNTriangles(triangles.size());
    hacd.SetCompacityWeight(settings.compacityWeight);
    hacd.SetVolumeWeight(settings.volumeWeight);
    hacd.SetNClusters(static_cast<size_t>(settings.minClusters));
    hacd.SetNVerticesPerCH(static_cast<size_t>(settings.maxVerticesPerHull));
    hacd.SetConcavity(settings.concavity);
    hacd.SetScaleFactor(settings.scale);
    hacd.SetAddExtraDistPoints(settings.addExtraDistPoints);
    hacd.SetAddNeighboursDistPoints(false);
    hacd.SetAddFacesPoints(settings.addFacesPoints);
    hacd.SetConnectDist(30.0);
    if (!hacd.Compute())
      throw std::runtime_error(mesh.source + ": HACD could not decompose the mesh");
    const long* partition = hacd.GetPartition();
    // HACD's cluster labels are sparse; renumber them 0..k-1 in order of first appearance.
    std::map<long, int> label;
    d.pieceOfTriangle.resize(mesh.triangles.size());
    for (size_t t = 0; t < mesh.triangles.size(); ++t) {
      auto [it, inserted] = label.emplace(partition[t], static_cast<int>(label.size()));
      (void)inserted;
      d.pieceOfTriangle[t] = it->second;
    }
    Eigen::Vector3d lo = mesh.vertices[0], hi = mesh.vertices[0];
    for (const auto& v : mesh.vertices) {
      lo = lo.cwiseMin(v);
      hi = hi.cwiseMax(v);
    }
    const double thickness = 1e-6 * (hi - lo).norm();
    std::vector<std::set<int>> members(label.size());
    std::vector<Eigen::Vector3d> normals(label.size(), Eigen::Vector3d::Zero());
    for (size_t t = 0; t < mesh.triangles.size(); ++t) {
      const auto& tri = mesh.triangles[t];
      const int piece = d.pieceOfTriangle[t];
      members[piece].insert(tri.begin(), tri.end());
      normals[piece] += (mesh.vertices[tri[1]] - mesh.vertices[tri[0]]).cross(mesh.vertices[tri[2]] - mesh.vertices[tri[0]]);
    }
    for (size_t piece = 0; piece < members.size(); ++piece) {
      std::vector<Eigen::Vector3d> cluster;
      for (int v : members[piece]) cluster.push_back(mesh.vertices[v]);
      const Eigen::Vector3d normal = normals[piece].norm() > 0 ? normals[piece].normalized() : Eigen::Vector3d::UnitZ();
      d.pieces.push_back(clusterHull(cluster, normal, thickness));
    }
    d.report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (!cacheFile.empty()) writeCache(cacheFile, d);
  }
  d.report.cacheFile = cacheFile;
  d.report.pieces = static_cast<int>(d.pieces.size());
  d.report.meshClosed = true;
  try {
    validateMesh(mesh, MeshRequirements{true});
  } catch (const std::invalid_argument&) {
    d.report.meshClosed = false;
  }
  d.report.meshVolume = std::abs(enclosedVolume(mesh));  // OFF and STL copies of one mesh may face opposite ways
  d.report.hullVolume = 0;
  for (const auto& piece : d.pieces) {
    d.report.verticesPerPiece.push_back(static_cast<int>(piece.size()));
    d.report.hullVolume += hullVolume(piece);
  }
  d.report.volumeExcess = d.report.meshVolume > 0 ? (d.report.hullVolume - d.report.meshVolume) / d.report.meshVolume
                                                  : std::numeric_limits<double>::quiet_NaN();
  return d;
}

}  // namespace gjkx
