// Convex hulls through Qhull's reentrant C library. Hulls are not the subject of the
// paper, so a well-kept library builds them; this file only turns Qhull's facets
// into the vertex adjacency that hill climbing walks on.
#include <gjkx/support_mapping/convex_hull.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>

extern "C" {
#include <libqhull_r/qhull_ra.h>
}

namespace gjkx {
namespace {

/// A length for a message, in as many digits as it needs (1.2e-13, not 0.000000).
std::string toText(double x) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.3g", x);
  return buffer;
}


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

// Flat and thin point sets, checked where they enter. Qhull decides every predicate with
// a round-off allowance relative to the coordinates' size, and on a set flat to ~1e-12 of
// its size it does not always give up: it can return a hull that silently leaves input
// points out (measured on tilted slabs of 50 random points 1e-10 to 1e-12 thick: extreme
// points missing by up to 1.5e-5 of the size, with no error and no warning; test
// `a thin slab's hull is the slab`). So the set's shape is measured first, in long
// double, in a frame of its own: e1 from the point farthest from the first point p0 to
// the point p1 farthest from that, L = |p1 - p0|; e2 towards the point farthest from that
// line; n = e1 x e2. Its widths along e2 and n are W and T.
//  - W or T below kFlatUlps round-offs of L (the size of the error in n.(p - p0)
//    itself, for points given to round-off): no volume, the caller's flat input; refused.
//  - W or T below kThinFraction of L (Qhull's trouble starts near 1e-10; kept three orders
//    off): Qhull runs on the set stretched along e2 and n to the width L. A convex hull
//    commutes with an affine map (the hull of A(X) is A of the hull of X, vertex for
//    vertex, face for face), so the stretched set has the same hull, and Qhull sees a
//    solid as fat as a cube. The hull keeps the input points themselves.
// Every hull is then checked against its input: no input point may lie outside a boundary
// triangle's plane (in the coordinates Qhull saw) by more than kOutsideUlps round-offs of
// their size; otherwise the hull is refused with the point named, never returned wrong.
constexpr long double kFlatUlps = 64;
constexpr long double kThinFraction = 1e-6L;
constexpr double kOutsideUlps = 4096;

// Near duplicates. Two input points closer than kWeldFraction of the set's size make
// Qhull's facets through both as good as round-off over their distance: a facet whose
// normal comes from an edge 3e-9 long (two prisms on the triangles of one nearly planar
// quad, moved back along normals 2e-6 rad apart) is tilted by about 1e-7, and Qhull's
// hull of such a set left a point 2.5e-8 outside (a node of the hierarchy of a torus's
// prisms). Such points are one point for Qhull: the first of them stands for the others,
// and the check below allows every input point its distance from the one that stood for it
// (at most kWeldFraction of the size, far below any tolerance a caller works at).
constexpr double kWeldFraction = 1e-8;

// The point that stands for each point (its own index, or an earlier point's within
// `weld`), and the largest distance of a point from the one that stands for it. Points
// sorted by x are compared only with their neighbours within `weld` along x.
std::pair<std::vector<int>, double> weldNearDuplicates(const std::vector<Eigen::Vector3d>& points, double weld) {
  std::vector<int> order(points.size()), standsFor(points.size());
  for (size_t i = 0; i < points.size(); ++i) order[i] = standsFor[i] = int(i);
  std::sort(order.begin(), order.end(), [&](int a, int b) { return points[a].x() < points[b].x(); });
  double farthest = 0;
  for (size_t k = 0; k < order.size(); ++k) {
    const int i = order[k];
    if (standsFor[i] != i) continue;  // an earlier point stands for it already
    for (size_t m = k + 1; m < order.size() && points[order[m]].x() - points[i].x() <= weld; ++m) {
      const int j = order[m];
      if (standsFor[j] != j) continue;
      if (const double d = (points[j] - points[i]).norm(); d <= weld) {
        standsFor[j] = i;
        farthest = std::max(farthest, d);
      }
    }
  }
  return {standsFor, farthest};
}

using LVec = Eigen::Matrix<long double, 3, 1>;

struct SetShape {
  bool flat = false;          // no volume within round-off
  bool thin = false;          // thin enough that Qhull runs on the stretched set
  std::vector<Eigen::Vector3d> stretched;  // the set in the frame (e1, e2 * L/W, n * L/T), when thin
};

SetShape measure(const std::vector<Eigen::Vector3d>& points) {
  SetShape shape;
  const auto at = [&](size_t i) { return LVec(points[i].cast<long double>()); };
  const auto farthestFrom = [&](const auto& distance) {
    size_t best = 0;
    long double bestValue = -1;
    for (size_t i = 0; i < points.size(); ++i)
      if (const long double d = distance(at(i)); d > bestValue) {
        bestValue = d;
        best = i;
      }
    return best;
  };
  const LVec first = at(0);
  const LVec p0 = at(farthestFrom([&](const LVec& p) { return (p - first).squaredNorm(); }));
  const LVec p1 = at(farthestFrom([&](const LVec& p) { return (p - p0).squaredNorm(); }));
  const long double L = (p1 - p0).norm();
  long double size = 0;  // the largest coordinate: the scale of the input's own round-off
  for (size_t i = 0; i < points.size(); ++i) size = std::max(size, at(i).cwiseAbs().maxCoeff());
  const long double roundOff = kFlatUlps * std::numeric_limits<double>::epsilon() * size;
  if (!(L > roundOff)) {
    shape.flat = true;
    return shape;
  }
  const LVec e1 = (p1 - p0) / L;
  const auto offLine = [&](const LVec& p) { return ((p - p0) - e1 * e1.dot(p - p0)).norm(); };
  const LVec p2 = at(farthestFrom(offLine));
  const LVec towards = (p2 - p0) - e1 * e1.dot(p2 - p0);
  if (!(towards.norm() > roundOff)) {
    shape.flat = true;
    return shape;
  }
  const LVec e2 = towards.normalized();
  const LVec n = e1.cross(e2).normalized();
  long double lo2 = 0, hi2 = 0, loN = 0, hiN = 0;
  for (size_t i = 0; i < points.size(); ++i) {
    const LVec d = at(i) - p0;
    lo2 = std::min(lo2, e2.dot(d));
    hi2 = std::max(hi2, e2.dot(d));
    loN = std::min(loN, n.dot(d));
    hiN = std::max(hiN, n.dot(d));
  }
  const long double W = hi2 - lo2, T = hiN - loN;
  if (!(W > roundOff) || !(T > roundOff)) {
    shape.flat = true;
    return shape;
  }
  if (W >= kThinFraction * L && T >= kThinFraction * L) return shape;
  shape.thin = true;
  for (size_t i = 0; i < points.size(); ++i) {
    const LVec d = at(i) - p0;
    shape.stretched.push_back(
        Eigen::Vector3d(double(e1.dot(d)), double(e2.dot(d) * (L / W)), double(n.dot(d) * (L / T))));
  }
  return shape;
}

// The input points in small groups, each in a ball, for the check that every input point
// lies inside every boundary triangle's plane: a plane with a whole ball on its inner side
// needs none of the ball's points looked at. Checking every point against every triangle
// took two thirds of the time of a 14,000-point hull; a triangle's plane now meets only
// the balls about its own part of the surface. Groups are runs of kGroupSize points in
// Morton order (coordinates quantized to 2^21 steps across the set's box), so each is
// compact in space.
class PointBalls {
 public:
  explicit PointBalls(const std::vector<Eigen::Vector3d>& points) : points_(points) {
    Eigen::Vector3d lo = points.front(), hi = lo;
    for (const auto& p : points) {
      lo = lo.cwiseMin(p);
      hi = hi.cwiseMax(p);
    }
    const Eigen::Vector3d extent = (hi - lo).cwiseMax(Eigen::Vector3d::Constant(1e-300));
    std::vector<std::pair<std::uint64_t, int>> keyed(points.size());
    for (size_t i = 0; i < points.size(); ++i) {
      const Eigen::Vector3d q = ((points[i] - lo).cwiseQuotient(extent) * double((1 << 21) - 1)).array().round();
      keyed[i] = {morton(std::uint64_t(q.x()), std::uint64_t(q.y()), std::uint64_t(q.z())), int(i)};
    }
    std::sort(keyed.begin(), keyed.end());
    for (const auto& entry : keyed) order_.push_back(entry.second);
    for (size_t first = 0; first < order_.size(); first += kGroupSize) {
      Ball ball;
      ball.first = int(first);
      ball.last = int(std::min(order_.size(), first + kGroupSize));
      Eigen::Vector3d blo = points[order_[first]], bhi = blo;
      for (int k = ball.first; k < ball.last; ++k) {
        blo = blo.cwiseMin(points[order_[k]]);
        bhi = bhi.cwiseMax(points[order_[k]]);
      }
      ball.centre = (blo + bhi) / 2;
      for (int k = ball.first; k < ball.last; ++k)
        ball.radius = std::max(ball.radius, (points[order_[k]] - ball.centre).norm());
      ball.radius = ball.radius * (1 + 1e-12) + 1e-300;  // rounded up: a bound, never short
      balls_.push_back(ball);
    }
  }
  // True when every point p has unit.(p - a) <= allowed: for each ball, either the ball is
  // inside by its centre's height plus its radius, or its points are looked at one by one.
  bool allInside(const Eigen::Vector3d& unit, const Eigen::Vector3d& a, double allowed) const {
    for (const Ball& ball : balls_) {
      if (unit.dot(ball.centre - a) + ball.radius <= allowed) continue;
      for (int k = ball.first; k < ball.last; ++k)
        if (unit.dot(points_[order_[k]] - a) > allowed) return false;
    }
    return true;
  }

 private:
  static constexpr size_t kGroupSize = 16;
  struct Ball {
    Eigen::Vector3d centre = Eigen::Vector3d::Zero();
    double radius = 0;
    int first = 0, last = 0;  // its points: order_[first, last)
  };
  // Interleaves the low 21 bits of x, y and z.
  static std::uint64_t morton(std::uint64_t x, std::uint64_t y, std::uint64_t z) {
    auto spread = [](std::uint64_t v) {
      v &= 0x1fffff;
      v = (v | v << 32) & 0x1f00000000ffffULL;
      v = (v | v << 16) & 0x1f0000ff0000ffULL;
      v = (v | v << 8) & 0x100f00f00f00f00fULL;
      v = (v | v << 4) & 0x10c30c30c30c30c3ULL;
      v = (v | v << 2) & 0x1249249249249249ULL;
      return v;
    };
    return spread(x) | spread(y) << 1 | spread(z) << 2;
  }
  const std::vector<Eigen::Vector3d>& points_;
  std::vector<int> order_;
  std::vector<Ball> balls_;
};

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
  const SetShape shape = measure(points);
  if (shape.flat) fail(field, "all points lie in one plane, to within round-off (a solid needs volume)");
  // The coordinates Qhull sees: the points, or a thin set stretched to a fat one (see measure()).
  const std::vector<Eigen::Vector3d>& seen = shape.thin ? shape.stretched : points;
  double size = 0;
  for (const auto& p : seen) size = std::max(size, p.cwiseAbs().maxCoeff());
  // Qhull sees one point for each group of near duplicates (see kWeldFraction); `qhullId`
  // maps its point ids back to the input's.
  const auto [standsFor, welded] = weldNearDuplicates(seen, kWeldFraction * size);
  std::vector<int> qhullId;
  std::vector<double> coords;
  coords.reserve(points.size() * 3);
  for (size_t i = 0; i < seen.size(); ++i)
    if (standsFor[i] == int(i)) {
      qhullId.push_back(int(i));
      coords.insert(coords.end(), {seen[i].x(), seen[i].y(), seen[i].z()});
    }
  if (qhullId.size() < 4)
    fail(field, "a solid needs at least 4 points apart, got " + std::to_string(qhullId.size()));

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
        if (k < 3) tri[k] = qhullId[qh_pointid(qh, vertex->point)];
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
  // Orientation and the check against the input, in the coordinates Qhull saw (the
  // stretch has a positive determinant: it keeps every triangle's orientation).
  const auto seenVertex = [&](int v) -> const Eigen::Vector3d& { return seen[hull.inputIndex[v]]; };
  const Eigen::Vector3d centroid = [&] {
    Eigen::Vector3d c = Eigen::Vector3d::Zero();
    for (int v = 0; v < int(hull.vertices.size()); ++v) c += seenVertex(v);
    return Eigen::Vector3d(c / double(hull.vertices.size()));
  }();
  const double roundOffAllowed = kOutsideUlps * std::numeric_limits<double>::epsilon() * size;
  const PointBalls balls(seen);
  std::set<std::pair<int, int>> edges;
  for (auto tri : facets) {
    for (int& id : tri) id = remap[id];
    // Make every triangle face outwards (counter-clockwise seen from outside).
    const Eigen::Vector3d& a = seenVertex(tri[0]);
    Eigen::Vector3d normal = (seenVertex(tri[1]) - a).cross(seenVertex(tri[2]) - a);
    if (normal.dot(a - centroid) < 0) {
      std::swap(tri[1], tri[2]);
      normal = -normal;
    }
    // Never a wrong hull: every input point inside this triangle's plane. A sliver
    // triangle (Qhull's triangulation of a merged facet) has a normal whose direction is
    // only as good as |e1| |e2| / |e1 x e2| round-offs: its allowance grows by that factor.
    if (const double length = normal.norm(); length > 0) {
      const double edges1 = (seenVertex(tri[1]) - a).norm() * (seenVertex(tri[2]) - a).norm();
      const double allowed = roundOffAllowed * std::max(1.0, edges1 / length) + welded;
      const Eigen::Vector3d unit = normal / length;
      if (!balls.allInside(unit, a, allowed))
        for (size_t i = 0; i < seen.size(); ++i)  // the first point outside, by index
          if (const double outside = normal.dot(seen[i] - a) / length; outside > allowed)
            fail(field, "Qhull's hull leaves point " + std::to_string(i) + " outside by " + toText(outside) +
                            " (of a set " + std::to_string(size) +
                            " across): the set is too flat for a hull in double; give it volume");
    }
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

// A triangular prism's faces are known: no hull has to be searched for. With the front
// triangle a b c and the back one a' b' c' (the same triangle moved by e), the front cap
// faces away from e and the back cap towards it; each edge u -> v of the front cap, in the
// cap's outward order, borders the side quad v u u' v', which the shared edge is walked
// the other way round. A side quad is planar only up to the rounding of its corners (a
// float piece's), so it is split along the diagonal that keeps it convex: v u u' and
// v u' v' when v' lies on or below the plane of v u u', else v u v' and u u' v'.
std::optional<ConvexHull> prismHull(const std::vector<Eigen::Vector3d>& points, const char* field) {
  checkFinite(points, field);
  if (points.size() != 6) fail(field, "a prism has 6 points (a triangle and its copy), got " + std::to_string(points.size()));
  const auto& p = points;
  const Eigen::Vector3d e = (p[3] - p[0] + p[4] - p[1] + p[5] - p[2]) / 3.0;
  const Eigen::Vector3d n = (p[1] - p[0]).cross(p[2] - p[0]);
  // A triangle with no area, or a copy not moved off its plane, is no prism.
  if (!(std::abs(n.dot(e)) > 1e-6 * n.norm() * e.norm())) return std::nullopt;
  ConvexHull hull;
  hull.vertices = points;
  hull.inputIndex = {0, 1, 2, 3, 4, 5};
  const std::array<int, 3> front = n.dot(e) < 0 ? std::array<int, 3>{0, 1, 2} : std::array<int, 3>{0, 2, 1};
  hull.triangles.push_back(front);
  hull.triangles.push_back({front[0] + 3, front[2] + 3, front[1] + 3});
  for (int k = 0; k < 3; ++k) {
    const int u = front[k], v = front[(k + 1) % 3], u1 = u + 3, v1 = v + 3;
    const Eigen::Vector3d normal = (p[u] - p[v]).cross(p[u1] - p[v]);
    if (normal.dot(p[v1] - p[v]) <= 0) {
      hull.triangles.push_back({v, u, u1});
      hull.triangles.push_back({v, u1, v1});
    } else {
      hull.triangles.push_back({v, u, v1});
      hull.triangles.push_back({u, u1, v1});
    }
  }
  // Never a wrong hull: every corner on or below every face (to round-off), as convexHull3d
  // checks Qhull's; a prism too thin for that is none.
  double size = 0;
  for (const auto& q : points) size = std::max(size, q.cwiseAbs().maxCoeff());
  const double allowed = kOutsideUlps * std::numeric_limits<double>::epsilon() * size;
  for (const auto& tri : hull.triangles) {
    const Eigen::Vector3d normal = (p[tri[1]] - p[tri[0]]).cross(p[tri[2]] - p[tri[0]]);
    const double length = normal.norm();
    if (!(length > 0)) return std::nullopt;
    for (const auto& q : points)
      if (normal.dot(q - p[tri[0]]) / length > allowed) return std::nullopt;
  }
  std::set<std::pair<int, int>> edges;
  for (const auto& tri : hull.triangles)
    for (int k = 0; k < 3; ++k) edges.insert({std::min(tri[k], tri[(k + 1) % 3]), std::max(tri[k], tri[(k + 1) % 3])});
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
