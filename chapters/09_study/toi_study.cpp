// toi_study: the time-of-impact part of the comparative study (chapter 09).
//
//   toi_study [--out DIR] [--quick] [--ccd-data DIR] [--seed N]
//
// Runs every method of toi_comparisons.hpp on every workload of workloads.hpp (each query
// judged against the independent long-double reference), prints the tables (per workload:
// median and 99th-percentile time per query, misses, false alarms, time-of-impact error),
// float against double for every method of ours, and the CCD benchmark's sample queries at
// four tolerances; then draws one plot per workload into DIR (default figures/study):
// toi-<workload>.csv and .gp, and toi-<workload>.png when gnuplot is installed (error of the
// time of impact against the time per query, both log scales, one curve per method joined
// across its settings, the misses of each method in the key). The tables are also written
// into DIR as markdown, for the docs page of the study: toi-workloads.md, toi-table.md,
// toi-float-vs-double.md and toi-ccd.md.
// 120 queries per workload (40 with --quick); a full run takes about 1.5 minutes on an idle
// 2-core machine (references about 30 s of it), --quick about 20 s. Regenerate the kept
// study figures with `build/chapters/09_study/toi_study --out figures/study`.
#include "../command_line.hpp"
#include "toi_comparisons.hpp"

#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <string>
#include <vector>

using namespace gjkx::study;

namespace {

struct Options {
  std::string out = "figures/study";
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

void plotWorkload(const std::string& folder, const ToiWorkload& w, const std::vector<ToiRow>& rows, bool haveGnuplot) {
  std::vector<std::string> curves;
  std::map<std::string, std::vector<const ToiRow*>> byCurve;
  for (const auto& r : rows) {
    if (r.workload != w.name) continue;
    const std::string c = curveName(r);
    if (!byCurve.count(c)) curves.push_back(c);
    byCurve[c].push_back(&r);
  }
  const std::string base = folder + "/toi-" + w.name;
  {
    std::ofstream csv(base + ".csv");
    csv << "curve,method,setting,scalar,median_us,p99_us,error_median,error_max,misses,ref_hits,false_alarms,clear_misses,plotted_error,"
           "point_label\n";
    for (std::size_t k = 0; k < curves.size(); ++k)
      for (const auto* r : byCurve[curves[k]]) {
        // Detection-only methods have no time of impact: plotted at error 1 (the whole interval).
        const double y = r->detectionOnly ? 1.0 : (std::isnan(r->errMedian) ? std::nan("") : std::max(r->errMedian, 1e-17));
        // Points labelled with their setting: ours in double, and the peers' settings.
        const bool labelled = (r->family == "ours" && r->scalar == "double") || (!r->ours && r->setting != "-");
        char line[512];
        std::snprintf(line, sizeof line, "%zu,%s,%s,%s,%.4g,%.4g,%.4g,%.4g,%d,%d,%d,%d,%.4g,%s\n", k, r->family.c_str(), r->setting.c_str(),
                      r->scalar.c_str(), r->medianUs, r->p99Us, r->errMedian, r->errMax, r->misses, r->refHits, r->falseAlarms,
                      r->clearMisses, y, labelled ? r->setting.c_str() : "");
        csv << line;
      }
  }
  {
    std::ofstream gp(base + ".gp");
    gp << "# gnuplot script written by toi_study (chapter 09): gnuplot " << std::filesystem::path(base + ".gp").filename().string() << "\n";
    gp << "set terminal pngcairo size 1200,800 font 'sans,10'\n";
    gp << "set output '" << std::filesystem::path(base + ".png").filename().string() << "'\n";
    gp << "set datafile separator ','\n";
    gp << "set termoption noenhanced\nset logscale xy\nset format y '%.0e'\nset grid\n";
    gp << "set xlabel 'median time per query (microseconds)'\nset ylabel 'median |t - t_ref| over the hits both report'\n";
    gp << "set title \"time of impact, workload " << w.name << " (" << w.queries.size()
       << " queries): error against time; swept test (yes/no only) plotted at error 1\" noenhanced\n";
    gp << "set key outside right top\n";
    // One colour per method; float curves dashed.
    static const char* const colours[] = {"#1f77b4", "#ff7f0e", "#2ca02c", "#d62728", "#9467bd", "#8c564b", "#e377c2",
                                          "#7f7f7f", "#bcbd22", "#17becf", "#000000", "#aa0000", "#005500", "#0000aa"};
    std::map<std::string, int> colourOf;
    gp << "plot ";
    for (std::size_t k = 0; k < curves.size(); ++k) {
      const ToiRow& first = *byCurve[curves[k]].front();
      if (!colourOf.count(first.family)) colourOf[first.family] = int(colourOf.size()) % 14;
      gp << (k ? ", \\\n     " : "") << "'" << std::filesystem::path(base + ".csv").filename().string()
         << "' skip 1 using ($1==" << k << " ? $5 : NaN):13 with linespoints lw 2 pt " << (k % 13 + 1) << " lc rgb '"
         << colours[colourOf[first.family]] << "' dt " << (first.scalar == "float" ? 2 : 1) << " title \"" << keyText(byCurve[curves[k]])
         << "\"";
    }
    gp << ", \\\n     '" << std::filesystem::path(base + ".csv").filename().string()
       << "' skip 1 using 5:13:14 with labels font ',7' offset 0,0.8 notitle\n";
  }
  if (haveGnuplot) {
    const std::string command = "cd '" + folder + "' && gnuplot 'toi-" + w.name + ".gp'";
    if (std::system(command.c_str()) != 0) std::fprintf(stderr, "toi_study: gnuplot failed on %s.gp\n", base.c_str());
    else std::printf("wrote %s.png\n", base.c_str());
  }
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

}  // namespace

int main(int argc, char** argv) {
  const Options o = parse(argc, argv);
  std::filesystem::create_directories(o.out);
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
  std::printf("wrote %s/toi-workloads.md, toi-table.md, toi-float-vs-double.md and toi-ccd.md\n", o.out.c_str());

  const bool haveGnuplot = std::system("gnuplot --version > /dev/null 2>&1") == 0;
  if (!haveGnuplot) std::printf("gnuplot not found: wrote the .csv and .gp files, skipped the plots\n");
  for (const auto& w : results.workloads) plotWorkload(o.out, w, results.rows, haveGnuplot);
  return 0;
}
