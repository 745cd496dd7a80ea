// The three torso runs kept in figures/data/ (docs 08: ours, the paper's §5, the hybrid) are
// what gjkx_simulate does now. Fig. 5, the crash's animation, Fig. 6 and its companions are
// drawn from them (and the statistics table's first three columns are runs of the same
// commands), and a change to the step that changes what a run does leaves them describing
// code that no longer exists, unnoticed. Each run is made again over
// its first frames, through the crash (frame 13), and every count of its frames.csv (every
// column but the timings, which belong to the machine) must equal the kept file's, frame by
// frame. It fails naming docs 08's command that remakes the run.
#include "../run_program.hpp"

#include <catch2/catch.hpp>

#include <filesystem>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace {

/// One kept run: its folder under figures/data and docs 08's options for it.
struct KeptRun {
  std::string folder;
  std::string options;
};

/// True for a column that is a timing (its name ends in `_s`): the machine's, not the run's.
bool isTiming(const std::string& column) {
  return column.size() > 2 && column.compare(column.size() - 2, 2, "_s") == 0;
}

/// The frames through the crash and a little after (the torso lands in frame 13).
constexpr int kFrames = 15;

}  // namespace

TEST_CASE("the kept torso runs are what gjkx_simulate does now, count for count, over the first 15 frames",
          "[torso]") {
  const fs::path dir = test::freshFolder("gjkx", "kept-runs");
  const test::ProgramResult generated = test::runProgram(GJKX_GENERATE_TORSO, "--out \"" + (dir / "torso").string() + "\"");
  INFO(generated.output);
  REQUIRE(generated.status == 0);
  // One decomposition of the meshes, shared by the three runs (not the user's cache).
  const std::string common = "\"" + (dir / "torso" / "scene.json").string() + "\" --no-checks --quiet --duration " +
                             std::to_string(kFrames / 24.0) + " --mesh-cache \"" + (dir / "cache").string() + "\"";
  const std::vector<KeptRun> runs = {{"torso-run", ""}, {"torso-run-paper", "--solver paper"},
                                     {"torso-run-hybrid", "--contact hybrid"}};
  for (const KeptRun& run : runs) {
    INFO("kept run figures/data/" << run.folder << ": remake it with docs 08's command (gjkx_simulate "
                                  << (run.options.empty() ? "" : run.options + " ") << "--no-checks)");
    const fs::path out = dir / run.folder;
    const test::ProgramResult simulated =
        test::runProgram(GJKX_SIMULATE, common + " " + run.options + " --out \"" + out.string() + "\"");
    INFO(simulated.output);
    REQUIRE(simulated.status == 0);
    const auto fresh = test::readCsv(out / "frames.csv");
    const auto kept = test::readCsv(fs::path(GJKX_KEPT_DATA) / run.folder / "frames.csv");
    REQUIRE(fresh.size() == std::size_t(kFrames) + 1);
    REQUIRE(kept.size() > std::size_t(kFrames));
    REQUIRE(kept[0] == fresh[0]);  // the same columns
    for (int frame = 1; frame <= kFrames; ++frame) {
      REQUIRE(kept[frame].size() == fresh[0].size());
      REQUIRE(fresh[frame].size() == fresh[0].size());
      for (std::size_t c = 0; c < fresh[0].size(); ++c) {
        if (isTiming(fresh[0][c])) continue;
        INFO("frame " << frame << ", column " << fresh[0][c]);
        CHECK(kept[frame][c] == fresh[frame][c]);
      }
    }
  }
  fs::remove_all(dir);
}
