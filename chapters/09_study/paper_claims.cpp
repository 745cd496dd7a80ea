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
// the simulation's statistics, and the torso model itself for the scene's size (bodies and
// triangles). Under the table, GJK's iterations as a histogram per vertex count
// (paper_claims_gjk.hpp). Every count is the same on every machine; the one time
// ratio (the boolean query against the distance query) is measured here. With --out the
// table is written as Markdown (figures/data/paper-claims.md); it always goes to standard
// output.
#include "../command_line.hpp"
#include "../formatting.hpp"
#include "paper_claims_gjk.hpp"
#include "paper_claims_torso.hpp"

#include <gjkx/brent/time_of_impact.hpp>
#include <gjkx/extrusion/static_sampling.hpp>
#include <gjkx/extrusion/sweeping.hpp>
#include <gjkx/study/workloads.hpp>

#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

using namespace gjkx;
using namespace gjkx::study;
using chapter::format;

namespace {

using claims::Counts;

struct Row {
  std::string claim, where, definition, paper, ours, workload;
};

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

  const claims::GjkClaims g = claims::measureGjk(pairs);
  WorkloadOptions options;
  options.queriesPerWorkload = queries;
  const std::vector<ToiWorkload> workloads = makeWorkloads(options);
  const double tol = double(defaultCollisionTolerance<float>());
  ToiSettings<double> paperSettings = ToiSettings<double>::paper(), oursSettings = ToiSettings<double>::gjkx();
  paperSettings.collisionTolerance = oursSettings.collisionTolerance = tol;
  const SolverClaims paper = measureSolver(workloads, paperSettings), ours = measureSolver(workloads, oursSettings);
  const OtherTests others = measureStaticAndSweeping(workloads);
  const claims::TorsoRun torsoP = claims::readTorso(torsoPaper), torsoG = claims::readTorso(torsoGjkx);
  const claims::TorsoSize torsoSize = claims::countTorso();
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
                  "the distance query's mean iterations and total time over the boolean query's (intersect, which stops at the first separating vector), same pairs; time: each query 20 times, the fastest of 3 rounds",
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
  rows.push_back({"(the same, in the simulation)", "§6", "as above, over a whole run", claims::torsoValue(torsoP, "brent"),
                  claims::torsoValue(torsoG, "brent"), torsoWorkload});
  rows.push_back({"\"an average 'photo-finish' false alarm rate of 70%\"", "§6",
                  "photo finishes over the queries that ran Brent (gjkx_simulate's photo_finish)",
                  pct(paper.photoFinishes, paper.brentQueries), pct(ours.photoFinishes, ours.brentQueries), toiWorkload});
  rows.push_back({"(the same, in the simulation)", "§6", "as above, over a whole run", claims::torsoValue(torsoP, "photo"),
                  claims::torsoValue(torsoG, "photo"), torsoWorkload});
  rows.push_back({"\"the ratio of execution time to simulation time ranged between 1.0 and 7.9\"", "§6",
                  "each frame's wall time over its simulated time (frames.csv), the smallest and the largest",
                  claims::torsoValue(torsoP, "ratio"), claims::torsoValue(torsoG, "ratio"), torsoWorkload});
  rows.push_back({"\"the peak at t ≈ 2 sec\"", "§6", "the simulated time of the frame with the largest wall time",
                  claims::torsoValue(torsoP, "peak"), claims::torsoValue(torsoG, "peak"), torsoWorkload});
  // The scene's size: counted from the model, so the same for both solvers.
  auto grouped = [](long n) {  // 24744 -> "24,744", as the paper writes its counts
    std::string digits = std::to_string(n);
    for (int i = int(digits.size()) - 3; i > 0; i -= 3) digits.insert(std::size_t(i), ",");
    return digits;
  };
  const std::string modelWorkload =
      "the torso model as `gjkx_generate_torso --out T` writes it (chapters/08_torso/torso_model.hpp; every seed the same meshes)";
  const std::string bones = grouped(torsoSize.bodies) + " bodies, " + grouped(torsoSize.boneTriangles) + " triangles";
  rows.push_back({"\"80 nonconvex rigid bodies and 24,790 triangles in total\"", "§6",
                  "the moving bodies of the scene (one per bone mesh) and the triangles of their meshes, summed",
                  bones, bones + " (the same scene)", modelWorkload});
  const std::string plant = grouped(torsoSize.plantTriangles) + " triangles";
  rows.push_back({"\"an aquatic plant fixed in space with 8640 triangles\"", "§6",
                  "the triangles of the static plant's mesh", plant, plant + " (the same scene)", modelWorkload});

  std::ostringstream md;
  md << "<!-- Written by gjkx_paper_claims --out (chapters/09_study/paper_claims.cpp); do not edit. -->\n\n";
  md << "| claim | § | measured as | §5 as written (paper) | ours (gjkx) | workload |\n";
  md << "| --- | --- | --- | --- | --- | --- |\n";
  for (const Row& r : rows)
    md << "| " << r.claim << " | " << r.where << " | " << r.definition << " | " << r.paper << " | " << r.ours << " | "
       << r.workload << " |\n";
  // GJK's iterations as distributions per vertex count (the rows above pool the sizes).
  md << "\nGJK's iterations per vertex count (§2.2), the distributions behind the first two rows: how many of the "
     << pairs << " pairs of each size took 1, 2, 3, ... iterations, cold (s_0 from centre to centre) and warm (Q moved "
        "1 mm and turned 1 degree, started from the last simplex). The paper: cold \"generally less than eight\", "
        "warm \"one or two iterations on the average\".\n\n"
     << claims::gjkHistograms(g);
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
