// Free flight against the physics of a torque-free rigid body: angular momentum and
// kinetic energy are conserved, a body spun near its intermediate principal axis flips
// over (the Dzhanibekov effect, the tennis racket theorem), and Boost.Odeint's answer
// agrees with a very fine, independent integration of R' = [omega] R,
// omega = R J_b^-1 R^T L by the classical Runge-Kutta method.
#include <gjkx/dynamics/free_flight.hpp>

#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

using namespace gjkx;
using Catch::Matchers::Contains;

namespace {

// An asymmetric box body: principal moments 13 : 10 : 5 about x, y, z (y intermediate).
RigidBody asymmetricBody() { return RigidBody::dynamic(massProperties(Box<double>(Eigen::Vector3d(0.1, 0.2, 0.3)), 1000.0)); }

BodyState stateWith(const Eigen::Vector3d& position, const Eigen::Matrix3d& rotation, const Eigen::Vector3d& v,
                    const Eigen::Vector3d& w) {
  BodyState s;
  s.worldFromBody = Pose<double>::fromRotationTranslation(rotation, position);
  s.velocity = v;
  s.angularVelocity = w;
  return s;
}

double angleBetween(const Eigen::Matrix3d& a, const Eigen::Matrix3d& b) {
  return Eigen::AngleAxisd(Eigen::Matrix3d(a.transpose() * b)).angle();
}

// The reference: classical RK4 on the rotation matrix with omega from the conserved L, a
// different formulation (world frame, matrix, momentum form) from the library's
// (quaternion, body-frame Euler equations), re-orthonormalised each step.
Eigen::Matrix3d referenceRotation(const RigidBody& body, Eigen::Matrix3d R, const Eigen::Vector3d& L, double T, int steps) {
  const Eigen::Matrix3d& Jinv = body.inverseInertiaBody();
  auto f = [&](const Eigen::Matrix3d& r) {
    const Eigen::Vector3d w = r * (Jinv * (r.transpose() * L));
    Eigen::Matrix3d wx;
    wx << 0, -w.z(), w.y(), w.z(), 0, -w.x(), -w.y(), w.x(), 0;
    return Eigen::Matrix3d(wx * r);
  };
  const double h = T / steps;
  for (int i = 0; i < steps; ++i) {
    const Eigen::Matrix3d k1 = f(R), k2 = f(R + 0.5 * h * k1), k3 = f(R + 0.5 * h * k2), k4 = f(R + h * k3);
    R += h / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
    const Eigen::JacobiSVD<Eigen::Matrix3d> svd(R, Eigen::ComputeFullU | Eigen::ComputeFullV);
    R = svd.matrixU() * svd.matrixV().transpose();
  }
  return R;
}
}  // namespace

TEST_CASE("free flight of a static body does nothing", "[dynamics][flight]") {
  const BodyState s = stateWith(Eigen::Vector3d(1, 2, 3), Eigen::Matrix3d::Identity(), Eigen::Vector3d::Zero(),
                                Eigen::Vector3d::Zero());
  const FreeFlight f = freeFlight(RigidBody::fixed(), s, 0.0, 1.0, Eigen::Vector3d(0, 0, -9.81));
  CHECK(f.status == FreeFlightStatus::Static);
  CHECK(f.motion.isStatic());
  CHECK(f.integratorSteps == 0);
  CHECK(f.end.worldFromBody.translation == s.worldFromBody.translation);
  CHECK(f.stateAt(0.5).velocity.norm() == 0);
}

// No spin: the centre of mass follows c0 + v0 t + g t^2 / 2, the rotation never changes.
TEST_CASE("free flight without spin is ballistic", "[dynamics][flight]") {
  const Eigen::Matrix3d R = Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitX()).toRotationMatrix();
  const BodyState s = stateWith(Eigen::Vector3d(0, 0, 10), R, Eigen::Vector3d(3, 0, 4), Eigen::Vector3d::Zero());
  const Eigen::Vector3d g(0, 0, -9.81);
  const FreeFlight f = freeFlight(asymmetricBody(), s, 1.0, 2.0, g);
  CHECK(f.status == FreeFlightStatus::Translating);
  CHECK(f.integratorSteps == 0);
  CHECK((f.end.worldFromBody.translation - Eigen::Vector3d(3, 0, 10 + 4 - 9.81 / 2)).norm() < 1e-13);
  CHECK(f.end.worldFromBody.rotation == R);
  CHECK((f.end.velocity - Eigen::Vector3d(3, 0, 4 - 9.81)).norm() < 1e-14);
  const BodyState mid = f.stateAt(1.25);
  CHECK((mid.velocity - (s.velocity + 0.25 * g)).norm() < 1e-14);
  CHECK(mid.worldFromBody.translation == f.motion.pose(1.25).translation);
  // Without gravity the path is a constant velocity.
  CHECK(std::holds_alternative<ConstantVelocity<double>>(
      freeFlight(asymmetricBody(), s, 0.0, 1.0, Eigen::Vector3d::Zero()).motion.variant()));
}

// A sphere and a cube have isotropic inertia: omega is constant and the rotation is
// exp([omega] t) R0 in closed form, with no integration.
TEST_CASE("free flight of an isotropic body turns at a constant rate", "[dynamics][flight]") {
  const Eigen::Vector3d w(0.4, -1.0, 0.7);
  const BodyState s = stateWith(Eigen::Vector3d::Zero(), Eigen::Matrix3d::Identity(), Eigen::Vector3d(1, 0, 0), w);
  for (const Shape<double>& shape : {Shape<double>(Sphere<double>(0.5)), Shape<double>(Box<double>(Eigen::Vector3d(1, 1, 1)))}) {
    const RigidBody body = RigidBody::dynamic(massProperties(shape, 2.0));
    for (const Eigen::Vector3d& g : {Eigen::Vector3d(0, 0, -9.81), Eigen::Vector3d(0, 0, 0)}) {
      const FreeFlight f = freeFlight(body, s, 0.0, 0.8, g);
      CHECK(f.status == FreeFlightStatus::Spinning);
      CHECK(f.integratorSteps == 0);
      const Eigen::Matrix3d expected = Eigen::AngleAxisd(w.norm() * 0.8, w.normalized()).toRotationMatrix();
      CHECK(angleBetween(f.end.worldFromBody.rotation, expected) < 1e-12);
      CHECK(angleBetween(f.motion.pose(0.4).rotation, Eigen::AngleAxisd(w.norm() * 0.4, w.normalized()).toRotationMatrix()) <
            1e-12);
      CHECK((f.stateAt(0.3).angularVelocity - w).norm() < 1e-14);
      CHECK((f.end.worldFromBody.translation - (0.8 * Eigen::Vector3d(1, 0, 0) + 0.32 * g)).norm() < 1e-14);
    }
  }
}

// An asymmetric body tumbling freely for 4 s: the integrated state conserves the world
// angular momentum and the kinetic energy to ~1e-11, the path ends exactly at the state,
// and the intermediate states are on the path.
TEST_CASE("torque-free flight conserves angular momentum and energy", "[dynamics][flight]") {
  const RigidBody body = asymmetricBody();
  const Eigen::Matrix3d R0 = Eigen::AngleAxisd(0.5, Eigen::Vector3d(1, 1, 0).normalized()).toRotationMatrix();
  const BodyState s = stateWith(Eigen::Vector3d(0, 0, 5), R0, Eigen::Vector3d(0, 1, 0), Eigen::Vector3d(2.0, -3.0, 1.5));
  const Eigen::Vector3d g(0, 0, -9.81);
  const FreeFlight f = freeFlight(body, s, 0.0, 4.0, g);
  REQUIRE(f.status == FreeFlightStatus::Integrated);
  CHECK(f.integratorSteps > 10);

  const Eigen::Matrix3d J0 = body.inertiaWorld(R0), J1 = body.inertiaWorld(f.end.worldFromBody.rotation);
  const Eigen::Vector3d L0 = J0 * s.angularVelocity, L1 = J1 * f.end.angularVelocity;
  CHECK((L1 - L0).norm() <= 1e-10 * L0.norm());
  const double E0 = 0.5 * s.angularVelocity.dot(L0), E1 = 0.5 * f.end.angularVelocity.dot(L1);
  CHECK(std::abs(E1 - E0) <= 1e-10 * E0);
  CHECK((f.angularMomentum - L0).norm() <= 1e-14 * L0.norm());

  // The path ends at the integrated state, exactly.
  CHECK(f.motion.pose(4.0).rotation == f.end.worldFromBody.rotation);
  CHECK(f.motion.pose(4.0).translation == f.end.worldFromBody.translation);
  const BodyState end = f.stateAt(4.0);
  CHECK(end.angularVelocity == f.end.angularVelocity);
  CHECK((f.end.velocity - (s.velocity + 4.0 * g)).norm() < 1e-13);

  // An intermediate state: on the path, with the momentum L.
  const BodyState mid = f.stateAt(1.7);
  CHECK(mid.worldFromBody.rotation == f.motion.pose(1.7).rotation);
  CHECK(mid.worldFromBody.translation == f.motion.pose(1.7).translation);
  CHECK((body.inertiaWorld(mid.worldFromBody.rotation) * mid.angularVelocity - L0).norm() <= 1e-12 * L0.norm());
  CHECK(f.turnedAngle > 4.0 * 2.0);  // |omega| never drops below |omega_x| about here
}

// Spun about its intermediate axis with a small perturbation, the box flips over again
// and again (Dzhanibekov). Flown in short flights of 0.05 s (as a simulation steps it), the
// body-frame spin about y changes sign; flown in one piece over 12 s, Boost.Odeint's end
// orientation agrees with the fine RK4 reference (h = 2e-5 s).
TEST_CASE("a body spun near its intermediate axis flips (Dzhanibekov)", "[dynamics][flight]") {
  const RigidBody body = asymmetricBody();
  const BodyState s0 = stateWith(Eigen::Vector3d::Zero(), Eigen::Matrix3d::Identity(), Eigen::Vector3d::Zero(),
                                 Eigen::Vector3d(1e-3, 6.0, 1e-3));
  BodyState s = s0;
  int flips = 0;
  double previous = 1;
  for (int i = 0; i < 240; ++i) {
    const FreeFlight f = freeFlight(body, s, 0.05 * i, 0.05 * (i + 1), Eigen::Vector3d::Zero());
    s = f.end;
    const double wy = (s.worldFromBody.rotation.transpose() * s.angularVelocity).y();
    if (wy * previous < 0) ++flips;
    previous = wy;
  }
  INFO("flips of the spin about the intermediate axis in 12 s: " << flips);
  CHECK(flips >= 2);

  const double T = 12.0;
  const FreeFlight whole = freeFlight(body, s0, 0.0, T, Eigen::Vector3d::Zero());
  REQUIRE(whole.status == FreeFlightStatus::Integrated);
  const Eigen::Vector3d L = body.inertiaWorld(s0.worldFromBody.rotation) * s0.angularVelocity;
  const Eigen::Matrix3d reference = referenceRotation(body, s0.worldFromBody.rotation, L, T, 600000);
  INFO("odeint against RK4: " << angleBetween(whole.end.worldFromBody.rotation, reference) << " rad");
  CHECK(angleBetween(whole.end.worldFromBody.rotation, reference) < 1e-7);
  // The chained short flights reach the same orientation as the single long one.
  CHECK(angleBetween(whole.end.worldFromBody.rotation, s.worldFromBody.rotation) < 1e-7);
}

TEST_CASE("free flight ends in its own status at the step cap", "[dynamics][flight]") {
  FreeFlightSettings settings;
  settings.maxSteps = 5;
  const BodyState s = stateWith(Eigen::Vector3d::Zero(), Eigen::Matrix3d::Identity(), Eigen::Vector3d::Zero(),
                                Eigen::Vector3d(2, 3, 1));
  const FreeFlight f = freeFlight(asymmetricBody(), s, 0.0, 100.0, Eigen::Vector3d::Zero(), settings);
  CHECK(f.status == FreeFlightStatus::StepCap);
  CHECK(f.integratorSteps == 5);
  CHECK(f.t1 < 100.0);
  CHECK(f.motion.pose(f.t1).rotation == f.end.worldFromBody.rotation);
}

TEST_CASE("free flight rejects bad input", "[dynamics][flight][input]") {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const RigidBody body = asymmetricBody();
  const BodyState good = stateWith(Eigen::Vector3d::Zero(), Eigen::Matrix3d::Identity(), Eigen::Vector3d::Zero(),
                                   Eigen::Vector3d(1, 0, 0));
  const Eigen::Vector3d g(0, 0, -9.81);
  REQUIRE_THROWS_WITH(freeFlight(body, good, 1.0, 0.0, g), Contains("flight.t1"));
  REQUIRE_THROWS_WITH(freeFlight(body, good, nan, 1.0, g), Contains("flight.t0"));
  REQUIRE_THROWS_WITH(freeFlight(body, good, 0.0, 1.0, Eigen::Vector3d(nan, 0, 0)), Contains("gravity"));
  BodyState bad = good;
  bad.velocity.x() = nan;
  REQUIRE_THROWS_WITH(freeFlight(body, bad, 0.0, 1.0, g), Contains("start.velocity"));
  bad = good;
  bad.angularVelocity.z() = INFINITY;
  REQUIRE_THROWS_WITH(freeFlight(body, bad, 0.0, 1.0, g), Contains("start.angularVelocity"));
  bad = good;
  bad.worldFromBody.rotation(0, 1) = 0.5;
  REQUIRE_THROWS_WITH(freeFlight(body, bad, 0.0, 1.0, g), Contains("start.worldFromBody.rotation"));
  FreeFlightSettings settings;
  settings.maxSteps = 0;
  REQUIRE_THROWS_WITH(freeFlight(body, good, 0.0, 1.0, g, settings), Contains("settings.maxSteps"));
  const FreeFlight f = freeFlight(body, good, 0.0, 1.0, g);
  REQUIRE_THROWS_WITH(f.stateAt(1.5), Contains("t"));
  REQUIRE_THROWS_AS(f.stateAt(-0.1), std::invalid_argument);

  MassProperties m = massProperties(Box<double>(Eigen::Vector3d(1, 1, 1)), 1.0);
  m.mass = -1;
  REQUIRE_THROWS_WITH(RigidBody::dynamic(m), Contains("massProperties.mass"));
  m.mass = 1;
  m.inertia(0, 0) = -1;
  REQUIRE_THROWS_WITH(RigidBody::dynamic(m), Contains("massProperties.inertia"));
  m.inertia(0, 0) = 1;
  m.inertia(0, 1) = 5;
  REQUIRE_THROWS_WITH(RigidBody::dynamic(m), Contains("massProperties.inertia"));
}
