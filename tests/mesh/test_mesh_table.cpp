// gjkx_mesh_table (chapter 06), the program that writes docs 06's table of assimp-testmodels,
// on a folder of small meshes written for the tests: every file is a row, what can be
// decomposed is, what is open is refused with gjkx's message and taken as a hull, and the
// caption's counts are the rows'. (The table itself takes minutes: it is made by the target
// figures, not here.)
#include "../run_program.hpp"

#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace {

/// The table's rows, each split into its cells.
std::vector<std::vector<std::string>> rowsOf(const std::string& table) {
  std::vector<std::vector<std::string>> rows;
  std::istringstream lines(table);
  for (std::string line; std::getline(lines, line);) {
    if (line.rfind("| ", 0) != 0 || line.rfind("| model", 0) == 0 || line.rfind("| ---", 0) == 0) continue;
    std::vector<std::string> cells;
    std::istringstream cellText(line.substr(2));
    for (std::string cell; std::getline(cellText, cell, '|');) {
      cell.erase(0, cell.find_first_not_of(' '));
      cell.erase(cell.find_last_not_of(' ') + 1);
      cells.push_back(cell);
    }
    rows.push_back(cells);
  }
  return rows;
}

}  // namespace

TEST_CASE("gjkx_mesh_table: a row per model, decomposed, refused with the message, or its hull", "[mesh]") {
  const fs::path dir = test::freshFolder("gjkx", "mesh-table");
  const fs::path models = dir / "models";
  fs::create_directories(models / "sub");
  for (const char* name : {"cube.off", "l_prism.off", "open_box.off"})
    fs::copy_file(fs::path(GJKX_MESH_TEST_DATA) / name, models / "sub" / name);
  std::ofstream(models / "notes.txt") << "not a model\n";  // Assimp reads no such file: left out, counted
  const test::ProgramResult r =
      test::runProgram(GJKX_MESH_TABLE, "--models " + models.string() + " --out " + (dir / "table.md").string());
  INFO(r.output);
  REQUIRE(r.status == 0);
  const std::string text = test::readText(dir / "table.md");
  const auto rows = rowsOf(text);
  REQUIRE(rows.size() == 3);  // in the order of their paths
  CHECK(rows[0][0] == "sub/cube.off");
  CHECK(rows[0][2] == "yes");
  CHECK(rows[0][3] == "decomposed");
  CHECK(rows[0][4] == "1 (8–8)");
  CHECK(rows[0][5] == "0.0 %");
  CHECK(rows[0][7] == "hull");
  CHECK(rows[1][0] == "sub/l_prism.off");
  CHECK(rows[1][3] == "decomposed");
  CHECK(rows[1][4].rfind("1 ", 0) != 0);  // an L is more than one convex piece
  CHECK(rows[2][0] == "sub/open_box.off");
  CHECK(rows[2][2] == "no");
  CHECK(rows[2][3].rfind("refused: sub/open_box.off: the mesh is not closed", 0) == 0);
  CHECK(rows[2][7] == "hull");
  CHECK(rows[2][8] == "8");
  CHECK_THAT(text, Catch::Contains("the 3 files") && Catch::Contains("the other 1 files") && Catch::Contains("decomposed: 2;") &&
                             Catch::Contains("refused: 1)") && Catch::Contains("(its hull: 3)"));
  fs::remove_all(dir);
}

TEST_CASE("gjkx_mesh_table: a folder that is not there is named, and the run fails", "[mesh]") {
  const test::ProgramResult r = test::runProgram(GJKX_MESH_TABLE, "--models /no/such/folder --out /tmp/never.md");
  CHECK(r.status == 1);
  CHECK_THAT(r.output, Catch::Contains("/no/such/folder") && Catch::Contains("assimp-testmodels"));
}
