// Brute-force distances of convex bodies in long double: the ground truth for GJK's
// distance (§2.2), the supporting distance (§2.3) and the study's tables.
//
// Two forms of a body, both in world coordinates (the caller maps a shape by its pose;
// this library links no stage, so it never sees a gjkx shape):
// - a Cloud: conv(points) + ball(radius), for a few points (a point, a segment, a
//   triangle, a box, a sphere, a capsule, a small hull). signedDistance tries every
//   candidate direction, so it needs no faces and works when the bodies overlap too.
// - a WorldPolytope: vertices and boundary triangles, for hulls of up to thousands of
//   vertices. boundaryDistance is the nearest of the feature pairs (vertex-triangle,
//   triangle-vertex, edge-edge) with features pruned by bounding boxes; distance adds the
//   overlap test (a vertex inside, or an edge through a triangle); separatingAxisGap is
//   the largest gap over the separating-axis candidates.
// The closest points of each feature pair are those of closest_points.hpp, the versions
// that stay exact on slivers.
#pragma once

#include <gjkx/reference/closest_points.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <set>
#include <utility>
#include <vector>

namespace gjkx::reference {

// ---------------------------------------------------------------------------------------
// Point clouds with a radius

/// conv(points) + ball(radius), in the world: every convex shape of the library is one of
/// these (a sphere is one point and its radius, a capsule two points and its radius).
struct Cloud {
  std::vector<Vec> points;  ///< the core's points (any number; all subsets are tried)
  Real radius = 0;          ///< the ball swept around the core
  /// The largest |point| + radius: the scale of the coordinates, what round-off scales with.
  Real extent() const {
    Real r = 0;
    for (const auto& p : points) r = std::max(r, p.norm());
    return r + radius;
  }
};

/// The signed distance of two clouds: their distance when apart, minus the penetration
/// depth when they overlap.
///
/// For any unit s the supporting distance SD(s) = min_b s.b - max_a s.a - rA - rB (§2.3)
/// is a lower bound of the signed distance, and the signed distance is its maximum over
/// s, attained at one of finitely many directions, all of which are tried: between the
/// closest points of every feature pair (vertex-vertex, vertex-edge, vertex-triangle and
/// edge-edge, features over all pairs and triples of points, so the hull's faces are
/// among them) for the disjoint case, and every triangle normal and edge-edge cross
/// product (the separating-axis candidates) for the overlapping case. The cost is
/// O(n^3 m + n m^3) for n and m points: meant for a dozen points.
///
/// Accuracy: when apart, the distance of the closest feature pair is an upper bound and
/// the best SD a lower bound, both exact at the right candidate; the larger of the two is
/// returned, right within a few eps times extent(). A direction between two points 1e-8
/// apart carries an error of eps / 1e-8, which tilts the supporting planes of a long
/// feature, so a pair's own distance is preferred; where a candidate point of a needle
/// was computed off its feature the pair fell below a proven SD (fuzz finding
/// `reference_needle_face_normal`: 1.49e-5 against 1.554e-5 checked in exact
/// arithmetic), hence the larger. A point-edge pair also tries t x ((x - a) x t), the
/// normal from the line to the point, which keeps its direction where the closest point's
/// round-off along a 47000-long edge does not (fuzz finding `reference_point_near_long_edge`).
inline Real signedDistance(const Cloud& A, const Cloud& B) {
  const auto& a = A.points;
  const auto& b = B.points;
  const int na = int(a.size()), nb = int(b.size());
  Real lower = -std::numeric_limits<Real>::infinity();  // max SD of the cores
  Real upper = std::numeric_limits<Real>::infinity();   // min distance of two core points
  auto tryDirection = [&](Vec s) {
    const Real n = s.norm();
    if (!(n > 0) || !std::isfinite(n)) return;
    s /= n;
    Real maxA = -std::numeric_limits<Real>::infinity(), minB = std::numeric_limits<Real>::infinity();
    for (const auto& x : a) maxA = std::max(maxA, s.dot(x));
    for (const auto& y : b) minB = std::min(minB, s.dot(y));
    lower = std::max(lower, minB - maxA);
  };
  auto tryPair = [&](const Vec& p, const Vec& q) {
    upper = std::min(upper, (q - p).norm());
    tryDirection(q - p);
  };
  auto tryBoth = [&](const Vec& s) {
    tryDirection(s);
    tryDirection(-s);
  };
  auto tryPointEdge = [&](const Vec& x, const Vec& e0, const Vec& e1) {
    const Vec t = e1 - e0;
    tryBoth(t.cross((x - e0).cross(t)));
  };
  for (int k = 0; k < 3; ++k) tryBoth(Vec::Unit(k));
  // Disjoint: between the closest points of every feature pair.
  for (const auto& x : a)
    for (const auto& y : b) tryPair(x, y);
  for (int i = 0; i < nb; ++i)
    for (int j = i + 1; j < nb; ++j)
      for (const auto& x : a) {
        tryPair(x, closestOnSegment(x, b[i], b[j]));
        tryPointEdge(x, b[i], b[j]);
      }
  for (int i = 0; i < na; ++i)
    for (int j = i + 1; j < na; ++j)
      for (const auto& y : b) {
        tryPair(closestOnSegment(y, a[i], a[j]), y);
        tryPointEdge(y, a[i], a[j]);
      }
  for (int i = 0; i < nb; ++i)
    for (int j = i + 1; j < nb; ++j)
      for (int k = j + 1; k < nb; ++k) {
        for (const auto& x : a)
          if (auto c = projectionInsideTriangle(x, b[i], b[j], b[k])) tryPair(x, *c);
        tryBoth(triangleNormal(b[i], b[j], b[k]));  // overlapping: face normals ...
      }
  for (int i = 0; i < na; ++i)
    for (int j = i + 1; j < na; ++j)
      for (int k = j + 1; k < na; ++k) {
        for (const auto& y : b)
          if (auto c = projectionInsideTriangle(y, a[i], a[j], a[k])) tryPair(*c, y);
        tryBoth(triangleNormal(a[i], a[j], a[k]));
      }
  for (int i = 0; i < na; ++i)
    for (int j = i + 1; j < na; ++j) {
      for (int k = 0; k < nb; ++k)
        for (int l = k + 1; l < nb; ++l) {
          const SegmentPair c = closestSegmentSegment(a[i], a[j], b[k], b[l]);
          tryPair(c.onFirst, c.onSecond);
          tryBoth((a[j] - a[i]).cross(b[l] - b[k]));  // ... and edge x edge
        }
      // Collinear edges: a direction normal to both is among the normals of an edge and an axis.
      for (int k = 0; k < 3; ++k) tryBoth((a[j] - a[i]).cross(Vec::Unit(k)));
    }
  return (lower > 0 ? std::max(upper, lower) : lower) - (A.radius + B.radius);
}

// ---------------------------------------------------------------------------------------
// Polytopes given by their boundary

/// A convex polytope in world coordinates: vertices, boundary triangles, and what the
/// distance and overlap tests need of them (edges, outward face planes, bounding box).
struct WorldPolytope {
  std::vector<Vec> vertices;                  ///< in the world
  std::vector<std::array<int, 3>> triangles;  ///< the boundary, any winding
  std::vector<std::pair<int, int>> edges;     ///< the triangles' edges, once each (i < j)
  std::vector<Vec> faceNormals;               ///< unit, outward, one per non-degenerate triangle
  std::vector<Real> faceOffsets;              ///< n . x <= offset inside
  Vec lo = Vec::Zero();                       ///< bounding box: the lowest corner
  Vec hi = Vec::Zero();                       ///< and the highest

  /// The polytope of the given world vertices and boundary triangles; edges, outward
  /// normals (triangleNormal, oriented away from the centroid) and the box are derived.
  static WorldPolytope fromTriangles(std::vector<Vec> vertices, std::vector<std::array<int, 3>> triangles) {
    WorldPolytope out;
    out.vertices = std::move(vertices);
    out.triangles = std::move(triangles);
    Vec centroid = Vec::Zero();
    for (const Vec& v : out.vertices) centroid += v;
    centroid /= Real(out.vertices.size());
    std::set<std::pair<int, int>> edges;
    for (const auto& tri : out.triangles) {
      for (int k = 0; k < 3; ++k) {
        const int a = tri[k], b = tri[(k + 1) % 3];
        edges.insert({std::min(a, b), std::max(a, b)});
      }
      const Vec& a = out.vertices[tri[0]];
      Vec n = triangleNormal(a, out.vertices[tri[1]], out.vertices[tri[2]]);
      if (!(n.norm() > Real(0))) continue;
      n.normalize();
      if (n.dot(a - centroid) < 0) n = -n;  // outward whatever the winding
      out.faceNormals.push_back(n);
      out.faceOffsets.push_back(n.dot(a));
    }
    out.edges.assign(edges.begin(), edges.end());
    out.lo = out.hi = out.vertices.at(0);
    for (const Vec& v : out.vertices) {
      out.lo = out.lo.cwiseMin(v);
      out.hi = out.hi.cwiseMax(v);
    }
    return out;
  }

  /// The largest signed distance of x past a face plane: <= 0 inside, ~0 on the boundary.
  Real planeDistance(const Vec& x) const {
    Real m = -std::numeric_limits<Real>::infinity();
    for (std::size_t f = 0; f < faceNormals.size(); ++f) m = std::max(m, faceNormals[f].dot(x) - faceOffsets[f]);
    return m;
  }
  /// Is x inside or on the boundary (no face plane has it strictly outside)?
  bool contains(const Vec& x) const {
    for (std::size_t f = 0; f < faceNormals.size(); ++f)
      if (faceNormals[f].dot(x) > faceOffsets[f]) return false;
    return true;
  }
  /// max over the vertices of s . x: the support value in direction s.
  Real supportValue(const Vec& s) const {
    Real m = -std::numeric_limits<Real>::infinity();
    for (const Vec& v : vertices) m = std::max(m, s.dot(v));
    return m;
  }
};

/// The closest pair of points of two boundaries and their distance.
struct FeatureDistance {
  Real distance = std::numeric_limits<Real>::infinity();  ///< |q - p|
  Vec p = Vec::Zero();                                     ///< on the first boundary
  Vec q = Vec::Zero();                                     ///< on the second boundary
};

namespace detail {

/// Distance between two axis-aligned boxes: a lower bound of the distance of anything inside them.
inline Real boxGap(const Vec& lo1, const Vec& hi1, const Vec& lo2, const Vec& hi2) {
  Vec gap;
  for (int k = 0; k < 3; ++k) gap[k] = std::max({Real(0), lo1[k] - hi2[k], lo2[k] - hi1[k]});
  return gap.norm();
}

/// The indices of P's vertices, edges and triangles whose boxes are within `reach` of Q's box.
struct NearFeatures {
  std::vector<int> vertices, edges, triangles;
};

inline NearFeatures nearFeatures(const WorldPolytope& P, const WorldPolytope& Q, Real reach) {
  NearFeatures out;
  auto near = [&](const Vec& lo, const Vec& hi) { return boxGap(lo, hi, Q.lo, Q.hi) <= reach; };
  for (std::size_t k = 0; k < P.vertices.size(); ++k)
    if (near(P.vertices[k], P.vertices[k])) out.vertices.push_back(int(k));
  for (std::size_t k = 0; k < P.edges.size(); ++k) {
    const Vec &a = P.vertices[P.edges[k].first], &b = P.vertices[P.edges[k].second];
    if (near(a.cwiseMin(b), a.cwiseMax(b))) out.edges.push_back(int(k));
  }
  for (std::size_t k = 0; k < P.triangles.size(); ++k) {
    const auto& t = P.triangles[k];
    const Vec &a = P.vertices[t[0]], &b = P.vertices[t[1]], &c = P.vertices[t[2]];
    if (near(a.cwiseMin(b).cwiseMin(c), a.cwiseMax(b).cwiseMax(c))) out.triangles.push_back(int(k));
  }
  return out;
}

}  // namespace detail

/// The distance between the boundaries of P and Q with its closest points: the nearest of
/// all vertex-vertex, vertex-triangle, triangle-vertex and edge-edge pairs (equal to the
/// distance between the solids when they do not overlap; when they do, intersecting
/// boundaries cross edge-to-face, a pair not looked at, so use distance()).
///
/// The nearest vertex pair bounds the answer first; a feature whose bounding box is
/// farther than that from the other polytope's box, and a pair whose boxes are farther
/// apart than the best so far, cannot hold the closest points and are skipped (this
/// never changes the minimum).
///
/// Accuracy: each pair's closest points are those of closest_points.hpp, right within a
/// few eps times the size of the coordinates on slivers too.
inline FeatureDistance boundaryDistance(const WorldPolytope& P, const WorldPolytope& Q) {
  FeatureDistance best;
  auto consider = [&](const Vec& p, const Vec& q) {
    const Real d = (q - p).norm();
    if (d < best.distance) best = FeatureDistance{d, p, q};
  };
  for (const Vec& p : P.vertices)
    for (const Vec& q : Q.vertices) consider(p, q);
  const detail::NearFeatures nP = detail::nearFeatures(P, Q, best.distance), nQ = detail::nearFeatures(Q, P, best.distance);
  auto vertexTriangles = [&](const WorldPolytope& X, const std::vector<int>& vs, const WorldPolytope& Y,
                             const std::vector<int>& ts, bool xIsP) {
    for (int t : ts) {
      const Vec &a = Y.vertices[Y.triangles[t][0]], &b = Y.vertices[Y.triangles[t][1]], &c = Y.vertices[Y.triangles[t][2]];
      const Vec lo = a.cwiseMin(b).cwiseMin(c), hi = a.cwiseMax(b).cwiseMax(c);
      for (int v : vs) {
        const Vec& x = X.vertices[v];
        if (detail::boxGap(x, x, lo, hi) >= best.distance) continue;
        const Vec y = closestOnTriangle(x, a, b, c);
        xIsP ? consider(x, y) : consider(y, x);
      }
    }
  };
  vertexTriangles(P, nP.vertices, Q, nQ.triangles, true);
  vertexTriangles(Q, nQ.vertices, P, nP.triangles, false);
  for (int i : nP.edges)
    for (int j : nQ.edges) {
      const Vec &a = P.vertices[P.edges[i].first], &b = P.vertices[P.edges[i].second];
      const Vec &c = Q.vertices[Q.edges[j].first], &d = Q.vertices[Q.edges[j].second];
      if (detail::boxGap(a.cwiseMin(b), a.cwiseMax(b), c.cwiseMin(d), c.cwiseMax(d)) >= best.distance) continue;
      const SegmentPair s = closestSegmentSegment(a, b, c, d);
      consider(s.onFirst, s.onSecond);
    }
  return best;
}

/// Does the segment [p, q] cross the triangle abc? (The ends on strictly opposite sides of
/// its plane, or one on it, and the crossing point inside or on the triangle by signed
/// areas; a segment lying in the plane does not count.)
inline bool segmentCrossesTriangle(const Vec& p, const Vec& q, const Vec& a, const Vec& b, const Vec& c) {
  const Vec n = (b - a).cross(c - a);
  const Real sp = n.dot(p - a), sq = n.dot(q - a);
  if ((sp > 0 && sq > 0) || (sp < 0 && sq < 0) || sp == sq) return false;
  const Vec x = p + (q - p) * (sp / (sp - sq));
  const Real u = n.dot((b - a).cross(x - a)), v = n.dot((c - b).cross(x - b)), w = n.dot((a - c).cross(x - c));
  return (u >= 0 && v >= 0 && w >= 0) || (u <= 0 && v <= 0 && w <= 0);
}

/// The distance between the solids P and Q, 0 when they overlap: a vertex of one inside
/// the other, or an edge of one through a triangle of the other, is overlap; otherwise
/// the boundary distance. Accuracy as boundaryDistance; contact within round-off of the
/// coordinates may go either way.
inline Real distance(const WorldPolytope& P, const WorldPolytope& Q) {
  for (const Vec& v : P.vertices)
    if (Q.contains(v)) return 0;
  for (const Vec& v : Q.vertices)
    if (P.contains(v)) return 0;
  const FeatureDistance boundary = boundaryDistance(P, Q);
  // Boundaries that cross with no vertex inside the other: an edge pierces a triangle.
  // Only features within the boundary distance of the other's box can take part.
  const detail::NearFeatures nP = detail::nearFeatures(P, Q, boundary.distance),
                             nQ = detail::nearFeatures(Q, P, boundary.distance);
  auto crossing = [](const WorldPolytope& X, const std::vector<int>& es, const WorldPolytope& Y, const std::vector<int>& ts) {
    for (int e : es)
      for (int t : ts)
        if (segmentCrossesTriangle(X.vertices[X.edges[e].first], X.vertices[X.edges[e].second],
                                   Y.vertices[Y.triangles[t][0]], Y.vertices[Y.triangles[t][1]],
                                   Y.vertices[Y.triangles[t][2]]))
          return true;
    return false;
  };
  if (crossing(P, nP.edges, Q, nQ.triangles) || crossing(Q, nQ.edges, P, nP.triangles)) return 0;
  return boundary.distance;
}

/// The separating-axis test: the largest gap between the projections of P and Q over the
/// face normals of both and the cross products of every edge pair. Positive: disjoint (two
/// convex polytopes are disjoint iff one of these axes separates them); when they overlap,
/// minus the penetration depth. Cost O(E_P E_Q (V_P + V_Q)): meant for small polytopes.
inline Real separatingAxisGap(const WorldPolytope& P, const WorldPolytope& Q) {
  Real best = -std::numeric_limits<Real>::infinity();
  auto axisGap = [&](const Vec& axis) {
    // the gap along +axis (Q beyond P) and along -axis (P beyond Q)
    Real pMax = -std::numeric_limits<Real>::infinity(), pMin = -pMax, qMax = pMax, qMin = pMin;
    for (const Vec& v : P.vertices) {
      const Real x = axis.dot(v);
      pMax = std::max(pMax, x), pMin = std::min(pMin, x);
    }
    for (const Vec& v : Q.vertices) {
      const Real x = axis.dot(v);
      qMax = std::max(qMax, x), qMin = std::min(qMin, x);
    }
    best = std::max(best, std::max(qMin - pMax, pMin - qMax));
  };
  for (const Vec& n : P.faceNormals) axisGap(n);
  for (const Vec& n : Q.faceNormals) axisGap(n);
  for (const auto& e : P.edges)
    for (const auto& f : Q.edges) {
      const Vec axis = (P.vertices[e.second] - P.vertices[e.first]).cross(Q.vertices[f.second] - Q.vertices[f.first]);
      const Real n = axis.norm();
      if (!(n > Real(0))) continue;
      axisGap(axis / n);
    }
  return best;
}

}  // namespace gjkx::reference
