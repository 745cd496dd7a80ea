// study_summary: a quick version of every comparison of the study (chapter 09), in one run,
// ending with lines a script can read.
//
//   study_summary [--ccd-data DIR]
//
// Runs the GJK comparison (gjk_comparisons.hpp, quick) and the time-of-impact comparison
// (toi_comparisons.hpp, quick: 40 queries per workload, short timing batches), prints their
// condensed tables and the CCD totals, then
//   RATIO <comparison> ours_vs_best_peer=X best_peer=NAME   (ours median time / fastest peer's, same run)
//   RATIO toi_<workload> ours_vs_fcl_ca=X                    (ours double tol 1e-7 / FCL conservative advancement)
//   RATIO toi_<workload> ours_vs_fcl_ca_mean=X, ours_vs_bullet_mean=X   (the same by mean time per query)
// and one line per method and time-of-impact workload:
//   MISSES method=<name> workload=<name> misses=N false_alarms=N queries=N
// For the time of impact "ours" in the RATIO lines is the paper's variant in double at
// collision tolerance 1e-7. Numbers are medians of per-query times.
#include "../command_line.hpp"
#include "toi_comparisons.hpp"

#include <gjkx/study/peers.hpp>

#if __has_include("gjk_comparisons.hpp")
#include "gjk_comparisons.hpp"
#define GJKX_STUDY_SUMMARY_GJK 1
#else
#define GJKX_STUDY_SUMMARY_GJK 0
#endif

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

int main(int argc, char** argv) {
  gjkx::study::ToiStudyOptions toiOptions;
  toiOptions.quick = true;
  CLI::App app{"A quick run of every comparison of the study, ending with RATIO and MISSES lines."};
  app.add_option("--ccd-data", toiOptions.ccdData, "the CCD benchmark's sample queries (default: the build's ../shared/data/ccd-queries)")
      ->type_name("DIR");
  chapter::parseOrExit(app, argc, argv);
  using Clock = std::chrono::steady_clock;
  const auto start = Clock::now();
  auto elapsed = [&] { return std::chrono::duration<double>(Clock::now() - start).count(); };

  std::printf("study_summary: peers found:");
  for (const auto& p : gjkx::study::peers::found(gjkx::study::peers::kToiPeers)) std::printf(" %s", p.c_str());
  std::printf("; left out (not installed):");
  const auto missing = gjkx::study::peers::missing(gjkx::study::peers::kToiPeers);
  if (missing.empty()) std::printf(" none");
  for (const auto& p : missing) std::printf(" %s", p.c_str());
  std::printf("\n");

  // --- GJK (quick) ---
  std::vector<std::string> ratioLines;
#if GJKX_STUDY_SUMMARY_GJK
  {
    gjkx::study::gjk_comparison::GjkStudyOptions gjkOptions;
    gjkOptions.quick = true;
    const auto rows = gjkx::study::gjk_comparison::runGjkComparisons(gjkOptions);
    std::printf("\n== GJK (quick) ==\n");
    for (const auto& r : rows) std::printf("%s\n", gjkx::study::gjk_comparison::formatGjkRow(r).c_str());
    for (const auto& line : gjkx::study::gjk_comparison::gjkRatioLines(rows)) ratioLines.push_back(line);
    std::printf("gjk comparison done at %.1f s\n", elapsed());
  }
#else
  std::printf("\n== GJK: gjk_comparisons.hpp not in this tree, comparison left out ==\n");
#endif

  // --- Time of impact (quick) ---
  const gjkx::study::ToiStudyResults toi = gjkx::study::runToiComparisons(toiOptions);
  std::printf("\n== Time of impact (quick; us per query, misses/ref hits, false alarms/clear misses, error) ==\n%s\n",
              gjkx::study::toiTableHeader());
  for (const auto& r : toi.rows) {
    // Condensed: the settings the RATIO lines and the note quote.
    const bool dbl = r.scalar == "double";
    const bool keep = !r.ours || (r.family == "ours" && dbl && (r.setting == "tol=1e-3" || r.setting == "tol=1e-7")) ||
                      (r.family == "ours" && !dbl && r.setting == "tol=1e-5") || (r.family == "certified" && dbl && r.setting == "tol=1e-7") ||
                      (r.family == "CA" && dbl && r.setting == "tol=1e-7") || (r.family == "static" && dbl && r.setting == "N=8") ||
                      (r.family == "swept" && dbl);
    if (keep) std::printf("%s\n", gjkx::study::formatToiRow(r).c_str());
  }
  std::printf("\n== CCD benchmark sample queries (ours, double) ==\n");
  if (toi.ccd.empty()) std::printf("%s\n", toi.ccdNote.c_str());
  for (const auto& c : toi.ccd)
    std::printf("CCD tolerance=%.0e queries=%lld fn=%lld fp=%lld us_per_query=%.3f\n", c.tolerance, c.queries, c.fn, c.fp, c.usPerQuery);
  std::printf("time of impact comparison done at %.1f s\n\n", elapsed());

  for (const auto& line : gjkx::study::toiRatioLines(toi.rows)) ratioLines.push_back(line);
  for (const auto& line : ratioLines) std::printf("%s\n", line.c_str());
  for (const auto& line : gjkx::study::toiMissLines(toi.rows)) std::printf("%s\n", line.c_str());
  return 0;
}
