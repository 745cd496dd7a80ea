// gjkx_frame_ratios: how far from real time a run of gjkx_simulate was, frame by frame
// (docs 07, "Speed"). §6 reports "the ratio of execution time to simulation time" per
// frame; this prints, for each run given as LABEL=DIR (DIR holding the run's frames.csv):
//
//   RUN LABEL frames=N simulated_s=... processor_s=... slowest_at_t=...
//   RATIO LABEL_slowest_frame_vs_real_time=<the largest of a frame's cost / its length>
//   RATIO LABEL_median_frame_vs_real_time=<their median>
//   RATIO LABEL_total_vs_real_time=<all frames' cost / the simulated time>
//
// A frame's cost is its processor time (frames.csv's cpu_s), not its wall time: on a
// machine other programs share, the wall time counts their turns on the processor too.
// With --wall the wall time (wall_s, less the independent checks' checks_s) is used instead.
// When two runs are given, one more line compares their slowest frames:
//
//   RATIO SECOND_vs_FIRST_slowest_frame=<second's slowest / first's slowest>
//
// A missing file or column exits 1 naming it; a bad command line exits 2.
#include "../command_line.hpp"
#include "../08_torso/run_stats.hpp"  // torso::readRun: a run read back from its folder

#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

namespace {

/// Frame k's cost in seconds: its processor time (cpu_s), or with `wall` its wall time
/// less the independent checks' (wall_s - checks_s). Throws naming a missing column.
double frameCost(const torso::Run& run, std::size_t k, bool wall) {
  return wall ? run.at("wall_s")[k] - run.at("checks_s")[k] : run.at("cpu_s")[k];
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"How far from real time each frame of a gjkx_simulate run was (RATIO lines)", "gjkx_frame_ratios"};
  std::vector<std::string> runs;
  bool wall = false;
  app.add_option("runs", runs, "LABEL=DIR: a run's label and the folder of its frames.csv")->required();
  app.add_flag("--wall", wall, "use the wall time (wall_s less checks_s) instead of the processor time (cpu_s)");
  chapter::parseOrExit(app, argc, argv);

  std::vector<std::pair<std::string, double>> slowest;
  for (const std::string& run : runs) {
    const auto eq = run.find('=');
    if (eq == std::string::npos || eq == 0 || eq + 1 == run.size()) {
      std::fprintf(stderr, "gjkx_frame_ratios: '%s': a run is LABEL=DIR\n", run.c_str());
      return chapter::kUsageError;
    }
    const std::string label = run.substr(0, eq);
    // Each frame's cost over its length: 1 is real time.
    std::vector<double> ratio;
    double total = 0;
    torso::Run frames;
    try {
      frames = torso::readRun(run.substr(eq + 1));
      for (std::size_t k = 0; k < frames.frames(); ++k) {
        const double cost = frameCost(frames, k, wall), length = frames.frameLength(k);
        ratio.push_back(length > 0 ? cost / length : 0.0);
        total += cost;
      }
    } catch (const std::exception& e) {
      std::fprintf(stderr, "gjkx_frame_ratios: %s\n", e.what());
      return 1;
    }
    const std::vector<double>& time = frames.at("time");
    const std::size_t worst = std::size_t(std::max_element(ratio.begin(), ratio.end()) - ratio.begin());
    std::vector<double> sorted = ratio;
    std::sort(sorted.begin(), sorted.end());
    const std::size_t n = sorted.size();
    const double median = n % 2 ? sorted[n / 2] : 0.5 * (sorted[n / 2 - 1] + sorted[n / 2]);
    std::printf("RUN %s frames=%zu simulated_s=%.6g %s=%.4g slowest_at_t=%.4g\n", label.c_str(), n, time.back(),
                wall ? "wall_s" : "processor_s", total, time[worst]);
    std::printf("RATIO %s_slowest_frame_vs_real_time=%.4g\n", label.c_str(), ratio[worst]);
    std::printf("RATIO %s_median_frame_vs_real_time=%.4g\n", label.c_str(), median);
    std::printf("RATIO %s_total_vs_real_time=%.4g\n", label.c_str(), total / time.back());
    slowest.emplace_back(label, ratio[worst]);
  }
  if (slowest.size() == 2)
    std::printf("RATIO %s_vs_%s_slowest_frame=%.4g\n", slowest[1].first.c_str(), slowest[0].first.c_str(),
                slowest[1].second / slowest[0].second);
  return 0;
}
