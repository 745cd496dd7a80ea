// A run of gjkx_simulate read back from its folder (frames.csv, summary.txt), and the
// statistics the paper's §6 reports about its own run: the ratio of execution time to
// simulation time per frame, Brent's iterations per time-of-impact query, the photo-finish
// rate, and the counters the paper does not report (collisions, rollbacks, penetration,
// tunnelling). Chapter 08 draws Fig. 6 from the first and tabulates the rest
// (`08_torso --stats`); docs/08_torso.md states the definitions.
#pragma once

#include "../formatting.hpp"

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace torso {

/// The paper's own figures for its run (§6), each with the sentence it comes from.
struct PaperFigures {
  /// "The ratio of execution time to simulation time ranged between 1.0 and 7.9 for the entire simulation."
  static constexpr double ratioMin = 1.0;
  static constexpr double ratioMax = 7.9;  ///< same sentence as ratioMin
  /// "The peak at t ≈ 2 sec indicates the point when the number of interdependent collisions within the
  /// skeletal model was maximized due to the crash."
  static constexpr double peakTime = 2.0;
  /// "we found the TOI solver completed in 2.2 iterations on the average, with a worst case of 43 iterations,"
  static constexpr double brentMean = 2.2;
  static constexpr int brentWorst = 43;  ///< same sentence as brentMean
  /// "and an average "photo-finish" false alarm rate of 70%."
  static constexpr double photoFinishRate = 0.70;
};

/// The parts of a frame's wall time that are the method's, as Fig. 6 stacks them (the
/// columns of frames.csv, bottom to top). The independent checks (`checks_s`) are not
/// the method's and are left out; drawing has no column (gjkx_simulate draws nothing).
/// The last, the hybrid contact model's contact solver (`contacts_s`), is the paper's
/// future work (§6: "a more robust hybrid implementation remains as future work"): a run
/// without the column (an older frames.csv) counts it as none.
inline const std::vector<std::pair<std::string, std::string>>& methodParts() {
  static const std::vector<std::pair<std::string, std::string>> parts = {
      {"integration_s", "integration"},
      {"bounds_s", "bounding volumes"},
      {"collision_detection_s", "collision detection (GJK extrusion, TOI)"},
      {"impulses_s", "impulses"},
      {"ordering_s", "Timewarp ordering"},
      {"contacts_s", "contact solver (the hybrid)"}};
  return parts;
}

/// A run of gjkx_simulate: frames.csv's columns by name, and summary.txt's lines when the
/// folder has one.
struct Run {
  std::string folder;                                 ///< where it was read from
  std::map<std::string, std::vector<double>> column;  ///< frames.csv, one value per frame
  std::string summary;                                ///< the SUMMARY line (empty without summary.txt)
  std::string settings;                               ///< the RUN line: scene, scalar, tolerance... (may be empty)
  std::map<std::string, double> work;                 ///< the WORK line's counts by key (empty when it has none)

  /// The frames read.
  std::size_t frames() const { return column.at("frame").size(); }
  /// A column of frames.csv; throws std::runtime_error naming the file and the column if it is missing.
  const std::vector<double>& at(const std::string& name) const {
    const auto found = column.find(name);
    if (found == column.end())
      throw std::runtime_error(folder + "/frames.csv: no column '" + name +
                               "' (a frames.csv of an older gjkx_simulate? run it again)");
    return found->second;
  }
  /// The length of frame `k` in simulated seconds (its time less the previous frame's).
  double frameLength(std::size_t k) const {
    const auto& time = at("time");
    return k > 0 ? time[k] - time[k - 1] : time[0] / at("frame")[0];
  }
  /// Whether frames.csv has the column.
  bool has(const std::string& name) const { return column.count(name) > 0; }
  /// The method's wall time of frame `k` (s): the sum of methodParts() the run has, the checks left out.
  double methodSeconds(std::size_t k) const {
    double sum = 0;
    for (const auto& part : methodParts())
      if (has(part.first)) sum += at(part.first)[k];
    return sum;
  }
  /// The parts Fig. 6 stacks for this run: methodParts() less a column the run lacks or that
  /// is 0 in every frame (the contact solver of a run under microcollisions).
  std::vector<std::pair<std::string, std::string>> parts() const {
    std::vector<std::pair<std::string, std::string>> out;
    for (const auto& part : methodParts()) {
      if (!has(part.first)) continue;
      const auto& values = at(part.first);
      if (part.first == methodParts().front().first || std::any_of(values.begin(), values.end(), [](double v) { return v != 0; }))
        out.push_back(part);
    }
    return out;
  }
  /// Frame `k`'s execution time over its simulated time: 1 is real time.
  double ratio(std::size_t k) const { return methodSeconds(k) / frameLength(k); }
};

/// The columns every reader of a run needs (Fig. 6 and the table).
inline const std::vector<std::string>& requiredColumns() {
  static const std::vector<std::string> names = {
      "frame",          "time",       "wall_s",          "collision_checks", "collisions",
      "microcollisions", "rollbacks", "brent_iterations", "brent_queries",    "brent_max",
      "photo_finishes", "max_penetration", "tunnelled",  "solver_caps",      "integration_s",
      "bounds_s",       "collision_detection_s", "impulses_s", "ordering_s",  "checks_s"};
  return names;
}

/// Reads FOLDER/frames.csv (and FOLDER/summary.txt if present), whose columns must include
/// `required` (gjkx_simulate's, by default; a peer's runner writes fewer). Throws
/// std::runtime_error naming the file, and the column or line, for a missing file, a
/// missing column, a malformed number or a run without frames.
inline Run readRun(const std::string& folder, const std::vector<std::string>& required = requiredColumns()) {
  Run run;
  run.folder = folder;
  const std::string path = folder + "/frames.csv";
  std::ifstream in(path);
  if (!in) throw std::runtime_error(path + ": cannot read (no run of gjkx_simulate there?)");
  std::string line;
  std::getline(in, line);
  const std::vector<std::string> names = chapter::csvFields(line);
  for (const std::string& name : required)
    if (std::find(names.begin(), names.end(), name) == names.end())
      throw std::runtime_error(path + ": no column '" + name + "' (a frames.csv of an older gjkx_simulate? run it again)");
  for (int row = 2; std::getline(in, line); ++row) {
    if (line.empty()) continue;
    std::size_t k = 0;
    for (const std::string& cell : chapter::csvFields(line)) {
      if (k >= names.size()) throw std::runtime_error(path + ":" + std::to_string(row) + ": more cells than columns");
      try {
        std::size_t used = 0;
        const double value = std::stod(cell, &used);
        if (used != cell.size()) throw std::invalid_argument(cell);
        run.column[names[k]].push_back(value);
      } catch (const std::logic_error&) {
        throw std::runtime_error(path + ":" + std::to_string(row) + ": column '" + names[k] + "': not a number: '" +
                                 cell + "'");
      }
      ++k;
    }
    if (k != names.size())
      throw std::runtime_error(path + ":" + std::to_string(row) + ": " + std::to_string(k) + " cells for " +
                               std::to_string(names.size()) + " columns");
  }
  if (run.column.empty()) throw std::runtime_error(path + ": no frames");
  std::ifstream summary(folder + "/summary.txt");
  for (std::string text; std::getline(summary, text);) {
    if (text.rfind("SUMMARY ", 0) == 0) run.summary = text.substr(8);
    if (text.rfind("RUN ", 0) == 0) run.settings = text.substr(4);
    if (text.rfind("WORK ", 0) == 0) {
      std::stringstream words(text.substr(5));
      for (std::string w; words >> w;)
        if (const auto eq = w.find('='); eq != std::string::npos) {
          try {
            run.work[w.substr(0, eq)] = std::stod(w.substr(eq + 1));
          } catch (const std::logic_error&) {
            throw std::runtime_error(folder + "/summary.txt: WORK " + w.substr(0, eq) + ": not a number: '" +
                                     w.substr(eq + 1) + "'");
          }
        }
    }
  }
  return run;
}

/// The statistics of a run that §6 reports for its own (and a few it does not).
struct RunStats {
  std::size_t frames = 0;       ///< frames of the run
  double simulated = 0;         ///< simulated seconds (the last frame's time)
  double ratioMin = 0;          ///< execution over simulation time: the least of a frame
  double ratioMedian = 0;       ///< the median over frames (mean of the two middle ones for an even count)
  double ratioMax = 0;          ///< the most of a frame
  double ratioMaxTime = 0;      ///< the time at the end of that frame
  double ratioPeak = 0;         ///< the ratio at the peak frame, the one with the most collisions
  double peakTime = 0;          ///< the time at the end of the peak frame
  long peakCollisions = 0;      ///< collisions in the peak frame
  double checksShare = 0;       ///< the independent checks' share of all wall time (not in the ratios)
  long collisionChecks = 0;     ///< time-of-impact queries
  long brentQueries = 0;        ///< queries whose first complete extrusion test failed, so that Brent ran
  long brentIterations = 0;     ///< Brent iterates of all queries
  double brentMean = 0;         ///< brentIterations / brentQueries (0 when no query ran Brent)
  int brentWorst = 0;           ///< the most iterates of one query
  long photoFinishes = 0;       ///< queries that ended in a photo finish
  double photoFinishRate = 0;   ///< photoFinishes / brentQueries (0 when no query ran Brent)
  long collisions = 0;          ///< impulses applied, microcollisions included
  long microcollisions = 0;     ///< of which microcollisions
  long rollbacks = 0;           ///< collisions that rolled back bodies
  long solverCaps = 0;          ///< queries that ran out of iterations
  double maxPenetration = 0;    ///< deepest penetration at any frame's end (-1: not checked)
  long tunnelled = 0;           ///< pairs that went through each other unreported (-1: not checked)
  double methodSeconds = 0;     ///< the method's wall time over all frames (the parts of Fig. 6)
  double boundsSeconds = 0;     ///< of which the bounding volumes (the 14-DOP hierarchies)
  double detectionSeconds = 0;  ///< of which collision detection (the time-of-impact queries)
  double completeTests = -1;    ///< complete extrusion tests (summary.txt's WORK line; -1: not recorded)
  double sdEvaluations = -1;    ///< supporting distances evaluated by the queries (-1: not recorded)
  double kdopNodes = -1;        ///< nodes of the 14-DOP test trees visited (-1: not recorded)
  // The hybrid contact model's columns (docs 07; -1: not recorded, an older frames.csv).
  double contactsSeconds = -1;  ///< wall time of the contact part (contacts_s), of methodSeconds
  double contactPoints = -1;    ///< manifold points solved per frame (summed over its intervals): mean
  double contactPointsMax = -1; ///< and the most in a frame
  double contactGroups = -1;    ///< contact groups solved per frame: mean
  double contactSweeps = -1;    ///< sweeps of sequential impulses per frame: mean
  double energyRises = -1;      ///< group solves whose kinetic energy rose: total
  double sleepingEnd = -1;      ///< bodies asleep at the last frame's end
  double sleepingMax = -1;      ///< the most asleep at a frame's end
  /// Where the slowest frame's work went (docs 07's columns; -1: not recorded, an older
  /// frames.csv): its intervals; the body pairs Timewarp checked at the intervals' starts,
  /// again after collisions and at own steps' ends; its impulses and, of them, the instant
  /// passes' cascaded ones.
  double slowestIntervals = -1;
  double slowestAtStarts = -1;         ///< checked_at_interval_starts
  double slowestAfterCollisions = -1;  ///< rechecked_after_collisions
  double slowestAtStepEnds = -1;       ///< rechecked_at_step_ends
  double slowestImpulses = -1;         ///< collisions
  double slowestCascaded = -1;         ///< cascade_impulses
};

/// The statistics of `run` (definitions at each field of RunStats).
inline RunStats statsOf(const Run& run) {
  RunStats s;
  s.frames = run.frames();
  s.simulated = run.at("time").back();
  std::vector<double> ratios;
  double wall = 0, checks = 0;
  std::size_t slowest = 0;  // the frame of ratioMax
  for (std::size_t k = 0; k < s.frames; ++k) {
    const double r = run.ratio(k), t = run.at("time")[k];
    ratios.push_back(r);
    if (k == 0 || r < s.ratioMin) s.ratioMin = r;
    if (k == 0 || r > s.ratioMax) s.ratioMax = r, s.ratioMaxTime = t, slowest = k;
    const long collisions = long(run.at("collisions")[k]);
    if (k == 0 || collisions > s.peakCollisions) s.peakCollisions = collisions, s.ratioPeak = r, s.peakTime = t;
    wall += run.at("wall_s")[k];
    checks += run.at("checks_s")[k];
    s.methodSeconds += run.methodSeconds(k);
    s.boundsSeconds += run.at("bounds_s")[k];
    s.detectionSeconds += run.at("collision_detection_s")[k];
    s.collisionChecks += long(run.at("collision_checks")[k]);
    s.brentQueries += long(run.at("brent_queries")[k]);
    s.brentIterations += long(run.at("brent_iterations")[k]);
    s.brentWorst = std::max(s.brentWorst, int(run.at("brent_max")[k]));
    s.photoFinishes += long(run.at("photo_finishes")[k]);
    s.collisions += collisions;
    s.microcollisions += long(run.at("microcollisions")[k]);
    s.rollbacks += long(run.at("rollbacks")[k]);
    s.solverCaps += long(run.at("solver_caps")[k]);
    const double penetration = run.at("max_penetration")[k], tunnelled = run.at("tunnelled")[k];
    s.maxPenetration = penetration < 0 || s.maxPenetration < 0 ? -1 : std::max(s.maxPenetration, penetration);
    s.tunnelled = tunnelled < 0 || s.tunnelled < 0 ? -1 : s.tunnelled + long(tunnelled);
  }
  std::sort(ratios.begin(), ratios.end());
  const std::size_t n = ratios.size();
  s.ratioMedian = n % 2 ? ratios[n / 2] : 0.5 * (ratios[n / 2 - 1] + ratios[n / 2]);
  s.checksShare = wall > 0 ? checks / wall : 0;
  s.brentMean = s.brentQueries > 0 ? double(s.brentIterations) / double(s.brentQueries) : 0;
  s.photoFinishRate = s.brentQueries > 0 ? double(s.photoFinishes) / double(s.brentQueries) : 0;
  const auto work = [&](const char* key) {
    const auto found = run.work.find(key);
    return found == run.work.end() ? -1.0 : found->second;
  };
  const auto total = [&](const char* name, bool mean) {
    if (!run.has(name)) return -1.0;
    double sum = 0;
    for (double v : run.at(name)) sum += v;
    return mean ? sum / double(s.frames) : sum;
  };
  const auto most = [&](const char* name) {
    return run.has(name) ? *std::max_element(run.at(name).begin(), run.at(name).end()) : -1.0;
  };
  s.contactsSeconds = total("contacts_s", false);
  s.contactPoints = total("contact_points", true);
  s.contactPointsMax = most("contact_points");
  s.contactGroups = total("contact_groups", true);
  s.contactSweeps = total("contact_sweeps", true);
  s.energyRises = total("energy_rises", false);
  s.sleepingEnd = run.has("sleeping") ? run.at("sleeping").back() : -1.0;
  s.sleepingMax = most("sleeping");
  const auto atSlowest = [&](const char* name) { return run.has(name) ? run.at(name)[slowest] : -1.0; };
  s.slowestIntervals = atSlowest("intervals");
  s.slowestAtStarts = atSlowest("checked_at_interval_starts");
  s.slowestAfterCollisions = atSlowest("rechecked_after_collisions");
  s.slowestAtStepEnds = atSlowest("rechecked_at_step_ends");
  s.slowestImpulses = atSlowest("collisions");
  s.slowestCascaded = atSlowest("cascade_impulses");
  s.completeTests = work("complete_tests");
  s.sdEvaluations = work("sd_evaluations");
  s.kdopNodes = work("kdop_nodes");
  return s;
}

/// A markdown table of the runs' statistics, one column per run (headed by its label), and
/// the paper's figures in the last column ("not reported" where §6 gives none). Under the
/// table: each run's folder and settings (summary.txt's RUN line) and `command`, the
/// command line that made the table.
inline std::string statsTable(const std::vector<std::pair<std::string, Run>>& runs, const std::string& command) {
  using chapter::format;
  using P = PaperFigures;
  std::vector<RunStats> stats;
  for (const auto& run : runs) stats.push_back(statsOf(run.second));
  const std::string none = "not reported";
  std::ostringstream md;
  auto row = [&](const std::string& name, auto cell, const std::string& paper) {
    md << "| " << name;
    for (const RunStats& s : stats) md << " | " << cell(s);
    md << " | " << paper << " |\n";
  };
  md << "| |";
  for (const auto& run : runs) md << " " << run.first << " |";
  md << " paper (§6) |\n| --- |";
  for (std::size_t k = 0; k < runs.size(); ++k) md << " ---: |";
  md << " ---: |\n";
  row("frames (simulated s)", [](const RunStats& s) { return format("%.0f", double(s.frames)) + format(" (%.3g s)", s.simulated); },
      "1/24 s each; " + none);
  row("execution / simulation time: min", [](const RunStats& s) { return format("%.3g", s.ratioMin); },
      format("%.1f", P::ratioMin));
  row("execution / simulation time: median", [](const RunStats& s) { return format("%.3g", s.ratioMedian); }, none);
  row("execution / simulation time: max (at t)",
      [](const RunStats& s) { return format("%.3g (%.3g s)", s.ratioMax, s.ratioMaxTime); },
      format("%.1f", P::ratioMax));
  row("execution / simulation time: peak frame (most collisions; at t, collisions)",
      [](const RunStats& s) {
        return format("%.3g (%.3g s", s.ratioPeak, s.peakTime) + format(", %.0f)", double(s.peakCollisions));
      },
      format("peak at t ≈ %.0f s; its value not given apart from the max", P::peakTime));
  row("method wall time, s (of which bounding volumes; collision detection)",
      [](const RunStats& s) {
        return format("%.1f (", s.methodSeconds) + format("%.1f; %.1f)", s.boundsSeconds, s.detectionSeconds);
      },
      none);
  const auto count = [](double n) { return n < 0 ? std::string("not recorded") : format("%.4g", n); };
  row("complete extrusion tests; supporting distances evaluated (per query)",
      [&](const RunStats& s) {
        return count(s.completeTests) + "; " + count(s.sdEvaluations) +
               (s.sdEvaluations < 0 || s.collisionChecks == 0
                    ? std::string()
                    : format(" (%.3g)", s.sdEvaluations / double(s.collisionChecks)));
      },
      none);
  row("14-DOP test-tree nodes visited", [&](const RunStats& s) { return count(s.kdopNodes); }, none);
  row("independent checks, share of wall time (not in the ratios)",
      [](const RunStats& s) { return format("%.1f%%", 100 * s.checksShare); }, "no such checks");
  row("time-of-impact queries (of which ran Brent)",
      [](const RunStats& s) { return std::to_string(s.collisionChecks) + " (" + std::to_string(s.brentQueries) + ")"; },
      none);
  row("Brent iterations per query that ran Brent: mean", [](const RunStats& s) { return format("%.3g", s.brentMean); },
      format("%.1f", P::brentMean));
  row("Brent iterations: worst query", [](const RunStats& s) { return std::to_string(s.brentWorst); },
      std::to_string(P::brentWorst));
  row("photo-finish rate (of queries that ran Brent)",
      [](const RunStats& s) { return format("%.1f%%", 100 * s.photoFinishRate); },
      format("%.0f%% (\"false alarm rate\")", 100 * P::photoFinishRate));
  row("collisions (microcollisions)",
      [](const RunStats& s) { return std::to_string(s.collisions) + " (" + std::to_string(s.microcollisions) + ")"; },
      none);
  row("rollbacks", [](const RunStats& s) { return std::to_string(s.rollbacks); }, none);
  row("solver iteration caps", [](const RunStats& s) { return std::to_string(s.solverCaps); }, none);
  row("deepest penetration at a frame's end",
      [](const RunStats& s) { return s.maxPenetration < 0 ? std::string("not checked") : format("%.3g m", s.maxPenetration); },
      none);
  row("pairs tunnelled", [](const RunStats& s) { return s.tunnelled < 0 ? std::string("not checked") : std::to_string(s.tunnelled); },
      none);
  // The hybrid contact model (docs 07, "Resting contact"), the paper's future work.
  const std::string future = "future work (§6)";
  row("contact solver wall time, s (of the method's)",
      [&](const RunStats& s) { return s.contactsSeconds < 0 ? std::string("not recorded") : format("%.2f", s.contactsSeconds); },
      future);
  row("contact points solved per frame: mean (most)",
      [&](const RunStats& s) {
        return s.contactPoints < 0 ? std::string("not recorded")
                                   : format("%.4g", s.contactPoints) + format(" (%.0f)", s.contactPointsMax);
      },
      future);
  row("contact groups solved per frame: mean",
      [&](const RunStats& s) { return s.contactGroups < 0 ? std::string("not recorded") : format("%.3g", s.contactGroups); },
      future);
  row("sequential-impulse sweeps per frame: mean",
      [&](const RunStats& s) { return s.contactSweeps < 0 ? std::string("not recorded") : format("%.3g", s.contactSweeps); },
      future);
  row("contact solves whose kinetic energy rose", [&](const RunStats& s) { return count(s.energyRises); }, future);
  row("bodies asleep at the end (most at a frame's end)",
      [&](const RunStats& s) {
        return s.sleepingEnd < 0 ? std::string("not recorded")
                                 : format("%.0f", s.sleepingEnd) + format(" (%.0f)", s.sleepingMax);
      },
      none);
  row("slowest frame: intervals; body pairs checked at their starts, after collisions, at step ends; impulses (cascaded)",
      [&](const RunStats& s) {
        if (s.slowestIntervals < 0) return std::string("not recorded");
        return format("%.0f; ", s.slowestIntervals) + format("%.0f, ", s.slowestAtStarts) +
               format("%.0f, ", s.slowestAfterCollisions) + format("%.0f; ", s.slowestAtStepEnds) +
               format("%.0f", s.slowestImpulses) + format(" (%.0f)", s.slowestCascaded);
      },
      none);
  md << "\nRuns:\n\n";
  for (const auto& run : runs)
    md << "- " << run.first << ": `" << run.second.folder << "`"
       << (run.second.settings.empty() ? std::string(" (no summary.txt: settings unknown)") : ", " + run.second.settings)
       << "\n";
  md << "- paper: 500 MHz Pentium III, 80 bones (24,790 triangles), plant of 8,640 triangles, float, tolerance "
        "ε^(1/2) ≈ 0.0003\n\nMade by `"
     << command << "`.\n";
  return md.str();
}

}  // namespace torso
