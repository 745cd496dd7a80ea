/// @file
/// @brief The static test of §1 over an interval: the static intersection test at evenly
/// spaced instants, with the first instant found intersecting (Fig. 1, left column).
///
/// "Static intersection tests check for intersection at specific instances in time. [...]
/// they often miss collisions, especially for small or flat objects, because although an
/// object pair might not intersect at two separate times, they may have actually passed
/// straight through each other." `staticSampling` runs the static test of §2.3
/// (gjkx::intersect) at N instants \f$t_k = t_0 + (t_1 - t_0)\,k / (N - 1)\f$, both ends
/// included, and stops at the first one that is not proven disjoint: its time is the
/// static test's time of impact (late by up to one spacing, and blind to what happens
/// between two instants). `staticTest` is its yes/no.
///
/// The chapter 04 figures, the study (chapters/09_study) and its table of extreme cases
/// run this one copy.
#pragma once

#include <gjkx/supporting_distance/intersection.hpp>

namespace gjkx {

/// How static sampling ended.
enum class StaticSamplingStatus {
  Hit,               ///< the bodies intersect (or are within the tolerance) at the instant `time`
  NoCollision,       ///< disjoint at every instant (what happens between them is not seen)
  IterationCap,      ///< GJK's cap ran out at the instant `time` before it proved either: undecided
  NumericalFailure,  ///< a support mapping returned a point that is not finite at the instant `time`
};

/// The name of a status, for messages and tables.
inline const char* toString(StaticSamplingStatus status) {
  switch (status) {
    case StaticSamplingStatus::Hit: return "hit";
    case StaticSamplingStatus::NoCollision: return "no-collision";
    case StaticSamplingStatus::IterationCap: return "iteration-cap";
    case StaticSamplingStatus::NumericalFailure: return "numerical-failure";
  }
  return "?";
}

/// Whether a status must be taken as a collision by a caller that may not miss one: a
/// hit, and the undecided ones (the cap, a numerical failure).
inline bool reportsCollision(StaticSamplingStatus status) { return status != StaticSamplingStatus::NoCollision; }

/// What static sampling found.
template <typename S>
struct StaticSamplingResult {
  /// How it ended.
  StaticSamplingStatus status = StaticSamplingStatus::NoCollision;
  /// The first instant not proven disjoint (`Hit` and the undecided statuses); \f$t_1\f$ when `NoCollision`.
  S time = S(0);
  /// The status of the static test at that instant (`Disjoint` when `NoCollision`).
  IntersectionStatus intersection = IntersectionStatus::Disjoint;
  /// Instants tested (static tests run, each one GJK run).
  int samplesRun = 0;
};

/// The static test (§1) of the moving bodies P and Q at `samples` evenly spaced instants of
/// \f$[t_0, t_1]\f$, both ends included; stops at the first instant not proven disjoint.
/// Throws std::invalid_argument for \f$t_1 < t_0\f$, a non-finite time, or fewer than 2 samples.
template <typename MovingP, typename MovingQ>
StaticSamplingResult<typename MovingP::Scalar> staticSampling(const MovingP& P, const MovingQ& Q, typename MovingP::Scalar t0,
                                                              typename MovingP::Scalar t1, int samples,
                                                              const IntersectionSettings<typename MovingP::Scalar>& settings = {}) {
  using S = typename MovingP::Scalar;
  requireFinite(t0, "staticSampling.t0");
  requireFinite(t1, "staticSampling.t1");
  if (t1 < t0) failInput("staticSampling.t1", "must not be before t0");
  if (samples < 2) failInput("staticSampling.samples", "needs at least 2 (the two ends)");
  StaticSamplingResult<S> out;
  out.time = t1;
  for (int k = 0; k < samples; ++k) {
    const S t = t0 + (t1 - t0) * S(k) / S(samples - 1);
    const IntersectionStatus status = intersect(P.at(t), Q.at(t), settings).status;
    out.samplesRun = k + 1;
    if (status == IntersectionStatus::Disjoint) continue;
    out.time = t;
    out.intersection = status;
    out.status = status == IntersectionStatus::IterationCap       ? StaticSamplingStatus::IterationCap
                 : status == IntersectionStatus::NumericalFailure ? StaticSamplingStatus::NumericalFailure
                                                                  : StaticSamplingStatus::Hit;
    return out;
  }
  return out;
}

/// The static test (§1) as a yes/no: does static sampling at `samples` instants of
/// \f$[t_0, t_1]\f$ (both ends included) report a collision? Never a false alarm; misses
/// what happens between the samples.
template <typename MovingP, typename MovingQ>
bool staticTest(const MovingP& P, const MovingQ& Q, typename MovingP::Scalar t0, typename MovingP::Scalar t1, int samples = 2,
                const IntersectionSettings<typename MovingP::Scalar>& settings = {}) {
  if (samples < 2) failInput("staticTest.samples", "needs at least 2 (the two ends)");
  return reportsCollision(staticSampling(P, Q, t0, t1, samples, settings).status);
}

}  // namespace gjkx
