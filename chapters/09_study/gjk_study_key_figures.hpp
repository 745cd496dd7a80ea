// The GJK study's key figures (chapter 09): what the docs page quotes, computed from the
// rows (measured, or read back from the CSV files by --replot): gjk-distance-summary.md,
// gjk-boolean-summary.md, gjk-float-summary.md, and the speed goals in gjk-goals.md.
#pragma once

#include "../formatting.hpp"
#include "gjk_study_workloads.hpp"

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

namespace gjk_study {

using gjkx::study::gjk_comparison::GjkRow;
using chapter::format;

// ---------------------------------------------------------------------------------------
// Key figures: the numbers the docs page quotes, computed from the rows (measured or read
// back from the CSV files by --replot), so the page's text follows every rerun.


/// One table, a row per shape: ours-double's median time, the fastest peer's, and their
/// ratio, cold and warm.
inline void writeSpeedTable(std::ostream& md, const std::vector<GjkRow>& rows, bool boolean) {
  md << "| shape | cold: ours-double ns | cold: fastest peer ns | cold: ours / peer | warm: ours-double ns | warm: fastest peer ns | warm: ours / peer |\n";
  md << "| --- | ---: | ---: | ---: | ---: | ---: | ---: |\n";
  for (const auto& shape : shapesOf(rows)) {
    md << "| " << shape;
    for (bool warm : {false, true}) {
      const std::string w = workloadName(boolean, shape, warm);
      const GjkRow* ours = rowOf(rows, w, "ours-double");
      const GjkRow* peer = bestPeerRow(rows, w);
      md << " | " << (ours ? format("%.0f", ours->medianNs) : "-") << " | "
         << (peer ? format("%.0f", peer->medianNs) + " (" + peer->method + ")" : "-") << " | "
         << (ours && peer ? format("%.2f", ours->medianNs / peer->medianNs) : "-");
    }
    md << " |\n";
  }
}

/// "lo to hi" of a set of values, formatted with f.
inline std::string rangeText(const char* f, std::vector<double> v) {
  if (v.empty()) return "-";
  const auto [lo, hi] = std::minmax_element(v.begin(), v.end());
  return *lo == *hi ? format(f, *lo) : format(f, *lo) + " to " + format(f, *hi);
}

inline bool isCurved(const std::string& shape) { return shape == "sphere" || shape == "capsule"; }

/// gjk-distance-summary.md: the distance queries' key figures.
inline void writeDistanceSummary(const std::string& path, const std::vector<GjkRow>& rows) {
  std::ofstream md(path);
  chapter::markdownTitle(md, true, "GJK distance queries: key figures");
  writeSpeedTable(md, rows, false);
  // Ratios and ours' largest error, boxes and polytopes apart from spheres and capsules.
  std::vector<double> cold[2], warm[2], errorMax[2];
  for (const auto& r : rows) {
    const WorkloadName n = split(r.workload);
    if (n.boolean || r.method != "ours-double") continue;
    const GjkRow* peer = bestPeerRow(rows, r.workload);
    const int curved = isCurved(n.shape);
    if (peer) (n.warm ? warm : cold)[curved].push_back(r.medianNs / peer->medianNs);
    errorMax[curved].push_back(r.errorMax);
  }
  md << "\n<br>Ours in double against the fastest peer: on boxes and polytopes " << rangeText("%.2f", cold[0]) << " of its time cold and "
     << rangeText("%.2f", warm[0]) << " warm, with a largest error of " << rangeText("%.1e", {*std::max_element(errorMax[0].begin(), errorMax[0].end())})
     << "; on spheres and capsules " << rangeText("%.2f", cold[1]) << " cold and " << rangeText("%.2f", warm[1])
     << " warm, with a largest error of " << rangeText("%.1e", {*std::max_element(errorMax[1].begin(), errorMax[1].end())}) << ".\n\n";
  // Per method: its times and errors over all distance workloads, and where its largest error was.
  md << "| method | median ns, over the workloads | median error, over the workloads | largest error | where |\n";
  md << "| --- | ---: | ---: | ---: | --- |\n";
  std::vector<std::string> methods;
  for (const auto& r : rows)
    if (!split(r.workload).boolean && std::find(methods.begin(), methods.end(), r.method) == methods.end()) methods.push_back(r.method);
  for (const auto& m : methods) {
    std::vector<double> ns, medians;
    const GjkRow* worst = nullptr;
    for (const auto& r : rows) {
      if (r.method != m || split(r.workload).boolean) continue;
      ns.push_back(r.medianNs);
      medians.push_back(r.errorMedian);
      if (!worst || r.errorMax > worst->errorMax) worst = &r;
    }
    const WorkloadName n = split(worst->workload);
    md << "| " << m << " | " << rangeText("%.0f", ns) << " | " << rangeText("%.1e", medians) << " | " << format("%.1e", worst->errorMax)
       << " | " << n.shape << (n.warm ? ", warm" : ", cold") << " |\n";
  }
  chapter::markdownNotes(md, "Computed by `gjk_study` (also with `--replot`) from the `gjk-distance-*.csv` files of the run in the GJK table. "
              "*ours / peer*: ours-double's median time divided by the fastest peer's (below 1: faster). Errors: `|d - d_ref|`.");
}

/// gjk-boolean-summary.md: the boolean queries' key figures.
inline void writeBooleanSummary(const std::string& path, const std::vector<GjkRow>& rows) {
  std::ofstream md(path);
  chapter::markdownTitle(md, true, "GJK boolean queries: key figures");
  writeSpeedTable(md, rows, true);
  int oursWrong = 0, oursFailed = 0, oursJudged = 0, peersWrong = 0;
  std::string peerCases;
  for (const auto& r : rows) {
    const WorkloadName n = split(r.workload);
    if (!n.boolean) continue;
    if (r.ours) {
      oursWrong += r.wrong;
      oursFailed += r.failures;
      oursJudged += r.judged;
    } else if (r.wrong + r.failures > 0) {
      peersWrong += r.wrong;
      peerCases += (peerCases.empty() ? "" : "; ") + r.method + " on " + n.shape + (n.warm ? " warm" : " cold") + ": " +
                   std::to_string(r.wrong) + " wrong of " + std::to_string(r.judged) + " judged" +
                   (r.failures ? ", " + std::to_string(r.failures) + " unanswered" : "");
    }
  }
  md << "\n<br>Ours, every scalar and workload: " << oursWrong << " wrong answers of " << oursJudged << " judged queries, " << oursFailed
     << " unanswered. The peers: " << peersWrong << (peersWrong == 1 ? " wrong answer" : " wrong answers") << (peerCases.empty() ? "" : " (" + peerCases + ")") << ".\n";
  chapter::markdownNotes(md, "Computed by `gjk_study` (also with `--replot`) from the `gjk-boolean-*.csv` files of the run in the GJK table. "
              "*ours / peer*: ours-double's median time divided by the fastest peer's (below 1: faster).");
}

/// gjk-float-summary.md: ours in float against ours in double, in one sentence.
inline void writeFloatSummary(const std::string& path, const std::vector<GjkRow>& rows) {
  std::vector<double> medians, maxima, timeRatio;
  int wrongFloat = 0, wrongDouble = 0, failedFloat = 0;
  for (const auto& p : scalarPairs(rows)) {
    if (!p.d || !p.f) continue;
    timeRatio.push_back(p.f->medianNs / p.d->medianNs);
    if (split(p.workload).boolean) {
      wrongFloat += p.f->wrong;
      wrongDouble += p.d->wrong;
    } else {
      medians.push_back(p.f->errorMedian);
      maxima.push_back(p.f->errorMax);
    }
    failedFloat += p.f->failures;
  }
  std::ofstream md(path);
  md << "GJK in float, over every distance workload: median errors " << rangeText("%.1e", medians) << ", largest error "
     << rangeText("%.1e", {maxima.empty() ? 0.0 : *std::max_element(maxima.begin(), maxima.end())}) << "; boolean answers: " << wrongFloat
     << " wrong in float, " << wrongDouble << " in double; " << failedFloat
     << " queries ended without an answer in float; its median time is " << rangeText("%.2f", timeRatio)
     << " times that of double (computed by `gjk_study` from the `gjk-*.csv` files).\n";
}

/// gjk-goals.md: the study's speed goals for GJK, each against this run: ours-double's
/// median time, the method the goal names, their ratio or the bound, and whether it is met.
inline void writeGoals(const std::string& path, const std::vector<GjkRow>& rows) {
  std::ofstream md(path);
  chapter::markdownTitle(md, true, "GJK: the speed goals against this run");
  md << "| goal | workload | ours-double ns | against, ns | ours / against | met |\n";
  md << "| --- | --- | ---: | --- | ---: | :---: |\n";
  int met = 0, goals = 0;
  auto row = [&](const std::string& goal, const std::string& workload, const GjkRow& ours, const std::string& against, double againstNs,
                 bool ok) {
    ++goals;
    met += ok;
    md << "| " << goal << " | " << workload << " | " << format("%.0f", ours.medianNs) << " | " << against << format(" %.0f", againstNs)
       << " | " << format("%.2f", ours.medianNs / againstNs) << " | " << (ok ? "yes" : "**no**") << " |\n";
  };
  // Warm boolean queries on 100-vertex polytopes under 50 ns.
  const std::string warm100 = workloadName(true, "polytope100", true);
  if (const GjkRow* ours = rowOf(rows, warm100, "ours-double"))
    row("warm boolean, 100-vertex polytopes, under 50 ns", warm100, *ours, "the bound", 50, ours->medianNs < 50);
  // Spheres and capsules within 1.5 times FCL's closed forms (its faster solver's row).
  for (const char* shape : {"sphere", "capsule"})
    for (const bool boolean : {false, true})
      for (const bool warm : {false, true}) {
        const std::string w = workloadName(boolean, shape, warm);
        const GjkRow* ours = rowOf(rows, w, "ours-double");
        const GjkRow* fcl = nullptr;
        for (const char* m : {"fcl-libccd", "fcl-indep"})
          if (const GjkRow* r = rowOf(rows, w, m); r && (!fcl || r->medianNs < fcl->medianNs)) fcl = r;
        if (!ours || !fcl) continue;
        const double ratio = ours->medianNs / fcl->medianNs;
        row("spheres and capsules within 1.5 times FCL's closed forms", w, *ours, fcl->method, fcl->medianNs, ratio <= 1.5);
      }
  // Cold boolean queries on boxes and 12-vertex polytopes at or below libccd's MPR.
  for (const char* shape : {"box", "polytope12"}) {
    const std::string w = workloadName(true, shape, false);
    const GjkRow* ours = rowOf(rows, w, "ours-double");
    const GjkRow* mpr = rowOf(rows, w, "ccd-mpr");
    if (!ours || !mpr) continue;
    const double ratio = ours->medianNs / mpr->medianNs;
    row("cold boolean at or below libccd's MPR", w, *ours, mpr->method, mpr->medianNs, ratio <= 1);
  }
  md << "\n<br>" << met << " of " << goals << " met in this run.\n";
  chapter::markdownNotes(md, "Computed by `gjk_study` (also with `--replot`) from the `gjk-*.csv` files of the run in the GJK table. "
              "Median times per query; *ours / against*: ours-double's divided by the method's the goal names (for the 50 ns goal, by 50 ns).");
}

inline void writeSummaries(const std::string& folder, const std::vector<GjkRow>& rows) {
  writeDistanceSummary(folder + "/gjk-distance-summary.md", rows);
  writeBooleanSummary(folder + "/gjk-boolean-summary.md", rows);
  writeFloatSummary(folder + "/gjk-float-summary.md", rows);
  writeGoals(folder + "/gjk-goals.md", rows);
  std::printf("wrote %s/gjk-distance-summary.md, gjk-boolean-summary.md, gjk-float-summary.md and gjk-goals.md\n", folder.c_str());
}

}  // namespace gjk_study
