// toi_study: the time-of-impact part of the comparative study (chapter 07).
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
// across its settings, the misses of each method in the key).
// 120 queries per workload (40 with --quick); a full run takes about 1.5 minutes on an idle
// 2-core machine (references about 30 s of it), --quick about 20 s. Regenerate the kept
// study figures with `build/chapters/07_study/toi_study --out figures/study`.
#include "toi_comparisons.hpp"

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <string>
#include <vector>

using namespace gjkx::toistudy;

namespace {

struct Options {
  std::string out = "figures/study";
  ToiStudyOptions study;
};

Options parse(int argc, char** argv) {
  Options o;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--out" && i + 1 < argc) {
      o.out = argv[++i];
    } else if (arg == "--quick") {
      o.study.quick = true;
    } else if (arg == "--ccd-data" && i + 1 < argc) {
      o.study.ccdData = argv[++i];
    } else if (arg == "--seed" && i + 1 < argc) {
      o.study.seed = std::strtoull(argv[++i], nullptr, 10);
    } else {
      std::fprintf(arg == "--help" || arg == "-h" ? stdout : stderr,
                   "usage: %s [--out DIR] [--quick] [--ccd-data DIR] [--seed N]\n"
                   "  the time-of-impact study: tables on stdout, plots in DIR (default figures/study)\n",
                   argv[0]);
      std::exit(arg == "--help" || arg == "-h" ? 0 : 2);
    }
  }
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
    gp << "# gnuplot script written by toi_study (chapter 07): gnuplot " << std::filesystem::path(base + ".gp").filename().string() << "\n";
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

void printFloatVsDouble(const std::vector<ToiRow>& rows) {
  struct Sum {
    int misses = 0, hits = 0, alarms = 0, clear = 0;
    std::vector<double> errors, times;
  };
  std::vector<std::string> order;
  std::map<std::string, std::map<std::string, Sum>> sums;  // family+setting -> scalar -> sum
  for (const auto& r : rows) {
    if (!r.ours) continue;
    const std::string key = r.family + " " + r.setting;
    if (!sums.count(key)) order.push_back(key);
    Sum& s = sums[key][r.scalar];
    s.misses += r.misses;
    s.hits += r.refHits;
    s.alarms += r.falseAlarms;
    s.clear += r.clearMisses;
    s.errors.insert(s.errors.end(), r.errors.begin(), r.errors.end());
    s.times.push_back(r.medianUs);
  }
  std::printf("\n== Float against double, every method of ours (all workloads together) ==\n");
  std::printf("%-22s | %-48s | %-48s\n", "method setting", "double: misses  f.alarms  err_med  err_max  us", "float: misses  f.alarms  err_med  err_max  us");
  for (const auto& key : order) {
    auto cell = [&](const std::string& scalar) {
      if (!sums[key].count(scalar)) return std::string("(not run)");
      const Sum& s = sums[key][scalar];
      char text[160];
      const double med = gjkx::toistudy::detail::median(s.errors);
      const double mx = s.errors.empty() ? std::nan("") : *std::max_element(s.errors.begin(), s.errors.end());
      std::snprintf(text, sizeof text, "%4d/%-4d %3d/%-4d %8.1e %8.1e %7.2f", s.misses, s.hits, s.alarms, s.clear, med, mx,
                    gjkx::toistudy::detail::median(s.times));
      return std::string(text);
    };
    std::printf("%-22s | %-48s | %-48s\n", key.c_str(), cell("double").c_str(), cell("float").c_str());
  }
}

}  // namespace

int main(int argc, char** argv) {
  const Options o = parse(argc, argv);
  std::filesystem::create_directories(o.out);
  std::printf("toi_study: peers found:");
  for (const auto& p : peers::found()) std::printf(" %s", p.c_str());
  std::printf("; left out (not installed):");
  const auto missing = peers::missing();
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

  const bool haveGnuplot = std::system("gnuplot --version > /dev/null 2>&1") == 0;
  if (!haveGnuplot) std::printf("gnuplot not found: wrote the .csv and .gp files, skipped the plots\n");
  for (const auto& w : results.workloads) plotWorkload(o.out, w, results.rows, haveGnuplot);
  return 0;
}
