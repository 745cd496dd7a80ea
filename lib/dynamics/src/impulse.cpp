// Mirtich's impulse integration through compression and restitution (see the header).
#include <gjkx/dynamics/impulse.hpp>

#include <gjkx/root_solver/brent_method.hpp>

#include <boost/numeric/odeint.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace gjkx {
namespace {

namespace odeint = boost::numeric::odeint;

Eigen::Matrix3d cross(const Eigen::Vector3d& r) {
  Eigen::Matrix3d m;
  m << 0, -r.z(), r.y(), r.z(), 0, -r.x(), -r.y(), r.x(), 0;
  return m;
}

// K_X = m^-1 1 - [r] J^-1 [r]: the change of the contact point's velocity per unit impulse.
// Derivation: an impulse p at r changes v by p/m and omega by J^-1 (r x p); the point's
// velocity v + omega x r changes by p/m + (J^-1 [r] p) x r = (m^-1 1 - [r] J^-1 [r]) p.
Eigen::Matrix3d collisionMatrix(const RigidBody& body, const BodyState& state, const Eigen::Vector3d& point) {
  if (body.isStatic()) return Eigen::Matrix3d::Zero();
  const Eigen::Matrix3d rx = cross(point - state.worldFromBody.translation);
  return body.inverseMass() * Eigen::Matrix3d::Identity() -
         rx * body.inverseInertiaWorld(state.worldFromBody.rotation) * rx;
}

// The integrated quantities, dimensionless. With U = |u0| and P = U / K_nn (the normal
// impulse that would stop the normal approach of a frictionless contact), the impulse is
// p = P (px, py, sigma) in the contact frame (t1, t2, n), sigma the independent variable
// (Mirtich's p_z), and the normal work is W = P U w. Then u / U = u0 / U + Khat p / P with
// Khat = K / K_nn, all of order one, and one absolute tolerance fits every component.
//   y[0], y[1] = px, py    (tangential impulse)
//   y[2]       = w         (normal work, dw/dsigma = u_n / U)
using State = std::array<double, 3>;

enum class Friction { None, Sliding, Sticking };

struct Collision {
  Eigen::Matrix3d K;  // Khat in the contact frame: columns t1, t2, n
  Eigen::Vector3d u0;  // u0 / U in the contact frame
  double mu = 0;
  Friction friction = Friction::None;
  Eigen::Vector2d stick = Eigen::Vector2d::Zero();  // d_t while sticking
  Eigen::Vector2d ray = Eigen::Vector2d::Zero();    // the sliding direction leaving u_t = 0
  bool onRay = false;                               // sliding leaves u_t = 0 along `ray`
  bool resumed = false;                             // sliding has resumed along a ray
  double zero = 0;                                  // tangential speed counted as zero

  Eigen::Vector3d velocity(const State& y, double sigma) const { return u0 + K * Eigen::Vector3d(y[0], y[1], sigma); }

  // d(px, py, w)/dsigma in the current friction mode.
  void operator()(const State& y, State& dy, double sigma) const {
    const Eigen::Vector3d u = velocity(y, sigma);
    Eigen::Vector2d dt = Eigen::Vector2d::Zero();
    if (friction == Friction::Sliding) {
      // Coulomb: the friction impulse opposes the sliding velocity, mu per unit normal impulse.
      const Eigen::Vector2d ut = u.head<2>();
      const double speed = ut.norm();
      const Eigen::Vector2d dir = (onRay || !(speed > 0)) ? ray : Eigen::Vector2d(ut / speed);
      dt = -mu * dir;
    } else if (friction == Friction::Sticking) {
      dt = stick;
    }
    dy[0] = dt.x();
    dy[1] = dt.y();
    dy[2] = u.z();
  }

  // Sticking: the impulse direction d = (d_t, 1) with (Khat d)_t = 0, i.e. A d_t = -b with
  // A the tangential block of Khat and b its tangential-normal column.
  Eigen::Vector2d stickingDirection() const {
    const Eigen::Matrix2d A = K.topLeftCorner<2, 2>();
    const Eigen::Vector2d b = K.topRightCorner<2, 1>();
    return -A.ldlt().solve(b);
  }

  // Where sliding resumes from u_t = 0 when sticking is not possible: the unit direction
  // uhat whose friction keeps u_t growing along uhat itself,
  //   (Khat (n - mu uhat))_t = b - mu A uhat = lambda uhat,  lambda > 0.
  // The angle is found by scanning for a sign change of the cross product (b - mu A uhat)
  // x uhat, refined by bisection; of several rays, the one that grows fastest (largest
  // lambda). Without one (not seen in practice), the friction impulse points along the
  // sticking direction clipped to the cone.
  Eigen::Vector2d slidingRay() const {
    const Eigen::Matrix2d A = K.topLeftCorner<2, 2>();
    const Eigen::Vector2d b = K.topRightCorner<2, 1>();
    auto g = [&](double theta) {
      const Eigen::Vector2d uh(std::cos(theta), std::sin(theta));
      const Eigen::Vector2d f = b - mu * A * uh;
      return std::make_pair(f.x() * uh.y() - f.y() * uh.x(), f.dot(uh));
    };
    constexpr int kSamples = 720;
    constexpr double kTwoPi = 6.283185307179586;
    double bestLambda = 0;
    Eigen::Vector2d best = Eigen::Vector2d::Zero();
    for (int i = 0; i < kSamples; ++i) {
      double lo = kTwoPi * i / kSamples, hi = kTwoPi * (i + 1) / kSamples;
      double glo = g(lo).first;
      if ((glo > 0) == (g(hi).first > 0)) continue;
      for (int k = 0; k < 60; ++k) {
        const double mid = 0.5 * (lo + hi);
        if ((g(mid).first > 0) == (glo > 0)) {
          lo = mid;
        } else {
          hi = mid;
        }
      }
      const double theta = 0.5 * (lo + hi);
      const double lambda = g(theta).second;
      if (lambda > bestLambda) {
        bestLambda = lambda;
        best = Eigen::Vector2d(std::cos(theta), std::sin(theta));
      }
    }
    if (bestLambda > 0) return best;
    const Eigen::Vector2d d = stickingDirection();
    return d.norm() > 0 ? Eigen::Vector2d(-d.normalized()) : Eigen::Vector2d(1, 0);
  }

  // At u_t = 0: stick if the sticking impulse lies in the friction cone, else slide on along the ray.
  void tangentialStop() {
    const Eigen::Vector2d d = stickingDirection();
    if (d.norm() <= mu) {
      friction = Friction::Sticking;
      stick = d;
    } else {
      // Sliding resumes along the ray, with the friction impulse held opposite it until
      // u_t has grown well clear of zero (its own direction is noise before that).
      friction = Friction::Sliding;
      ray = slidingRay();
      onRay = true;
      resumed = true;
    }
  }

  // Leaves the ray once u_t is clearly along it.
  void leaveRay(const Eigen::Vector2d& ut) {
    if (onRay && ut.norm() > 1000 * zero && ut.dot(ray) > 0) onRay = false;
  }
};

enum class Phase { Compression, Restitution, Done };

void requireSetting(bool ok, const char* field, const char* what) {
  if (!ok) failInput(field, what);
}

}  // namespace

void ImpulseSettings::validate(const std::string& field) const {
  if (!(microcollisionSpeed >= 0 && std::isfinite(microcollisionSpeed)))
    failInput(field + ".microcollisionSpeed", "must be finite and not negative");
  if (!(absoluteTolerance > 0 && std::isfinite(absoluteTolerance)))
    failInput(field + ".absoluteTolerance", "must be finite and positive");
  if (!(relativeTolerance >= 0 && std::isfinite(relativeTolerance)))
    failInput(field + ".relativeTolerance", "must be finite and not negative");
  if (!(stickingTolerance > 0 && stickingTolerance < 1)) failInput(field + ".stickingTolerance", "must lie in (0, 1)");
  if (maxSteps < 1) failInput(field + ".maxSteps", "must be at least 1");
}

ImpulseResult resolveCollision(const RigidBody& A, BodyState& a, const RigidBody& B, BodyState& b,
                               const Contact& contact, const CollisionMaterial& material,
                               const ImpulseSettings& settings, ImpulseTrace* trace) {
  a.validate("a");
  b.validate("b");
  requireFinite(contact.point, "contact.point");
  requireFinite(contact.normal, "contact.normal");
  if (std::abs(contact.normal.norm() - 1) > 1e-6) failInput("contact.normal", "must be a unit vector");
  requireSetting(material.restitution >= 0 && material.restitution <= 1, "material.restitution", "must lie in [0, 1]");
  requireSetting(material.friction >= 0 && std::isfinite(material.friction), "material.friction",
                 "must be finite and not negative");
  settings.validate("settings");
  if (A.isStatic() && B.isStatic()) failInput("bodies", "both static: an impulse can move neither");

  ImpulseResult result;
  result.kineticEnergyBefore = A.kineticEnergy(a) + B.kineticEnergy(b);
  result.kineticEnergyAfter = result.kineticEnergyBefore;
  result.restitution = material.restitution;

  // The contact frame (t1, t2, n).
  const Eigen::Vector3d n = contact.normal.normalized();
  const Eigen::Vector3d t1 = n.unitOrthogonal();
  const Eigen::Vector3d t2 = n.cross(t1);
  Eigen::Matrix3d frame;
  frame << t1, t2, n;

  const Eigen::Vector3d u0 = B.velocityAt(b, contact.point) - A.velocityAt(a, contact.point);
  const double un0 = u0.dot(n);
  result.approachSpeed = -un0;
  result.separationSpeed = un0;
  if (!(un0 < 0)) return result;  // not approaching: nothing to resolve

  // A microcollision: restitution 1 (see the header).
  double e = material.restitution;
  result.status = ImpulseStatus::Collision;
  if (-un0 < settings.microcollisionSpeed) {
    e = 1;
    result.status = ImpulseStatus::Microcollision;
  }
  result.restitution = e;

  // Scales (see State above).
  const Eigen::Matrix3d K = frame.transpose() *
                            (collisionMatrix(A, a, contact.point) + collisionMatrix(B, b, contact.point)) * frame;
  const double U = u0.norm();
  const double Knn = K(2, 2);  // > 0: at least one body is dynamic
  const double P = U / Knn;

  Collision c;
  c.K = K / Knn;
  c.u0 = frame.transpose() * u0 / U;
  c.mu = material.friction;
  c.zero = settings.stickingTolerance;
  if (c.mu > 0) {
    if (c.u0.head<2>().norm() <= c.zero) {
      c.tangentialStop();
    } else {
      c.friction = Friction::Sliding;
    }
  }

  // Integrate over sigma until restitution ends.
  auto controlled = odeint::make_controlled<odeint::runge_kutta_dopri5<State>>(settings.absoluteTolerance,
                                                                              settings.relativeTolerance);
  Phase phase = Phase::Compression;
  double wTarget = 0;
  State y = {0, 0, 0}, dydsigma;
  double sigma = 0, h = 0.01;
  c(y, dydsigma, sigma);
  // One fixed-length Dormand-Prince step from a state (a fresh stepper each time: the
  // stepper keeps the derivative of its last step, which belongs to another state).
  auto plainStep = [&](State& s, double from, double length) {
    odeint::runge_kutta_dopri5<State> plain;
    plain.do_step(c, s, from, length);
  };
  int steps = 0;
  // The trace's record of a phase change, in the caller's units (the state is scaled by P and U).
  auto record = [&](ImpulsePhaseChange::Kind kind) {
    if (!trace) return;
    ImpulsePhaseChange change;
    change.kind = kind;
    change.normalImpulse = P * sigma;
    change.tangentialImpulse = P * Eigen::Vector2d(y[0], y[1]);
    change.work = P * U * y[2];
    change.normalVelocity = U * c.velocity(y, sigma).z();
    change.sticking = c.friction == Friction::Sticking;
    trace->changes.push_back(change);
  };

  // Sliding has stopped (|u_t| within the tolerance): close the remainder with the
  // tangential impulse -A^-1 u_t, then stick or slide on along the ray.
  auto stopSliding = [&]() {
    const Eigen::Vector2d ut = c.velocity(y, sigma).head<2>();
    const Eigen::Vector2d dp = -c.K.topLeftCorner<2, 2>().ldlt().solve(ut);
    y[0] += dp.x();
    y[1] += dp.y();
    c.tangentialStop();
    record(ImpulsePhaseChange::Kind::SlidingStopped);
  };

  // The events that end the current stretch of the integration, each a continuous function
  // of the state that is >= 0 exactly when its event has happened (-inf for an event the
  // phase cannot meet): zero - |u_t| and -u_t . u_t(start), the larger of the two (sliding
  // has stopped or turned back); u_n (compression has ended); w - W_target (restitution has
  // ended). Their largest, g, is >= 0 exactly when some event has happened: event location
  // finds where g crosses 0.
  enum Event { kNone = 0, kStop = 1, kCompressed = 2, kRestituted = 4 };
  struct EventValues {
    double stop, compressed, restituted;
    double g() const { return std::max({stop, compressed, restituted}); }
    int flags() const {
      return (stop >= 0 ? kStop : kNone) | (compressed >= 0 ? kCompressed : kNone) |
             (restituted >= 0 ? kRestituted : kNone);
    }
  };
  auto eventValues = [&](const State& s, double sig, const Eigen::Vector2d& utStart) {
    constexpr double never = -std::numeric_limits<double>::infinity();
    EventValues v{never, never, never};
    const Eigen::Vector3d u = c.velocity(s, sig);
    if (c.friction == Friction::Sliding && !c.onRay && utStart.norm() > c.zero) {
      const Eigen::Vector2d ut = u.head<2>();
      v.stop = std::max(c.zero - ut.norm(), -ut.dot(utStart));
    }
    if (phase == Phase::Compression) v.compressed = u.z();
    if (phase == Phase::Restitution) v.restituted = s[2] - wTarget;
    return v;
  };

  // Without sliding (frictionless, or stuck: stuck stays stuck, K being constant) the
  // impulse direction d = (d_t, 1) is constant, so u_n grows linearly,
  // u_n(sigma) = u_n + k (sigma - sigma_0) with k = (Khat d)_n > 0, and the work is a
  // quadratic: W = W_0 + u_n s + k s^2 / 2. The rest of the collision is then closed form:
  // compression ends after s_c = -u_n / k with W_c = W_0 - u_n^2 / (2k), and restitution
  // ends where W_c + k s^2 / 2 reaches (1 - e^2) W_c. No integration is needed.
  auto finishLinear = [&]() {
    const Eigen::Vector3d d(c.friction == Friction::Sticking ? c.stick.x() : 0.0,
                            c.friction == Friction::Sticking ? c.stick.y() : 0.0, 1.0);
    const double k = (c.K * d).z();
    auto advance = [&](double s) {
      const double un = c.velocity(y, sigma).z();
      y[0] += s * d.x();
      y[1] += s * d.y();
      y[2] += un * s + 0.5 * k * s * s;
      sigma += s;
    };
    if (phase == Phase::Compression) {
      const double un = c.velocity(y, sigma).z();
      if (un < 0) advance(-un / k);
      wTarget = (1 - e * e) * y[2];
      phase = Phase::Restitution;
      record(ImpulsePhaseChange::Kind::EndOfCompression);
    }
    const double un = std::max(0.0, c.velocity(y, sigma).z());
    if (y[2] < wTarget) advance((-un + std::sqrt(un * un + 2 * k * (wTarget - y[2]))) / k);
    phase = Phase::Done;
    record(ImpulsePhaseChange::Kind::EndOfRestitution);
  };

  while (phase != Phase::Done) {
    if (c.friction != Friction::Sliding) {
      finishLinear();
      break;
    }
    if (steps >= settings.maxSteps || !(sigma < 1e12)) {
      result.status = ImpulseStatus::StepCap;
      break;
    }
    ++steps;
    const State yPrev = y;
    const double sigmaPrev = sigma;
    const Eigen::Vector2d utStart = c.velocity(y, sigma).head<2>();
    // Sliding towards u_t = 0: Coulomb's law has a kink there, which an adaptive step
    // straddling it cannot resolve (stages on both sides of the kink can even agree on a
    // false cycle around zero). So no step goes beyond half the linear estimate of the
    // stop, sigma* = |u_t| / (closing rate): |u_t| shrinks geometrically and smoothly. Once
    // it is below the sticking tolerance, the rest is closed by a tangential impulse
    // dp_t = -A^-1 u_t (A the tangential block of K), which sets u_t to zero and takes
    // energy out (dE = -u_t^T A^-1 u_t / 2); its size is of the order of the tolerance.
    if (c.friction == Friction::Sliding && !c.onRay) {
      const double speed = utStart.norm();
      if (speed <= c.zero) {
        stopSliding();
        c(y, dydsigma, sigma);
        --steps;
        continue;
      }
      State dy;
      c(y, dy, sigma);
      const Eigen::Vector2d rate = (c.K * Eigen::Vector3d(dy[0], dy[1], 1)).head<2>();
      const double closing = -rate.dot(utStart) / speed;
      if (closing > 0) h = std::min(h, 0.5 * speed / closing);
    }
    // The FSAL form of the step: the derivative at y is passed in (and recomputed after
    // every change the integrator does not know of: a located event, a friction mode).
    if (controlled.try_step(c, y, dydsigma, sigma, h) != odeint::success) continue;
    if (c.onRay) {
      c.leaveRay(c.velocity(y, sigma).head<2>());
      if (!c.onRay) c(y, dydsigma, sigma);  // the friction law changed form: a fresh derivative
    }
    int ev = eventValues(y, sigma, utStart).flags();
    if (ev == kNone) continue;

    // A phase change inside the step: find the step length h where g, measured on the
    // step redone from its start with the plain Dormand-Prince stepper, crosses 0. Every
    // trial is a whole Dormand-Prince step, so the root is found by the same Brent's method
    // as §5's time of impact (gjkx/root_solver/brent_method.hpp): superlinear, a handful of trials where
    // bisection took some fifty. The step ends at the bracket's end where g >= 0, where
    // some event has happened.
    const double length = sigma - sigmaPrev;
    const double gStart = eventValues(yPrev, sigmaPrev, utStart).g(), gEnd = eventValues(y, sigma, utStart).g();
    double hi = 0;  // an event already at the start (g >= 0 there) ends the step at once
    if (gStart < 0) {
      BrentStepper<double> brent(0.0, gStart, length, gEnd, 1e-15 * std::max(1.0, sigma));
      // Brent's method takes at most about log2(length / tolerance)^2 steps (Brent 1973:
      // its bisections halve the bracket whenever interpolation is slow). Here length <= sigma,
      // so length / tolerance <= 1e15 < 2^50 and that is at most 2,500: the cap is never met.
      for (int k = 0; k < 100 * 100 && !brent.converged(); ++k) {
        const double h = brent.next();
        State trial = yPrev;
        plainStep(trial, sigmaPrev, h);
        brent.update(eventValues(trial, sigmaPrev + h, utStart).g());
      }
      hi = brent.fRoot() >= 0 ? brent.root() : brent.counterpart();
    }
    y = yPrev;
    plainStep(y, sigmaPrev, hi);
    sigma = sigmaPrev + hi;
    ev = eventValues(y, sigma, utStart).flags();

    if (ev & kStop) stopSliding();
    if (ev & kCompressed) {
      // End of compression: W_c = w now; restitution ends at (1 - e^2) W_c (Stronge).
      wTarget = (1 - e * e) * y[2];
      phase = Phase::Restitution;
      record(ImpulsePhaseChange::Kind::EndOfCompression);
      if (y[2] >= wTarget) phase = Phase::Done;  // e = 0: no restitution
    }
    if (phase == Phase::Restitution && (ev & kRestituted)) phase = Phase::Done;
    if (phase == Phase::Done) record(ImpulsePhaseChange::Kind::EndOfRestitution);
    c(y, dydsigma, sigma);
  }
  result.integratorSteps = steps;
  result.sticking = c.friction == Friction::Sticking;
  result.slidingResumed = c.resumed;

  // Apply p to B and -p to A.
  const Eigen::Vector3d p = P * (frame * Eigen::Vector3d(y[0], y[1], sigma));
  result.impulse = p;
  if (!B.isStatic()) {
    b.velocity += B.inverseMass() * p;
    b.angularVelocity +=
        B.inverseInertiaWorld(b.worldFromBody.rotation) * (contact.point - b.worldFromBody.translation).cross(p);
  }
  if (!A.isStatic()) {
    a.velocity -= A.inverseMass() * p;
    a.angularVelocity -=
        A.inverseInertiaWorld(a.worldFromBody.rotation) * (contact.point - a.worldFromBody.translation).cross(p);
  }
  result.kineticEnergyAfter = A.kineticEnergy(a) + B.kineticEnergy(b);
  result.separationSpeed = (B.velocityAt(b, contact.point) - A.velocityAt(a, contact.point)).dot(n);
  return result;
}

}  // namespace gjkx
