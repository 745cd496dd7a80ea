// gjkx_bullet_scene as a user runs it (docs/08_torso.md): chapter 07's ball drop runs in
// Bullet to the end, writes gjkx_simulate's bodies.csv columns, and the ball rebounds
// (its energy falls by the restitution, it neither sinks into the floor nor passes it);
// the tunnelling check fires on a run that does tunnel (a fast small sphere and a thin
// plate, CCD off, one step a frame); a bad command line exits 2, a bad scene 1.
#include <catch2/catch.hpp>

#include "../run_program.hpp"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace {

using Result = test::ProgramResult;

// Runs gjkx_bullet_scene (its path passed in by tests/bullet/CMakeLists.txt) with `arguments`.
Result run(const std::string& arguments) { return test::runProgram(GJKX_BULLET_SCENE, arguments); }

fs::path freshFolder(const std::string& name) { return test::freshFolder("gjkx-bullet", name); }

using test::readCsv;

}  // namespace

TEST_CASE("a ball dropped in Bullet rebounds, measured by the simulator's checks", "[bullet]") {
  const fs::path out = freshFolder("ball");
  const Result r = run("\"" + std::string(GJKX_SCENES) + "/ball_drop.json\" --out \"" + out.string() + "\" --quiet");
  INFO(r.output);
  REQUIRE(r.status == 0);
  const auto keys = test::summaryKeys(r.output);
  for (const std::string& key : test::peerSummaryKeys()) REQUIRE(keys.count(key) == 1);
  CHECK(keys.at("frames") == 48);  // 2 s at 24 frames a second
  CHECK(keys.at("sim_s") == Approx(2.0));
  CHECK(keys.at("steps") == 480);  // at most 1/240 s a step
  CHECK(keys.at("tunnelled") == 0);
  CHECK(keys.at("max_penetration") >= 0);
  CHECK(keys.at("max_penetration") < 0.005);  // 5% of the ball's radius

  const auto frames = readCsv(out / "frames.csv");
  REQUIRE(frames.size() == 49);
  CHECK(frames[0] == std::vector<std::string>{"frame", "time", "wall_s", "max_penetration", "kinetic_energy",
                                              "contact_pairs", "tunnelled", "checks_s"});
  const auto bodies = readCsv(out / "bodies.csv");
  REQUIRE(bodies.size() == 1 + 48 * 2);
  // gjkx_simulate's columns, so the same renderer draws both runs.
  CHECK(bodies[0] == std::vector<std::string>{"frame", "time", "name", "x", "y", "z", "qw", "qx", "qy", "qz", "vx",
                                              "vy", "vz", "wx", "wy", "wz", "kinetic_energy"});

  // The ball (radius 0.1, from 1.1 above a floor at 0, e = 0.7): its energy per unit mass,
  // g z + |v|^2 / 2, measured from where it rests on the floor.
  const double g = 9.81, rest = 0.1, start = g * (1.1 - rest);
  std::vector<double> z, vz, energy;
  for (std::size_t k = 1; k < bodies.size(); ++k) {
    if (bodies[k][2] != "ball") continue;
    const double x = std::stod(bodies[k][5]), vx = std::stod(bodies[k][10]), vy = std::stod(bodies[k][11]),
                 v = std::stod(bodies[k][12]);
    z.push_back(x);
    vz.push_back(v);
    energy.push_back(g * (x - rest) + 0.5 * (vx * vx + vy * vy + v * v));
  }
  REQUIRE(z.size() == 48);
  // It rebounds: falling, then rising.
  std::size_t bounce = 0;
  while (bounce + 1 < vz.size() && !(vz[bounce] < 0 && vz[bounce + 1] > 0)) ++bounce;
  REQUIRE(bounce + 1 < vz.size());
  // The first rebound rises to about e^2 of the drop (0.49): between a quarter and 3/4 of it.
  double peak = 0;
  for (std::size_t k = bounce + 1; k < z.size() && vz[k] > -1e-9; ++k) peak = std::max(peak, z[k] - rest);
  CHECK(peak > 0.25 * (1.1 - rest));
  CHECK(peak < 0.75 * (1.1 - rest));
  // Energy falls and never rises above the start's (1% for Bullet's float steps).
  CHECK(energy.back() < 0.5 * start);
  for (double e : energy) CHECK(e < 1.01 * start);
  // Never below the floor.
  for (double x : z) CHECK(x > rest - 0.005);
}

TEST_CASE("the tunnelling check catches Bullet passing a thin plate without CCD", "[bullet]") {
  // A 1 cm sphere at 60 m/s and a 1 cm plate: 2.5 m a frame in one step, far past the plate.
  const fs::path out = freshFolder("tunnel");
  std::ofstream(out / "shot.json") << R"({ "gravity": [0, 0, 0], "frame_rate": 24, "duration": 0.125,
    "bodies": [
      { "name": "plate", "shape": {"box": [0.5, 0.5, 0.005]}, "position": [0, 0, 0], "static": true },
      { "name": "shot", "shape": {"sphere": 0.01}, "position": [0, 0, 1], "velocity": [0, 0, -60] } ] })";
  const Result r = run("\"" + (out / "shot.json").string() + "\" --out \"" + out.string() + "\" --substeps 1 --no-ccd --quiet");
  INFO(r.output);
  REQUIRE(r.status == 0);
  const auto keys = test::summaryKeys(r.output);
  REQUIRE(keys.count("tunnelled") == 1);
  CHECK(keys.at("tunnelled") == 1);
  // It went through: the shot ends below the plate, never stopped.
  const auto bodies = readCsv(out / "bodies.csv");
  CHECK(std::stod(bodies.back()[5]) < -1.0);
}

TEST_CASE("gjkx_bullet_scene refuses a bad command line (2) and a bad scene (1)", "[bullet]") {
  const std::string ball = "\"" + std::string(GJKX_SCENES) + "/ball_drop.json\"";
  CHECK(run("").status == 2);                                   // no scene
  CHECK(run(ball + " --substeps 0").status == 2);               // out of range
  CHECK(run(ball + " --substeps many").status == 2);            // not a number
  CHECK(run(ball + " --no-such-option").status == 2);           // unknown
  const Result missing = run("/nonexistent/scene.json");
  CHECK(missing.status == 1);
  CHECK(missing.output.find("/nonexistent/scene.json") != std::string::npos);
  const fs::path out = freshFolder("bad");
  std::ofstream(out / "bad.json") << R"({ "duration": 1, "bodies": [ { "name": "b", "shape": {"sphere": -1}, "position": [0, 0, 0] } ] })";
  const Result bad = run("\"" + (out / "bad.json").string() + "\" --out \"" + out.string() + "\"");
  CHECK(bad.status == 1);
  CHECK(bad.output.find("shape.sphere") != std::string::npos);
}
