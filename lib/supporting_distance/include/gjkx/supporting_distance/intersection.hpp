/// @file
/// @brief The static intersection test: GJK that stops at the first separating vector (§2.3).
#pragma once

#include <gjkx/gjk/gjk.hpp>
#include <gjkx/motion/round_off.hpp>
#include <gjkx/supporting_distance/supporting_distance.hpp>

#include <cmath>
#include <limits>

namespace gjkx {

/// The answer of the static test.
enum class IntersectionStatus {
  Disjoint,          ///< a separating vector with \f$SD >\f$ tolerance was found: P and Q are apart
  Intersecting,      ///< no such vector exists: P and Q intersect or are within the tolerance
  IterationCap,      ///< GJK's iteration cap ran out before either was proven
  NumericalFailure,  ///< a support mapping returned a point that is not finite
  StoppedByVisitor,  ///< the caller's visitor stopped the run
};

/// The name of a status, for messages and tables.
inline const char* toString(IntersectionStatus status) {
  switch (status) {
    case IntersectionStatus::Disjoint: return "disjoint";
    case IntersectionStatus::Intersecting: return "intersecting";
    case IntersectionStatus::IterationCap: return "iteration-cap";
    case IntersectionStatus::NumericalFailure: return "numerical-failure";
    case IntersectionStatus::StoppedByVisitor: return "stopped-by-visitor";
  }
  return "?";
}

/// Settings of the static test.
template <typename S>
struct IntersectionSettings {
  /// P and Q collide when they are closer than this (§2.3): "enforcing separation between
  /// objects by a nonzero *collision tolerance* based on floating point precision".
  S collisionTolerance = defaultCollisionTolerance<S>();
  /// The GJK run's own settings (its separation threshold is set from the tolerance).
  GjkSettings<S> gjk;
};

/// What the static test found.
template <typename S>
struct IntersectionResult {
  /// The answer.
  IntersectionStatus status = IntersectionStatus::IterationCap;
  /// The separating vector (unit) when `Disjoint`.
  Vector3<S> separatingVector = Vector3<S>::Zero();
  /// \f$SD(P, Q, \vec{s})\f$ along it.
  S supportingDistance = -std::numeric_limits<S>::infinity();
  /// GJK iterations run.
  int iterations = 0;
};

/// Static intersection test (§2.3): "A boolean query can stop once it finds the first
/// such vector, because it proves P and Q are disjoint. If the GJK algorithm finds a
/// local minimum for the Minkowski distance and halts before a separating vector can be
/// found, then such a vector provably doesn't exist, and P and Q therefore must either
/// intersect, or be so close together that round-off error dominates the computation."
template <typename ShapeP, typename ShapeQ, typename Visitor = NoGjkVisitor>
IntersectionResult<typename ShapeP::Scalar> intersect(const ShapeP& P, const ShapeQ& Q,
                                                      const IntersectionSettings<typename ShapeP::Scalar>& settings = {},
                                                      GjkCache<typename ShapeP::Scalar>* cache = nullptr,
                                                      Visitor&& visit = {}) {
  using S = typename ShapeP::Scalar;
  GjkSettings<S> gjkSettings = settings.gjk;
  gjkSettings.separationThreshold = settings.collisionTolerance;
  const GjkResult<S> run = gjk(P, Q, gjkSettings, cache, std::forward<Visitor>(visit));
  IntersectionResult<S> out;
  out.iterations = run.iterations;
  out.separatingVector = run.separatingVector;
  out.supportingDistance = run.lowerBound;
  switch (run.status) {
    case GjkStatus::SeparatingVector: out.status = IntersectionStatus::Disjoint; break;
    case GjkStatus::Separated:  // converged below the tolerance: within it, hence colliding
    case GjkStatus::Stalled:    // "halts before a separating vector can be found": no SD above the tolerance
    case GjkStatus::Overlapping: out.status = IntersectionStatus::Intersecting; break;
    case GjkStatus::NumericalFailure: out.status = IntersectionStatus::NumericalFailure; break;
    case GjkStatus::IterationCap: out.status = IntersectionStatus::IterationCap; break;
    case GjkStatus::StoppedByVisitor: out.status = IntersectionStatus::StoppedByVisitor; break;
  }
  return out;
}

}  // namespace gjkx
