// The GJK comparison of the study (chapter 09): ours against libccd, FCL and Bullet on
// distance and boolean queries, cold and warm-started, with the disagreement against an
// exact reference. Prints one table per workload, float against double for ours, and ends
// with the RATIO lines (ours-double median time / the best peer's, measured in this run).
//
//   gjk_study [--out DIR] [--quick] [--seed N] [--format png|svg|pdf]
//   gjk_study --replot [--out DIR] [--format png|svg|pdf]
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
#include "../formatting.hpp"
#include "gjk_comparisons.hpp"
#include "gjk_study_csv.hpp"
#include "gjk_study_key_figures.hpp"
#include "gjk_study_plots.hpp"
#include "gjk_study_tables.hpp"
#include "gjk_study_workloads.hpp"

#include <gjkx/study/peers.hpp>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

using namespace gjk_study;
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
  chapter::addFormatOption(app);
  chapter::parseOrExit(app, argc, argv);
  return o;
}

std::string provenance(const Options& o) {
  return std::string("Written by `gjk_study --out ") + o.out + (o.study.quick ? " --quick" : "") +
         (o.study.seed != gjkx::study::gjk_comparison::GjkStudyOptions{}.seed ? " --seed " + std::to_string(o.study.seed) : std::string()) + "` (" +
         (o.study.quick ? "quick" : "full") + " run, seed " + std::to_string(o.study.seed) + ") on " + chapter::utcNow() + "; " +
         peers::presentText(peers::kGjkPeers) + ".";
}

}  // namespace

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
  writeMainTable(o.out + "/gjk-table.md", provenance(o), rows);
  writeFloatVsDouble(o.out + "/gjk-float-vs-double.md", provenance(o), rows);
  std::printf("\nwrote %s/gjk-table.md and %s/gjk-float-vs-double.md\n", o.out.c_str(), o.out.c_str());
  writeSummaries(o.out, rows);
  const bool haveGnuplot = std::system("gnuplot --version > /dev/null 2>&1") == 0;
  if (!haveGnuplot) std::printf("gnuplot not found: wrote the .csv and .gp files, skipped the plots\n");
  for (const Group& g : kGroups) plotGroup(o.out, g, rows, haveGnuplot);

  std::printf("\n");
  for (const auto& line : gjkx::study::gjk_comparison::gjkRatioLines(rows)) std::printf("%s\n", line.c_str());
  return 0;
}
