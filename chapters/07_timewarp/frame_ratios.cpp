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
#include "../formatting.hpp"

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

/// One run's frames: each frame's length in simulated seconds and its cost in seconds.
struct FrameCosts {
  std::vector<double> time, length, cost;
};

/// Reads DIR/frames.csv: the columns `time` and `cpu_s` (or `wall_s` less `checks_s`).
FrameCosts readFrames(const std::string& folder, bool wall) {
  const std::string path = folder + "/frames.csv";
  std::ifstream in(path);
  if (!in) throw std::runtime_error(path + ": cannot read (no run of gjkx_simulate there?)");
  std::string line;
  std::getline(in, line);
  const std::vector<std::string> names = chapter::csvFields(line);
  const auto columnOf = [&](const std::string& name) {
    const auto found = std::find(names.begin(), names.end(), name);
    if (found == names.end())
      throw std::runtime_error(path + ": no column '" + name + "' (a frames.csv of an older gjkx_simulate? run it again)");
    return std::size_t(found - names.begin());
  };
  const std::size_t time = columnOf("time");
  const std::size_t cost = columnOf(wall ? "wall_s" : "cpu_s");
  const std::size_t checks = wall ? columnOf("checks_s") : cost;
  FrameCosts frames;
  for (int row = 2; std::getline(in, line); ++row) {
    if (line.empty()) continue;
    const std::vector<std::string> cells = chapter::csvFields(line);
    if (cells.size() != names.size())
      throw std::runtime_error(path + ":" + std::to_string(row) + ": " + std::to_string(cells.size()) + " cells for " +
                               std::to_string(names.size()) + " columns");
    const auto number = [&](std::size_t k) {
      try {
        return std::stod(cells[k]);
      } catch (const std::logic_error&) {
        throw std::runtime_error(path + ":" + std::to_string(row) + ": column '" + names[k] + "': not a number");
      }
    };
    const double t = number(time);
    frames.length.push_back(t - (frames.time.empty() ? 0.0 : frames.time.back()));
    frames.time.push_back(t);
    frames.cost.push_back(number(cost) - (wall ? number(checks) : 0.0));
  }
  if (frames.time.empty()) throw std::runtime_error(path + ": no frames");
  return frames;
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
    FrameCosts frames;
    try {
      frames = readFrames(run.substr(eq + 1), wall);
    } catch (const std::exception& e) {
      std::fprintf(stderr, "gjkx_frame_ratios: %s\n", e.what());
      return 1;
    }
    // Each frame's cost over its length: 1 is real time.
    std::vector<double> ratio;
    double total = 0;
    for (std::size_t k = 0; k < frames.time.size(); ++k) {
      ratio.push_back(frames.length[k] > 0 ? frames.cost[k] / frames.length[k] : 0.0);
      total += frames.cost[k];
    }
    const std::size_t worst = std::size_t(std::max_element(ratio.begin(), ratio.end()) - ratio.begin());
    std::vector<double> sorted = ratio;
    std::sort(sorted.begin(), sorted.end());
    const std::size_t n = sorted.size();
    const double median = n % 2 ? sorted[n / 2] : 0.5 * (sorted[n / 2 - 1] + sorted[n / 2]);
    std::printf("RUN %s frames=%zu simulated_s=%.6g %s=%.4g slowest_at_t=%.4g\n", label.c_str(), n, frames.time.back(),
                wall ? "wall_s" : "processor_s", total, frames.time[worst]);
    std::printf("RATIO %s_slowest_frame_vs_real_time=%.4g\n", label.c_str(), ratio[worst]);
    std::printf("RATIO %s_median_frame_vs_real_time=%.4g\n", label.c_str(), median);
    std::printf("RATIO %s_total_vs_real_time=%.4g\n", label.c_str(), total / frames.time.back());
    slowest.emplace_back(label, ratio[worst]);
  }
  if (slowest.size() == 2)
    std::printf("RATIO %s_vs_%s_slowest_frame=%.4g\n", slowest[1].first.c_str(), slowest[0].first.c_str(),
                slowest[1].second / slowest[0].second);
  return 0;
}
