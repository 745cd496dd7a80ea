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

/// Which time-of-impact solver runs: §5 exactly as the paper wrote it, or this project's,
/// with every refinement beyond the paper on (`ToiSettings::paper()`, `ToiSettings::gjkx()`).
enum class ToiSolverMode {
  Paper,  ///< the paper's extrusion test and §5's loop, and nothing else
  Gjkx,   ///< §5 with this project's refinements (the default)
};

/// The name of a solver mode, as `gjkx_simulate --solver` and the scene file spell it.
inline const char* toString(ToiSolverMode mode) { return mode == ToiSolverMode::Paper ? "paper" : "gjkx"; }

/// Settings of the time-of-impact solver.
///
/// Every refinement beyond §5 is a switch of its own, documented with what it buys (the
/// numbers: figures/data/toi-refinements.md, written by `gjkx_toi_refinements`). They
/// change how much work a query does, never what a verdict proves: every interval
/// declared free of contact is proven so as §5's own steps prove it. `paper()` turns them
/// all off; `gjkx()`, the default, has them all on.
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
  /// Applies only with `acceptedBand`.
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

  // --- Beyond the paper: each refinement a switch (all on here, all off in paper()) ---

  /// *Warm-started complete tests.* Every complete extrusion test after the first starts
  /// where the last one ended (its GJK simplex and the support hints at \f$t_1\f$,
  /// `ExtrusionCache`): the restarts come ever closer to the contact, where the closest
  /// features change little, and a warm GJK needs a couple of iterations where a cold one
  /// needs five or more. §5 recomputes "a complete GJK extrusion test" at each restart.
  bool warmStart = true;
  /// *Coherence between queries* (§2.2's reinitialization from the previous query, which
  /// §5 does not ask of the extrusion test): the first complete test starts where the
  /// caller's `coherence` cache says the pair's last query ended (its separating vector,
  /// tried first, GJK's simplex and hints), and this query's end is kept there for the
  /// next. Needs `warmStart`.
  bool coherence = true;
  /// *Per-vector support hints.* Each stored separating vector keeps where its support
  /// searches last ended, and the searches at \f$t_1\f$ along GJK's successive directions
  /// start where the last one ended: hill climbing (§2.1) then takes a step or two instead
  /// of a climb from the first vertex. The hints change where a climb starts, never where
  /// it ends. (GJK's own climbs from one iteration to the next are GJK's, not a switch.)
  bool supportHints = true;
  /// *Reuse of the bracket's far end.* After a restart, Brent's bracket ends at the last
  /// bracket's far end where the new vectors are below the tolerance there, instead of at
  /// \f$t_1\f$: a first secant towards a far \f$t_1\f$ creeps (toi_refinements.hpp).
  bool farEndReuse = true;
  /// *The probe.* After a restart, a complete test where the exact distances of the last
  /// complete tests extrapolate to the tolerance (the secant, or Muller's parabola), and
  /// the proof of the interval up to it by the vectors found there: superlinear where the
  /// restarts of §5 converge only linearly under rotation (toi_refinements.hpp).
  bool probe = true;
  /// *The leap.* After a restart that advanced less than a quarter of what is left of the
  /// bracket, an iterate twice that advance ahead: it doubles the steps past a near miss's
  /// minimum instead of creeping towards it (toi_refinements.hpp).
  bool leap = true;
  /// *The accepted band.* `acceptedDistance` and `acceptedAfter` end a grazing pass at
  /// the first restart within the band; false ignores them (§5's criterion only).
  bool acceptedBand = true;
  /// *Moving apart at the start.* Bodies within the tolerance at \f$t_0\f$ that provably
  /// move apart (their supporting distance along the closest direction rises and stays
  /// positive) are reported `Separating`, not `StartsPenetrating`: a resting contact that
  /// leaves needs no impulse. §5 assumes, by induction, bodies apart at \f$t_0\f$.
  bool separatingAtStart = true;
  /// *The query's frame.* Run the query in the frame of P (see `timeOfImpact`); false runs
  /// it in world coordinates, as the paper does (the study's extreme cases show what that
  /// costs in float far from the origin).
  bool inFrameOfP = true;
  /// *The query's clock.* Run the query on times \f$t - t_0\f$ (see `timeOfImpact`); false
  /// runs it on the caller's clock, as the paper does (coarse in float far from t = 0).
  bool onQueryClock = true;

  /// §5 exactly as the paper wrote it: the paper's extrusion test, Brent's method on the
  /// approximate maximum supporting distance, a cold complete test at every restart, and
  /// no refinement (every switch above off, no accepted band).
  static ToiSettings paper() {
    ToiSettings settings;
    settings.variant = ExtrusionVariant::Paper;
    settings.acceptedDistance = S(0);
    settings.acceptedAfter = 0;
    settings.warmStart = settings.coherence = settings.supportHints = false;
    settings.farEndReuse = settings.probe = settings.leap = settings.acceptedBand = false;
    settings.separatingAtStart = settings.inFrameOfP = settings.onQueryClock = false;
    return settings;
  }
  /// This project's solver: every refinement on (the default settings).
  static ToiSettings gjkx() { return ToiSettings{}; }
  /// The preset of `mode`.
  static ToiSettings of(ToiSolverMode mode) { return mode == ToiSolverMode::Paper ? paper() : gjkx(); }
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
  /// True when GJK stalled at `time` (`GjkStatus::Stalled`): `distance` is then only an upper
  /// bound of the closest distance there (the contact within the tolerance still holds).
  bool distanceIsUpperBound = false;
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
