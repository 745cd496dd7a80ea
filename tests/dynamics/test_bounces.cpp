// The dynamics stage on its own, over several collisions (no collision detection: the
// contact times are solved by hand): free flight and collision response together give the
// textbook answers of a ball bouncing on a floor and of a box sliding to a stop.
#include <gjkx/dynamics/free_flight.hpp>
#include <gjkx/dynamics/impulse.hpp>

#include <catch2/catch.hpp>

#include <cmath>

using namespace gjkx;

// A spinning ball dropped from height H above a floor rebounds to e^2 of its drop height at
// every bounce: the normal through the contact passes through the centre, so friction
// (here sliding against the spin) never changes the normal impulse, and the rebound speed
// is e times the impact speed, sqrt(2 g H). The contact time is the root of the parabola.
TEST_CASE("a ball dropped on a floor rebounds to e^2 of its height each bounce", "[dynamics][bounce]") {
  const double r = 0.25, g = 9.81, e = 0.7;
  const RigidBody floor = RigidBody::fixed(), ball = RigidBody::dynamic(massProperties(Sphere<double>(r), 500.0));
  BodyState floorState;
  floorState.worldFromBody = Pose<double>::translate(Eigen::Vector3d(0, 0, -1));
  BodyState s;
  s.worldFromBody = Pose<double>::translate(Eigen::Vector3d(0, 0, r + 2.0));  // 2 m above the floor
  s.angularVelocity = Eigen::Vector3d(0, 5, 0);
  const Eigen::Vector3d gravity(0, 0, -g);
  double t = 0, height = 2.0;
  for (int bounce = 0; bounce < 6; ++bounce) {
    // Fall: z(t) = z0 + v tau - g tau^2 / 2 reaches r.
    const double z0 = s.worldFromBody.translation.z(), v = s.velocity.z();
    const double tau = (v + std::sqrt(v * v + 2 * g * (z0 - r))) / g;
    const FreeFlight flight = freeFlight(ball, s, t, t + tau, gravity);
    s = flight.end;
    t += tau;
    CHECK(s.worldFromBody.translation.z() == Approx(r).epsilon(1e-12));
    CHECK(-s.velocity.z() == Approx(std::sqrt(2 * g * height)).epsilon(1e-10));
    const Contact contact{s.worldFromBody.translation - Eigen::Vector3d(0, 0, r), Eigen::Vector3d::UnitZ()};
    const ImpulseResult hit = resolveCollision(floor, floorState, ball, s, contact, {e, 0.4});
    REQUIRE(hit.status == ImpulseStatus::Collision);
    // Up again: the apex is v^2 / (2g) above the contact height.
    const double apex = s.velocity.z() * s.velocity.z() / (2 * g);
    CHECK(apex / height == Approx(e * e).epsilon(1e-9));
    height = apex;
  }
}

// A box sliding on a floor under gravity stops after v^2 / (2 mu g). Resting contact is a
// train of microcollisions (Mirtich): the box rests on its corners, every corner that
// has reached the floor and approaches it gets a collision, elastic below the
// microcollision speed sqrt(2 g eps). Each of them takes mu P_n of tangential momentum
// while the corners slide, and the normal impulses average m g over time, so the box
// decelerates at mu g. Contacts are found at the end of short flights of 1 ms (the
// corners' heights are checked by hand; no collision detection).
TEST_CASE("a box sliding on a floor stops after v^2/(2 mu g)", "[dynamics][bounce]") {
  const double g = 9.81, mu = 0.4, v0 = 2.0, eps = 1e-4, dt = 1e-3;
  const Eigen::Vector3d h(0.2, 0.15, 0.1);
  const RigidBody floor = RigidBody::fixed(), box = RigidBody::dynamic(massProperties(Box<double>(h), 800.0));
  BodyState floorState;
  BodyState s;
  s.worldFromBody = Pose<double>::translate(Eigen::Vector3d(0, 0, h.z()));
  s.velocity = Eigen::Vector3d(v0, 0, 0);
  ImpulseSettings settings;
  settings.microcollisionSpeed = std::sqrt(2 * g * eps);
  const CollisionMaterial material{0.7, mu};
  double t = 0, tStop = -1, xStop = 0;
  int collisions = 0, microcollisions = 0;
  while (t < 1.0) {
    s = freeFlight(box, s, t, t + dt, Eigen::Vector3d(0, 0, -g)).end;
    t += dt;
    // Collide every corner at or below the floor that approaches it, until none does.
    for (int pass = 0; pass < 20; ++pass) {
      bool any = false;
      for (int i = 0; i < 8; ++i) {
        const Eigen::Vector3d corner =
            s.worldFromBody(Eigen::Vector3d((i & 1) ? h.x() : -h.x(), (i & 2) ? h.y() : -h.y(), (i & 4) ? h.z() : -h.z()));
        if (corner.z() > 0) continue;
        const ImpulseResult r = resolveCollision(floor, floorState, box, s, {corner, Eigen::Vector3d::UnitZ()}, material, settings);
        if (r.status == ImpulseStatus::Separating) continue;
        any = true;
        ++collisions;
        microcollisions += r.status == ImpulseStatus::Microcollision;
      }
      if (!any) break;
    }
    if (tStop < 0 && s.velocity.head<2>().norm() < 0.01 * v0) {
      tStop = t;
      xStop = s.worldFromBody.translation.x();
    }
  }
  const double distance = xStop;
  const double expected = v0 * v0 / (2 * mu * g);
  INFO("stopped after " << distance << " m in " << tStop << " s (expected " << expected << " m, " << v0 / (mu * g)
                        << " s); " << collisions << " collisions, " << microcollisions
                        << " microcollisions; at 1 s: x " << s.worldFromBody.translation.x() << " m, |v_xy| "
                        << s.velocity.head<2>().norm() << " m/s, z " << s.worldFromBody.translation.z() << " m");
  REQUIRE(tStop > 0);
  CHECK(distance == Approx(expected).epsilon(0.03));
  CHECK(tStop == Approx(v0 / (mu * g)).epsilon(0.03));
  // And it stays stopped: a second later it has not crept on.
  CHECK(std::abs(s.worldFromBody.translation.x() - xStop) < 0.01 * expected);
  CHECK(microcollisions > 100);
  CHECK(std::abs(s.worldFromBody.translation.z() - h.z()) < 0.01);  // neither sunk nor flown off
}
