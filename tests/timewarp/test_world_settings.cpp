// The world's inputs, checked where they enter: the impulse integration's tolerances and a
// step's constants are the settings' and are refused by name when out of range, every
// constant can be set by its name (gjkx_simulate --tuning), a frame past the event cap says
// so in its status, and a mesh is taken as users have it (scaled, an open one's hull, an
// open one to decompose refused at once).
#include <gjkx/timewarp/scene.hpp>
#include <gjkx/timewarp/world.hpp>

#include "world_test_support.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

using namespace gjkx;
using namespace gjkx::world_test;

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
