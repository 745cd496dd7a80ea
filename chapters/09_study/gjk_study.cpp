// The GJK comparison of the study (chapter 09): ours against libccd, FCL and Bullet on
// distance and boolean queries, cold and warm-started, with the disagreement against an
// exact reference. Prints one table per workload, float against double for ours, and ends
// with the RATIO lines (ours-double median time / the best peer's, measured in this run).
//
//   gjk_study [--out DIR] [--quick] [--seed N]
//   gjk_study --replot [--out DIR]
//
// Writes into DIR (default figures/study):
// - gjk-table.md, gjk-float-vs-double.md: the tables of stdout as markdown (the docs page
//   of the study includes them);
// - per workload group (distance cold, distance warm, boolean cold, boolean warm):
//   gjk-<group>.csv and .gp, and gjk-<group>.png when gnuplot is installed: one panel per
//   shape. Distance queries: error (log) against median time per query (log), one point
//   per method, the median error |d - d_ref| with a bar to the maximum (an error of 0
//   cannot sit on a log axis: it is drawn at a floor, which the figure states), a cross
//   over a method that left queries unanswered. Boolean queries (a yes/no answer has no
//   error): one row per method, the median time per query with a whisker to the 99th
//   percentile, the wrong answers and unanswered queries counted beside it.
// - gjk-distance-summary.md, gjk-boolean-summary.md, gjk-float-summary.md: the key figures
//   the docs page quotes (ratios to the fastest peer, largest errors, wrong answers);
// - gjk-goals.md: the study's speed goals for GJK, each with this run's figure and whether
//   it is met.
// --replot measures nothing, redraws the plots from the CSV files already in DIR and
// writes the key figures again from them.
// A full run takes about 25 s of processor time (51 s of wall time on the shared 2-core
// machine at half a core), --quick a few seconds. Regenerate the kept figures with
// `build/chapters/09_study/gjk_study --out figures/study`.
//
// What each column means, and how the shapes, poses and references are made:
// gjk_comparisons.hpp; how each peer is called (margins, warm starts): gjkx/study/peers.hpp.
#include "../command_line.hpp"
#include "gjk_comparisons.hpp"

#include <gjkx/study/peers.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

using gjkx::study::gjk_comparison::GjkRow;
namespace peers = gjkx::study::peers;

namespace {

struct Options {
  std::string out = "figures/study";
  bool replot = false;
  gjkx::study::gjk_comparison::GjkStudyOptions study;
};

Options parse(int argc, char** argv) {
  Options o;
  CLI::App app{"The GJK study: tables on stdout, markdown tables and plots in DIR."};
  app.add_option("--out", o.out, "the folder for the plots and markdown tables")->type_name("DIR")->capture_default_str();
  app.add_flag("--quick", o.study.quick, "a short run: fewer pairs and repetitions");
  app.add_option("--seed", o.study.seed, "seed of the shapes and poses")->type_name("N")->capture_default_str();
  app.add_flag("--replot", o.replot, "measure nothing: redraw the plots and write the key figures from the gjk-<group>.csv files already in DIR");
  chapter::parseOrExit(app, argc, argv);
  return o;
}

// A workload name gjk_<distance|boolean>_<shape>[_warm], taken apart.
struct WorkloadName {
  bool boolean = false, warm = false;
  std::string shape;
};
WorkloadName split(const std::string& workload) {
  WorkloadName n;
  std::string rest = workload.substr(4);  // after "gjk_"
  n.boolean = rest.rfind("boolean_", 0) == 0;
  rest = rest.substr(n.boolean ? 8 : 9);
  n.warm = rest.size() > 5 && rest.compare(rest.size() - 5, 5, "_warm") == 0;
  n.shape = n.warm ? rest.substr(0, rest.size() - 5) : rest;
  return n;
}

// The four workload groups, in the order of the figures and tables.
struct Group {
  bool boolean, warm;
  const char* file;   // gjk-<file>.png
  const char* title;  // for titles and headings
};
constexpr Group kGroups[] = {{false, false, "distance-cold", "distance queries, cold"},
                             {false, true, "distance-warm", "distance queries, warm-started"},
                             {true, false, "boolean-cold", "boolean queries, cold"},
                             {true, true, "boolean-warm", "boolean queries, warm-started"}};

// Where an error of exactly 0 is drawn on the log axis.
constexpr double kDistanceFloor = 1e-18;
constexpr double kBooleanFloor = 1e-4;

// The fastest peer of a workload (median time), 0 when it has none.
double bestPeerNs(const std::vector<GjkRow>& rows, const std::string& workload) {
  double best = 0;
  for (const auto& r : rows)
    if (r.workload == workload && !r.ours && (best == 0 || r.medianNs < best)) best = r.medianNs;
  return best;
}

std::string format(const char* f, double x) {
  char s[64];
  std::snprintf(s, sizeof s, f, x);
  return s;
}

std::string today() {
  char s[32];
  const std::time_t now = std::time(nullptr);
  std::strftime(s, sizeof s, "%Y-%m-%d %H:%M UTC", std::gmtime(&now));
  return s;
}

std::string provenance(const Options& o) {
  return std::string("Written by `gjk_study --out ") + o.out + (o.study.quick ? " --quick" : "") +
         (o.study.seed != gjkx::study::gjk_comparison::GjkStudyOptions{}.seed ? " --seed " + std::to_string(o.study.seed) : std::string()) + "` (" +
         (o.study.quick ? "quick" : "full") + " run, seed " + std::to_string(o.study.seed) + ") on " + today() + "; " +
         peers::presentText(peers::kGjkPeers) + ".";
}

// Failures of ours, by status: "0", or e.g. "3 (cap 2, numerical 1)".
std::string failureText(const GjkRow& r) {
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

void mdTitle(std::ostream& md, bool first, const std::string& title) { md << (first ? "" : "\n<br>") << "**" << title << "**\n\n"; }
void mdNotes(std::ostream& md, const std::string& notes) { md << "\n<br>" << notes << "\n"; }

void writeMainTable(const std::string& path, const Options& o, const std::vector<GjkRow>& rows) {
  std::ofstream md(path);
  const std::string notes = provenance(o) + " Time: median and 99th percentile per query (ns), over batches of 16 queries timed together. "
      + "*vs best peer*: this row's median time divided by the fastest peer's on the same workload (below 1: faster than every peer). "
      + "Distance error: `|d - d_ref|` against the exact long-double reference (an overlap counts as distance 0). "
      + "Boolean: wrong answers / judged queries (pairs closer than 5e-4 but apart are not judged). "
      + "*failures*: queries without an answer.";
  for (const Group& g : kGroups) {
    mdTitle(md, &g == &kGroups[0], std::string("GJK, ") + g.title);
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
  mdNotes(md, notes);
}

// Ours in double against ours in float, workload by workload.
struct ScalarPair {
  std::string workload;
  const GjkRow *d = nullptr, *f = nullptr;
};

std::vector<ScalarPair> scalarPairs(const std::vector<GjkRow>& rows) {
  std::vector<ScalarPair> pairs;
  for (const auto& r : rows) {
    if (r.method != "ours-double" && r.method != "ours-float") continue;
    if (pairs.empty() || pairs.back().workload != r.workload) pairs.push_back({r.workload});
    (r.method == "ours-double" ? pairs.back().d : pairs.back().f) = &r;
  }
  return pairs;
}

std::string statusCounts(const GjkRow& r) {
  std::string s = std::to_string(r.iterationCap) + " / " + std::to_string(r.numericalFailure);
  if (r.otherFailure) s += " (+" + std::to_string(r.otherFailure) + " other)";
  return s;
}

void writeFloatVsDouble(const std::string& path, const Options& o, const std::vector<GjkRow>& rows) {
  std::ofstream md(path);
  const std::string notes = provenance(o) + " Ours in double (`ours-double`) against the same code in float (`ours-float`), same shapes and poses "
      + "(rounded to float), same default settings. *cap / num.*: queries that ended in GjkStatus::IterationCap / "
      + "GjkStatus::NumericalFailure (for boolean queries the matching IntersectionStatus), counted in an untimed pass. "
      + "*float/double*: ratio of the median times.";
  for (const bool boolean : {false, true}) {
    mdTitle(md, !boolean, std::string("GJK ") + (boolean ? "boolean" : "distance") + " queries: float against double");
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
  mdNotes(md, notes);
}

void printFloatVsDouble(const std::vector<GjkRow>& rows) {
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

// ---------------------------------------------------------------------------------------
// Figures: one PNG per group, one panel per shape.

struct Style {
  const char* colour;
  int point;
};
// Ours in blues (filled: double, open: float, diamond: the paper's GJK on the curved surfaces, roundedCores = false); each peer its own colour.
Style styleOf(const std::string& method) {
  static const std::map<std::string, Style> styles = {
      {"ours-double", {"#08306b", 7}}, {"ours-float", {"#4292c6", 6}},   {"ours-curved", {"#17becf", 13}},
      {"ccd-gjk", {"#ff7f0e", 5}},     {"ccd-mpr", {"#8c564b", 4}},      {"fcl-libccd", {"#d62728", 9}},
      {"fcl-indep", {"#e377c2", 11}},  {"bullet-gjk", {"#2ca02c", 15}},  {"bullet-gjk-dist", {"#2ca02c", 15}}};
  const auto it = styles.find(method);
  return it == styles.end() ? Style{"#000000", 1} : it->second;
}

// The geometry of a figure, so that the labels can be placed without overlapping: a
// 1500 x 1000 image, 3 panels per row above a key strip, each panel's plot area at fixed
// pixel margins inside it.
constexpr double kImageW = 1500, kImageH = 1000;
constexpr int kColumns = 3;
constexpr double kPanelsTop = 0.95, kPanelsBottom = 0.12;  // screen fractions
constexpr double kLeftPx = 70, kRightPx = 15, kBottomPx = 50, kTopPx = 28;
constexpr double kCharW = 6.0, kCharH = 12.0;  // the labels' font (sans 8), roughly

// One method on one shape: a point of a panel, and where its label goes.
struct PlotPoint {
  const GjkRow* row;
  int panel, method;
  double x, y, yMax;
  std::string label;
  double labelX = 0, labelY = 0;
};

// The axis ranges of a panel (data units) and its plot area in pixels.
struct PanelAxes {
  double xLo, xHi, yLo, yHi, widthPx, heightPx;
  double px(double x) const { return std::log10(x / xLo) / std::log10(xHi / xLo) * widthPx; }
  double py(double y) const { return std::log10(y / yLo) / std::log10(yHi / yLo) * heightPx; }
  double fromPx(double p) const { return xLo * std::pow(xHi / xLo, p / widthPx); }
  double fromPy(double p) const { return yLo * std::pow(yHi / yLo, p / heightPx); }
};

// Places the labels of one panel greedily, left to right: beside the point if free, else
// one row up or down, then two, ... (a leader line joins a moved label to its point).
void placeLabels(std::vector<PlotPoint*>& points, const PanelAxes& axes) {
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

// Tics at 1, 2, 5 times the powers of ten inside [lo, hi] (only the powers when that is
// too many to fit), so that a panel spanning less than a decade still has numbers on its x axis.
std::string xTics(double lo, double hi, bool powersOnly = false) {
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

// The plot of a boolean group: a yes/no answer has no error to plot, so each panel (one
// per shape) puts the methods one per row, the median time per query as the point and a
// whisker out to the 99th percentile (log time axis), and at the right of each row the
// wrong answers among the judged queries (red when any) and the queries left unanswered.
void writeTimePlot(const std::string& base, const std::string& name, const Group& g, const std::vector<std::string>& shapes,
                   const std::vector<std::string>& methods, std::map<std::string, int>& queries, const std::vector<PlotPoint>& points) {
  const std::string csvName = name + ".csv";
  const int panelRows = int((shapes.size() + kColumns - 1) / kColumns);
  const double panelW = kImageW / kColumns, panelH = (kPanelsTop - kPanelsBottom) * kImageH / panelRows;
  constexpr double leftPx = 110;  // room for the method names
  std::ofstream gp(base + ".gp");
  gp << "# gnuplot script written by gjk_study (chapter 09): gnuplot " << name << ".gp\n";
  gp << "set terminal pngcairo size " << kImageW << "," << kImageH << " font 'sans,10'\n";
  gp << "set output '" << name << ".png'\n";
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

void plotGroup(const std::string& folder, const Group& g, const std::vector<GjkRow>& rows, bool haveGnuplot) {
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
    gp << "set terminal pngcairo size " << kImageW << "," << kImageH << " font 'sans,10'\n";
    gp << "set output '" << name << ".png'\n";
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
    else std::printf("wrote %s.png\n", base.c_str());
  }
}


// ---------------------------------------------------------------------------------------
// Key figures: the numbers the docs page quotes, computed from the rows (measured or read
// back from the CSV files by --replot), so the page's text follows every rerun.

// The shapes in the order of the rows.
std::vector<std::string> shapesOf(const std::vector<GjkRow>& rows) {
  std::vector<std::string> shapes;
  for (const auto& r : rows) {
    const std::string s = split(r.workload).shape;
    if (std::find(shapes.begin(), shapes.end(), s) == shapes.end()) shapes.push_back(s);
  }
  return shapes;
}

// The row of a method on a workload, or nullptr.
const GjkRow* rowOf(const std::vector<GjkRow>& rows, const std::string& workload, const std::string& method) {
  for (const auto& r : rows)
    if (r.workload == workload && r.method == method) return &r;
  return nullptr;
}

// The fastest peer's row on a workload, or nullptr.
const GjkRow* bestPeerRow(const std::vector<GjkRow>& rows, const std::string& workload) {
  const GjkRow* best = nullptr;
  for (const auto& r : rows)
    if (r.workload == workload && !r.ours && (!best || r.medianNs < best->medianNs)) best = &r;
  return best;
}

std::string workloadName(bool boolean, const std::string& shape, bool warm) {
  return std::string("gjk_") + (boolean ? "boolean_" : "distance_") + shape + (warm ? "_warm" : "");
}

// One table, a row per shape: ours-double's median time, the fastest peer's, and their
// ratio, cold and warm.
void writeSpeedTable(std::ostream& md, const std::vector<GjkRow>& rows, bool boolean) {
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

// "lo to hi" of a set of values, formatted with f.
std::string rangeText(const char* f, std::vector<double> v) {
  if (v.empty()) return "-";
  const auto [lo, hi] = std::minmax_element(v.begin(), v.end());
  return *lo == *hi ? format(f, *lo) : format(f, *lo) + " to " + format(f, *hi);
}

bool isCurved(const std::string& shape) { return shape == "sphere" || shape == "capsule"; }

// gjk-distance-summary.md: the distance queries' key figures.
void writeDistanceSummary(const std::string& path, const std::vector<GjkRow>& rows) {
  std::ofstream md(path);
  mdTitle(md, true, "GJK distance queries: key figures");
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
  mdNotes(md, "Computed by `gjk_study` (also with `--replot`) from the `gjk-distance-*.csv` files of the run in the GJK table. "
              "*ours / peer*: ours-double's median time divided by the fastest peer's (below 1: faster). Errors: `|d - d_ref|`.");
}

// gjk-boolean-summary.md: the boolean queries' key figures.
void writeBooleanSummary(const std::string& path, const std::vector<GjkRow>& rows) {
  std::ofstream md(path);
  mdTitle(md, true, "GJK boolean queries: key figures");
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
  mdNotes(md, "Computed by `gjk_study` (also with `--replot`) from the `gjk-boolean-*.csv` files of the run in the GJK table. "
              "*ours / peer*: ours-double's median time divided by the fastest peer's (below 1: faster).");
}

// gjk-float-summary.md: ours in float against ours in double, in one sentence.
void writeFloatSummary(const std::string& path, const std::vector<GjkRow>& rows) {
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

// gjk-goals.md: the study's speed goals for GJK, each against this run: ours-double's
// median time, the method the goal names, their ratio or the bound, and whether it is met.
void writeGoals(const std::string& path, const std::vector<GjkRow>& rows) {
  std::ofstream md(path);
  mdTitle(md, true, "GJK: the speed goals against this run");
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
  mdNotes(md, "Computed by `gjk_study` (also with `--replot`) from the `gjk-*.csv` files of the run in the GJK table. "
              "Median times per query; *ours / against*: ours-double's divided by the method's the goal names (for the 50 ns goal, by 50 ns).");
}

void writeSummaries(const std::string& folder, const std::vector<GjkRow>& rows) {
  writeDistanceSummary(folder + "/gjk-distance-summary.md", rows);
  writeBooleanSummary(folder + "/gjk-boolean-summary.md", rows);
  writeFloatSummary(folder + "/gjk-float-summary.md", rows);
  writeGoals(folder + "/gjk-goals.md", rows);
  std::printf("wrote %s/gjk-distance-summary.md, gjk-boolean-summary.md, gjk-float-summary.md and gjk-goals.md\n", folder.c_str());
}

}  // namespace

// The rows of one group back from its gjk-<group>.csv (for --replot: the plots redrawn
// without measuring again); false when the file is missing or has no queries column.
bool readGroupCsv(const std::string& folder, const Group& g, std::vector<GjkRow>& rows) {
  std::ifstream csv(folder + "/gjk-" + g.file + ".csv");
  std::string line;
  if (!std::getline(csv, line) || line.find(",queries") == std::string::npos) return false;
  while (std::getline(csv, line)) {
    std::vector<std::string> f;
    std::stringstream fields(line);
    for (std::string item; std::getline(fields, item, ',');) f.push_back(item);
    if (f.size() < 18) return false;
    GjkRow r;
    r.workload = std::string("gjk_") + (g.boolean ? "boolean_" : "distance_") + f[1] + (g.warm ? "_warm" : "");
    r.method = f[3];
    r.warmStart = f[4];
    r.ours = r.method.rfind("ours", 0) == 0;
    r.medianNs = std::stod(f[5]);
    r.p99Ns = std::stod(f[6]);
    r.errorMedian = std::stod(f[7]);
    r.errorMax = std::stod(f[8]);
    r.judged = std::stoi(f[9]);
    r.wrong = std::stoi(f[10]);
    r.failures = std::stoi(f[11]);
    r.queries = std::stoi(f[17]);
    rows.push_back(r);
  }
  return !rows.empty();
}

int main(int argc, char** argv) {
  const Options o = parse(argc, argv);
  if (o.replot) {
    const bool haveGnuplot = std::system("gnuplot --version > /dev/null 2>&1") == 0;
    std::vector<GjkRow> all;  // every group's rows, for the key figures
    for (const Group& g : kGroups) {
      std::vector<GjkRow> rows;
      if (!readGroupCsv(o.out, g, rows)) {
        std::fprintf(stderr, "gjk_study: %s/gjk-%s.csv is missing or lacks the queries column; run the study again\n", o.out.c_str(), g.file);
        return 1;
      }
      plotGroup(o.out, g, rows, haveGnuplot);
      all.insert(all.end(), rows.begin(), rows.end());
    }
    writeSummaries(o.out, all);
    return 0;
  }
  std::printf("GJK comparison (%s run, seed %u); %s\n", o.study.quick ? "quick" : "full", o.study.seed, peers::presentText(peers::kGjkPeers).c_str());
  std::printf("time per query: median and p99 over batches of 16; distance error |d - d_ref| (overlap = 0);\n");
  std::printf("boolean: wrong answers / judged queries against the exact reference\n");
  const auto rows = gjkx::study::gjk_comparison::runGjkComparisons(o.study);
  std::string last;
  for (const auto& r : rows) {
    if (r.workload != last) {
      if (!last.empty()) std::printf("  best peer: %s\n", gjkx::study::gjk_comparison::gjkBestPeer(rows, last).c_str());
      std::printf("\n%s (%d queries)\n", r.workload.c_str(), r.queries);
      last = r.workload;
    }
    std::printf("  %s\n", gjkx::study::gjk_comparison::formatGjkRow(r).c_str());
  }
  if (!last.empty()) std::printf("  best peer: %s\n", gjkx::study::gjk_comparison::gjkBestPeer(rows, last).c_str());
  printFloatVsDouble(rows);

  std::filesystem::create_directories(o.out);
  writeMainTable(o.out + "/gjk-table.md", o, rows);
  writeFloatVsDouble(o.out + "/gjk-float-vs-double.md", o, rows);
  std::printf("\nwrote %s/gjk-table.md and %s/gjk-float-vs-double.md\n", o.out.c_str(), o.out.c_str());
  writeSummaries(o.out, rows);
  const bool haveGnuplot = std::system("gnuplot --version > /dev/null 2>&1") == 0;
  if (!haveGnuplot) std::printf("gnuplot not found: wrote the .csv and .gp files, skipped the plots\n");
  for (const Group& g : kGroups) plotGroup(o.out, g, rows, haveGnuplot);

  std::printf("\n");
  for (const auto& line : gjkx::study::gjk_comparison::gjkRatioLines(rows)) std::printf("%s\n", line.c_str());
  return 0;
}
