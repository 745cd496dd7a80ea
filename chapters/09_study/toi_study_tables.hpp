// The time-of-impact study's tables (chapter 09): the workloads, every method on every
// workload, every method of ours in float against double, and the CCD benchmark's sample
// queries, as markdown for the docs page (toi-workloads.md, toi-table.md,
// toi-float-vs-double.md, toi-ccd.md); float against double on standard output too.
#pragma once

#include "../formatting.hpp"
#include "toi_comparisons.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <string>
#include <vector>

namespace toi_study {

using namespace gjkx::study;
using chapter::formatOrDash;

/// Every method of ours in float and in double, over all workloads together.
struct ScalarSum {
  int misses = 0, hits = 0, alarms = 0, clear = 0;
  std::vector<double> errors, times;
  double errMedian() const { return gjkx::study::detail::median(errors); }
  double errMax() const { return errors.empty() ? std::nan("") : *std::max_element(errors.begin(), errors.end()); }
  double usMedian() const { return gjkx::study::detail::median(times); }
};
struct FloatVsDouble {
  std::vector<std::string> order;                                // "family setting"
  std::map<std::string, std::map<std::string, ScalarSum>> sums;  // family+setting -> scalar -> sum
};

inline FloatVsDouble floatVsDouble(const std::vector<ToiRow>& rows) {
  FloatVsDouble t;
  for (const auto& r : rows) {
    if (!r.ours) continue;
    const std::string key = r.family + " " + r.setting;
    if (!t.sums.count(key)) t.order.push_back(key);
    ScalarSum& s = t.sums[key][r.scalar];
    s.misses += r.misses;
    s.hits += r.refHits;
    s.alarms += r.falseAlarms;
    s.clear += r.clearMisses;
    s.errors.insert(s.errors.end(), r.errors.begin(), r.errors.end());
    s.times.push_back(r.medianUs);
  }
  return t;
}

inline void printFloatVsDouble(const std::vector<ToiRow>& rows) {
  FloatVsDouble t = floatVsDouble(rows);
  std::printf("\n== Float against double, every method of ours (all workloads together) ==\n");
  std::printf("%-22s | %-48s | %-48s\n", "method setting", "double: misses  f.alarms  err_med  err_max  us", "float: misses  f.alarms  err_med  err_max  us");
  for (const auto& key : t.order) {
    auto cell = [&](const std::string& scalar) {
      if (!t.sums[key].count(scalar)) return std::string("(not run)");
      const ScalarSum& s = t.sums[key][scalar];
      char text[160];
      std::snprintf(text, sizeof text, "%4d/%-4d %3d/%-4d %8.1e %8.1e %7.2f", s.misses, s.hits, s.alarms, s.clear, s.errMedian(), s.errMax(),
                    s.usMedian());
      return std::string(text);
    };
    std::printf("%-22s | %-48s | %-48s\n", key.c_str(), cell("double").c_str(), cell("float").c_str());
  }
}

inline void writeFloatVsDouble(const std::string& path, const std::string& provenance, const std::vector<ToiRow>& rows) {
  FloatVsDouble t = floatVsDouble(rows);
  std::ofstream md(path);
  const std::string notes = provenance + " Every method of ours in double and in float, all workloads together: misses / reference hits, "
      + "false alarms / clear misses, the time-of-impact error `|t - t_ref|` (median and maximum over the hits both report) and "
      + "the median over the workloads of the median time per query (us).";
  md << "| method | setting | misses, double | misses, float | false alarms, double | false alarms, float | error median, double | "
        "error median, float | error max, double | error max, float | us double | us float |\n";
  md << "| --- | --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |\n";
  for (const auto& key : t.order) {
    const auto space = key.find(' ');
    md << "| " << key.substr(0, space) << " | " << key.substr(space + 1) << " | ";
    const bool both = t.sums[key].count("double") && t.sums[key].count("float");
    const ScalarSum none;
    const ScalarSum& d = t.sums[key].count("double") ? t.sums[key]["double"] : none;
    const ScalarSum& f = t.sums[key].count("float") ? t.sums[key]["float"] : none;
    auto ratio = [](int a, int b) { return std::to_string(a) + " / " + std::to_string(b); };
    md << ratio(d.misses, d.hits) << " | " << (both ? ratio(f.misses, f.hits) : "(not run)") << " | " << ratio(d.alarms, d.clear) << " | "
       << (both ? ratio(f.alarms, f.clear) : "(not run)") << " | " << formatOrDash("%.1e", d.errMedian()) << " | " << formatOrDash("%.1e", f.errMedian()) << " | "
       << formatOrDash("%.1e", d.errMax()) << " | " << formatOrDash("%.1e", f.errMax()) << " | " << formatOrDash("%.2f", d.usMedian()) << " | " << formatOrDash("%.2f", f.usMedian())
       << " |\n";
  }
  chapter::markdownNotes(md, notes);
}

/// The main table: one block per workload, every method and setting.
inline void writeMainTable(const std::string& path, const std::string& provenance, const ToiStudyResults& results) {
  std::ofstream md(path);
  const std::string notes = provenance + " Per workload and method: median and 99th-percentile time per query (us), misses / reference hits, "
      + "false alarms / clear misses (queries the reference calls in between are not judged), the time-of-impact error "
      + "`|t - t_ref|` over the hits both report (median, maximum; - when there are none or the method reports no time), and, for "
      + "ours, the GJK runs per query.";
  for (const auto& w : results.workloads) {
    chapter::markdownTitle(md, &w == &results.workloads.front(), "Time of impact, workload " + w.name,
            " (" + std::to_string(w.queries.size()) + " queries): " + chapter::markdownCell(w.description));
    md << "| method | setting | scalar | median us | p99 us | misses | false alarms | error median | error max | GJK runs |\n";
    md << "| --- | --- | --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: |\n";
    for (const auto& r : results.rows) {
      if (r.workload != w.name) continue;
      const bool highlight = r.family == "ours" && r.setting == "tol=1e-7" && r.scalar == "double";
      md << "| " << (highlight ? "**" + r.family + "**" : r.family) << " | " << r.setting << " | " << r.scalar << " | " << formatOrDash("%.2f", r.medianUs)
         << " | " << formatOrDash("%.2f", r.p99Us) << " | " << r.misses << " / " << r.refHits << " | " << r.falseAlarms << " / " << r.clearMisses << " | "
         << (r.detectionOnly ? "(yes/no)" : formatOrDash("%.1e", r.errMedian)) << " | " << (r.detectionOnly ? "(yes/no)" : formatOrDash("%.1e", r.errMax)) << " | "
         << (r.ours ? formatOrDash("%.1f", r.meanGjkRuns) : "-") << " |\n";
    }
  }
  chapter::markdownNotes(md, notes);
}

inline void writeWorkloads(const std::string& path, const std::string& provenance, const ToiStudyResults& results) {
  std::ofstream md(path);
  const std::string notes = provenance + " The time-of-impact workloads and their reference: long-double distance, Lipschitz-certified dense sampling, "
      + "bisection to 1e-13. Queries the reference finds neither hit nor clear miss are not judged.";
  md << "| workload | queries | reference hits | clear misses | not judged | what it is |\n| --- | ---: | ---: | ---: | ---: | --- |\n";
  for (const auto& w : results.workloads) {
    int hits = 0, clear = 0;
    for (const auto& q : w.queries) {
      hits += q.refHit;
      clear += q.clearMiss;
    }
    md << "| " << w.name << " | " << w.queries.size() << " | " << hits << " | " << clear << " | " << int(w.queries.size()) - hits - clear << " | "
       << chapter::markdownCell(w.description) << " |\n";
  }
  chapter::markdownNotes(md, notes);
}

inline void writeCcd(const std::string& path, const std::string& provenance, const ToiStudyResults& results) {
  std::ofstream md(path);
  const std::string notes = provenance + " The sample queries of the external CCD benchmark, ours in double (the paper's variant) at four collision "
      + "tolerances: false negatives (fn: the benchmark says they collide, we say no), false positives (fp), queries that "
      + "ended at the iteration cap, and the time per query.";
  if (results.ccd.empty()) {
    md << "Not run: " << results.ccdNote << "\n";
    chapter::markdownNotes(md, notes);
    return;
  }
  md << "| tolerance | queries | truth positives | our positives | fn | fp | capped | us per query |\n";
  md << "| ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |\n";
  for (const auto& c : results.ccd)
    md << "| " << formatOrDash("%.0e", c.tolerance) << " | " << c.queries << " | " << c.truthPositives << " | " << c.positives << " | " << c.fn << " | "
       << c.fp << " | " << c.capped << " | " << formatOrDash("%.3f", c.usPerQuery) << " |\n";
  chapter::markdownNotes(md, notes);
}

}  // namespace toi_study
