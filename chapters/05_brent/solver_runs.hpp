// Chapter 05's runs of the time-of-impact solver (§5) and the functions its figures draw: the
// solver's result with its trace (ToiTrace), the true maximum supporting distance over time
// (§4), and the approximation of one complete extrusion test (§5).
#pragma once

#include "../chapter.hpp"

#include <gjkx/brent/time_of_impact.hpp>
#include <gjkx/gjk/gjk.hpp>
#include <gjkx/support_mapping/placed.hpp>
#include <gjkx/support_mapping/polytope.hpp>
#include <gjkx/supporting_distance/supporting_distance.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

namespace brent_figures {

using namespace gjkx;
using V = Vector3<double>;
using Body = Moving<Polytope<double>>;

/// The collision tolerance of the figures' solver runs (the library's default is sqrt(eps)):
/// 0.05, so that its band can be seen.
constexpr double kTol = 0.05;
/// Unit directions for the penetration depth, half a degree apart.
constexpr int kDirections = 720;

/// `count` unit directions of the plane z = 0, evenly spaced.
inline std::vector<V> unitDirections(int count) {
  std::vector<V> dirs;
  for (int k = 0; k < count; ++k) dirs.push_back(V(std::cos(2 * M_PI * k / count), std::sin(2 * M_PI * k / count), 0));
  return dirs;
}

/// One run of the solver over [0, 1]: its settings, its result and its trace.
struct Run {
  ToiSettings<double> settings;
  ToiResult<double> result;
  ToiTrace<double> trace;
  /// The collision tolerance the run used.
  double tolerance() const { return settings.collisionTolerance; }
};

/// Runs the solver on P and Q over [0, 1] with `settings`, and says what it found on
/// standard output.
inline Run solve(const Body& P, const Body& Q, const ToiSettings<double>& settings) {
  Run run;
  run.settings = settings;
  run.result = timeOfImpact(P, Q, 0.0, 1.0, settings, &run.trace);
  std::printf("status %s", toString(run.result.status));
  if (reportsCollision(run.result.status))
    std::printf(", time of impact %.6f (distance %.6f)", run.result.time, run.result.distance);
  std::printf(", Brent iterations %d, GJK runs %d, restarts %d\n", run.result.brentIterations, run.result.gjkRuns,
              run.result.restarts);
  return run;
}

/// The true maximum supporting distance at t (§4): "equivalent to the closest distance when
/// P and Q are disjoint" (GJK), and "the penetration distance when they intersect", where
/// "an exhaustive search may be required" (here over kDirections unit directions).
inline double trueMaximumSd(const Body& P, const Body& Q, double t) {
  static const std::vector<V> dirs = unitDirections(kDirections);
  const auto Pt = P.at(t);
  const auto Qt = Q.at(t);
  const GjkResult<double> run = gjk(Pt, Qt);
  return run.status == GjkStatus::Overlapping ? maximumSupportingDistance(Pt, Qt, dirs).value : run.distance;
}

/// The approximation of one complete test: the maximum of SD(P(t), Q(t), s_k) over the
/// separating vectors s_k it stored at its start (§5).
inline double approximateMaximumSd(const Body& P, const Body& Q, const ToiInterval<double>& test, double t) {
  double value = -1e300;
  for (int k = 0; k < test.separating.count; ++k)
    value = std::max(value, supportingDistanceAt(P, Q, test.separating.vectors[k], t));
  return value;
}

}  // namespace brent_figures
