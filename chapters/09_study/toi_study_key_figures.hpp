// The time-of-impact study's key figures (chapter 09): what the docs page quotes, computed
// from the rows (measured, or read back from the CSV files by --replot): misses and false
// alarms per method and ours against the peers in toi-summary.md, the speed goals in
// toi-goals.md.
#pragma once

#include "../formatting.hpp"
#include "toi_comparisons.hpp"

#include <algorithm>
#include <fstream>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace toi_study {

using namespace gjkx::study;
using chapter::formatOrDash;

// ---------------------------------------------------------------------------------------
// Key figures: the numbers the docs page quotes, computed from the rows (measured or read
// back from the CSV files by --replot), so the page's text follows every rerun. Workloads
// in the order of their names, the same whichever way the rows came.

inline bool isTheSolver(const ToiRow& r) { return r.family == "ours" || r.family == "certified"; }

inline std::vector<std::string> workloadsOf(const std::vector<ToiRow>& rows) {
  std::set<std::string> names;
  for (const auto& r : rows) names.insert(r.workload);
  return {names.begin(), names.end()};
}

/// The row of ours in double at the tolerance the RATIO lines use, and FCL's conservative advancement.
inline const ToiRow* findRow(const std::vector<ToiRow>& rows, const std::string& workload, const std::string& family, const std::string& setting,
                      const std::string& scalar) {
  for (const auto& r : rows)
    if (r.workload == workload && r.family == family && (setting.empty() || r.setting == setting) && r.scalar == scalar) return &r;
  return nullptr;
}

/// "lo (workload) to hi (workload)" of a value per workload.
inline std::string rangeText(const char* f, const std::map<std::string, double>& v) {
  if (v.empty()) return "-";
  auto lo = v.begin(), hi = v.begin();
  for (auto it = v.begin(); it != v.end(); ++it) {
    if (it->second < lo->second) lo = it;
    if (it->second > hi->second) hi = it;
  }
  return formatOrDash(f, lo->second) + " (" + lo->first + ") to " + formatOrDash(f, hi->second) + " (" + hi->first + ")";
}

/// toi-summary.md: misses and false alarms of every method, and ours' speed against the peers.
inline void writeSummary(const std::string& path, const std::vector<ToiRow>& rows) {
  const std::vector<std::string> workloads = workloadsOf(rows);
  std::ofstream md(path);
  chapter::markdownTitle(md, true, "Time of impact: key figures", "");

  // Ours: every setting of the paper's variant and the certified one, both scalars.
  std::set<std::string> settings;
  int misses = 0, falseAlarms = 0, hits = 0, clear = 0;
  for (const auto& r : rows)
    if (isTheSolver(r)) {
      settings.insert(r.label());
      misses += r.misses;
      falseAlarms += r.falseAlarms;
    }
  for (const auto& w : workloads)
    for (const auto& r : rows)
      if (r.workload == w) {
        hits += r.refHits;
        clear += r.clearMisses;
        break;
      }
  md << "The paper's solver and the certified variant, " << settings.size() << " settings (tolerance and scalar) over " << workloads.size()
     << " workloads with " << hits << " reference hits and " << clear << " clear misses: " << misses << " misses and " << falseAlarms
     << " false alarms in all.\n\n";

  // Every method that missed a hit or raised a false alarm, with where.
  md << "| method | misses (workload: missed / reference hits) | false alarms (workload: raised / clear misses) |\n";
  md << "| --- | --- | --- |\n";
  std::vector<std::string> labels;
  for (const auto& r : rows)
    if (std::find(labels.begin(), labels.end(), r.label()) == labels.end()) labels.push_back(r.label());
  std::sort(labels.begin(), labels.end());
  int listed = 0;
  for (const auto& label : labels) {
    std::string missText, alarmText;
    for (const auto& w : workloads)
      for (const auto& r : rows) {
        if (r.workload != w || r.label() != label) continue;
        if (r.misses) missText += (missText.empty() ? "" : ", ") + w + ": " + std::to_string(r.misses) + " / " + std::to_string(r.refHits);
        if (r.falseAlarms)
          alarmText += (alarmText.empty() ? "" : ", ") + w + ": " + std::to_string(r.falseAlarms) + " / " + std::to_string(r.clearMisses);
      }
    if (missText.empty() && alarmText.empty()) continue;
    md << "| " << label << " | " << (missText.empty() ? "none" : missText) << " | " << (alarmText.empty() ? "none" : alarmText) << " |\n";
    ++listed;
  }
  if (listed == 0) md << "| (every method) | none | none |\n";

  // Speed: ours in double at 1e-7 against FCL's conservative advancement and the fastest peer.
  md << "\n<br>**Ours (double, tolerance 1e-7) against the peers**\n\n";
  md << "| workload | ours us | ours error median | FCL CA us | FCL CA error median | ours / FCL CA | fastest peer us | ours / fastest peer |\n";
  md << "| --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: |\n";
  std::map<std::string, double> vsCa, vsBest, vsBestElsewhere;  // elsewhere: the workloads FCL's CA does not run
  std::map<std::string, int> fastestCount;
  for (const auto& w : workloads) {
    const ToiRow* ours = findRow(rows, w, "ours", "tol=1e-7", "double");
    if (!ours) continue;
    const ToiRow* ca = findRow(rows, w, "FCL CA", "", "double");
    const ToiRow* best = nullptr;
    for (const auto& r : rows)
      if (r.workload == w && !r.ours && (!best || r.medianUs < best->medianUs)) best = &r;
    if (ca) vsCa[w] = ours->medianUs / ca->medianUs;
    if (best) {
      (ca ? vsBest : vsBestElsewhere)[w] = ours->medianUs / best->medianUs;
      ++fastestCount[best->label()];
    }
    md << "| " << w << " | " << formatOrDash("%.2f", ours->medianUs) << " | " << formatOrDash("%.1e", ours->errMedian) << " | "
       << (ca ? formatOrDash("%.2f", ca->medianUs) : "-") << " | " << (ca ? formatOrDash("%.1e", ca->errMedian) : "-") << " | "
       << (ca ? formatOrDash("%.2f", vsCa[w]) : "-") << " | " << (best ? formatOrDash("%.2f", best->medianUs) + " (" + best->label() + ")" : "-") << " | "
       << (best ? formatOrDash("%.2f", ours->medianUs / best->medianUs) : "-") << " |\n";
  }
  std::string fastest;
  for (const auto& [label, count] : fastestCount)
    fastest += (fastest.empty() ? "" : ", ") + label + " on " + std::to_string(count);
  md << "\n<br>On the workloads FCL's conservative advancement runs on, ours takes " << rangeText("%.2f", vsCa) << " of its median time and "
     << rangeText("%.2f", vsBest) << " of the fastest peer's";
  for (const auto& [w, ratio] : vsBestElsewhere) md << "; on " << w << " " << formatOrDash("%.2f", ratio) << " of the fastest peer's";
  md << " (the fastest peer: " << fastest << " of the " << workloads.size() << " workloads).\n";
  chapter::markdownNotes(md, "Computed by `toi_study` (also with `--replot`) from the `toi-<workload>.csv` files of the run in the time-of-impact table. "
              "Times: median per query (us); errors: `|t - t_ref|` in units of the interval; *ours / ...*: ratio of the median times.");
}

/// toi-goals.md: the study's speed goals for the time of impact, each against this run:
/// ours (double, tolerance 1e-7) against the method the goal names, by median time, with
/// both errors where the goal asks for equal or lower error.
inline void writeGoals(const std::string& path, const std::vector<ToiRow>& rows) {
  std::ofstream md(path);
  chapter::markdownTitle(md, true, "Time of impact: the speed goals against this run", "");
  md << "| goal | workload | ours us | against, us | ours / against | error median: ours, against | met |\n";
  md << "| --- | --- | ---: | --- | ---: | --- | :---: |\n";
  int met = 0, goals = 0;
  // One row: ours against `other`; `ok` empty for a goal with no ratio to reach.
  auto row = [&](const char* goal, const std::string& w, const ToiRow& ours, const ToiRow& other, std::optional<bool> ok) {
    if (ok) ++goals, met += *ok;
    md << "| " << goal << " | " << w << " | " << formatOrDash("%.2f", ours.medianUs) << " | " << other.label() << " " << formatOrDash("%.2f", other.medianUs)
       << " | " << formatOrDash("%.2f", ours.medianUs / other.medianUs) << " | " << formatOrDash("%.1e", ours.errMedian) << ", " << formatOrDash("%.1e", other.errMedian)
       << (other.misses ? " (" + std::to_string(other.misses) + " misses)" : "") << " | "
       << (!ok ? "(see the text)" : *ok ? "yes" : "**no**") << " |\n";
  };
  for (const auto& w : workloadsOf(rows)) {
    const ToiRow* ours = findRow(rows, w, "ours", "tol=1e-7", "double");
    if (!ours) continue;
    // At most a third of FCL's conservative advancement's time, at equal or lower error (its
    // misses count against it: its error is over the hits it found).
    if (const ToiRow* ca = findRow(rows, w, "FCL CA", "", "double")) {
      const bool error = ours->errMedian <= ca->errMedian || ca->misses > ours->misses;
      row("a third of FCL's conservative advancement, at equal or lower error", w, *ours, *ca,
          ours->medianUs / ca->medianUs <= 1.0 / 3 && error);
    }
    // At or below Bullet on ballistic and screw motion.
    if (w == "ballistic" || w.rfind("screw", 0) == 0)
      if (const ToiRow* bullet = findRow(rows, w, "Bullet", "", "float"))
        row("at or below Bullet", w, *ours, *bullet, ours->medianUs <= bullet->medianUs);
    // The planar set: no ratio to reach; the docs page says why Box2D is faster.
    if (const ToiRow* box2d = findRow(rows, w, "Box2D", "", "float"))
      row("Box2D on the planar set: say why it is faster", w, *ours, *box2d, std::nullopt);
  }
  md << "\n<br>" << met << " of " << goals << " met in this run.\n";
  chapter::markdownNotes(md, "Computed by `toi_study` (also with `--replot`) from the `toi-<workload>.csv` files of the run in the time-of-impact table. "
              "Ours: the paper's solver in double at tolerance 1e-7. Times: median per query (us); *ours / against*: their ratio; "
              "errors: median `|t - t_ref|` over the hits each reports, in units of the interval.");
}

}  // namespace toi_study
