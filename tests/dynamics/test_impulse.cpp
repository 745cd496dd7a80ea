// Impulse-based collision response (Mirtich's thesis, ch. 4) against physics nobody here
// wrote: Newton's cradle's head-on restitution, conservation of linear and angular
// momentum, kinetic energy that never rises, Coulomb's sliding loss mu P_n / m, the ball
// that ends rolling with 5/7 of its speed, a tilted box rebounding from a floor.
#include <gjkx/dynamics/impulse.hpp>

#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

using namespace gjkx;
using Catch::Matchers::Contains;

namespace {

BodyState at(const Eigen::Vector3d& position, const Eigen::Vector3d& v = Eigen::Vector3d::Zero(),
             const Eigen::Vector3d& w = Eigen::Vector3d::Zero(),
             const Eigen::Matrix3d& rotation = Eigen::Matrix3d::Identity()) {
  BodyState s;
  s.worldFromBody = Pose<double>::fromRotationTranslation(rotation, position);
  s.velocity = v;
  s.angularVelocity = w;
  return s;
}

RigidBody ball(double radius, double density) { return RigidBody::dynamic(massProperties(Sphere<double>(radius), density)); }

double relativeNormalSpeed(const RigidBody& A, const BodyState& a, const RigidBody& B, const BodyState& b,
                           const Contact& c) {
  return (B.velocityAt(b, c.point) - A.velocityAt(a, c.point)).dot(c.normal);
}

// The collision matrix measured rather than assembled: apply a unit impulse along each
// axis (to B, and its opposite to A) through the bodies' momenta, and read the change of
// the relative velocity at the contact point. Column i of K is that change.
Eigen::Matrix3d measuredCollisionMatrix(const RigidBody& A, const BodyState& a, const RigidBody& B, const BodyState& b,
                                        const Eigen::Vector3d& point) {
  auto relative = [&](const BodyState& sa, const BodyState& sb) -> Eigen::Vector3d {
    return B.velocityAt(sb, point) - A.velocityAt(sa, point);
  };
  Eigen::Matrix3d K;
  for (int i = 0; i < 3; ++i) {
    Eigen::Vector3d p = Eigen::Vector3d::Zero();
    p[i] = 1;
    BodyState a2 = a, b2 = b;
    b2.velocity += B.inverseMass() * p;
    b2.angularVelocity += B.inverseInertiaWorld(b.worldFromBody.rotation) * (point - b.worldFromBody.translation).cross(p);
    a2.velocity -= A.inverseMass() * p;
    a2.angularVelocity -= A.inverseInertiaWorld(a.worldFromBody.rotation) * (point - a.worldFromBody.translation).cross(p);
    K.col(i) = relative(a2, b2) - relative(a, b);
  }
  return K;
}

Eigen::Matrix3d randomRotation(std::mt19937& rng) {
  std::normal_distribution<double> n(0, 1);
  return Eigen::Quaterniond(n(rng), n(rng), n(rng), n(rng)).normalized().toRotationMatrix();
}
}  // namespace

// Two spheres head on, frictionless: the relative normal velocity after is -e times the
// one before, for equal and unequal masses and e = 0, 0.7, 1 (Newton's law, which
// Stronge's coefficient equals when friction does not couple in).
TEST_CASE("head-on spheres rebound with -e times the approach speed", "[dynamics][impulse]") {
  for (double e : {0.0, 0.7, 1.0}) {
    for (double densityB : {1.0, 3.0}) {
      const RigidBody A = ball(1.0, 1.0), B = ball(1.0, densityB);
      BodyState a = at(Eigen::Vector3d(-1, 0, 0), Eigen::Vector3d(2, 0, 0));
      BodyState b = at(Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(-0.5, 0, 0));
      const Contact c{Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitX()};
      const double before = relativeNormalSpeed(A, a, B, b, c);
      const ImpulseResult r = resolveCollision(A, a, B, b, c, {e, 0.0});
      CHECK(r.status == ImpulseStatus::Collision);
      CHECK(r.approachSpeed == Approx(2.5));
      CHECK(relativeNormalSpeed(A, a, B, b, c) == Approx(-e * before).margin(1e-12));
      CHECK(r.separationSpeed == Approx(-e * before).margin(1e-12));
      CHECK(a.angularVelocity.norm() < 1e-15);
      CHECK(b.angularVelocity.norm() < 1e-15);
      CHECK(r.integratorSteps == 0);  // frictionless: the impulse is linear, in closed form
      // Equal masses, e = 1: the velocities swap (Newton's cradle).
      if (e == 1.0 && densityB == 1.0) {
        CHECK((a.velocity - Eigen::Vector3d(-0.5, 0, 0)).norm() < 1e-12);
        CHECK((b.velocity - Eigen::Vector3d(2, 0, 0)).norm() < 1e-12);
      }
    }
  }
}

// Two free, turned boxes hit off centre with friction: the total linear momentum and the
// total angular momentum about the world origin are the same after as before.
TEST_CASE("an off-centre collision conserves linear and angular momentum", "[dynamics][impulse]") {
  std::mt19937 rng(7);
  const RigidBody A = RigidBody::dynamic(massProperties(Box<double>(Eigen::Vector3d(0.5, 0.2, 0.3)), 2.0));
  const RigidBody B = RigidBody::dynamic(massProperties(Box<double>(Eigen::Vector3d(0.3, 0.4, 0.1)), 5.0));
  for (int i = 0; i < 50; ++i) {
    BodyState a = at(Eigen::Vector3d(-0.6, 0.1, 0.2), Eigen::Vector3d(3, 1, -0.5), Eigen::Vector3d(1, -2, 0.5),
                     randomRotation(rng));
    BodyState b = at(Eigen::Vector3d(0.5, -0.3, 0.1), Eigen::Vector3d(-1, 0.5, 0.2), Eigen::Vector3d(0, 3, -1),
                     randomRotation(rng));
    const Contact c{Eigen::Vector3d(0.0, 0.05 * i - 1.0, 0.3), Eigen::Vector3d(1, 0.2, -0.1).normalized()};
    const Eigen::Vector3d P0 = A.linearMomentum(a) + B.linearMomentum(b);
    const Eigen::Vector3d L0 = A.angularMomentum(a) + B.angularMomentum(b);
    const ImpulseResult r = resolveCollision(A, a, B, b, c, {0.7, 0.4});
    if (r.status == ImpulseStatus::Separating) continue;
    CHECK((A.linearMomentum(a) + B.linearMomentum(b) - P0).norm() <= 1e-12 * P0.norm());
    CHECK((A.angularMomentum(a) + B.angularMomentum(b) - L0).norm() <= 1e-12 * std::max(1.0, L0.norm()));
    CHECK(r.kineticEnergyAfter <= r.kineticEnergyBefore);
  }
}

// Random bodies, contacts, velocities, restitution in [0, 1] and friction in [0, 1.5]:
// the kinetic energy never rises, and the bodies are not approaching afterwards.
TEST_CASE("kinetic energy never rises in a collision (random cases)", "[dynamics][impulse]") {
  std::mt19937 rng(2024);
  std::uniform_real_distribution<double> u(-1, 1), pos(0.05, 1.0), unit(0, 1);
  int collisions = 0, sticking = 0, resumed = 0;
  // One draw per statement, so the sequence does not depend on the order of evaluation.
  auto vec = [&](double scale) {
    const double x = u(rng), y = u(rng), z = u(rng);
    return Eigen::Vector3d(scale * x, scale * y, scale * z);
  };
  auto box = [&]() {
    const double hx = pos(rng), hy = pos(rng), hz = pos(rng);
    const double density = 1 + 9 * unit(rng);
    return RigidBody::dynamic(massProperties(Box<double>(Eigen::Vector3d(hx, hy, hz)), density));
  };
  for (int i = 0; i < 1500; ++i) {
    const RigidBody A = (i % 5 == 0) ? RigidBody::fixed() : box();
    const RigidBody B = box();
    const Eigen::Vector3d pa = vec(1), va = vec(3), wa = vec(5);
    const Eigen::Matrix3d Ra = randomRotation(rng);
    BodyState a = A.isStatic() ? at(pa, Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(), Ra) : at(pa, va, wa, Ra);
    const Eigen::Vector3d pb = vec(1), vb = vec(3), wb = vec(5);
    BodyState b = at(pb, vb, wb, randomRotation(rng));
    const Eigen::Vector3d point = vec(1), normal = vec(1).normalized();
    const Contact c{point, normal};
    const double e = unit(rng), mu = 1.5 * unit(rng);
    const CollisionMaterial material{e, mu};
    // Whether the contact can stick (Mirtich): the impulse direction (d_t, 1) that keeps the
    // tangential velocity still, K_tt d_t = -K_tn, must lie in the friction cone.
    const Eigen::Matrix3d K = measuredCollisionMatrix(A, a, B, b, c.point);
    const Eigen::Vector3d t1 = c.normal.unitOrthogonal(), t2 = c.normal.cross(t1);
    Eigen::Matrix3d frame;
    frame << t1, t2, c.normal;
    const Eigen::Matrix3d Kc = frame.transpose() * K * frame;
    const double stickRatio = Kc.topLeftCorner<2, 2>().ldlt().solve(Kc.topRightCorner<2, 1>()).norm();
    const ImpulseResult r = resolveCollision(A, a, B, b, c, material);
    if (r.status == ImpulseStatus::Separating) continue;
    ++collisions;
    sticking += r.sticking;
    resumed += r.slidingResumed;
    if (r.sticking) CHECK(stickRatio <= mu * (1 + 1e-9));
    if (r.slidingResumed) CHECK(stickRatio >= mu * (1 - 1e-9));
    INFO("case " << i << ": e " << material.restitution << ", mu " << material.friction);
    CHECK(r.status == ImpulseStatus::Collision);
    CHECK(r.kineticEnergyAfter <= r.kineticEnergyBefore * (1 + 1e-12));
    CHECK(r.impulse.dot(c.normal) > 0);  // the normal impulse pushes B away from A
    CHECK(relativeNormalSpeed(A, a, B, b, c) >= -1e-9 * r.approachSpeed);
  }
  CHECK(collisions > 400);
  CHECK(sticking > 40);  // every friction regime is exercised: sliding, sticking, and
  CHECK(resumed > 0);    // sliding that stops where it cannot stick and resumes on a ray
}

// The textbook cases below hold at the default tolerances to 1e-8, and to 1e-10 at tight
// ones (the integration's own accuracy, not the default's trade of digits for steps).
struct ToleranceCase {
  const char* name;
  ImpulseSettings settings;
  double epsilon;
};
std::vector<ToleranceCase> toleranceCases() {
  ImpulseSettings tight;
  tight.absoluteTolerance = tight.relativeTolerance = 1e-12;
  tight.stickingTolerance = 1e-9;
  return {{"default tolerances", ImpulseSettings{}, 1e-8}, {"tight tolerances", tight, 1e-10}};
}

// A ball sliding fast on a static floor: it slides all through the collision, so friction
// takes mu P_n from its tangential momentum, P_n = (1 + e) m v_n (the contact normal passes
// through the centre, so friction does not change the normal impulse).
TEST_CASE("a sliding hit loses mu times the normal impulse over m", "[dynamics][impulse]") {
  for (const ToleranceCase& t : toleranceCases()) {
    INFO(t.name);
    const RigidBody floor = RigidBody::fixed(), B = ball(0.5, 2.0);
    const double m = B.massProperties().mass, e = 0.7, mu = 0.4;
    BodyState a = at(Eigen::Vector3d(0, 0, -1));
    BodyState b = at(Eigen::Vector3d(0, 0, 0.5), Eigen::Vector3d(10, 0, -2));
    const ImpulseResult r =
        resolveCollision(floor, a, B, b, {Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitZ()}, {e, mu}, t.settings);
    const double Pn = (1 + e) * m * 2;
    CHECK(r.impulse.z() == Approx(Pn).epsilon(t.epsilon));
    CHECK(b.velocity.x() == Approx(10 - mu * Pn / m).epsilon(t.epsilon));
    CHECK(b.velocity.z() == Approx(e * 2).epsilon(t.epsilon));
    CHECK_FALSE(r.sticking);
    // The friction impulse at the bottom of the ball spins it forward: omega_y = (r x p)_y / J.
    const double J = 0.4 * m * 0.25;
    CHECK(b.angularVelocity.y() == Approx(0.5 * mu * Pn / J).epsilon(t.epsilon));
    CHECK(a.velocity.norm() == 0);  // the floor stays
  }
}

// A ball hitting the floor with little spin-free tangential speed: the contact point's
// sliding stops during the collision and the ball sticks, leaving it rolling without
// slipping with 5/7 of its tangential speed (the textbook result for a uniform ball:
// the tangential impulse is 2/7 m v_t). The normal rebound is still e v_n.
TEST_CASE("a slow sliding hit sticks and the ball rolls with 5/7 of its speed", "[dynamics][impulse]") {
  for (const ToleranceCase& t : toleranceCases()) {
    INFO(t.name);
    const RigidBody floor = RigidBody::fixed(), B = ball(0.5, 2.0);
    BodyState a = at(Eigen::Vector3d(0, 0, -1));
    BodyState b = at(Eigen::Vector3d(0, 0, 0.5), Eigen::Vector3d(1.0, 0.3, -2));
    const Contact c{Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitZ()};
    const ImpulseResult r = resolveCollision(floor, a, B, b, c, {0.7, 0.4}, t.settings);
    CHECK(r.sticking);
    CHECK((b.velocity.head<2>() - 5.0 / 7.0 * Eigen::Vector2d(1.0, 0.3)).norm() < t.epsilon);
    CHECK(B.velocityAt(b, c.point).head<2>().norm() < t.epsilon);  // rolling: the contact point is at rest
    CHECK(b.velocity.z() == Approx(1.4).epsilon(t.epsilon));
  }
}

// A box turned about two axes falls on a static floor, frictionless, e = 0.7: its lowest
// corner touches, and the normal velocity of that corner is -0.7 times its approach.
TEST_CASE("a box hitting a floor rebounds at e times its normal speed at the contact", "[dynamics][impulse]") {
  const RigidBody floor = RigidBody::fixed();
  const Eigen::Vector3d h(0.4, 0.2, 0.3);
  const RigidBody box = RigidBody::dynamic(massProperties(Box<double>(h), 3.0));
  const Eigen::Matrix3d R = (Eigen::AngleAxisd(0.5, Eigen::Vector3d::UnitX()) * Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitY())).toRotationMatrix();
  BodyState b = at(Eigen::Vector3d(0, 0, 1), Eigen::Vector3d(0.5, 0, -3), Eigen::Vector3d(0.2, 1, 0), R);
  Eigen::Vector3d lowest = Eigen::Vector3d::Constant(1e9);
  for (int i = 0; i < 8; ++i) {
    const Eigen::Vector3d corner = b.worldFromBody(Eigen::Vector3d((i & 1) ? h.x() : -h.x(), (i & 2) ? h.y() : -h.y(), (i & 4) ? h.z() : -h.z()));
    if (corner.z() < lowest.z()) lowest = corner;
  }
  BodyState a = at(Eigen::Vector3d(0, 0, -5));
  const Contact c{lowest, Eigen::Vector3d::UnitZ()};
  const double before = relativeNormalSpeed(floor, a, box, b, c);
  REQUIRE(before < 0);
  const ImpulseResult r = resolveCollision(floor, a, box, b, c, {0.7, 0.0});
  CHECK(r.status == ImpulseStatus::Collision);
  CHECK(relativeNormalSpeed(floor, a, box, b, c) == Approx(-0.7 * before).epsilon(1e-10));
  CHECK((r.impulse - r.impulse.dot(c.normal) * c.normal).norm() < 1e-12 * r.impulse.norm());  // frictionless
}

TEST_CASE("separating bodies get no impulse", "[dynamics][impulse]") {
  const RigidBody A = ball(1, 1), B = ball(1, 1);
  BodyState a = at(Eigen::Vector3d(-1, 0, 0), Eigen::Vector3d(-1, 0, 0));
  BodyState b = at(Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(0, 3, 0));
  const ImpulseResult r = resolveCollision(A, a, B, b, {Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitX()}, {});
  CHECK(r.status == ImpulseStatus::Separating);
  CHECK(r.impulse.norm() == 0);
  CHECK(a.velocity == Eigen::Vector3d(-1, 0, 0));
  CHECK(b.velocity == Eigen::Vector3d(0, 3, 0));
}

// Below the microcollision speed the restitution is 1, so a resting body bounces off
// with the speed it came in with instead of sinking; above it, the material's e holds.
TEST_CASE("microcollisions are elastic below the threshold speed", "[dynamics][impulse]") {
  const RigidBody floor = RigidBody::fixed(), B = ball(0.5, 1.0);
  ImpulseSettings settings;
  settings.microcollisionSpeed = 0.05;
  const Contact c{Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitZ()};
  for (double v : {0.001, 0.01, 0.049}) {
    BodyState a = at(Eigen::Vector3d(0, 0, -1)), b = at(Eigen::Vector3d(0, 0, 0.5), Eigen::Vector3d(0, 0, -v));
    const ImpulseResult r = resolveCollision(floor, a, B, b, c, {0.7, 0.4}, settings);
    CHECK(r.status == ImpulseStatus::Microcollision);
    CHECK(r.restitution == 1.0);
    CHECK(b.velocity.z() == Approx(v).epsilon(1e-10));
    CHECK(r.kineticEnergyAfter <= r.kineticEnergyBefore * (1 + 1e-12));
  }
  for (double v : {0.051, 1.0}) {
    BodyState a = at(Eigen::Vector3d(0, 0, -1)), b = at(Eigen::Vector3d(0, 0, 0.5), Eigen::Vector3d(0, 0, -v));
    const ImpulseResult r = resolveCollision(floor, a, B, b, c, {0.7, 0.4}, settings);
    CHECK(r.status == ImpulseStatus::Collision);
    CHECK(b.velocity.z() == Approx(0.7 * v).epsilon(1e-10));
  }
  // Off, the same slow approach keeps the material's e.
  BodyState a = at(Eigen::Vector3d(0, 0, -1)), b = at(Eigen::Vector3d(0, 0, 0.5), Eigen::Vector3d(0, 0, -0.01));
  const ImpulseResult r = resolveCollision(floor, a, B, b, c, {0.7, 0.4});
  CHECK(r.status == ImpulseStatus::Collision);
  CHECK(b.velocity.z() == Approx(0.007).epsilon(1e-10));
}

TEST_CASE("the impulse integration ends in its own status at the step cap", "[dynamics][impulse]") {
  const RigidBody A = ball(1, 1), B = ball(1, 1);
  BodyState a = at(Eigen::Vector3d(-1, 0, 0), Eigen::Vector3d(1, 0.5, 0));
  BodyState b = at(Eigen::Vector3d(1, 0, 0));
  ImpulseSettings settings;
  settings.maxSteps = 1;
  const ImpulseResult r = resolveCollision(A, a, B, b, {Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitX()}, {}, settings);
  CHECK(r.status == ImpulseStatus::StepCap);
  CHECK(r.integratorSteps == 1);
  CHECK(r.kineticEnergyAfter <= r.kineticEnergyBefore);
}

TEST_CASE("collision response rejects bad input", "[dynamics][impulse][input]") {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const RigidBody A = ball(1, 1), B = ball(1, 1);
  BodyState a = at(Eigen::Vector3d(-1, 0, 0), Eigen::Vector3d(1, 0, 0)), b = at(Eigen::Vector3d(1, 0, 0));
  const Contact c{Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitX()};
  REQUIRE_THROWS_WITH(resolveCollision(A, a, B, b, {Eigen::Vector3d(nan, 0, 0), Eigen::Vector3d::UnitX()}, {}),
                      Contains("contact.point"));
  REQUIRE_THROWS_WITH(resolveCollision(A, a, B, b, {Eigen::Vector3d::Zero(), Eigen::Vector3d(2, 0, 0)}, {}),
                      Contains("contact.normal"));
  REQUIRE_THROWS_WITH(resolveCollision(A, a, B, b, {Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()}, {}),
                      Contains("contact.normal"));
  REQUIRE_THROWS_WITH(resolveCollision(A, a, B, b, c, {1.5, 0.4}), Contains("material.restitution"));
  REQUIRE_THROWS_WITH(resolveCollision(A, a, B, b, c, {-0.1, 0.4}), Contains("material.restitution"));
  REQUIRE_THROWS_WITH(resolveCollision(A, a, B, b, c, {0.5, -1.0}), Contains("material.friction"));
  REQUIRE_THROWS_WITH(resolveCollision(A, a, B, b, c, {0.5, nan}), Contains("material.friction"));
  ImpulseSettings s;
  s.microcollisionSpeed = -1;
  REQUIRE_THROWS_WITH(resolveCollision(A, a, B, b, c, {}, s), Contains("settings.microcollisionSpeed"));
  BodyState bad = b;
  bad.velocity.y() = nan;
  REQUIRE_THROWS_WITH(resolveCollision(A, a, B, bad, c, {}), Contains("b.velocity"));
  bad = a;
  bad.worldFromBody.rotation *= 2;
  REQUIRE_THROWS_WITH(resolveCollision(A, bad, B, b, c, {}), Contains("a.worldFromBody.rotation"));
  const RigidBody wall = RigidBody::fixed();
  REQUIRE_THROWS_WITH(resolveCollision(wall, a, wall, b, c, {}), Contains("bodies"));
}

// An impulse step by step (Mirtich's integration over the normal impulse p_z, Stronge's
// restitution), on a uniform ball of mass m and radius r hitting a static floor with normal
// speed v_n = 1 and tangential speed v_t = 0.35 along x, no spin, mu = 0.4, e = 0.5. At the
// contact point r = (0, 0, -r) from the centre, the collision matrix in the contact frame
// is diagonal: K_tt = 1/m + r^2/J = (1 + 5/2)/m = 3.5/m (J = 2 m r^2 / 5), K_nn = 1/m.
//  1. Sliding: the tangential impulse is -mu p_z along the slide, so
//     u_t(p_z) = v_t - 3.5 mu p_z / m, zero at p_z = m v_t / (3.5 mu) = 0.25 m. There the
//     sticking impulse (the one that keeps u_t = 0) has no tangential part (K is
//     diagonal), inside the friction cone: the contact sticks, with tangential impulse
//     -mu p_z = -0.1 m.
//  2. Compression: u_n(p_z) = -v_n + p_z / m, zero at p_z = m v_n = m; the work done is
//     W_c = int_0^m u_n dp_z = -m v_n^2 / 2 = -0.5 m.
//  3. Restitution (Stronge): it ends when W = (1 - e^2) W_c = -0.375 m; after compression
//     W = W_c + (p_z - m)^2 / (2m), so (p_z - m)^2 = m^2 e^2 v_n^2: p_z = m (1 + e) = 1.5 m,
//     where u_n = e v_n = 0.5.
// The ball leaves rolling: v_t' = v_t - 0.1 = 0.25 = (5/7) v_t, v_n' = 0.5.
TEST_CASE("an impulse, step by step: sliding, sticking, compression and Stronge's restitution", "[dynamics][impulse][steps]") {
  const RigidBody floor = RigidBody::fixed(), B = ball(0.5, 2.0);
  const double m = 1 / B.inverseMass();
  BodyState a = at(Eigen::Vector3d(0, 0, -1));
  BodyState b = at(Eigen::Vector3d(0, 0, 0.5), Eigen::Vector3d(0.35, 0, -1));
  const Contact c{Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitZ()};
  ImpulseTrace trace;
  const ImpulseResult r = resolveCollision(floor, a, B, b, c, {0.5, 0.4}, {}, &trace);
  REQUIRE(r.status == ImpulseStatus::Collision);
  REQUIRE(trace.changes.size() == 3);
  const ImpulsePhaseChange& stop = trace.changes[0];
  CHECK(stop.kind == ImpulsePhaseChange::Kind::SlidingStopped);
  CHECK(stop.sticking);
  CHECK(stop.normalImpulse == Approx(0.25 * m).epsilon(1e-5));
  CHECK(stop.tangentialImpulse.norm() == Approx(0.1 * m).epsilon(1e-5));
  CHECK(stop.normalVelocity == Approx(-1 + 0.25).epsilon(1e-5));
  const ImpulsePhaseChange& compressed = trace.changes[1];
  CHECK(compressed.kind == ImpulsePhaseChange::Kind::EndOfCompression);
  CHECK(compressed.normalImpulse == Approx(m).epsilon(1e-9));
  CHECK(compressed.work == Approx(-0.5 * m).epsilon(1e-9));
  CHECK(std::abs(compressed.normalVelocity) < 1e-9);
  const ImpulsePhaseChange& restituted = trace.changes[2];
  CHECK(restituted.kind == ImpulsePhaseChange::Kind::EndOfRestitution);
  CHECK(restituted.normalImpulse == Approx(1.5 * m).epsilon(1e-9));
  CHECK(restituted.work == Approx((1 - 0.25) * compressed.work).epsilon(1e-9));  // Stronge: (1 - e^2) W_c
  CHECK(restituted.normalVelocity == Approx(0.5).epsilon(1e-9));
  CHECK(b.velocity.x() == Approx(0.25).epsilon(1e-5));
  CHECK(b.velocity.z() == Approx(0.5).epsilon(1e-9));
  CHECK(B.velocityAt(b, c.point).x() == Approx(0).margin(1e-6));  // rolling
}
