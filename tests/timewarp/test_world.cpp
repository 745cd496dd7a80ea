// The world against physics nobody here wrote: bounces lose e^2 of their height, friction
// stops a sliding box after v^2 / (2 mu g), collisions conserve momentum and never make
// energy, a falling stack has no collisions, Newton's cradle passes the momentum down the
// row in order, a thin plate does not tunnel through a thin wall, and the three orderings
// agree where all three are valid.
#include <gjkx/timewarp/scene.hpp>
#include <gjkx/timewarp/world.hpp>

#include <Eigen/Geometry>
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

using namespace gjkx;

namespace {

struct Run {
  long collisions = 0, rollbacks = 0, checks = 0;
  int tunnelled = 0;
  double maxPenetration = 0;
};

Run runAll(World& world) {
  Run run;
  while (!world.done()) {
    const FrameReport r = world.step();
    run.collisions += r.counters.collisions;
    run.rollbacks += r.counters.rollbacks;
    run.checks += r.counters.collisionChecks;
    run.tunnelled += r.counters.tunnelled;
    run.maxPenetration = std::max(run.maxPenetration, r.counters.maxPenetration);
  }
  return run;
}

/// The settings of these tests: the independent checks on (off by default), so that every
/// run is measured for penetration and tunnelling.
WorldSettings checked() {
  WorldSettings settings;
  settings.checks = true;
  return settings;
}

std::string orderingKey(Ordering o) { return std::string(R"("ordering": ")") + orderingName(o) + R"(",)"; }

}  // namespace

TEST_CASE("world: a ball dropped on the floor rebounds to e^2 of its height each bounce") {
  const double e = 0.7, g = 9.81, h0 = 1.0, r = 0.1;
  const Scene scene = parseScene(R"({ "duration": 2.2, "restitution": 0.7, "friction": 0, "scalar": "double",
      "bodies": [ { "name": "floor", "shape": {"box": [2, 2, 0.5]}, "position": [0, 0, -0.5], "static": true },
                  { "name": "ball", "shape": {"sphere": 0.1}, "position": [0, 0, 1.1] } ] })");
  World world(scene, checked());
  // Between bounces z + vz^2 / (2g) is the apex height of the ball's bottom (ballistic flight).
  std::vector<double> apexes;
  double last = h0;
  while (!world.done()) {
    world.step();
    const BodyState s = world.stateOf(1);
    const double apex = s.worldFromBody.translation.z() - r + s.velocity.z() * s.velocity.z() / (2 * g);
    if (std::abs(apex - last) > 1e-3 * h0) apexes.push_back(apex);
    last = apex;
  }
  REQUIRE(apexes.size() >= 3);
  CHECK(apexes[0] == Approx(h0 * e * e).epsilon(0.02));
  CHECK(apexes[1] == Approx(h0 * std::pow(e, 4)).epsilon(0.03));
  CHECK(apexes[2] == Approx(h0 * std::pow(e, 6)).epsilon(0.05));
}

TEST_CASE("world: a box sliding on the floor stops after v^2 / (2 mu g)") {
  const double v = 2.0, mu = 0.4, g = 9.81;
  const Scene scene = parseScene(R"({ "duration": 1.5, "friction": 0.4, "scalar": "double",
      "bodies": [ { "name": "floor", "shape": {"box": [4, 4, 0.5]}, "position": [0, 0, -0.5], "static": true },
                  { "name": "box", "shape": {"box": [0.2, 0.2, 0.05]}, "position": [-1, 0, 0.0502], "velocity": [2, 0, 0] } ] })");
  World world(scene, checked());
  runAll(world);
  const double travelled = world.positionOf(1).x() + 1;
  CHECK(travelled == Approx(v * v / (2 * mu * g)).epsilon(0.1));
  CHECK(world.stateOf(1).velocity.norm() < 0.05);
}

// The impulse integration's tolerances come in with the world's settings: the sliding box
// stops where friction stops it at the default tolerances and at tight ones (the sliding
// contact's impulses are integrated in either, in fewer steps at the default), and a bad
// setting is refused when the world is built, by name.
TEST_CASE("world: the impulse tolerances are the settings', and a bad one is refused by name") {
  // The paper's model: the sliding box is a train of microcollisions, each an integrated
  // impulse (under the hybrid its contact solver holds it, and no impulse is integrated).
  const Scene scene = parseScene(R"({ "duration": 1.5, "friction": 0.4, "scalar": "double", "contact": "microcollisions",
      "bodies": [ { "name": "floor", "shape": {"box": [4, 4, 0.5]}, "position": [0, 0, -0.5], "static": true },
                  { "name": "box", "shape": {"box": [0.2, 0.2, 0.05]}, "position": [-1, 0, 0.0502], "velocity": [2, 0, 0] } ] })");
  WorldSettings tight;
  tight.impulse.absoluteTolerance = tight.impulse.relativeTolerance = 1e-12;
  tight.impulse.stickingTolerance = 1e-9;
  long steps[2] = {0, 0};
  double travelled[2] = {0, 0};
  for (int k = 0; k < 2; ++k) {
    World world(scene, k == 0 ? checked() : tight);
    long collisions = 0;
    while (!world.done()) {
      const FrameReport r = world.step();
      steps[k] += r.counters.impulseSteps;
      collisions += r.counters.collisions;
    }
    CHECK(collisions > 0);
    travelled[k] = world.positionOf(1).x() + 1;
  }
  CHECK(travelled[0] == Approx(2.0 * 2.0 / (2 * 0.4 * 9.81)).epsilon(0.1));
  CHECK(travelled[0] == Approx(travelled[1]).epsilon(0.01));
  CHECK(steps[0] > 0);
  CHECK(steps[0] < steps[1]);

  // An integration cut short by its step cap is counted, not silent.
  WorldSettings capped;
  capped.impulse.maxSteps = 1;
  World cut(scene, capped);
  long caps = 0;
  while (!cut.done()) caps += cut.step().counters.impulseCaps;
  CHECK(caps > 0);

  WorldSettings bad;
  bad.impulse.stickingTolerance = 0;
  CHECK_THROWS_WITH(World(scene, bad), Catch::Matchers::Contains("settings.impulse.stickingTolerance"));
  bad = WorldSettings{};
  bad.impulse.absoluteTolerance = std::nan("");
  CHECK_THROWS_WITH(World(scene, bad), Catch::Matchers::Contains("settings.impulse.absoluteTolerance"));
}

// Settling (gjkx::settle, sleep.hpp): a body with too little kinetic energy to lift its centre of
// mass by one tolerance, struck only by resting bodies in a frame, sleeps at its end. A
// thin rod dropped 2 mm onto the floor at a slant (it lands on one end and rocks) must end
// asleep, still, and no deeper than the tolerance band; a box thrown up slowly from 1.5 m
// (the same tiny energy at the top of its flight, but struck by nothing there) must not
// sleep before it has landed.
TEST_CASE("world: a body rattling in the tolerance band settles, one in the air does not") {
  const Scene scene = parseScene(R"({ "duration": 1.0, "friction": 0.4, "restitution": 0.3, "scalar": "float",
      "bodies": [ { "name": "floor", "shape": {"box": [2, 2, 0.5]}, "position": [0, 0, -0.5], "static": true },
                  { "name": "rod", "shape": {"box": [0.15, 0.01, 0.01]}, "position": [0, 0, 0.04],
                    "orientation": [0.9990482, 0, 0.0436194, 0] },
                  { "name": "tossed", "shape": {"box": [0.05, 0.05, 0.05]}, "position": [1, 1, 1.5], "velocity": [0, 0, 0.01] } ] })");
  World world(scene, checked());
  long settled = 0;
  bool tossedSleptInAir = false;
  double deepest = 0;
  while (!world.done()) {
    const FrameReport r = world.step();
    settled += r.counters.settled;
    deepest = std::max(deepest, r.counters.maxPenetration);
    tossedSleptInAir = tossedSleptInAir || (world.bodies()[2].asleep && world.positionOf(2).z() > 0.1);
  }
  INFO("settled " << settled << ", deepest penetration " << deepest);
  CHECK(settled >= 1);
  CHECK(world.bodies()[1].asleep);
  CHECK(world.stateOf(1).velocity.norm() == 0);
  CHECK(world.stateOf(1).angularVelocity.norm() == 0);
  CHECK(deepest <= scene.collisionTolerance);
  CHECK_FALSE(tossedSleptInAir);
}

TEST_CASE("world: a collision between free bodies conserves linear and angular momentum and makes no energy") {
  for (Ordering ordering : {Ordering::Timewarp, Ordering::ToiHeap}) {
    const Scene scene = parseScene(R"({ "duration": 1, "gravity": [0, 0, 0], "scalar": "double", )" +
                                   orderingKey(ordering) + R"(
        "bodies": [ { "name": "a", "shape": {"box": [0.2, 0.1, 0.15]}, "position": [-1, 0.05, 0], "velocity": [2, 0, 0],
                      "angular_velocity": [0, 0.5, 1] },
                    { "name": "b", "shape": {"polytope": [[0,0,0],[0.3,0,0],[0,0.4,0],[0,0,0.3],[0.3,0.3,0.3]]},
                      "position": [0.5, -0.1, -0.1], "velocity": [-1, 0, 0], "density": 700 } ] })");
    World world(scene, checked());
    auto momenta = [&]() {
      Eigen::Vector3d P = Eigen::Vector3d::Zero(), L = Eigen::Vector3d::Zero();
      double E = 0;
      for (int b = 0; b < 2; ++b) {
        const BodyState s = world.stateOf(b);
        const RigidBody& body = world.bodies()[b].rigid;
        P += body.linearMomentum(s);
        L += body.angularMomentum(s);  // about the world origin, orbital part included
        E += body.kineticEnergy(s);
      }
      return std::make_tuple(P, L, E);
    };
    const auto [P0, L0, E0] = momenta();
    const Run run = runAll(world);
    const auto [P1, L1, E1] = momenta();
    INFO(orderingName(ordering));
    CHECK(run.collisions >= 1);
    CHECK((P1 - P0).norm() < 1e-9 * P0.norm() + 1e-9);
    CHECK((L1 - L0).norm() < 1e-7 * (L0.norm() + 1));
    CHECK(E1 <= E0 * (1 + 1e-9));
    CHECK(E1 < E0);  // e = 0.7: the collision lost energy
  }
}

TEST_CASE("world: kinetic energy never rises in collisions (zero gravity, a crowd of bodies)") {
  std::string bodies;
  for (int k = 0; k < 12; ++k) {
    const double x = (k % 4) * 0.6 - 0.9, y = (k / 4) * 0.6 - 0.6;
    const char* shape = k % 3 == 0 ? R"({"sphere": 0.15})" : (k % 3 == 1 ? R"({"box": [0.12, 0.1, 0.14]})" : R"({"capsule": [0.08, 0.1]})");
    bodies += std::string(k ? "," : "") + R"({ "name": "b)" + std::to_string(k) + R"(", "shape": )" + shape +
              R"(, "position": [)" + std::to_string(x) + "," + std::to_string(y) + R"(, 0], "velocity": [)" +
              std::to_string(std::sin(k * 1.3)) + "," + std::to_string(std::cos(k * 2.1)) + R"(, 0.3],
              "angular_velocity": [)" + std::to_string(std::cos(k)) + R"(, 1, 0] })";
  }
  const Scene scene = parseScene(R"({ "duration": 1.5, "gravity": [0, 0, 0], "bodies": [)" + bodies +
                                 R"(, { "name": "wall", "shape": {"box": [2, 2, 0.1]}, "position": [0, 0, 0.6], "static": true } ] })");
  World world(scene, checked());
  auto energy = [&]() {
    double E = 0;
    for (std::size_t b = 0; b < world.bodies().size(); ++b) E += world.bodies()[b].rigid.kineticEnergy(world.stateOf(int(b)));
    return E;
  };
  double before = energy();
  long collisions = 0;
  while (!world.done()) {
    collisions += world.step().counters.collisions;
    const double now = energy();
    CHECK(now <= before * (1 + 1e-9) + 1e-12);
    before = now;
  }
  CHECK(collisions > 3);
}

TEST_CASE("world: a stack of blocks in free fall reports no collision (the paper's sweeping false alarm)") {
  const Scene scene = parseScene(R"({ "duration": 1, "bodies": [
      { "name": "a", "shape": {"box": [0.2, 0.2, 0.1]}, "position": [0, 0, 0] },
      { "name": "b", "shape": {"box": [0.2, 0.2, 0.1]}, "position": [0, 0, 0.201] },
      { "name": "c", "shape": {"box": [0.2, 0.2, 0.1]}, "position": [0, 0, 0.402] } ] })");
  World world(scene, checked());
  const Run run = runAll(world);
  CHECK(run.checks > 0);  // the broad phase hands the pairs to the solver every frame...
  CHECK(run.collisions == 0);  // ... which proves them apart over each whole frame
  CHECK(run.tunnelled == 0);
}

TEST_CASE("world: Newton's cradle passes the momentum down the row, in order") {
  std::string bodies;
  for (int k = 0; k < 5; ++k)
    bodies += std::string(k ? "," : "") + R"({ "name": "ball)" + std::to_string(k) + R"(", "shape": {"sphere": 0.1},
        "position": [)" + std::to_string(k == 0 ? -0.5 : 0.201 * k) + R"(, 0, 0], "velocity": [)" + (k == 0 ? "1" : "0") + R"(, 0, 0] })";
  for (Ordering ordering : {Ordering::Timewarp, Ordering::ToiHeap}) {
    const Scene scene = parseScene(R"({ "duration": 1.5, "gravity": [0, 0, 0], "restitution": 1, "friction": 0, )" +
                                   orderingKey(ordering) + R"( "bodies": [)" + bodies + "] }");
    World world(scene, checked());
    runAll(world);
    INFO(orderingName(ordering));
    const auto& log = world.collisionLog();
    REQUIRE(log.size() >= 4);
    for (int k = 0; k < 4; ++k) {
      CHECK(log[k].i == k);
      CHECK(log[k].j == k + 1);
      if (k) CHECK(log[k].time >= log[k - 1].time);
    }
    CHECK(world.stateOf(4).velocity.x() == Approx(1.0).epsilon(0.01));
    for (int k = 0; k < 4; ++k) CHECK(std::abs(world.stateOf(k).velocity.x()) < 0.02);
  }
}

TEST_CASE("world: a blow passes through a row of touching balls at one instant, in one event") {
  // The balls 1..4 touch (0.05 mm apart, within the tolerance of 0.345 mm); ball 0 strikes
  // the row. The impulses pass the blow down the row at the instant of the strike (the
  // instant pass of gjkx::resolve, response.hpp): one event, one roll back, four collisions at the
  // same time, and ball 4 leaves with ball 0's velocity.
  std::string bodies;
  for (int k = 0; k < 5; ++k)
    bodies += std::string(k ? "," : "") + R"({ "name": "ball)" + std::to_string(k) + R"(", "shape": {"sphere": 0.1},
        "position": [)" + std::to_string(k == 0 ? -0.3 : 0.20005 * k) + R"(, 0, 0], "velocity": [)" + (k == 0 ? "1" : "0") + R"(, 0, 0] })";
  const Scene scene = parseScene(R"({ "duration": 0.5, "gravity": [0, 0, 0], "restitution": 1, "friction": 0,
      "scalar": "double", "bodies": [)" + bodies + "] }");
  World world(scene, checked());
  const Run run = runAll(world);
  const auto& log = world.collisionLog();
  REQUIRE(log.size() == 4);
  for (int k = 0; k < 4; ++k) {
    CHECK(log[k].i == k);
    CHECK(log[k].j == k + 1);
    CHECK(log[k].time == log[0].time);
  }
  CHECK(run.rollbacks == 1);
  CHECK(world.stateOf(4).velocity.x() == Approx(1.0).epsilon(1e-6));
  for (int k = 0; k < 4; ++k) CHECK(std::abs(world.stateOf(k).velocity.x()) < 1e-6);
}

TEST_CASE("world: a row 1.8 tolerances apart passes a blow at one instant under the hybrid, ball by ball under microcollisions") {
  // The balls 1..4 lie 1.8 tolerances apart: beyond the tolerance (and the accepted band of
  // the time-of-impact queries, 1.5), within the hybrid's contact band (2 tolerances),
  // where its solver holds them as contacts. Under the hybrid
  // the instant pass reaches every contact the solver holds (contact.hpp, contactAt), so
  // ball 0's blow runs down the row at the instant it strikes; under microcollisions the
  // balls are not in contact, and each strikes the next after closing the gap.
  const double tol = 3.4526698e-4;  // the scene's default collision tolerance
  std::string bodies;
  for (int k = 0; k < 5; ++k) {
    char at[64];
    std::snprintf(at, sizeof at, "%.12g", k == 0 ? -0.3 : (0.2 + 1.8 * tol) * k);
    bodies += std::string(k ? "," : "") + R"({ "name": "ball)" + std::to_string(k) + R"(", "shape": {"sphere": 0.1},
        "position": [)" + at + R"(, 0, 0], "velocity": [)" + (k == 0 ? "1" : "0") + R"(, 0, 0] })";
  }
  for (const char* model : {"hybrid", "microcollisions"}) {
    const Scene scene = parseScene(R"({ "duration": 0.5, "gravity": [0, 0, 0], "restitution": 1, "friction": 0,
        "scalar": "double", "contact": ")" + std::string(model) + R"(", "bodies": [)" + bodies + "] }");
    World world(scene, checked());
    const Run run = runAll(world);
    INFO(model);
    const auto& log = world.collisionLog();
    REQUIRE(log.size() >= 4);
    for (int k = 0; k < 4; ++k) {
      CHECK(log[k].i == k);
      CHECK(log[k].j == k + 1);
      // 0.8 tolerances to close at 1 m/s: each next ball is struck 0.28 ms later under microcollisions.
      if (k && std::string(model) == "hybrid") CHECK(log[k].time == log[0].time);
      if (k && std::string(model) == "microcollisions") CHECK(log[k].time - log[k - 1].time > 0.5 * tol);
    }
    CHECK(run.tunnelled == 0);
    CHECK(world.stateOf(4).velocity.x() == Approx(1.0).epsilon(0.01));
    for (int k = 0; k < 4; ++k) CHECK(std::abs(world.stateOf(k).velocity.x()) < 0.02);
  }
}

TEST_CASE("world: a thin plate thrown at a thin wall does not tunnel, fixed steps do, and the check sees it") {
  auto scene = [](const std::string& ordering) {
    return parseScene(R"({ "duration": 0.25, "gravity": [0, 0, 0], "ordering": ")" + ordering + R"(", "fixed_substeps": 1,
        "bodies": [ { "name": "wall", "shape": {"box": [0.005, 1, 1]}, "position": [0, 0, 0], "static": true },
                    { "name": "plate", "shape": {"box": [0.005, 0.3, 0.3]}, "position": [-0.5, 0, 0], "velocity": [48, 0, 0] } ] })");
  };
  // 48 m/s at 24 frames per second: 2 m per frame, the wall is 1 cm thick.
  for (const char* ordering : {"timewarp", "toi_heap"}) {
    World world(scene(ordering), checked());
    const Run run = runAll(world);
    INFO(ordering);
    CHECK(run.collisions >= 1);
    CHECK(run.tunnelled == 0);
    CHECK(world.positionOf(1).x() < 0);  // still on its side of the wall
    CHECK(run.maxPenetration < 1e-3);
  }
  World discrete(scene("fixed_step"), checked());
  const Run run = runAll(discrete);
  CHECK(run.collisions == 0);
  CHECK(discrete.positionOf(1).x() > 0);  // through the wall
  CHECK(run.tunnelled == 1);              // and the independent check says so
}

TEST_CASE("world: a box pivoting on one edge off the floor brings its other edge down, and it is seen in time") {
  // A cube (half side a) tilted by 1 degree about x rests on its lower bottom edge A, half a
  // tolerance above the floor. It turns at 16 rad/s about A, so that its other bottom edge B,
  // 2 a sin(1 deg) = 3.5 mm up, comes down at 3.2 m/s, and A leaves at 0.1 m/s. The pair
  // starts within the tolerance and leaving at its closest points: the narrow phase looks
  // again after tol / 0.1 m/s = 3.5 ms, by which time B has gone 7 mm into the floor, unless
  // the time it skips is checked (narrow_phase.cpp). B lands at about 1.2 ms.
  const double a = 0.1, tol = 0.000345267, tilt = M_PI / 180;
  const Eigen::Matrix3d R = Eigen::AngleAxisd(tilt, Eigen::Vector3d::UnitX()).toRotationMatrix();
  const Eigen::Vector3d edgeA(0, -a, -a);
  const Eigen::Vector3d centre(0, 0, 0.5 * tol - (R * edgeA).z());  // A half a tolerance above z = 0
  const Eigen::Vector3d w(-16, 0, 0);                          // B goes down, A stays (about A)
  const Eigen::Vector3d v = w.cross(-R * edgeA) + Eigen::Vector3d(0, 0, 0.1);  // A leaves at 0.1 m/s
  const Eigen::Quaterniond q(R);
  const auto vec = [](const Eigen::Vector3d& x) {
    char text[128];
    std::snprintf(text, sizeof text, "[%.17g, %.17g, %.17g]", x.x(), x.y(), x.z());
    return std::string(text);
  };
  char orientation[128];
  std::snprintf(orientation, sizeof orientation, "[%.17g, %.17g, %.17g, %.17g]", q.w(), q.x(), q.y(), q.z());
  const std::string position = vec(centre);
  for (const char* contact : {"microcollisions", "hybrid"}) {
    const Scene scene = parseScene(R"({ "duration": 0.0833333333, "collision_tolerance": )" + std::to_string(tol) +
                                   R"(, "restitution": 0.5, "contact": ")" + contact + R"(",
        "bodies": [ { "name": "floor", "shape": {"box": [2, 2, 0.1]}, "position": [0, 0, -0.1], "static": true },
                    { "name": "cube", "shape": {"box": [0.1, 0.1, 0.1]}, "position": )" + position +
                                   R"(, "orientation": )" + orientation + R"(, "velocity": )" + vec(v) +
                                   R"(, "angular_velocity": )" + vec(w) + R"( } ] })");
    World world(scene, checked());
    const Run run = runAll(world);
    INFO(contact);
    REQUIRE(!world.collisionLog().empty());
    CHECK(world.collisionLog().front().time < 2e-3);     // B's landing, not 3.5 ms late
    CHECK(world.collisionLog().front().approachSpeed > 1);  // at B's speed, not A's
    CHECK(run.maxPenetration <= tol);
    CHECK(run.tunnelled == 0);
  }
}

TEST_CASE("world: two thin plates falling through each other: the check sees it, though gravity cancels between them") {
  // Both fall under gravity, so their relative velocity is constant (the check's Lipschitz
  // bound uses it): 48 m/s, 2 m a frame, each plate 1 cm thick.
  auto scene = [](const std::string& ordering) {
    return parseScene(R"({ "duration": 0.25, "gravity": [0, 0, -9.81], "ordering": ")" + ordering + R"(", "fixed_substeps": 1,
        "bodies": [ { "name": "left", "shape": {"box": [0.005, 0.3, 0.3]}, "position": [-0.5, 0, 0], "velocity": [24, 0, 0] },
                    { "name": "right", "shape": {"box": [0.005, 0.3, 0.3]}, "position": [0.5, 0, 0], "velocity": [-24, 0, 0] } ] })");
  };
  World discrete(scene("fixed_step"), checked());
  const Run passed = runAll(discrete);
  CHECK(passed.collisions == 0);
  CHECK(discrete.positionOf(0).x() > discrete.positionOf(1).x());  // through each other
  CHECK(passed.tunnelled == 1);                                    // and the independent check says so
  World world(scene("timewarp"), checked());
  const Run run = runAll(world);
  CHECK(run.collisions >= 1);
  CHECK(run.tunnelled == 0);
  CHECK(world.positionOf(0).x() < world.positionOf(1).x());
}

TEST_CASE("world: Timewarp, the time-of-impact heap and small fixed steps agree where all three are valid") {
  auto run = [](const char* ordering) {
    const Scene scene = parseScene(R"({ "duration": 1, "gravity": [0, 0, 0], "scalar": "double", "friction": 0.2,
        "ordering": ")" + std::string(ordering) + R"(", "fixed_substeps": 200,
        "bodies": [ { "name": "a", "shape": {"sphere": 0.2}, "position": [-1, 0.05, 0], "velocity": [3, 0, 0] },
                    { "name": "b", "shape": {"sphere": 0.25}, "position": [1, -0.05, 0], "velocity": [-2, 0.2, 0] },
                    { "name": "c", "shape": {"sphere": 0.2}, "position": [0, 1.5, 0], "velocity": [0, -1, 0] } ] })");
    World world(scene, checked());
    runAll(world);
    std::vector<Eigen::Vector3d> v;
    for (int b = 0; b < 3; ++b) v.push_back(world.stateOf(b).velocity);
    return v;
  };
  const auto timewarp = run("timewarp"), heap = run("toi_heap"), fixed = run("fixed_step");
  for (int b = 0; b < 3; ++b) {
    INFO("body " << b);
    CHECK((timewarp[b] - heap[b]).norm() < 1e-6);
    CHECK((timewarp[b] - fixed[b]).norm() < 0.05 * (timewarp[b].norm() + 0.1));
  }
  CHECK((timewarp[0] - Eigen::Vector3d(3, 0, 0)).norm() > 0.5);  // they did collide
}

TEST_CASE("world: every run gives the same result") {
  const Scene scene = parseScene(R"({ "duration": 0.5, "bodies": [
      { "name": "floor", "shape": {"box": [2, 2, 0.5]}, "position": [0, 0, -0.5], "static": true },
      { "name": "a", "shape": {"box": [0.1, 0.2, 0.1]}, "position": [0, 0, 0.5], "angular_velocity": [1, 2, 0.5] },
      { "name": "b", "shape": {"capsule": [0.05, 0.2]}, "position": [0.05, 0.1, 0.9], "angular_velocity": [0, 3, 0] } ] })");
  World first(scene), second(scene);
  runAll(first);
  runAll(second);
  for (int b = 1; b < 3; ++b) {
    CHECK(first.stateOf(b).worldFromBody.translation == second.stateOf(b).worldFromBody.translation);
    CHECK(first.stateOf(b).velocity == second.stateOf(b).velocity);
  }
}

TEST_CASE("world: a fast spinner is flown in intervals of an eighth of a turn, one too fast for 4096 of them is refused") {
  // A box spinning about its shortest principal axis (z) keeps turning at the same rate:
  // after 0.5 s at 80 rad/s (3.3 rad a frame, more than a free-flight path holds) it has
  // turned 40 rad about z. A frame is run again in more intervals when a body spins too
  // fast for them, up to 4096 (an eighth of a turn each: 77,000 rad/s at 24 frames a second); at
  // 200,000 rad/s even those hold too little, and the world says so.
  const Scene scene = parseScene(R"({ "duration": 0.5, "gravity": [0, 0, 0], "bodies": [
      { "name": "spinner", "shape": {"box": [0.3, 0.2, 0.1]}, "position": [0, 0, 0], "angular_velocity": [0, 0, 80] } ] })");
  World world(scene, checked());
  while (!world.done()) world.step();
  const BodyState s = world.stateOf(0);
  const Eigen::Matrix3d expected = Eigen::AngleAxisd(40.0, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  CHECK((s.worldFromBody.rotation - expected).norm() < 1e-6);
  CHECK(s.angularVelocity.z() == Approx(80.0));

  const Scene tooFast = parseScene(R"({ "duration": 0.5, "bodies": [
      { "name": "spinner", "shape": {"box": [0.3, 0.2, 0.1]}, "position": [0, 0, 0], "angular_velocity": [0, 200000, 0] } ] })");
  World refused(tooFast);
  try {
    refused.step();
    FAIL("no error");
  } catch (const std::runtime_error& e) {
    const std::string message = e.what();
    CHECK(message.find("spinner") != std::string::npos);
    CHECK(message.find("frame_rate") != std::string::npos);
  }
}

TEST_CASE("world: under microcollisions a body spinning past spinIntervals eighths of a turn a frame flies in steps of its own") {
  // Under Timewarp with microcollisions a frame is cut into intervals of an eighth of a turn of
  // its fastest body among those spinning at most StepTuning::spinIntervals eighths of a turn a
  // frame (8: one turn a frame, 150.8 rad/s at 24 frames a second); a body spinning faster
  // flies an eighth of a turn at a time, each step's end an event of its own (FrameCounters::stepEnds). Boxes
  // spinning about their shortest principal axis (z) keep turning at the same rate.
  const auto run = [](const std::string& bodies) {
    const Scene scene = parseScene(R"({ "duration": 0.25, "gravity": [0, 0, 0], "contact": "microcollisions", "bodies": [)" +
                                   bodies + "] }");
    World world(scene, checked());
    FrameCounters sum;
    while (!world.done()) sum += world.step().counters;
    return std::make_pair(sum, world.stateOf(0));
  };
  const std::string fast = R"({ "name": "fast", "shape": {"box": [0.3, 0.2, 0.1]}, "position": [0, 0, 0], "angular_velocity": [0, 0, 1000] })";
  const std::string slow = R"({ "name": "slow", "shape": {"box": [0.3, 0.2, 0.1]}, "position": [5, 0, 0], "angular_velocity": [0, 0, 100] })";
  const StepTuning tuning;
  REQUIRE(1000 > tuning.spinIntervals * eighthTurn * 24);
  REQUIRE(100 < tuning.spinIntervals * eighthTurn * 24);
  // 1000 rad/s alone: the frames are not cut (6 frames, one interval each); its own steps
  // are an eighth of a turn each, 0.25 s * 1000 rad/s / eighthTurn of them.
  const auto [alone, spun] = run(fast);
  CHECK(alone.intervals == 6);
  CHECK(alone.spinRestarts == 0);
  CHECK(alone.stepEnds >= long(std::floor(250 / eighthTurn)) - 6);
  const Eigen::Matrix3d turned = Eigen::AngleAxisd(250.0, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  CHECK((spun.worldFromBody.rotation - turned).norm() < 1e-6);
  CHECK(spun.angularVelocity.z() == Approx(1000.0));
  // 100 rad/s cuts every frame into ceil(100 / 24 / eighthTurn) = 6 intervals, and the fast
  // box still flies its own steps within them.
  const auto [both, spunWith] = run(fast + "," + slow);
  CHECK(both.intervals == 6 * long(std::ceil(100.0 / 24 / eighthTurn)));
  CHECK(both.stepEnds > 0);
  CHECK((spunWith.worldFromBody.rotation - turned).norm() < 1e-6);
  // The slow box alone: its intervals hold it, no step of its own.
  const auto [slowAlone, unused] = run(slow);
  (void)unused;
  CHECK(slowAlone.intervals == both.intervals);
  CHECK(slowAlone.stepEnds == 0);
}

TEST_CASE("world: a ball thrown at 10^6 m/s 2 mm over a box passes clean, neither struck nor reported tunnelling") {
  // The solver's time tolerance is the time the pair needs to close half a tolerance: at
  // the solver's default (sqrt(eps) of the frame) the ball moved 14 m in float, and a hit
  // was reported 2 mm above the box; the check's bisection stopped at a millionth of the
  // frame (4 cm of travel) and reported the clean pass as tunnelling. A ball 2 mm lower
  // strikes the box.
  for (const char* scalar : {"float", "double"}) {
    for (const double above : {0.002, -0.002}) {
      INFO(scalar << ", " << above << " m above the box");
      const Scene scene = parseScene(std::string(R"({ "duration": 0.0833, "scalar": ")") + scalar + R"(",
          "bodies": [ { "name": "floor", "shape": {"box": [5, 5, 0.5]}, "position": [0, 0, -0.5], "static": true },
                      { "name": "box", "shape": {"box": [0.5, 0.5, 0.5]}, "position": [0, 0, 0.5] },
                      { "name": "ball", "shape": {"sphere": 0.3}, "position": [-2, 0, )" +
                                     std::to_string(1.3 + above) + R"(], "velocity": [)" +
                                     (above > 0 ? "1e6" : "1e3") + R"(, 0, 0] } ] })");
      World world(scene, checked());
      const Run run = runAll(world);
      bool struck = false;
      for (const CollisionRecord& c : world.collisionLog()) struck = struck || (c.i == 1 && c.j == 2);
      CHECK(run.tunnelled == 0);
      CHECK(struck == (above < 0));
      if (above > 0) CHECK(world.stateOf(1).velocity.norm() < 1e-3);  // the box rests as it was
    }
  }
}

TEST_CASE("world: a step's tunables are checked by name before the bodies are built") {
  const Scene scene = parseScene(R"({ "duration": 0.1,
      "bodies": [ { "name": "ball", "shape": {"sphere": 0.1}, "position": [0, 0, 1] } ] })");
  WorldSettings settings;
  settings.tuning.caughtAfter = 0;
  CHECK_THROWS_WITH(World(scene, settings), Catch::Contains("settings.tuning.caughtAfter"));
  settings = {};
  settings.tuning.acceptedBand = 0.5;
  CHECK_THROWS_WITH(World(scene, settings), Catch::Contains("settings.tuning.acceptedBand"));
  settings = {};
  settings.tuning.reliableNormal = std::nan("");
  CHECK_THROWS_WITH(World(scene, settings), Catch::Contains("settings.tuning.reliableNormal"));
  settings = {};
  settings.tuning.maxSpinIntervals = 8;  // fewer than maxIntervals
  CHECK_THROWS_WITH(World(scene, settings), Catch::Contains("settings.tuning.maxSpinIntervals"));
  settings = {};
  settings.tuning.struckStep = 0;  // a step of no length would never end
  CHECK_THROWS_WITH(World(scene, settings), Catch::Contains("settings.tuning.struckStep"));
  settings = {};
  settings.tuning.spinIntervals = 0;  // no body could cut a frame
  CHECK_THROWS_WITH(World(scene, settings), Catch::Contains("settings.tuning.spinIntervals"));
}

TEST_CASE("world: every constant of a step can be set by its name, each name its own field") {
  // setTuning's table is written by hand beside the struct: each name must reach a field
  // of its own (two names on one field, or a name on none, fail here), and every name the
  // validation reports must be settable.
  const std::vector<std::string> names = tuningNames();
  REQUIRE(names.size() >= 30);
  const auto bytes = [](const StepTuning& t) {
    return std::string(reinterpret_cast<const char*>(&t), sizeof t);
  };
  std::vector<std::size_t> changed;  // per name, the first byte it changed
  for (const std::string& name : names) {
    StepTuning t;
    const std::string before = bytes(t);
    setTuning(t, name, "7");  // 7 is no field's default
    const std::string after = bytes(t);
    std::size_t at = 0;
    while (at < before.size() && before[at] == after[at]) ++at;
    INFO(name);
    REQUIRE(at < before.size());
    CHECK(std::find(changed.begin(), changed.end(), at) == changed.end());
    changed.push_back(at);
  }
  StepTuning t;
  setTuning(t, "contactSettled", "0.25");
  CHECK(t.contactSettled == 0.25);
  setTuning(t, "contactIterations", "64");
  CHECK(t.contactIterations == 64);
  setTuning(t, "eventCap", "12345678901");
  CHECK(t.eventCap == 12345678901L);
  CHECK_THROWS_WITH(setTuning(t, "noSuch", "1"), Catch::Contains("tuning.noSuch: no such setting (known: patchDepth"));
  CHECK_THROWS_WITH(setTuning(t, "contactSettled", "0.2x"), Catch::Contains("tuning.contactSettled: must be a finite number"));
  CHECK_THROWS_WITH(setTuning(t, "contactSettled", "inf"), Catch::Contains("tuning.contactSettled"));
  CHECK_THROWS_WITH(setTuning(t, "contactIterations", "3.5"), Catch::Contains("tuning.contactIterations: must be a whole number"));
  CHECK_THROWS_WITH(setTuning(t, "contactIterations", "99999999999"), Catch::Contains("tuning.contactIterations"));
  CHECK_THROWS_WITH(setTuning(t, "contactIterations", ""), Catch::Contains("tuning.contactIterations"));
  // In range is the world's to check, by the same name.
  WorldSettings settings;
  setTuning(settings.tuning, "struckStep", "2");
  const Scene scene = parseScene(R"({ "duration": 0.1,
      "bodies": [ { "name": "ball", "shape": {"sphere": 0.1}, "position": [0, 0, 1] } ] })");
  CHECK_THROWS_WITH(World(scene, settings), Catch::Contains("settings.tuning.struckStep"));
}

TEST_CASE("world: a frame past the event cap ends with its status, counted, not with an exception") {
  // Twenty balls dropped on a floor with a cap of one event per interval: every frame with
  // collisions reaches it, reports FrameStatus::EventCap and counts it, and the run goes on.
  std::string bodies = R"({ "name": "floor", "shape": {"box": [5, 5, 0.5]}, "position": [0, 0, -0.5], "static": true })";
  for (int k = 0; k < 20; ++k)
    bodies += R"(, { "name": "ball)" + std::to_string(k) + R"(", "shape": {"sphere": 0.1}, "position": [)" +
              std::to_string(0.3 * (k % 5)) + ", " + std::to_string(0.3 * (k / 5)) + R"(, 0.2] })";
  const Scene scene = parseScene(R"({ "duration": 0.5, "scalar": "double", "bodies": [ )" + bodies + " ] }");
  WorldSettings settings;
  settings.tuning.eventCap = 1;
  settings.tuning.eventCapPerBody = 0;
  settings.checks = false;
  World world(scene, settings);
  long capped = 0, frames = 0;
  while (!world.done()) {
    const FrameReport r = world.step();
    ++frames;
    CHECK((r.status == FrameStatus::EventCap) == (r.counters.eventCaps > 0));
    capped += r.counters.eventCaps;
  }
  CHECK(frames == world.frameCount());
  CHECK(capped > 0);
}

TEST_CASE("world: fixed steps hold a box dropped on the floor, and the dominoes stay out of it") {
  // A discrete engine's projection (fixed_step.hpp): without it the box sank a little at
  // every step that found it late and nothing lifted it back; the dominoes under fixed
  // steps ended 0.55 m deep in the floor. What a frame's end shows is what the step's
  // projection left: touching, within the tolerance band.
  for (const char* scalar : {"float", "double"}) {
    INFO(scalar);
    const Scene scene = parseScene(std::string(R"({ "duration": 2, "ordering": "fixed_step", "scalar": ")") + scalar +
                                   R"(", "bodies": [
        { "name": "floor", "shape": {"box": [5, 5, 0.5]}, "position": [0, 0, -0.5], "static": true },
        { "name": "box", "shape": {"box": [0.5, 0.5, 0.5]}, "position": [0, 0, 1.0] } ] })");
    World world(scene, checked());
    const Run run = runAll(world);
    CHECK(run.tunnelled == 0);
    CHECK(run.maxPenetration < 2 * scene.collisionTolerance);
    CHECK(world.positionOf(1).z() == Approx(0.5).margin(2 * scene.collisionTolerance));
  }
  Scene dominoes = loadScene(std::string(GJKX_SCENES) + "/dominoes.json");
  dominoes.run.ordering = Ordering::FixedStep;
  World world(dominoes, checked());
  const Run run = runAll(world);
  // Was 0.55 m. What a step's end shows is at most what one step of a falling domino can
  // sink (1.5 m/s for 1/192 s: 8 mm) before its projection, which the checks see only at a
  // frame's end after it: a few millimetres. (With the impulse at the centre of the floor's
  // face, the patch of an overlap, dominoes spun up and ended 3 cm deep.)
  CHECK(run.maxPenetration < 0.008);
  CHECK(run.tunnelled == 0);
}

TEST_CASE("world: a body's own mass and restitution are the ones its collisions use") {
  // A ball of 2 kg (its density follows from its volume) with restitution 0.9 on a floor
  // of the scene's 0.5: the pair bounces with the larger, 0.9, to 0.81 of its height.
  const Scene scene = parseScene(R"({ "duration": 1.0, "restitution": 0.5, "friction": 0, "scalar": "double",
      "bodies": [ { "name": "floor", "shape": {"box": [2, 2, 0.5]}, "position": [0, 0, -0.5], "static": true },
                  { "name": "ball", "shape": {"sphere": 0.1}, "position": [0, 0, 0.6], "mass": 2, "restitution": 0.9 } ] })");
  World world(scene, checked());
  CHECK(world.bodies()[1].rigid.massProperties().mass == Approx(2.0).epsilon(1e-12));
  double apex = 0, lastVz = 0;
  bool bounced = false;
  while (!world.done()) {
    world.step();
    const BodyState s = world.stateOf(1);
    if (lastVz < 0 && s.velocity.z() > 0) bounced = true;
    if (bounced) apex = std::max(apex, s.worldFromBody.translation.z() - 0.1 + s.velocity.z() * s.velocity.z() / (2 * 9.81));
    lastVz = s.velocity.z();
  }
  REQUIRE(bounced);
  CHECK(apex == Approx(0.5 * 0.81).epsilon(0.03));
}

TEST_CASE("world: a mesh as users have it: scaled, its hull for an open mesh, and an open one to decompose refused at once") {
  const std::string data = std::string(GJKX_SCENES) + "/../../../tests/mesh/data";
  const auto bodyWith = [&](const std::string& shape) {
    Scene scene = parseScene(R"({ "duration": 0.05, "gravity": [0, 0, 0], "bodies": [
        { "name": "part", "shape": )" + shape + R"(, "position": [0, 0, 0] } ] })", "test.json");
    scene.folder = data;
    return scene;
  };
  // Scale: the L prism at half its size has an eighth of its mass.
  const double full = World(bodyWith(R"({"mesh": "l_prism.off"})")).bodies()[0].rigid.massProperties().mass;
  const double half =
      World(bodyWith(R"({"mesh": "l_prism.off", "scale": 0.5})")).bodies()[0].rigid.massProperties().mass;
  CHECK(half == Approx(full / 8).epsilon(1e-9));
  // An open mesh: a unit cube with its top face missing.
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "gjkx-open-mesh";
  std::filesystem::create_directories(dir);
  {
    std::ofstream off(dir / "open_cube.off");
    off << "OFF\n8 10 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 1\n1 0 1\n1 1 1\n0 1 1\n"
        << "3 0 2 1\n3 0 3 2\n3 0 1 5\n3 0 5 4\n3 1 2 6\n3 1 6 5\n3 2 3 7\n3 2 7 6\n3 3 0 4\n3 3 4 7\n";
  }
  Scene open = bodyWith(R"({"mesh": "open_cube.off"})");
  open.folder = dir.string();
  CHECK_THROWS_WITH(World(open), Catch::Contains("test.json") && Catch::Contains("shape.mesh") &&
                                     Catch::Contains("\"collision\": \"hull\""));
  Scene asHull = bodyWith(R"({"mesh": "open_cube.off", "collision": "hull", "scale": [2, 1, 1]})");
  asHull.folder = dir.string();
  const World world(asHull);
  CHECK(world.bodies()[0].pieces.size() == 1);
  CHECK(world.bodies()[0].rigid.massProperties().mass == Approx(1000 * 2.0).epsilon(1e-9));  // the hull: 2 x 1 x 1
  std::filesystem::remove_all(dir);
  // A bad option is named.
  CHECK_THROWS_WITH(parseScene(R"({ "duration": 1, "bodies": [ { "name": "m", "shape": {"mesh": "a.off", "collision": "convex"},
      "position": [0, 0, 0] } ] })"), Catch::Contains("shape.collision"));
  CHECK_THROWS_WITH(parseScene(R"({ "duration": 1, "bodies": [ { "name": "m", "shape": {"mesh": "a.off", "scale": -1},
      "position": [0, 0, 0] } ] })"), Catch::Contains("shape.scale"));
}

TEST_CASE("world: a cylinder dropped on its cap, and one dropped on its side, come to rest on the floor") {
  // Standing, its cap meets the floor with its whole rim; lying, a line of its side does.
  // Either way it must end where the floor holds it: its centre h or r above the floor,
  // upright or lying as it fell, and still.
  const double r = 0.1, h = 0.15;
  for (const bool standing : {true, false}) {
    INFO((standing ? "standing" : "lying"));
    const std::string orientation = standing ? "[1, 0, 0, 0]" : "[0.7071067811865476, 0, 0.7071067811865476, 0]";
    const double rest = standing ? h : r;
    const Scene scene = parseScene(R"({ "duration": 2, "bodies": [
        { "name": "floor", "shape": {"box": [5, 5, 0.5]}, "position": [0, 0, -0.5], "static": true },
        { "name": "cylinder", "shape": {"cylinder": [0.1, 0.15]}, "orientation": )" + orientation +
                                   R"(, "position": [0, 0, )" + std::to_string(rest + 0.05) + R"(] } ] })");
    World world(scene, checked());
    CHECK(world.bodies()[1].rigid.massProperties().mass == Approx(1000 * M_PI * r * r * 2 * h).epsilon(1e-12));
    const Run run = runAll(world);
    CHECK(run.collisions > 0);
    CHECK(run.tunnelled == 0);
    CHECK(run.maxPenetration < 2 * scene.collisionTolerance);
    CHECK(world.positionOf(1).z() == Approx(rest).margin(2 * scene.collisionTolerance));
    const BodyState s = world.stateOf(1);
    const double axisUp = std::abs((s.worldFromBody.rotation * Eigen::Vector3d::UnitZ()).z());
    CHECK(axisUp == Approx(standing ? 1.0 : 0.0).margin(1e-3));
    CHECK(s.velocity.norm() < 1e-2);
  }
}

// Timewarp, step by step: three balls of radius 0.1 and equal mass on the x axis, no
// gravity, restitution 1/2, no friction, one frame [0, 0.5] (frame rate 2). Ball 0 from
// x = -0.5 at +2, ball 1 at rest at 0, ball 2 from 0.65 at -1.5. Times below ignore the
// collision tolerance (each comes about tol / closing speed = 1e-4 s earlier). Equal
// masses, e = 1/2: a collision leaves the pair with its mean velocity -/+ half the closing
// speed over two.
//  1. Every body runs ahead to the frame's end: each one's local time is 0.5. The pair
//     checks queue (0,1) at 0.15 (gap 0.3 closing at 2), (0,2) at 0.2714 (0.95 at 3.5; ball
//     0's path still runs through ball 1) and (1,2) at 0.3 (0.45 at 1.5).
//  2. The global virtual time moves to the earliest event, (0,1) at 0.15: balls 0 and 1 roll
//     back from 0.5 to 0.15 (ball 2 is left alone), leave at 0.5 and 1.5, and fly on to 0.5.
//     Their pairs are checked again from 0.15: (1,2) at 0.225 (ball 2 at 0.425, gap 0.225
//     closing at 3) and (0,2) at 0.3625 (gap 0.425 closing at 2).
//  3. (1,2) at 0.225: balls 1 and 2 roll back to 0.225 and leave at -0.75 and 0.75. The
//     re-check finds (0,1) at 0.285 (ball 0 at -0.1625, ball 1 at 0.1125: gap 0.075 closing
//     at 1.25).
//  4. (0,2) at 0.2714, queued in 1 on paths both collisions replaced: stale, dropped.
//  5. (0,1) at 0.285: balls 0 and 1 roll back to 0.285 and leave at -0.4375 and 0.1875.
//  6. (1,2) at 0.3 (from 1) and (0,2) at 0.3625 (from 2): stale, dropped.
// Three collisions, three rollbacks, six events popped of which three were stale; the
// global virtual time (each processed event's time) never goes back.
TEST_CASE("Timewarp, step by step: three balls, each body's local time, its rollbacks, the stale events") {
  const std::string bodies = R"("bodies": [
        { "name": "ball0", "shape": {"sphere": 0.1}, "position": [-0.5, 0, 0], "velocity": [2, 0, 0] },
        { "name": "ball1", "shape": {"sphere": 0.1}, "position": [0, 0, 0] },
        { "name": "ball2", "shape": {"sphere": 0.1}, "position": [0.65, 0, 0], "velocity": [-1.5, 0, 0] } ] })";
  const std::string settings0 = R"({ "duration": 0.5, "frame_rate": 2, "gravity": [0, 0, 0], "restitution": 0.5,
      "friction": 0, "scalar": "double", )";
  // The paper's model of contact, microcollisions, which runs a frame as one interval (the
  // hybrid cuts frames into shorter intervals: another trace).
  const Scene scene = parseScene(settings0 + R"("contact": "microcollisions", )" + bodies);
  WorldSettings settings;
  settings.trace = true;
  World world(scene, settings);
  const FrameReport report = world.step();
  REQUIRE(world.done());
  std::vector<TraceEvent> events;  // the trace without its pair checks
  for (const TraceEvent& e : world.trace())
    if (e.kind != TraceEvent::Kind::Check) events.push_back(e);
  const double m = 1e-3;  // the tolerance's shift of every time, and more
  using K = TraceEvent::Kind;
  // 1. every body ahead to 0.5
  REQUIRE(events.size() >= 3);
  for (int b = 0; b < 3; ++b) {
    CHECK(events[b].kind == K::Advance);
    CHECK(events[b].body == b);
    CHECK(events[b].from == 0);
    CHECK(events[b].to == 0.5);
  }
  // 2, 3, 5: each collision, then a rollback of each of its bodies to its time and a flight
  // from there to the frame's end.
  struct Expected {
    int i, j;
    double time;
  };
  const Expected collisions[] = {{0, 1, 0.15}, {1, 2, 0.225}, {0, 1, 0.285}};
  std::size_t k = 3;
  double virtualTime = 0;
  for (const Expected& c : collisions) {
    INFO("collision of " << c.i << " and " << c.j << " at " << c.time);
    REQUIRE(k < events.size());
    CHECK(events[k].kind == K::Collision);
    CHECK(events[k].body == c.i);
    CHECK(events[k].other == c.j);
    CHECK(events[k].to == Approx(c.time).margin(m));
    CHECK(events[k].to >= virtualTime);  // the global virtual time never goes back
    virtualTime = events[k].to;
    ++k;
    int rolledBack = 0, flown = 0;
    for (; k < events.size() && events[k].kind != K::Collision; ++k) {
      CHECK((events[k].body == c.i || events[k].body == c.j));  // the third ball is left alone
      if (events[k].kind == K::Rollback) {
        ++rolledBack;
        CHECK(events[k].from == 0.5);  // its local time was the frame's end
        CHECK(events[k].to == virtualTime);
      } else if (events[k].kind == K::Advance) {
        ++flown;
        CHECK(events[k].from == virtualTime);
        CHECK(events[k].to == 0.5);
      }
    }
    CHECK(rolledBack == 2);
    CHECK(flown == 2);
  }
  CHECK(k == events.size());
  CHECK(report.counters.collisions == 3);
  CHECK(report.counters.rollbacks == 3);
  // 4 and 6: six events popped, three of them stale and dropped.
  CHECK(report.counters.events == 6);
  // Each ball's final velocity, as the three collisions above leave it.
  CHECK(world.stateOf(0).velocity.x() == Approx(-0.4375).epsilon(1e-6));
  CHECK(world.stateOf(1).velocity.x() == Approx(0.1875).epsilon(1e-6));
  CHECK(world.stateOf(2).velocity.x() == Approx(0.75).epsilon(1e-6));
}

TEST_CASE("world: a tilted L dropped on the floor strikes with its lower arm, when free fall says") {
  // An L prism (several convex pieces) tilted about x, so that one arm hangs lower. Its pair
  // with the floor has a piece pair per piece; the pair's collision is the earliest one's,
  // whichever is checked first (those after a hit are checked only until it). Tilted one
  // way and the other, each arm is the lower one once.
  const std::string data = std::string(GJKX_SCENES) + "/../../../tests/mesh/data";
  const double g = 9.81, tilt = GENERATE(-0.3, 0.3);
  const double c = std::cos(tilt / 2), s = std::sin(tilt / 2);
  Scene scene = parseScene(R"({ "duration": 0.5, "friction": 0, "bodies": [
      { "name": "floor", "shape": {"box": [3, 3, 0.5]}, "position": [0, 0, -0.5], "static": true },
      { "name": "L", "shape": {"mesh": "l_prism.off"}, "position": [0, -1, 1.2],
        "orientation": [)" + std::to_string(c) + ", " + std::to_string(s) + R"(, 0, 0] } ] })", "test.json");
  scene.folder = data;
  World world(scene);
  const WorldBody& L = world.bodies()[1];
  // Each piece's lowest point at the start (its support along -z).
  std::vector<double> low;
  for (const Shape<double>& piece : L.pieces)
    low.push_back(Placed<Shape<double>>{piece, L.path.start.worldFromBody}.support(Eigen::Vector3d(0, 0, -1)).z());
  const double lowest = *std::min_element(low.begin(), low.end());
  REQUIRE(*std::max_element(low.begin(), low.end()) > lowest + 0.1);  // the tilt makes one arm clearly lower
  while (!world.done() && world.collisionLog().empty()) world.step();
  REQUIRE_FALSE(world.collisionLog().empty());
  const CollisionRecord& first = world.collisionLog().front();
  INFO("tilt " << tilt << ": the struck piece's lowest point " << low[std::size_t(first.pieceJ)] << ", the lowest "
               << lowest);
  CHECK(low[std::size_t(first.pieceJ)] == Approx(lowest).margin(1e-6));
  const double fall = lowest - scene.collisionTolerance;
  // Free fall to within the tolerance band of the floor's top (z = 0).
  CHECK(first.time == Approx(std::sqrt(2 * fall / g)).epsilon(2e-3));
}
