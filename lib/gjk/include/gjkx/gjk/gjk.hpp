/// @file
/// @brief GJK: the closest distance between two convex sets (§2.2, Fig. 2).
#pragma once

#include <gjkx/gjk/simplex.hpp>
#include <gjkx/gjk/trace.hpp>
#include <gjkx/motion/round_off.hpp>
#include <gjkx/support_mapping/support.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <type_traits>
#include <utility>

namespace gjkx {

/// How a GJK run ended. Only `Separated` and `Overlapping` are answers about the
/// distance; a stall, the iteration cap and a numerical failure are said as such, never
/// as "no collision".
enum class GjkStatus {
  Separated,         ///< converged: `distance` is the closest distance, within the tolerance
  SeparatingVector,  ///< boolean query: stopped at the first \f$\vec{s}_i\f$ with \f$SD > \f$ `separationThreshold`
  Overlapping,       ///< the origin is in \f$V_Q - V_P\f$ (up to round-off): P and Q intersect or touch
  Stalled,           ///< no progress, the gap \f$MD - SD\f$ open: the distance is between `lowerBound` and `distance`
  IterationCap,      ///< `maxIterations` ran out; `distance` is only an upper bound
  StoppedByVisitor,  ///< the per-iteration visitor asked to stop
  NumericalFailure,  ///< a support mapping returned a point that is not finite
};

/// The name of a status, for messages and tables.
inline const char* toString(GjkStatus status) {
  switch (status) {
    case GjkStatus::Separated: return "separated";
    case GjkStatus::SeparatingVector: return "separating-vector";
    case GjkStatus::Overlapping: return "overlapping";
    case GjkStatus::Stalled: return "stalled";
    case GjkStatus::IterationCap: return "iteration-cap";
    case GjkStatus::StoppedByVisitor: return "stopped-by-visitor";
    case GjkStatus::NumericalFailure: return "numerical-failure";
  }
  return "?";
}

/// Tolerances and limits of a GJK run.
template <typename S>
struct GjkSettings {
  /// The run ends with `IterationCap` after this many iterations.
  int maxIterations = 128;
  /// Convergence: stop when the Minkowski distance (an upper bound of the closest
  /// distance) and the supporting distance along \f$\vec{s}_i\f$ (a lower bound, §2.3)
  /// agree within this fraction: \f$MD - SD \le \tau\,MD\f$. Default \f$\epsilon^{3/4}\f$.
  S relativeTolerance = defaultGjkRelativeTolerance<S>();
  /// Overlap: the origin counts as reached when \f$\lVert z\rVert \le \tau\max_k\lVert w_k\rVert\f$,
  /// i.e. within round-off of the simplex's own size. Default \f$16\epsilon\f$.
  S overlapTolerance = defaultOverlapTolerance<S>();
  /// Boolean query (§2.3): stop at the first \f$\vec{s}_i\f$ with \f$SD(P,Q,\vec{s}_i)\f$ above this.
  /// Infinity (the default) computes the closest distance.
  S separationThreshold = std::numeric_limits<S>::infinity();
  /// \f$\vec{s}_0\f$ for a cold start: "an arbitrary nonzero vector". Zero (the default)
  /// takes the direction from P's centre to Q's, which usually saves iterations.
  Vector3<S> initialDirection = Vector3<S>::Zero();
  /// Rounded shapes (spheres, capsules: a core swept by a ball, support.hpp `IsRounded`):
  /// run GJK on the cores and subtract the radii (the default), or, when false, on the
  /// full curved supports as the paper does (which converges only linearly).
  bool roundedCores = true;
};

/// What a GJK run found.
template <typename S>
struct GjkResult {
  /// How the run ended.
  GjkStatus status = GjkStatus::IterationCap;
  /// The Minkowski distance \f$\lVert z\rVert\f$ at the end (0 when overlapping): the closest
  /// distance when `status` is `Separated`, an upper bound of it otherwise.
  S distance = std::numeric_limits<S>::infinity();
  /// The largest supporting distance seen, \f$\max_i SD(P,Q,\vec{s}_i)\f$: a lower bound of
  /// the closest distance; positive means P and Q are proven disjoint.
  S lowerBound = -std::numeric_limits<S>::infinity();
  /// The unit \f$\vec{s}_i\f$ that gave `lowerBound`: a separating vector when it is positive.
  Vector3<S> separatingVector = Vector3<S>::Zero();
  /// z, the point of \f$V_Q - V_P\f$ closest to the origin (\f$z = q - p\f$).
  Vector3<S> z = Vector3<S>::Zero();
  /// The closest point on P (meaningful when `Separated`).
  Vector3<S> witnessP = Vector3<S>::Zero();
  /// The closest point on Q (meaningful when `Separated`).
  Vector3<S> witnessQ = Vector3<S>::Zero();
  /// The final simplex: the closest features, \f$V_P\f$ and \f$V_Q\f$ (§2.2).
  Simplex<S> simplex;
  /// Iterations run (support queries made, warm start included).
  int iterations = 0;
};

/// What one query leaves for the next (§2.2, temporal coherence): "the work from the
/// previous query (e.g. \f$V_P\f$ and \f$V_Q\f$) can be used to reinitialize the current query".
/// The next run starts along the last direction and re-asks the supports of the last
/// simplex's directions at the shapes' new poses, starting hill climbing at the last
/// vertices found.
template <typename S>
struct GjkCache {
  /// The last simplex (with each vertex's direction and hints).
  Simplex<S> simplex;
  /// The last search direction.
  Vector3<S> direction = Vector3<S>::Zero();
  /// Hill-climbing hint for P.
  SupportHint hintP = 0;
  /// Hill-climbing hint for Q.
  SupportHint hintQ = 0;
  /// False until a run fills the cache.
  bool valid = false;
};

namespace detail {
/// True when every coordinate of v is finite: Eigen's `allFinite`, written out (speed: that
/// call is not inlined, and GJK asks it of every support pair).
template <typename S>
bool isFinite(const Vector3<S>& v) {
  return std::isfinite(v.x()) && std::isfinite(v.y()) && std::isfinite(v.z());
}

template <typename P, typename Q, typename S>
SimplexVertex<S> supportPair(const P& shapeP, const Q& shapeQ, const Vector3<S>& s, SupportHint& hintP,
                             SupportHint& hintQ) {
  SimplexVertex<S> v;
  v.s = s;
  v.p = supportFrom(shapeP, s, hintP);
  v.q = supportFrom(shapeQ, Vector3<S>(-s), hintQ);
  v.w = v.q - v.p;
  v.hintP = hintP;
  v.hintQ = hintQ;
  return v;
}

/// The warm boolean query's first step, lean (§2.3 with §2.2's temporal coherence).
///
/// A boolean query stops at the first \f$\vec{s}_i\f$ whose supporting distance
/// \f$SD(P,Q,\vec{s}_i)\f$ is above the threshold, and a warm query's \f$\vec{s}_0\f$ is the
/// direction the last query ended on. While the bodies move little, the separating vector
/// that ended the last query still separates them, and the first support pair is the
/// whole query (about nine warm queries in ten in the study). This is the loop's first
/// iteration for that case alone, with none of its bookkeeping (no simplex vertex, no
/// closest point, no witnesses): two supports climbed from the remembered hints and one
/// supporting distance, in the loop's own arithmetic, so its answer is the loop's.
///
/// Returns true when \f$SD(P,Q,\vec{s}_0)\f$ is finite and above `threshold`, with `result`
/// and `cache` as the loop leaves them at that exit (status `SeparatingVector`, one
/// iteration, an empty simplex). Returns false, having written nothing, otherwise: the
/// loop then runs the query from its start (a non-finite support point included, which
/// makes SD non-finite and is reported by the loop).
template <typename ShapeP, typename ShapeQ, typename S>
bool separatedAlongCachedDirection(const ShapeP& P, const ShapeQ& Q, const Vector3<S>& s, S threshold, GjkCache<S>& cache,
                                   GjkResult<S>& result) {
  SupportHint hintP = cache.hintP, hintQ = cache.hintQ;
  const Vector3<S> p = supportFrom(P, s, hintP);
  const Vector3<S> q = supportFrom(Q, Vector3<S>(-s), hintQ);
  // SD(P, Q, s) = s . S_Q(-s) - s . S_P(s), for a unit s (§2.3), as in the loop.
  const S sNorm = s.norm();
  const S sd = s.dot(Vector3<S>(q - p)) / sNorm;
  if (!(sd > threshold) || !std::isfinite(sd)) return false;
  result.status = GjkStatus::SeparatingVector;
  result.iterations = 1;
  result.lowerBound = sd;
  result.separatingVector = s / sNorm;
  cache.simplex.size = 0;  // the loop's simplex at this exit is empty
  cache.simplex.z = Vector3<S>::Zero();
  cache.direction = s;
  cache.hintP = hintP;
  cache.hintQ = hintQ;
  return true;
}

/// The GJK loop itself (`gjk` without the rounded-shape dispatch).
template <typename ShapeP, typename ShapeQ, typename Visitor>
GjkResult<typename ShapeP::Scalar> gjkRun(const ShapeP& P, const ShapeQ& Q, const GjkSettings<typename ShapeP::Scalar>& settings,
                                          GjkCache<typename ShapeP::Scalar>* cache, Visitor&& visit) {
  using S = typename ShapeP::Scalar;
  static_assert(std::is_same_v<S, typename ShapeQ::Scalar>, "P and Q must use the same scalar type");
  constexpr bool visiting = !std::is_same_v<std::decay_t<Visitor>, NoGjkVisitor>;

  GjkResult<S> result;
  Simplex<S>& simplex = result.simplex;
  SupportHint hintP = 0, hintQ = 0;
  Vector3<S> s;                 // s_i
  bool warmSimplexPending = false;
  if (cache && cache->valid) {  // temporal coherence: start where the last query ended
    s = cache->direction;
    hintP = cache->hintP;
    hintQ = cache->hintQ;
    warmSimplexPending = cache->simplex.size > 0;
  } else if (settings.initialDirection.squaredNorm() > S(0)) {
    s = settings.initialDirection;
  } else {
    s = Q.center() - P.center();  // s_0: from P towards Q
  }
  if (!(s.squaredNorm() > S(0)) || !isFinite(s)) s = Vector3<S>::UnitX();  // any nonzero vector will do

  // A warm boolean query ends, most often, at its first support pair (see above).
  if constexpr (!visiting) {
    if (cache && cache->valid) {
      if (settings.separationThreshold < std::numeric_limits<S>::infinity() &&
          separatedAlongCachedDirection(P, Q, s, settings.separationThreshold, *cache, result))
        return result;
    }
  }

  S md = std::numeric_limits<S>::infinity();  // Minkowski distance |z| of the current simplex
  Vector3<S> z = Vector3<S>::Zero();

  // Fills the result's last fields and the cache. Every exit then returns `result`
  // itself, so the (large) result is built in place rather than copied out (speed).
  auto finish = [&](GjkStatus status) {
    result.status = status;
    result.z = z;
    result.distance = status == GjkStatus::Overlapping ? S(0) : md;
    result.witnessP = simplex.witnessP();
    result.witnessQ = simplex.witnessQ();
    if (cache && status != GjkStatus::NumericalFailure) {
      cache->simplex.assignUsed(simplex);
      cache->direction = s;
      cache->hintP = hintP;
      cache->hintQ = hintQ;
      cache->valid = true;
    }
  };

  // The origin is in the simplex, or within round-off of it (relative to its own size):
  // \f$\lVert z\rVert \le \tau\max_k\lVert w_k\rVert\f$, z the simplex's closest point. Compared
  // squared, \f$\lVert z\rVert^2 \le \tau^2\max_k\lVert w_k\rVert^2\f$, to save the square roots (speed).
  // \f$\max_k\lVert w_k\rVert^2\f$: the simplex's size, the scale of its round-off.
  auto largestW2 = [](const Simplex<S>& x) {
    S wMax2 = S(0);
    for (int k = 0; k < x.size; ++k) wMax2 = std::max(wMax2, x.vertices[k].w.squaredNorm());
    return wMax2;
  };
  auto overlapsAt = [&](const Simplex<S>& x, const Vector3<S>& zx) {
    if (x.size == 4) return true;
    const S tau = settings.overlapTolerance;
    return zx.squaredNorm() <= tau * tau * largestW2(x);
  };
  auto overlaps = [&](const Simplex<S>& x) { return overlapsAt(x, x.closestPoint()); };
  auto contains = [](const Simplex<S>& x, const Vector3<S>& w) {
    for (int k = 0; k < x.size; ++k)
      if (x.vertices[k].w == w) return true;
    return false;
  };

  // Ties: steps taken although |z| did not fall, at most kMaxTies per run (see below). A
  // tie is a new |z| within round-off of the old, which is about epsilon times the
  // simplex's own size, not |z|'s: z is computed from the w, and on a flat V_Q - V_P
  // 2000 wide a |z| of 1.7e-8 is only good to 1e-13 or so.
  constexpr int kMaxTies = 2;
  int ties = 0;
  auto isTie = [&](const Simplex<S>& x, const Vector3<S>& w, S mdNew) {
    if (ties >= kMaxTies || !contains(x, w)) return false;
    return mdNew <= md + gjkTieAllowance<S>() * std::sqrt(largestW2(x));
  };

  // "No decrease" (the paper's stop) may leave the gap MD - SD open: the distance is then
  // only bracketed, and the run says `Stalled`. Near a contact z's direction is known only
  // to round-off, and SD lags MD (it falls with the angle, MD with its square); where
  // V_Q - V_P has a face of ties along z far wider than the distance (a slab 2e-5 thick,
  // 1e6 wide), z picks a far vertex whose progress is below what |z| resolves, and MD is
  // wrong. GJK cannot tell the two apart. Open: beyond the tolerance and the round-off of
  // the bounds' values (epsilon of max |w_k|, as for ties).
  auto gapOpen = [&](const Simplex<S>& x, const Vector3<S>& w) {
    const S size = std::sqrt(std::max(largestW2(x), w.squaredNorm()));
    return md - result.lowerBound > settings.relativeTolerance * md + gjkTieAllowance<S>() * size;
  };

  for (int i = 0; i < settings.maxIterations; ++i) {
    result.iterations = i + 1;
    const SimplexVertex<S> v = detail::supportPair(P, Q, s, hintP, hintQ);
    if (!isFinite(v.w)) {
      finish(GjkStatus::NumericalFailure);
      return result;
    }

    // SD(P, Q, s_i) = s_i . S_Q(-s_i) - s_i . S_P(s_i), for a unit s_i (§2.3).
    const S sNorm = s.norm();
    const S sd = s.dot(v.w) / sNorm;
    if (sd > result.lowerBound) {
      result.lowerBound = sd;
      result.separatingVector = s / sNorm;
    }

    GjkStep step = GjkStep::Continue;
    if (sd > settings.separationThreshold) {
      step = GjkStep::SeparatingVector;  // a boolean query can stop at the first separating vector
    } else if (warmSimplexPending) {
      // Warm start: the last simplex, its supports re-asked at the new poses, plus w. Here
      // s_0 is the remembered direction, not this simplex's z, so no stopping test below
      // holds yet (a repeated w or a closed gap along s_0 says nothing about the new z):
      // this iteration only builds the simplex, and the next, along its z, is a regular one.
      warmSimplexPending = false;
      for (int k = 0; k < cache->simplex.size; ++k) {
        const SimplexVertex<S>& old = cache->simplex.vertices[k];
        SupportHint hp = old.hintP, hq = old.hintQ;
        const SimplexVertex<S> again = detail::supportPair(P, Q, old.s, hp, hq);
        if (!isFinite(again.w)) {
          finish(GjkStatus::NumericalFailure);
          return result;
        }
        simplex.push(again);
      }
      reduceToClosestFeature(simplex);  // the last simplex may already hold the origin
      if (!overlaps(simplex) && !contains(simplex, v.w)) {
        simplex.push(v);
        reduceToClosestFeature(simplex);
      }
      z = simplex.closestPoint();
      md = z.norm();
      if (overlaps(simplex)) {
        md = S(0);
        step = GjkStep::Overlap;
      }
    } else if (simplex.size > 0 && (contains(simplex, v.w) || md - sd <= settings.relativeTolerance * md)) {
      // The gap between the upper bound MD and the lower bound SD(s_i) is closed (or w is
      // already in the simplex): z is the closest point within the tolerance.
      step = GjkStep::Converged;
    } else {
      Simplex<S> before;
      before.assignUsed(simplex);
      simplex.push(v);
      reduceToClosestFeature(simplex);
      const Vector3<S> zNew = simplex.closestPoint();
      const S mdNew = zNew.norm();
      if (overlapsAt(simplex, zNew)) {
        z = zNew;
        md = S(0);
        step = GjkStep::Overlap;
      } else if (!(mdNew < md) && !isTie(simplex, v.w, mdNew)) {
        simplex.assignUsed(before);  // "until this distance no longer decreases": keep the better simplex
        step = gapOpen(before, v.w) ? GjkStep::Stalled : GjkStep::Converged;
      } else {
        // A decrease, or a tie within round-off with w kept in the new simplex. Near the
        // end the distance falls as the square of z's angle to the optimum (|z| cos θ), so
        // in float it stops falling while the direction is still ~sqrt(ε) off and the gap
        // MD - SD open; and on a flat V_Q - V_P, a new triangle tilted across the origin
        // can be farther by round-off while SD is negative. A tie taken once or twice lets
        // the next support close the gap (or find the origin inside).
        if (!(mdNew < md)) ++ties;
        z = zNew;
        md = mdNew;
      }
    }

    if constexpr (visiting) {
      GjkIteration<S> record;
      record.i = i;
      record.s = s;
      record.supportP = v.p;
      record.supportQ = v.q;
      record.supportingDistance = sd;
      record.simplex = simplex;
      record.z = z;
      record.minkowskiDistance = md;
      record.step = step;
      if (!visit(record) && step == GjkStep::Continue) {
        finish(GjkStatus::StoppedByVisitor);
        return result;
      }
    }
    switch (step) {
      case GjkStep::SeparatingVector: finish(GjkStatus::SeparatingVector); return result;
      case GjkStep::Converged: finish(GjkStatus::Separated); return result;
      case GjkStep::Stalled: finish(GjkStatus::Stalled); return result;
      case GjkStep::Overlap: finish(GjkStatus::Overlapping); return result;
      case GjkStep::Continue: break;
    }
    s = z;  // s_{i+1} = z
  }
  finish(GjkStatus::IterationCap);
  return result;
}

/// The core of a shape as a support mapping of its own (support.hpp, `IsRounded`):
/// \f$S_C(\vec{s})\f$ of a rounded shape, the shape itself for any other.
template <typename X>
struct CoreOf {
  /// The scalar type.
  using Scalar = typename X::Scalar;
  /// The shape whose core this is.
  const X& shape;
  /// \f$S_C(\vec{s})\f$.
  Vector3<Scalar> support(const Vector3<Scalar>& s) const {
    SupportHint hint = 0;
    return coreSupportFrom(shape, s, hint);
  }
  /// \f$S_C(\vec{s})\f$ from a hint.
  Vector3<Scalar> support(const Vector3<Scalar>& s, SupportHint& hint) const { return coreSupportFrom(shape, s, hint); }
  /// The shape's centre (inside its core for the spheres and capsules).
  Vector3<Scalar> center() const { return shape.center(); }
};

/// GJK on rounded shapes \f$P = C_P \oplus B(r_P)\f$, \f$Q = C_Q \oplus B(r_Q)\f$, r = r_P + r_Q.
///
/// Every supporting distance of the shapes is the cores' less r (support.hpp), so GJK
/// runs on the cores, with the boolean threshold raised by r, and the answer comes back:
/// - the cores are d > r apart: P and Q are d - r apart, along the same z, their closest
///   points the cores' moved by \f$r_P\,\hat z\f$ and \f$-r_Q\,\hat z\f$;
/// - the cores are d <= r apart (or overlap): P and Q overlap;
/// - the lower bound and every visited iteration's distances are less r.
/// The iterations (and a trace) are the cores': on two spheres, one support query each.
template <typename ShapeP, typename ShapeQ, typename Visitor>
GjkResult<typename ShapeP::Scalar> gjkOnCores(const ShapeP& P, const ShapeQ& Q, typename ShapeP::Scalar rP,
                                              typename ShapeP::Scalar rQ, const GjkSettings<typename ShapeP::Scalar>& settings,
                                              GjkCache<typename ShapeP::Scalar>* cache, Visitor&& visit) {
  using S = typename ShapeP::Scalar;
  const S r = rP + rQ;
  GjkSettings<S> coreSettings = settings;
  coreSettings.separationThreshold = settings.separationThreshold + r;  // SD(P, Q) > t  <=>  SD(cores) > t + r
  // (Built in place: the result is large, and a default-constructed one assigned from the
  // run cost a third of a two-sphere query.)
  GjkResult<S> result = [&] {
    if constexpr (std::is_same_v<std::decay_t<Visitor>, NoGjkVisitor>) {
      return gjkRun(CoreOf<ShapeP>{P}, CoreOf<ShapeQ>{Q}, coreSettings, cache, NoGjkVisitor{});
    } else {
      auto ofShapes = [&](const GjkIteration<S>& core) {
        GjkIteration<S> record = core;
        record.supportingDistance -= r;
        record.minkowskiDistance = std::max(S(0), record.minkowskiDistance - r);
        return visit(record);
      };
      return gjkRun(CoreOf<ShapeP>{P}, CoreOf<ShapeQ>{Q}, coreSettings, cache, ofShapes);
    }
  }();
  result.lowerBound -= r;
  if (result.status == GjkStatus::Overlapping || result.status == GjkStatus::NumericalFailure) return result;
  const S dCore = result.distance;
  if (!(dCore > r)) {  // the balls about the cores' closest points overlap (a stalled dCore is an upper bound)
    if (result.status == GjkStatus::Separated || result.status == GjkStatus::Stalled) {
      result.status = GjkStatus::Overlapping;
      result.z = Vector3<S>::Zero();
    }
    result.distance = S(0);
    return result;
  }
  result.distance = dCore - r;
  if (std::isfinite(dCore)) {  // (a boolean query may stop before any simplex: no z yet, distance infinite)
    const Vector3<S> zHat = result.z / dCore;
    result.z = zHat * result.distance;
    result.witnessP += rP * zHat;
    result.witnessQ -= rQ * zHat;
  }
  return result;
}

/// The closest points of two segments \f$[a_0, a_1]\f$ and \f$[b_0, b_1]\f$ (either may be a
/// point), as the parameters (u, v) of \f$x = a_0 + u\,d_1\f$ and \f$y = b_0 + v\,d_2\f$.
///
/// Derivation. With \f$d_1 = a_1 - a_0\f$, \f$d_2 = b_1 - b_0\f$, \f$r = a_0 - b_0\f$, minimise
/// \f$f(u, v) = \lVert r + u\,d_1 - v\,d_2\rVert^2\f$ over the unit square. With
/// \f$a = d_1\!\cdot d_1\f$, \f$b = d_1\!\cdot d_2\f$, \f$c = d_1\!\cdot r\f$, \f$e = d_2\!\cdot d_2\f$,
/// \f$f_0 = d_2\!\cdot r\f$ the gradient vanishes where
/// \f$a u - b v = -c\f$ and \f$b u - e v = -f_0\f$, i.e. \f$u = (b f_0 - c e)/(a e - b^2)\f$.
/// For a fixed u the best v is \f$(b u + f_0)/e\f$ clamped to [0, 1], for a fixed v the best
/// u is \f$(b v - c)/a\f$ clamped. f is a convex quadratic, so: take the lines' u clamped
/// (any u when they are parallel, \f$a e - b^2 = 0\f$), the best v for it, and if that v had
/// to be clamped, the best u for the clamped v. A point core (a = 0 or e = 0) fixes its
/// parameter at 0 and the other is one projection. Its independent check, in long double
/// and written otherwise (no product of lengths subtracted), is the reference library's
/// closestSegmentSegment (gjkx/reference/closest_points.hpp; tests/gjk/test_gjk_rounded.cpp).
template <typename S>
std::pair<S, S> closestParametersOfSegments(const CoreEnds<S>& A, const CoreEnds<S>& B) {
  const Vector3<S> d1 = A.b - A.a, d2 = B.b - B.a, r = A.a - B.a;
  const S a = d1.squaredNorm(), e = d2.squaredNorm(), f0 = d2.dot(r);
  auto clamp01 = [](S x) { return std::min(S(1), std::max(S(0), x)); };
  if (a == S(0) && e == S(0)) return {S(0), S(0)};  // two points
  if (a == S(0)) return {S(0), clamp01(f0 / e)};     // a point and a segment
  const S c = d1.dot(r);
  if (e == S(0)) return {clamp01(-c / a), S(0)};     // a segment and a point
  const S b = d1.dot(d2);
  const S denominator = a * e - b * b;  // >= 0; round-off size when (nearly) parallel
  S u = denominator > std::numeric_limits<S>::epsilon() * a * e ? clamp01((b * f0 - c * e) / denominator) : S(0);
  S v = (b * u + f0) / e;
  if (v < S(0) || v > S(1)) {
    v = clamp01(v);
    u = clamp01((b * v - c) / a);
  }
  return {u, v};
}

/// GJK on two rounded shapes whose cores are points or segments (`HasSegmentCore`): the
/// spheres and capsules. §2.2's loop on such cores ends in one to three iterations at
/// the closest points of two segments, which are known in closed form
/// (`closestParametersOfSegments`), so the scene that needs only these shapes leaves the
/// general machinery out: no support queries, no sub-algorithm, no warm start (the cache
/// is neither read nor written). The result is what `gjkOnCores` returns, with the exact
/// closest features of the cores as its simplex and the distance along z as its lower bound.
template <typename ShapeP, typename ShapeQ>
GjkResult<typename ShapeP::Scalar> gjkOnSegmentCores(const ShapeP& P, const ShapeQ& Q,
                                                     const GjkSettings<typename ShapeP::Scalar>& settings) {
  using S = typename ShapeP::Scalar;
  const CoreEnds<S> A = P.coreEnds(), B = Q.coreEnds();
  const auto [u, v] = closestParametersOfSegments(A, B);
  const Vector3<S> p = A.a + u * (A.b - A.a), q = B.a + v * (B.b - B.a);  // the cores' closest points
  const S rP = P.coreRadius(), rQ = Q.coreRadius(), radius = rP + rQ;

  GjkResult<S> result;
  result.iterations = 1;
  // The closest feature of V_Q - V_P: a vertex, an edge, or (two edges) the parallelogram of
  // their differences, written as the triangle of it that holds z, so that
  // \f$z = \sum_k \lambda_k (q_k - p_k)\f$ as in any GJK simplex.
  Simplex<S>& x = result.simplex;
  auto vertex = [&](const Vector3<S>& pk, const Vector3<S>& qk, S lambda) {
    SimplexVertex<S>& w = x.vertices[x.size];
    w.p = pk;
    w.q = qk;
    w.w = qk - pk;
    w.s = p - q;  // the direction that finds the closest features
    w.hintP = w.hintQ = 0;
    x.lambda[x.size++] = lambda;
  };
  const bool edgeP = u > S(0) && u < S(1), edgeQ = v > S(0) && v < S(1);
  const Vector3<S>& pEnd = u < S(1) ? A.a : A.b;
  const Vector3<S>& qEnd = v < S(1) ? B.a : B.b;
  if (edgeP && edgeQ) {
    if (u + v <= S(1)) {
      vertex(A.a, B.a, S(1) - u - v), vertex(A.b, B.a, u), vertex(A.a, B.b, v);
    } else {
      vertex(A.b, B.b, u + v - S(1)), vertex(A.a, B.b, S(1) - u), vertex(A.b, B.a, S(1) - v);
    }
  } else if (edgeP) {
    vertex(A.a, qEnd, S(1) - u), vertex(A.b, qEnd, u);
  } else if (edgeQ) {
    vertex(pEnd, B.a, S(1) - v), vertex(pEnd, B.b, v);
  } else {
    vertex(pEnd, qEnd, S(1));
  }
  const Vector3<S> zCore = q - p;
  x.z = zCore;
  const S dCore = zCore.norm();
  result.witnessP = p;
  result.witnessQ = q;
  if (dCore > S(0)) {
    result.separatingVector = zCore / dCore;
    result.lowerBound = dCore - radius;  // SD along z of the cores is their distance (§2.3)
  }
  if (!(dCore > radius)) {  // the balls about the cores' closest points overlap
    result.status = GjkStatus::Overlapping;
    result.distance = S(0);
    return result;
  }
  result.distance = dCore - radius;
  result.z = result.separatingVector * result.distance;
  result.witnessP += rP * result.separatingVector;
  result.witnessQ -= rQ * result.separatingVector;
  result.status = result.distance > settings.separationThreshold ? GjkStatus::SeparatingVector : GjkStatus::Separated;
  return result;
}
}  // namespace detail

/// GJK (§2.2): the closest distance between convex sets P and Q, and their closest points.
///
/// "Begin GJK with two convex polyhedra P and Q, an arbitrary nonzero vector \f$\vec{s}_0\f$,
/// and two vertex sets \f$V_P\f$ and \f$V_Q\f$, initially empty. At each iteration i, append
/// the vertices \f$S_P(\vec{s}_i)\f$ and \f$S_Q(-\vec{s}_i)\f$ to \f$V_P\f$ and \f$V_Q\f$ [...]
/// Then calculate the feature of the Minkowski sum \f$V_Z = V_Q - V_P\f$ [...] which is closest
/// to the origin. [...] GJK reiterates with \f$\vec{s}_{i+1}\f$ set to z until this distance no
/// longer decreases."
///
/// Each iteration also measures the supporting distance \f$SD(P,Q,\vec{s}_i)\f$ of §2.3 (a
/// lower bound of the distance, where the Minkowski distance is an upper bound); their
/// gap is the convergence test, and with `settings.separationThreshold` the run stops at
/// the first separating vector (the boolean query).
///
/// Rounded shapes (spheres, capsules; support.hpp `IsRounded`) are, by default, handled
/// by GJK on their cores with the radii subtracted (`detail::gjkOnCores`): the paper's
/// GJK on the curved surface converges only linearly (16 to 29 iterations on two spheres
/// at the default tolerance), on the cores it ends in one to three. When both cores are
/// points or segments (two spheres or capsules, `HasSegmentCore`) and no visitor is
/// given, those iterations are replaced by their known answer, the closest points of two
/// segments (`detail::gjkOnSegmentCores`), so such a scene pays for none of the loop.
///
/// @param P, Q      support mappings (any types with `support(s)` and `center()`)
/// @param settings  tolerances, iteration cap, optional separation threshold
/// @param cache     optional warm start: read if valid, written at the end
/// @param visit     optional per-iteration visitor `bool(const GjkIteration<S>&)`; returning
///                  false stops the run (`StoppedByVisitor`). A `GjkTrace` keeps every iteration.
template <typename ShapeP, typename ShapeQ, typename Visitor = NoGjkVisitor>
GjkResult<typename ShapeP::Scalar> gjk(const ShapeP& P, const ShapeQ& Q,
                                       const GjkSettings<typename ShapeP::Scalar>& settings = {},
                                       GjkCache<typename ShapeP::Scalar>* cache = nullptr, Visitor&& visit = {}) {
  using S = typename ShapeP::Scalar;
  static_assert(std::is_same_v<S, typename ShapeQ::Scalar>, "P and Q must use the same scalar type");
  // Two spheres or capsules: the cores' answer in closed form (`detail::gjkOnSegmentCores`).
  // A visitor sees the loop itself, so a trace still runs it.
  if constexpr (HasSegmentCore<ShapeP>::value && HasSegmentCore<ShapeQ>::value &&
                std::is_same_v<std::decay_t<Visitor>, NoGjkVisitor>) {
    if (settings.roundedCores) return detail::gjkOnSegmentCores(P, Q, settings);
  }
  if constexpr (IsRounded<ShapeP>::value || IsRounded<ShapeQ>::value) {
    const S rP = coreRadiusOf(P), rQ = coreRadiusOf(Q);
    if (settings.roundedCores && (rP > S(0) || rQ > S(0)))
      return detail::gjkOnCores(P, Q, rP, rQ, settings, cache, std::forward<Visitor>(visit));
  }
  return detail::gjkRun(P, Q, settings, cache, std::forward<Visitor>(visit));
}

}  // namespace gjkx
