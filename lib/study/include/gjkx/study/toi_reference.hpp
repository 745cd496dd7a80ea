/// @file
/// @brief The time-of-impact study's independent reference: the long-double distance of two
/// placed shapes and their first contact over [0, 1] (`ref`, `computeReference`).
///

/// The reference time of impact is computed here, independently of every method of the
/// study (no GJK, no support mapping): in long double,
/// - the distance between two placed shapes is a brute force over feature pairs
///   (vertex-vertex, vertex-edge, vertex-triangle, edge-edge) of their cores (a polytope,
///   a segment for a capsule, a point for a sphere) less the radii, with an edge crossing
///   a triangle or a vertex inside a solid counting as contact (distance 0). Features far
///   from the other body are skipped by a bounding-sphere test that cannot change the minimum;
/// - the distance d(t) changes no faster than L, the sum over both bodies of
///   |v| + |a| + |w| r (r: the body's bounding radius about its origin). The interval is
///   sampled densely (64 samples), and each gap between two samples [ta, tb] is proven
///   free of contact when (d(ta) + d(tb) - L (tb - ta)) / 2 > threshold, else split in two
///   (left half first), down to 1e-13: the first time d(t) <= threshold is found by
///   bisection, and no contact between samples (tunnelling) can slip through
///   (gjkx::reference::firstContact; the closest points are the reference library's too).
/// The reference hits when d(t) <= 1e-10 somewhere in [0, 1]; it is a clear miss when
/// d(t) > kClearMargin (0.02) everywhere. Queries in between are judged for neither misses
/// nor false alarms.
///
/// The 2D set (polygons and disks in the plane z = 0, motions in that plane) has its own
/// 2D reference: polygon-polygon distance by vertex-edge pairs, contact by a vertex inside
/// or two edges crossing.
///
/// Part of the study's workloads (workloads.hpp, the header to include); the queries it
/// judges: toi_query.hpp.
#pragma once

#include <gjkx/study/shape_description.hpp>
#include <gjkx/study/toi_query.hpp>

#include <gjkx/reference/polytope_distance.hpp>
#include <gjkx/reference/time_of_impact.hpp>

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

namespace gjkx::study {


/// The reference's scalar.
using LD = long double;
/// A point of the reference.
using V3L = Eigen::Matrix<LD, 3, 1>;
/// A rotation of the reference.
using M3L = Eigen::Matrix<LD, 3, 3>;

// ---------------------------------------------------------------------------------------
// The reference (long double)
/// The time-of-impact study's independent reference: long-double distances of placed
/// shapes and their first contact over [0, 1] (see the file comment).
namespace ref {

// The closest points and the contact test come from the reference library (long double,
// sliver-safe; gjkx/reference/closest_points.hpp and polytope_distance.hpp).
using reference::pointSegmentDistance;
using reference::pointTriangleDistance;
using reference::segmentCrossesTriangle;
using reference::segmentSegmentDistance;

/// A shape's core (vertices, edges, triangles) and skin radius, in the body frame.
struct Body {
  std::vector<V3L> v;                  ///< the core's vertices
  std::vector<std::array<int, 2>> e;   ///< its edges (vertex pairs)
  std::vector<std::array<int, 3>> f;   ///< its triangles (a closed polytope's)
  LD skin = 0;                         ///< the radius around the core (sphere, capsule, disk)
  bool solid = false;   ///< closed polytope: containment counts
  LD radius = 0;        ///< bounding radius of the whole shape about the body origin
};

/// The reference's body for a shape description.
inline Body body(const ShapeDescription& s) {
  Body b;
  b.radius = LD(s.boundingRadius());
  switch (s.kind) {
    case ShapeKind::Sphere:
    case ShapeKind::Disk:
      b.v.push_back(V3L::Zero());
      b.skin = LD(s.radius);
      return b;
    case ShapeKind::Capsule:
      b.v.push_back(V3L(0, 0, -LD(s.halfLength)));
      b.v.push_back(V3L(0, 0, LD(s.halfLength)));
      b.e.push_back({0, 1});
      b.skin = LD(s.radius);
      return b;
    case ShapeKind::Box:
    case ShapeKind::Polytope:
    case ShapeKind::Polygon: {
      const Polytope<double>& h = *s.hull;
      for (const auto& x : h.vertices()) b.v.push_back(x.cast<LD>());
      if (h.planar()) {  // the boundary ring, by angle about the centroid
        std::vector<int> order(b.v.size());
        for (std::size_t i = 0; i < order.size(); ++i) order[i] = int(i);
        const V3L c = h.center().cast<LD>();
        auto angle = [&](int i) { return std::atan2(double(b.v[i].y() - c.y()), double(b.v[i].x() - c.x())); };
        std::sort(order.begin(), order.end(), [&](int i, int j) { return angle(i) < angle(j); });
        for (std::size_t i = 0; i < order.size(); ++i) b.e.push_back({order[i], order[(i + 1) % order.size()]});
        return b;
      }
      for (int i = 0; i < h.vertexCount(); ++i)
        for (int n : h.neighbours(i))
          if (i < n) b.e.push_back({i, n});
      {
        b.f = h.triangles();
        b.solid = true;
      }
      return b;
    }
  }
  return b;
}

/// A body placed in the world, with a bounding sphere per feature.
struct Placed {
  std::vector<V3L> v;   ///< the vertices in the world
  std::vector<V3L> ec;  ///< the edges' centres
  std::vector<V3L> fc;  ///< the triangles' centres
  std::vector<LD> er;   ///< the edges' bounding radii
  std::vector<LD> fr;   ///< the triangles' bounding radii
  V3L centre;           ///< the body origin in the world
  LD radius;            ///< the core's bounding radius about it
};

/// Places a body at the pose (R, p), with each feature's bounding sphere.
inline void place(const Body& b, const M3L& R, const V3L& p, Placed& w) {
  w.v.resize(b.v.size());
  for (std::size_t i = 0; i < b.v.size(); ++i) w.v[i] = R * b.v[i] + p;
  w.ec.resize(b.e.size());
  w.er.resize(b.e.size());
  for (std::size_t i = 0; i < b.e.size(); ++i) {
    const V3L& x = w.v[b.e[i][0]];
    const V3L& y = w.v[b.e[i][1]];
    w.ec[i] = (x + y) / 2;
    w.er[i] = (x - y).norm() / 2;
  }
  w.fc.resize(b.f.size());
  w.fr.resize(b.f.size());
  for (std::size_t i = 0; i < b.f.size(); ++i) {
    const V3L& x = w.v[b.f[i][0]];
    const V3L& y = w.v[b.f[i][1]];
    const V3L& z = w.v[b.f[i][2]];
    w.fc[i] = (x + y + z) / 3;
    w.fr[i] = std::max({(x - w.fc[i]).norm(), (y - w.fc[i]).norm(), (z - w.fc[i]).norm()});
  }
  w.centre = p;
  w.radius = b.radius - b.skin;
}

/// Whether x is inside a placed solid body (behind every triangle).
inline bool inside(const V3L& x, const Body& b, const Placed& w) {
  for (const auto& f : b.f) {
    const V3L& a = w.v[f[0]];
    const V3L n = (w.v[f[1]] - a).cross(w.v[f[2]] - a);
    if (n.dot(x - a) > 0) return false;
  }
  return true;
}

/// The distance between two placed bodies (0 in contact); see the file comment.
inline LD distance(const Body& A, const Placed& a, const Body& B, const Placed& b) {
  // Features of one body that could be within `reach` of the other body's bounding sphere.
  auto near = [](const std::vector<V3L>& c, const std::vector<LD>* r, const Placed& other, LD reach) {
    std::vector<int> keep;
    for (std::size_t i = 0; i < c.size(); ++i)
      if ((c[i] - other.centre).norm() - (r ? (*r)[i] : LD(0)) - other.radius <= reach) keep.push_back(int(i));
    return keep;
  };
  // Contact: an edge of one crossing a triangle of the other, or one inside the other.
  {
    const auto eA = near(a.ec, &a.er, b, 0), eB = near(b.ec, &b.er, a, 0);
    const auto fA = near(a.fc, &a.fr, b, 0), fB = near(b.fc, &b.fr, a, 0);
    for (int i : eA)
      for (int j : fB)
        if ((a.ec[i] - b.fc[j]).norm() <= a.er[i] + b.fr[j] &&
            segmentCrossesTriangle(a.v[A.e[i][0]], a.v[A.e[i][1]], b.v[B.f[j][0]], b.v[B.f[j][1]], b.v[B.f[j][2]]))
          return 0;
    for (int i : eB)
      for (int j : fA)
        if ((b.ec[i] - a.fc[j]).norm() <= b.er[i] + a.fr[j] &&
            segmentCrossesTriangle(b.v[B.e[i][0]], b.v[B.e[i][1]], a.v[A.f[j][0]], a.v[A.f[j][1]], a.v[A.f[j][2]]))
          return 0;
    if (B.solid && inside(a.v[0], B, b)) return 0;
    if (A.solid && inside(b.v[0], A, a)) return 0;
  }
  // An upper bound: the closest vertex pair.
  LD best = std::numeric_limits<LD>::infinity();
  {
    const LD coarse = std::max(LD(0), (a.centre - b.centre).norm());  // any reach that keeps a vertex pair
    auto vA = near(a.v, nullptr, b, coarse + a.radius + b.radius);
    auto vB = near(b.v, nullptr, a, coarse + a.radius + b.radius);
    for (int i : vA)
      for (int j : vB) best = std::min(best, (a.v[i] - b.v[j]).norm());
  }
  const auto vA = near(a.v, nullptr, b, best), vB = near(b.v, nullptr, a, best);
  const auto eA = near(a.ec, &a.er, b, best), eB = near(b.ec, &b.er, a, best);
  const auto fA = near(a.fc, &a.fr, b, best), fB = near(b.fc, &b.fr, a, best);
  for (int i : vA) {
    for (int j : fB)
      if ((a.v[i] - b.fc[j]).norm() - b.fr[j] < best)
        best = std::min(best, pointTriangleDistance(a.v[i], b.v[B.f[j][0]], b.v[B.f[j][1]], b.v[B.f[j][2]]));
    for (int j : eB)
      if ((a.v[i] - b.ec[j]).norm() - b.er[j] < best)
        best = std::min(best, pointSegmentDistance(a.v[i], b.v[B.e[j][0]], b.v[B.e[j][1]]));
  }
  for (int j : vB) {
    for (int i : fA)
      if ((b.v[j] - a.fc[i]).norm() - a.fr[i] < best)
        best = std::min(best, pointTriangleDistance(b.v[j], a.v[A.f[i][0]], a.v[A.f[i][1]], a.v[A.f[i][2]]));
    for (int i : eA)
      if ((b.v[j] - a.ec[i]).norm() - a.er[i] < best)
        best = std::min(best, pointSegmentDistance(b.v[j], a.v[A.e[i][0]], a.v[A.e[i][1]]));
  }
  for (int i : eA)
    for (int j : eB)
      if ((a.ec[i] - b.ec[j]).norm() - a.er[i] - b.er[j] < best)
        best = std::min(best, segmentSegmentDistance(a.v[A.e[i][0]], a.v[A.e[i][1]], b.v[B.e[j][0]], b.v[B.e[j][1]]));
  return std::max(LD(0), best - A.skin - B.skin);
}

// 2D (z = 0): polygons as vertex loops (edges from the hull's neighbours), disks as points.
/// The z of the cross product of a and b (2D).
inline LD cross2(const V3L& a, const V3L& b) { return a.x() * b.y() - a.y() * b.x(); }
/// Whether the segments [p, q] and [r, s] of the plane cross properly.
inline bool segmentsCross2(const V3L& p, const V3L& q, const V3L& r, const V3L& s) {
  const LD d1 = cross2(q - p, r - p), d2 = cross2(q - p, s - p), d3 = cross2(s - r, p - r), d4 = cross2(s - r, q - r);
  return ((d1 > 0) != (d2 > 0)) && ((d3 > 0) != (d4 > 0)) && d1 != 0 && d2 != 0 && d3 != 0 && d4 != 0;
}
/// Whether x is inside a placed convex polygon.
inline bool inside2(const V3L& x, const Body& b, const Placed& w) {
  if (b.e.size() < 3) return false;
  // Convex polygon: x is inside when it is on the same side of every edge as the centroid.
  V3L c = V3L::Zero();
  for (const auto& y : w.v) c += y;
  c /= LD(w.v.size());
  for (const auto& e : b.e) {
    const LD sx = cross2(w.v[e[1]] - w.v[e[0]], x - w.v[e[0]]);
    const LD sc = cross2(w.v[e[1]] - w.v[e[0]], c - w.v[e[0]]);
    if ((sx > 0) != (sc > 0) && sx != 0) return false;
  }
  return true;
}
/// The distance between two placed 2D bodies (0 in contact).
inline LD distance2d(const Body& A, const Placed& a, const Body& B, const Placed& b) {
  for (const auto& e : A.e)
    for (const auto& f : B.e)
      if (segmentsCross2(a.v[e[0]], a.v[e[1]], b.v[f[0]], b.v[f[1]])) return 0;
  if (inside2(a.v[0], B, b) || inside2(b.v[0], A, a)) return 0;
  LD best = std::numeric_limits<LD>::infinity();
  for (const auto& x : a.v)
    for (const auto& y : b.v) best = std::min(best, (x - y).norm());
  for (const auto& x : a.v)
    for (const auto& f : B.e) best = std::min(best, pointSegmentDistance(x, b.v[f[0]], b.v[f[1]]));
  for (const auto& y : b.v)
    for (const auto& e : A.e) best = std::min(best, pointSegmentDistance(y, a.v[e[0]], a.v[e[1]]));
  return std::max(LD(0), best - A.skin - B.skin);
}

/// The pose of a motion at t, in long double.
inline void poseAt(const MotionSpec& m, LD t, M3L& R, V3L& p) {
  const V3L w = m.w.cast<LD>();
  const LD speed = w.norm();
  R = m.R0.cast<LD>();
  if (speed > 0) R = Eigen::AngleAxis<LD>(speed * t, w / speed).toRotationMatrix() * R;
  p = m.p0.cast<LD>() + m.v.cast<LD>() * t + m.a.cast<LD>() * (t * t / 2);
}

/// A query's distance function d(t) and its Lipschitz bound L.
class DistanceFunction {
 public:
  /// The distance function of a query (which must outlive it).
  explicit DistanceFunction(const ToiQuery& q) : q_(q), A_(body(q.P)), B_(body(q.Q)) {
    auto bound = [](const MotionSpec& m, const ShapeDescription& s) {
      return LD(m.v.norm()) + LD(m.a.norm()) + LD(m.w.norm()) * LD(s.boundingRadius());
    };
    lipschitz_ = (bound(q.motionP, q.P) + bound(q.motionQ, q.Q)) * LD(1.000001) + LD(1e-30);
  }
  /// d(t): the distance of the query's bodies at t.
  LD operator()(LD t) {
    M3L R;
    V3L p;
    poseAt(q_.motionP, t, R, p);
    place(A_, R, p, a_);
    poseAt(q_.motionQ, t, R, p);
    place(B_, R, p, b_);
    ++evaluations;
    return q_.planar ? distance2d(A_, a_, B_, b_) : distance(A_, a_, B_, b_);
  }
  /// L: |d'(t)| <= L over [0, 1].
  LD lipschitz() const { return lipschitz_; }
  /// Evaluations of d so far.
  long evaluations = 0;

 private:
  const ToiQuery& q_;
  Body A_, B_;
  Placed a_, b_;
  LD lipschitz_;
};

/// The first time in [0, 1] the bodies come within `threshold` (0 if they start so), or -1:
/// the reference library's dense sampling with bisection (gjkx/reference/time_of_impact.hpp)
/// on d(t), 64 samples, bracket 1e-13.
inline LD firstContact(DistanceFunction& d, LD threshold) {
  return reference::firstContact(d, d.lipschitz(), threshold);
}

}  // namespace ref

/// Fills in the reference of a query (refHit, tRef, clearMiss).
inline void computeReference(ToiQuery& q) {
  ref::DistanceFunction d(q);
  const LD t = ref::firstContact(d, LD(kReferenceThreshold));
  q.refHit = t >= 0;
  q.tRef = q.refHit ? double(t) : 1.0;
  q.clearMiss = !q.refHit && ref::firstContact(d, LD(kClearMargin)) < 0;
}

}  // namespace gjkx::study
