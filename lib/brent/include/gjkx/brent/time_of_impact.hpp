/// @file
/// @brief The time-of-impact solver of §5: the extrusion test of §3 driven by Brent's method.
///
/// §5: "If the initial extrusion test at \f$t_0\f$ and \f$t_1\f$ fails, we use the closest distance
/// at \f$t_0\f$ and the approximate maximum supporting distance at \f$t_1\f$ to calculate an
/// intermediate time \f$t_x\f$ using Brent's method. [...] we can speed up this intermediate
/// query by storing all the separating vectors \f$\vec{s}_i\f$ we found at \f$t_0\f$, and use this set
/// [...] to recalculate \f$SD(P(t_x), Q(t_x), \vec{s}_i)\f$ and obtain a new approximate maximum
/// supporting distance at \f$t_x\f$. If this distance is negative, we continue normally with
/// further iterations of Brent's method. However, if this distance is positive, we assume
/// P and Q are disjoint from \f$t_0\f$ to \f$t_x\f$, so we recompute a complete GJK extrusion test
/// for \f$t_x\f$ and \f$t_1\f$ in order to determine the exact closest distance at \f$t_x\f$ before we
/// proceed."
///
/// The function Brent solves on the current interval \f$[t_a, t_1]\f$ is
/// \f[ F(t) = \max_k SD(P(t), Q(t), \vec{s}_k) - m(t - t_a) - \mathrm{tol}, \f]
/// the approximate maximum supporting distance from the stored vectors \f$\vec{s}_k\f$, less the
/// certified margin m (zero for the paper's variant) and the collision tolerance: its root
/// is where the bodies come within the tolerance. \f$F(t_a) > 0\f$ (the exact distance at
/// \f$t_a\f$ exceeds the tolerance) and \f$F(t_1) \le 0\f$ (the extrusion test failed), so it is
/// a bracket. At each iterate \f$t_x\f$:
/// - approximate maximum SD below the tolerance (\f$F(t_x) < 0\f$): no stored vector
///   separates at \f$t_x\f$ by the tolerance; Brent goes on;
/// - at least the tolerance (\f$F(t_x) \ge 0\f$): \f$[t_a, t_x]\f$ is free of contact; a complete
///   extrusion test on \f$[t_x, t_1]\f$ then either succeeds (a *photo finish*: no collision,
///   proven on a chain of intervals), finds the bodies within the tolerance at \f$t_x\f$ (the
///   *time of impact*: "the maximum supporting distance is positive and smaller than the
///   collision tolerance"), or fails again, and Brent restarts on \f$[t_x, t_1]\f$ with the
///   new vectors.
/// "Positive" is read here as the extrusion test reads it (extrusion.hpp): above the
/// collision tolerance. A stored vector \f$\vec{s}_k\f$ has \f$SD > \mathrm{tol}\f$ at \f$t_a\f$; if its SD
/// is also \f$\ge \mathrm{tol}\f$ at \f$t_x\f$, then (linear in t for linear motion, concave for per-vertex
/// linear motion, within the margin of the chord for the certified variant) it stays
/// \f$\ge \mathrm{tol}\f$ on all of \f$[t_a, t_x]\f$: the bodies do not come within the tolerance
/// there. Merely positive (between 0 and tol) would prove only that they do not
/// interpenetrate: a pass within the tolerance between \f$t_a\f$ and \f$t_x\f$ would then go
/// unseen (a photo finish if the bodies are apart again at \f$t_x\f$), and a hit at \f$t_x\f$
/// could come long after the bodies first came within the tolerance, for a slow grazing
/// approach (both found by tests/brent/test_time_of_impact_random.cpp on grazing passes).
/// When Brent's bracket \f$[t_a, t_b]\f$ shrinks below the time tolerance, the time of impact is
/// \f$t_b\f$ if the stored vectors still separate there (approximate maximum SD > 0) and the
/// exact distance there is within the tolerance (the paper's criterion above), else the
/// last time proven free of contact, \f$t_a\f$ (the distance there exceeds the tolerance by at
/// most what the bodies move in one time tolerance, plus GJK's own uncertainty). Every
/// reported time is one at which the bodies do not interpenetrate, and no later than the
/// first time they come within the tolerance (plus the time tolerance).
///
/// Beyond the paper, refinements make a query cheaper without changing what it proves,
/// each a switch of `ToiSettings` (all off in `ToiSettings::paper()`, which runs §5 as
/// written; all on in `ToiSettings::gjkx()`, the default): each complete test after the
/// first starts GJK from the last one's simplex (`warmStart`, an `ExtrusionCache`) and
/// the first from the pair's last query (`coherence`); each stored vector keeps where its
/// support searches ended (`supportHints`, its hill-climbing hints); after a restart the
/// bracket's far end is the nearest known point where the new vectors are below the
/// tolerance (`farEndReuse`), so that Brent does not creep towards a far t1 one restart at
/// a time; a *probe* goes straight to where the exact distances extrapolate to the
/// tolerance (`probe`); a *leap* doubles a creeping restart's advance (`leap`); a grazing
/// pass may end within an accepted band (`acceptedBand`); a contact leaving at t0 is
/// told apart (`separatingAtStart`); and the query runs in P's frame and on its own clock
/// (`inFrameOfP`, `onQueryClock`). The bracket's refinements are in toi_refinements.hpp,
/// whose file comment says why Brent needs them; what each buys is measured in
/// figures/data/toi-refinements.md.
///
/// *Grazing.* Where the distance has a long, shallow minimum just above the tolerance (a
/// spinning rib passing a cartilage at 1.1 tolerances), no single vector separates by the
/// tolerance for long: the proof that the pass is free of contact is a chain of short
/// links, each about (d - tol) / (the speed at which the supporting distance along a fixed
/// vector falls) long, and that can take the whole iteration cap. `acceptedDistance` lets
/// a caller who does not need that proof end such a query at the first restart within it.
///
/// The solver in parts, one concept each; this header includes them all and is the one
/// to include:
/// - toi_result.hpp: what a query is asked and what it answers (`ToiSettings`,
///   `ToiStatus`, `ToiResult`, and the record of its steps, `ToiTrace`);
/// - toi_solver.hpp: §5's paragraph step by step, a member a step (`detail::ToiSolver`);
/// - toi_refinements.hpp: beyond the paper, Brent's bracket after a restart (its far end,
///   the leap past a creeping restart) and the probe at the distance secant;
/// - toi_query_frame.hpp: the frame and the clock a query runs in (see `timeOfImpact`).
#pragma once

#include <gjkx/brent/toi_query_frame.hpp>
#include <gjkx/brent/toi_refinements.hpp>
#include <gjkx/brent/toi_result.hpp>
#include <gjkx/brent/toi_solver.hpp>
#include <gjkx/extrusion/extrusion.hpp>

#include <cmath>

namespace gjkx {

/// Non-collision or the time of impact of two moving bodies over \f$[t_0, t_1]\f$ (§5); see
/// the file comment. The bodies are any types with `at(t)` and `accelerationBound()`
/// (`Moving<Shape>`, `DeformingSimplex`). Throws std::invalid_argument for a bad interval.
///
/// The query runs in the frame of P: both bodies are seen from an origin at P's position at
/// \f$t_0\f$ (as Box2D v3 runs its queries in the frame of its first shape), and the witness
/// points are moved back to the world. Far from the world's origin this keeps GJK's
/// arithmetic on the bodies' small relative coordinates: in float at coordinates near
/// \f$10^5\f$ (spacing 0.0078) the time of impact is then as accurate as in double (measured
/// by the study's extreme cases, docs 09). The translation itself is exact in floating
/// point for bodies near the origin chosen (Sterbenz's lemma).
///
/// It runs on its own clock too, the same change on the time axis: its times are
/// \f$\tau = t - t_0\f$, on \f$[0, t_1 - t_0]\f$, and the bodies are put on that clock
/// (`retimed(t0)`). On the caller's clock, far from \f$t = 0\f$, the spacing of times is
/// relative to \f$|t_0|\f$, not to the interval: in float at \f$t_0\f$ = 1000 it is 6.1e-5, and an
/// interval 2^-10 long holds 16 times. Brent's bracket then stops shrinking at its
/// round-off, \f$2\cdot 2\epsilon|t| = 2.4\cdot 10^{-4}\f$, a quarter of the interval, and the
/// converged bracket's far end, a hit there, came up to 4 spacings after the bodies came
/// within the tolerance (tests/fuzz/corpus/fuzz_time_of_impact/finding-toi_float_late_hit_at_t1000).
/// On the query's clock the round-off is relative to the interval and the time tolerance
/// holds as asked. A time the caller cannot hold is reported at the latest one it can
/// before it (see `ToiSolver::report`). A motion that starts at \f$t_0\f$ reads its own
/// \f$t - t_0\f$ exactly either way; at \f$t_0 = 0\f$ nothing changes.
template <typename MovingP, typename MovingQ>
ToiResult<typename MovingP::Scalar> timeOfImpact(const MovingP& P, const MovingQ& Q, typename MovingP::Scalar t0,
                                                 typename MovingP::Scalar t1,
                                                 const ToiSettings<typename MovingP::Scalar>& settings = {},
                                                 ToiTrace<typename MovingP::Scalar>* trace = nullptr,
                                                 ExtrusionCache<typename MovingP::Scalar>* coherence = nullptr) {
  using S = typename MovingP::Scalar;
  // Temporal coherence (§2: the work of the previous query reinitializes the current one):
  // the first complete test starts where the pair's last query ended, and this query's end
  // is kept for the next. A hint only: the verdicts are those of a cold start.
  const auto run = [&](detail::ToiSolver<MovingP, MovingQ>&& solver) {
    ToiResult<S> result = solver.solve();
    if (coherence && settings.warmStart && settings.coherence) *coherence = solver.cache();
    return result;
  };
  requireInterval(t0, t1, "timeOfImpact");
  if (!(settings.collisionTolerance > S(0))) failInput("toiSettings.collisionTolerance", "must be positive");
  if (!(settings.acceptedDistance >= S(0)) || !std::isfinite(settings.acceptedDistance))
    failInput("toiSettings.acceptedDistance", "must be finite and not negative");
  if (settings.acceptedAfter < 0) failInput("toiSettings.acceptedAfter", "must not be negative");
  if constexpr (detail::CanTranslate<MovingP>::value && detail::CanTranslate<MovingQ>::value &&
                detail::CanRetime<MovingP>::value && detail::CanRetime<MovingQ>::value) {
    const Vector3<S> origin = settings.inFrameOfP ? detail::queryOrigin(P, t0) : Vector3<S>::Zero();
    const S duration = t1 - t0;
    // an interval too long for S stays on the caller's clock
    const S clock = settings.onQueryClock && std::isfinite(duration) ? t0 : S(0);
    if (origin.squaredNorm() > S(0) || clock != S(0)) {  // already there: nothing to change
      const MovingP localP = detail::localBody(P, Vector3<S>(-origin), clock);
      const MovingQ localQ = detail::localBody(Q, Vector3<S>(-origin), clock);
      return run(detail::ToiSolver<MovingP, MovingQ>(localP, localQ, t0 - clock, t1 - clock, settings, trace, origin,
                                                     clock, coherence));
    }
  }
  return run(detail::ToiSolver<MovingP, MovingQ>(P, Q, t0, t1, settings, trace, Vector3<S>::Zero(), S(0), coherence));
}

}  // namespace gjkx