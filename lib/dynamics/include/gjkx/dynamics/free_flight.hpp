/// @file
/// @brief Free flight of a rigid body under gravity over [t0, t1], handed on as a `Motion` (§5–§6).
///
/// Between collisions a body flies freely: its centre of mass follows the ballistic
/// parabola \f$c(t) = c_0 + v_0\tau + \tfrac12 g\tau^2\f$ in closed form, and it turns
/// torque-free about the centre: the world angular momentum \f$L = J(t)\,\omega(t)\f$ is
/// conserved, and in body axes Euler's equations hold,
/// \f$J_b\dot\omega_b + \omega_b \times J_b\omega_b = 0\f$, with
/// \f$\dot q = \tfrac12\,q \otimes (0, \omega_b)\f$ for the orientation quaternion.
/// For a body whose inertia is not isotropic these are integrated with Boost.Odeint's
/// Dormand–Prince 5(4) pair under step-size control, the quaternion renormalised after
/// each step (Mirtich's thesis, ch. 2, integrates the same equations between collisions).
/// The result is exposed as the `motion` stage's interface, so the paper's time-of-impact
/// solver (§5) sees the body's path over the step: a `FreeFlightPath` that ends exactly at
/// the integrated orientation.
///
/// What a body does not need is left out (DESIGN.md §3): a static body is not integrated
/// (`Motion::fixed`); a body that does not turn does no rotation work
/// (`ConstantAcceleration`, or `ConstantVelocity` without gravity); a body with isotropic
/// inertia (sphere, cube) keeps \f$\omega\f$ constant and turns in closed form
/// (`ScrewMotion` without gravity, a `FreeFlightPath` to \f$\exp([\omega]\Delta t)R_0\f$ with it).
#pragma once

#include <gjkx/dynamics/rigid_body.hpp>
#include <gjkx/motion/motion.hpp>

namespace gjkx {

/// Settings of the free-flight integration.
struct FreeFlightSettings {
  /// Absolute error tolerance of the Dormand–Prince step control (per component of the
  /// unit quaternion and of \f$\omega_b\f$ divided by its initial norm).
  double absoluteTolerance = 1e-12;
  /// Relative error tolerance of the step control.
  double relativeTolerance = 1e-12;
  /// Cap on the integrator's steps (accepted and rejected); reaching it ends in
  /// FreeFlightStatus::StepCap.
  int maxSteps = 200000;
  /// Inertia counted as isotropic (closed-form rotation) when its principal moments differ
  /// by less than this fraction of the largest.
  double isotropyTolerance = 1e-12;
};

/// How a free flight was computed.
enum class FreeFlightStatus {
  Static,       ///< a static body: Motion::fixed, no work
  Translating,  ///< no angular velocity: ballistic (or constant-velocity) translation only
  Spinning,     ///< isotropic inertia: constant \f$\omega\f$, closed-form rotation
  Integrated,   ///< Euler's equations integrated by Dormand–Prince 5(4)
  StepCap       ///< the integrator hit FreeFlightSettings::maxSteps; the flight ends early, at `t1`
};

/// A body's free flight over [t0, t1]: its start and end states and its path as a Motion.
struct FreeFlight {
  /// Start of the flight.
  double t0 = 0;
  /// End of the flight (earlier than asked for if status is StepCap).
  double t1 = 0;
  /// The state at t0 (as given).
  BodyState start;
  /// The state at t1: pose `motion.pose(t1)`, velocity \f$v_0 + g\,(t_1 - t_0)\f$, angular velocity as integrated.
  BodyState end;
  /// The path over [t0, t1] for the time-of-impact solver.
  Motion<double> motion;
  /// How the flight was computed.
  FreeFlightStatus status = FreeFlightStatus::Static;
  /// Integrator steps taken (accepted and rejected); 0 when nothing was integrated.
  int integratorSteps = 0;
  /// The angle the body turned through, \f$\int_{t_0}^{t_1}\lVert\omega\rVert\,dt\f$. The path's rotation
  /// takes the shortest arc from start to end, which is the body's only if this is below \f$\pi\f$;
  /// a caller with faster spins splits the interval.
  double turnedAngle = 0;
  /// Gravity over the flight.
  Eigen::Vector3d gravity = Eigen::Vector3d::Zero();
  /// The conserved angular momentum about the centre of mass, world frame: \f$L = J_0\,\omega_0\f$.
  Eigen::Vector3d angularMomentum = Eigen::Vector3d::Zero();
  /// The body's inverse inertia in body axes (for stateAt()).
  Eigen::Matrix3d inverseInertiaBody = Eigen::Matrix3d::Zero();

  /// The state at t in [t0, t1]: pose `motion.pose(t)` exactly; velocity \f$v_0 + g\,(t - t_0)\f$;
  /// angular velocity \f$R(t)\,J_b^{-1}R(t)^T L\f$ (so a collision at t starts from a state
  /// consistent with the path and with the conserved momentum); `start` at t0 and `end` at t1.
  /// Throws std::invalid_argument ("t") outside [t0, t1].
  BodyState stateAt(double t) const;
};

/// The free flight of `body` from `start` at t0 to t1 under `gravity` (see the file comment).
/// Throws std::invalid_argument naming the field: "start.worldFromBody...",
/// "start.velocity", "start.angularVelocity", "flight.t0", "flight.t1", "gravity", "settings...".
FreeFlight freeFlight(const RigidBody& body, const BodyState& start, double t0, double t1,
                      const Eigen::Vector3d& gravity, const FreeFlightSettings& settings = {});

}  // namespace gjkx
