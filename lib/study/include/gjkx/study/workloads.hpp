/// @file
/// @brief The time-of-impact workloads of the study (chapters/09_study) and their
/// independent reference.
///
/// Holds (namespace gjkx::study): the query (`MotionSpec`, `ToiQuery`, `ToiWorkload`,
/// `relativeSpeedBound`), the long-double reference (`ref`, `computeReference`) and the
/// generator of the workloads (`gen`, `makeWorkloads`). Shapes are the study's one
/// description, shape_description.hpp.
///
/// A query is two shapes P and Q, each moving over [0, 1] along a rigid motion given by
/// its parameters (start pose, velocity v, acceleration a, angular velocity w about the body
/// origin): R(t) = exp([w] t) R0, p(t) = p0 + v t + a t^2 / 2. Linear, ballistic and screw
/// motions are the three special cases (w = 0 and a = 0; w = 0; a = 0).
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
#pragma once

#include <gjkx/study/shape_description.hpp>

#include <gjkx/motion/motion.hpp>
#include <gjkx/support_mapping/polytope.hpp>
#include <gjkx/support_mapping/primitives.hpp>
#include <gjkx/reference/polytope_distance.hpp>
#include <gjkx/reference/time_of_impact.hpp>

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <random>
#include <stdexcept>
#include <string>
#include <variant>
#include <vector>

namespace gjkx::study {

/// The reference's scalar.
using LD = long double;
/// A point of the reference.
using V3L = Eigen::Matrix<LD, 3, 1>;
/// A rotation of the reference.
using M3L = Eigen::Matrix<LD, 3, 3>;

/// The reference says "hit" when the bodies come within this distance.
constexpr double kReferenceThreshold = 1e-10;
/// A reference non-hit counts as a clear miss (a hit reported there is a false alarm) when
/// the bodies stay farther apart than this over the whole interval.
constexpr double kClearMargin = 0.02;

// ---------------------------------------------------------------------------------------
// Motions and queries

/// A rigid motion over [0, 1] by its parameters (see the file comment).
struct MotionSpec {
  /// The body origin at t = 0.
  Eigen::Vector3d p0 = Eigen::Vector3d::Zero();
  /// The rotation at t = 0.
  Eigen::Matrix3d R0 = Eigen::Matrix3d::Identity();
  /// Velocity of the body origin.
  Eigen::Vector3d v = Eigen::Vector3d::Zero();
  /// Acceleration of the body origin.
  Eigen::Vector3d a = Eigen::Vector3d::Zero();
  /// Angular velocity about the body origin.
  Eigen::Vector3d w = Eigen::Vector3d::Zero();

  /// Whether the body turns.
  bool rotates() const { return w.squaredNorm() > 0; }
  /// Whether the body accelerates.
  bool accelerates() const { return a.squaredNorm() > 0; }
  /// The pose at t in double (for the peers' start and end poses).
  std::pair<Eigen::Matrix3d, Eigen::Vector3d> poseAt(double t) const {
    Eigen::Matrix3d R = R0;
    const double speed = w.norm();
    if (speed > 0) R = Eigen::AngleAxisd(speed * t, w / speed).toRotationMatrix() * R0;
    return {R, p0 + v * t + a * (0.5 * t * t)};
  }
  /// The pose at t as the library's `Pose<double>`.
  Pose<double> pose(double t) const {
    const auto [R, p] = poseAt(t);
    Pose<double> out;
    out.rotation = R;
    out.translation = p;
    return out;
  }
  /// A bound on the speed of any point of a shape of bounding radius r carried by this
  /// motion over [0, 1]: |v| + |a| + |w| r.
  double speedBound(double r) const { return v.norm() + a.norm() + w.norm() * r; }
};

/// The motion as the library's `Motion<S>` (constant velocity, constant acceleration or screw).
template <typename S>
Motion<S> toMotion(const MotionSpec& m) {
  Pose<S> start;
  start.rotation = m.R0.cast<S>();
  start.translation = m.p0.cast<S>();
  if (m.rotates()) return Motion<S>::screw(start, m.v.cast<S>(), m.w.cast<S>());
  if (m.accelerates()) return Motion<S>::constantAcceleration(start, m.v.cast<S>(), m.a.cast<S>());
  return Motion<S>::constantVelocity(start, m.v.cast<S>());
}

/// One query with its reference.
struct ToiQuery {
  /// The first body's shape.
  ShapeDescription P;
  /// The second body's shape.
  ShapeDescription Q;
  /// P's motion.
  MotionSpec motionP;
  /// Q's motion.
  MotionSpec motionQ;
  bool refHit = false;     ///< the bodies come within kReferenceThreshold in [0, 1]
  double tRef = 1;         ///< the first such time
  bool clearMiss = false;  ///< never within kClearMargin
  bool planar = false;     ///< 2D query (polygons, disks, motion in z = 0)
};

/// A named set of queries.
struct ToiWorkload {
  /// Its name in the tables ("linear", "screw_w1.5", "planar_2d", ...).
  std::string name;
  /// What its queries are, in one line.
  std::string description;
  /// The 2D set (Box2D's).
  bool planar = false;
  /// The queries, each with its reference.
  std::vector<ToiQuery> queries;
};

/// L of a query: a bound on how fast the distance between its bodies can change (the sum of
/// both bodies' speed bounds about their bounding radii, 1e-6 larger), the bound the
/// conservative advancement of the study steps with.
inline double relativeSpeedBound(const ToiQuery& q) {
  return (q.motionP.speedBound(q.P.boundingRadius()) + q.motionQ.speedBound(q.Q.boundingRadius())) * 1.000001;
}

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

// ---------------------------------------------------------------------------------------
// The workloads

/// Options of the generator.
struct WorkloadOptions {
  /// Queries in each workload.
  int queriesPerWorkload = 48;
  /// Seed of the generator.
  std::uint64_t seed = 4;
};

/// The generator of the workloads.
namespace gen {

/// A small deterministic generator (the same numbers on every platform).
struct Random {
  /// The engine.
  std::mt19937_64 engine;
  /// A generator from a seed.
  explicit Random(std::uint64_t seed) : engine(seed) {}
  /// Uniform in [lo, hi), from the engine's top 53 bits.
  double uniform(double lo = 0, double hi = 1) { return lo + (hi - lo) * double(engine() >> 11) * 0x1.0p-53; }
  /// Uniform in {0, ..., n - 1}.
  int integer(int n) { return int(engine() % std::uint64_t(n)); }
  /// A random unit vector (rejection sampling in the unit ball).
  Eigen::Vector3d unit() {
    for (;;) {
      const Eigen::Vector3d x(uniform(-1, 1), uniform(-1, 1), uniform(-1, 1));
      const double n = x.norm();
      if (n > 0.1 && n <= 1) return x / n;
    }
  }
  /// A random rotation (a uniform angle about a random axis).
  Eigen::Matrix3d rotation() { return Eigen::AngleAxisd(uniform(0, 2 * M_PI), unit()).toRotationMatrix(); }
};

/// n points on an ellipsoid of semi-axes `axes` (all on the hull).
inline ShapeDescription randomPolytope(Random& rng, int n, const Eigen::Vector3d& axes) {
  std::vector<Vector3<double>> points;
  for (int k = 0; k < n; ++k) points.push_back(rng.unit().cwiseProduct(axes));
  return polytopeDescription(points);
}

/// A convex polygon of n vertices in z = 0, one in each of n equal angular sectors, at
/// radius r (squeezed in y by a random 0.6 to 1).
inline ShapeDescription randomPolygon(Random& rng, int n, double r) {
  std::vector<Vector3<double>> points;
  for (int k = 0; k < n; ++k) {
    const double a = 2 * M_PI * (k + rng.uniform(0.1, 0.9)) / n;
    points.emplace_back(r * std::cos(a), r * rng.uniform(0.6, 1.0) * std::sin(a), 0);
  }
  return polygonDescription(points);
}

/// A shape of medium size (about 0.3 to 0.8): box, capsule or polytope of 12, 100 or 1000 vertices.
inline ShapeDescription mediumShape(Random& rng, int which) {
  switch (which) {
    case 0: return boxDescription(Eigen::Vector3d(rng.uniform(0.2, 0.6), rng.uniform(0.2, 0.6), rng.uniform(0.1, 0.5)));
    case 1: return capsuleDescription(rng.uniform(0.2, 0.5), rng.uniform(0.1, 0.3));
    case 2: return randomPolytope(rng, 12, Eigen::Vector3d(rng.uniform(0.3, 0.6), rng.uniform(0.3, 0.6), rng.uniform(0.2, 0.5)));
    case 3: return randomPolytope(rng, 100, Eigen::Vector3d(rng.uniform(0.3, 0.6), rng.uniform(0.3, 0.6), rng.uniform(0.2, 0.5)));
    default: return randomPolytope(rng, 1000, Eigen::Vector3d(rng.uniform(0.3, 0.6), rng.uniform(0.3, 0.6), rng.uniform(0.2, 0.5)));
  }
}

/// P's velocity (and acceleration) to reach `target` at time `arrive` from p0.
inline Eigen::Vector3d aim(const Eigen::Vector3d& p0, const Eigen::Vector3d& target, const Eigen::Vector3d& a, double arrive) {
  return (target - p0 - 0.5 * a * arrive * arrive) / arrive;
}

/// A random offset perpendicular to `dir` of length `length`.
inline Eigen::Vector3d sideways(Random& rng, const Eigen::Vector3d& dir, double length) {
  Eigen::Vector3d x = rng.unit();
  x -= dir * dir.dot(x);
  if (x.norm() < 1e-6) x = dir.unitOrthogonal();
  return x.normalized() * length;
}

/// Two bodies flying at each other (hit: aimed within a fraction of the smaller size) or
/// past each other (miss: the bounding spheres pass a clear margin apart), with the given
/// acceleration and angular speed.
inline ToiQuery encounter(Random& rng, ShapeDescription P, ShapeDescription Q, bool hit, double accel, double spin, double speed = 4) {
  ToiQuery q;
  q.P = std::move(P);
  q.Q = std::move(Q);
  const double rP = q.P.boundingRadius(), rQ = q.Q.boundingRadius();
  q.motionQ.R0 = rng.rotation();
  q.motionQ.v = rng.unit() * rng.uniform(0, 0.3);
  const Eigen::Vector3d dir = rng.unit();
  q.motionP.R0 = rng.rotation();
  q.motionP.p0 = -dir * (rP + rQ + 0.1 + speed * rng.uniform(0.2, 0.5));
  q.motionP.a = accel > 0 ? Eigen::Vector3d(rng.unit() * accel) : Eigen::Vector3d::Zero();
  if (spin > 0) q.motionP.w = rng.unit() * spin;
  if (spin > 0 && rng.uniform() < 0.5) q.motionQ.w = rng.unit() * spin * 0.5;
  const double arrive = rng.uniform(0.35, 1.1);
  // Q's centre at `arrive`, and an offset: small for a hit, beyond both bounding radii for a miss.
  const Eigen::Vector3d qAt = q.motionQ.v * arrive;
  const Eigen::Vector3d offset = hit ? sideways(rng, dir, rng.uniform(0, 0.3) * std::min(rP, rQ))
                                     : sideways(rng, dir, rP + rQ + rng.uniform(0.05, 0.5));
  q.motionP.v = aim(q.motionP.p0, qAt + offset, q.motionP.a, arrive);
  return q;
}

}  // namespace gen

/// The 3D workloads and the 2D set; each query with its reference.
inline std::vector<ToiWorkload> makeWorkloads(const WorkloadOptions& o) {
  using gen::Random;
  std::vector<ToiWorkload> out;
  const int n = o.queriesPerWorkload;
  Random rng(o.seed);
  // Shape pairs: P from box, capsule, poly12, poly100, poly1000 (1 in 8); Q never poly1000.
  auto shapeP = [&](int k) { return gen::mediumShape(rng, k % 8 == 7 ? 4 : k % 4); };
  auto shapeQ = [&](int k) { return gen::mediumShape(rng, (k / 4) % 4); };

  auto encounters = [&](const std::string& name, const std::string& description, double accel, double spin) {
    ToiWorkload w{name, description, false, {}};
    for (int k = 0; k < n; ++k) {
      ShapeDescription P = shapeP(k), Q = shapeQ(k);
      w.queries.push_back(gen::encounter(rng, std::move(P), std::move(Q), k % 3 != 2, accel, spin));
    }
    out.push_back(std::move(w));
  };
  encounters("linear", "constant velocity, boxes/capsules/polytopes of 12-1000 vertices, 2/3 aimed to hit", 0, 0);
  encounters("ballistic", "constant acceleration |a| = 6 (curved paths), aimed along the parabola", 6, 0);
  encounters("screw_w0.5", "screw motion, 0.5 rad per interval", 0, 0.5);
  encounters("screw_w1.5", "screw motion, 1.5 rad per interval", 0, 1.5);
  encounters("screw_w3.0", "screw motion, 3.0 rad per interval (almost half a turn)", 0, 3.0);

  {  // The paper's tunnelling case: a small fast box through a thin plate.
    ToiWorkload w{"thin_plate", "small box (0.01-0.05) at speed 2-6 through a plate 0.005 thick; 1/4 pass beside it", false, {}};
    for (int k = 0; k < n; ++k) {
      ToiQuery q;
      q.Q = boxDescription(Eigen::Vector3d(1, 1, 0.0025));
      q.motionQ.R0 = Eigen::Matrix3d::Identity();
      const double h = rng.uniform(0.01, 0.05);
      q.P = k % 2 ? boxDescription(Eigen::Vector3d(h, h, h)) : gen::randomPolytope(rng, 12, Eigen::Vector3d(h, h, h));
      q.motionP.R0 = rng.rotation();
      const double speed = rng.uniform(2, 6);
      const bool beside = k % 4 == 3;
      q.motionP.p0 = Eigen::Vector3d(rng.uniform(-0.8, 0.8) + (beside ? 2.2 : 0), rng.uniform(-0.8, 0.8), speed * rng.uniform(0.2, 0.8));
      q.motionP.v = Eigen::Vector3d(rng.uniform(-0.3, 0.3), rng.uniform(-0.3, 0.3), -speed);
      if (k % 3 == 0) q.motionP.w = rng.unit() * 2.0;
      w.queries.push_back(q);
    }
    out.push_back(std::move(w));
  }
  {  // Small fast objects against medium ones.
    ToiWorkload w{"small_fast", "small sphere/box/poly12 (0.01-0.04) at speed 10-20 at a medium body; 1/3 aimed to miss", false, {}};
    for (int k = 0; k < n; ++k) {
      const double h = rng.uniform(0.01, 0.04);
      ShapeDescription P = k % 3 == 0 ? sphereDescription(h) : (k % 3 == 1 ? boxDescription(Eigen::Vector3d(h, h, h)) : gen::randomPolytope(rng, 12, Eigen::Vector3d(h, h, h)));
      ShapeDescription Q = gen::mediumShape(rng, k % 8 == 5 ? 4 : k % 4);
      w.queries.push_back(gen::encounter(rng, std::move(P), std::move(Q), k % 3 != 1, 0, k % 2 ? 0 : 4.0, rng.uniform(10, 20)));
    }
    out.push_back(std::move(w));
  }
  {  // Near misses: P slides over Q, its lowest point a gap above Q's highest; half are shallow grazes (negative gap).
    ToiWorkload w{"near_miss", "P's lowest point slides over Q's highest at a gap of 0.025-0.1 (clear misses) or -0.05 to -0.005 (grazes)", false, {}};
    for (int k = 0; k < n; ++k) {
      ToiQuery q;
      q.P = shapeP(k);
      q.Q = shapeQ(k + 1);
      q.motionP.R0 = rng.rotation();
      q.motionQ.R0 = rng.rotation();
      // P's lowest point passes straight over Q's highest point, `gap` above it (negative: a graze).
      // The z extents come from the reference's own vertices (cores, plus the skins).
      auto extreme = [](const ShapeDescription& s, const Eigen::Matrix3d& R, double sign) {
        const ref::Body b = ref::body(s);
        Eigen::Vector3d best = Eigen::Vector3d::Zero();
        double value = -1e300;
        for (const auto& x : b.v) {
          const Eigen::Vector3d y = (R * x.cast<double>());
          if (sign * y.z() > value) {
            value = sign * y.z();
            best = y;
          }
        }
        return Eigen::Vector3d(best + Eigen::Vector3d(0, 0, sign * double(b.skin)));
      };
      const double gap = k % 2 ? rng.uniform(0.025, 0.1) : -rng.uniform(0.005, 0.05);
      const Eigen::Vector3d top = extreme(q.Q, q.motionQ.R0, 1), low = extreme(q.P, q.motionP.R0, -1);
      const double speed = rng.uniform(2, 5);
      const double span = q.P.boundingRadius() + q.Q.boundingRadius() + 0.1;
      const Eigen::Vector3d across(std::cos(k * 1.3), std::sin(k * 1.3), 0);
      const Eigen::Vector3d over(top.x() - low.x(), top.y() - low.y(), top.z() + gap - low.z());  // P's origin when low is over top
      const double when = rng.uniform(0.3, 0.8);
      q.motionP.p0 = over - across * (speed * when);
      (void)span;
      q.motionP.v = across * speed;
      w.queries.push_back(q);
    }
    out.push_back(std::move(w));
  }
  {  // Crossing paths (the paper's Fig. 1B): both bodies fast, their paths cross; at the same time (hit) or not (miss).
    ToiWorkload w{"crossing", "P and Q both fast (speed 3-6), paths crossing; they reach the crossing together (hit) or apart (miss)", false, {}};
    for (int k = 0; k < n; ++k) {
      ToiQuery q;
      q.P = shapeP(k);
      q.Q = shapeQ(k + 2);
      q.motionP.R0 = rng.rotation();
      q.motionQ.R0 = rng.rotation();
      const Eigen::Vector3d dP = rng.unit(), dQ0 = rng.unit();
      const Eigen::Vector3d dQ = (dQ0 - dP * dP.dot(dQ0)).normalized();  // perpendicular paths
      const double sP = rng.uniform(3, 6), sQ = rng.uniform(3, 6);
      const double tP = rng.uniform(0.3, 0.7);
      const double rSum = q.P.boundingRadius() + q.Q.boundingRadius();
      const bool hit = k % 2 == 0;
      // Miss: Q reaches the crossing when P is already rSum + 0.1 to 0.5 past it (or before it).
      const double lag = hit ? rng.uniform(-0.2, 0.2) * rSum / sQ : (rSum + rng.uniform(0.1, 0.5)) * (1 / sP + 1 / sQ) * (k % 4 == 1 ? 1 : -1);
      const double tQ = tP + lag;
      q.motionP.p0 = -dP * (sP * tP);
      q.motionP.v = dP * sP;
      q.motionQ.p0 = -dQ * (sQ * tQ);
      q.motionQ.v = dQ * sQ;
      w.queries.push_back(q);
    }
    out.push_back(std::move(w));
  }
  {  // 2D: polygons of 3-8 vertices and disks in the plane z = 0 (Box2D's set).
    ToiWorkload w{"planar_2d", "polygons of 3-8 vertices and disks in z = 0, linear + spin up to 3 rad; 2/3 aimed to hit", true, {}};
    for (int k = 0; k < n; ++k) {
      auto planarShape = [&](int j) {
        return j % 4 == 3 ? diskDescription(rng.uniform(0.2, 0.5)) : gen::randomPolygon(rng, 3 + rng.integer(6), rng.uniform(0.3, 0.8));
      };
      ToiQuery q;
      q.planar = true;
      q.P = planarShape(k);
      q.Q = planarShape(k / 2 + 1);
      auto planarRotation = [&] { return Eigen::AngleAxisd(rng.uniform(0, 2 * M_PI), Eigen::Vector3d::UnitZ()).toRotationMatrix(); };
      q.motionP.R0 = planarRotation();
      q.motionQ.R0 = planarRotation();
      const double rP = q.P.boundingRadius(), rQ = q.Q.boundingRadius();
      const double ang = rng.uniform(0, 2 * M_PI);
      const Eigen::Vector3d dir(std::cos(ang), std::sin(ang), 0);
      q.motionP.p0 = -dir * (rP + rQ + 0.1 + rng.uniform(0.5, 2));
      q.motionP.w = Eigen::Vector3d(0, 0, rng.uniform(-3, 3));
      q.motionQ.w = Eigen::Vector3d(0, 0, rng.uniform(-1, 1));
      const double arrive = rng.uniform(0.35, 1.1);
      const bool hit = k % 3 != 2;
      const Eigen::Vector3d side(-dir.y(), dir.x(), 0);
      const Eigen::Vector3d target = side * (hit ? rng.uniform(-0.3, 0.3) * std::min(rP, rQ) : (rP + rQ + rng.uniform(0.05, 0.5)));
      q.motionP.v = (target - q.motionP.p0) / arrive;
      w.queries.push_back(q);
    }
    out.push_back(std::move(w));
  }
  for (auto& w : out)
    for (auto& q : w.queries) computeReference(q);
  return out;
}

}  // namespace gjkx::study
