// Nothing passes through anything, however fast or thin: a thin plate thrown at a thin
// wall, two thin plates falling through each other, a box pivoting its far edge down, a
// ball thrown at 10^6 m/s just over a box, a tilted L striking with its lower arm, and
// bodies spinning too fast for one path a frame (flown an eighth of a turn at a time).
#include <gjkx/timewarp/scene.hpp>
#include <gjkx/timewarp/world.hpp>

#include "world_test_support.hpp"

#include <Eigen/Geometry>
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

using namespace gjkx;
using namespace gjkx::world_test;

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
