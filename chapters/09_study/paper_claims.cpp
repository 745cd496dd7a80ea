// gjkx_paper_claims: the paper's quantitative claims, measured, in one table.
//
//   gjkx_paper_claims [--pairs N] [--queries N] [--torso-paper DIR] [--torso-gjkx DIR] [--out FILE.md]
//
// One row per claim: the paper's words, where it says them, what is measured and how
// (one definition per statistic, stated in the row), the measurement for §5 as the paper
// wrote it (`ToiSettings::paper()`, `gjkx_simulate --solver paper`) and for this project's
// solver (`ToiSettings::gjkx()`), and the workload. GJK's claims (§2) do not depend on the
// solver: one measurement serves both columns.
//
// Workloads: random polytope pairs of 12, 100 and 1000 vertices (the study's generator,
// gjkx/study/workloads.hpp), disjoint, at random poses, for GJK; the study's time-of-impact
// workloads (linear, ballistic and screw motions, near misses, thin plates, ...; each query
// with its long-double reference) for the extrusion test and Brent's method; and, when
// given, two runs of the torso scene of §6 (gjkx_simulate's summary.txt and frames.csv) for
// the simulation's statistics. Every count is the same on every machine; the one time
// ratio (the boolean query against the distance query) is measured here. With --out the
// table is written as Markdown (figures/data/paper-claims.md); it always goes to standard
// output.
#include "../command_line.hpp"
#include "../formatting.hpp"

#include <gjkx/brent/time_of_impact.hpp>
#include <gjkx/extrusion/static_sampling.hpp>
#include <gjkx/extrusion/sweeping.hpp>
#include <gjkx/study/workloads.hpp>
#include <gjkx/support_mapping/placed.hpp>
#include <gjkx/supporting_distance/intersection.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

using namespace gjkx;
using namespace gjkx::study;
using chapter::format;

namespace {

// A distribution of counts: mean, worst, and the share below a bound.
struct Counts {
  std::vector<int> values;
  void add(int v) { values.push_back(v); }
  double mean() const {
    double s = 0;
    for (int v : values) s += v;
    return values.empty() ? 0 : s / double(values.size());
  }
  int max() const { return values.empty() ? 0 : *std::max_element(values.begin(), values.end()); }
  double shareBelow(int bound) const {
    long n = 0;
    for (int v : values) n += v < bound;
    return values.empty() ? 0 : double(n) / double(values.size());
  }
  std::string summary(int below) const {
    return "mean " + format("%.2f", mean()) + ", max " + std::to_string(max()) + ", " +
           format("%.1f", 100 * shareBelow(below)) + "% below " + std::to_string(below) + " (" +
           std::to_string(values.size()) + " runs)";
  }
};

struct Row {
  std::string claim, where, definition, paper, ours, workload;
};

// ---- §2: GJK on random polytope pairs ------------------------------------------------

struct GjkClaims {
  Counts cold, warm, simplex, boolean;
  double booleanSeconds = 0, distanceSeconds = 0;
};

GjkClaims measureGjk(int pairs) {
  GjkClaims out;
  gen::Random rng(29);
  for (int n : {12, 100, 1000}) {
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
      int largest = 0;
      for (const auto& it : trace.iterations) largest = std::max(largest, it.simplex.size);
      out.simplex.add(largest);
      // Warm: Q moved a little (1 mm along a random direction, turned by 1 degree), GJK
      // started from the last simplex (§2.2: "the work from the previous query").
      Pose<double> moved = poseQ;
      moved.translation += rng.unit() * 0.001;
      moved.rotation = Eigen::AngleAxisd(M_PI / 180, rng.unit()).toRotationMatrix() * moved.rotation;
      out.warm.add(gjk(placedP, gjkx::place(Q, moved), GjkSettings<double>{}, &cache).iterations);
      // The boolean query (§2.3) on the first pose: it stops at the first separating vector.
      out.boolean.add(intersect(placedP, gjkx::place(Q, poseQ)).iterations);
      const int reps = 20;
      auto start = std::chrono::steady_clock::now();
      int sink = 0;
      for (int r = 0; r < reps; ++r) sink += intersect(placedP, gjkx::place(Q, poseQ)).iterations;
      out.booleanSeconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      start = std::chrono::steady_clock::now();
      for (int r = 0; r < reps; ++r) sink += gjk(placedP, gjkx::place(Q, poseQ)).iterations;
      out.distanceSeconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      if (sink < 0) std::fprintf(stderr, "?");
    }
  }
  return out;
}

// ---- §3, §5: the extrusion test and Brent's method on the study's workloads ------------

struct SolverClaims {
  Counts stored;         // separating vectors stored per complete test
  Counts brent;          // Brent iterations per query that ran Brent
  long photoFinishes = 0, brentQueries = 0;
  long linearQueries = 0, linearMisses = 0, linearFalseAlarms = 0, linearClear = 0, linearHits = 0;
  long rotatingQueries = 0, rotatingMisses = 0, rotatingHits = 0;
};

struct OtherTests {
  long hits = 0, clear = 0, staticMisses = 0, sweepFalseAlarms = 0;
};

SolverClaims measureSolver(const std::vector<ToiWorkload>& workloads, const ToiSettings<double>& settings) {
  SolverClaims out;
  for (const ToiWorkload& w : workloads) {
    const bool linear = w.name == "linear";
    for (const ToiQuery& q : w.queries) {
      ToiTrace<double> trace;
      const ToiResult<double> r = std::visit(
          [&](const auto& a, const auto& b) {
            return timeOfImpact(moving(a, toMotion<double>(q.motionP)), moving(b, toMotion<double>(q.motionQ)), 0.0,
                                1.0, settings, &trace);
          },
          ourShape<double>(q.P), ourShape<double>(q.Q));
      for (const ToiInterval<double>& test : trace.intervals)
        if (test.status != ExtrusionStatus::CollidingAtStart) out.stored.add(test.separating.count);
      if (r.brentIterations > 0) {
        ++out.brentQueries;
        out.brent.add(r.brentIterations);
        if (r.status == ToiStatus::PhotoFinish) ++out.photoFinishes;
      }
      const bool reported = reportsCollision(r.status);
      if (linear) {
        ++out.linearQueries;
        out.linearHits += q.refHit;
        out.linearClear += q.clearMiss;
        out.linearMisses += q.refHit && !reported;
        out.linearFalseAlarms += q.clearMiss && reported;
      } else if (q.motionP.rotates() || q.motionQ.rotates()) {
        ++out.rotatingQueries;
        out.rotatingHits += q.refHit;
        out.rotatingMisses += q.refHit && !reported;
      }
    }
  }
  return out;
}

OtherTests measureStaticAndSweeping(const std::vector<ToiWorkload>& workloads) {
  OtherTests out;
  for (const ToiWorkload& w : workloads)
    for (const ToiQuery& q : w.queries)
      std::visit(
          [&](const auto& a, const auto& b) {
            const auto P = moving(a, toMotion<double>(q.motionP));
            const auto Q = moving(b, toMotion<double>(q.motionQ));
            if (q.refHit) {
              ++out.hits;
              out.staticMisses += !staticTest(P, Q, 0.0, 1.0, 2);
            }
            if (q.clearMiss) {
              ++out.clear;
              out.sweepFalseAlarms += sweepingTest(P, Q, 0.0, 1.0).status != IntersectionStatus::Disjoint;
            }
          },
          ourShape<double>(q.P), ourShape<double>(q.Q));
  return out;
}

// ---- §6: a run of the torso scene ------------------------------------------------------

struct TorsoRun {
  bool found = false;
  std::map<std::string, std::string> summary;  // SUMMARY's key=value pairs
  double ratioMin = 0, ratioMax = 0, peakTime = 0;
};

TorsoRun readTorso(const std::string& dir) {
  TorsoRun run;
  if (dir.empty()) return run;
  std::ifstream summary(dir + "/summary.txt"), frames(dir + "/frames.csv");
  std::string line;
  if (!summary || !std::getline(summary, line)) return run;
  std::istringstream words(line);
  for (std::string word; words >> word;) {
    const auto eq = word.find('=');
    if (eq != std::string::npos) run.summary[word.substr(0, eq)] = word.substr(eq + 1);
  }
  // frames.csv: the wall time of each frame over its simulated time (1/24 s at the paper's rate).
  std::string header;
  if (!frames || !std::getline(frames, header)) return run;
  double lastTime = 0, peak = -1;
  run.ratioMin = 1e300;
  while (std::getline(frames, line)) {
    std::istringstream fields(line);
    std::string frame, time, wall;
    std::getline(fields, frame, ',');
    std::getline(fields, time, ',');
    std::getline(fields, wall, ',');
    const double t = std::stod(time), w = std::stod(wall), ratio = w / (t - lastTime);
    lastTime = t;
    run.ratioMin = std::min(run.ratioMin, ratio);
    run.ratioMax = std::max(run.ratioMax, ratio);
    if (w > peak) {
      peak = w;
      run.peakTime = t;
    }
  }
  run.found = true;
  return run;
}

std::string torsoValue(const TorsoRun& run, const std::string& what) {
  if (!run.found) return "not run (see the command)";
  if (what == "brent") return "mean " + run.summary.at("brent_mean") + ", max " + run.summary.at("brent_max");
  if (what == "photo")
    return format("%.1f", 100 * std::stod(run.summary.at("photo_finish"))) + "% of the queries that ran Brent";
  if (what == "ratio")
    return format("%.2f", run.ratioMin) + " to " + format("%.1f", run.ratioMax) + " (this machine, shared)";
  if (what == "peak") return "t = " + format("%.2f", run.peakTime) + " s";
  return "?";
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"The paper's quantitative claims, measured for §5 as written and for this project's solver, in one "
               "table.",
               "gjkx_paper_claims"};
  int pairs = 100, queries = 64;
  std::string torsoPaper, torsoGjkx, out;
  app.add_option("--pairs", pairs, "random polytope pairs per size (12, 100, 1000 vertices)")
      ->check(CLI::Range(1, 100000))
      ->capture_default_str();
  app.add_option("--queries", queries, "queries per time-of-impact workload")->check(CLI::Range(1, 100000))->capture_default_str();
  app.add_option("--torso-paper", torsoPaper, "a gjkx_simulate --solver paper run of the torso scene (its --out folder)");
  app.add_option("--torso-gjkx", torsoGjkx, "a gjkx_simulate run of the torso scene with our solver (its --out folder)");
  app.add_option("--out", out, "also write the table as Markdown to this file");
  chapter::parseOrExit(app, argc, argv);

  const GjkClaims g = measureGjk(pairs);
  WorkloadOptions options;
  options.queriesPerWorkload = queries;
  const std::vector<ToiWorkload> workloads = makeWorkloads(options);
  const double tol = double(defaultCollisionTolerance<float>());
  ToiSettings<double> paperSettings = ToiSettings<double>::paper(), oursSettings = ToiSettings<double>::gjkx();
  paperSettings.collisionTolerance = oursSettings.collisionTolerance = tol;
  const SolverClaims paper = measureSolver(workloads, paperSettings), ours = measureSolver(workloads, oursSettings);
  const OtherTests others = measureStaticAndSweeping(workloads);
  const TorsoRun torsoP = readTorso(torsoPaper), torsoG = readTorso(torsoGjkx);
  long toiQueries = 0;
  for (const ToiWorkload& w : workloads) toiQueries += long(w.queries.size());

  const std::string gjkWorkload = std::to_string(3 * pairs) + " disjoint random polytope pairs, " + std::to_string(pairs) +
                                  " each of 12, 100 and 1000 vertices, random poses";
  const std::string toiWorkload = "the study's " + std::to_string(workloads.size()) + " time-of-impact workloads, " +
                                  std::to_string(toiQueries) + " queries, tolerance " + format("%.3g", tol);
  const std::string torsoWorkload =
      "the torso scene (`gjkx_generate_torso --out T`, `gjkx_simulate T/scene.json --solver paper` or `--solver gjkx`)";
  auto same = [](const std::string& s) { return s + " (the same: GJK is not the solver)"; };
  auto pct = [](long a, long b) { return b > 0 ? format("%.0f", 100.0 * double(a) / double(b)) + "%" : std::string("-"); };

  std::vector<Row> rows;
  rows.push_back({"GJK completes \"generally [in] less than eight\" iterations", "§2.2",
                  "iterations of a cold distance query (GjkResult::iterations, s_0 from centre to centre)",
                  g.cold.summary(8), same(g.cold.summary(8)), gjkWorkload});
  rows.push_back({"warm, \"typically completing within one or two iterations on the average\"", "§2.2",
                  "iterations of the distance query after Q moved 1 mm and turned 1 degree, started from the last simplex (GjkCache)",
                  g.warm.summary(3), same(g.warm.summary(3)), gjkWorkload});
  rows.push_back({"\"V_P and V_Q will always contain three vertices or less\"", "§2.2",
                  "the largest kept simplex over every iteration of the cold runs (GjkIteration::simplex)",
                  "at most " + std::to_string(g.simplex.max()), same("at most " + std::to_string(g.simplex.max())),
                  gjkWorkload});
  const double speed = g.booleanSeconds > 0 ? g.distanceSeconds / g.booleanSeconds : 0;
  rows.push_back({"\"a boolean intersection test may execute several times faster than a complete closest distance query\"",
                  "§2.3, §4",
                  "the distance query's iterations and time over the boolean query's (intersect, which stops at the first separating vector), same pairs",
                  "iterations " + format("%.2f", g.cold.mean() / std::max(1e-300, g.boolean.mean())) + " times, time " +
                      format("%.1f", speed) + " times (this machine)",
                  same("as paper"), gjkWorkload});
  rows.push_back({"the stored separating vectors: \"a constant number, generally less than seven\"", "§5",
                  "separating vectors stored by each complete extrusion test that did not start within the tolerance",
                  paper.stored.summary(7), ours.stored.summary(7), toiWorkload});
  rows.push_back({"the extrusion test is exact under linear motion (\"never intersect if and only if their separating hyperspace is a convex set\")",
                  "§3",
                  "misses (a reference hit not reported) and false alarms (a hit reported on a clear miss) on the linear workload",
                  std::to_string(paper.linearMisses) + " misses of " + std::to_string(paper.linearHits) + ", " +
                      std::to_string(paper.linearFalseAlarms) + " false alarms of " + std::to_string(paper.linearClear),
                  std::to_string(ours.linearMisses) + " misses of " + std::to_string(ours.linearHits) + ", " +
                      std::to_string(ours.linearFalseAlarms) + " false alarms of " + std::to_string(ours.linearClear),
                  "linear, " + std::to_string(paper.linearQueries) + " queries"});
  rows.push_back({"under rotation the separating space \"may vanish undetected\" (\"practically negligible for sufficiently small time steps\")",
                  "§3",
                  "misses of the paper's extrusion test on the rotating queries (the certified variant, beyond the paper, has none: docs 09)",
                  std::to_string(paper.rotatingMisses) + " misses of " + std::to_string(paper.rotatingHits),
                  std::to_string(ours.rotatingMisses) + " misses of " + std::to_string(ours.rotatingHits) +
                      " (the paper's test too)",
                  std::to_string(paper.rotatingQueries) + " rotating queries of the study's workloads"});
  rows.push_back({"static tests \"often miss collisions\"; sweeping tests \"report false alarms\"", "§1",
                  "static test at t_0 and t_1 (staticTest, 2 samples): reference hits missed; sweeping test (the hulls at t_0 and t_1): clear misses reported",
                  "static: " + std::to_string(others.staticMisses) + " of " + std::to_string(others.hits) +
                      " hits missed; sweeping: " + std::to_string(others.sweepFalseAlarms) + " of " +
                      std::to_string(others.clear) + " clear misses reported",
                  same("as paper"), toiWorkload});
  rows.push_back({"\"the TOI solver completed in 2.2 iterations on the average, with a worst case of 43\"", "§6",
                  "Brent iterations per query that ran Brent (brentIterations > 0), averaged over those queries (gjkx_simulate's brent_mean)",
                  "mean " + format("%.2f", paper.brent.mean()) + ", max " + std::to_string(paper.brent.max()),
                  "mean " + format("%.2f", ours.brent.mean()) + ", max " + std::to_string(ours.brent.max()),
                  toiWorkload});
  rows.push_back({"(the same, in the simulation)", "§6", "as above, over a whole run", torsoValue(torsoP, "brent"),
                  torsoValue(torsoG, "brent"), torsoWorkload});
  rows.push_back({"\"an average 'photo-finish' false alarm rate of 70%\"", "§6",
                  "photo finishes over the queries that ran Brent (gjkx_simulate's photo_finish)",
                  pct(paper.photoFinishes, paper.brentQueries), pct(ours.photoFinishes, ours.brentQueries), toiWorkload});
  rows.push_back({"(the same, in the simulation)", "§6", "as above, over a whole run", torsoValue(torsoP, "photo"),
                  torsoValue(torsoG, "photo"), torsoWorkload});
  rows.push_back({"\"the ratio of execution time to simulation time ranged between 1.0 and 7.9\"", "§6",
                  "each frame's wall time over its simulated time (frames.csv), the smallest and the largest",
                  torsoValue(torsoP, "ratio"), torsoValue(torsoG, "ratio"), torsoWorkload});
  rows.push_back({"\"the peak at t ≈ 2 sec\"", "§6", "the simulated time of the frame with the largest wall time",
                  torsoValue(torsoP, "peak"), torsoValue(torsoG, "peak"), torsoWorkload});

  std::ostringstream md;
  md << "<!-- Written by gjkx_paper_claims --out (chapters/09_study/paper_claims.cpp); do not edit. -->\n\n";
  md << "| claim | § | measured as | §5 as written (paper) | ours (gjkx) | workload |\n";
  md << "| --- | --- | --- | --- | --- | --- |\n";
  for (const Row& r : rows)
    md << "| " << r.claim << " | " << r.where << " | " << r.definition << " | " << r.paper << " | " << r.ours << " | "
       << r.workload << " |\n";
  std::cout << md.str();
  if (!out.empty()) {
    std::ofstream file(out);
    file << md.str();
    if (!file) {
      std::cerr << "gjkx_paper_claims: cannot write " << out << "\n";
      return 1;
    }
  }
  return 0;
}
