// The world against physics nobody here wrote: bounces lose e^2 of their height, friction
// stops a sliding box after v^2 / (2 mu g), collisions conserve momentum and never make
// energy, a falling stack has no collisions, Newton's cradle passes the momentum down the
// row in order, and the three orderings agree where all three are valid; and Timewarp
// step by step. (Fast and thin bodies: test_world_fast.cpp; the inputs:
// test_world_settings.cpp.)
#include <gjkx/timewarp/scene.hpp>
#include <gjkx/timewarp/world.hpp>

#include "world_test_support.hpp"

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

using namespace gjkx::world_test;

namespace {

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
