// gjkx_mujoco_scene as a user runs it (docs/08_torso.md, "The peers side by side"): a box
// dropped onto a floor in MuJoCo comes to rest on it, measured by the same independent
// checks as gjkx_simulate (penetration within a bound, nothing tunnelled), with the CSV
// columns and SUMMARY keys of gjkx_bullet_scene; a bad command line exits 2, a bad scene 1;
// a thin rod spinning in free flight blows up under MuJoCo's default integrator, which the
// runner says naming the body, and keeps its energy under the implicit one.
#include <catch2/catch.hpp>

#include "../run_program.hpp"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace {

test::ProgramResult run(const std::string& arguments) { return test::runProgram(GJKX_MUJOCO_SCENE, arguments); }

using test::readCsv;

// A 0.2 m box (turned 30 degrees about z, so that MuJoCo's body frame is not the world's)
// dropped from 0.5 m above a static floor whose top is at z = 0.
const char* kBoxDrop = R"({ "gravity": [0, 0, -9.81], "frame_rate": 24, "duration": 2.0, "friction": 0.5,
  "bodies": [
    { "name": "floor", "shape": {"box": [2, 2, 0.5]}, "position": [0, 0, -0.5], "static": true },
    { "name": "box", "shape": {"box": [0.1, 0.1, 0.1]}, "position": [0, 0, 0.6],
      "orientation": [0.9659258, 0, 0, 0.2588190] } ] })";

}  // namespace

TEST_CASE("a box dropped in MuJoCo comes to rest on the floor, measured by the simulator's checks", "[peers]") {
  const fs::path out = test::freshFolder("gjkx-mujoco", "box");
  std::ofstream(out / "box.json") << kBoxDrop;
  const test::ProgramResult r = run("\"" + (out / "box.json").string() + "\" --out \"" + out.string() + "\" --quiet");
  INFO(r.output);
  REQUIRE(r.status == 0);
  const auto keys = test::summaryKeys(r.output);
  for (const std::string& key : test::peerSummaryKeys()) REQUIRE(keys.count(key) == 1);
  CHECK(keys.at("frames") == 48);
  CHECK(keys.at("steps") == 48 * 21);  // at most MuJoCo's default 2 ms a step
  CHECK(keys.at("tunnelled") == 0);
  // MuJoCo's contacts are soft: the box sinks into the floor as it lands (3 m/s), then
  // comes back up to rest with a small overlap.
  CHECK(keys.at("max_penetration") >= 0);
  CHECK(keys.at("max_penetration") < 0.05);  // half the box's half size at the landing
  CHECK(keys.at("kinetic_end") < 1e-3 * keys.at("kinetic_max"));

  const auto frames = readCsv(out / "frames.csv");
  REQUIRE(frames.size() == 49);
  CHECK(frames[0] == std::vector<std::string>{"frame", "time", "wall_s", "max_penetration", "kinetic_energy",
                                              "contact_pairs", "tunnelled", "checks_s"});
  CHECK(frames.back()[5] == "1");                   // at rest on the floor: one pair in contact
  CHECK(std::stod(frames.back()[3]) < 0.0005);       // resting within half a millimetre
  const auto bodies = readCsv(out / "bodies.csv");
  REQUIRE(bodies.size() == 1 + 48 * 2);
  CHECK(bodies[0] == std::vector<std::string>{"frame", "time", "name", "x", "y", "z", "qw", "qx", "qy", "qz", "vx",
                                              "vy", "vz", "wx", "wy", "wz", "kinetic_energy"});
  // The last row is the box at the end: on the floor (its centre half its size above the
  // floor's top, within the penetration bound), where it fell, still turned 30 degrees.
  const auto& box = bodies.back();
  REQUIRE(box[2] == "box");
  CHECK(std::abs(std::stod(box[3])) < 1e-3);
  CHECK(std::abs(std::stod(box[4])) < 1e-3);
  CHECK(std::stod(box[5]) == Approx(0.1).margin(0.0005));
  CHECK(std::abs(std::stod(box[6])) == Approx(0.9659258).margin(1e-3));
  for (int v = 10; v <= 15; ++v) CHECK(std::abs(std::stod(box[std::size_t(v)])) < 0.01);
  CHECK(fs::exists(out / "model.xml"));
}

TEST_CASE("gjkx_mujoco_scene refuses a bad command line (2) and a bad scene (1)", "[peers]") {
  const fs::path out = test::freshFolder("gjkx-mujoco", "bad");
  std::ofstream(out / "box.json") << kBoxDrop;
  const std::string box = "\"" + (out / "box.json").string() + "\" --out \"" + out.string() + "\"";
  CHECK(run("").status == 2);                          // no scene
  CHECK(run(box + " --substeps 0").status == 2);       // out of range
  CHECK(run(box + " --duration -1").status == 2);      // not positive
  CHECK(run(box + " --no-such-option").status == 2);   // unknown
  CHECK(run(box + " --integrator rk4").status == 2);   // not one of MuJoCo's two offered
  const test::ProgramResult missing = run("/nonexistent/scene.json");
  CHECK(missing.status == 1);
  CHECK(missing.output.find("/nonexistent/scene.json") != std::string::npos);
  std::ofstream(out / "bad.json") << R"({ "duration": 1, "bodies": [ { "name": "b", "shape": {"sphere": -1}, "position": [0, 0, 0] } ] })";
  const test::ProgramResult bad = run("\"" + (out / "bad.json").string() + "\" --out \"" + out.string() + "\"");
  CHECK(bad.status == 1);
  CHECK(bad.output.find("shape.sphere") != std::string::npos);
}

// A thin rod (10 cm by 8 mm by 4 mm, spinning_rod.json) spinning at 300 rad/s about an axis
// near its long one, for 1 s, with no gravity and nothing to touch: its energy is constant (Euler's equations without
// torque). MuJoCo's default semi-implicit Euler integrates the gyroscopic torque explicitly,
// and the spin grows from step to step until MuJoCo resets the run; its implicit integrator
// takes the gyroscopic terms into the step and does not make energy.
TEST_CASE("a thin rod spinning in MuJoCo: its default integrator blows up and the runner names the body, its implicit one holds", "[peers]") {
  const fs::path out = test::freshFolder("gjkx-mujoco", "spin");
  const std::string rod = "\"" + std::string(GJKX_SPINNING_ROD) + "\" --quiet --out \"";
  const test::ProgramResult euler = run(rod + (out / "euler").string() + "\"");
  INFO(euler.output);
  CHECK(euler.status == 1);
  CHECK(euler.output.find("mjWARN_BADQACC) in body 'rod'") != std::string::npos);
  CHECK(euler.output.find("--integrator implicit") != std::string::npos);

  const test::ProgramResult implicit = run(rod + (out / "implicit").string() + "\" --integrator implicit");
  INFO(implicit.output);
  REQUIRE(implicit.status == 0);
  const auto keys = test::summaryKeys(implicit.output);
  CHECK(keys.at("frames") == 24);
  CHECK(keys.at("kinetic_max") <= keys.at("kinetic_start") * (1 + 1e-9));  // no energy made
  CHECK(keys.at("kinetic_end") > 0);                                       // still spinning
  std::ifstream model(out / "implicit" / "model.xml");
  const std::string xml((std::istreambuf_iterator<char>(model)), std::istreambuf_iterator<char>());
  CHECK(xml.find("integrator=\"implicit\"") != std::string::npos);
}
