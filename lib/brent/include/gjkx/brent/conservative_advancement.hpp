/// @file
/// @brief Conservative advancement: §4's "popular way" to the time of impact (the paper's
/// reference [8]), beside the §5 solver it is compared with.
///
/// §4: "A popular way to compute the TOI [...] is conservative advancement [8]": march the
/// time forward by steps that cannot skip a contact. At time t GJK gives a proven lower
/// bound d of the distance between P(t) and Q(t) (its largest supporting distance, §2.3);
/// if no point of either body moves faster than the caller's bound L on the relative
/// speed, the distance cannot fall to zero before t + d / L, so the next step is there:
/// \f[ t_{k+1} = t_k + \frac{\max(d_k, 0)}{L}. \f]
/// The march ends with a hit when GJK finds the bodies overlapping or closer than the
/// collision tolerance, with no collision when it passes \f$t_1\f$, and with its own status
/// when the cap on steps runs out (a slow grazing approach takes many small steps) or a
/// support mapping returns a point that is not finite. Unlike the §5 solver, it needs the
/// bound L, and its steps shrink with the distance: many GJK runs for a graze.
///
/// The study (chapters/09_study) and its table of extreme cases run this one copy.
#pragma once

#include <gjkx/gjk/gjk.hpp>
#include <gjkx/supporting_distance/intersection.hpp>

#include <algorithm>
#include <cmath>

namespace gjkx {

/// How conservative advancement ended.
enum class ConservativeAdvancementStatus {
  Hit,               ///< the bodies are overlapping or within the collision tolerance at `time`
  NoCollision,       ///< a step passed \f$t_1\f$: proven apart over the whole interval
  IterationCap,      ///< `maxSteps` ran out at `time`: undecided, never "no collision"
  NumericalFailure,  ///< GJK reported a support point that is not finite, at `time`
};

/// The name of a status, for messages and tables.
inline const char* toString(ConservativeAdvancementStatus status) {
  switch (status) {
    case ConservativeAdvancementStatus::Hit: return "hit";
    case ConservativeAdvancementStatus::NoCollision: return "no-collision";
    case ConservativeAdvancementStatus::IterationCap: return "iteration-cap";
    case ConservativeAdvancementStatus::NumericalFailure: return "numerical-failure";
  }
  return "?";
}

/// Settings of conservative advancement.
template <typename S>
struct ConservativeAdvancementSettings {
  /// L: a bound on how fast the distance between P(t) and Q(t) can fall, the largest
  /// relative speed of any two of their points (for a rigid body, |v| + |a| + |w| r summed
  /// over both bodies, r the bounding radius about the rotation centre). Must be finite
  /// and not negative; 0 (nothing moves) decides the interval at \f$t_0\f$.
  S relativeSpeedBound = S(0);
  /// A hit when GJK's distance falls below this (§2.3's collision tolerance).
  S collisionTolerance = defaultCollisionTolerance<S>();
  /// The march ends with `IterationCap` after this many GJK runs.
  int maxSteps = 10000;
  /// Settings of every GJK run.
  GjkSettings<S> gjk;
};

/// What conservative advancement found.
template <typename S>
struct ConservativeAdvancementResult {
  /// How it ended.
  ConservativeAdvancementStatus status = ConservativeAdvancementStatus::IterationCap;
  /// The time of impact when `Hit`; the last time reached for the cap and a numerical
  /// failure; \f$t_1\f$ when `NoCollision`.
  S time = S(0);
  /// GJK runs made (one per step).
  int steps = 0;
};

/// Whether a status must be taken as a collision by a caller that may not miss one: a
/// hit, and the undecided ones (the cap, a numerical failure).
inline bool reportsCollision(ConservativeAdvancementStatus status) {
  return status != ConservativeAdvancementStatus::NoCollision;
}

/// Conservative advancement of the moving bodies P and Q over \f$[t_0, t_1]\f$ (see the file
/// comment). Throws std::invalid_argument for \f$t_1 < t_0\f$, a non-finite time, a negative
/// or non-finite speed bound, a tolerance that is not positive, or `maxSteps` < 1.
template <typename MovingP, typename MovingQ>
ConservativeAdvancementResult<typename MovingP::Scalar> conservativeAdvancement(
    const MovingP& P, const MovingQ& Q, typename MovingP::Scalar t0, typename MovingP::Scalar t1,
    const ConservativeAdvancementSettings<typename MovingP::Scalar>& settings) {
  using S = typename MovingP::Scalar;
  requireFinite(t0, "conservativeAdvancement.t0");
  requireFinite(t1, "conservativeAdvancement.t1");
  if (t1 < t0) failInput("conservativeAdvancement.t1", "must not be before t0");
  const S L = settings.relativeSpeedBound;
  if (!(L >= S(0)) || !std::isfinite(L))
    failInput("conservativeAdvancementSettings.relativeSpeedBound", "must be finite and not negative");
  if (!(settings.collisionTolerance > S(0))) failInput("conservativeAdvancementSettings.collisionTolerance", "must be positive");
  if (settings.maxSteps < 1) failInput("conservativeAdvancementSettings.maxSteps", "must be at least 1");

  ConservativeAdvancementResult<S> out;
  S t = t0;
  for (int step = 0; step < settings.maxSteps; ++step) {
    const GjkResult<S> r = gjk(P.at(t), Q.at(t), settings.gjk);
    out.steps = step + 1;
    out.time = t;
    if (r.status == GjkStatus::NumericalFailure) {
      out.status = ConservativeAdvancementStatus::NumericalFailure;
      return out;
    }
    if (r.status == GjkStatus::Overlapping || r.distance < settings.collisionTolerance) {
      out.status = ConservativeAdvancementStatus::Hit;
      return out;
    }
    if (L == S(0)) {  // nothing moves: the distance at t0 holds over the whole interval
      out.status = ConservativeAdvancementStatus::NoCollision;
      out.time = t1;
      return out;
    }
    t += std::max(r.lowerBound, S(0)) / L;  // proven: the bodies are at least lowerBound apart
    if (t > t1) {
      out.status = ConservativeAdvancementStatus::NoCollision;
      out.time = t1;
      return out;
    }
  }
  out.status = ConservativeAdvancementStatus::IterationCap;
  out.time = t;
  return out;
}

}  // namespace gjkx
