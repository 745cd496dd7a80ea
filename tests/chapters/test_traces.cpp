// The chapters' traces (docs/traces.md): the chapter programs run as a reader runs them,
// with --trace and queries of their own, and the tables they print checked against values
// derived by hand in the comments (and the Fig. 2 run against tests/gjk/test_gjk_figure2_steps.cpp).
#include "../run_program.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

namespace {

using Row = std::vector<std::string>;

/// The rows of the table titled `title` in `output` (the header excluded): the lines after
/// its header up to the blank line, each split where two or more spaces part the columns.
std::vector<Row> table(const std::string& output, const std::string& title) {
  std::istringstream in(output);
  std::vector<Row> rows;
  bool found = false, header = false;
  for (std::string line; std::getline(in, line);) {
    if (!found) {
      found = line == title;
      continue;
    }
    if (!header) {
      header = true;
      continue;
    }
    if (line.empty()) break;
    static const std::regex gap("  +");
    rows.emplace_back(std::sregex_token_iterator(line.begin(), line.end(), gap, -1), std::sregex_token_iterator());
  }
  INFO(output);
  REQUIRE(found);
  return rows;
}

double number(const std::string& cell) { return std::stod(cell); }

/// The numbers of a point cell "(x, y)".
std::pair<double, double> point(const std::string& cell) {
  const std::size_t comma = cell.find(',');
  return {std::stod(cell.substr(1, comma - 1)), std::stod(cell.substr(comma + 1))};
}

test::ProgramResult run(const std::string& program, const std::string& name, const std::string& arguments) {
  const auto folder = test::freshFolder("gjkx-traces", name);
  const auto result = test::runProgram(program, "--out " + folder.string() + " " + arguments);
  INFO(result.output);
  REQUIRE(result.status == 0);
  return result;
}

/// Runs `program` with `arguments` (a bad value) and checks that it is refused with exit
/// status 2 and a message naming `option`.
void checkRefused(const std::string& program, const std::string& arguments, const std::string& option) {
  const auto result =
      test::runProgram(program, "--out " + test::freshFolder("gjkx-traces", "bad").string() + " " + arguments);
  INFO(arguments << "\n" << result.output);
  CHECK(result.status == 2);
  CHECK(result.output.find(option) != std::string::npos);
}

}  // namespace

TEST_CASE("01_support_mapping --trace: each hill climb rises to a vertex no neighbour tops", "[chapters][trace][support_mapping]") {
  // Hill climbing (§2.1) on a convex polytope: from each vertex to its best neighbour while that
  // is strictly higher along s. So on every row s.x is above the row before, the step taken goes
  // to the next row's vertex, that vertex is the best of the neighbours listed, and the last row
  // (S_X(s), the global maximum on a convex polytope) has no neighbour higher.
  const auto result = run(GJKX_CHAPTER_01, "climb", "--vertices 1000 --direction 1,2,-0.5 --trace");
  for (const std::string title : {"support-mapping-hill-climbing: cold start (§2.1, s = 0.4364, 0.8729, -0.2182)",
                                  "support-mapping-hill-climbing: warm start from the last answer"}) {
    INFO(title);
    const auto rows = table(result.output, title);
    REQUIRE(!rows.empty());
    for (std::size_t k = 0; k < rows.size(); ++k) {
      // The neighbours' cell: "n: s.x_n" pairs; the best of them.
      std::istringstream cell(rows[k][3]);
      std::string name;
      double best = -1e300, value = 0;
      bool nextListed = false;
      while (cell >> name >> value) {
        best = std::max(best, value);
        nextListed = nextListed || (k + 1 < rows.size() && name == rows[k + 1][1] + ":");
      }
      if (k + 1 < rows.size()) {
        CHECK(number(rows[k + 1][2]) > number(rows[k][2]));
        CHECK(rows[k][4] == "to " + rows[k + 1][1]);
        CHECK(nextListed);
        CHECK(number(rows[k + 1][2]) == Approx(best).margin(1e-6));  // the best neighbour (ties printed alike)
      } else {
        CHECK(best <= number(rows[k][2]));
        CHECK(rows[k][4] == "stop: no neighbour higher, S_X(s) = vertex " + rows[k][1]);
      }
    }
  }
}

TEST_CASE("02_gjk --trace prints Fig. 2's run step by step", "[chapters][trace][gjk]") {
  // The run of tests/gjk/test_gjk_figure2_steps.cpp: six iterations, from s_0 = (0,-1) with
  // S_P = (0,0), S_Q = (9,9), SD = -9 and MD = 9 sqrt 2, to the closest distance 15/sqrt 17.
  const auto result = run(GJKX_CHAPTER_02, "gjk", "--trace");
  const auto rows = table(result.output, "fig02-gjk-2d: GJK iteration by iteration (§2.2, Fig. 2)");
  REQUIRE(rows.size() == 6);
  CHECK(rows[0][0] == "0");
  CHECK(point(rows[0][1]) == std::pair<double, double>(0, -1));
  CHECK(point(rows[0][2]) == std::pair<double, double>(0, 0));
  CHECK(point(rows[0][3]) == std::pair<double, double>(9, 9));
  CHECK(number(rows[0][4]) == Approx(-9));
  CHECK(number(rows[0][8]) == Approx(9 * std::sqrt(2.0)).margin(1e-6));
  // i = 1: s_1 = (9,9), S_P = (6,6), S_Q = (11,3), SD = sqrt 2, the segment (6,6)-(0,0) of V_P kept.
  CHECK(point(rows[1][2]) == std::pair<double, double>(6, 6));
  CHECK(point(rows[1][3]) == std::pair<double, double>(11, 3));
  CHECK(number(rows[1][4]) == Approx(std::sqrt(2.0)).margin(1e-6));
  CHECK(number(rows[1][8]) == Approx(std::sqrt(32.4)).margin(1e-6));
  CHECK(rows[5][9] == "converged");
  CHECK(number(rows[5][8]) == Approx(15 / std::sqrt(17.0)).margin(1e-6));
}

TEST_CASE("02_gjk --trace on a query of one's own", "[chapters][trace][gjk]") {
  // Two 2 x 2 boxes, Q's centre at (5, 0), s_0 = (1, 0): S_P(s_0) lies on P's right side x = 1
  // and S_Q(-s_0) on Q's left side x = 4, so SD(s_0) = 3, the distance itself: s_1 = z is
  // horizontal and the run converges at distance 3.
  const auto result = run(GJKX_CHAPTER_02, "gjk-query", "--p box:2,2 --q box:2,2 --q-at 5,0 --s0 1,0 --trace");
  const auto rows = table(result.output, "fig02-gjk-2d: GJK iteration by iteration (§2.2, Fig. 2)");
  REQUIRE(rows.size() >= 2);
  CHECK(point(rows[0][2]).first == Approx(1));
  CHECK(point(rows[0][3]).first == Approx(4));
  CHECK(number(rows[0][4]) == Approx(3));
  CHECK(rows.back()[9] == "converged");
  CHECK(number(rows.back()[8]) == Approx(3).margin(1e-6));
  CHECK(result.output.find("result: separated") != std::string::npos);
}

TEST_CASE("02_gjk names a bad option", "[chapters][trace][gjk]") {
  for (const auto& [arguments, option] :
       {std::pair<std::string, std::string>{"--s0 0,0", "--s0"}, {"--p blob:1", "--p"}, {"--q box:1", "--q"},
        {"--q-at 1", "--q-at"}, {"--p polygon:0,0,1,1,2,2", "--p"}})
    checkRefused(GJKX_CHAPTER_02, arguments, option);
}

TEST_CASE("05_brent --trace: Brent's iterates stay in their brackets, and §5 as written takes only Brent's steps",
          "[chapters][trace][brent]") {
  // Q, a 2 x 1.2 box, slides at (-5, 0) from x = 6 without turning: its left side x = 5 - 5t
  // reaches P's corner (2, 0.5) at t = 0.6, and closer than the tolerance 0.05 from
  // t = 0.59. The paper's solver (ToiSettings::paper) reports the hit in [0.59, 0.6], and
  // every iterate is one of Brent's own rules (no probe, no leap).
  const auto result = run(GJKX_CHAPTER_05, "brent",
                          "--solver paper --q-start 6,0,0 --q-velocity -5,0 --q-spin 0 --trace");
  const auto steps = table(result.output, "brent-time-of-impact: Brent's iterates (§5)");
  REQUIRE(!steps.empty());
  for (const Row& step : steps) {
    INFO(step[0] << ": " << step[1] << " " << step[2] << " " << step[3] << " " << step[4]);
    CHECK(number(step[1]) <= number(step[3]));
    CHECK(number(step[3]) <= number(step[2]));
    CHECK((step[4] == "bisection" || step[4] == "secant" || step[4] == "inverse-quadratic" ||
           step[4] == "minimal-step"));
  }
  const std::smatch hit = [&] {
    std::smatch m;
    REQUIRE(std::regex_search(result.output, m, std::regex("brent-time-of-impact: result hit at t = ([0-9.]+)")));
    return m;
  }();
  CHECK(std::stod(hit[1]) >= 0.59 - 1e-9);
  CHECK(std::stod(hit[1]) <= 0.6);
  // The first complete test is on [0, 1] and cannot decide: the box reaches P within it.
  const auto tests = table(result.output, "brent-time-of-impact: complete extrusion tests (§3)");
  REQUIRE(!tests.empty());
  CHECK(tests[0][1] == "[0.000000, 1]");
  // Brent's method alone on x^3 - 2x - 5 ends on its root 2.0945514815423265 (Brent's example).
  const auto root = table(result.output, "brent-root-finder: findRoot(x^3 - 2x - 5, 1, 3, 1e-10), Brent's method alone (§5)");
  REQUIRE(!root.empty());
  CHECK(number(root.back()[1]) == Approx(2.0945514815423265).margin(1e-9));
}

TEST_CASE("05_brent names a bad option", "[chapters][trace][brent]") {
  for (const auto& [arguments, option] : {std::pair<std::string, std::string>{"--q-size 0,1", "--q-size"},
                                          {"--q-start x,1", "--q-start"}, {"--tolerance -1", "--tolerance"}})
    checkRefused(GJKX_CHAPTER_05, arguments, option);
}

TEST_CASE("07_timewarp --trace: the cradle event by event", "[chapters][trace][timewarp]") {
  // The cradle of chapter 07: ball1 (radius 0.1, at x = -0.01) at 1 m/s towards ball2 at 0.22:
  // the gap 0.03 closes at t = 0.03; each further gap of 0.02 closes 0.02 s later as the
  // momentum runs down the row: collisions near 0.03 (frame 1), 0.05 and 0.07 (frame 2) and
  // 0.09 (frame 3), frames of 1/24 s, each found when the balls come within the scene's
  // collision tolerance (0.35 mm: 0.35 ms early at 1 m/s, accumulating down the row). Each is
  // found after both its balls flew to their frame's end T1, sets the GVT to t_c, and rolls
  // back exactly those two balls to t_c, each flying on from there to T1.
  const auto result = run(GJKX_CHAPTER_07, "timewarp", "--trace");
  const auto rows = table(result.output, "fig-timewarp-spacetime: the Timewarp run event by event (Mirtich's Timewarp, §5-§6)");
  const double expected[] = {0.03, 0.05, 0.07, 0.09};
  const int frames[] = {1, 2, 2, 3};
  int collisions = 0, rollbacks = 0;
  for (std::size_t k = 0; k < rows.size(); ++k) {
    const Row& row = rows[k];
    if (row[2] == "rollback") ++rollbacks;
    if (row[2] != "collision") continue;
    REQUIRE(collisions < 4);
    INFO("collision " << collisions + 1);
    const double tc = number(row[6]), T1 = frames[collisions] / 24.0;
    CHECK(row[1] == std::to_string(frames[collisions]));
    CHECK(row[3] == "ball" + std::to_string(collisions + 1));
    CHECK(row[4] == "ball" + std::to_string(collisions + 2));
    CHECK(tc < expected[collisions]);
    CHECK(tc > expected[collisions] - 2e-3);
    CHECK(number(row[7]) == Approx(tc));  // the GVT: the collision taken
    // Then each of its two balls: rolled back from T1 to t_c, and flown on from t_c to T1.
    REQUIRE(k + 4 < rows.size());
    for (std::size_t j : {k + 1, k + 3}) {
      CHECK(rows[j][2] == "rollback");
      CHECK(rows[j][3] == (j == k + 1 ? row[3] : row[4]));
      CHECK(number(rows[j][5]) == Approx(T1).margin(1e-6));
      CHECK(number(rows[j][6]) == Approx(tc));
      CHECK(rows[j + 1][2] == "advance");
      CHECK(rows[j + 1][3] == rows[j][3]);
      CHECK(number(rows[j + 1][5]) == Approx(tc));
      CHECK(number(rows[j + 1][6]) == Approx(T1).margin(1e-6));
    }
    ++collisions;
  }
  CHECK(collisions == 4);
  CHECK(rollbacks == 8);
  // After the last event every ball's local time is the third frame's end, 0.125.
  std::istringstream times(rows.back()[8]);
  int balls = 0;
  for (double t; times >> t; ++balls) CHECK(t == Approx(0.125).margin(1e-6));
  CHECK(balls == 5);
}

TEST_CASE("07_timewarp --trace on a scene of one's own", "[chapters][trace][timewarp]") {
  const auto result = run(GJKX_CHAPTER_07, "timewarp-scene", "--scene " GJKX_SCENES "/ball_drop.json --frames 2 --trace");
  const auto rows = table(result.output, "fig-timewarp-spacetime: the Timewarp run event by event (Mirtich's Timewarp, §5-§6)");
  REQUIRE(!rows.empty());
  for (const Row& row : rows) CHECK((row[1] == "1" || row[1] == "2"));
  CHECK(rows.back()[1] == "2");
  checkRefused(GJKX_CHAPTER_07, "--scene /nonexistent/scene.json", "--scene");
  checkRefused(GJKX_CHAPTER_07, "--frames 0", "--frames");
}
