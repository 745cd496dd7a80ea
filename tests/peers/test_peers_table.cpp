// gjkx_peers_table as a user runs it (docs/08_torso.md, "The peers side by side"): a scene
// whose label holds a space, in a work folder whose path holds one, is run by every
// simulator that was built and written as rows of one table.
#include <catch2/catch.hpp>

#include "../run_program.hpp"

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

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
  const std::string made = tableOf("");
  CHECK(made.find("| thin plate | gjkx (hybrid) | 0.25 s |") != std::string::npos);
  CHECK(made.find("failed") == std::string::npos);
  CHECK(made.find("*earlier*") == std::string::npos);  // every run made by this call
  // Again with --reuse: the rows are read from those runs, and the table says so.
  const std::string reused = tableOf("--reuse ");
  CHECK(reused.find("| thin plate | gjkx (hybrid) | 0.25 s |") != std::string::npos);
  CHECK(reused.find("--out '" + (dir / "work").string() + "/thin plate-gjkx_simulate' --quiet` (*earlier*)") !=
        std::string::npos);
  fs::remove_all(dir);
}
