// gjkx_peers_table as a user runs it (docs/08_torso.md, "The peers side by side"): a scene
// whose label holds a space, in a work folder whose path holds one, is run by every
// simulator that was built and written as rows of one table; where MuJoCo fails, a second
// row runs it with its implicit integrator.
#include <catch2/catch.hpp>

#include "../run_program.hpp"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;

TEST_CASE("gjkx_peers_table runs a scene labelled with a space, in a folder with a space", "[peers]") {
  const fs::path dir = test::freshFolder("peers table", "spaces");
  const fs::path table = dir / "table.md";
  // Runs the table on the thin plate with `options`; its exit status must be 0; the table's text.
  const auto tableOf = [&](const std::string& options) {
    const test::ProgramResult r =
        test::runProgram(GJKX_PEERS_TABLE, "'thin plate=" + std::string(GJKX_THIN_PLATE) + "' --work '" +
                                               (dir / "work").string() + "' " + options + "--table '" + table.string() + "'");
    INFO(r.output);
    REQUIRE(r.status == 0);
    return test::readText(table);
  };
  // Ours runs; a row per simulator built, none of them failed for its command line.
  const fs::path framesCsv = dir / "frames.csv";
  const std::string made = tableOf("--frames '" + framesCsv.string() + "' ");
  CHECK(made.find("| thin plate | gjkx (hybrid) | 0.25 s |") != std::string::npos);
  CHECK(made.find("failed") == std::string::npos);
  CHECK(made.find("*earlier*") == std::string::npos);  // every run made by this call
  // Its slowest frame, recomputed from the run's frames.csv: the largest of each frame's own
  // wall time (less its checks) over the simulated time the frame covers.
  {
    std::ifstream in(dir / "work" / "thin plate-gjkx_simulate" / "frames.csv");
    std::string line;
    std::getline(in, line);
    std::vector<std::string> header;
    for (std::istringstream cells(line); std::getline(cells, line, ',');) header.push_back(line);
    const auto column = [&](const std::string& name) {
      return std::size_t(std::find(header.begin(), header.end(), name) - header.begin());
    };
    double largest = 0, start = 0;
    int which = 0, frames = 0;
    while (std::getline(in, line)) {
      std::vector<double> row;
      for (std::istringstream cells(line); std::getline(cells, line, ',');) row.push_back(std::stod(line));
      const double ratio = (row[column("wall_s")] - row[column("checks_s")]) / (row[column("time")] - start);
      start = row[column("time")];
      ++frames;
      if (ratio > largest) {
        largest = ratio;
        which = int(row[column("frame")]);
      }
    }
    REQUIRE(frames == 6);  // 0.25 s at 24 frames a second
    char cell[64];
    std::snprintf(cell, sizeof cell, " | %.3g (frame %d) | ", largest, which);
    INFO(made);
    CHECK(made.find(cell) != std::string::npos);
    CHECK(made.find("| slowest frame over its simulated time | median frame over its simulated time |") != std::string::npos);
    // --frames: every frame of ours in the CSV, its largest ratio the table's.
    std::ifstream csv(framesCsv);
    std::getline(csv, line);
    CHECK(line == "scene,frame,time,frame_over_real_time,simulator");
    int ours = 0;
    double oursLargest = 0;
    while (std::getline(csv, line)) {
      if (line.size() < 14 || line.compare(line.size() - 13, 13, "gjkx (hybrid)") != 0) continue;
      CHECK(line.rfind("thin plate,", 0) == 0);
      ++ours;
      std::vector<std::string> cells;
      for (std::istringstream in(line); std::getline(in, line, ',');) cells.push_back(line);
      oursLargest = std::max(oursLargest, std::stod(cells.at(3)));
    }
    CHECK(ours == 6);
    std::snprintf(cell, sizeof cell, "%.3g", oursLargest);
    char tabled[64];
    std::snprintf(tabled, sizeof tabled, "%.3g", largest);
    CHECK(std::string(cell) == tabled);
  }
  // Again with --reuse: the rows are read from those runs, and the table says so.
  const std::string reused = tableOf("--reuse ");
  CHECK(reused.find("| thin plate | gjkx (hybrid) | 0.25 s |") != std::string::npos);
  CHECK(reused.find("--out '" + (dir / "work").string() + "/thin plate-gjkx_simulate' --quiet` (*earlier*)") !=
        std::string::npos);
  fs::remove_all(dir);
}

#if GJKX_HAVE_MUJOCO_SCENE  // (a build without MuJoCo leaves this test out, as it does test_mujoco_scene)
TEST_CASE("gjkx_peers_table runs MuJoCo again with its implicit integrator where it failed, and only there", "[peers]") {
  const fs::path dir = test::freshFolder("gjkx-peers-table", "fallback");
  // A thin rod spinning in free flight, on which MuJoCo's default integrator blows up
  // (spinning_rod.json, tests/peers/test_mujoco_scene.cpp), and the thin plate, on which it
  // does not; both cut to half a second.
  const fs::path table = dir / "table.md";
  const test::ProgramResult r = test::runProgram(
      GJKX_PEERS_TABLE, "rod=" + std::string(GJKX_SPINNING_ROD) + " plate=" + std::string(GJKX_THIN_PLATE) +
                            " --duration 0.5 --work " + (dir / "work").string() + " --table " + table.string());
  INFO(r.output);
  REQUIRE(r.status == 0);
  const std::string made = test::readText(table);
  INFO(made);
  CHECK(made.find("| rod | MuJoCo | failed (exit status 1: gjkx_mujoco_scene: MuJoCo found its simulation unstable") !=
        std::string::npos);
  CHECK(made.find("| rod | MuJoCo, implicit integrator | 0.5 s |") != std::string::npos);
  CHECK(made.find("--integrator implicit --duration 0.5 --out " + (dir / "work").string() + "/rod-gjkx_mujoco_scene-implicit") !=
        std::string::npos);
  CHECK(made.find("| plate | MuJoCo | 0.25 s |") != std::string::npos);
  CHECK(made.find("| plate | MuJoCo, implicit integrator") == std::string::npos);
  fs::remove_all(dir);
}
#endif
