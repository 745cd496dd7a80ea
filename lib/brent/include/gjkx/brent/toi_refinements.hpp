/// @file
/// @brief Beyond the paper, the time-of-impact solver's answer to slow restarts: Brent's
/// bracket after a restart (its nearest known far end, a leap past a creeping restart)
/// and the probe at the distance secant (members of `detail::ToiSolver`).
///
/// Part of the solver of gjkx/brent/time_of_impact.hpp, the header to include; its file
/// comment is §5's paragraph, and toi_solver.hpp the solver these members belong to.
/// They change how fast a query ends, not what it proves: every interval they declare
/// free of contact is proven so as §5's own steps prove it.
///
/// Why the restarts creep when the bodies turn ("Brent creep"). Let d(t) be the exact
/// distance and \f$\vec{s}_a\f$ the closest direction at \f$t_a\f$. SD along the fixed
/// \f$\vec{s}_a\f$ equals d at \f$t_a\f$ but falls faster than d as the bodies turn: the closest
/// features swing away from it. Near the contact, to first order,
/// \f[ d(t) \approx d_a - v\,(t - t_a), \qquad SD(t, \vec{s}_a) \approx d_a - (v + u)(t - t_a), \f]
/// with u > 0 what the turning adds along \f$\vec{s}_a\f$ (about \f$\omega r\f$, r the lever of
/// the closest feature). F's root is then \f$t_x = t_a + (d_a - \mathrm{tol})/(v + u)\f$, where the
/// distance is still \f$\mathrm{tol} + (d_a - \mathrm{tol})\,u/(v + u)\f$: however well Brent solves
/// F, each restart shrinks the gap to the contact only by the constant factor u/(v + u).
/// Linear convergence, not superlinear (planar_2d, 2D polygons spinning up to 3 rad: about
/// 0.57 a restart, up to 30 restarts and 98 iterations for one query).
///
/// The probe. After a restart the solver knows the exact distance at two times: \f$d_b\f$ at
/// the last test's start \f$t_b\f$ and \f$d_a\f$ at \f$t_a\f$. The secant through them reaches
/// the tolerance at
/// \f[ t_S = t_a + (d_a - \mathrm{tol})\,\frac{t_a - t_b}{d_b - d_a}, \f]
/// the secant method on d - tol itself, which converges superlinearly where d is smooth.
/// A complete test on \f$[t_S, t_1]\f$ gives the exact distance at \f$t_S\f$ and stores the
/// vectors found there; each is then checked back at \f$t_a\f$. A vector that separates by the
/// tolerance at both \f$t_a\f$ and \f$t_S\f$ proves \f$[t_a, t_S]\f$ free of contact just as a
/// vector stored at \f$t_a\f$ does: §3's test asks a vector to separate at both ends of the
/// interval, whichever end it was found at (the same chord, and for the certified variant
/// the same margin). The closest direction at \f$t_S\f$ has turned with the bodies, so it
/// proves the interval the vectors from \f$t_a\f$ could not. Proven, the probe is a restart at
/// \f$t_S\f$ (or a photo finish, or a hit); not proven, it is a nearer far end for Brent.
#pragma once

#include <gjkx/brent/toi_solver.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <utility>

namespace gjkx {

namespace detail {

/// Brent's bracket on \f$[t_a, t_1]\f$: \f$F(t_a)\f$ = the exact distance at \f$t_a\f$ less the
/// tolerance, > 0; at the far end, F at \f$t_1\f$ (\f$\le 0\f$ since the test failed; clamped)
/// or at a nearer time where the stored vectors are below the tolerance. Brent's history
/// is lost on a restart, and a first secant towards \f$t_1\f$ creeps like regula falsi where
/// F bends away from the chord (accelerating or turning bodies: each secant lands short, F
/// is above the tolerance there, and every restart costs a complete test). So the far end
/// is the nearest of these where the new vectors are below the tolerance:
/// - the probe's \f$t_S\f$ (`probed`), when it was not proven free;
/// - the last bracket's far end.
///
/// A secant can also creep towards a near miss: where the distance has a minimum just
/// above the tolerance (two resting bodies that rock, a grazing pass), F has no root, and
/// each restart lands a little short of the minimum, ever closer (a rocking box: 74
/// restarts, each a fifth shorter than the last). So after a restart that advanced less
/// than a quarter of what is left of the bracket, the solver also *leaps* twice that
/// advance ahead (`leap`): where the new vectors still separate by the tolerance, the leap
/// is an iterate like any other (proven free of contact, a complete test follows), and
/// the advances double until they pass the minimum; where they do not, the leap is the
/// bracket's far end, and Brent works on a bracket that short.
template <typename MovingP, typename MovingQ>
inline auto ToiSolver<MovingP, MovingQ>::bracket(std::optional<BrentIterate>& leap, const ProbeOutcome& probed)
    -> BrentStepper<S> {
  const S distanceAtTa = last_.distanceAtStart;
  S high = t1_, fHigh = std::min(approximateMaxSdAtT1() - tol_, S(0));
  if (probed.farEnd && probed.t < high) {
    high = probed.t;
    fHigh = probed.f;
  }
  if (settings_.farEndReuse) tryNearerFarEnd(previousHigh_, high, fHigh);
  const S advance = ta_ - taBefore_;
  if (settings_.leap && result_.restarts > 0 && advance < S(0.25) * (high - ta_) && result_.brentIterations < settings_.maxIterations) {
    BrentIterate x = iterateAt(ta_ + 2 * advance, BrentStepKind::Leap, ta_, high);
    if (x.separates) {
      leap = std::move(x);
    } else {
      high = x.t;
      fHigh = x.approximateMaxSd - tol_;
    }
  }
  return BrentStepper<S>(ta_, distanceAtTa - tol_, high, fHigh, timeTolerance_);
}

/// Makes t the bracket's far end (`high`, with F there in `fHigh`) if it lies inside
/// \f$(t_a, \mathrm{high})\f$ and F is negative there.
template <typename MovingP, typename MovingQ>
inline void ToiSolver<MovingP, MovingQ>::tryNearerFarEnd(S t, S& high, S& fHigh) {
  if (!(t > ta_ && t < high)) return;
  const S f = approximateMaxSd(P_.at(t), Q_.at(t), t) - tol_;
  if (f < S(0)) {
    high = t;
    fHigh = f;
  }
}

/// The probe (see the file comment): after a restart, a complete test on \f$[t_S, t_1]\f$ at
/// the time \f$t_S\f$ where the exact distances of the last two complete tests extrapolate
/// to the tolerance (at least one time tolerance past \f$t_a\f$, so that the probes advance),
/// and the proof of \f$[t_a, t_S]\f$: a vector found at \f$t_S\f$ that separates at \f$t_a\f$ too
/// (`backwardProof`), else one stored at \f$t_a\f$ that separates at \f$t_S\f$ (F, §5's own).
/// Proven: a photo finish if the test succeeded, a hit at \f$t_S\f$ if the distance there is
/// within the tolerance, else the solver restarts at \f$t_S\f$. Not proven: \f$t_S\f$ is a far
/// end of Brent's bracket (F < 0 there). Counted as a Brent iteration (one evaluation of
/// the solver at an iterate) and traced as a `DistanceSecant` step. No probe before the
/// first restart (one exact distance only), nor where the distance does not fall.
template <typename MovingP, typename MovingQ>
inline auto ToiSolver<MovingP, MovingQ>::probe() -> ProbeOutcome {
  ProbeOutcome out;
  const S da = last_.distanceAtStart;
  if (!settings_.probe) return out;
  if (!(taBefore2_ < taBefore_ && distanceBefore_ > da) || result_.brentIterations >= settings_.maxIterations) return out;
  // Half a time tolerance short of the estimate: where it is that good, the probe lands
  // still apart (proven), and the next, one time tolerance on, within the tolerance: a
  // bracket within the time tolerance, the end.
  const S ts = std::max(ta_ + stepToContact() - S(0.5) * timeTolerance_, ta_ + timeTolerance_);
  if (!(ts < std::min(t1_, contactBy_))) return out;  // past t1 (or never), or past a known contact: Brent as before
  ++result_.brentIterations;
  const PlacedP Ps = P_.at(ts);
  const PlacedQ Qs = Q_.at(ts);
  ExtrusionResult<S> test = completeTest(Ps, Qs, ts);
  if (test.status == ExtrusionStatus::NumericalFailure || test.status == ExtrusionStatus::IterationCap)
    return out;  // no verdict from a probe that failed: Brent goes on as without it
  S proof = backwardProof(test.separating, ts);
  S forward = -std::numeric_limits<S>::infinity();
  if (proof < tol_) {
    forward = approximateMaxSd(Ps, Qs, ts);
    proof = std::max(proof, forward);
  }
  const bool proven = proof >= tol_;
  if (trace_)
    trace_->steps.push_back(ToiStep<S>{callerTime(ts), proof, callerTime(ta_), callerTime(t1_),
                                       BrentStepKind::DistanceSecant, proven});
  if (!proven) {
    out.farEnd = true;
    out.t = ts;
    out.f = forward - tol_;
    if (test.status == ExtrusionStatus::CollidingAtStart) {  // within the tolerance at ts: kept for the end
      contactBy_ = ts;
      contactTest_ = std::move(test);
    }
    return out;
  }
  ++result_.restarts;
  if (test.status != ExtrusionStatus::Undecided) {
    out.verdict = verdictAt(ts, test);
    return out;
  }
  moveStartTo(ts, std::move(test));
  out.restarted = true;
  return out;
}

/// How far past \f$t_a\f$ the exact distances of the last complete tests extrapolate to the
/// tolerance: \f$t_S - t_a\f$ of the probe (needs \f$d_b > d_a\f$; may be infinite).
///
/// Through the last two, \f$(t_b, d_b)\f$ and \f$(t_a, d_a)\f$, the secant: with the slope
/// \f$\sigma = (d_a - d_b)/(t_a - t_b) < 0\f$, \f$h = (d_a - \mathrm{tol}) / (-\sigma)\f$. Where the
/// bodies turn, d bends, and the secant overshoots into contact when d is concave (each
/// probe then only a far end) or stops short when it is convex. With a third,
/// \f$(t_c, d_c)\f$, the parabola through all three (Newton's form),
/// \f[ d(t_a + h) \approx d_a + \sigma h + \kappa\, h\,(h + t_a - t_b), \qquad
///     \kappa = \frac{\sigma - (d_b - d_c)/(t_b - t_c)}{t_a - t_c}, \f]
/// reaches the tolerance where \f$\kappa h^2 + \beta h + (d_a - \mathrm{tol}) = 0\f$, with
/// \f$\beta = \sigma + \kappa (t_a - t_b)\f$ its slope at \f$t_a\f$ (Muller's method). Its first
/// root past \f$t_a\f$, written without cancellation,
/// \f[ h = \frac{2 (d_a - \mathrm{tol})}{-\beta + \sqrt{\beta^2 - 4 \kappa (d_a - \mathrm{tol})}}, \f]
/// is taken when it is real and the parabola falls at \f$t_a\f$ (\f$\beta < 0\f$); else the
/// secant (a parabola that stays above the tolerance: a near miss, where the secant leaps
/// past the minimum).
template <typename MovingP, typename MovingQ>
inline auto ToiSolver<MovingP, MovingQ>::stepToContact() const -> S {
  const S gap = last_.distanceAtStart - tol_;
  const S slope = (last_.distanceAtStart - distanceBefore_) / (ta_ - taBefore_);
  const S secant = gap / -slope;
  if (!(taBefore2_ < taBefore_)) return secant;  // two exact distances only
  const S slopeBefore = (distanceBefore_ - distanceBefore2_) / (taBefore_ - taBefore2_);
  const S curvature = (slope - slopeBefore) / (ta_ - taBefore2_);
  const S beta = slope + curvature * (ta_ - taBefore_);
  const S discriminant = beta * beta - S(4) * curvature * gap;
  if (!(beta < S(0) && discriminant >= S(0))) return secant;
  const S muller = S(2) * gap / (-beta + std::sqrt(discriminant));
  return muller > S(0) && std::isfinite(muller) ? muller : secant;
}

/// The proof of \f$[t_a, t_S]\f$ by the vectors `vectors` found at \f$t_S\f$: the largest lowest
/// value of \f$SD(t, \vec{s}_k)\f$ on the interval that its end values allow (the chord's lower
/// end, less for the certified variant the margin's parabola, `lowestSupportingDistance`:
/// for a vector whose SD falls fast, its end value itself), which proves the interval free
/// when at least the tolerance.
/// The vectors nearest the closest direction at \f$t_S\f$ come last in GJK's order: they are
/// tried first, and the first that proves it ends the search. Their hints stay as found
/// at \f$t_S\f$ (the searches at \f$t_a\f$ start from copies).
template <typename MovingP, typename MovingQ>
inline auto ToiSolver<MovingP, MovingQ>::backwardProof(const SeparatingVectors<S>& vectors, S ts) -> S {
  S best = -std::numeric_limits<S>::infinity();
  if (vectors.count == 0) return best;
  const PlacedP Pa = P_.at(ta_);
  const PlacedQ Qa = Q_.at(ta_);
  for (int k = vectors.count - 1; k >= 0 && best < tol_; --k) {
    SupportHint hintP = settings_.supportHints ? vectors.hintP[k] : 0;
    SupportHint hintQ = settings_.supportHints ? vectors.hintQ[k] : 0;
    const S sd = supportingDistance(Pa, Qa, vectors.vectors[k], hintP, hintQ);
    ++result_.sdEvaluations;
    best = std::max(best, lowestSupportingDistance(settings_.variant, sd, vectors.sdStart[k], ts - ta_,
                                                   accelerationP_, accelerationQ_));
  }
  return best;
}

}  // namespace detail

}  // namespace gjkx
