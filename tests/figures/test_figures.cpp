// The kept figures are what the chapters draw: regenerate every figure into a
// temporary folder and compare it with the PNG kept in figures/, within the kept
// figures' tolerance (kept::kTolerance, chapters/kept_figures.hpp: another machine's
// rasteriser or font library may round the last bit of an edge's coverage otherwise).
#include "kept_figures.hpp"

#include <catch2/catch.hpp>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <unistd.h>

namespace fs = std::filesystem;

namespace {

// Chapter programs and the kept figures, passed in by tests/CMakeLists.txt.
std::vector<std::string> chapterPrograms() {
  std::vector<std::string> programs;
  std::stringstream list(GJKX_CHAPTER_PROGRAMS);
  for (std::string item; std::getline(list, item, '|');)
    if (!item.empty()) programs.push_back(item);
  return programs;
}

fs::path freshFolder(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("gjkx-figures-" + name + "-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

std::set<std::string> pngsIn(const fs::path& dir) {
  std::set<std::string> names;
  for (const auto& entry : fs::directory_iterator(dir))
    if (entry.path().extension() == ".png") names.insert(entry.path().filename().string());
  return names;
}

}  // namespace

TEST_CASE("every chapter redraws its kept figures within a small pixel tolerance", "[figures]") {
  const fs::path keptDir = GJKX_KEPT_FIGURES;
  std::set<std::string> regenerated;
  for (const std::string& program : chapterPrograms()) {
    const fs::path out = freshFolder(fs::path(program).filename().string());
    const std::string command = "\"" + program + "\" --out \"" + out.string() + "\" > \"" + (out / "log.txt").string() + "\" 2>&1";
    INFO("running " << command);
    REQUIRE(std::system(command.c_str()) == 0);
    const auto names = pngsIn(out);
    CHECK_FALSE(names.empty());  // a chapter that draws nothing is not done
    for (const std::string& name : names) {
      INFO("figure " << name << " from " << program);
      regenerated.insert(name);
      REQUIRE(fs::exists(keptDir / name));  // a new figure must be kept in figures/
      const kept::Diff diff = kept::compare(kept::readPng((keptDir / name).string()), kept::readPng((out / name).string()));
      INFO("differing pixels: " << diff.differingPixels << " (" << diff.differingFraction * 100 << "%), max channel "
                                << diff.maxChannelDifference);
      CHECK(diff.same());
    }
    fs::remove_all(out);
  }
  // And no kept figure is left without a chapter that draws it (when every chapter was
  // built: a build without OSMesa leaves out those with 3D figures).
  if (!GJKX_ALL_CHAPTERS_BUILT) return;
  for (const std::string& name : pngsIn(keptDir)) {
    INFO("kept figure " << name << " is drawn by no chapter");
    CHECK(regenerated.count(name) == 1);
  }
}

TEST_CASE("figures/README.md lists every kept figure", "[figures]") {
  const fs::path keptDir = GJKX_KEPT_FIGURES;
  std::ifstream readme(keptDir / "README.md");
  REQUIRE(readme.good());
  const std::string text((std::istreambuf_iterator<char>(readme)), std::istreambuf_iterator<char>());
  for (const std::string& name : pngsIn(keptDir)) {
    INFO(name << " is missing from figures/README.md");
    CHECK(text.find(name) != std::string::npos);
  }
}
