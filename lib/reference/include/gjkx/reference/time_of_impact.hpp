// The reference time of impact (§5): the first time a distance function d(t) comes
// within a threshold, found by dense sampling and bisection, in long double. The caller
// supplies d(t) (for two moving bodies: place both at t and take a distance of
// polytope_distance.hpp or a closed form) and, for the certified search, a bound L on its
// rate of change; nothing here knows about shapes or motions.
#pragma once

#include <gjkx/reference/closest_points.hpp>

#include <algorithm>
#include <limits>
#include <stdexcept>

namespace gjkx::reference {

/// Where and how finely firstContact searches.
struct ContactSearch {
  Real t0 = 0;               ///< start of the interval
  Real t1 = 1;               ///< end of the interval
  int samples = 64;          ///< evenly spaced samples of [t0, t1] (both ends included)
  Real resolution = 1e-13;   ///< bisection stops at a bracket this wide ...
  int maxDepth = 60;         ///< ... or this many halvings
};

namespace detail {

/// The first t in [ta, tb] with d(t) <= threshold, given d(ta) = da > threshold and
/// d(tb) = db, or -1 when the bracket is proven free; see firstContact.
template <typename D>
Real firstContactIn(D& d, Real lipschitz, Real threshold, const ContactSearch& search, Real ta, Real da, Real tb,
                    Real db, int depth) {
  if ((da + db - lipschitz * (tb - ta)) / 2 > threshold) return -1;  // proven free
  if (tb - ta <= search.resolution || depth > search.maxDepth)
    return db <= threshold ? tb : (std::min(da, db) <= threshold ? ta : tb);
  const Real tm = (ta + tb) / 2, dm = d(tm);
  const Real left = firstContactIn(d, lipschitz, threshold, search, ta, da, tm, dm, depth + 1);
  if (left >= 0) return left;
  if (dm <= threshold) return tm;
  return firstContactIn(d, lipschitz, threshold, search, tm, dm, tb, db, depth + 1);
}

}  // namespace detail

/// The first time in [search.t0, search.t1] at which d(t) <= threshold (search.t0 if it
/// starts so), or -1 if there is none.
///
/// d is any callable Real -> Real whose rate of change is at most `lipschitz` (for two
/// rigid bodies, the sum over both of |v| + |a| + |w| r, r the bounding radius about the
/// body origin; inflate it by a few ulps). The interval is sampled at search.samples
/// points; each gap [ta, tb] between two samples is proven free of contact when
///     (d(ta) + d(tb) - L (tb - ta)) / 2 > threshold
/// (the lowest d can dip between two samples), else split in two, left half first, down
/// to search.resolution.
///
/// Accuracy: no contact between samples can slip through (no tunnelling), since a gap is
/// skipped only on that proof; the returned time is at most search.resolution after the
/// first time d(t) <= threshold, plus the error of d itself divided by the rate at which
/// d falls there. Cost: a few hundred evaluations of d for a grazing query.
template <typename D>
Real firstContact(D&& d, Real lipschitz, Real threshold, const ContactSearch& search = {}) {
  if (!(search.t1 >= search.t0)) throw std::invalid_argument("reference::firstContact: search.t1 < search.t0");
  if (search.samples < 1) throw std::invalid_argument("reference::firstContact: search.samples < 1");
  if (!(lipschitz >= 0)) throw std::invalid_argument("reference::firstContact: lipschitz must be >= 0");
  Real ta = search.t0, da = d(ta);
  if (da <= threshold) return ta;
  for (int k = 1; k <= search.samples; ++k) {
    const Real tb = k == search.samples ? search.t1 : search.t0 + (search.t1 - search.t0) * Real(k) / Real(search.samples);
    const Real db = d(tb);
    const Real t = detail::firstContactIn(d, lipschitz, threshold, search, ta, da, tb, db, 0);
    if (t >= 0) return t;
    ta = tb;
    da = db;
  }
  return -1;
}

/// The first root in [0, 1] of a gap function g(t) with g(0) > 0 (0 if g(0) <= 0), by
/// scanning `scan` evenly spaced samples for the first g <= 0 and bisecting that bracket
/// 200 times; NaN when no sample has g <= 0.
///
/// Accuracy: uncertified, unlike firstContact: a root between two samples where g dips
/// below 0 and comes back is missed, so g must not do that within 1 / scan (true of the
/// closed forms it serves: one moving feature against a plane). Within the bracket the
/// bisection reaches the long-double resolution of t; the returned time is the upper end
/// (g <= 0 there).
template <typename G>
double firstRoot(G&& gap, int scan = 20000) {
  Real ta = 0;
  const Real ga = gap(ta);
  if (ga <= 0) return 0;
  for (int k = 1; k <= scan; ++k) {
    const Real tb = Real(k) / scan, gb = gap(tb);
    if (gb <= 0) {
      Real lo = ta, hi = tb;
      for (int it = 0; it < 200; ++it) {
        const Real mid = (lo + hi) / 2;
        (gap(mid) > 0 ? lo : hi) = mid;
      }
      return double(hi);
    }
    ta = tb;
  }
  return std::numeric_limits<double>::quiet_NaN();
}

}  // namespace gjkx::reference
