// The time-of-impact study's plots (chapter 09): per workload, toi-<workload>.csv (the
// plotted values) and the gnuplot script toi-<workload>.gp written for that data, then
// gnuplot run on it: the error of the time of impact against the time per query, one
// curve per method, with the share of the reference's hits each setting missed below.
#pragma once

#include "../command_line.hpp"
#include "toi_comparisons.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <string>
#include <vector>

namespace toi_study {

using namespace gjkx::study;
using chapter::formatOrDash;

inline std::string curveName(const ToiRow& r) { return r.family + " " + r.scalar; }

/// The key of a curve: its name and its misses (and false alarms), never hidden.
inline std::string keyText(const std::vector<const ToiRow*>& rows) {
  std::set<int> missCounts, alarmCounts;
  for (const auto* r : rows) {
    missCounts.insert(r->misses);
    alarmCounts.insert(r->falseAlarms);
  }
  auto counts = [&](const std::set<int>& set, auto member, const char* what) {
    if (set.size() == 1) return std::to_string(*set.begin()) + " " + what;
    std::string s = std::string(what) + " ";
    for (std::size_t k = 0; k < rows.size(); ++k) s += (k ? "/" : "") + std::to_string(rows[k]->*member);
    s += " at ";
    for (std::size_t k = 0; k < rows.size(); ++k) s += (k ? "/" : "") + rows[k]->setting;
    return s;
  };
  std::string text = curveName(*rows.front()) + " (" + counts(missCounts, &ToiRow::misses, "misses");
  if (!(alarmCounts.size() == 1 && *alarmCounts.begin() == 0)) text += ", " + counts(alarmCounts, &ToiRow::falseAlarms, "false alarms");
  return text + ")";
}

/// How a method family looks on every plot of the study: its own colour and marker (filled
/// for the first six, open for the rest; never a cross, which marks misses). Float curves
/// are dashed.
struct FamilyStyle {
  const char* colour;
  int point;
};
inline FamilyStyle familyStyle(const std::string& family) {
  static const std::map<std::string, FamilyStyle> styles = {
      {"ours", {"#d62728", 7}},       {"certified", {"#9467bd", 5}}, {"static", {"#1f77b4", 9}},    {"swept", {"#ff7f0e", 11}},
      {"CA", {"#2ca02c", 13}},        {"FCL naive", {"#8c564b", 15}}, {"FCL CA", {"#e377c2", 6}},    {"FCL CA indep", {"#555555", 8}},
      {"Bullet", {"#a6a600", 12}},    {"Box2D", {"#17becf", 4}}};
  const auto it = styles.find(family);
  return it == styles.end() ? FamilyStyle{"#000000", 10} : it->second;
}

/// Writes toi-<workload>.csv from the rows of one workload.
inline void writeWorkloadCsv(const std::string& base, const std::vector<std::string>& curves,
                      std::map<std::string, std::vector<const ToiRow*>>& byCurve) {
  std::ofstream csv(base + ".csv");
  csv << "curve,method,setting,scalar,median_us,p99_us,error_median,error_max,misses,ref_hits,false_alarms,clear_misses,plotted_error,"
         "point_label,queries\n";
  for (std::size_t k = 0; k < curves.size(); ++k)
    for (const auto* r : byCurve[curves[k]]) {
      // Detection-only methods have no time of impact: plotted at error 1 (the whole interval).
      const double y = r->detectionOnly ? 1.0 : (std::isnan(r->errMedian) ? std::nan("") : std::max(r->errMedian, 1e-17));
      // Points labelled with their setting: ours in double, and the peers' settings.
      const bool labelled = (r->family == "ours" && r->scalar == "double") || (!r->ours && r->setting != "-");
      char line[512];
      std::snprintf(line, sizeof line, "%zu,%s,%s,%s,%.6g,%.6g,%.6g,%.6g,%d,%d,%d,%d,%.4g,%s,%d\n", k, r->family.c_str(), r->setting.c_str(),
                    r->scalar.c_str(), r->medianUs, r->p99Us, r->errMedian, r->errMax, r->misses, r->refHits, r->falseAlarms,
                    r->clearMisses, y, labelled ? r->setting.c_str() : "", r->queries);
      csv << line;
    }
}

/// The plot of one workload, in two panels on one time axis, with the key to their right:
/// above, the median error of the time of impact against the median time per query (both
/// log), one curve per method joined across its settings, and a black cross over every
/// setting that missed a collision the reference found; below, the share of the
/// reference's hits each setting missed, so that a method that misses sits visibly high.
inline void writeWorkloadPlot(const std::string& base, const std::string& workload, int queries, const std::vector<std::string>& curves,
                       std::map<std::string, std::vector<const ToiRow*>>& byCurve) {
  const std::string csvName = std::filesystem::path(base + ".csv").filename().string();
  double xLo = 1e300, xHi = 0, yLo = 1, missTop = 0;
  int refHits = 0, clearMisses = 0;
  for (const auto& c : curves)
    for (const auto* r : byCurve[c]) {
      xLo = std::min(xLo, r->medianUs);
      xHi = std::max(xHi, r->medianUs);
      if (!r->detectionOnly && !std::isnan(r->errMedian)) yLo = std::min(yLo, std::max(r->errMedian, 1e-17));
      if (r->refHits) missTop = std::max(missTop, 100.0 * r->misses / r->refHits);
      refHits = r->refHits;
      clearMisses = r->clearMisses;
    }
  xLo /= 1.5;
  xHi *= 1.5;
  missTop = missTop > 0 ? std::min(100.0, std::ceil(missTop * 1.25 / 10) * 10) : 10;
  const double yBottom = std::pow(10.0, std::floor(std::log10(yLo)) - 1);
  std::ofstream gp(base + ".gp");
  gp << "# gnuplot script written by toi_study (chapter 09): gnuplot " << std::filesystem::path(base + ".gp").filename().string() << "\n";
  gp << chapter::gnuplotTerminal(1300, 900, "sans,10");
  gp << "set output '" << std::filesystem::path(base + "." + chapter::figureFormat()).filename().string() << "'\n";
  gp << "set datafile separator ','\nset termoption noenhanced\n";
  gp << "set multiplot title \"time of impact, workload " << workload << " (" << queries << " queries: " << refHits
     << " hits and " << clearMisses << " clear misses by the reference)\"\n";
  gp << "set lmargin at screen 0.08\nset rmargin at screen 0.66\n";
  gp << "set logscale x\nset xrange [" << xLo << ":" << xHi << "]\nset grid\n";
  // The error panel.
  gp << "set tmargin at screen 0.93\nset bmargin at screen 0.33\n";
  gp << "set logscale y\nset yrange [" << yBottom << ":5]\nset format y '%.0e'\nset format x ''\nunset xlabel\n";
  gp << "set ylabel 'median |t - t_ref|, in units of the interval [t_0, t_1]'\n";
  gp << "set label 1 'yes/no only: plotted at error 1' at graph 0.01, first 1.6 left font ',8' tc rgb '#777777'\n";
  gp << "set key at screen 0.675,0.93 left top Left reverse width -4 samplen 3 spacing 1.15 font ',9'\n";
  gp << "plot ";
  for (std::size_t k = 0; k < curves.size(); ++k) {
    const ToiRow& first = *byCurve[curves[k]].front();
    const FamilyStyle st = familyStyle(first.family);
    gp << (k ? ", \\\n     " : "") << "'" << csvName << "' skip 1 using ($1==" << k << " ? $5 : NaN):13 with linespoints lw 2 pt "
       << st.point << " ps 1.3 lc rgb '" << st.colour << "' dt " << (first.scalar == "float" ? 2 : 1) << " title \""
       << keyText(byCurve[curves[k]]) << "\"";
  }
  // A black cross over every setting that missed a hit; the settings' names beside the points.
  gp << ", \\\n     '" << csvName << "' skip 1 using ($9 > 0 ? $5 : NaN):13 with points pt 2 ps 2.2 lw 2.5 lc rgb '#000000'"
     << " title \"X: missed some of the reference's hits\"";
  gp << ", \\\n     '" << csvName << "' skip 1 using 5:13:14 with labels font ',7' offset 0,0.9 notitle\n";
  // The miss strip, on the same time axis.
  gp << "unset label 1\nunset key\n";
  gp << "set tmargin at screen 0.30\nset bmargin at screen 0.09\n";
  gp << "unset logscale y\nset yrange [-" << missTop * 0.08 << ":" << missTop << "]\nset format y '%g%%'\nset ytics " << missTop / 2
     << "\nset format x '%g'\n";
  gp << "set xlabel 'median time per query (microseconds)'\nset ylabel \"missed hits (%)\"\n";
  gp << "plot ";
  for (std::size_t k = 0; k < curves.size(); ++k) {
    const ToiRow& first = *byCurve[curves[k]].front();
    const FamilyStyle st = familyStyle(first.family);
    gp << (k ? ", \\\n     " : "") << "'" << csvName << "' skip 1 using ($1==" << k << " ? $5 : NaN):($10 > 0 ? 100.0*$9/$10 : NaN) with points pt "
       << st.point << " ps 1.3 lw 1.5 lc rgb '" << st.colour << "' notitle";
  }
  gp << ", \\\n     '" << csvName << "' skip 1 using ($9 > 0 ? $5 : NaN):(100.0*$9/$10) with points pt 2 ps 2.2 lw 2.5 lc rgb '#000000' notitle";
  gp << "\n";
  gp << "unset multiplot\n";
}

/// One workload's CSV, plot script and (with gnuplot) PNG.
inline void plotWorkload(const std::string& folder, const std::string& workload, int queries, const std::vector<ToiRow>& rows, bool writeCsv,
                  bool haveGnuplot) {
  std::vector<std::string> curves;
  std::map<std::string, std::vector<const ToiRow*>> byCurve;
  for (const auto& r : rows) {
    if (r.workload != workload) continue;
    const std::string c = curveName(r);
    if (!byCurve.count(c)) curves.push_back(c);
    byCurve[c].push_back(&r);
  }
  const std::string base = folder + "/toi-" + workload;
  if (writeCsv) writeWorkloadCsv(base, curves, byCurve);
  writeWorkloadPlot(base, workload, queries, curves, byCurve);
  if (haveGnuplot) {
    const std::string command = "cd '" + folder + "' && gnuplot 'toi-" + workload + ".gp'";
    if (std::system(command.c_str()) != 0) std::fprintf(stderr, "toi_study: gnuplot failed on %s.gp\n", base.c_str());
    else std::printf("wrote %s.%s\n", base.c_str(), chapter::figureFormat().c_str());
  }
}

}  // namespace toi_study
