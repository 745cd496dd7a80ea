// The study's key figures (chapter 09) are those of its kept data: the *-summary.md and
// *-goals.md files in figures/study, which docs/09_study.md includes and whose numbers its
// prose discusses, are exactly what `gjk_study --replot` and `toi_study --replot` compute
// from the CSV files kept beside them. A number edited by hand, or a CSV kept from one run
// beside key figures from another, fails here.
#include "../run_program.hpp"

#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace fs = std::filesystem;

namespace {

std::string contents(const fs::path& file) { return test::readText(file); }

}  // namespace

TEST_CASE("the study's kept key figures are what its kept CSV files give") {
  const fs::path kept = GJKX_STUDY_FIGURES;
  const fs::path dir = test::freshFolder("gjkx-study", "key-figures");
  int csvs = 0;
  for (const auto& entry : fs::directory_iterator(kept))
    if (entry.path().extension() == ".csv") {
      fs::copy_file(entry.path(), dir / entry.path().filename());
      ++csvs;
    }
  REQUIRE(csvs > 0);
  for (const char* program : {GJKX_GJK_STUDY, GJKX_TOI_STUDY}) {
    const test::ProgramResult r = test::runProgram(program, "--replot --out \"" + dir.string() + "\"");
    INFO(program << " said:\n" << r.output);
    REQUIRE(r.status == 0);
  }
  for (const char* name : {"gjk-distance-summary.md", "gjk-boolean-summary.md", "gjk-float-summary.md", "gjk-goals.md",
                           "toi-summary.md", "toi-goals.md"}) {
    INFO(name);
    REQUIRE(fs::exists(kept / name));
    REQUIRE(fs::exists(dir / name));
    CHECK(contents(dir / name) == contents(kept / name));
  }
  fs::remove_all(dir);
}
