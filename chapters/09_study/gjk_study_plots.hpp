// The GJK study's plots (chapter 09): per workload group, gjk-<group>.csv (the plotted
// values, with each label placed where it overlaps no other) and the gnuplot script
// gjk-<group>.gp written for that data, then gnuplot run on it: one panel per shape, error
// against time for distance queries, time with its 99th percentile for boolean ones.
#pragma once

#include "../command_line.hpp"
#include "../formatting.hpp"
#include "gjk_study_workloads.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <string>
#include <vector>

namespace gjk_study {

using gjkx::study::gjk_comparison::GjkRow;
using chapter::format;


/// Where an error of exactly 0 is drawn on the log axis.
constexpr double kDistanceFloor = 1e-18;
constexpr double kBooleanFloor = 1e-4;

// ---------------------------------------------------------------------------------------
// Figures: one PNG per group, one panel per shape.

struct Style {
  const char* colour;
  int point;
};
/// Ours in blues (filled: double, open: float, diamond: the paper's GJK on the curved surfaces, roundedCores = false); each peer its own colour.
inline Style styleOf(const std::string& method) {
  static const std::map<std::string, Style> styles = {
      {"ours-double", {"#08306b", 7}}, {"ours-float", {"#4292c6", 6}},   {"ours-curved", {"#17becf", 13}},
      {"ccd-gjk", {"#ff7f0e", 5}},     {"ccd-mpr", {"#8c564b", 4}},      {"fcl-libccd", {"#d62728", 9}},
      {"fcl-indep", {"#e377c2", 11}},  {"bullet-gjk", {"#2ca02c", 15}},  {"bullet-gjk-dist", {"#2ca02c", 15}}};
  const auto it = styles.find(method);
  return it == styles.end() ? Style{"#000000", 1} : it->second;
}

/// The geometry of a figure, so that the labels can be placed without overlapping: a
/// 1500 x 1000 image, 3 panels per row above a key strip, each panel's plot area at fixed
/// pixel margins inside it.
constexpr double kImageW = 1500, kImageH = 1000;
constexpr int kColumns = 3;
constexpr double kPanelsTop = 0.95, kPanelsBottom = 0.12;  // screen fractions
constexpr double kLeftPx = 70, kRightPx = 15, kBottomPx = 50, kTopPx = 28;
constexpr double kCharW = 6.0, kCharH = 12.0;  // the labels' font (sans 8), roughly

/// One method on one shape: a point of a panel, and where its label goes.
struct PlotPoint {
  const GjkRow* row;
  int panel, method;
  double x, y, yMax;
  std::string label;
  double labelX = 0, labelY = 0;
};

/// The axis ranges of a panel (data units) and its plot area in pixels.
struct PanelAxes {
  double xLo, xHi, yLo, yHi, widthPx, heightPx;
  double px(double x) const { return std::log10(x / xLo) / std::log10(xHi / xLo) * widthPx; }
  double py(double y) const { return std::log10(y / yLo) / std::log10(yHi / yLo) * heightPx; }
  double fromPx(double p) const { return xLo * std::pow(xHi / xLo, p / widthPx); }
  double fromPy(double p) const { return yLo * std::pow(yHi / yLo, p / heightPx); }
};

/// Places the labels of one panel greedily, left to right: beside the point if free, else
/// one row up or down, then two, ... (a leader line joins a moved label to its point).
inline void placeLabels(std::vector<PlotPoint*>& points, const PanelAxes& axes) {
  struct Box {
    double x0, y0, x1, y1;
    bool hits(const Box& o) const { return x0 < o.x1 && o.x0 < x1 && y0 < o.y1 && o.y0 < y1; }
  };
  std::vector<Box> taken;
  for (const auto* p : points) taken.push_back({axes.px(p->x) - 7, axes.py(p->y) - 7, axes.px(p->x) + 7, axes.py(p->y) + 7});
  std::sort(points.begin(), points.end(), [](const PlotPoint* a, const PlotPoint* b) { return a->x < b->x; });
  for (auto* p : points) {
    const double x0 = axes.px(p->x) + 9, w = kCharW * double(p->label.size()), y = axes.py(p->y);
    Box chosen{x0, y - kCharH / 2, x0 + w, y + kCharH / 2};
    for (int k = 0; k < 40; ++k) {
      const double dy = (k % 2 ? -1.0 : 1.0) * double((k + 1) / 2) * (kCharH + 2);
      const Box b{x0, y + dy - kCharH / 2, x0 + w, y + dy + kCharH / 2};
      if (b.y0 < 0 || b.y1 > axes.heightPx) continue;
      if (std::none_of(taken.begin(), taken.end(), [&](const Box& t) { return t.hits(b); })) {
        chosen = b;
        break;
      }
    }
    taken.push_back(chosen);
    p->labelX = axes.fromPx(chosen.x0);
    p->labelY = axes.fromPy((chosen.y0 + chosen.y1) / 2);
  }
}

/// Tics at 1, 2, 5 times the powers of ten inside [lo, hi] (only the powers when that is
/// too many to fit), so that a panel spanning less than a decade still has numbers on its x axis.
inline std::string xTics(double lo, double hi, bool powersOnly = false) {
  for (const bool coarse : {powersOnly, true}) {
    std::vector<double> tics;
    for (double decade = std::pow(10.0, std::floor(std::log10(lo))); decade <= hi; decade *= 10)
      for (const double m : {1.0, 2.0, 5.0})
        if ((!coarse || m == 1.0) && m * decade >= lo && m * decade <= hi) tics.push_back(m * decade);
    if (tics.size() <= 7 || coarse) {
      std::string text;
      for (const double t : tics) text += (text.empty() ? "" : ", ") + format("'%g'", t) + " " + format("%g", t);
      return text;
    }
  }
  return "";
}

/// The plot of a boolean group: a yes/no answer has no error to plot, so each panel (one
/// per shape) puts the methods one per row, the median time per query as the point and a
/// whisker out to the 99th percentile (log time axis), and at the right of each row the
/// wrong answers among the judged queries (red when any) and the queries left unanswered.
inline void writeTimePlot(const std::string& base, const std::string& name, const Group& g, const std::vector<std::string>& shapes,
                   const std::vector<std::string>& methods, std::map<std::string, int>& queries, const std::vector<PlotPoint>& points) {
  const std::string csvName = name + ".csv";
  const int panelRows = int((shapes.size() + kColumns - 1) / kColumns);
  const double panelW = kImageW / kColumns, panelH = (kPanelsTop - kPanelsBottom) * kImageH / panelRows;
  constexpr double leftPx = 110;  // room for the method names
  std::ofstream gp(base + ".gp");
  gp << "# gnuplot script written by gjk_study (chapter 09): gnuplot " << name << ".gp\n";
  gp << chapter::gnuplotTerminal(kImageW, kImageH, "sans,10");
  gp << "set output '" << name << "." << chapter::figureFormat() << "'\n";
  gp << "set datafile separator ','\nset termoption noenhanced\n";
  gp << "set multiplot title \"GJK, " << g.title
     << ": median time per query (point) and 99th percentile (whisker) per method, one panel per shape; wrong answers counted at the right\"\n";
  gp << "set logscale x\nset grid xtics\nunset key\nset xlabel 'time per query (ns)' offset 0,0.3\n";
  for (std::size_t s = 0; s < shapes.size(); ++s) {
    double lo = 0, hi = 0;
    std::string tics;
    for (const auto& p : points)
      if (p.panel == int(s)) {
        lo = lo == 0 ? p.row->medianNs : std::min(lo, p.row->medianNs);
        hi = std::max(hi, p.row->p99Ns);
        tics += (tics.empty() ? "" : ", ") + std::string("'") + p.row->method + "' " + std::to_string(p.method);
      }
    // The data take the left two thirds of the axis; the counts sit in the last third.
    const double xLo = lo / 1.4, dataHi = hi * 1.4, xHi = xLo * std::pow(dataHi / xLo, 1.5), countX = xLo * std::pow(dataHi / xLo, 1.07);
    const double left = double(s % kColumns) * panelW, bottom = (1 - kPanelsTop) * kImageH + double(s / kColumns + 1) * panelH;
    gp << "set lmargin at screen " << (left + leftPx) / kImageW << "\nset rmargin at screen " << (left + panelW - kRightPx) / kImageW << "\n";
    gp << "set bmargin at screen " << 1 - (bottom - kBottomPx) / kImageH << "\nset tmargin at screen " << 1 - (bottom - panelH + kTopPx) / kImageH
       << "\n";
    // Tics at the powers of ten only when the data span more than a decade and a half (the
    // data have two thirds of the panel's width).
    gp << "set xtics (" << (std::log10(dataHi / xLo) > 1.5 ? xTics(xLo, dataHi, true) : xTics(xLo, dataHi)) << ")\n";
    gp << "set xrange [" << xLo << ":" << xHi << "]\nset yrange [" << double(methods.size()) - 0.4 << ":-0.6]\n";
    gp << "set ytics (" << tics << ") font ',9'\n";
    gp << "set title '" << shapes[s] << " (" << queries[shapes[s]] << " queries)' offset 0,-0.6\n";
    gp << "plot ";
    const std::string inPanel = "$1==" + std::to_string(s);
    for (std::size_t m = 0; m < methods.size(); ++m) {
      const Style st = styleOf(methods[m]);
      gp << (m ? ", \\\n     " : "") << "'" << csvName << "' skip 1 using (" << inPanel << " && $3==" << m
         << " ? $6 : NaN):3:6:7 with xerrorbars pt " << st.point << " ps 1.5 lw 1.5 lc rgb '" << st.colour << "' notitle";
    }
    // The counts: wrong / judged, and the unanswered, in grey when 0 and in red otherwise.
    gp << ", \\\n     '" << csvName << "' skip 1 using (" << inPanel << " && $11==0 && $12==0 ? " << countX
       << " : NaN):3:(sprintf('%d/%d wrong', $11, $10)) with labels left font ',9' tc rgb '#777777' notitle";
    gp << ", \\\n     '" << csvName << "' skip 1 using (" << inPanel << " && ($11>0 || $12>0) ? " << countX
       << " : NaN):3:(sprintf('%d/%d wrong%s', $11, $10, $12>0 ? sprintf(', %d no answer', $12) : '')) with labels left font ',9:Bold' tc rgb "
          "'#c00000' notitle\n";
  }
  gp << "set label 1 \"Times over batches of queries timed together. Judged: the queries whose reference distance is 0 or above "
     << format("%.0e", gjkx::study::gjk_comparison::detail::kBand) << " (closer pairs are touching within the methods' tolerances).\" at screen 0.5,0.06 center font ',10'\n";
  gp << "unset border\nunset tics\nunset grid\nunset xlabel\nunset title\nunset logscale\nset xrange [0:1]\nset yrange [0:1]\nplot NaN notitle\n";
  gp << "unset multiplot\n";
}

inline void plotGroup(const std::string& folder, const Group& g, const std::vector<GjkRow>& rows, bool haveGnuplot) {
  std::vector<std::string> shapes, methods;
  std::map<std::string, int> queries;
  for (const auto& r : rows) {
    const WorkloadName n = split(r.workload);
    if (n.boolean != g.boolean || n.warm != g.warm) continue;
    if (std::find(shapes.begin(), shapes.end(), n.shape) == shapes.end()) shapes.push_back(n.shape);
    if (std::find(methods.begin(), methods.end(), r.method) == methods.end()) methods.push_back(r.method);
    queries[n.shape] = r.queries;
  }
  if (shapes.empty()) return;
  const std::string name = std::string("gjk-") + g.file;
  const std::string base = folder + "/" + name;
  const double floor = g.boolean ? kBooleanFloor : kDistanceFloor;

  std::vector<PlotPoint> points;
  for (const auto& r : rows) {
    const WorkloadName n = split(r.workload);
    if (n.boolean != g.boolean || n.warm != g.warm) continue;
    PlotPoint p{&r, int(std::find(shapes.begin(), shapes.end(), n.shape) - shapes.begin()),
                int(std::find(methods.begin(), methods.end(), r.method) - methods.begin()), r.medianNs, 0, 0, r.method};
    if (g.boolean) {
      p.y = p.yMax = std::max(r.judged ? double(r.wrong) / r.judged : 0.0, floor);
    } else {
      p.y = std::max(r.errorMedian, floor);
      p.yMax = std::max(r.errorMax, floor);
    }
    // Anything that is not a right answer is in the label (never hidden).
    if (g.boolean && r.wrong) p.label += " (" + std::to_string(r.wrong) + " wrong)";
    if (r.failures) p.label += " (" + std::to_string(r.failures) + " no answer)";
    points.push_back(p);
  }
  // Axes per panel: x over the panel's times with room on the right for the labels; y fixed
  // per group (distance: from below the floor to above the largest error; boolean: rates).
  const int panelRows = int((shapes.size() + kColumns - 1) / kColumns);
  const double panelW = kImageW / kColumns, panelH = (kPanelsTop - kPanelsBottom) * kImageH / panelRows;
  double yTop = g.boolean ? 3.0 : 10.0;
  for (const auto& p : points) yTop = std::max(yTop, p.yMax * 10);
  std::vector<PanelAxes> axes;
  for (std::size_t s = 0; s < shapes.size(); ++s) {
    double lo = 0, hi = 0, longest = 0;
    for (const auto& p : points)
      if (p.panel == int(s)) {
        lo = lo == 0 ? p.x : std::min(lo, p.x);
        hi = std::max(hi, p.x);
        longest = std::max(longest, double(p.label.size()));
      }
    PanelAxes a{0, 0, floor / 5, yTop, panelW - kLeftPx - kRightPx, panelH - kBottomPx - kTopPx};
    // The data take the left part of the width; the rest holds the longest label.
    const double decades = std::max(std::log10(hi / lo), 0.3) + 0.3;
    const double dataShare = std::max(0.4, 1.0 - (kCharW * longest + 15) / a.widthPx);
    a.xLo = lo / std::pow(10.0, 0.15);
    a.xHi = a.xLo * std::pow(10.0, decades / dataShare);
    axes.push_back(a);
    std::vector<PlotPoint*> panel;
    for (auto& p : points)
      if (p.panel == int(s)) panel.push_back(&p);
    placeLabels(panel, a);
  }

  const std::string csvName = name + ".csv";
  {
    std::ofstream csv(base + ".csv");
    csv << "panel,shape,method_index,method,warm_start,median_ns,p99_ns,error_median,error_max,judged,wrong,failures,plotted_y,plotted_y_max,"
           "label,label_x,label_y,queries\n";
    for (const auto& p : points) {
      const GjkRow& r = *p.row;
      char line[640];
      std::snprintf(line, sizeof line, "%d,%s,%d,%s,%s,%.6g,%.6g,%.6g,%.6g,%d,%d,%d,%.4g,%.4g,%s,%.5g,%.5g,%d\n", p.panel, shapes[p.panel].c_str(),
                    p.method, r.method.c_str(), r.warmStart.c_str(), r.medianNs, r.p99Ns, r.errorMedian, r.errorMax, r.judged, r.wrong, r.failures,
                    p.y, p.yMax, p.label.c_str(), p.labelX, p.labelY, r.queries);
      csv << line;
    }
  }
  if (g.boolean) {
    writeTimePlot(base, name, g, shapes, methods, queries, points);
  } else {
    std::ofstream gp(base + ".gp");
    gp << "# gnuplot script written by gjk_study (chapter 09): gnuplot " << name << ".gp\n";
    gp << chapter::gnuplotTerminal(kImageW, kImageH, "sans,10");
    gp << "set output '" << name << "." << chapter::figureFormat() << "'\n";
    gp << "set datafile separator ','\nset termoption noenhanced\n";
    gp << "set multiplot title \"GJK, " << g.title << ": " << (g.boolean ? "wrong-answer rate" : "error")
       << " against median time per query, one point per method, one panel per shape\"\n";
    gp << "set logscale xy\nset grid\nset format y '%.0e'\nunset key\n";
    gp << "set xlabel 'median time per query (ns)' offset 0,0.3\n";
    gp << "set ylabel \"|d - d_ref| (the shapes' length unit)\"\n";
    for (std::size_t s = 0; s < shapes.size(); ++s) {
      const double left = double(s % kColumns) * panelW, bottom = (1 - kPanelsTop) * kImageH + double(s / kColumns + 1) * panelH;
      // Margins in screen fractions, so the plot area is where placeLabels assumed it.
      gp << "set lmargin at screen " << (left + kLeftPx) / kImageW << "\nset rmargin at screen " << (left + panelW - kRightPx) / kImageW << "\n";
      gp << "set bmargin at screen " << 1 - (bottom - kBottomPx) / kImageH << "\nset tmargin at screen " << 1 - (bottom - panelH + kTopPx) / kImageH
         << "\n";
      gp << "set xtics (" << xTics(axes[s].xLo, axes[s].xHi) << ")\n";
      gp << "set xrange [" << axes[s].xLo << ":" << axes[s].xHi << "]\nset yrange [" << axes[s].yLo << ":" << axes[s].yHi << "]\n";
      gp << "set title '" << shapes[s] << " (" << queries[shapes[s]] << " queries)' offset 0,-0.6\n";
      gp << "plot ";
      const std::string inPanel = "$1==" + std::to_string(s);
      // Leader lines from a moved label back to its point.
      gp << "'" << csvName << "' skip 1 using (" << inPanel << " ? $6 : NaN):13:($16/1.04-$6):($17-$13) with vectors nohead lc rgb '#bbbbbb' notitle";
      for (std::size_t m = 0; m < methods.size(); ++m) {
        const Style st = styleOf(methods[m]);
        const std::string filter = "(" + inPanel + " && $3==" + std::to_string(m) + " ? $6 : NaN)";
        gp << ", \\\n     '" << csvName << "' skip 1 using " << filter << (g.boolean ? ":13 with points" : ":13:13:14 with yerrorbars") << " pt "
           << st.point << " ps 1.6 lw 1.5 lc rgb '" << st.colour << "' notitle";
        gp << ", \\\n     '" << csvName << "' skip 1 using (" << inPanel << " && $3==" << m << " ? $16 : NaN):17:15 with labels left font ',8' tc rgb '"
           << st.colour << "' notitle";
      }
      // A black cross over a method that gave no answer on some queries: its error is over the rest only.
      gp << ", \\\n     '" << csvName << "' skip 1 using (" << inPanel << " && $12 > 0 ? $6 : NaN):13 with points pt 2 ps 2.6 lw 2.5 lc rgb '#000000' notitle";
      gp << "\n";
    }
    // The key: one entry per method, and what the floor means.
    gp << "set origin 0,0\nset size 1," << kPanelsBottom << "\nset lmargin 0\nset rmargin 0\nset tmargin 0\nset bmargin 0\n"
       << "unset title\nunset logscale\nunset border\nunset tics\nunset grid\nunset xlabel\nunset ylabel\nset xrange [0:1]\nset yrange [0:1]\n";
    gp << "set key at screen 0.5," << kPanelsBottom - 0.015 << " center top horizontal maxrows 1 width 2 samplen 1 font ',10'\n";
    gp << "set label 1 \"An error of 0 is drawn at " << format("%.0e", floor)
       << "; the point is the median error over the queries, the bar reaches the maximum. A black cross and the label mark a method that gave no answer on some"
          " queries.\" at screen 0.5,0.04 center font ',10'\n";
    gp << "plot ";
    for (std::size_t m = 0; m < methods.size(); ++m) {
      const Style st = styleOf(methods[m]);
      gp << (m ? ", " : "") << "NaN with points pt " << st.point << " ps 1.6 lc rgb '" << st.colour << "' title '" << methods[m] << "'";
    }
    gp << "\nunset multiplot\n";
  }
  if (haveGnuplot) {
    const std::string command = "cd '" + folder + "' && gnuplot '" + name + ".gp'";
    if (std::system(command.c_str()) != 0) std::fprintf(stderr, "gjk_study: gnuplot failed on %s.gp\n", base.c_str());
    else std::printf("wrote %s.%s\n", base.c_str(), chapter::figureFormat().c_str());
  }
}

}  // namespace gjk_study
