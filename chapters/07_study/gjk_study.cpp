// The GJK comparison of the study (chapter 07): ours against libccd, FCL and Bullet on
// distance and boolean queries, cold and warm-started, with the disagreement against an
// exact reference. Prints one table per workload and ends with the RATIO lines
// (ours-double median time / the best peer's, measured in this run).
//
//   gjk_study [--quick] [--seed N]
//
// What each column means, and how the shapes, poses and references are made:
// gjk_comparisons.hpp; how each peer is called (margins, warm starts): peers_gjk.hpp.
#include "gjk_comparisons.hpp"

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

int main(int argc, char** argv) {
  gjkx::study::GjkStudyOptions options;
  for (int k = 1; k < argc; ++k) {
    if (!std::strcmp(argv[k], "--quick")) {
      options.quick = true;
    } else if (!std::strcmp(argv[k], "--seed") && k + 1 < argc) {
      options.seed = unsigned(std::strtoul(argv[++k], nullptr, 10));
    } else {
      std::fprintf(stderr, "usage: %s [--quick] [--seed N]\n", argv[0]);
      return 2;
    }
  }
  std::printf("GJK comparison (%s run, seed %u); %s\n", options.quick ? "quick" : "full", options.seed, gjkx::study::peersPresent().c_str());
  std::printf("time per query: median and p99 over batches of 16; distance error |d - d_ref| (overlap = 0);\n");
  std::printf("boolean: wrong answers / judged queries against the exact reference\n");
  const auto rows = gjkx::study::runGjkComparisons(options);
  std::string last;
  for (const auto& r : rows) {
    if (r.workload != last) {
      if (!last.empty()) std::printf("  best peer: %s\n", gjkx::study::gjkBestPeer(rows, last).c_str());
      std::printf("\n%s (%d queries)\n", r.workload.c_str(), r.queries);
      last = r.workload;
    }
    std::printf("  %s\n", gjkx::study::formatGjkRow(r).c_str());
  }
  if (!last.empty()) std::printf("  best peer: %s\n", gjkx::study::gjkBestPeer(rows, last).c_str());
  std::printf("\n");
  for (const auto& line : gjkx::study::gjkRatioLines(rows)) std::printf("%s\n", line.c_str());
  return 0;
}
