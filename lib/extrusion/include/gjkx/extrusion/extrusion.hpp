/// @file
/// @brief The separating hyperspace test over a time interval \f$[t_0, t_1]\f$ (§3, Fig. 1, Fig. 4).
#pragma once

#include <gjkx/extrusion/certified_margin.hpp>
#include <gjkx/gjk/gjk.hpp>
#include <gjkx/supporting_distance/intersection.hpp>

#include <algorithm>
#include <array>
#include <limits>
#include <utility>
#include <vector>

namespace gjkx {

/// How the extrusion test ended.
enum class ExtrusionStatus {
  NoCollision,       ///< a vector separates P and Q at both \f$t_0\f$ and \f$t_1\f$: no collision on the whole interval
  Undecided,         ///< GJK at \f$t_0\f$ halted without such a vector: "this extrusion test fails" (§3); see §5
  CollidingAtStart,  ///< P(\f$t_0\f$) and Q(\f$t_0\f$) are within the collision tolerance
  IterationCap,      ///< GJK's iteration cap ran out at \f$t_0\f$
  NumericalFailure,  ///< a support mapping returned a point that is not finite
};

/// The name of a status, for messages and tables.
inline const char* toString(ExtrusionStatus status) {
  switch (status) {
    case ExtrusionStatus::NoCollision: return "no-collision";
    case ExtrusionStatus::Undecided: return "undecided";
    case ExtrusionStatus::CollidingAtStart: return "colliding-at-start";
    case ExtrusionStatus::IterationCap: return "iteration-cap";
    case ExtrusionStatus::NumericalFailure: return "numerical-failure";
  }
  return "?";
}

/// Settings of the extrusion test.
template <typename S>
struct ExtrusionSettings {
  /// P and Q collide when closer than this (§2.3); default \f$\sqrt{\epsilon}\f$.
  S collisionTolerance = defaultCollisionTolerance<S>();
  /// The paper's test, or the certified one (beyond the paper, certified_margin.hpp).
  ExtrusionVariant variant = ExtrusionVariant::Paper;
  /// Settings of the GJK run at \f$t_0\f$.
  GjkSettings<S> gjk;
  /// Start each support search at \f$t_1\f$ where the last one ended (GJK's successive
  /// directions turn little; beyond the paper, `ToiSettings::supportHints`); false starts
  /// every one at the first vertex. The same verdict either way.
  bool supportHints = true;
};

/// One step of the test, as a figure or a step-by-step test reads it.
template <typename S>
struct ExtrusionStep {
  /// The GJK iteration i at \f$t_0\f$ (-1 for the remembered vector tried first).
  int i = 0;
  /// \f$\vec{s}_i\f$ (unit).
  Vector3<S> s = Vector3<S>::Zero();
  /// \f$SD(P(t_0), Q(t_0), \vec{s}_i)\f$.
  S sdStart = S(0);
  /// \f$SD(P(t_1), Q(t_1), \vec{s}_i)\f$, computed only where \f$\vec{s}_i\f$ separates at \f$t_0\f$.
  S sdEnd = -std::numeric_limits<S>::infinity();
  /// True when \f$SD(t_0) >\f$ tolerance: \f$\vec{s}_i\f$ is a separating vector at \f$t_0\f$.
  bool separatesStart = false;
  /// True when \f$SD >\f$ tolerance + margin at both \f$t_0\f$ and \f$t_1\f$: the test succeeds.
  bool separatesEnd = false;
};

/// A visitor that keeps every step of the extrusion test.
template <typename S>
struct ExtrusionTrace {
  /// The steps, in order.
  std::vector<ExtrusionStep<S>> steps;
  /// Keeps the step.
  void operator()(const ExtrusionStep<S>& step) { steps.push_back(step); }
};

/// The default visitor: sees nothing, costs nothing.
struct NoExtrusionVisitor {
  /// Ignores the step.
  template <typename Step>
  void operator()(const Step&) const {}
};

/// The separating vectors found at \f$t_0\f$ (§5: "a constant number, generally less than
/// seven"), kept for the time-of-impact solver with their supporting distances at both
/// ends. Holds up to 16; past that, a new vector replaces the one with the smallest
/// \f$SD(t_1)\f$. Each vector also keeps the hill-climbing hints of its last supports (speed:
/// the solver evaluates SD along it at many times, and a climb started where the last
/// one ended takes a step or two).
template <typename S>
struct SeparatingVectors {
  /// Capacity.
  static constexpr int kCapacity = 16;
  /// The unit vectors; only the first `count` are used.
  std::array<Vector3<S>, kCapacity> vectors;
  /// \f$SD(t_0, \vec{s}_k)\f$ of each (above the collision tolerance).
  std::array<S, kCapacity> sdStart{};
  /// \f$SD(t_1, \vec{s}_k)\f$ of each.
  std::array<S, kCapacity> sdEnd{};
  /// Hill-climbing hint of \f$S_P(\vec{s}_k)\f$ at the last time SD was evaluated along \f$\vec{s}_k\f$.
  std::array<SupportHint, kCapacity> hintP{};
  /// Hill-climbing hint of \f$S_Q(-\vec{s}_k)\f$, likewise.
  std::array<SupportHint, kCapacity> hintQ{};
  /// How many are held.
  int count = 0;
  /// Adds a vector (once), or replaces the weakest when full; `hp`, `hq` are its hints.
  void add(const Vector3<S>& s, S sd0, S sd1, SupportHint hp = 0, SupportHint hq = 0) {
    for (int k = 0; k < count; ++k)
      if (vectors[k] == s) return;  // GJK may repeat a direction: keep it once
    int slot = count;
    if (count == kCapacity) {
      slot = 0;
      for (int k = 1; k < count; ++k)
        if (sdEnd[k] < sdEnd[slot]) slot = k;
      if (sdEnd[slot] >= sd1) return;
    } else {
      ++count;
    }
    vectors[slot] = s;
    sdStart[slot] = sd0;
    sdEnd[slot] = sd1;
    hintP[slot] = hp;
    hintQ[slot] = hq;
  }
};

/// What the extrusion test found.
template <typename S>
struct ExtrusionResult {
  /// The verdict.
  ExtrusionStatus status = ExtrusionStatus::IterationCap;
  /// The vector that separates at both ends (unit), when `NoCollision`.
  Vector3<S> separatingVector = Vector3<S>::Zero();
  /// The closest distance at \f$t_0\f$ (GJK's distance; an upper bound if GJK stopped early
  /// or stalled, see `gjkStatus`).
  S distanceAtStart = std::numeric_limits<S>::infinity();
  /// How GJK at \f$t_0\f$ ended: `Separated` or `Overlapping` when `distanceAtStart` is the
  /// closest distance, `Stalled` when it is only an upper bound (gjk.hpp), `StoppedByVisitor`
  /// when a vector separating at both ends stopped it.
  GjkStatus gjkStatus = GjkStatus::IterationCap;
  /// The closest point of P at \f$t_0\f$ (GJK's witness).
  Vector3<S> witnessP = Vector3<S>::Zero();
  /// The closest point of Q at \f$t_0\f$ (GJK's witness).
  Vector3<S> witnessQ = Vector3<S>::Zero();
  /// The separating vectors found at \f$t_0\f$, each with its \f$SD(t_1)\f$ (§5).
  SeparatingVectors<S> separating;
  /// \f$\max_i SD(P(t_1), Q(t_1), \vec{s}_i)\f$ over them: §5's approximate maximum
  /// supporting distance at \f$t_1\f$ (\f$-\infty\f$ if none separates at \f$t_0\f$).
  S maxSdEnd = -std::numeric_limits<S>::infinity();
  /// The margin asked of every vector (0 for the paper's variant).
  S margin = S(0);
  /// GJK iterations run at \f$t_0\f$.
  int gjkIterations = 0;
  /// Supporting distances evaluated (each is two support queries).
  int sdEvaluations = 0;
  /// True when the remembered vector decided the test without running GJK.
  bool usedRememberedVector = false;
};

/// What one interval leaves for the next (temporal coherence): the separating vector
/// that decided it, tried first next time, GJK's own warm start, and where the last
/// support searches at the far end ended. The time-of-impact solver also passes one from
/// each complete test to the next within a query (§5's restarts at \f$t_x\f$): the bodies
/// have moved little since the last test, so GJK starts from the last simplex.
template <typename S>
struct ExtrusionCache {
  /// The last vector that separated at both ends.
  Vector3<S> separatingVector = Vector3<S>::Zero();
  /// True once a vector is remembered.
  bool valid = false;
  /// GJK's warm start at \f$t_0\f$.
  GjkCache<S> gjk;
  /// Hill-climbing hint of the last support of P searched at the far end \f$t_1\f$.
  SupportHint endHintP = 0;
  /// Hill-climbing hint of the last support of Q searched at the far end \f$t_1\f$.
  SupportHint endHintQ = 0;
};

/// \f$SD(P(t), Q(t), \vec{s})\f$ of two moving bodies at time t, for a unit s.
template <typename MovingP, typename MovingQ>
typename MovingP::Scalar supportingDistanceAt(const MovingP& P, const MovingQ& Q,
                                              const Vector3<typename MovingP::Scalar>& s, typename MovingP::Scalar t) {
  return supportingDistance(P.at(t), Q.at(t), s);
}

/// The separating hyperspace test (§3) on the bodies already placed at both ends of the
/// interval: `P0`, `Q0` at \f$t_0\f$ and `P1`, `Q1` at \f$t_1\f$ (static support mappings, e.g.
/// `P.at(t0)`), with the certified `margin` over it (0 for the paper's variant). This is
/// `extrusionTest` without the poses, for a caller that has them already: the
/// time-of-impact solver tests many intervals \f$[t_x, t_1]\f$ with the same far end, and
/// places the bodies at \f$t_x\f$ once for both its approximate SD and the test (speed).
template <typename PlacedP0, typename PlacedQ0, typename PlacedP1, typename PlacedQ1,
          typename Visitor = NoExtrusionVisitor>
ExtrusionResult<typename PlacedP0::Scalar> extrusionTestPlaced(const PlacedP0& P0, const PlacedQ0& Q0, const PlacedP1& P1,
                                                               const PlacedQ1& Q1, typename PlacedP0::Scalar margin,
                                                               const ExtrusionSettings<typename PlacedP0::Scalar>& settings,
                                                               ExtrusionCache<typename PlacedP0::Scalar>* cache = nullptr,
                                                               Visitor&& visit = {}) {
  using S = typename PlacedP0::Scalar;
  ExtrusionResult<S> result;
  result.margin = margin;
  const S tol = settings.collisionTolerance;
  const S threshold = tol + result.margin;  // what both ends must exceed

  // The supports at t1 are searched along GJK's successive directions, which turn little
  // from one iteration to the next: each search starts where the last one ended (speed;
  // the hints change where a climb starts, never where it ends).
  SupportHint endHintP = cache ? cache->endHintP : 0, endHintQ = cache ? cache->endHintQ : 0;
  auto coldEndHints = [&] {  // without hints, every search at t1 starts at the first vertex
    if (!settings.supportHints) endHintP = endHintQ = 0;
  };
  auto keepEndHints = [&] {
    if (!cache) return;
    cache->endHintP = endHintP;
    cache->endHintQ = endHintQ;
  };

  // Temporal coherence: the vector that separated the last interval is tried first.
  if (cache && cache->valid) {
    ExtrusionStep<S> step;
    step.i = -1;
    step.s = cache->separatingVector;
    step.sdStart = supportingDistance(P0, Q0, step.s);
    ++result.sdEvaluations;
    step.separatesStart = step.sdStart > tol;
    if (step.sdStart > threshold) {
      coldEndHints();
      step.sdEnd = supportingDistance(P1, Q1, step.s, endHintP, endHintQ);
      ++result.sdEvaluations;
      step.separatesEnd = step.sdEnd > threshold;
    }
    visit(step);
    if (step.separatesEnd) {
      result.status = ExtrusionStatus::NoCollision;
      result.separatingVector = step.s;
      result.usedRememberedVector = true;
      keepEndHints();
      return result;
    }
  }

  // GJK at t0; its visitor sees SD(t0, s_i) and asks SD(t1, s_i) where s_i separates at t0.
  bool found = false;
  auto atEachIteration = [&](const GjkIteration<S>& it) {
    ++result.sdEvaluations;  // GJK measured SD(t0, s_i) on the way
    ExtrusionStep<S> step;
    step.i = it.i;
    step.s = it.s.normalized();
    step.sdStart = it.supportingDistance;
    step.separatesStart = step.sdStart > tol;
    if (step.separatesStart) {
      coldEndHints();
      step.sdEnd = supportingDistance(P1, Q1, step.s, endHintP, endHintQ);
      ++result.sdEvaluations;
      step.separatesEnd = step.sdStart > threshold && step.sdEnd > threshold;
      result.separating.add(step.s, step.sdStart, step.sdEnd, endHintP, endHintQ);
      result.maxSdEnd = std::max(result.maxSdEnd, step.sdEnd);
      if (step.separatesEnd) {
        found = true;
        result.separatingVector = step.s;
      }
    }
    visit(step);
    return !found;  // stop GJK at the first vector that separates at both ends
  };
  GjkCache<S>* gjkCache = cache ? &cache->gjk : nullptr;
  const GjkResult<S> run = gjk(P0, Q0, settings.gjk, gjkCache, atEachIteration);
  result.gjkIterations = run.iterations;
  result.distanceAtStart = run.distance;
  result.gjkStatus = run.status;
  result.witnessP = run.witnessP;
  result.witnessQ = run.witnessQ;

  if (found) {
    result.status = ExtrusionStatus::NoCollision;
  } else if (run.status == GjkStatus::NumericalFailure) {
    result.status = ExtrusionStatus::NumericalFailure;
  } else if (run.status == GjkStatus::IterationCap) {
    result.status = ExtrusionStatus::IterationCap;
  } else if (run.status == GjkStatus::Overlapping || run.distance <= settings.collisionTolerance) {
    // (A stalled run's distance is an upper bound: at most the tolerance, it proves the contact too.)
    result.status = ExtrusionStatus::CollidingAtStart;
  } else {
    result.status = ExtrusionStatus::Undecided;
  }
  if (cache) {
    cache->valid = found;
    if (found) cache->separatingVector = result.separatingVector;
  }
  keepEndHints();
  return result;
}

/// The separating hyperspace test (§3) of two moving bodies over \f$[t_0, t_1]\f$.
///
/// "Assuming by induction that \f$P(t_0)\f$ and \f$Q(t_0)\f$ do not intersect, we execute the
/// GJK algorithm at \f$t_0\f$. At each iteration, we compute \f$SD(P(t_0), Q(t_0), \vec{s}_i)\f$. If
/// this distance is positive, \f$\vec{s}_i\f$ is a separating vector at \f$t_0\f$, so we compute
/// \f$SD(P(t_1), Q(t_1), \vec{s}_i)\f$. If this distance is also positive, then \f$\vec{s}_i\f$ is a
/// separating vector for both \f$t_0\f$ and \f$t_1\f$ and their separating spaces intersect, so
/// the test returns non-collision for the entire time interval."
///
/// "Positive" here means above the collision tolerance (plus the certified margin).
/// The bodies are any types with `at(t)` (a static support mapping) and
/// `accelerationBound()`: `Moving<Shape>` and `DeformingSimplex`.
template <typename MovingP, typename MovingQ, typename Visitor = NoExtrusionVisitor>
ExtrusionResult<typename MovingP::Scalar> extrusionTest(const MovingP& P, const MovingQ& Q, typename MovingP::Scalar t0,
                                                        typename MovingP::Scalar t1,
                                                        const ExtrusionSettings<typename MovingP::Scalar>& settings = {},
                                                        ExtrusionCache<typename MovingP::Scalar>* cache = nullptr,
                                                        Visitor&& visit = {}) {
  using S = typename MovingP::Scalar;
  const S margin = extrusionMargin(settings.variant, t1 - t0, S(P.accelerationBound()), S(Q.accelerationBound()));
  // One declaration per body: P and Q may be different kinds of body (a rigid
  // Moving<Shape> against a DeformingSimplex) whose at(t) return different types.
  return extrusionTestPlaced(P.at(t0), Q.at(t0), P.at(t1), Q.at(t1), margin, settings, cache,
                             std::forward<Visitor>(visit));
}

}  // namespace gjkx
