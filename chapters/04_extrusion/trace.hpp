// Chapter 04's traces (--trace, docs/traces.md): for a pair of moving bodies, the extrusion
// test's steps (§3: each s_i of GJK at t_0, its SD at t_0 and at t_1) and the §5 solver's
// iterates behind it (chapter 05's tables).
#pragma once

#include "../05_brent/toi_trace.hpp"
#include "moving_pair.hpp"

#include <gjkx/brent/time_of_impact.hpp>
#include <gjkx/extrusion/extrusion.hpp>

#include <cmath>
#include <string>

namespace extrusion_figures {

/// The settings of the chapter's tests: the library's defaults, or a reader's collision tolerance.
struct TestSettings {
  ExtrusionSettings<double> extrusion;
  ToiSettings<double> toi;
};

/// Prints the extrusion test of `pair` over [t_0, t_1] step by step (the GJK iteration i at t_0,
/// s_i, SD(P(t_0), Q(t_0), s_i), SD at t_1 where s_i separates at t_0, and whether s_i
/// separates at both ends: then the test succeeds, "no collision"), then the §5 solver's trace.
inline void printPairTrace(const std::string& title, const Pair& pair, const TestSettings& settings) {
  ExtrusionTrace<double> steps;
  const auto test = extrusionTest(pair.P, pair.Q, t0, t1, settings.extrusion, nullptr, steps);
  chapter::TraceTable table{title + ": the extrusion test (§3)",
                            {"i", "s_i", "SD at t_0", "SD at t_1", "separates at t_0", "at both ends"}, {}};
  for (const auto& step : steps.steps)
    table.rows.push_back({step.i < 0 ? "remembered" : std::to_string(step.i), chapter::pointCell(step.s, 4),
                          chapter::fixed(step.sdStart, 6),
                          std::isfinite(step.sdEnd) ? chapter::fixed(step.sdEnd, 6) : "-",
                          step.separatesStart ? "yes" : "no", step.separatesEnd ? "yes" : "no"});
  table.print();
  std::printf("%s: extrusion test %s\n\n", title.c_str(), toString(test.status));
  ToiTrace<double> toiTrace;
  const auto toi = timeOfImpact(pair.P, pair.Q, t0, t1, settings.toi, &toiTrace);
  brent_figures::printToiTrace(title, toiTrace, toi, t1);
}

}  // namespace extrusion_figures
