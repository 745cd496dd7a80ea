/// @file
/// @brief Impulse-based collision response with friction and restitution, as in Mirtich's thesis (§6).
///
/// When the time-of-impact solver (§5) finds two bodies touching and approaching, the
/// simulation the paper serves (§6, e = 0.7, μ = 0.4) changes their velocities by a
/// collision impulse. This follows B. Mirtich, "Impulse-based Dynamic Simulation of Rigid
/// Body Systems", PhD thesis, UC Berkeley, 1996, ch. 4 ("Collision response"):
///
/// - The collision is instantaneous: positions do not change while it lasts, so the
///   relative contact velocity u (of B's contact point relative to A's) is linear in the
///   impulse p applied to B (−p to A): \f$u = u_0 + K p\f$, with the *collision matrix*
///   \f$K = \sum_{X=A,B} \left(m_X^{-1}\mathbf 1 - [r_X]\,J_X^{-1}[r_X]\right)\f$, r the contact point
///   relative to the centre of mass and [r] its cross-product matrix.
/// - The impulse is built up along the collision, parametrised by the normal impulse
///   \f$p_z\f$ (Mirtich's choice): \f$dp/dp_z = n - \mu\,\hat u_t\f$ while the contact slides
///   (Coulomb friction opposite the tangential sliding velocity \f$u_t\f$). When \f$u_t\f$ reaches
///   zero the contact *sticks* if the impulse direction that keeps \f$u_t = 0\f$,
///   \f$d = (d_t, 1)\f$ with \f$(K d)_t = 0\f$, lies in the friction cone (\f$\lVert d_t\rVert \le \mu\f$), and
///   then stays stuck (K is constant); otherwise it slides on along the ray Mirtich
///   derives: the tangential direction \f$\hat u\f$ in which \f$du_t/dp_z\f$ points along
///   \f$\hat u\f$ itself, \f$(K(n - \mu\hat u))_t = \lambda\hat u\f$, \f$\lambda > 0\f$.
/// - *Compression* lasts while \f$u_n < 0\f$; the normal work \f$W_z = \int u_n\,dp_z\f$ done then is
///   \f$W_c < 0\f$. *Restitution* follows and ends when \f$W_z = (1 - e^2)\,W_c\f$: Stronge's energetic
///   coefficient of restitution, which, unlike Newton's and Poisson's, never creates
///   energy with friction.
/// - The three quantities (tangential impulse, and the work W_z) are integrated over \f$p_z\f$
///   with Boost.Odeint's Dormand–Prince 5(4) pair under step-size control; each phase
///   change (sticking, end of compression, end of restitution) is located on the step
///   that crossed it by the same Brent's method as §5's time of impact (gjkx/root_solver/brent_method.hpp),
///   on one continuous function that is \f$\ge 0\f$ exactly when some change has happened.
/// - *Microcollisions* (Mirtich's thesis, ch. 4): resting contact is a train of tiny
///   collisions. Below a threshold approach speed \f$v_\mu\f$ a collision is processed with
///   restitution 1, so the bodies separate (frictionless) at the speed they met instead
///   of settling into each other: a body resting under gravity hops in collisions slower
///   than \f$v_\mu\f$, never sinks, and no energy is created. This is the "minimum
///   separation" the scheme needs without adding energy: the raised restitution is the
///   largest that conserves it. The scene chooses \f$v_\mu\f$ from gravity and its collision
///   tolerance, e.g. \f$v_\mu = \sqrt{2 g\,\varepsilon}\f$, the speed gravity gives over the tolerance
///   \f$\varepsilon\f$, so a hop never rises above the tolerance.
/// - Once sliding slows to within a tolerance of zero, the last sliver is closed by the
///   tangential impulse \f$-A^{-1}u_t\f$ (A the tangential block of K); it removes energy and is
///   of the order of the tolerance (ImpulseSettings::stickingTolerance). An integration
///   cap ends in ImpulseStatus::StepCap, with the impulse built so far applied.
#pragma once

#include <gjkx/dynamics/rigid_body.hpp>

#include <string>
#include <vector>

namespace gjkx {

/// A point of contact between bodies A and B, world frame.
struct Contact {
  /// The contact point.
  Eigen::Vector3d point = Eigen::Vector3d::Zero();
  /// Unit normal from A towards B.
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();
};

/// The material of a contact: the paper's values by default (§6).
struct CollisionMaterial {
  /// Stronge's energetic coefficient of restitution e in [0, 1].
  double restitution = 0.7;
  /// Coulomb's coefficient of friction μ (not negative).
  double friction = 0.4;
};

/// Settings of the impulse integration.
struct ImpulseSettings {
  /// Approach speeds below this are microcollisions (restitution 1, see the file
  /// comment); 0 turns microcollisions off.
  double microcollisionSpeed = 0;
  /// Absolute tolerance of the Dormand–Prince step control, on the impulse and work scaled
  /// by the collision's own units (approach speed, normal impulse to stop it). The defaults
  /// take a third of the steps of tolerances of 1e-12 and 1e-9 on the torso of chapter 08
  /// (`gjkx_simulate --impulse-tolerance`, `--sticking-tolerance`; docs 08); an impulse then
  /// differs from the tight one by about the sticking tolerance at most (its closing
  /// tangential impulse), far below what a float simulation keeps.
  double absoluteTolerance = 1e-9;
  /// Relative tolerance of the step control.
  double relativeTolerance = 1e-9;
  /// The tangential speed counted as zero (sliding stops), as a fraction of the initial relative
  /// speed; the remainder is removed by a tangential impulse of that order. Keep it well
  /// above the tolerances: u_t is a difference of quantities of order one, each known to
  /// about the tolerance, and sliding that is to stop must see |u_t| fall below it (with
  /// 1e-9 against tolerances of 1e-9, collisions stalled at the step cap).
  double stickingTolerance = 1e-6;
  /// Cap on the integrator's steps; reaching it ends in ImpulseStatus::StepCap.
  int maxSteps = 100000;

  /// Throws std::invalid_argument naming the setting (`field` + ".absoluteTolerance", ...)
  /// for one out of range: resolveCollision() checks its settings with it, and a caller
  /// that keeps settings for later (gjkx::World) checks them where they enter.
  void validate(const std::string& field) const;
};

/// What a collision did.
enum class ImpulseStatus {
  Separating,      ///< not approaching at the contact (\f$u_n \ge 0\f$): nothing applied
  Collision,       ///< a collision integrated through compression and restitution
  Microcollision,  ///< a collision below the microcollision speed, restitution 1
  StepCap          ///< the integrator hit ImpulseSettings::maxSteps; the impulse so far is applied
};

/// The result of resolveCollision().
struct ImpulseResult {
  /// What happened.
  ImpulseStatus status = ImpulseStatus::Separating;
  /// The impulse applied to B (−impulse to A), world frame.
  Eigen::Vector3d impulse = Eigen::Vector3d::Zero();
  /// \f$-u_n\f$ before the collision (positive when approaching).
  double approachSpeed = 0;
  /// \f$u_n\f$ after the collision.
  double separationSpeed = 0;
  /// The restitution used (1 for a microcollision).
  double restitution = 0;
  /// Kinetic energy of A and B before.
  double kineticEnergyBefore = 0;
  /// Kinetic energy of A and B after.
  double kineticEnergyAfter = 0;
  /// True if the contact ended sticking (no tangential sliding).
  bool sticking = false;
  /// True if sliding stopped where sticking was impossible (the sticking impulse outside
  /// the friction cone) and resumed along Mirtich's ray.
  bool slidingResumed = false;
  /// Integrator steps taken (accepted and rejected).
  int integratorSteps = 0;
};

/// One phase change of a collision, as a step-by-step test reads it (`ImpulseTrace`).
struct ImpulsePhaseChange {
  /// What changed.
  enum class Kind {
    SlidingStopped,    ///< the tangential velocity reached zero: the contact sticks, or slides on along Mirtich's ray
    EndOfCompression,  ///< \f$u_n\f$ reached zero: the work done so far is \f$W_c\f$
    EndOfRestitution,  ///< \f$W_z\f$ reached \f$(1 - e^2)\,W_c\f$ (Stronge): the collision ends
  };
  /// What changed.
  Kind kind = Kind::EndOfCompression;
  /// The normal impulse \f$p_z\f$ applied so far (N s).
  double normalImpulse = 0;
  /// The tangential impulse applied so far, in the contact frame's two tangent directions (N s).
  Eigen::Vector2d tangentialImpulse = Eigen::Vector2d::Zero();
  /// The normal work \f$W_z = \int u_n\,dp_z\f$ done so far (J).
  double work = 0;
  /// The relative normal velocity \f$u_n\f$ there (m/s).
  double normalVelocity = 0;
  /// True when the contact sticks from here on (for `SlidingStopped`).
  bool sticking = false;
};

/// A caller-owned record of one collision's phase changes, in order (for the tests).
struct ImpulseTrace {
  /// The phase changes, in order.
  std::vector<ImpulsePhaseChange> changes;
};

/// Resolves a collision of A and B at `contact`: integrates the impulse (see the file
/// comment) and updates the velocities of `a` and `b` (a static body's are left alone).
/// Throws std::invalid_argument naming the field: "a...", "b...", "contact.point",
/// "contact.normal" (finite, unit), "material.restitution" (in [0, 1]), "material.friction"
/// (not negative), "settings...", "bodies" (both static). `trace`, when given, records
/// each phase change (sliding stopped, end of compression, end of restitution).
ImpulseResult resolveCollision(const RigidBody& A, BodyState& a, const RigidBody& B, BodyState& b,
                               const Contact& contact, const CollisionMaterial& material,
                               const ImpulseSettings& settings = {}, ImpulseTrace* trace = nullptr);

}  // namespace gjkx
