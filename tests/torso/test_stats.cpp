// `08_torso --stats` (chapter 08, docs/08_torso.md) on a small frames.csv made by hand,
// whose statistics are worked out below: the ratio of execution to simulation time per
// frame (min, median, max, at the peak frame), Brent's mean and worst, the photo-finish
// rate and the totals; and its refusal of a frames.csv that lacks a column.
#include <catch2/catch.hpp>

#include "../run_program.hpp"

#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace {

const char* header =
    "frame,time,wall_s,collision_checks,collisions,microcollisions,rollbacks,brent_iterations,brent_queries,"
    "brent_max,photo_finishes,max_penetration,tunnelled,solver_caps,integration_s,bounds_s,collision_detection_s,"
    "impulses_s,ordering_s,checks_s\n";

// Four frames of 0.25 s. The method's time (integration + bounds + detection + impulses +
// ordering) is 0.25, 0.5, 1.0 and 0.125 s: ratios 1, 2, 4 and 0.5, so min 0.5, median
// (1 + 2) / 2 = 1.5, max 4 at t = 0.75; the most collisions (5) are in frame 2, ratio 2.
// Brent: 6 + 3 + 0 + 3 = 12 iterates over 2 + 1 + 0 + 1 = 4 queries, mean 3, worst 4;
// photo finishes 1 + 0 + 0 + 1 = 2 of 4 queries, 50%. The checks (0.25 s a frame) are in
// wall_s but not in the ratios: 1 s of 2.875 s of wall time, 34.8%.
const char* rows =
    "1,0.25,0.5,10,2,0,1,6,2,4,1,0.001,0,0,0.05,0.05,0.1,0.05,0,0.25\n"
    "2,0.5,0.75,12,5,1,3,3,1,3,0,0.002,0,0,0.1,0.1,0.2,0.1,0,0.25\n"
    "3,0.75,1.25,8,1,0,0,0,0,0,0,0,0,0,0.2,0.2,0.4,0.1,0.1,0.25\n"
    "4,1,0.375,4,0,0,0,3,1,3,1,0,0,0,0.025,0.025,0.05,0.025,0,0.25\n";

fs::path runFolder(const std::string& name, const std::string& csv) {
  const fs::path dir = fs::temp_directory_path() / ("gjkx-torso-stats-" + name + "-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::ofstream(dir / "frames.csv") << csv;
  return dir;
}

struct Result {
  int status = -1;
  std::string output;
};

Result stats(const std::string& arguments, const fs::path& log) {
  const std::string command = std::string("\"") + GJKX_TORSO_CHAPTER + "\" --stats " + arguments + " > \"" +
                              log.string() + "\" 2>&1";
  const int status = std::system(command.c_str());
  Result r;
  r.status = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  std::ifstream in(log);
  std::stringstream s;
  s << in.rdbuf();
  r.output = s.str();
  return r;
}

// The cells of the table row whose first cell is `name` (the runs' columns, then the paper's).
std::vector<std::string> row(const std::string& table, const std::string& name) {
  std::stringstream lines(table);
  for (std::string line; std::getline(lines, line);) {
    if (line.rfind("| " + name + " |", 0) != 0) continue;
    std::vector<std::string> cells;
    std::stringstream parts(line.substr(name.size() + 4));
    for (std::string cell; std::getline(parts, cell, '|');) {
      const auto first = cell.find_first_not_of(' '), last = cell.find_last_not_of(' ');
      if (first != std::string::npos) cells.push_back(cell.substr(first, last - first + 1));
    }
    return cells;
  }
  return {};
}

// The table `08_torso --stats LABEL=RUN` writes for the run folder `run` (a test fails when it fails).
std::string tableOf(const fs::path& run, const std::string& label) {
  const fs::path table = run / "table.md";
  const Result r = stats(label + "=\"" + run.string() + "\" --table \"" + table.string() + "\"", run / "log.txt");
  INFO(r.output);
  REQUIRE(r.status == 0);
  return test::readText(table);
}

// The hand-made frames with `columns` added at the end of the header, and `cells[k]` (each
// starting with a comma) at the end of row k.
std::string withColumns(const std::string& columns, const std::vector<std::string>& cells) {
  std::string csv = std::string(header);
  csv.insert(csv.size() - 1, columns);
  std::stringstream lines(rows);
  std::size_t k = 0;
  for (std::string line; std::getline(lines, line); ++k) csv += line + cells.at(k) + "\n";
  return csv;
}

const std::string kSlowestRow =
    "slowest frame: intervals; body pairs checked at their starts, after collisions, at step ends; impulses (cascaded)";

}  // namespace

TEST_CASE("08_torso --stats works out the paper's statistics from a run's frames.csv", "[torso][stats]") {
  const fs::path run = runFolder("hand", std::string(header) + rows);
  const std::string md = tableOf(run, "hand");
  INFO(md);
  CHECK(md.rfind("| | hand | paper (§6) |", 0) == 0);
  CHECK(row(md, "execution / simulation time: min") == std::vector<std::string>{"0.5", "1.0"});
  CHECK(row(md, "execution / simulation time: median") == std::vector<std::string>{"1.5", "not reported"});
  CHECK(row(md, "execution / simulation time: max (at t)") == std::vector<std::string>{"4 (0.75 s)", "7.9"});
  CHECK(row(md, "execution / simulation time: peak frame (most collisions; at t, collisions)").at(0) ==
        "2 (0.5 s, 5)");
  CHECK(row(md, "independent checks, share of wall time (not in the ratios)").at(0) == "34.8%");
  CHECK(row(md, "time-of-impact queries (of which ran Brent)").at(0) == "34 (4)");
  CHECK(row(md, "Brent iterations per query that ran Brent: mean") == std::vector<std::string>{"3", "2.2"});
  CHECK(row(md, "Brent iterations: worst query") == std::vector<std::string>{"4", "43"});
  CHECK(row(md, "photo-finish rate (of queries that ran Brent)").at(0) == "50.0%");
  CHECK(row(md, "collisions (microcollisions)").at(0) == "8 (1)");
  CHECK(row(md, "rollbacks").at(0) == "4");
  CHECK(row(md, "deepest penetration at a frame's end").at(0) == "0.002 m");
  CHECK(row(md, "pairs tunnelled").at(0) == "0");
  // A frames.csv without the hybrid contact model's columns: its rows say so.
  CHECK(row(md, "contact points solved per frame: mean (most)") == std::vector<std::string>{"not recorded", "future work (§6)"});
  CHECK(row(md, "bodies asleep at the end (most at a frame's end)").at(0) == "not recorded");
  CHECK(row(md, kSlowestRow) == std::vector<std::string>{"not recorded", "not reported"});
  fs::remove_all(run);
}

TEST_CASE("08_torso --stats says where the slowest frame's work went", "[torso][stats]") {
  // The same frames with the anatomy's columns at the end; frame 3 is the slowest (ratio 4):
  // its 4 intervals, 40 pairs checked at their starts, 7 after collisions, 3 at step ends, and
  // its 1 impulse, none cascaded. The other frames' values differ, so a wrong frame shows.
  const fs::path run = runFolder("anatomy", withColumns(",cascade_impulses,step_ends,rechecked_after_collisions,"
                                                       "rechecked_at_step_ends,checked_at_interval_starts,intervals",
                                                       {",1,9,20,9,10,1", ",2,8,30,8,20,2", ",0,2,7,3,40,4",
                                                        ",0,1,1,1,5,1"}));
  const std::string md = tableOf(run, "anatomy");
  INFO(md);
  CHECK(row(md, kSlowestRow) == std::vector<std::string>{"4; 40, 7, 3; 1 (0)", "not reported"});
  fs::remove_all(run);
}

TEST_CASE("08_torso --stats adds the contact solver to the method's time and tabulates the hybrid's columns",
          "[torso][stats]") {
  // The same frames with the hybrid's columns at the end: the contact solver took 0.25 s in
  // frame 1 (its ratio 2 instead of 1: min 0.5, median (2 + 2) / 2 = 2, max 4), 8 + 4 + 0 + 0
  // contact points (mean 3, most 8) in 2 + 1 + 0 + 0 groups (mean 0.75), 6 + 2 sweeps (mean 2),
  // no energy rise, 0, 1, 3 and 2 bodies asleep (2 at the end, 3 at most).
  const fs::path run =
      runFolder("hybrid", withColumns(",contact_points,contact_groups,contact_sweeps,energy_rises,sleeping,contacts_s",
                                      {",8,2,6,0,0,0.25", ",4,1,2,0,1,0", ",0,0,0,0,3,0", ",0,0,0,0,2,0"}));
  const std::string md = tableOf(run, "hybrid");
  INFO(md);
  CHECK(row(md, "execution / simulation time: median").at(0) == "2");
  CHECK(row(md, "contact solver wall time, s (of the method's)").at(0) == "0.25");
  CHECK(row(md, "contact points solved per frame: mean (most)").at(0) == "3 (8)");
  CHECK(row(md, "contact groups solved per frame: mean").at(0) == "0.75");
  CHECK(row(md, "sequential-impulse sweeps per frame: mean").at(0) == "2");
  CHECK(row(md, "contact solves whose kinetic energy rose").at(0) == "0");
  CHECK(row(md, "bodies asleep at the end (most at a frame's end)").at(0) == "2 (3)");
  fs::remove_all(run);
}

TEST_CASE("08_torso --stats names the file and the column a frames.csv lacks", "[torso][stats]") {
  std::string csv = std::string(header) + rows;
  const std::string column = ",brent_queries";
  csv.erase(csv.find(column), column.size());  // the header only: the rows now have a cell too many
  const fs::path run = runFolder("old", csv);
  const Result r = stats("\"" + run.string() + "\"", run / "log.txt");
  INFO(r.output);
  CHECK(r.status == 1);
  CHECK(r.output.find((run / "frames.csv").string()) != std::string::npos);
  CHECK(r.output.find("'brent_queries'") != std::string::npos);
  const Result missing = stats("\"" + (run / "nowhere").string() + "\"", run / "log2.txt");
  CHECK(missing.status == 1);
  CHECK(missing.output.find((run / "nowhere" / "frames.csv").string()) != std::string::npos);
  fs::remove_all(run);
}
