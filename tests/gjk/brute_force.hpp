// Independent references for the GJK tests, computed in long double by brute force.
//
// Nothing here uses the library's sub-algorithm: the closest point of a small point
// set is found by trying *every* sub-simplex (vertex, edge, triangle, tetrahedron),
// projecting the origin onto its affine hull with a least-squares solve (Householder
// QR, so a sliver costs its condition number, not its square), and keeping the nearest
// projection whose barycentric coordinates are all >= 0. The distance between two
// convex polytopes is the nearest of all their feature pairs (vertex-triangle,
// triangle-vertex, edge-edge; vertex-vertex is a sub-case of each), and whether they
// overlap is decided by a separating-axis test.
#pragma once

#include <gjkx/motion/pose.hpp>
#include <gjkx/support_mapping/polytope.hpp>

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <set>
#include <utility>
#include <vector>

namespace gjkx::test {

using Real = long double;
using RVec = Eigen::Matrix<Real, 3, 1>;

template <typename S>
RVec toReal(const Vector3<S>& v) {
  return v.template cast<Real>();
}

/// The point of conv{w_0..w_{n-1}} (n <= 4) closest to the origin, with its barycentric
/// coordinates over the n input points.
struct ClosestPoint {
  RVec point = RVec::Zero();
  Real distance = std::numeric_limits<Real>::infinity();
  std::array<Real, 4> lambda{};
};

namespace detail {

// Projection of the origin onto the affine hull of the points ids[0..K] (K+1 points):
// minimise |w0 + A mu| with A = [w_j - w0], lambda = (1 - sum mu, mu). Kept when every
// lambda >= 0; the point is then rebuilt from lambda, so it lies in the hull.
template <int K>
void tryFeature(const std::array<RVec, 4>& w, const std::array<int, K + 1>& ids, ClosestPoint& best) {
  Eigen::Matrix<Real, 3, K> A;
  for (int j = 0; j < K; ++j) A.col(j) = w[ids[j + 1]] - w[ids[0]];
  const Eigen::Matrix<Real, K, 1> mu = A.colPivHouseholderQr().solve(RVec(-w[ids[0]]));
  if (!mu.allFinite()) return;
  std::array<Real, 4> lambda{};
  lambda[ids[0]] = Real(1) - mu.sum();
  for (int j = 0; j < K; ++j) lambda[ids[j + 1]] = mu[j];
  for (int k = 0; k < K + 1; ++k)
    if (lambda[ids[k]] < Real(0)) return;
  RVec p = RVec::Zero();
  for (int k = 0; k < K + 1; ++k) p += lambda[ids[k]] * w[ids[k]];
  const Real d = p.norm();
  if (d < best.distance) {
    best.distance = d;
    best.point = p;
    best.lambda = lambda;
  }
}

}  // namespace detail

/// Brute force over every sub-simplex of the n <= 4 points.
inline ClosestPoint closestToOrigin(const std::array<RVec, 4>& w, int n) {
  ClosestPoint best;
  for (int a = 0; a < n; ++a) {  // vertices: always feasible
    const Real d = w[a].norm();
    if (d < best.distance) {
      best = ClosestPoint{};
      best.distance = d;
      best.point = w[a];
      best.lambda[a] = Real(1);
    }
  }
  for (int a = 0; a < n; ++a)
    for (int b = a + 1; b < n; ++b) {
      detail::tryFeature<1>(w, {a, b}, best);
      for (int c = b + 1; c < n; ++c) {
        detail::tryFeature<2>(w, {a, b, c}, best);
        for (int d = c + 1; d < n; ++d) detail::tryFeature<3>(w, {a, b, c, d}, best);
      }
    }
  return best;
}

template <typename S>
ClosestPoint closestToOrigin(const std::vector<Vector3<S>>& points) {
  std::array<RVec, 4> w;
  for (size_t k = 0; k < points.size(); ++k) w[k] = toReal(points[k]);
  return closestToOrigin(w, static_cast<int>(points.size()));
}

/// A convex polytope in world coordinates (long double), from a Polytope and its pose.
struct WorldPolytope {
  std::vector<RVec> vertices;
  std::vector<std::array<int, 3>> triangles;
  std::vector<std::pair<int, int>> edges;
  std::vector<RVec> faceNormals;  // unit, outward
  std::vector<Real> faceOffsets;  // n . x <= offset inside
  RVec lo, hi;                    // bounding box

  /// The largest signed distance of x past a face plane: <= 0 inside, ~0 on the boundary.
  Real planeDistance(const RVec& x) const {
    Real m = -std::numeric_limits<Real>::infinity();
    for (size_t f = 0; f < faceNormals.size(); ++f) m = std::max(m, faceNormals[f].dot(x) - faceOffsets[f]);
    return m;
  }
  /// max over vertices of s . x
  Real supportValue(const RVec& s) const {
    Real m = -std::numeric_limits<Real>::infinity();
    for (const RVec& v : vertices) m = std::max(m, s.dot(v));
    return m;
  }
};

/// The polytope's vertices and triangles mapped by the pose, computed in long double
/// from the very same float/double numbers GJK sees.
template <typename S>
WorldPolytope toWorld(const Polytope<S>& shape, const Pose<S>& pose) {
  WorldPolytope out;
  const Eigen::Matrix<Real, 3, 3> R = pose.rotation.template cast<Real>();
  const RVec t = toReal(pose.translation);
  RVec centroid = RVec::Zero();
  for (const auto& v : shape.vertices()) {
    out.vertices.push_back(R * toReal(v) + t);
    centroid += out.vertices.back();
  }
  centroid /= Real(out.vertices.size());
  out.triangles = shape.triangles();
  std::set<std::pair<int, int>> edges;
  for (const auto& tri : out.triangles) {
    for (int k = 0; k < 3; ++k) {
      const int a = tri[k], b = tri[(k + 1) % 3];
      edges.insert({std::min(a, b), std::max(a, b)});
    }
    const RVec& a = out.vertices[tri[0]];
    RVec n = (out.vertices[tri[1]] - a).cross(out.vertices[tri[2]] - a);
    if (!(n.norm() > Real(0))) continue;
    n.normalize();
    if (n.dot(a - centroid) < 0) n = -n;  // outward whatever the winding
    out.faceNormals.push_back(n);
    out.faceOffsets.push_back(n.dot(a));
  }
  out.edges.assign(edges.begin(), edges.end());
  out.lo = out.hi = out.vertices[0];
  for (const RVec& v : out.vertices) {
    out.lo = out.lo.cwiseMin(v);
    out.hi = out.hi.cwiseMax(v);
  }
  return out;
}

/// The closest pair of points of the two boundaries, by every feature pair.
struct FeatureDistance {
  Real distance = std::numeric_limits<Real>::infinity();
  RVec p = RVec::Zero(), q = RVec::Zero();
};

namespace detail {
// Distance between two axis-aligned boxes: a lower bound of the distance of anything inside them.
inline Real boxGap(const RVec& lo1, const RVec& hi1, const RVec& lo2, const RVec& hi2) {
  RVec gap;
  for (int k = 0; k < 3; ++k) gap[k] = std::max({Real(0), lo1[k] - hi2[k], lo2[k] - hi1[k]});
  return gap.norm();
}
// Closest points of conv(ps) and conv(qs) (|ps| * |qs| <= 4) via the closest point of
// their Minkowski difference conv{q - p}.
inline void tryPair(const std::vector<RVec>& ps, const std::vector<RVec>& qs, FeatureDistance& best) {
  RVec lo1 = ps[0], hi1 = ps[0], lo2 = qs[0], hi2 = qs[0];
  for (const RVec& p : ps) lo1 = lo1.cwiseMin(p), hi1 = hi1.cwiseMax(p);
  for (const RVec& q : qs) lo2 = lo2.cwiseMin(q), hi2 = hi2.cwiseMax(q);
  if (boxGap(lo1, hi1, lo2, hi2) >= best.distance) return;  // cannot beat the best pair
  std::array<RVec, 4> w;
  std::array<std::pair<int, int>, 4> from;
  int n = 0;
  for (size_t i = 0; i < ps.size(); ++i)
    for (size_t j = 0; j < qs.size(); ++j) {
      w[n] = qs[j] - ps[i];
      from[n++] = {int(i), int(j)};
    }
  const ClosestPoint c = closestToOrigin(w, n);
  if (c.distance < best.distance) {
    best.distance = c.distance;
    best.p = best.q = RVec::Zero();
    for (int k = 0; k < n; ++k) {
      best.p += c.lambda[k] * ps[from[k].first];
      best.q += c.lambda[k] * qs[from[k].second];
    }
  }
}
}  // namespace detail

/// The distance between the boundaries of P and Q: the nearest of all vertex-triangle,
/// triangle-vertex and edge-edge pairs. (Equal to the distance between the solids when
/// they do not overlap.)
inline FeatureDistance boundaryDistance(const WorldPolytope& P, const WorldPolytope& Q) {
  FeatureDistance best;
  for (const RVec& p : P.vertices)  // vertex-vertex first: a good bound prunes the rest
    for (const RVec& q : Q.vertices) detail::tryPair({p}, {q}, best);
  for (const RVec& p : P.vertices)
    for (const auto& t : Q.triangles)
      detail::tryPair({p}, {Q.vertices[t[0]], Q.vertices[t[1]], Q.vertices[t[2]]}, best);
  for (const auto& t : P.triangles)
    for (const RVec& q : Q.vertices)
      detail::tryPair({P.vertices[t[0]], P.vertices[t[1]], P.vertices[t[2]]}, {q}, best);
  for (const auto& e : P.edges)
    for (const auto& f : Q.edges)
      detail::tryPair({P.vertices[e.first], P.vertices[e.second]}, {Q.vertices[f.first], Q.vertices[f.second]},
                      best);
  return best;
}

/// Separating-axis test: the largest gap between the projections of P and Q over the
/// face normals of both and the cross products of every edge pair. Positive: disjoint
/// (two convex polytopes are disjoint iff one of these axes separates them).
inline Real separatingAxisGap(const WorldPolytope& P, const WorldPolytope& Q) {
  Real best = -std::numeric_limits<Real>::infinity();
  auto axisGap = [&](const RVec& axis) {
    // gap along +axis (Q beyond P) and along -axis (P beyond Q)
    Real pMax = -std::numeric_limits<Real>::infinity(), pMin = -pMax, qMax = pMax, qMin = pMin;
    for (const RVec& v : P.vertices) {
      const Real x = axis.dot(v);
      pMax = std::max(pMax, x), pMin = std::min(pMin, x);
    }
    for (const RVec& v : Q.vertices) {
      const Real x = axis.dot(v);
      qMax = std::max(qMax, x), qMin = std::min(qMin, x);
    }
    best = std::max(best, std::max(qMin - pMax, pMin - qMax));
  };
  for (const RVec& n : P.faceNormals) axisGap(n);
  for (const RVec& n : Q.faceNormals) axisGap(n);
  for (const auto& e : P.edges)
    for (const auto& f : Q.edges) {
      RVec axis = (P.vertices[e.second] - P.vertices[e.first]).cross(Q.vertices[f.second] - Q.vertices[f.first]);
      const Real n = axis.norm();
      if (!(n > Real(0))) continue;
      axisGap(axis / n);
    }
  return best;
}

}  // namespace gjkx::test
