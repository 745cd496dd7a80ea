/// @file
/// @brief A time-of-impact query of the study (chapters/09_study): two shapes on rigid
/// motions over [0, 1] given by their parameters (`MotionSpec`, `ToiQuery`), a named set
/// of them (`ToiWorkload`), and the speed bound conservative advancement steps with
/// (`relativeSpeedBound`).
///

/// A query is two shapes P and Q, each moving over [0, 1] along a rigid motion given by
/// its parameters (start pose, velocity v, acceleration a, angular velocity w about the body
/// origin): R(t) = exp([w] t) R0, p(t) = p0 + v t + a t^2 / 2. Linear, ballistic and screw
/// motions are the three special cases (w = 0 and a = 0; w = 0; a = 0).
///
/// Each query carries its reference answer (toi_reference.hpp); the workloads are made by
/// workloads.hpp, the header to include. Shapes are the study's one description,
/// shape_description.hpp.
#pragma once

#include <gjkx/study/shape_description.hpp>

#include <gjkx/motion/motion.hpp>

#include <Eigen/Geometry>

#include <string>
#include <utility>
#include <vector>

namespace gjkx::study {

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

}  // namespace gjkx::study
