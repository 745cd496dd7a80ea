/// @file
/// @brief What a time-of-impact query of §5 is asked and what it answers: its settings
/// (`ToiSettings`), its verdict (`ToiStatus`, `ToiResult`) and the record of its steps for
/// the figures and the tests (`ToiTrace`).
///
/// Part of the solver of gjkx/brent/time_of_impact.hpp, the header to include; its file
/// comment is §5's paragraph and what a verdict proves.
#pragma once

#include <gjkx/extrusion/extrusion.hpp>
#include <gjkx/motion/round_off.hpp>
#include <gjkx/root_solver/brent_method.hpp>

#include <vector>

namespace gjkx {

/// How the time-of-impact solver ended.
enum class ToiStatus {
  NoCollision,        ///< the first extrusion test over \f$[t_0, t_1]\f$ succeeded
  PhotoFinish,        ///< no collision, proven on a chain of subintervals \f$[t_0, t_{x1}], \dots, [t_{xn}, t_1]\f$
  Hit,                ///< the bodies come within the collision tolerance at `time`
  StartsPenetrating,  ///< within the tolerance at \f$t_0\f$ and not moving apart
  Separating,         ///< within the tolerance at \f$t_0\f$ but provably moving apart: no new contact
  IterationCap,       ///< the cap on Brent iterations (or GJK's) ran out: undecided, never "no collision"
  NumericalFailure,   ///< a support mapping returned a point that is not finite
};

/// The name of a status, for messages and tables.
inline const char* toString(ToiStatus status) {
  switch (status) {
    case ToiStatus::NoCollision: return "no-collision";
    case ToiStatus::PhotoFinish: return "photo-finish";
    case ToiStatus::Hit: return "hit";
    case ToiStatus::StartsPenetrating: return "starts-penetrating";
    case ToiStatus::Separating: return "separating";
    case ToiStatus::IterationCap: return "iteration-cap";
    case ToiStatus::NumericalFailure: return "numerical-failure";
  }
  return "?";
}

/// True for the statuses that report a collision (or may, for a cap: a caller that must
/// not miss treats an undecided pair as colliding).
inline bool reportsCollision(ToiStatus status) {
  return status == ToiStatus::Hit || status == ToiStatus::StartsPenetrating || status == ToiStatus::IterationCap ||
         status == ToiStatus::NumericalFailure;
}

/// Settings of the time-of-impact solver.
template <typename S>
struct ToiSettings {
  /// Bodies closer than this collide (§2.3); default \f$\sqrt{\epsilon}\f$.
  S collisionTolerance = defaultCollisionTolerance<S>();
  /// Brent stops when the time of impact is bracketed within this fraction of the interval.
  /// Default \f$\sqrt{\epsilon}\f$.
  S timeTolerance = defaultTimeTolerance<S>();
  /// A restart whose exact distance is at most this ends the query with a hit there
  /// (beyond the paper; 0, the default, leaves §5's criterion alone: a hit needs the
  /// distance within the collision tolerance). A caller to whom a contact a little beyond
  /// the tolerance is as good as one at it (a simulation's impulse) sets, say, 1.5
  /// tolerances: a grazing pass whose distance stays just above the tolerance then ends
  /// at the first restart inside the band, instead of proving the pass free of contact one
  /// short link at a time (see time_of_impact.hpp's file comment, *Grazing*). Every reported time is still
  /// one proven free of contact, and no later than the first time within the tolerance.
  S acceptedDistance = S(0);
  /// `acceptedDistance` applies only once the query has taken this many Brent iterations,
  /// so that it cuts the long chains of a grazing pass and leaves every short query as §5
  /// ends it.
  int acceptedAfter = 0;
  /// The paper's extrusion test or the certified one.
  ExtrusionVariant variant = ExtrusionVariant::Paper;
  /// The cap on Brent iterations over all restarts (the paper saw at most 43).
  int maxIterations = 100;
  /// Settings of every GJK run.
  GjkSettings<S> gjk;
  /// Run the query in the frame of P (see `timeOfImpact`); false runs it in world
  /// coordinates, for comparison only (the study's extreme cases show what that costs).
  bool inFrameOfP = true;
  /// Start every complete extrusion test after the first where the last one ended (its GJK
  /// simplex and its support hints, `ExtrusionCache`), and the first where the caller's
  /// `coherence` cache says the last query ended; false runs each cold, to measure what the
  /// warm starts buy. The verdicts are the same either way.
  bool warmStart = true;
};

/// One Brent iterate of the solver, as chapter 05 draws it.
template <typename S>
struct ToiStep {
  /// The iterate \f$t_x\f$.
  S t = S(0);
  /// The approximate maximum supporting distance at \f$t_x\f$ from the stored vectors (less the
  /// margin); for a probe (`DistanceSecant`), the best proof of \f$[t_a, t_x]\f$ it found.
  S approximateMaxSd = S(0);
  /// The low end \f$t_a\f$ of the bracket the iterate was taken in: the last time proven free of contact.
  S bracketLow = S(0);
  /// The high end of that bracket.
  S bracketHigh = S(0);
  /// The rule that chose \f$t_x\f$.
  BrentStepKind kind = BrentStepKind::Bisection;
  /// True when the approximate maximum was at least the tolerance and a complete extrusion test
  /// followed; for a probe (which always runs its complete test first), when it proved
  /// \f$[t_a, t_x]\f$ free.
  bool completeTest = false;
};

/// One complete extrusion test of the solver: the first, one per restart, and the check at
/// the far end of a converged bracket.
template <typename S>
struct ToiInterval {
  /// Its start \f$t_a\f$ (the end is always \f$t_1\f$).
  S start = S(0);
  /// Its verdict.
  ExtrusionStatus status = ExtrusionStatus::Undecided;
  /// The exact closest distance at \f$t_a\f$.
  S distanceAtStart = S(0);
  /// The separating vectors found at \f$t_a\f$ (drawn as lines \f$SD(t, \vec{s}_k)\f$ by chapter 05).
  SeparatingVectors<S> separating;
};

/// A caller-owned record of a solver run (for the figures and step-by-step tests).
template <typename S>
struct ToiTrace {
  /// The Brent iterates, in order.
  std::vector<ToiStep<S>> steps;
  /// The complete extrusion tests, in order.
  std::vector<ToiInterval<S>> intervals;
};

/// What the solver found.
template <typename S>
struct ToiResult {
  /// The verdict.
  ToiStatus status = ToiStatus::IterationCap;
  /// The time of impact when `Hit` (\f$t_0\f$ for `StartsPenetrating`); for a cap, the last
  /// time proven free of contact.
  S time = S(0);
  /// The closest distance at `time`: for a hit, at most the tolerance (up to round-off), or,
  /// when the hit is reported at the last time proven free of contact (see the file
  /// comment), at most the tolerance plus what the bodies move in one time tolerance, or
  /// in one spacing of the caller's times near \f$t_0\f$ where that is coarser (see `timeOfImpact`).
  S distance = S(0);
  /// Unit contact normal at `time`, from P towards Q.
  Vector3<S> normal = Vector3<S>::Zero();
  /// The closest point of P at `time`.
  Vector3<S> witnessP = Vector3<S>::Zero();
  /// The closest point of Q at `time`.
  Vector3<S> witnessQ = Vector3<S>::Zero();
  /// Brent iterates evaluated (the paper: 2.2 on average, 43 at worst).
  int brentIterations = 0;
  /// Complete GJK runs (one per extrusion test).
  int gjkRuns = 0;
  /// Supporting distances evaluated, including those GJK measured.
  int sdEvaluations = 0;
  /// Complete extrusion tests after the first (restarts of Brent).
  int restarts = 0;
};

}  // namespace gjkx
