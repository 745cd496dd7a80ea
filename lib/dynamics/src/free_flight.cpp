// Free flight: ballistic translation in closed form, torque-free rotation by Euler's
// equations under Boost.Odeint's Dormand-Prince 5(4) (see the header).
#include <gjkx/dynamics/free_flight.hpp>

#include <boost/numeric/odeint.hpp>

#include <algorithm>
#include <array>
#include <cmath>

namespace gjkx {
namespace {

namespace odeint = boost::numeric::odeint;

// The integrated state, in dimensionless form. With w0 = |omega_b(0)| the time is
// s = w0 (t - t0) and the angular velocity w = omega_b / w0, so every component is of
// order one and one absolute tolerance fits all (Euler's equations are homogeneous of
// degree two in omega, so they keep their form):
//   x[0..3] = q = (w, x, y, z), the orientation worldFromBody as a unit quaternion,
//   x[4..6] = w, the body-frame angular velocity over w0,
//   x[7]    = the angle turned, \int |w| ds.
using State = std::array<double, 8>;

struct EulerEquations {
  Eigen::Matrix3d inertia, inverseInertia;  // body axes
  void operator()(const State& x, State& dxds, double /*s*/) const {
    const Eigen::Vector3d w(x[4], x[5], x[6]);
    // q' = 1/2 q (x) (0, w): the body-frame angular velocity turns the body frame.
    const double qw = x[0], qx = x[1], qy = x[2], qz = x[3];
    dxds[0] = 0.5 * (-qx * w.x() - qy * w.y() - qz * w.z());
    dxds[1] = 0.5 * (qw * w.x() + qy * w.z() - qz * w.y());
    dxds[2] = 0.5 * (qw * w.y() + qz * w.x() - qx * w.z());
    dxds[3] = 0.5 * (qw * w.z() + qx * w.y() - qy * w.x());
    // Euler's equations: J_b w' = -(w x J_b w) (no torque).
    const Eigen::Vector3d dw = -(inverseInertia * w.cross(inertia * w));
    dxds[4] = dw.x();
    dxds[5] = dw.y();
    dxds[6] = dw.z();
    dxds[7] = w.norm();
  }
};

bool isotropic(const Eigen::Matrix3d& inertia, double tolerance) {
  const Eigen::Vector3d moments =
      Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(inertia, Eigen::EigenvaluesOnly).eigenvalues();
  return moments.maxCoeff() - moments.minCoeff() <= tolerance * moments.maxCoeff();
}

}  // namespace

BodyState FreeFlight::stateAt(double t) const {
  if (!(t >= t0 && t <= t1)) failInput("t", "must lie in the flight's [t0, t1]");
  if (t == t0) return start;
  if (t == t1) return end;
  BodyState s;
  s.worldFromBody = motion.pose(t);
  if (status == FreeFlightStatus::Static) return s;
  s.velocity = start.velocity + gravity * (t - t0);
  if (status == FreeFlightStatus::Spinning) {
    s.angularVelocity = start.angularVelocity;
  } else if (status != FreeFlightStatus::Translating) {
    const Eigen::Matrix3d& R = s.worldFromBody.rotation;
    s.angularVelocity = R * (inverseInertiaBody * (R.transpose() * angularMomentum));
  }
  return s;
}

FreeFlight freeFlight(const RigidBody& body, const BodyState& start, double t0, double t1,
                      const Eigen::Vector3d& gravity, const FreeFlightSettings& settings) {
  start.validate("start");
  requireInterval(t0, t1, "flight");
  requireFinite(gravity, "gravity");
  if (!(settings.absoluteTolerance > 0) || !std::isfinite(settings.absoluteTolerance))
    failInput("settings.absoluteTolerance", "must be finite and positive");
  if (!(settings.relativeTolerance >= 0) || !std::isfinite(settings.relativeTolerance))
    failInput("settings.relativeTolerance", "must be finite and not negative");
  if (settings.maxSteps < 1) failInput("settings.maxSteps", "must be at least 1");
  if (!(settings.isotropyTolerance >= 0)) failInput("settings.isotropyTolerance", "must not be negative");

  FreeFlight f;
  f.t0 = t0;
  f.t1 = t1;
  f.start = start;
  f.gravity = gravity;
  const double dt = t1 - t0;
  const Pose<double>& p0 = start.worldFromBody;

  // A static body: never integrated.
  if (body.isStatic()) {
    f.start.velocity.setZero();
    f.start.angularVelocity.setZero();
    f.end = f.start;
    f.gravity.setZero();
    f.motion = Motion<double>::fixed(p0);
    f.status = FreeFlightStatus::Static;
    return f;
  }

  // The centre of mass: the ballistic parabola, in closed form.
  f.end.velocity = start.velocity + gravity * dt;
  f.inverseInertiaBody = body.inverseInertiaBody();
  const Eigen::Matrix3d& Jb = body.massProperties().inertia;
  f.angularMomentum = p0.rotation * (Jb * (p0.rotation.transpose() * start.angularVelocity));
  const double w0 = start.angularVelocity.norm();

  auto ballistic = [&](const Matrix3<double>& endRotation) {
    if (dt == 0) return Motion<double>::constantAcceleration(p0, start.velocity, gravity, t0);
    return Motion<double>::freeFlight(p0, start.velocity, gravity, endRotation, t0, t1);
  };

  // No angular velocity: no rotation work at all.
  if (w0 == 0) {
    f.motion = gravity.isZero(0) ? Motion<double>::constantVelocity(p0, start.velocity, t0)
                                 : Motion<double>::constantAcceleration(p0, start.velocity, gravity, t0);
    f.status = FreeFlightStatus::Translating;
    f.end.worldFromBody = f.motion.pose(t1);
    return f;
  }

  // Isotropic inertia: L = J w with J a multiple of the identity, so w is constant and the
  // body turns about a fixed axis: R(t) = exp([w] tau) R0.
  if (isotropic(Jb, settings.isotropyTolerance)) {
    f.status = FreeFlightStatus::Spinning;
    f.turnedAngle = w0 * dt;
    if (gravity.isZero(0)) {
      f.motion = Motion<double>::screw(p0, start.velocity, start.angularVelocity, t0);
    } else {
      const Matrix3<double> endRotation =
          Eigen::AngleAxisd(w0 * dt, start.angularVelocity / w0).toRotationMatrix() * p0.rotation;
      f.motion = ballistic(endRotation);
    }
    f.end.worldFromBody = f.motion.pose(t1);
    f.end.angularVelocity = start.angularVelocity;
    return f;
  }

  // The general case: Euler's equations by Dormand-Prince 5(4), in the scaled time s.
  const EulerEquations equations{Jb, body.inverseInertiaBody()};
  const Eigen::Quaterniond q0(p0.rotation);
  const Eigen::Vector3d wb = p0.rotation.transpose() * start.angularVelocity / w0;
  State x = {q0.w(), q0.x(), q0.y(), q0.z(), wb.x(), wb.y(), wb.z(), 0.0};
  auto stepper = odeint::make_controlled<odeint::runge_kutta_dopri5<State>>(settings.absoluteTolerance,
                                                                           settings.relativeTolerance);
  const double sEnd = w0 * dt;
  double s = 0;
  double ds = std::min(0.01, sEnd);
  int steps = 0;
  State dxds;
  equations(x, dxds, s);
  while (s < sEnd && steps < settings.maxSteps) {
    ++steps;
    // The last step lands on sEnd exactly.
    const bool last = s + ds >= sEnd;
    double h = last ? sEnd - s : ds;
    // The FSAL form: the derivative at x is passed in and recomputed after the renormalisation.
    if (stepper.try_step(equations, x, dxds, s, h) == odeint::success) {
      if (last) s = sEnd;  // no rounding remainder of sEnd - s left to step
      // Keep q on the unit sphere: the integrator's error leaves it a little off.
      const double norm = std::sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2] + x[3] * x[3]);
      for (int k = 0; k < 4; ++k) x[k] /= norm;
      equations(x, dxds, s);
      ds = h;  // the controller's suggestion for the next step
    } else {
      ds = h;  // rejected: the controller shrank the step
    }
  }
  f.integratorSteps = steps;
  f.status = FreeFlightStatus::Integrated;
  if (s < sEnd) {
    f.status = FreeFlightStatus::StepCap;
    f.t1 = t0 + s / w0;
    f.end.velocity = start.velocity + gravity * (f.t1 - t0);
  }
  f.turnedAngle = x[7];
  const Matrix3<double> endRotation = Eigen::Quaterniond(x[0], x[1], x[2], x[3]).toRotationMatrix();
  f.motion = f.t1 > t0 ? Motion<double>::freeFlight(p0, start.velocity, gravity, endRotation, t0, f.t1)
                       : Motion<double>::constantAcceleration(p0, start.velocity, gravity, t0);
  f.end.worldFromBody = f.motion.pose(f.t1);
  f.end.angularVelocity = endRotation * (w0 * Eigen::Vector3d(x[4], x[5], x[6]));
  return f;
}

}  // namespace gjkx
