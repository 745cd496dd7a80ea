// toi_study: the time-of-impact part of the comparative study (chapter 09).
//
//   toi_study [--out DIR] [--quick] [--ccd-data DIR] [--seed N] [--format png|svg|pdf]
//   toi_study --replot [--out DIR] [--format png|svg|pdf]
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
#include "../formatting.hpp"
#include "toi_comparisons.hpp"
#include "toi_study_csv.hpp"
#include "toi_study_key_figures.hpp"
#include "toi_study_plots.hpp"
#include "toi_study_tables.hpp"

#include <gjkx/study/peers.hpp>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

using namespace toi_study;

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
  chapter::addFormatOption(app);
  chapter::parseOrExit(app, argc, argv);
  return o;
}

// The provenance line of every markdown table: the command, the run and the date.
std::string provenance(const Options& o) {
  const std::string peersText = peers::joined(peers::found(peers::kToiPeers));
  return "Written by `toi_study --out " + o.out + (o.study.quick ? " --quick" : "") + "` (" + (o.study.quick ? "quick" : "full") +
         " run, seed " + std::to_string(o.study.seed) + ") on " + chapter::utcNow() + "; peers: " + (peersText.empty() ? "none" : peersText) + ".";
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

  writeWorkloads(o.out + "/toi-workloads.md", provenance(o), results);
  writeMainTable(o.out + "/toi-table.md", provenance(o), results);
  writeFloatVsDouble(o.out + "/toi-float-vs-double.md", provenance(o), results.rows);
  writeCcd(o.out + "/toi-ccd.md", provenance(o), results);
  writeSummary(o.out + "/toi-summary.md", results.rows);
  writeGoals(o.out + "/toi-goals.md", results.rows);
  std::printf("wrote %s/toi-workloads.md, toi-table.md, toi-float-vs-double.md, toi-ccd.md, toi-summary.md and toi-goals.md\n", o.out.c_str());

  for (const auto& w : results.workloads) plotWorkload(o.out, w.name, int(w.queries.size()), results.rows, true, haveGnuplot);
  return 0;
}
