// toi_study: the time-of-impact part of the comparative study (chapter 09).
//
//   toi_study [--out DIR] [--quick] [--ccd-data DIR] [--seed N]
//   toi_study --replot [--out DIR]
//
// Runs every method of toi_comparisons.hpp on every workload of workloads.hpp (each query
// judged against the independent long-double reference), prints the tables (per workload:
// median and 99th-percentile time per query, misses, false alarms, time-of-impact error),
// float against double for every method of ours, and the CCD benchmark's sample queries at
// four tolerances; then draws one plot per workload into DIR (default figures/study):
// toi-<workload>.csv and .gp, and toi-<workload>.png when gnuplot is installed (error of the
// time of impact against the time per query, both log scales, one curve per method joined
// across its settings, a cross over every setting that missed a hit, the misses in the key;
// under it, on the same time axis, the share of the reference's hits each setting missed).
// --replot measures nothing and redraws the plots from the CSV files already in DIR. The tables are also written
// into DIR as markdown, for the docs page of the study: toi-workloads.md, toi-table.md,
// toi-float-vs-double.md and toi-ccd.md; and the key figures the page quotes (misses and
// false alarms per method, ours against the peers' time) in toi-summary.md, and the study's
// speed goals against the run in toi-goals.md, both of which --replot writes again from the
// CSV files.
// 120 queries per workload (40 with --quick); a full run takes about 1.5 minutes on an idle
// 2-core machine (references about 30 s of it), --quick about 20 s. Regenerate the kept
// study figures with `build/chapters/09_study/toi_study --out figures/study`.
#include "../command_line.hpp"
#include "toi_comparisons.hpp"

#include <gjkx/study/peers.hpp>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <set>
#include <sstream>
#include <string>
#include <vector>

using namespace gjkx::study;

namespace {

struct Options {
  std::string out = "figures/study";
  bool replot = false;
  ToiStudyOptions study;
};

Options parse(int argc, char** argv) {
  Options o;
  CLI::App app{"The time-of-impact study: tables on stdout, plots and tables in DIR."};
  app.add_option("--out", o.out, "the folder for the plots and markdown tables")->type_name("DIR")->capture_default_str();
  app.add_flag("--quick", o.study.quick, "a short run: fewer queries, shorter timing batches");
  app.add_option("--ccd-data", o.study.ccdData, "the CCD benchmark's sample queries (default: the build's ../shared/data/ccd-queries)")
      ->type_name("DIR");
  app.add_option("--seed", o.study.seed, "seed of the workloads")->type_name("N")->capture_default_str();
  app.add_flag("--replot", o.replot, "measure nothing: redraw the plots and write the key figures from the toi-<workload>.csv files already in DIR");
  chapter::parseOrExit(app, argc, argv);
  return o;
}

std::string curveName(const ToiRow& r) { return r.family + " " + r.scalar; }

// The key of a curve: its name and its misses (and false alarms), never hidden.
std::string keyText(const std::vector<const ToiRow*>& rows) {
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

// How a method family looks on every plot of the study: its own colour and marker (filled
// for the first six, open for the rest; never a cross, which marks misses). Float curves
// are dashed.
struct FamilyStyle {
  const char* colour;
  int point;
};
FamilyStyle familyStyle(const std::string& family) {
  static const std::map<std::string, FamilyStyle> styles = {
      {"ours", {"#d62728", 7}},       {"certified", {"#9467bd", 5}}, {"static", {"#1f77b4", 9}},    {"swept", {"#ff7f0e", 11}},
      {"CA", {"#2ca02c", 13}},        {"FCL naive", {"#8c564b", 15}}, {"FCL CA", {"#e377c2", 6}},    {"FCL CA indep", {"#555555", 8}},
      {"Bullet", {"#a6a600", 12}},    {"Box2D", {"#17becf", 4}}};
  const auto it = styles.find(family);
  return it == styles.end() ? FamilyStyle{"#000000", 10} : it->second;
}

// The families the study implements itself (the rest are peers).
bool isOurs(const std::string& family) {
  return family == "static" || family == "swept" || family == "CA" || family == "ours" || family == "certified";
}

// Writes toi-<workload>.csv from the rows of one workload.
void writeWorkloadCsv(const std::string& base, const std::vector<std::string>& curves,
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

// The plot of one workload, in two panels on one time axis, with the key to their right:
// above, the median error of the time of impact against the median time per query (both
// log), one curve per method joined across its settings, and a black cross over every
// setting that missed a collision the reference found; below, the share of the
// reference's hits each setting missed, so that a method that misses sits visibly high.
void writeWorkloadPlot(const std::string& base, const std::string& workload, int queries, const std::vector<std::string>& curves,
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
  gp << "set terminal pngcairo size 1300,900 font 'sans,10'\n";
  gp << "set output '" << std::filesystem::path(base + ".png").filename().string() << "'\n";
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

// One workload's CSV, plot script and (with gnuplot) PNG.
void plotWorkload(const std::string& folder, const std::string& workload, int queries, const std::vector<ToiRow>& rows, bool writeCsv,
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
    else std::printf("wrote %s.png\n", base.c_str());
  }
}

// The rows of one workload back from its toi-<workload>.csv (for --replot: the plots
// redrawn without measuring again). Returns the workload's query count, 0 if unreadable.
int readWorkloadCsv(const std::string& path, const std::string& workload, std::vector<ToiRow>& rows) {
  std::ifstream csv(path);
  std::string line;
  if (!std::getline(csv, line)) return 0;
  int queries = 0;
  while (std::getline(csv, line)) {
    std::vector<std::string> f;
    std::stringstream fields(line);
    for (std::string item; std::getline(fields, item, ',');) f.push_back(item);
    if (f.size() < 13) continue;
    ToiRow r;
    r.workload = workload;
    r.family = f[1];
    r.setting = f[2];
    r.scalar = f[3];
    r.ours = isOurs(r.family);
    r.medianUs = std::stod(f[4]);
    r.p99Us = std::stod(f[5]);
    r.errMedian = std::stod(f[6]);
    r.errMax = std::stod(f[7]);
    r.misses = std::stoi(f[8]);
    r.refHits = std::stoi(f[9]);
    r.falseAlarms = std::stoi(f[10]);
    r.clearMisses = std::stoi(f[11]);
    r.detectionOnly = std::isnan(r.errMedian) && std::stod(f[12]) == 1.0;
    r.queries = f.size() > 14 ? std::stoi(f[14]) : 0;
    queries = r.queries;
    rows.push_back(r);
  }
  return queries;
}

// The provenance line of every markdown table: the command, the run and the date.
std::string provenance(const Options& o) {
  char date[32];
  const std::time_t now = std::time(nullptr);
  std::strftime(date, sizeof date, "%Y-%m-%d %H:%M UTC", std::gmtime(&now));
  const std::string peersText = peers::joined(peers::found(peers::kToiPeers));
  return "Written by `toi_study --out " + o.out + (o.study.quick ? " --quick" : "") + "` (" + (o.study.quick ? "quick" : "full") +
         " run, seed " + std::to_string(o.study.seed) + ") on " + date + "; peers: " + (peersText.empty() ? "none" : peersText) + ".";
}

std::string fmt(const char* f, double x) {
  if (std::isnan(x)) return "-";
  char s[64];
  std::snprintf(s, sizeof s, f, x);
  return s;
}

// Text for a markdown table cell: a '|' would end the cell.
std::string mdCell(const std::string& text) {
  std::string out;
  for (const char c : text) out += c == '|' ? std::string("\\|") : std::string(1, c);
  return out;
}

// The docs page includes the markdown files with Doxygen's \includedoc, which joins an
// included file into one paragraph: so a file starts with a title or a table, puts a line
// break before every later title, and ends with its notes (command, run, date, what the
// columns mean), which then read as a caption under the tables.
void mdTitle(std::ostream& md, bool first, const std::string& bold, const std::string& rest) {
  md << (first ? "" : "\n<br>") << "**" << bold << "**" << rest << "\n\n";
}
void mdNotes(std::ostream& md, const std::string& notes) { md << "\n<br>" << notes << "\n"; }

// Every method of ours in float and in double, over all workloads together.
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

FloatVsDouble floatVsDouble(const std::vector<ToiRow>& rows) {
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

void printFloatVsDouble(const std::vector<ToiRow>& rows) {
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

void writeFloatVsDouble(const std::string& path, const Options& o, const std::vector<ToiRow>& rows) {
  FloatVsDouble t = floatVsDouble(rows);
  std::ofstream md(path);
  const std::string notes = provenance(o) + " Every method of ours in double and in float, all workloads together: misses / reference hits, "
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
       << (both ? ratio(f.alarms, f.clear) : "(not run)") << " | " << fmt("%.1e", d.errMedian()) << " | " << fmt("%.1e", f.errMedian()) << " | "
       << fmt("%.1e", d.errMax()) << " | " << fmt("%.1e", f.errMax()) << " | " << fmt("%.2f", d.usMedian()) << " | " << fmt("%.2f", f.usMedian())
       << " |\n";
  }
  mdNotes(md, notes);
}

// The main table: one block per workload, every method and setting.
void writeMainTable(const std::string& path, const Options& o, const ToiStudyResults& results) {
  std::ofstream md(path);
  const std::string notes = provenance(o) + " Per workload and method: median and 99th-percentile time per query (us), misses / reference hits, "
      + "false alarms / clear misses (queries the reference calls in between are not judged), the time-of-impact error "
      + "`|t - t_ref|` over the hits both report (median, maximum; - when there are none or the method reports no time), and, for "
      + "ours, the GJK runs per query.";
  for (const auto& w : results.workloads) {
    mdTitle(md, &w == &results.workloads.front(), "Time of impact, workload " + w.name,
            " (" + std::to_string(w.queries.size()) + " queries): " + mdCell(w.description));
    md << "| method | setting | scalar | median us | p99 us | misses | false alarms | error median | error max | GJK runs |\n";
    md << "| --- | --- | --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: |\n";
    for (const auto& r : results.rows) {
      if (r.workload != w.name) continue;
      const bool highlight = r.family == "ours" && r.setting == "tol=1e-7" && r.scalar == "double";
      md << "| " << (highlight ? "**" + r.family + "**" : r.family) << " | " << r.setting << " | " << r.scalar << " | " << fmt("%.2f", r.medianUs)
         << " | " << fmt("%.2f", r.p99Us) << " | " << r.misses << " / " << r.refHits << " | " << r.falseAlarms << " / " << r.clearMisses << " | "
         << (r.detectionOnly ? "(yes/no)" : fmt("%.1e", r.errMedian)) << " | " << (r.detectionOnly ? "(yes/no)" : fmt("%.1e", r.errMax)) << " | "
         << (r.ours ? fmt("%.1f", r.meanGjkRuns) : "-") << " |\n";
    }
  }
  mdNotes(md, notes);
}

void writeWorkloads(const std::string& path, const Options& o, const ToiStudyResults& results) {
  std::ofstream md(path);
  const std::string notes = provenance(o) + " The time-of-impact workloads and their reference: long-double distance, Lipschitz-certified dense sampling, "
      + "bisection to 1e-13. Queries the reference finds neither hit nor clear miss are not judged.";
  md << "| workload | queries | reference hits | clear misses | not judged | what it is |\n| --- | ---: | ---: | ---: | ---: | --- |\n";
  for (const auto& w : results.workloads) {
    int hits = 0, clear = 0;
    for (const auto& q : w.queries) {
      hits += q.refHit;
      clear += q.clearMiss;
    }
    md << "| " << w.name << " | " << w.queries.size() << " | " << hits << " | " << clear << " | " << int(w.queries.size()) - hits - clear << " | "
       << mdCell(w.description) << " |\n";
  }
  mdNotes(md, notes);
}

void writeCcd(const std::string& path, const Options& o, const ToiStudyResults& results) {
  std::ofstream md(path);
  const std::string notes = provenance(o) + " The sample queries of the external CCD benchmark, ours in double (the paper's variant) at four collision "
      + "tolerances: false negatives (fn: the benchmark says they collide, we say no), false positives (fp), queries that "
      + "ended at the iteration cap, and the time per query.";
  if (results.ccd.empty()) {
    md << "Not run: " << results.ccdNote << "\n";
    mdNotes(md, notes);
    return;
  }
  md << "| tolerance | queries | truth positives | our positives | fn | fp | capped | us per query |\n";
  md << "| ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |\n";
  for (const auto& c : results.ccd)
    md << "| " << fmt("%.0e", c.tolerance) << " | " << c.queries << " | " << c.truthPositives << " | " << c.positives << " | " << c.fn << " | "
       << c.fp << " | " << c.capped << " | " << fmt("%.3f", c.usPerQuery) << " |\n";
  mdNotes(md, notes);
}


// ---------------------------------------------------------------------------------------
// Key figures: the numbers the docs page quotes, computed from the rows (measured or read
// back from the CSV files by --replot), so the page's text follows every rerun. Workloads
// in the order of their names, the same whichever way the rows came.

bool isTheSolver(const ToiRow& r) { return r.family == "ours" || r.family == "certified"; }

std::vector<std::string> workloadsOf(const std::vector<ToiRow>& rows) {
  std::set<std::string> names;
  for (const auto& r : rows) names.insert(r.workload);
  return {names.begin(), names.end()};
}

// The row of ours in double at the tolerance the RATIO lines use, and FCL's conservative advancement.
const ToiRow* findRow(const std::vector<ToiRow>& rows, const std::string& workload, const std::string& family, const std::string& setting,
                      const std::string& scalar) {
  for (const auto& r : rows)
    if (r.workload == workload && r.family == family && (setting.empty() || r.setting == setting) && r.scalar == scalar) return &r;
  return nullptr;
}

// "lo (workload) to hi (workload)" of a value per workload.
std::string rangeText(const char* f, const std::map<std::string, double>& v) {
  if (v.empty()) return "-";
  auto lo = v.begin(), hi = v.begin();
  for (auto it = v.begin(); it != v.end(); ++it) {
    if (it->second < lo->second) lo = it;
    if (it->second > hi->second) hi = it;
  }
  return fmt(f, lo->second) + " (" + lo->first + ") to " + fmt(f, hi->second) + " (" + hi->first + ")";
}

// toi-summary.md: misses and false alarms of every method, and ours' speed against the peers.
void writeSummary(const std::string& path, const std::vector<ToiRow>& rows) {
  const std::vector<std::string> workloads = workloadsOf(rows);
  std::ofstream md(path);
  mdTitle(md, true, "Time of impact: key figures", "");

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
    md << "| " << w << " | " << fmt("%.2f", ours->medianUs) << " | " << fmt("%.1e", ours->errMedian) << " | "
       << (ca ? fmt("%.2f", ca->medianUs) : "-") << " | " << (ca ? fmt("%.1e", ca->errMedian) : "-") << " | "
       << (ca ? fmt("%.2f", vsCa[w]) : "-") << " | " << (best ? fmt("%.2f", best->medianUs) + " (" + best->label() + ")" : "-") << " | "
       << (best ? fmt("%.2f", ours->medianUs / best->medianUs) : "-") << " |\n";
  }
  std::string fastest;
  for (const auto& [label, count] : fastestCount)
    fastest += (fastest.empty() ? "" : ", ") + label + " on " + std::to_string(count);
  md << "\n<br>On the workloads FCL's conservative advancement runs on, ours takes " << rangeText("%.2f", vsCa) << " of its median time and "
     << rangeText("%.2f", vsBest) << " of the fastest peer's";
  for (const auto& [w, ratio] : vsBestElsewhere) md << "; on " << w << " " << fmt("%.2f", ratio) << " of the fastest peer's";
  md << " (the fastest peer: " << fastest << " of the " << workloads.size() << " workloads).\n";
  mdNotes(md, "Computed by `toi_study` (also with `--replot`) from the `toi-<workload>.csv` files of the run in the time-of-impact table. "
              "Times: median per query (us); errors: `|t - t_ref|` in units of the interval; *ours / ...*: ratio of the median times.");
}

// toi-goals.md: the study's speed goals for the time of impact, each against this run:
// ours (double, tolerance 1e-7) against the method the goal names, by median time, with
// both errors where the goal asks for equal or lower error.
void writeGoals(const std::string& path, const std::vector<ToiRow>& rows) {
  std::ofstream md(path);
  mdTitle(md, true, "Time of impact: the speed goals against this run", "");
  md << "| goal | workload | ours us | against, us | ours / against | error median: ours, against | met |\n";
  md << "| --- | --- | ---: | --- | ---: | --- | :---: |\n";
  int met = 0, goals = 0;
  // One row: ours against `other`; `ok` empty for a goal with no ratio to reach.
  auto row = [&](const char* goal, const std::string& w, const ToiRow& ours, const ToiRow& other, std::optional<bool> ok) {
    if (ok) ++goals, met += *ok;
    md << "| " << goal << " | " << w << " | " << fmt("%.2f", ours.medianUs) << " | " << other.label() << " " << fmt("%.2f", other.medianUs)
       << " | " << fmt("%.2f", ours.medianUs / other.medianUs) << " | " << fmt("%.1e", ours.errMedian) << ", " << fmt("%.1e", other.errMedian)
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
  mdNotes(md, "Computed by `toi_study` (also with `--replot`) from the `toi-<workload>.csv` files of the run in the time-of-impact table. "
              "Ours: the paper's solver in double at tolerance 1e-7. Times: median per query (us); *ours / against*: their ratio; "
              "errors: median `|t - t_ref|` over the hits each reports, in units of the interval.");
}

}  // namespace

int main(int argc, char** argv) {
  const Options o = parse(argc, argv);
  std::filesystem::create_directories(o.out);
  const bool haveGnuplot = std::system("gnuplot --version > /dev/null 2>&1") == 0;
  if (!haveGnuplot) std::printf("gnuplot not found: writing the .gp files, skipping the plots\n");
  if (o.replot) {
    std::vector<ToiRow> all;  // every workload's rows, for the key figures
    for (const auto& entry : std::filesystem::directory_iterator(o.out)) {
      const std::string file = entry.path().filename().string();
      if (file.rfind("toi-", 0) != 0 || entry.path().extension() != ".csv") continue;
      const std::string workload = file.substr(4, file.size() - 8);
      std::vector<ToiRow> rows;
      const int queries = readWorkloadCsv(entry.path().string(), workload, rows);
      if (rows.empty() || queries == 0) {
        std::fprintf(stderr, "toi_study: %s has no rows or no queries column; run the study again\n", file.c_str());
        return 1;
      }
      plotWorkload(o.out, workload, queries, rows, false, haveGnuplot);
      all.insert(all.end(), rows.begin(), rows.end());
    }
    writeSummary(o.out + "/toi-summary.md", all);
    writeGoals(o.out + "/toi-goals.md", all);
    std::printf("wrote %s/toi-summary.md and toi-goals.md\n", o.out.c_str());
    return 0;
  }
  std::printf("toi_study: peers found:");
  for (const auto& p : peers::found(peers::kToiPeers)) std::printf(" %s", p.c_str());
  std::printf("; left out (not installed):");
  const auto missing = peers::missing(peers::kToiPeers);
  if (missing.empty()) std::printf(" none");
  for (const auto& p : missing) std::printf(" %s", p.c_str());
  std::printf("\n");

  ToiStudyOptions study = o.study;
  study.verbose = true;
  const ToiStudyResults results = runToiComparisons(study);

  std::printf("\n== Workloads (reference: long-double distance, Lipschitz-certified dense sampling, bisection to 1e-13) ==\n");
  for (const auto& w : results.workloads) {
    int hits = 0, clear = 0;
    for (const auto& q : w.queries) {
      hits += q.refHit;
      clear += q.clearMiss;
    }
    std::printf("%-11s %3zu queries: %3d hits, %3d clear misses, %3d in between (not judged): %s\n", w.name.c_str(), w.queries.size(), hits,
                clear, int(w.queries.size()) - hits - clear, w.description.c_str());
  }

  std::printf("\n== Time of impact: time per query (us), misses/reference hits, false alarms/clear misses, error |t - t_ref| ==\n");
  std::printf("%s\n", toiTableHeader());
  std::string last;
  for (const auto& r : results.rows) {
    if (r.workload != last && !last.empty()) std::printf("\n");
    last = r.workload;
    std::printf("%s\n", formatToiRow(r).c_str());
  }

  printFloatVsDouble(results.rows);

  std::printf("\n== CCD benchmark sample queries (ours, double, paper variant) ==\n");
  if (results.ccd.empty()) std::printf("%s\n", results.ccdNote.c_str());
  else std::printf("%-9s %8s %6s %9s %5s %5s %6s %12s\n", "tolerance", "queries", "truth", "positives", "fn", "fp", "capped", "us_per_query");
  for (const auto& c : results.ccd)
    std::printf("%-9.0e %8lld %6lld %9lld %5lld %5lld %6lld %12.3f\n", c.tolerance, c.queries, c.truthPositives, c.positives, c.fn, c.fp,
                c.capped, c.usPerQuery);

  std::printf("\n");
  for (const auto& line : toiRatioLines(results.rows)) std::printf("%s\n", line.c_str());

  writeWorkloads(o.out + "/toi-workloads.md", o, results);
  writeMainTable(o.out + "/toi-table.md", o, results);
  writeFloatVsDouble(o.out + "/toi-float-vs-double.md", o, results.rows);
  writeCcd(o.out + "/toi-ccd.md", o, results);
  writeSummary(o.out + "/toi-summary.md", results.rows);
  writeGoals(o.out + "/toi-goals.md", results.rows);
  std::printf("wrote %s/toi-workloads.md, toi-table.md, toi-float-vs-double.md, toi-ccd.md, toi-summary.md and toi-goals.md\n", o.out.c_str());

  for (const auto& w : results.workloads) plotWorkload(o.out, w.name, int(w.queries.size()), results.rows, true, haveGnuplot);
  return 0;
}
