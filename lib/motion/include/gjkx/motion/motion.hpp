/// @file
/// @brief Rigid motions `pose(t)`: how P(t) and Q(t) move over a time interval (§3, §5).
///
/// The extrusion test of §3 and the time-of-impact solver of §5 see a moving body
/// only through its pose at a time t. Each motion here answers `pose(t)`; a static
/// body does no work at all, and a translating body does no rotation work.
#pragma once

#include <gjkx/motion/pose.hpp>

#include <type_traits>
#include <variant>

namespace gjkx {

/// How fast a motion can bend a body's path: the bounds the certified extrusion test
/// needs (beyond the paper, see gjkx/extrusion/certified_margin.hpp). A body point at
/// distance r from the body origin has acceleration at most
/// \f$\lVert\ddot x\rVert \le a + \alpha r + \omega^2 r\f$ (translation, angular acceleration, centripetal).
template <typename Scalar>
struct MotionBound {
  /// Upper bound of the body origin's acceleration \f$\lVert\ddot p\rVert\f$.
  Scalar linearAcceleration = Scalar(0);
  /// Upper bound of the angular speed \f$\lVert\omega\rVert\f$.
  Scalar angularSpeed = Scalar(0);
  /// Upper bound of the angular acceleration \f$\lVert\dot\omega\rVert\f$.
  Scalar angularAcceleration = Scalar(0);
  /// \f$a + \alpha r + \omega^2 r\f$: the largest acceleration of a body point within `radius` of the origin.
  Scalar pointAcceleration(Scalar radius) const {
    return linearAcceleration + (angularAcceleration + angularSpeed * angularSpeed) * radius;
  }
};

/// A body that does not move: `pose(t)` is the same for every t.
template <typename Scalar>
struct StaticMotion {
  /// The pose at every time.
  Pose<Scalar> start;
  /// The pose at time t (always `start`).
  const Pose<Scalar>& pose(Scalar /*t*/) const { return start; }
  /// No motion at all.
  MotionBound<Scalar> bound() const { return {}; }
  /// The same motion: every parameter equal.
  bool operator==(const StaticMotion& o) const { return start == o.start; }
};

/// Constant linear velocity, no rotation: \f$p(t) = p_0 + v\,(t - t_0)\f$ ("linear motion", §3).
template <typename Scalar>
struct ConstantVelocity {
  /// The pose at time t0.
  Pose<Scalar> start;
  /// Velocity of the body origin, in world units per unit time.
  Vector3<Scalar> velocity = Vector3<Scalar>::Zero();
  /// The time at which the body is at `start`.
  Scalar t0 = Scalar(0);
  /// The pose at time t.
  Pose<Scalar> pose(Scalar t) const {
    Pose<Scalar> p = start;
    p.translation += velocity * (t - t0);
    return p;
  }
  /// Linear motion: nothing bends.
  MotionBound<Scalar> bound() const { return {}; }
  /// The same motion: every parameter equal.
  bool operator==(const ConstantVelocity& o) const { return start == o.start && velocity == o.velocity && t0 == o.t0; }
};

/// Constant acceleration, no rotation (ballistic flight): \f$p(t) = p_0 + v\,\tau + \tfrac12 a\,\tau^2\f$, \f$\tau = t - t_0\f$.
/// A second-order motion in the sense of §3.
template <typename Scalar>
struct ConstantAcceleration {
  /// The pose at time t0.
  Pose<Scalar> start;
  /// Velocity of the body origin at t0.
  Vector3<Scalar> velocity = Vector3<Scalar>::Zero();
  /// Constant acceleration of the body origin (gravity, say).
  Vector3<Scalar> acceleration = Vector3<Scalar>::Zero();
  /// The time at which the body is at `start`.
  Scalar t0 = Scalar(0);
  /// The pose at time t.
  Pose<Scalar> pose(Scalar t) const {
    const Scalar tau = t - t0;
    Pose<Scalar> p = start;
    p.translation += velocity * tau + acceleration * (Scalar(0.5) * tau * tau);
    return p;
  }
  /// The acceleration, and no rotation.
  MotionBound<Scalar> bound() const { return {acceleration.norm(), Scalar(0), Scalar(0)}; }
  /// The same motion: every parameter equal.
  bool operator==(const ConstantAcceleration& o) const { return start == o.start && velocity == o.velocity && acceleration == o.acceleration && t0 == o.t0; }
};

/// Screw motion: constant linear velocity of the body origin and constant angular
/// velocity about it, \f$R(t) = \exp([\omega]\,\tau)\,R_0\f$, \f$p(t) = p_0 + v\,\tau\f$.
/// Rotation makes the motion second order (§3).
template <typename Scalar>
struct ScrewMotion {
  /// The pose at time t0.
  Pose<Scalar> start;
  /// Velocity of the body origin.
  Vector3<Scalar> velocity = Vector3<Scalar>::Zero();
  /// Angular velocity in the world frame (radians per unit time) about the body origin.
  Vector3<Scalar> angularVelocity = Vector3<Scalar>::Zero();
  /// The time at which the body is at `start`.
  Scalar t0 = Scalar(0);
  /// The pose at time t.
  Pose<Scalar> pose(Scalar t) const {
    const Scalar tau = t - t0;
    Pose<Scalar> p = start;
    const Scalar speed = angularVelocity.norm();
    if (speed > Scalar(0)) {
      p.rotation = Eigen::AngleAxis<Scalar>(speed * tau, angularVelocity / speed).toRotationMatrix() * start.rotation;
    }
    p.translation += velocity * tau;
    return p;
  }
  /// Constant angular speed, no linear acceleration.
  MotionBound<Scalar> bound() const { return {Scalar(0), angularVelocity.norm(), Scalar(0)}; }
  /// The same motion: every parameter equal.
  bool operator==(const ScrewMotion& o) const { return start == o.start && velocity == o.velocity && angularVelocity == o.angularVelocity && t0 == o.t0; }
};

/// Interpolation between two poses over [t0, t1]: the translation moves on a line and
/// the rotation turns at constant rate along the shortest arc (quaternion slerp).
/// Outside [t0, t1] the pose is held at the nearest end.
template <typename Scalar>
struct PoseInterpolation {
  /// The pose at t0.
  Pose<Scalar> from;
  /// The pose at t1.
  Pose<Scalar> to;
  /// Start of the interval.
  Scalar t0 = Scalar(0);
  /// End of the interval (t1 > t0).
  Scalar t1 = Scalar(1);
  /// The pose at time t.
  Pose<Scalar> pose(Scalar t) const {
    Scalar u = (t - t0) / (t1 - t0);
    u = u < Scalar(0) ? Scalar(0) : (u > Scalar(1) ? Scalar(1) : u);
    const Eigen::Quaternion<Scalar> q0(from.rotation), q1(to.rotation);
    Pose<Scalar> p;
    p.rotation = q0.slerp(u, q1).toRotationMatrix();
    p.translation = from.translation + u * (to.translation - from.translation);
    return p;
  }
  /// The slerp turns at a constant rate: the angle between the two rotations over t1 - t0.
  MotionBound<Scalar> bound() const {
    const Eigen::Quaternion<Scalar> q0(from.rotation), q1(to.rotation);
    return {Scalar(0), q0.angularDistance(q1) / (t1 - t0), Scalar(0)};
  }
  /// The same motion: every parameter equal.
  bool operator==(const PoseInterpolation& o) const { return from == o.from && to == o.to && t0 == o.t0 && t1 == o.t1; }
};

/// Free flight of a rigid body over [t0, t1], as the dynamics stage hands it to the
/// time-of-impact solver (§5–§6): ballistic translation
/// \f$p(t) = p_0 + v\,\tau + \tfrac12 a\,\tau^2\f$, \f$\tau = t - t_0\f$, and a rotation that turns
/// at a constant rate along the shortest arc (quaternion slerp) from `start.rotation` at t0
/// to `endRotation` at t1, held at the nearest end outside [t0, t1]. The dynamics stage
/// integrates the torque-free rotation accurately and puts the orientation it reached at t1
/// into `endRotation`, so the path ends exactly where the integrated body does. The turn
/// from start to end must be less than a half turn for the shortest arc to be the body's.
template <typename Scalar>
struct FreeFlightPath {
  /// The pose at t0.
  Pose<Scalar> start;
  /// Velocity of the body origin at t0.
  Vector3<Scalar> velocity = Vector3<Scalar>::Zero();
  /// Constant acceleration of the body origin (gravity).
  Vector3<Scalar> acceleration = Vector3<Scalar>::Zero();
  /// The rotation reached at t1.
  Matrix3<Scalar> endRotation = Matrix3<Scalar>::Identity();
  /// Start of the interval.
  Scalar t0 = Scalar(0);
  /// End of the interval (t1 > t0).
  Scalar t1 = Scalar(1);
  /// The pose at time t.
  Pose<Scalar> pose(Scalar t) const {
    const Scalar tau = t - t0;
    Scalar u = tau / (t1 - t0);
    u = u < Scalar(0) ? Scalar(0) : (u > Scalar(1) ? Scalar(1) : u);
    Pose<Scalar> p;
    if (u == Scalar(0)) {
      p.rotation = start.rotation;
    } else if (u == Scalar(1)) {
      p.rotation = endRotation;
    } else {
      const Eigen::Quaternion<Scalar> q0(start.rotation), q1(endRotation);
      p.rotation = q0.slerp(u, q1).toRotationMatrix();
    }
    p.translation = start.translation + velocity * tau + acceleration * (Scalar(0.5) * tau * tau);
    return p;
  }
  /// The path exactly: linear acceleration |a|, angular speed the angle turned over t1 - t0,
  /// no angular acceleration (the slerp turns about a fixed axis at a constant rate).
  MotionBound<Scalar> bound() const {
    const Eigen::Quaternion<Scalar> q0(start.rotation), q1(endRotation);
    return {acceleration.norm(), q0.angularDistance(q1) / (t1 - t0), Scalar(0)};
  }
  /// The same motion: every parameter equal.
  bool operator==(const FreeFlightPath& o) const {
    return start == o.start && velocity == o.velocity && acceleration == o.acceleration &&
           endRotation == o.endRotation && t0 == o.t0 && t1 == o.t1;
  }
};

/// Any of the rigid motions above, behind one `pose(t)`.
///
/// Build one through the named constructors, which validate their input and throw
/// std::invalid_argument naming the field that was wrong.
template <typename Scalar>
class Motion {
 public:
  /// The alternatives.
  using Variant = std::variant<StaticMotion<Scalar>, ConstantVelocity<Scalar>, ConstantAcceleration<Scalar>,
                               ScrewMotion<Scalar>, PoseInterpolation<Scalar>, FreeFlightPath<Scalar>>;

  /// A body at rest at the identity pose.
  Motion() : motion_(StaticMotion<Scalar>{}) {}

  /// A body at rest at `pose`.
  static Motion fixed(const Pose<Scalar>& pose) {
    pose.validate("motion.start");
    return Motion(StaticMotion<Scalar>{pose});
  }
  /// Constant velocity from `start` at time t0.
  static Motion constantVelocity(const Pose<Scalar>& start, const Vector3<Scalar>& velocity, Scalar t0 = 0) {
    start.validate("motion.start");
    requireFinite(velocity, "motion.velocity");
    requireFinite(t0, "motion.t0");
    return Motion(ConstantVelocity<Scalar>{start, velocity, t0});
  }
  /// Constant acceleration (ballistic) from `start` at time t0.
  static Motion constantAcceleration(const Pose<Scalar>& start, const Vector3<Scalar>& velocity,
                                     const Vector3<Scalar>& acceleration, Scalar t0 = 0) {
    start.validate("motion.start");
    requireFinite(velocity, "motion.velocity");
    requireFinite(acceleration, "motion.acceleration");
    requireFinite(t0, "motion.t0");
    return Motion(ConstantAcceleration<Scalar>{start, velocity, acceleration, t0});
  }
  /// Screw motion (constant linear and angular velocity) from `start` at time t0.
  static Motion screw(const Pose<Scalar>& start, const Vector3<Scalar>& velocity,
                      const Vector3<Scalar>& angularVelocity, Scalar t0 = 0) {
    start.validate("motion.start");
    requireFinite(velocity, "motion.velocity");
    requireFinite(angularVelocity, "motion.angularVelocity");
    requireFinite(t0, "motion.t0");
    return Motion(ScrewMotion<Scalar>{start, velocity, angularVelocity, t0});
  }
  /// Interpolation from `from` at t0 to `to` at t1.
  static Motion interpolate(const Pose<Scalar>& from, const Pose<Scalar>& to, Scalar t0 = 0, Scalar t1 = 1) {
    from.validate("motion.from");
    to.validate("motion.to");
    requireInterval(t0, t1, "motion");
    if (t1 == t0) failInput("motion.t1", "must be after t0 for an interpolation");
    return Motion(PoseInterpolation<Scalar>{from, to, t0, t1});
  }

  /// Free flight (ballistic translation, rotation turning at a constant rate from
  /// `start.rotation` to `endRotation`) over [t0, t1], t1 > t0.
  static Motion freeFlight(const Pose<Scalar>& start, const Vector3<Scalar>& velocity,
                           const Vector3<Scalar>& acceleration, const Matrix3<Scalar>& endRotation, Scalar t0,
                           Scalar t1) {
    start.validate("motion.start");
    requireFinite(velocity, "motion.velocity");
    requireFinite(acceleration, "motion.acceleration");
    if (!endRotation.allFinite()) failInput("motion.endRotation", "must be finite");
    if (!(endRotation.transpose() * endRotation).isIdentity(rotationTolerance<Scalar>()) ||
        endRotation.determinant() < Scalar(0))
      failInput("motion.endRotation", "must be orthonormal with determinant +1");
    requireInterval(t0, t1, "motion");
    if (t1 == t0) failInput("motion.t1", "must be after t0 for a free flight");
    return Motion(FreeFlightPath<Scalar>{start, velocity, acceleration, endRotation, t0, t1});
  }

  /// The pose `worldFromBody` at time t.
  Pose<Scalar> pose(Scalar t) const {
    return std::visit([t](const auto& m) { return Pose<Scalar>(m.pose(t)); }, motion_);
  }
  /// Bounds of the motion's acceleration and rotation (for the certified extrusion test).
  MotionBound<Scalar> bound() const {
    return std::visit([](const auto& m) { return m.bound(); }, motion_);
  }
  /// The same motion seen from a frame whose origin sits at `-offset`: every pose's
  /// translation moved by `offset`, nothing else changed. A query runs in the frame of one
  /// of its bodies this way (time_of_impact.hpp), as Box2D v3 runs its queries in the frame
  /// of the first shape, so that its arithmetic works on the bodies' small relative
  /// coordinates rather than on large world ones. In float, moving a translation by a
  /// nearby float is exact (Sterbenz's lemma), so nothing of the input is lost.
  Motion translated(const Vector3<Scalar>& offset) const {
    Motion moved = *this;
    std::visit(
        [&offset](auto& m) {
          if constexpr (std::is_same_v<std::decay_t<decltype(m)>, PoseInterpolation<Scalar>>) {
            m.from.translation += offset;
            m.to.translation += offset;
          } else {
            m.start.translation += offset;
          }
        },
        moved.motion_);
    return moved;
  }
  /// The same motion on a clock that reads 0 at time `clock`: `retimed(c).pose(tau)` is
  /// `pose(c + tau)`, each motion's own start time (and an interpolation's end) moved back
  /// by `clock`, nothing else changed. A query over \f$[t_0, t_1]\f$ runs on this clock with
  /// `clock` = \f$t_0\f$ (time_of_impact.hpp), the time-axis twin of `translated`: its times
  /// are then \f$\tau = t - t_0\f$, whose floating-point spacing is relative to the interval's
  /// length rather than to \f$|t_0|\f$ (in float at \f$t_0\f$ = 1000 the spacing of t is 6.1e-5,
  /// of \f$\tau\f$ on an interval 2^-10 long at most 5.8e-11). A motion that starts at `clock`
  /// gets the start time 0 exactly, and its \f$\tau\f$ is then the query's own.
  Motion retimed(Scalar clock) const {
    Motion moved = *this;
    std::visit(
        [clock](auto& m) {
          using M = std::decay_t<decltype(m)>;
          if constexpr (std::is_same_v<M, PoseInterpolation<Scalar>> || std::is_same_v<M, FreeFlightPath<Scalar>>) {
            m.t0 -= clock;  // both ends of a motion defined over an interval
            m.t1 -= clock;
          } else if constexpr (!std::is_same_v<M, StaticMotion<Scalar>>) {
            m.t0 -= clock;
          }
        },
        moved.motion_);
    return moved;
  }
  /// True for a body that never moves (lets a scene skip its work).
  bool isStatic() const { return std::holds_alternative<StaticMotion<Scalar>>(motion_); }
  /// The same motion: the same kind, every parameter equal (so every pose equal).
  bool operator==(const Motion& o) const { return motion_ == o.motion_; }
  /// Not the same motion.
  bool operator!=(const Motion& o) const { return !(*this == o); }
  /// The alternative held, for code that wants to dispatch on it.
  const Variant& variant() const { return motion_; }

 private:
  explicit Motion(Variant motion) : motion_(std::move(motion)) {}
  Variant motion_;
};

}  // namespace gjkx
