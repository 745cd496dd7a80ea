// gjkx_paper_claims, §2: GJK's iteration counts, the kept simplex and the boolean query on
// random polytope pairs, as distributions per vertex count (paper_claims.cpp writes them).
//
// Workload: for each of 12, 100 and 1000 vertices, `pairs` disjoint pairs of random
// polytopes (the study's generator, gjkx/study/workloads.hpp) at random poses. A cold query
// starts from s_0 = centre to centre; a warm one after Q moved 1 mm and turned 1 degree,
// from the last query's simplex (§2.2: "the work from the previous query [...] can be used
// to reinitialize the current query").
#pragma once

#include "../formatting.hpp"

#include <gjkx/gjk/gjk.hpp>
#include <gjkx/study/workloads.hpp>
#include <gjkx/support_mapping/placed.hpp>
#include <gjkx/supporting_distance/intersection.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <map>
#include <string>
#include <vector>

namespace claims {

/// A distribution of counts (iterations, stored vectors, ...): mean, worst, the share
/// below a bound, and how many runs took each count.
struct Counts {
  std::vector<int> values;  ///< one count per run
  void add(int v) { values.push_back(v); }
  /// The arithmetic mean over every run.
  double mean() const {
    double s = 0;
    for (int v : values) s += v;
    return values.empty() ? 0 : s / double(values.size());
  }
  /// The largest count.
  int max() const { return values.empty() ? 0 : *std::max_element(values.begin(), values.end()); }
  /// The share of runs whose count is strictly below `bound`.
  double shareBelow(int bound) const {
    long n = 0;
    for (int v : values) n += v < bound;
    return values.empty() ? 0 : double(n) / double(values.size());
  }
  /// How many runs took exactly `v`.
  long runsWith(int v) const { return long(std::count(values.begin(), values.end(), v)); }
  /// "mean 4.23, max 11, 96.3% below 8 (300 runs)".
  std::string summary(int below) const {
    return "mean " + chapter::format("%.2f", mean()) + ", max " + std::to_string(max()) + ", " +
           chapter::format("%.1f", 100 * shareBelow(below)) + "% below " + std::to_string(below) + " (" +
           std::to_string(values.size()) + " runs)";
  }
};

/// The vertex counts of the GJK workload, the paper's range "12 to 1000".
inline const std::vector<int>& polytopeSizes() {
  static const std::vector<int> sizes{12, 100, 1000};
  return sizes;
}

/// Everything measured on GJK: over all sizes, and per vertex count for the histograms.
struct GjkClaims {
  Counts cold;     ///< iterations of a cold distance query (GjkResult::iterations)
  Counts warm;     ///< iterations of the warm distance query (GjkCache from the cold one)
  Counts simplex;  ///< the largest kept simplex of each cold run (vertices of V_Z)
  Counts boolean;  ///< iterations of the boolean query (intersect) on the cold pose
  std::map<int, Counts> coldBySize, warmBySize;  ///< the same, per vertex count
  double booleanSeconds = 0, distanceSeconds = 0;  ///< wall time of 20 repetitions of each (the fastest of 3 rounds), summed over the pairs
};

/// Measures GJK on `pairs` disjoint random polytope pairs of each size (seed 29: the same
/// counts on every machine; only the two times depend on it).
inline GjkClaims measureGjk(int pairs) {
  using namespace gjkx;
  using namespace gjkx::study;
  GjkClaims out;
  gen::Random rng(29);
  for (int n : polytopeSizes()) {
    for (int k = 0; k < pairs; ++k) {
      const auto axes = [&] { return Eigen::Vector3d(rng.uniform(0.3, 0.6), rng.uniform(0.3, 0.6), rng.uniform(0.2, 0.5)); };
      const Polytope<double> P = std::get<Polytope<double>>(ourShape<double>(gen::randomPolytope(rng, n, axes())));
      const Polytope<double> Q = std::get<Polytope<double>>(ourShape<double>(gen::randomPolytope(rng, n, axes())));
      Pose<double> poseP, poseQ;
      poseP.rotation = rng.rotation();
      poseQ.rotation = rng.rotation();
      poseQ.translation = rng.unit() * rng.uniform(1.3, 2.0);  // bounding radii at most 0.6 each: disjoint
      GjkTrace<double> trace;
      GjkCache<double> cache;
      const auto placedP = gjkx::place(P, poseP);
      const GjkResult<double> cold = gjk(placedP, gjkx::place(Q, poseQ), GjkSettings<double>{}, &cache, trace);
      if (cold.status != GjkStatus::Separated) continue;
      out.cold.add(cold.iterations);
      out.coldBySize[n].add(cold.iterations);
      int largest = 0;
      for (const auto& it : trace.iterations) largest = std::max(largest, it.simplex.size);
      out.simplex.add(largest);
      // Warm: Q moved a little (1 mm along a random direction, turned by 1 degree), GJK
      // started from the last simplex (§2.2: "the work from the previous query").
      Pose<double> moved = poseQ;
      moved.translation += rng.unit() * 0.001;
      moved.rotation = Eigen::AngleAxisd(M_PI / 180, rng.unit()).toRotationMatrix() * moved.rotation;
      const int warm = gjk(placedP, gjkx::place(Q, moved), GjkSettings<double>{}, &cache).iterations;
      out.warm.add(warm);
      out.warmBySize[n].add(warm);
      // The boolean query (§2.3) on the first pose: it stops at the first separating vector.
      out.boolean.add(intersect(placedP, gjkx::place(Q, poseQ)).iterations);
      // Each query 20 times in a row, timed; three such rounds, alternating the two kinds,
      // and the fastest round of each kept, so that a round preempted on a shared machine
      // does not count.
      const int reps = 20;
      int sink = 0;
      double booleanBest = 1e300, distanceBest = 1e300;
      for (int round = 0; round < 3; ++round) {
        auto start = std::chrono::steady_clock::now();
        for (int r = 0; r < reps; ++r) sink += intersect(placedP, gjkx::place(Q, poseQ)).iterations;
        booleanBest = std::min(booleanBest, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
        start = std::chrono::steady_clock::now();
        for (int r = 0; r < reps; ++r) sink += gjk(placedP, gjkx::place(Q, poseQ)).iterations;
        distanceBest = std::min(distanceBest, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
      }
      out.booleanSeconds += booleanBest;
      out.distanceSeconds += distanceBest;
      if (sink < 0) std::fprintf(stderr, "?");
    }
  }
  return out;
}

/// The histograms of GJK's iterations as a Markdown table: one row per query kind (cold,
/// warm) and vertex count, one column per iteration count from 1 to the largest seen, each
/// cell the number of runs that took exactly that many iterations (empty for none).
inline std::string gjkHistograms(const GjkClaims& g) {
  int largest = std::max(g.cold.max(), g.warm.max());
  std::string md = "| query | vertices | runs | mean |";
  for (int i = 1; i <= largest; ++i) md += " " + std::to_string(i) + " |";
  md += "\n| --- | --- | --- | --- |";
  for (int i = 1; i <= largest; ++i) md += " --- |";
  md += "\n";
  auto row = [&](const std::string& kind, int n, const Counts& c) {
    md += "| " + kind + " | " + std::to_string(n) + " | " + std::to_string(c.values.size()) + " | " +
          chapter::format("%.2f", c.mean()) + " |";
    for (int i = 1; i <= largest; ++i) {
      const long k = c.runsWith(i);
      md += k ? " " + std::to_string(k) + " |" : " |";
    }
    md += "\n";
  };
  for (int n : polytopeSizes())
    if (g.coldBySize.count(n)) row("cold", n, g.coldBySize.at(n));
  for (int n : polytopeSizes())
    if (g.warmBySize.count(n)) row("warm", n, g.warmBySize.at(n));
  return md;
}

}  // namespace claims
