/// @file
/// @brief A rigid body's mass and its state: pose and velocities at one instant (§6).
///
/// The body frame has its origin at the centre of mass (so free flight separates into
/// the centre's ballistic path and a torque-free rotation about it) and its axes along
/// the shape's body axes. Velocities are in the world frame, as in B. Mirtich,
/// "Impulse-based Dynamic Simulation of Rigid Body Systems", PhD thesis, UC Berkeley,
/// 1996, ch. 2–4. A static body has infinite mass: every impulse leaves it at rest and it
/// is never integrated.
#pragma once

#include <gjkx/dynamics/mass_properties.hpp>
#include <gjkx/motion/pose.hpp>

#include <Eigen/Core>
#include <Eigen/Eigenvalues>
#include <Eigen/LU>

#include <cmath>
#include <limits>

namespace gjkx {

/// Where a body is and how it moves at one instant. The body origin is the centre of mass.
struct BodyState {
  /// The pose of the body frame (origin at the centre of mass).
  Pose<double> worldFromBody;
  /// Velocity of the centre of mass, world frame.
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();
  /// Angular velocity \f$\omega\f$, world frame (radians per unit time).
  Eigen::Vector3d angularVelocity = Eigen::Vector3d::Zero();

  /// Throws std::invalid_argument naming `field` if the pose is bad or a velocity is not finite.
  void validate(const std::string& field) const {
    worldFromBody.validate(field + ".worldFromBody");
    requireFinite(velocity, field + ".velocity");
    requireFinite(angularVelocity, field + ".angularVelocity");
  }
};

/// The mass of a body: either dynamic (finite, positive mass and inertia) or static
/// (infinite mass: never moved by an impulse, never integrated).
class RigidBody {
 public:
  /// A dynamic body with the given mass properties (mass > 0, inertia symmetric positive
  /// definite; the centre of mass is kept for reference, the body frame is centred on it).
  /// Throws std::invalid_argument ("massProperties.mass", "massProperties.inertia").
  static RigidBody dynamic(const MassProperties& properties) {
    if (!std::isfinite(properties.mass) || !(properties.mass > 0))
      failInput("massProperties.mass", "must be finite and positive");
    requireFinite(properties.centerOfMass, "massProperties.centerOfMass");
    const Eigen::Matrix3d& J = properties.inertia;
    if (!J.allFinite()) failInput("massProperties.inertia", "must be finite");
    if (!J.isApprox(J.transpose(), 1e-9)) failInput("massProperties.inertia", "must be symmetric");
    const Eigen::Matrix3d Js = 0.5 * (J + J.transpose());
    if (!(Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(Js, Eigen::EigenvaluesOnly).eigenvalues().minCoeff() > 0))
      failInput("massProperties.inertia", "must be positive definite");
    RigidBody body;
    body.properties_ = properties;
    body.properties_.inertia = Js;
    body.inverseMass_ = 1 / properties.mass;
    body.inverseInertiaBody_ = Js.inverse();
    body.inverseInertiaBody_ = 0.5 * (body.inverseInertiaBody_ + body.inverseInertiaBody_.transpose());
    return body;
  }
  /// A static body: infinite mass and inertia, zero inverses.
  static RigidBody fixed() {
    RigidBody body;
    const double inf = std::numeric_limits<double>::infinity();
    body.properties_.mass = inf;
    body.properties_.inertia = inf * Eigen::Matrix3d::Identity();
    body.static_ = true;
    return body;
  }

  /// True for a static body.
  bool isStatic() const { return static_; }
  /// 1 / m (0 for a static body).
  double inverseMass() const { return inverseMass_; }
  /// \f$J_b^{-1}\f$, the inverse inertia in body axes (0 for a static body).
  const Eigen::Matrix3d& inverseInertiaBody() const { return inverseInertiaBody_; }
  /// \f$J^{-1} = R\,J_b^{-1}R^T\f$, the inverse inertia in world axes for the body rotation R.
  Eigen::Matrix3d inverseInertiaWorld(const Eigen::Matrix3d& rotation) const {
    return rotation * inverseInertiaBody_ * rotation.transpose();
  }
  /// \f$J = R\,J_b R^T\f$, the inertia in world axes (a dynamic body only).
  Eigen::Matrix3d inertiaWorld(const Eigen::Matrix3d& rotation) const {
    return rotation * properties_.inertia * rotation.transpose();
  }
  /// \f$\tfrac12 m\lVert v\rVert^2 + \tfrac12\omega^T J\,\omega\f$ (0 for a static body).
  double kineticEnergy(const BodyState& state) const {
    if (static_) return 0;
    const Eigen::Vector3d& w = state.angularVelocity;
    return 0.5 * properties_.mass * state.velocity.squaredNorm() +
           0.5 * w.dot(inertiaWorld(state.worldFromBody.rotation) * w);
  }
  /// Linear momentum \f$m v\f$ (0 for a static body).
  Eigen::Vector3d linearMomentum(const BodyState& state) const {
    return static_ ? Eigen::Vector3d::Zero() : Eigen::Vector3d(properties_.mass * state.velocity);
  }
  /// Angular momentum about the world origin, \f$J\omega + c \times m v\f$ (0 for a static body).
  Eigen::Vector3d angularMomentum(const BodyState& state) const {
    if (static_) return Eigen::Vector3d::Zero();
    return inertiaWorld(state.worldFromBody.rotation) * state.angularVelocity +
           state.worldFromBody.translation.cross(properties_.mass * state.velocity);
  }
  /// The mass properties (mass and inertia infinite for a static body).
  const MassProperties& massProperties() const { return properties_; }
  /// Velocity of the body point at `worldPoint`: \f$v + \omega \times (x - c)\f$.
  Eigen::Vector3d velocityAt(const BodyState& state, const Eigen::Vector3d& worldPoint) const {
    return state.velocity + state.angularVelocity.cross(worldPoint - state.worldFromBody.translation);
  }

 private:
  RigidBody() = default;
  MassProperties properties_;
  double inverseMass_ = 0;
  Eigen::Matrix3d inverseInertiaBody_ = Eigen::Matrix3d::Zero();
  bool static_ = false;
};

}  // namespace gjkx
