// The kept figures/data/timewarp-benchmark.txt holds the counts timewarp_benchmark writes
// now. Docs 07 includes it: a change to the step that changes one of its counts
// (collisions, rollbacks, pair checks, Brent iterations) must remake it with docs 07's
// command, or this test fails, naming the command. The wall times and their shares depend
// on the machine and are not compared.
#include "../run_program.hpp"

#include <catch2/catch.hpp>

#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace {

/// docs 07's command, less the program and the redirection.
const std::string kArguments = "--bodies 60 --duration 1 --contact microcollisions";

/// Per ordering's row (its first word: timewarp, toi_heap, fixed_step, timewarp*), the row's
/// counts: collisions, rollbacks, rollbacks per frame, pair checks and Brent iterations (the
/// words after the wall time, up to the '|' before the parts' shares).
std::map<std::string, std::vector<std::string>> countsOf(const std::string& text) {
  std::map<std::string, std::vector<std::string>> rows;
  std::istringstream lines(text);
  for (std::string line; std::getline(lines, line);) {
    std::istringstream words(line.substr(0, line.find('|')));
    std::string ordering, wall;
    if (!(words >> ordering >> wall)) continue;
    if (ordering != "timewarp" && ordering != "toi_heap" && ordering != "fixed_step" && ordering != "timewarp*") continue;
    std::vector<std::string> counts;
    for (std::string w; words >> w;) counts.push_back(w);
    rows[ordering] = counts;
  }
  return rows;
}

}  // namespace

TEST_CASE("the kept timewarp-benchmark.txt has the counts timewarp_benchmark writes now", "[benchmark]") {
  std::ifstream in(GJKX_KEPT_BENCHMARK);
  REQUIRE(in);
  std::stringstream kept;
  kept << in.rdbuf();
  const test::ProgramResult fresh = test::runProgram(GJKX_TIMEWARP_BENCHMARK, kArguments + " 2>/dev/null");
  REQUIRE(fresh.status == 0);
  const auto keptRows = countsOf(kept.str()), freshRows = countsOf(fresh.output);
  INFO("remake it: build/chapters/timewarp_benchmark " << kArguments << " > figures/data/timewarp-benchmark.txt");
  REQUIRE(freshRows.size() == 4);
  for (const auto& [ordering, counts] : freshRows) {
    INFO("ordering " << ordering);
    REQUIRE(keptRows.count(ordering) == 1);
    REQUIRE(counts.size() == 5);
    CHECK(keptRows.at(ordering) == counts);
  }
  // The first line says what was run: the same bodies, time and model.
  CHECK(kept.str().substr(0, kept.str().find('\n')) == fresh.output.substr(0, fresh.output.find('\n')));
}
