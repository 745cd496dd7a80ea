// The GJK study's tables (chapter 09): every method on every workload, and ours in float
// against ours in double, as markdown for the docs page (gjk-table.md,
// gjk-float-vs-double.md) and the latter on standard output.
#pragma once

#include "../formatting.hpp"
#include "gjk_study_workloads.hpp"

#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

namespace gjk_study {

using gjkx::study::gjk_comparison::GjkRow;
using chapter::format;

/// Failures of ours, by status: "0", or e.g. "3 (cap 2, numerical 1)".
inline std::string failureText(const GjkRow& r) {
  if (r.failures == 0) return "0";
  std::string s = std::to_string(r.failures);
  if (r.ours) {
    s += " (cap " + std::to_string(r.iterationCap) + ", numerical " + std::to_string(r.numericalFailure);
    if (r.otherFailure) s += ", other " + std::to_string(r.otherFailure);
    s += ")";
  }
  return s;
}

// ---------------------------------------------------------------------------------------
// Markdown tables. The docs page includes these files with Doxygen's \includedoc, which
// joins an included file into one paragraph: so each file starts with a bold title, puts a
// line break before every later title, and ends with its notes (command, run, date, what
// the columns mean), which then read as a caption under the tables.


inline void writeMainTable(const std::string& path, const std::string& provenance, const std::vector<GjkRow>& rows) {
  std::ofstream md(path);
  const std::string notes = provenance + " Time: median and 99th percentile per query (ns), over batches of 16 queries timed together. "
      + "*vs best peer*: this row's median time divided by the fastest peer's on the same workload (below 1: faster than every peer). "
      + "Distance error: `|d - d_ref|` against the exact long-double reference (an overlap counts as distance 0). "
      + "Boolean: wrong answers / judged queries (pairs closer than 5e-4 but apart are not judged). "
      + "*failures*: queries without an answer.";
  for (const Group& g : kGroups) {
    chapter::markdownTitle(md, &g == &kGroups[0], std::string("GJK, ") + g.title);
    if (g.boolean) {
      md << "| shape | method | warm start | median ns | p99 ns | wrong / judged | failures | vs best peer |\n";
      md << "| --- | --- | --- | ---: | ---: | ---: | ---: | ---: |\n";
    } else {
      md << "| shape | method | warm start | median ns | p99 ns | error median | error max | failures | vs best peer |\n";
      md << "| --- | --- | --- | ---: | ---: | ---: | ---: | ---: | ---: |\n";
    }
    for (const auto& r : rows) {
      const WorkloadName n = split(r.workload);
      if (n.boolean != g.boolean || n.warm != g.warm) continue;
      const double best = bestPeerNs(rows, r.workload);
      md << "| " << n.shape << " (" << r.queries << ") | " << (r.method == "ours-double" ? "**ours-double**" : r.method) << " | "
         << r.warmStart << " | " << format("%.1f", r.medianNs) << " | " << format("%.1f", r.p99Ns) << " | ";
      if (g.boolean) md << r.wrong << " / " << r.judged << " | ";
      else md << format("%.1e", r.errorMedian) << " | " << format("%.1e", r.errorMax) << " | ";
      md << failureText(r) << " | " << (best > 0 ? format("%.2f", r.medianNs / best) : std::string("-")) << " |\n";
    }
  }
  chapter::markdownNotes(md, notes);
}

inline void writeFloatVsDouble(const std::string& path, const std::string& provenance, const std::vector<GjkRow>& rows) {
  std::ofstream md(path);
  const std::string notes = provenance + " Ours in double (`ours-double`) against the same code in float (`ours-float`), same shapes and poses "
      + "(rounded to float), same default settings. *cap / num.*: queries that ended in GjkStatus::IterationCap / "
      + "GjkStatus::NumericalFailure (for boolean queries the matching IntersectionStatus), counted in an untimed pass. "
      + "*float/double*: ratio of the median times.";
  for (const bool boolean : {false, true}) {
    chapter::markdownTitle(md, !boolean, std::string("GJK ") + (boolean ? "boolean" : "distance") + " queries: float against double");
    if (boolean) {
      md << "| workload | wrong / judged, double | wrong / judged, float | cap / num., double | cap / num., float | ns double | ns float "
            "| float/double |\n| --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: |\n";
    } else {
      md << "| workload | error median, double | error max, double | error median, float | error max, float | cap / num., double | cap / "
            "num., float | ns double | ns float | float/double |\n| --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |\n";
    }
    for (const auto& p : scalarPairs(rows)) {
      if (!p.d || !p.f || split(p.workload).boolean != boolean) continue;
      md << "| " << p.workload.substr(4) << " | ";
      if (boolean) {
        md << p.d->wrong << " / " << p.d->judged << " | " << p.f->wrong << " / " << p.f->judged << " | ";
      } else {
        md << format("%.1e", p.d->errorMedian) << " | " << format("%.1e", p.d->errorMax) << " | " << format("%.1e", p.f->errorMedian) << " | "
           << format("%.1e", p.f->errorMax) << " | ";
      }
      md << statusCounts(*p.d) << " | " << statusCounts(*p.f) << " | " << format("%.1f", p.d->medianNs) << " | "
         << format("%.1f", p.f->medianNs) << " | " << format("%.2f", p.f->medianNs / p.d->medianNs) << " |\n";
    }
  }
  chapter::markdownNotes(md, notes);
}

inline void printFloatVsDouble(const std::vector<GjkRow>& rows) {
  std::printf("\n== Float against double, ours (cap/num: iteration cap / numerical failure statuses) ==\n");
  std::printf("%-28s | %-44s | %-44s | %s\n", "workload", "double: error med / max (wrong/judged)  cap/num  ns",
              "float: error med / max (wrong/judged)  cap/num  ns", "float/double time");
  for (const auto& p : scalarPairs(rows)) {
    if (!p.d || !p.f) continue;
    const bool boolean = split(p.workload).boolean;
    auto cell = [&](const GjkRow& r) {
      char s[128];
      if (boolean)
        std::snprintf(s, sizeof s, "%8d/%-8d  %18s %3d/%-3d %8.1f", r.wrong, r.judged, "", r.iterationCap, r.numericalFailure, r.medianNs);
      else
        std::snprintf(s, sizeof s, "%8.1e / %8.1e  %17s %3d/%-3d %8.1f", r.errorMedian, r.errorMax, "", r.iterationCap, r.numericalFailure,
                      r.medianNs);
      return std::string(s);
    };
    std::printf("%-28s | %-44s | %-44s | %.2f\n", p.workload.substr(4).c_str(), cell(*p.d).c_str(), cell(*p.f).c_str(),
                p.f->medianNs / p.d->medianNs);
  }
}

}  // namespace gjk_study
