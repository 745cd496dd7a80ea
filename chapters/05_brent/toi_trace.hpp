// The time-of-impact solver's trace (§5) as tables on standard output (--trace of chapters
// 04 and 05): one row per Brent iterate t_x with the bracket it was taken in, the rule that
// chose it and the approximate maximum supporting distance there, then one row per complete
// extrusion test.
#pragma once

#include "../chapter.hpp"

#include <gjkx/brent/time_of_impact.hpp>

#include <string>

namespace brent_figures {

using namespace gjkx;

/// What followed iterate `step` of a run traced in `trace`: Brent went on (the approximate
/// maximum SD was below the tolerance), or a complete extrusion test started at t_x (a
/// restart, the check at the far end of a converged bracket, or the probe's test) and its verdict.
inline std::string stepThen(const ToiTrace<double>& trace, const ToiStep<double>& step) {
  std::string then = "< tol: Brent goes on";
  for (const auto& test : trace.intervals)
    if (test.start == step.t && test.start > 0)
      then = step.kind == BrentStepKind::DistanceSecant
                 ? "probe: test \u2192 " + std::string(toString(test.status)) +
                       (step.completeTest ? ", proven" : ", far end")
                 : (step.completeTest ? "\u2265 tol: complete test \u2192 " : "converged: test at t_b \u2192 ") +
                       std::string(toString(test.status));
  return then;
}

/// Prints the solver's run on [t0, t1] as two tables under `title`: its iterates (the bracket
/// [t_a, t_b], t_x, the step's kind as BrentStepKind names it, the approximate maximum SD at
/// t_x, what followed) and its complete extrusion tests (start, verdict, exact distance at the
/// start, the separating vectors stored), then the result.
inline void printToiTrace(const std::string& title, const ToiTrace<double>& trace, const ToiResult<double>& result,
                          double t1 = 1.0) {
  using chapter::format;
  chapter::TraceTable steps{title + ": Brent's iterates (§5)", {"#", "t_a", "t_b", "t_x", "kind", "approx max SD", "then"}, {}};
  for (std::size_t i = 0; i < trace.steps.size(); ++i) {
    const auto& step = trace.steps[i];
    steps.rows.push_back({std::to_string(i + 1), format("%.6f", step.bracketLow), format("%.6f", step.bracketHigh),
                          format("%.6f", step.t), toString(step.kind), format("%.6f", step.approximateMaxSd),
                          stepThen(trace, step)});
  }
  steps.print();
  chapter::TraceTable tests{title + ": complete extrusion tests (§3)",
                            {"#", "interval", "verdict", "distance at start", "stored s_k"}, {}};
  for (std::size_t k = 0; k < trace.intervals.size(); ++k) {
    const auto& test = trace.intervals[k];
    tests.rows.push_back({std::to_string(k + 1), "[" + format("%.6f", test.start) + ", " + format("%g", t1) + "]",
                          toString(test.status), format("%.6f", test.distanceAtStart),
                          std::to_string(test.separating.count)});
  }
  tests.print();
  std::printf("%s: result %s", title.c_str(), toString(result.status));
  if (reportsCollision(result.status)) std::printf(" at t = %.6f (distance %.6f)", result.time, result.distance);
  std::printf(", %d Brent iterations, %d restarts\n\n", result.brentIterations, result.restarts);
}

}  // namespace brent_figures
