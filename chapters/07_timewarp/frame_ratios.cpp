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
//
// A run may be given as LABEL=DIR1,DIR2,...: the same scene run several times. A run is
// deterministic, so each frame did the same work in each; its cost is then the least of
// its times (what the machine's load added to the others is left out), and the runs must
// agree on every frame's collisions and pair checks, else the program exits 1 naming the
// first frame where they differ. The RUN line then says runs=N, and one more line gives
// how much the load moved that frame:
//
//   RATIO LABEL_slowest_frame_spread=<that frame's largest time over the runs / its least>
//
// And what the slowest frame did: its events (the hits taken from the ordering's queue,
// stale ones included, frames.csv's `events`; step ends are not among them), what each
// cost on average, and what each may cost for the frame to run in real time (its length
// over its events); with the body pairs checked again per event (after collisions and at
// step ends) and the time-of-impact queries per event:
//
//   SLOWEST LABEL frame=K events=E cost_per_event_us=... real_time_per_event_us=...
//           pairs_per_event=... queries_per_event=...
//
// (a slowest frame of no events has only its frame and events=0)
//
// When two runs are given, one more line compares their slowest frames:
//
//   RATIO SECOND_vs_FIRST_slowest_frame=<second's slowest / first's slowest>
//
// A missing file or column exits 1 naming it; a bad command line exits 2.
#include "../command_line.hpp"
#include "../08_torso/run_stats.hpp"  // torso::readRun: a run read back from its folder

#include <algorithm>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

/// Frame k's cost in seconds: its processor time (cpu_s), or with `wall` its wall time
/// less the independent checks' (wall_s - checks_s). Throws naming a missing column.
double frameCost(const torso::Run& run, std::size_t k, bool wall) {
  return wall ? run.at("wall_s")[k] - run.at("checks_s")[k] : run.at("cpu_s")[k];
}

/// The folders of a run's DIR1,DIR2,... (empty names are refused by the caller).
std::vector<std::string> foldersOf(const std::string& list) {
  std::vector<std::string> folders;
  std::size_t start = 0;
  for (std::size_t comma; (comma = list.find(',', start)) != std::string::npos; start = comma + 1)
    folders.push_back(list.substr(start, comma - start));
  folders.push_back(list.substr(start));
  return folders;
}

/// Throws unless `other` is the same run as `first`, frame by frame: as many frames, and
/// the same collisions and pair checks in each (a run is deterministic).
void requireSameRun(const torso::Run& first, const torso::Run& other) {
  if (other.frames() != first.frames())
    throw std::runtime_error(other.folder + ": " + std::to_string(other.frames()) + " frames, " + first.folder +
                             ": " + std::to_string(first.frames()) + ": not runs of the same scene");
  for (const char* column : {"collisions", "collision_checks"})
    for (std::size_t k = 0; k < first.frames(); ++k)
      if (other.at(column)[k] != first.at(column)[k])
        throw std::runtime_error(other.folder + ": frame " + std::to_string(k + 1) + " has " +
                                 std::to_string(long(other.at(column)[k])) + " " + column + ", " + first.folder + " " +
                                 std::to_string(long(first.at(column)[k])) + ": not the same run");
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"How far from real time each frame of a gjkx_simulate run was (RATIO lines)", "gjkx_frame_ratios"};
  std::vector<std::string> runs;
  bool wall = false;
  app.add_option("runs", runs,
                 "LABEL=DIR: a run's label and the folder of its frames.csv; LABEL=DIR1,DIR2,...: the same run repeated, "
                 "each frame's cost the least of its times")
      ->required();
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
    std::vector<double> ratio, spread;
    double total = 0;
    torso::Run frames;
    std::size_t repeats = 0;
    try {
      std::vector<torso::Run> repeated;
      for (const std::string& folder : foldersOf(run.substr(eq + 1))) {
        if (folder.empty()) throw std::runtime_error("'" + run + "': an empty folder name");
        repeated.push_back(torso::readRun(folder));
        requireSameRun(repeated.front(), repeated.back());
      }
      frames = repeated.front();
      repeats = repeated.size();
      for (std::size_t k = 0; k < frames.frames(); ++k) {
        double least = frameCost(frames, k, wall), most = least;
        for (const torso::Run& again : repeated) {
          least = std::min(least, frameCost(again, k, wall));
          most = std::max(most, frameCost(again, k, wall));
        }
        const double length = frames.frameLength(k);
        ratio.push_back(length > 0 ? least / length : 0.0);
        spread.push_back(least > 0 ? most / least : 1.0);
        total += least;
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
    std::printf("RUN %s frames=%zu simulated_s=%.6g %s=%.4g slowest_at_t=%.4g", label.c_str(), n, time.back(),
                wall ? "wall_s" : "processor_s", total, time[worst]);
    if (repeats > 1) std::printf(" runs=%zu", repeats);
    std::printf("\n");
    std::printf("RATIO %s_slowest_frame_vs_real_time=%.4g\n", label.c_str(), ratio[worst]);
    std::printf("RATIO %s_median_frame_vs_real_time=%.4g\n", label.c_str(), median);
    std::printf("RATIO %s_total_vs_real_time=%.4g\n", label.c_str(), total / time.back());
    if (repeats > 1) std::printf("RATIO %s_slowest_frame_spread=%.4g\n", label.c_str(), spread[worst]);
    // The slowest frame's events: each must cost no more than the frame's length over their
    // number for the frame to run in real time.
    try {
      const double events = frames.at("events")[worst];
      std::printf("SLOWEST %s frame=%zu events=%.0f", label.c_str(), worst + 1, events);
      if (events > 0) {  // (a frame of no events has no cost per event)
        const double length = frames.frameLength(worst);
        const double pairs = frames.at("rechecked_after_collisions")[worst] + frames.at("rechecked_at_step_ends")[worst];
        std::printf(" cost_per_event_us=%.4g real_time_per_event_us=%.4g pairs_per_event=%.4g queries_per_event=%.4g",
                    1e6 * ratio[worst] * length / events, 1e6 * length / events, pairs / events,
                    frames.at("collision_checks")[worst] / events);
      }
      std::printf("\n");
    } catch (const std::exception& e) {
      std::fprintf(stderr, "gjkx_frame_ratios: %s\n", e.what());
      return 1;
    }
    slowest.emplace_back(label, ratio[worst]);
  }
  if (slowest.size() == 2)
    std::printf("RATIO %s_vs_%s_slowest_frame=%.4g\n", slowest[1].first.c_str(), slowest[0].first.c_str(),
                slowest[1].second / slowest[0].second);
  return 0;
}
