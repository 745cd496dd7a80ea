// toi_profile: one method of the time-of-impact study run once per query, without timing
// loops, so that an instruction count under callgrind is repeatable and per query.
//
//   toi_profile [--method ours|certified|fcl_ca|bullet|box2d] [--workload NAME]... [--queries N] [--repeat N] [--tol T]
//               [--steps] [--dump N]
//
// Builds the quick workloads of workloads.hpp (40 queries each unless --queries), then runs
// the chosen method `--repeat` times (default 1) on every query of the chosen workloads
// (default: every 3D workload), and prints per workload: queries, hits reported, misses and
// false alarms against the reference, and for ours the mean GJK runs, Brent iterations,
// restarts and supporting distances per query. Under valgrind the counting is switched on
// only around the method's calls (callgrind client requests, when the header is there):
//
//   valgrind --tool=callgrind --instr-atstart=no build/chapters/09_study/toi_profile --workload linear
//   callgrind_annotate --inclusive=yes callgrind.out.<pid>
//
// The total instruction count divided by the "calls" line (queries x repeat) is the
// instruction count per query; the same command with --method fcl_ca gives the peer's.
//
// The planar set (`--workload planar_2d`) runs with ours, certified and box2d. For Box2D
// the line adds its own counters, read from the library: b2Distance calls and their
// iterations (one support pair each) per query, and b2TimeOfImpact's iterations (each
// finds the deepest points along a separating axis: one support pair) and its root
// finder's (one evaluation of that axis's separation: one support pair). Ours counts support-pair evaluations as `sd_evaluations` (every GJK
// iteration and every supporting distance of a stored vector). Instructions per query
// divided by evaluations per query, for each, splits the gap to Box2D into "how many
// evaluations" and "what one evaluation costs" (a 3D solver in the plane against a 2D one).
//
// `--steps` (ours) adds a STEPS line per workload from one more, traced, run of each query
// (outside the counting): where the Brent iterations go, by the rule that chose them
// (bisection, secant, inverse quadratic, minimal step, leap, advance) and by what followed
// (complete tests, i.e. restarts), and how the queries ended. `--dump N` prints the trace
// of query N of each workload chosen, one line per iterate and per complete test.
#include "../command_line.hpp"
#include "callgrind_markers.hpp"
#include "toi_comparisons.hpp"

#include <gjkx/study/peers_toi.hpp>

#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

using namespace gjkx;
using namespace gjkx::study;
namespace comparison = gjkx::study::detail;  // the time-of-impact comparison's own parts

namespace {

struct Options {
  std::string method = "ours";
  std::vector<std::string> workloads;
  int queries = 40;
  int repeat = 1;
  double tol = 1e-7;
  bool steps = false;
  int dump = -1;
};

Options parse(int argc, char** argv) {
  Options o;
  CLI::App app{"Runs one time-of-impact method once per query (no timing), for callgrind."};
  app.add_option("--method", o.method, "the method")
      ->check(CLI::IsMember({"ours", "certified", "fcl_ca", "bullet", "box2d"}))
      ->capture_default_str();
  app.add_option("--workload", o.workloads, "a workload to run (repeatable; default: every one the method runs on)")->type_name("NAME");
  app.add_option("--queries", o.queries, "queries per workload")->type_name("N")->check(CLI::PositiveNumber)->capture_default_str();
  app.add_option("--repeat", o.repeat, "calls per query")->type_name("N")->check(CLI::PositiveNumber)->capture_default_str();
  app.add_option("--tol", o.tol, "collision tolerance of ours")->type_name("T")->check(CLI::PositiveNumber)->capture_default_str();
  app.add_flag("--steps", o.steps, "ours: where the Brent iterations go (one more traced run per query)");
  app.add_option("--dump", o.dump, "ours: print the trace of this query of each workload")->type_name("N");
  chapter::parseOrExit(app, argc, argv);
  return o;
}

// Counters of ours over a workload.
struct Counts {
  long long gjkRuns = 0, brentIterations = 0, restarts = 0, sdEvaluations = 0;
  long long byKind[6] = {};          // Brent iterates by BrentStepKind
  long long separatingIterates = 0;  // iterates where the stored vectors separated: a complete test followed
  long long byStatus[7] = {};        // queries by ToiStatus
  int worstIterations = 0;
};

// The traced run of `--steps` and `--dump`: adds to the STEPS counters, prints query `index` if dumped.
void traceOurs(const comparison::Prepared<double>& p, const ToiSettings<double>& settings, int index, const Options& o,
               Counts& counts) {
  ToiTrace<double> trace;
  const ToiResult<double> r = comparison::runOurs(p, settings, 1, &trace);
  for (const ToiStep<double>& step : trace.steps) {
    ++counts.byKind[int(step.kind)];
    counts.separatingIterates += step.completeTest;
  }
  ++counts.byStatus[int(r.status)];
  counts.worstIterations = std::max(counts.worstIterations, r.brentIterations);
  if (index != o.dump) return;
  std::printf("DUMP query=%d status=%s time=%.17g distance=%.3g brent_iterations=%d restarts=%d sd_evaluations=%d\n", index,
              toString(r.status), r.time, r.distance, r.brentIterations, r.restarts, r.sdEvaluations);
  for (const ToiStep<double>& step : trace.steps)
    std::printf("  step  t=%.17g F=%.6g bracket=[%.17g, %.17g] %s%s\n", step.t, step.approximateMaxSd - settings.collisionTolerance,
                step.bracketLow, step.bracketHigh, toString(step.kind), step.completeTest ? " separates" : "");
  for (const ToiInterval<double>& test : trace.intervals)
    std::printf("  test  ta=%.17g distance=%.6g status=%s vectors=%d\n", test.start, test.distanceAtStart,
                toString(test.status), test.separating.count);
}

#if GJKX_HAVE_BOX2D
}  // namespace
// Box2D 2.4's own counters: defined and exported by the library (b2_distance.cpp,
// b2_time_of_impact.cpp), not declared in its installed headers.
extern int b2_gjkCalls, b2_gjkIters, b2_toiCalls, b2_toiIters, b2_toiRootIters;
namespace {
#endif

// `repeat` calls of `run` with callgrind counting (when built with valgrind's header);
// the last call's answer.
template <typename Run>
auto profiled(int repeat, Run run) {
  decltype(run()) r{};
  GJKX_PROFILE_START();
  for (int k = 0; k < repeat; ++k) r = run();
  GJKX_PROFILE_STOP();
  return r;
}

// One run of ours (double), keeping the solver's own counters.
comparison::Outcome runOurs(const comparison::Prepared<double>& p, const Options& o, Counts& counts, int index) {
  const ToiSettings<double> settings =
      toiSettings<double>(o.tol, o.method == "certified" ? ExtrusionVariant::Certified : ExtrusionVariant::Paper);
  const ToiResult<double> r = comparison::runOurs(p, settings, o.repeat);
  counts.gjkRuns += r.gjkRuns;
  counts.brentIterations += r.brentIterations;
  counts.restarts += r.restarts;
  counts.sdEvaluations += r.sdEvaluations;
  if (o.steps || o.dump >= 0) traceOurs(p, settings, index, o, counts);
  return comparison::Outcome{reportsCollision(r.status), r.time, r.gjkRuns};
}

}  // namespace

int main(int argc, char** argv) {
  const Options o = parse(argc, argv);
  WorkloadOptions wo;
  wo.queriesPerWorkload = o.queries;
  const std::vector<ToiWorkload> workloads = makeWorkloads(wo);
  bool any = false;
  for (const ToiWorkload& w : workloads) {
    const bool box2d = o.method == "box2d", ours = o.method == "ours" || o.method == "certified";
    if (box2d && !w.planar) continue;                         // Box2D: the planar set only
    if (!box2d && !ours && w.planar) continue;                // FCL, Bullet: the 3D workloads only
    if (ours && w.planar && o.workloads.empty()) continue;    // ours: the planar set when it is named
    if (!o.workloads.empty() && std::find(o.workloads.begin(), o.workloads.end(), w.name) == o.workloads.end()) continue;
    any = true;
    int hits = 0, misses = 0, falseAlarms = 0;
    Counts counts;
#if GJKX_HAVE_BOX2D
    b2_gjkCalls = b2_gjkIters = b2_toiCalls = b2_toiIters = b2_toiRootIters = 0;
#endif
    int index = 0;
    for (const ToiQuery& q : w.queries) {
      comparison::Outcome out;
      // A peer's query object, run `repeat` times under the profiler.
      const auto runPeer = [&](const auto& query) {
        const peers::PeerOutcome r = profiled(o.repeat, [&] { return query.run(); });
        return comparison::Outcome{r.hit, r.time};
      };
      (void)runPeer;  // (unused when no peer was found at build time)
      if (ours) {
        const comparison::Prepared<double> p(q);
        out = runOurs(p, o, counts, index);
      } else if (o.method == "fcl_ca") {
#if GJKX_HAVE_FCL
        const peers::FclQuery fcl(q);
        const peers::PeerOutcome r = profiled(o.repeat, [&] { return fcl.run(true, 1e-4, fcl::GST_LIBCCD); });
        out = comparison::Outcome{r.hit, r.time};
#else
        std::fprintf(stderr, "toi_profile: FCL was not found at build time\n");
        return 1;
#endif
      } else if (box2d) {
#if GJKX_HAVE_BOX2D
        out = runPeer(peers::Box2dQuery(q));
#else
        std::fprintf(stderr, "toi_profile: Box2D was not found at build time\n");
        return 1;
#endif
      } else {
#if GJKX_HAVE_BULLET
        out = runPeer(peers::BulletQuery(q));
#else
        std::fprintf(stderr, "toi_profile: Bullet was not found at build time\n");
        return 1;
#endif
      }
      ++index;
      hits += out.hit;
      misses += q.refHit && !out.hit;
      falseAlarms += q.clearMiss && out.hit;
    }
    const double n = double(w.queries.size());
    std::printf("PROFILE method=%s workload=%s queries=%zu repeat=%d calls=%lld hits=%d misses=%d false_alarms=%d", o.method.c_str(),
                w.name.c_str(), w.queries.size(), o.repeat, (long long)w.queries.size() * o.repeat, hits, misses, falseAlarms);
    if (ours)
      std::printf(" gjk_runs=%.2f brent_iterations=%.2f restarts=%.2f sd_evaluations=%.2f", counts.gjkRuns / n,
                  counts.brentIterations / n, counts.restarts / n, counts.sdEvaluations / n);
#if GJKX_HAVE_BOX2D
    if (box2d)
      std::printf(" distance_calls=%.2f distance_iterations=%.2f toi_iterations=%.2f root_iterations=%.2f", b2_gjkCalls / n / o.repeat,
                  b2_gjkIters / n / o.repeat, b2_toiIters / n / o.repeat, b2_toiRootIters / n / o.repeat);
#endif
    std::printf("\n");
    if (ours && o.steps) {
      std::printf("STEPS method=%s workload=%s", o.method.c_str(), w.name.c_str());
      for (int k = 0; k < 6; ++k)
        if (counts.byKind[k]) std::printf(" %s=%.2f", toString(BrentStepKind(k)), counts.byKind[k] / n);
      std::printf(" separating_iterates=%.2f worst_iterations=%d ends:", counts.separatingIterates / n, counts.worstIterations);
      for (int k = 0; k < 7; ++k)
        if (counts.byStatus[k]) std::printf(" %s=%lld", toString(ToiStatus(k)), counts.byStatus[k]);
      std::printf("\n");
    }
  }
  if (!any) {
    std::fprintf(stderr, "toi_profile: no workload matched for this method\n");
    return 2;
  }
  return 0;
}
