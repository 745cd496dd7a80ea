// Convex decomposition through HACD, hulls through Qhull, and the on-disk cache
// (gjkx/mesh/convex_decomposition.hpp).
#include <gjkx/mesh/convex_decomposition.hpp>

#include <gjkx/mesh/forked_worker.hpp>
#include <gjkx/support_mapping/convex_hull.hpp>

#include <Eigen/Geometry>

#include <HACD/hacdHACD.h>

#include <algorithm>
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
#include <string_view>
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

// The worker's side of the decomposition. HACD's call-back (a plain function pointer, so
// its state is the worker process's own globals) turns HACD's messages into progress lines
// "p <phase> <fraction>" on the pipe, at most twenty a second. HACD says where it is by
// the text of its message (hacdHACD.cpp): "+ InitializeDualGraph" once per triangle f with
// (f, triangles), "+ Initializing Priority Queue" before it costs every merge, "<percent>
// %% V = ..." as it merges, with the share of triangles merged away in percent, and
// "+ Computing final convex-hulls" at the end. Its answer is ignored (HACD never stops).
int gProgressFd = -1;
std::chrono::steady_clock::time_point gLastProgress;
const char* gLastPhase = nullptr;

bool sayProgress(const char* message, double progress, double total, size_t) {
  const char* phase = nullptr;
  double fraction = 0;
  if (std::strncmp(message, "+ InitializeDualGraph", 21) == 0) {
    phase = "graph";
    fraction = total > 0 ? progress / total : 0;
  } else if (std::strncmp(message, "+ Initializing Priority Queue", 29) == 0) {
    phase = "costs";
  } else if (std::strncmp(message, "+ Simplification", 16) == 0) {
    phase = "merging";
  } else if (message[0] == ' ' || (message[0] >= '0' && message[0] <= '9')) {
    phase = "merging";
    fraction = progress / 100;
  } else if (std::strncmp(message, "+ Computing final convex-hulls", 30) == 0) {
    phase = "hulls";
  } else {
    return true;
  }
  const auto now = std::chrono::steady_clock::now();
  if (phase == gLastPhase && now - gLastProgress < std::chrono::milliseconds(50)) return true;
  gLastPhase = phase;
  gLastProgress = now;
  char line[64];
  const int n = std::snprintf(line, sizeof line, "p %s %.4f\n", phase, std::clamp(fraction, 0.0, 1.0));
  writeAll(gProgressFd, line, std::size_t(n));
  return true;
}

// Runs HACD on `mesh` in the worker and writes its partition to `fd` as one line
// "r <labels...>"; exit status 0, or 1 with a line "e <why>" when HACD refuses.
int hacdWorker(const TriangleMesh& mesh, const DecompositionSettings& settings, int fd) {
  gProgressFd = fd;
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
  hacd.SetCallBack(&sayProgress);
  if (!hacd.Compute()) {
    const char refused[] = "e HACD could not decompose the mesh\n";
    writeAll(fd, refused, sizeof refused - 1);
    return 1;
  }
  const long* partition = hacd.GetPartition();
  std::string line = "r";
  for (size_t t = 0; t < mesh.triangles.size(); ++t) line += " " + std::to_string(partition[t]);
  line += "\n";
  return writeAll(fd, line.data(), line.size()) ? 0 : 3;
}

// What the parent heard from the worker: the partition, or why there is none.
struct WorkerAnswer {
  std::vector<long> partition;  // empty: none
  std::string why;              // why not, for the fallback's message
  double seconds = 0;
};

WorkerAnswer runHacd(const TriangleMesh& mesh, const DecompositionSettings& settings,
                     const DecompositionObserver& observer) {
  WorkerAnswer answer;
  std::string pending, result;
  DecompositionProgress progress;
  progress.phase = "starting";
  progress.budgetSeconds = settings.budgetSeconds;
  const auto hear = [&](std::string_view chunk) {
    pending.append(chunk);
    for (std::size_t end; (end = pending.find('\n')) != std::string::npos; pending.erase(0, end + 1)) {
      const std::string line = pending.substr(0, end);
      if (line.rfind("p ", 0) != 0) {
        result += line;
        continue;
      }
      char phase[16] = {};
      double fraction = 0;
      if (std::sscanf(line.c_str(), "p %15s %lf", phase, &fraction) != 2) continue;
      for (const char* known : {"graph", "costs", "merging", "hulls"})
        if (std::strcmp(phase, known) == 0) progress.phase = known;  // a literal: it outlives the line
      progress.fraction = fraction;
    }
  };
  const auto tick = [&](double seconds) {
    progress.seconds = seconds;
    if (observer) observer(progress);
  };
  const WorkerEnd end = runForked([&](int fd) { return hacdWorker(mesh, settings, fd); }, settings.budgetSeconds, hear,
                                  tick);
  answer.seconds = end.seconds;
  const char* reached = progress.phase;
  progress.phase = "done";  // the last call: a progress bar ends its line
  progress.fraction = 1;
  tick(end.seconds);
  char text[160];
  if (end.timedOut) {
    std::snprintf(text, sizeof text, "its budget of %g s ran out (in HACD's %s phase)", settings.budgetSeconds, reached);
    answer.why = text;
  } else if (end.signal != 0) {
    std::snprintf(text, sizeof text, "HACD died of signal %d (%s)", end.signal, strsignal(end.signal));
    answer.why = text;
  } else if (result.rfind("e ", 0) == 0) {
    answer.why = result.substr(2);
  } else if (!end.exited || end.exitCode != 0 || result.rfind("r", 0) != 0) {
    answer.why = "HACD's worker ended without an answer (exit status " + std::to_string(end.exitCode) + ")";
  } else {
    std::istringstream labels(result.substr(1));
    answer.partition.reserve(mesh.triangles.size());
    for (long label; labels >> label;) answer.partition.push_back(label);
    if (answer.partition.size() != mesh.triangles.size()) {
      answer.partition.clear();
      answer.why = "HACD's worker answered for the wrong number of triangles";
    }
  }
  return answer;
}

// A decomposition that did not finish remembers its budget: a later run with no larger a
// budget falls back at once instead of spending it again.
void writeFallback(const std::string& file, double budget) {
  std::ofstream out(file);
  if (out) out << "gjkx-fallback " << kCacheVersion << "\n" << budget << "\n";
}

bool readFallback(const std::string& file, double budget) {
  std::ifstream in(file);
  std::string magic;
  int version = 0;
  double spent = 0;
  return in >> magic >> version >> spent && magic == "gjkx-fallback" && version == kCacheVersion && spent >= budget;
}

}  // namespace

std::string describe(const DecompositionReport& r, const std::string& name) {
  std::ostringstream line;
  line << name << ": ";
  if (r.fellBack) {
    line << "not decomposed, " << r.fallbackReason << ": its convex hull is its one piece (" << r.verticesPerPiece.front()
         << " vertices)";
  } else {
    const auto [fewest, most] = std::minmax_element(r.verticesPerPiece.begin(), r.verticesPerPiece.end());
    double mean = 0;
    for (int v : r.verticesPerPiece) mean += v;
    mean /= double(std::max<std::size_t>(1, r.verticesPerPiece.size()));
    line << r.pieces << (r.pieces == 1 ? " convex piece" : " convex pieces") << ", vertices per piece " << *fewest
         << " to " << *most << " (mean " << std::lround(mean) << ")";
  }
  char excess[64];
  std::snprintf(excess, sizeof excess, ", volume excess %.3g", r.volumeExcess);
  line << excess;
  if (r.fromCache) {
    line << " (cached)";
  } else {
    char seconds[32];
    std::snprintf(seconds, sizeof seconds, ", %.1f s", r.seconds);
    line << seconds;
  }
  return line.str();
}

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
  positive(budgetSeconds, "budgetSeconds");
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
                              const std::string& cacheDir, const DecompositionObserver& observer) {
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
  const std::string fallbackFile = cacheFile.empty() ? "" : cacheFile.substr(0, cacheFile.size() - 7) + ".fallback";
  // The fallback: the hull of every vertex is the one piece, and every triangle is in it.
  const auto fallBack = [&](const std::string& why) {
    d = ConvexDecomposition{};
    d.pieces = {convexHull3d(mesh.vertices, "mesh").vertices};
    d.pieceOfTriangle.assign(mesh.triangles.size(), 0);
    d.report.fellBack = true;
    d.report.fallbackReason = why;
  };
  if (!cacheFile.empty() && readCache(cacheFile, d, mesh.triangles.size())) {
    d.report.fromCache = true;
  } else if (!fallbackFile.empty() && readFallback(fallbackFile, settings.budgetSeconds)) {
    char why[96];
    std::snprintf(why, sizeof why, "a budget of at least %g s ran out in an earlier run", settings.budgetSeconds);
    fallBack(why);
    d.report.fromCache = true;
  } else {
    d = ConvexDecomposition{};
    const WorkerAnswer answer = runHacd(mesh, settings, observer);
    if (answer.partition.empty()) {
      fallBack(answer.why);
      d.report.seconds = answer.seconds;
      std::fprintf(stderr, "gjkx: %s: the convex decomposition stopped after %.1f s: %s; the mesh's convex hull is its one piece instead\n",
                   mesh.source.c_str(), answer.seconds, answer.why.c_str());
      if (!fallbackFile.empty() && answer.why.rfind("its budget", 0) == 0) writeFallback(fallbackFile, settings.budgetSeconds);
    } else {
      // HACD's cluster labels are sparse; renumber them 0..k-1 in order of first appearance.
      std::map<long, int> label;
      d.pieceOfTriangle.resize(mesh.triangles.size());
      for (size_t t = 0; t < mesh.triangles.size(); ++t) {
        auto [it, inserted] = label.emplace(answer.partition[t], static_cast<int>(label.size()));
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
      d.report.seconds = answer.seconds;
      if (!cacheFile.empty()) writeCache(cacheFile, d);
    }
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
