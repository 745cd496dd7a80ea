// Convex hulls through Qhull's reentrant C library. Hulls are not the subject of the
// paper, so a well-kept library builds them; this file only turns Qhull's facets
// into the vertex adjacency that hill climbing walks on.
#include <gjkx/support_mapping/convex_hull.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <set>
#include <stdexcept>
#include <string>

extern "C" {
#include <libqhull_r/qhull_ra.h>
}

namespace gjkx {
namespace {

[[noreturn]] void fail(const char* field, const std::string& what) {
  throw std::invalid_argument(std::string(field) + ": " + what);
}

void checkFinite(const std::vector<Eigen::Vector3d>& points, const char* field) {
  for (size_t i = 0; i < points.size(); ++i)
    if (!points[i].allFinite()) fail(field, "point " + std::to_string(i) + " is not finite");
}

// Runs Qhull on `coords` (dim x n, row-major points) and calls `visit(qh)` while the
// result is alive. Returns Qhull's exit code; the message goes to `message`.
template <typename Visit>
int runQhull(std::vector<double>& coords, int dim, const char* options, std::string& message, Visit visit) {
  qhT qhData;
  qhT* qh = &qhData;
  char* buffer = nullptr;
  size_t bufferSize = 0;
  FILE* errors = open_memstream(&buffer, &bufferSize);
  QHULL_LIB_CHECK
  qh_zero(qh, errors);
  const int n = static_cast<int>(coords.size()) / dim;
  int exitCode = qh_new_qhull(qh, dim, n, coords.data(), False, const_cast<char*>(options), nullptr, errors);
  if (exitCode == 0) visit(qh);
  qh_freeqhull(qh, !qh_ALL);
  int curlong = 0, totlong = 0;
  qh_memfreeshort(qh, &curlong, &totlong);
  fclose(errors);
  if (buffer) {
    message.assign(buffer, bufferSize);
    std::free(buffer);
  }
  return exitCode;
}

// Fix (tests): Qhull's answer to input with no volume (no area in 2D) is not always
// QH6154 "initial simplex is flat". Points that all coincide end in QH6421 (zero width,
// an "internal error"), and points flat to within round-off (a slab 1e-14 thick) give
// the warning QH7089 "initial hull is narrow" and then a topology error QH6227. Both
// are the caller's degenerate input, so they get the "no volume" message too.
bool qhullSaysDegenerate(const std::string& message) {
  for (const char* code : {"QH6154", "flat", "QH6214", "QH6421", "QH7089"})
    if (message.find(code) != std::string::npos) return true;
  return false;
}

// Fix (tests): the first line of Qhull's message may be a warning (QH7xxx); report the
// first error line (QH6xxx) when there is one.
std::string qhullFirstError(const std::string& message) {
  size_t at = message.find("QH6");
  if (at == std::string::npos) at = 0;
  return message.substr(at, message.find('\n', at) - at);
}

// Fills firstNeighbour/neighbours from a set of undirected edges.
void buildAdjacency(ConvexHull& hull, const std::set<std::pair<int, int>>& edges) {
  const int n = static_cast<int>(hull.vertices.size());
  std::vector<std::vector<int>> adjacent(n);
  for (const auto& [a, b] : edges) {
    adjacent[a].push_back(b);
    adjacent[b].push_back(a);
  }
  hull.firstNeighbour.assign(1, 0);
  for (auto& list : adjacent) {
    std::sort(list.begin(), list.end());
    hull.neighbours.insert(hull.neighbours.end(), list.begin(), list.end());
    hull.firstNeighbour.push_back(static_cast<int>(hull.neighbours.size()));
  }
}

}  // namespace

ConvexHull convexHull3d(const std::vector<Eigen::Vector3d>& points, const char* field) {
  checkFinite(points, field);
  if (points.size() < 4)
    fail(field, "a solid needs at least 4 points, got " + std::to_string(points.size()));
  std::vector<double> coords;
  coords.reserve(points.size() * 3);
  for (const auto& p : points) coords.insert(coords.end(), {p.x(), p.y(), p.z()});

  ConvexHull hull;
  std::map<int, int> hullIndexOfPoint;
  std::vector<std::array<int, 3>> facets;  // input point indices
  std::string message;
  // Qt: triangulated output; Qs: search all points for the initial simplex.
  const int exitCode = runQhull(coords, 3, "qhull Qt Qs", message, [&](qhT* qh) {
    facetT* facet;
    FORALLfacets {
      std::array<int, 3> tri{};
      int k = 0;
      vertexT *vertex, **vertexp;
      FOREACHvertex_(facet->vertices) {
        if (k < 3) tri[k] = qh_pointid(qh, vertex->point);
        ++k;
      }
      if (k != 3) continue;  // Qt makes every facet a triangle
      // Qhull's vertex order is not an orientation; toporient says which way it faces.
      if (facet->toporient ^ qh_ORIENTclock) std::swap(tri[1], tri[2]);
      facets.push_back(tri);
    }
  });
  if (exitCode != 0) {
    if (qhullSaysDegenerate(message)) fail(field, "all points lie in one plane (a solid needs volume)");
    fail(field, "Qhull could not build the hull: " + qhullFirstError(message));
  }
  for (auto& tri : facets)
    for (int& id : tri) {
      auto [it, inserted] = hullIndexOfPoint.emplace(id, static_cast<int>(hullIndexOfPoint.size()));
      (void)inserted;
      id = it->second;
    }
  hull.vertices.resize(hullIndexOfPoint.size());
  hull.inputIndex.resize(hullIndexOfPoint.size());
  // Renumber the hull vertices in input order, so results do not depend on Qhull's order.
  std::vector<int> remap(hullIndexOfPoint.size());
  {
    int next = 0;
    for (const auto& [inputId, firstSeen] : hullIndexOfPoint) {
      remap[firstSeen] = next;
      hull.vertices[next] = points[inputId];
      hull.inputIndex[next] = inputId;
      ++next;
    }
  }
  const Eigen::Vector3d centroid = [&] {
    Eigen::Vector3d c = Eigen::Vector3d::Zero();
    for (const auto& v : hull.vertices) c += v;
    return Eigen::Vector3d(c / double(hull.vertices.size()));
  }();
  std::set<std::pair<int, int>> edges;
  for (auto tri : facets) {
    for (int& id : tri) id = remap[id];
    // Make every triangle face outwards (counter-clockwise seen from outside).
    const Eigen::Vector3d& a = hull.vertices[tri[0]];
    const Eigen::Vector3d normal = (hull.vertices[tri[1]] - a).cross(hull.vertices[tri[2]] - a);
    if (normal.dot(a - centroid) < 0) std::swap(tri[1], tri[2]);
    hull.triangles.push_back(tri);
    for (int e = 0; e < 3; ++e) {
      const int u = tri[e], v = tri[(e + 1) % 3];
      edges.insert({std::min(u, v), std::max(u, v)});
    }
  }
  std::sort(hull.triangles.begin(), hull.triangles.end());
  buildAdjacency(hull, edges);
  return hull;
}

ConvexHull convexHull2d(const std::vector<Eigen::Vector3d>& points, const char* field) {
  checkFinite(points, field);
  for (size_t i = 0; i < points.size(); ++i)
    if (points[i].z() != 0.0) fail(field, "point " + std::to_string(i) + " must lie in the plane z = 0");
  if (points.size() < 3) fail(field, "a polygon needs at least 3 points, got " + std::to_string(points.size()));
  std::vector<double> coords;
  for (const auto& p : points) coords.insert(coords.end(), {p.x(), p.y()});

  std::vector<int> ids;
  std::string message;
  const int exitCode = runQhull(coords, 2, "qhull Qs", message, [&](qhT* qh) {
    vertexT* vertex;
    FORALLvertices { ids.push_back(qh_pointid(qh, vertex->point)); }
  });
  if (exitCode != 0) {
    if (qhullSaysDegenerate(message)) fail(field, "all points lie on one line (a polygon needs area)");
    fail(field, "Qhull could not build the hull: " + qhullFirstError(message));
  }
  // Order the hull vertices counter-clockwise about their centroid, starting from the
  // lowest input index so the result does not depend on Qhull's order.
  Eigen::Vector3d c = Eigen::Vector3d::Zero();
  for (int id : ids) c += points[id];
  c /= double(ids.size());
  std::sort(ids.begin(), ids.end(), [&](int a, int b) {
    return std::atan2(points[a].y() - c.y(), points[a].x() - c.x()) <
           std::atan2(points[b].y() - c.y(), points[b].x() - c.x());
  });
  std::rotate(ids.begin(), std::min_element(ids.begin(), ids.end()), ids.end());

  ConvexHull hull;
  hull.planar = true;
  const int n = static_cast<int>(ids.size());
  for (int id : ids) {
    hull.vertices.push_back(points[id]);
    hull.inputIndex.push_back(id);
  }
  std::set<std::pair<int, int>> edges;
  for (int i = 0; i < n; ++i) {
    const int j = (i + 1) % n;
    edges.insert({std::min(i, j), std::max(i, j)});
    if (i >= 1 && i + 1 < n) hull.triangles.push_back({0, i, i + 1});
  }
  buildAdjacency(hull, edges);
  return hull;
}

}  // namespace gjkx
