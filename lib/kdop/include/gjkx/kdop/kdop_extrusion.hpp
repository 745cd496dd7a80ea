/// @file
/// @brief The k-DOP extrusion test: two 14-DOPs proven apart over \f$[t_0, t_1]\f$ by one slab (§3, §6).
///
/// §3's extrusion test proves two convex bodies apart over an interval when one vector
/// separates them at both ends. §6 prunes the pairs of a nonconvex body's pieces in the
/// same spirit, with the 7 fixed slab directions of 14-DOPs as the candidate vectors.
///
/// **Linear motion.** A body that translates at constant velocity without turning has
/// \f$hi_k(t) = \max_x \vec{a}_k\cdot(x + v\,t)\f$ linear in t, and so is the gap
/// \f$g_k(t) = lo^Q_k(t) - hi^P_k(t)\f$ between P's slab and Q's. A linear function positive at
/// both ends is positive in between: a slab that separates on the same side at \f$t_0\f$ and
/// at \f$t_1\f$ separates over the whole interval, so the pair can be pruned.
///
/// **Rotating or accelerating motion.** The gap is no longer linear, and a slab may close
/// between the ends (§3's "errors of second order motion"). The certified variant bounds the
/// dip exactly as the certified time-of-impact variant does (`certified_margin.hpp`): each
/// body point's acceleration is at most \f$D = a + \alpha r + \omega^2 r\f$ (`MotionBound`, r
/// the node's bounding radius about the centre of rotation), a support value stays within
/// \f$\frac{(t-t_0)(t_1-t)}{2}D\f$ of its chord, and so does the gap with \f$D_P + D_Q\f$. The slab
/// separates over the interval if the least value of that lower bound,
/// `lowestSupportingDistance`, exceeds the tolerance. Never a pair that collides is pruned.
#pragma once

#include <gjkx/extrusion/certified_margin.hpp>
#include <gjkx/kdop/kdop.hpp>

namespace gjkx {

/// The verdict of the k-DOP extrusion test.
struct KdopExtrusionResult {
  /// True if a slab proves the two k-DOPs apart over the whole interval.
  bool separated = false;
  /// The slab that does (0..6), -1 if none.
  int slab = -1;
};

/// One side of one slab over the interval: the gap between P's and Q's slab ends, in world
/// units, is `gap0` at \f$t_0\f$ and `gap1` at \f$t_1\f$; true if it stays above `tolerance` in
/// between (linear motion: both ends above suffice; certified: its lower bound
/// `lowestSupportingDistance` does too).
template <typename S>
bool slabSeparatesOverInterval(S gap0, S gap1, S duration, S accelerationP, S accelerationQ, ExtrusionVariant variant,
                               S tolerance) {
  return gap0 > tolerance && gap1 > tolerance &&
         lowestSupportingDistance(variant, gap0, gap1, duration, accelerationP, accelerationQ) > tolerance;
}

/// The k-DOP extrusion test of P and Q over \f$[t_0, t_1]\f$, given their 14-DOPs at both ends
/// (`p0`, `p1`, `q0`, `q1`), the interval's length `duration`, and the bodies' point
/// acceleration bounds `accelerationP`, `accelerationQ` (`MotionBound::pointAcceleration`;
/// 0 for linear motion, and unused by the `Paper` variant). A slab separates if the lower
/// bound of its gap (in world units) exceeds `tolerance` on one side.
template <typename S>
KdopExtrusionResult kdopExtrusionTest(const Kdop14<S>& p0, const Kdop14<S>& p1, const Kdop14<S>& q0,
                                      const Kdop14<S>& q1, S duration, S accelerationP, S accelerationQ,
                                      ExtrusionVariant variant, S tolerance = S(0)) {
  for (int k = 0; k < Kdop14<S>::kSlabs; ++k) {
    const S scale = S(1) / Kdop14<S>::axisLength(k);
    // Q above P along a_k, then P above Q: each side's gap must stay open by itself.
    if (slabSeparatesOverInterval((q0.lo[k] - p0.hi[k]) * scale, (q1.lo[k] - p1.hi[k]) * scale, duration, accelerationP,
                                  accelerationQ, variant, tolerance) ||
        slabSeparatesOverInterval((p0.lo[k] - q0.hi[k]) * scale, (p1.lo[k] - q1.hi[k]) * scale, duration, accelerationP,
                                  accelerationQ, variant, tolerance))
      return {true, k};
  }
  return {};
}

}  // namespace gjkx
