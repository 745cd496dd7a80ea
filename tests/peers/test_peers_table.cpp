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
  const test::ProgramResult r =
      test::runProgram(GJKX_PEERS_TABLE, "'thin plate=" + std::string(GJKX_THIN_PLATE) + "' --work '" +
                                             (dir / "work").string() + "' --table '" + table.string() + "'");
  INFO(r.output);
  REQUIRE(r.status == 0);
  std::ifstream in(table);
  std::stringstream text;
  text << in.rdbuf();
  // Ours runs; a row per simulator built, none of them failed for its command line.
  CHECK(text.str().find("| thin plate | gjkx (hybrid) | 0.25 s |") != std::string::npos);
  CHECK(text.str().find("failed") == std::string::npos);
  CHECK(text.str().find("*earlier*") == std::string::npos);  // every run made by this call
  // Again with --reuse: the rows are read from those runs, and the table says so.
  const test::ProgramResult again =
      test::runProgram(GJKX_PEERS_TABLE, "'thin plate=" + std::string(GJKX_THIN_PLATE) + "' --work '" +
                                             (dir / "work").string() + "' --reuse --table '" + table.string() + "'");
  INFO(again.output);
  REQUIRE(again.status == 0);
  std::ifstream reread(table);
  std::stringstream reused;
  reused << reread.rdbuf();
  CHECK(reused.str().find("| thin plate | gjkx (hybrid) | 0.25 s |") != std::string::npos);
  CHECK(reused.str().find("--out '" + (dir / "work").string() + "/thin plate-gjkx_simulate' --quiet` (*earlier*)") !=
        std::string::npos);
  fs::remove_all(dir);
}
