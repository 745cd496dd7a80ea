/// @file
/// @brief The time-of-impact solver of §5: the extrusion test of §3 driven by Brent's method.
///
/// §5: "If the initial extrusion test at \f$t_0\f$ and \f$t_1\f$ fails, we use the closest distance
/// at \f$t_0\f$ and the approximate maximum supporting distance at \f$t_1\f$ to calculate an
/// intermediate time \f$t_x\f$ using Brent's method. [...] we can speed up this intermediate
/// query by storing all the separating vectors \f$\vec{s}_i\f$ we found at \f$t_0\f$, and use this set
/// [...] to recalculate \f$SD(P(t_x), Q(t_x), \vec{s}_i)\f$ and obtain a new approximate maximum
/// supporting distance at \f$t_x\f$. If this distance is negative, we continue normally with
/// further iterations of Brent's method. However, if this distance is positive, we assume
/// P and Q are disjoint from \f$t_0\f$ to \f$t_x\f$, so we recompute a complete GJK extrusion test
/// for \f$t_x\f$ and \f$t_1\f$ in order to determine the exact closest distance at \f$t_x\f$ before we
/// proceed."
///
/// The function Brent solves on the current interval \f$[t_a, t_1]\f$ is
/// \f[ F(t) = \max_k SD(P(t), Q(t), \vec{s}_k) - m(t - t_a) - \mathrm{tol}, \f]
/// the approximate maximum supporting distance from the stored vectors \f$\vec{s}_k\f$, less the
/// certified margin m (zero for the paper's variant) and the collision tolerance: its root
/// is where the bodies come within the tolerance. \f$F(t_a) > 0\f$ (the exact distance at
/// \f$t_a\f$ exceeds the tolerance) and \f$F(t_1) \le 0\f$ (the extrusion test failed), so it is
/// a bracket. At each iterate \f$t_x\f$:
/// - approximate maximum SD below the tolerance (\f$F(t_x) < 0\f$): no stored vector
///   separates at \f$t_x\f$ by the tolerance; Brent goes on;
/// - at least the tolerance (\f$F(t_x) \ge 0\f$): \f$[t_a, t_x]\f$ is free of contact; a complete
///   extrusion test on \f$[t_x, t_1]\f$ then either succeeds (a *photo finish*: no collision,
///   proven on a chain of intervals), finds the bodies within the tolerance at \f$t_x\f$ (the
///   *time of impact*: "the maximum supporting distance is positive and smaller than the
///   collision tolerance"), or fails again, and Brent restarts on \f$[t_x, t_1]\f$ with the
///   new vectors.
/// "Positive" is read here as the extrusion test reads it (extrusion.hpp): above the
/// collision tolerance. A stored vector \f$\vec{s}_k\f$ has \f$SD > \mathrm{tol}\f$ at \f$t_a\f$; if its SD
/// is also \f$\ge \mathrm{tol}\f$ at \f$t_x\f$, then (linear in t for linear motion, concave for per-vertex
/// linear motion, within the margin of the chord for the certified variant) it stays
/// \f$\ge \mathrm{tol}\f$ on all of \f$[t_a, t_x]\f$: the bodies do not come within the tolerance
/// there. Merely positive (between 0 and tol) would prove only that they do not
/// interpenetrate: a pass within the tolerance between \f$t_a\f$ and \f$t_x\f$ would then go
/// unseen (a photo finish if the bodies are apart again at \f$t_x\f$), and a hit at \f$t_x\f$
/// could come long after the bodies first came within the tolerance, for a slow grazing
/// approach (both found by tests/brent/test_time_of_impact.cpp on grazing passes).
/// When Brent's bracket \f$[t_a, t_b]\f$ shrinks below the time tolerance, the time of impact is
/// \f$t_b\f$ if the stored vectors still separate there (approximate maximum SD > 0) and the
/// exact distance there is within the tolerance (the paper's criterion above), else the
/// last time proven free of contact, \f$t_a\f$ (the distance there exceeds the tolerance by at
/// most what the bodies move in one time tolerance, plus GJK's own uncertainty). Every
/// reported time is one at which the bodies do not interpenetrate, and no later than the
/// first time they come within the tolerance (plus the time tolerance).
///
/// Four things beyond the paper make a query cheaper without changing what it proves:
/// each complete test after the first starts GJK from the last one's simplex (an
/// `ExtrusionCache`); each stored vector keeps where its support searches ended (its
/// hill-climbing hints); after a restart the bracket's far end is the nearest known point
/// where the new vectors are below the tolerance (the last bracket's), so that Brent does
/// not creep towards a far t1 one restart at a time; and after a restart a *probe* goes
/// straight to where the exact distances extrapolate to the tolerance (below).
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
/// *Grazing.* Where the distance has a long, shallow minimum just above the tolerance (a
/// spinning rib passing a cartilage at 1.1 tolerances), no single vector separates by the
/// tolerance for long: the proof that the pass is free of contact is a chain of short
/// links, each about (d - tol) / (the speed at which the supporting distance along a fixed
/// vector falls) long, and that can take the whole iteration cap. `acceptedDistance` lets
/// a caller who does not need that proof end such a query at the first restart within it.
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

#include <optional>
#include <utility>

#include <gjkx/root_solver/brent_method.hpp>
#include <gjkx/extrusion/extrusion.hpp>
#include <gjkx/support_mapping/deforming_simplex.hpp>
#include <gjkx/support_mapping/placed.hpp>

#include <cmath>
#include <limits>
#include <type_traits>
#include <utility>
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
  /// short link at a time (see the file comment, *Grazing*). Every reported time is still
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

namespace detail {

/// The contact data of a GJK run `run` at `time` (the exact distance, the witness points and
/// the unit normal from P towards Q), into `result`, moved back to the world from the frame
/// whose origin is at `origin`.
template <typename S>
void takeContact(ToiResult<S>& result, S time, const GjkResult<S>& run, const Vector3<S>& origin) {
  result.time = time;
  result.distance = run.distance;
  result.witnessP = run.witnessP + origin;
  result.witnessQ = run.witnessQ + origin;
  const Vector3<S> z = run.witnessQ - run.witnessP;
  result.normal = z.norm() > S(0) ? Vector3<S>(z.normalized()) : Vector3<S>::Zero();
}

/// The contact data of the complete test `test` at its start `time` (the exact distance,
/// the witness points and the unit normal from P towards Q), into `result`. The test ran in
/// the query's frame, whose origin is at `origin` in the world: the witnesses move back there.
template <typename S>
void takeContact(ToiResult<S>& result, S time, const ExtrusionResult<S>& test, const Vector3<S>& origin) {
  result.time = time;
  result.distance = test.distanceAtStart;
  result.witnessP = test.witnessP + origin;
  result.witnessQ = test.witnessQ + origin;
  const Vector3<S> z = test.witnessQ - test.witnessP;
  result.normal = z.norm() > S(0) ? Vector3<S>(z.normalized()) : Vector3<S>::Zero();
}

/// One query of the time-of-impact solver of §5, one step of the paragraph a member (see
/// the file comment): the complete extrusion test, the Brent step, the restart at
/// \f$t_x\f$, the photo finish and the hit. Built for one query and run once by `solve()`.
template <typename MovingP, typename MovingQ>
class ToiSolver {
 public:
  /// The scalar type of both bodies.
  using S = typename MovingP::Scalar;
  /// P placed at a time: the static support mapping GJK and the supporting distances run on.
  using PlacedP = decltype(std::declval<const MovingP&>().at(S(0)));
  /// Q placed at a time.
  using PlacedQ = decltype(std::declval<const MovingQ&>().at(S(0)));

  /// A query over \f$[t_0, t_1]\f$ (checked by `timeOfImpact`); `trace` may be null. P and Q
  /// are seen from the query's frame, whose origin is at `origin` in the world, and on the
  /// query's clock, which reads 0 at the caller's time `clock` (t0 and t1 are read on it;
  /// the result's and the trace's times are the caller's). Runs §5's
  /// first step, the complete test over \f$[t_0, t_1]\f$, straight into `last_` (a test's
  /// result holds all its separating vectors: built in place, it is not copied).
  ToiSolver(const MovingP& P, const MovingQ& Q, S t0, S t1, const ToiSettings<S>& settings, ToiTrace<S>* trace,
            const Vector3<S>& origin = Vector3<S>::Zero(), S clock = S(0),
            const ExtrusionCache<S>* carried = nullptr)
      : origin_(origin),
        clock_(clock),
        P_(P),
        Q_(Q),
        t0_(t0),
        t1_(t1),
        settings_(settings),
        trace_(trace),
        tol_(settings.collisionTolerance),
        accelerationP_(S(P.accelerationBound())),
        accelerationQ_(S(Q.accelerationBound())),
        timeTolerance_(settings.timeTolerance * (t1 - t0)),
        extrusion_(extrusionSettings(settings)),
        cache_(carried && settings.warmStart ? *carried : ExtrusionCache<S>{}),
        P1_(P.at(t1)),
        Q1_(Q.at(t1)),
        ta_(t0),
        last_(completeTest(P.at(t0), Q.at(t0), t0)),
        previousHigh_(t1),
        taBefore_(t0),
        taBefore2_(t0) {}

  /// §5 from start to end: the complete test over \f$[t_0, t_1]\f$ (run on construction);
  /// if it fails, Brent's method on F over \f$[t_a, t_1]\f$ (first \f$t_a = t_0\f$), one Brent
  /// step at a time, until a step lands where the stored vectors still separate by the
  /// tolerance: there a complete test on \f$[t_x, t_1]\f$ gives a photo finish, a hit at
  /// \f$t_x\f$, or a restart at \f$t_x\f$.
  /// Where the query's last complete test ended (its separating vector, GJK simplex and
  /// hints): what the next query of the same pair may start from (`timeOfImpact`'s `coherence`).
  const ExtrusionCache<S>& cache() const { return cache_; }

  ToiResult<S> solve() {
    if (last_.status != ExtrusionStatus::Undecided) return verdictOfFirstTest();
    for (;;) {  // one Brent run per interval [ta, t1]: the first, then one per restart
      if (last_.separating.count == 0) return hit(ta_, last_);
      if (result_.restarts > 0 && result_.brentIterations >= settings_.acceptedAfter &&
          last_.distanceAtStart <= settings_.acceptedDistance)
        return hit(ta_, last_);
      ProbeOutcome probed = probe();  // after a restart: straight to where the distance reaches the tolerance
      if (probed.verdict) return *probed.verdict;
      if (probed.restarted) continue;
      std::optional<BrentIterate> leap;
      BrentStepper<S> brent = bracket(leap, probed);
      for (;;) {
        if (brent.converged()) return hitOnConvergedBracket(brent);
        if (result_.brentIterations >= settings_.maxIterations) return iterationCap();
        const BrentIterate x = leap ? *std::exchange(leap, std::nullopt) : brentStep(brent);
        if (!x.separates) {  // §5's "negative": Brent goes on with F(tx) < 0
          brent.update(x.approximateMaxSd - tol_);
          continue;
        }
        ExtrusionResult<S> test = completeTestAt(x);  // §5's "positive": [ta, tx] is free of contact
        if (test.status != ExtrusionStatus::Undecided) return verdictAt(x.t, test);
        restartAt(x, brent, std::move(test));
        break;
      }
    }
  }

 private:
  /// One Brent iterate \f$t_x\f$: the bodies placed there and the stored vectors' verdict.
  struct BrentIterate {
    /// The iterate \f$t_x\f$.
    S t;
    /// P at \f$t_x\f$.
    PlacedP P;
    /// Q at \f$t_x\f$.
    PlacedQ Q;
    /// §5's approximate maximum supporting distance at \f$t_x\f$, less the margin.
    S approximateMaxSd = S(0);
    /// True when it is at least the tolerance (\f$F(t_x) \ge 0\f$): \f$[t_a, t_x]\f$ is free of contact.
    bool separates = false;
  };

  /// What a probe at the distance secant decided (see `probe`).
  struct ProbeOutcome {
    /// The query's verdict, when the probe reached one (a photo finish or a hit at \f$t_S\f$).
    std::optional<ToiResult<S>> verdict;
    /// True when \f$[t_a, t_S]\f$ was proven free and the solver moved its start to \f$t_S\f$.
    bool restarted = false;
    /// True when \f$t_S\f$ was not proven free: it is then a far end for Brent, F < 0 there.
    bool farEnd = false;
    /// \f$t_S\f$.
    S t = S(0);
    /// F at \f$t_S\f$ (from the vectors stored at \f$t_a\f$), when `farEnd`.
    S f = S(0);
  };

  /// The settings of every complete test: the solver's tolerance and variant, and its GJK settings.
  static ExtrusionSettings<S> extrusionSettings(const ToiSettings<S>& settings) {
    ExtrusionSettings<S> extrusion;
    extrusion.collisionTolerance = settings.collisionTolerance;
    extrusion.variant = settings.variant;
    extrusion.gjk = settings.gjk;
    return extrusion;
  }

  /// The certified margin \f$m(\Delta)\f$ over an interval of length `duration`
  /// (certified_margin.hpp; 0 for the paper's variant).
  S margin(S duration) const { return extrusionMargin(settings_.variant, duration, accelerationP_, accelerationQ_); }

  /// The complete GJK extrusion test on \f$[t_a, t_1]\f$, with the bodies placed at `ta` by the
  /// caller (who has usually just placed them there for the approximate maximum SD) and at
  /// \f$t_1\f$ once for all tests. Each test after the first starts where the last one ended
  /// (`cache_`). Counts its work and records it in the trace.
  ExtrusionResult<S> completeTest(const PlacedP& Pa, const PlacedQ& Qa, S ta) {
    ExtrusionResult<S> test = extrusionTestPlaced(Pa, Qa, P1_, Q1_, margin(t1_ - ta), extrusion_,
                                                      settings_.warmStart ? &cache_ : nullptr);
    ++result_.gjkRuns;
    result_.sdEvaluations += test.sdEvaluations;
    if (trace_) trace_->intervals.push_back({callerTime(ta), test.status, test.distanceAtStart, test.separating});
    return test;
  }

  /// The complete test on \f$[t_x, t_1]\f$ at a Brent iterate whose stored vectors separate by
  /// the tolerance: a photo finish, a hit at \f$t_x\f$, or a restart at \f$t_x\f$ follows.
  ExtrusionResult<S> completeTestAt(const BrentIterate& x) {
    ++result_.restarts;
    return completeTest(x.P, x.Q, x.t);
  }

  /// The verdict of the first complete test, over \f$[t_0, t_1]\f$, when it decided the query.
  ToiResult<S> verdictOfFirstTest() {
    switch (last_.status) {
      case ExtrusionStatus::NoCollision: result_.status = ToiStatus::NoCollision; break;
      case ExtrusionStatus::NumericalFailure: result_.status = ToiStatus::NumericalFailure; break;
      case ExtrusionStatus::IterationCap:
        result_.status = ToiStatus::IterationCap;
        result_.time = callerTime(t0_);
        break;
      case ExtrusionStatus::CollidingAtStart:
        report(t0_, last_);
        result_.status = movingApart() ? ToiStatus::Separating : ToiStatus::StartsPenetrating;
        break;
      case ExtrusionStatus::Undecided: break;  // not a verdict: solve() goes on to Brent
    }
    return result_;
  }

  /// Within the tolerance at \f$t_0\f$: true when the bodies provably move apart. Along the
  /// closest direction n, the supporting distance is at least its chord less the margin's
  /// parabola (certified_margin.hpp; linear and per-vertex linear motion: less nothing). If
  /// that stays positive and it rises, the bodies never touch.
  bool movingApart() {
    if (!(result_.distance > S(0) && result_.normal.squaredNorm() > S(0))) return false;
    const S sd0 = supportingDistanceAt(P_, Q_, result_.normal, t0_);
    const S sd1 = supportingDistanceAt(P_, Q_, result_.normal, t1_);
    result_.sdEvaluations += 2;
    return sd0 > S(0) && sd1 >= sd0 &&
           lowestSupportingDistance(settings_.variant, sd0, sd1, t1_ - t0_, accelerationP_, accelerationQ_) > S(0);
  }

  /// §5's approximate maximum supporting distance at t, the bodies placed there: the largest
  /// SD along the stored vectors, less the margin over \f$[t_a, t]\f$. The certified variant
  /// counts a vector only as far as it separates at both \f$t_a\f$ and t: positive then proves
  /// \f$[t_a, t]\f$ free of contact. Each vector's support searches start where its last ones
  /// ended (its hints): the bodies have moved little since, and the climbs are short.
  /// Kept out of line (speed): the loop then gets the support searches inlined, which it
  /// does not once inlined into `solve()` (2.7% more instructions per query, callgrind).
  [[gnu::noinline]] S approximateMaxSd(const PlacedP& Pt, const PlacedQ& Qt, S t) {
    SeparatingVectors<S>& vectors = last_.separating;
    const bool certified = settings_.variant == ExtrusionVariant::Certified;
    S best = -std::numeric_limits<S>::infinity();
    for (int k = 0; k < vectors.count; ++k) {
      const S sd = supportingDistance(Pt, Qt, vectors.vectors[k], vectors.hintP[k], vectors.hintQ[k]);
      best = std::max(best, certified ? std::min(sd, vectors.sdStart[k]) : sd);
    }
    result_.sdEvaluations += vectors.count;
    return best - margin(t - ta_);
  }

  /// The same at \f$t_1\f$, from the values the last complete test stored there.
  S approximateMaxSdAtT1() const {
    const SeparatingVectors<S>& vectors = last_.separating;
    const bool certified = settings_.variant == ExtrusionVariant::Certified;
    S best = -std::numeric_limits<S>::infinity();
    for (int k = 0; k < vectors.count; ++k)
      best = std::max(best, certified ? std::min(vectors.sdEnd[k], vectors.sdStart[k]) : vectors.sdEnd[k]);
    return best - margin(t1_ - ta_);
  }

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
  BrentStepper<S> bracket(std::optional<BrentIterate>& leap, const ProbeOutcome& probed) {
    const S distanceAtTa = last_.distanceAtStart;
    S high = t1_, fHigh = std::min(approximateMaxSdAtT1() - tol_, S(0));
    if (probed.farEnd && probed.t < high) {
      high = probed.t;
      fHigh = probed.f;
    }
    tryNearerFarEnd(previousHigh_, high, fHigh);
    const S advance = ta_ - taBefore_;
    if (result_.restarts > 0 && advance < S(0.25) * (high - ta_) && result_.brentIterations < settings_.maxIterations) {
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
  void tryNearerFarEnd(S t, S& high, S& fHigh) {
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
  ProbeOutcome probe() {
    ProbeOutcome out;
    const S da = last_.distanceAtStart;
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
  S stepToContact() const {
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
  S backwardProof(const SeparatingVectors<S>& vectors, S ts) {
    S best = -std::numeric_limits<S>::infinity();
    if (vectors.count == 0) return best;
    const PlacedP Pa = P_.at(ta_);
    const PlacedQ Qa = Q_.at(ta_);
    for (int k = vectors.count - 1; k >= 0 && best < tol_; --k) {
      SupportHint hintP = vectors.hintP[k], hintQ = vectors.hintQ[k];
      const S sd = supportingDistance(Pa, Qa, vectors.vectors[k], hintP, hintQ);
      ++result_.sdEvaluations;
      best = std::max(best, lowestSupportingDistance(settings_.variant, sd, vectors.sdStart[k], ts - ta_,
                                                     accelerationP_, accelerationQ_));
    }
    return best;
  }

  /// The Brent step: the next iterate \f$t_x\f$, the bodies placed there, and the approximate
  /// maximum SD there. "Positive" means at least the tolerance (\f$F(t_x) \ge 0\f$), not merely
  /// above 0: only then are the bodies proven no closer than the tolerance on all of
  /// \f$[t_a, t_x]\f$ (see the file comment). Records the step in the trace.
  BrentIterate brentStep(const BrentStepper<S>& brent) {
    return iterateAt(brent.next(), brent.nextKind(), ta_, std::max(brent.root(), brent.counterpart()));
  }

  /// An iterate at `tx`, chosen by the rule `kind` in the bracket [low, high]: the bodies
  /// placed there and the approximate maximum SD there. Counted as a Brent iteration
  /// (an evaluation of F) and recorded in the trace.
  BrentIterate iterateAt(S tx, BrentStepKind kind, S low, S high) {
    ++result_.brentIterations;
    BrentIterate x{tx, P_.at(tx), Q_.at(tx)};
    x.approximateMaxSd = approximateMaxSd(x.P, x.Q, tx);
    x.separates = x.approximateMaxSd >= tol_;
    if (trace_)
      trace_->steps.push_back(
          ToiStep<S>{callerTime(tx), x.approximateMaxSd, callerTime(low), callerTime(high), kind, x.separates});
    return x;
  }

  /// The restart at \f$t_x\f$: the complete test there failed again, so Brent starts afresh on
  /// \f$[t_x, t_1]\f$ with its vectors and its exact distance at \f$t_x\f$. Remembers the last
  /// bracket's far end for the next bracket.
  void restartAt(const BrentIterate& x, const BrentStepper<S>& brent, ExtrusionResult<S>&& test) {
    previousHigh_ = std::max(brent.root(), brent.counterpart());
    moveStartTo(x.t, std::move(test));
  }

  /// \f$t_a\f$ moves to `tx`, proven free of contact, with the complete test there; the last
  /// start and its exact distance are kept for the probe's secant.
  void moveStartTo(S tx, ExtrusionResult<S>&& test) {
    taBefore2_ = taBefore_;
    distanceBefore2_ = distanceBefore_;
    taBefore_ = ta_;
    distanceBefore_ = last_.distanceAtStart;
    ta_ = tx;
    last_ = std::move(test);
  }

  /// The verdict of a complete test on \f$[t_x, t_1]\f$ that did not fail: a photo finish if it
  /// succeeded, a hit at \f$t_x\f$ if the bodies are within the tolerance there.
  ToiResult<S> verdictAt(S tx, const ExtrusionResult<S>& test) {
    switch (test.status) {
      case ExtrusionStatus::NoCollision: return photoFinish();
      case ExtrusionStatus::CollidingAtStart: return hit(tx, test);  // exact distance at tx within the tolerance
      case ExtrusionStatus::NumericalFailure: result_.status = ToiStatus::NumericalFailure; return result_;
      case ExtrusionStatus::IterationCap: return iterationCap();
      case ExtrusionStatus::Undecided: break;  // not a verdict: solve() restarts at tx
    }
    return result_;
  }

  /// The photo finish: no collision, proven on the chain \f$[t_0, t_{x1}], \dots, [t_{xn}, t_1]\f$
  /// (each link but the last by a stored vector, the last by the complete test that succeeded).
  ToiResult<S> photoFinish() {
    result_.status = ToiStatus::PhotoFinish;
    return result_;
  }

  /// The hit: the bodies come within the tolerance at `time`, with the contact data of the
  /// complete test there.
  ToiResult<S> hit(S time, const ExtrusionResult<S>& test) {
    result_.status = ToiStatus::Hit;
    report(time, test);
    return result_;
  }

  /// The hit when Brent's bracket \f$[t_a, t_b]\f$ is within the time tolerance: \f$t_b\f$ if the
  /// stored vectors still prove the bodies apart there (approximate maximum SD > 0) and a
  /// complete test finds the exact distance there within the tolerance (the paper's "its
  /// maximum supporting distance is positive and smaller than the collision tolerance");
  /// otherwise \f$t_a\f$, the last time proven free of contact, where the distance exceeds the
  /// tolerance by at most what the bodies move in one time tolerance.
  ToiResult<S> hitOnConvergedBracket(const BrentStepper<S>& brent) {
    const S tb = brent.root() == ta_ ? brent.counterpart() : brent.root();
    if (tb > ta_) {  // the stored vectors are never empty here (solve() checked)
      const PlacedP Pb = P_.at(tb);
      const PlacedQ Qb = Q_.at(tb);
      if (approximateMaxSd(Pb, Qb, tb) > S(0)) {
        if (tb == contactBy_ && contactTest_) return hit(tb, *contactTest_);  // a probe's test, within the tolerance there
        const ExtrusionResult<S> atEnd = completeTest(Pb, Qb, tb);
        if (atEnd.status == ExtrusionStatus::CollidingAtStart) return hit(tb, atEnd);
      }
    }
    return hit(ta_, last_);
  }

  /// Out of iterations (Brent's or GJK's): undecided, reported at the last time proven free
  /// of contact, \f$t_a\f$.
  ToiResult<S> iterationCap() {
    result_.status = ToiStatus::IterationCap;
    report(ta_, last_);
    return result_;
  }

  /// A time of the query's clock as the caller reads it (rounded to nearest; for the trace).
  S callerTime(S tau) const { return clock_ + tau; }

  /// The contact data of the complete test `test` at `tau` (on the query's clock, a time
  /// proven free of contact or the converged hit), at the caller's time. On the query's
  /// clock tau is far finer than the caller's times near a large \f$t_0\f$ (in float at 1000
  /// the caller's spacing is 6.1e-5), so \f$t_0 + \tau\f$ may be no time the caller can hold.
  /// Rounding it to nearest could report a time up to half that spacing past the contact,
  /// where fast bodies already interpenetrate. So the reported time is the latest the caller
  /// can hold that is not after \f$t_0 + \tau\f$: earlier than a time proven free of contact,
  /// hence free of contact itself; and the distance, witnesses and normal are those of a
  /// GJK run there (`contactAt`), so that they belong to the time reported. The distance
  /// there exceeds the tolerance by at most what the bodies move in one spacing of the
  /// caller's time: no query can answer
  /// more finely in the caller's arithmetic. At \f$t_0\f$ = 0 (or wherever \f$t_0 + \tau\f$ is
  /// exact) the test's own data are taken as they are.
  void report(S tau, const ExtrusionResult<S>& test) {
    S t = clock_ + tau;
    S tauT = t - clock_;  // the caller's motions, at t, see this time since their start
    while (tauT > tau) {
      t = std::nextafter(t, -std::numeric_limits<S>::infinity());
      tauT = t - clock_;
    }
    if (tauT == tau) {
      takeContact(result_, t, test, origin_);
      return;
    }
    contactAt(t, tauT);
  }

  /// The contact data at `tau` (on the query's clock), reported at the caller's time `t`:
  /// a GJK run there, to convergence. Not a complete test: one that succeeds stops GJK at
  /// the first vector separating at both ends, and its distance is then only an upper
  /// bound (the fuzzer found one reported as infinite). Out of line and cold, as it is
  /// rare. (This second instance of GJK in the solver moves the compiler's inlining of the
  /// hot path: at \f$t_0 = 0\f$, where it never runs, a query costs 1.4% more instructions
  /// under callgrind with the same work done; docs 09.)
  [[gnu::noinline, gnu::cold]] void contactAt(S t, S tau) {
    const GjkResult<S> there = gjk(P_.at(tau), Q_.at(tau), settings_.gjk);
    ++result_.gjkRuns;
    result_.sdEvaluations += there.iterations;  // one supporting distance per GJK iteration
    takeContact(result_, t, there, origin_);
  }

  /// Where the query's frame has its origin, in the world (P's position at \f$t_0\f$; see
  /// `timeOfImpact`).
  Vector3<S> origin_;
  /// The caller's time at which the query's clock reads 0 (\f$t_0\f$; see `timeOfImpact`).
  S clock_;
  /// The moving body P, seen from the query's frame and on the query's clock.
  const MovingP& P_;
  /// The moving body Q.
  const MovingQ& Q_;
  /// The start of the interval, on the query's clock.
  S t0_;
  /// The end of the interval, where every complete test ends.
  S t1_;
  /// The caller's settings.
  const ToiSettings<S>& settings_;
  /// The caller's trace, or null.
  ToiTrace<S>* trace_;
  /// The collision tolerance.
  S tol_;
  /// P's acceleration bound (for the certified margin).
  S accelerationP_;
  /// Q's acceleration bound.
  S accelerationQ_;
  /// Brent's time tolerance: the settings' fraction of \f$t_1 - t_0\f$.
  S timeTolerance_;
  /// The settings of every complete test.
  ExtrusionSettings<S> extrusion_;
  /// Every complete test after the first starts where the last one ended (speed): GJK from
  /// the last simplex, its supports re-asked at the new time (GjkCache), and the searches
  /// at \f$t_1\f$ from the last vertices found there. The restarts of §5 come at times ever
  /// closer to the contact, where the closest features change little, so the warm GJK
  /// needs a couple of iterations where a cold one needs five or more. The verdicts are
  /// those of cold tests: GJK converges to the same tolerance from either start.
  ExtrusionCache<S> cache_;
  /// P at \f$t_1\f$, placed once (speed: a pose under rotation costs a sine and a cosine).
  PlacedP P1_;
  /// Q at \f$t_1\f$, placed once.
  PlacedQ Q1_;
  /// What the solver found so far: the counters, then the verdict.
  ToiResult<S> result_;
  /// \f$t_a\f$: the start of the last complete test, the last time proven free of contact.
  S ta_;
  /// The last complete test, on \f$[t_a, t_1]\f$: its exact distance at \f$t_a\f$ and its stored
  /// vectors, which define F (their hints change as they are used).
  ExtrusionResult<S> last_;
  /// The far end of the last Brent bracket, where F was negative.
  S previousHigh_;
  /// The start of the complete test before the last...
  S taBefore_;
  /// ...and its exact distance there (0 before the first restart: no probe then).
  S distanceBefore_ = S(0);
  /// The start of the complete test before that (\f$t_0\f$ until the second restart)...
  S taBefore2_;
  /// ...and its exact distance there (Muller's parabola, `stepToContact`).
  S distanceBefore2_ = S(0);
  /// The earliest time a probe found the bodies within the tolerance (no probe goes past it)...
  S contactBy_ = std::numeric_limits<S>::infinity();
  /// ...and its complete test, for the hit there when Brent's bracket closes on it.
  std::optional<ExtrusionResult<S>> contactTest_;
};

/// A point of P at \f$t_0\f$ to put the query's origin at: the body origin of a rigid body,
/// the first vertex of a deforming simplex.
template <typename Shape>
Vector3<typename Shape::Scalar> queryOrigin(const Moving<Shape>& P, typename Shape::Scalar t0) {
  return P.motion.pose(t0).translation;
}
/// The same for a deforming simplex.
template <typename S>
Vector3<S> queryOrigin(const DeformingSimplex<S>& P, S t0) {
  return P.at(t0).points[0];
}

/// True for a body type that can be seen from another frame (`translated(offset)`).
template <typename X, typename = void>
struct CanTranslate : std::false_type {};
/// True for a body type that can be seen from another frame (`translated(offset)`).
template <typename X>
struct CanTranslate<X, std::void_t<decltype(std::declval<const X&>().translated(
                           std::declval<const Vector3<typename X::Scalar>&>()))>> : std::true_type {};

/// True for a body type that can be put on another clock (`retimed(clock)`).
template <typename X, typename = void>
struct CanRetime : std::false_type {};
/// True for a body type that can be put on another clock (`retimed(clock)`).
template <typename X>
struct CanRetime<X, std::void_t<decltype(std::declval<const X&>().retimed(std::declval<typename X::Scalar>()))>>
    : std::true_type {};

/// A body seen from the query's frame (origin moved by `offset`) and on its clock (0 at `clock`).
template <typename X>
X localBody(const X& body, const Vector3<typename X::Scalar>& offset, typename X::Scalar clock) {
  if (clock == 0) return body.translated(offset);
  if (offset.squaredNorm() == 0) return body.retimed(clock);
  return body.translated(offset).retimed(clock);
}

}  // namespace detail

/// Non-collision or the time of impact of two moving bodies over \f$[t_0, t_1]\f$ (§5); see
/// the file comment. The bodies are any types with `at(t)` and `accelerationBound()`
/// (`Moving<Shape>`, `DeformingSimplex`). Throws std::invalid_argument for a bad interval.
///
/// The query runs in the frame of P: both bodies are seen from an origin at P's position at
/// \f$t_0\f$ (as Box2D v3 runs its queries in the frame of its first shape), and the witness
/// points are moved back to the world. Far from the world's origin this keeps GJK's
/// arithmetic on the bodies' small relative coordinates: in float at coordinates near
/// \f$10^5\f$ (spacing 0.0078) the time of impact is then as accurate as in double (measured
/// by the study's extreme cases, docs 09). The translation itself is exact in floating
/// point for bodies near the origin chosen (Sterbenz's lemma).
///
/// It runs on its own clock too, the same change on the time axis: its times are
/// \f$\tau = t - t_0\f$, on \f$[0, t_1 - t_0]\f$, and the bodies are put on that clock
/// (`retimed(t0)`). On the caller's clock, far from \f$t = 0\f$, the spacing of times is
/// relative to \f$|t_0|\f$, not to the interval: in float at \f$t_0\f$ = 1000 it is 6.1e-5, and an
/// interval 2^-10 long holds 16 times. Brent's bracket then stops shrinking at its
/// round-off, \f$2\cdot 2\epsilon|t| = 2.4\cdot 10^{-4}\f$, a quarter of the interval, and the
/// converged bracket's far end, a hit there, came up to 4 spacings after the bodies came
/// within the tolerance (tests/fuzz/corpus/fuzz_time_of_impact/finding-toi_float_late_hit_at_t1000).
/// On the query's clock the round-off is relative to the interval and the time tolerance
/// holds as asked. A time the caller cannot hold is reported at the latest one it can
/// before it (see `ToiSolver::report`). A motion that starts at \f$t_0\f$ reads its own
/// \f$t - t_0\f$ exactly either way; at \f$t_0 = 0\f$ nothing changes.
template <typename MovingP, typename MovingQ>
ToiResult<typename MovingP::Scalar> timeOfImpact(const MovingP& P, const MovingQ& Q, typename MovingP::Scalar t0,
                                                 typename MovingP::Scalar t1,
                                                 const ToiSettings<typename MovingP::Scalar>& settings = {},
                                                 ToiTrace<typename MovingP::Scalar>* trace = nullptr,
                                                 ExtrusionCache<typename MovingP::Scalar>* coherence = nullptr) {
  using S = typename MovingP::Scalar;
  // Temporal coherence (§2: the work of the previous query reinitializes the current one):
  // the first complete test starts where the pair's last query ended, and this query's end
  // is kept for the next. A hint only: the verdicts are those of a cold start.
  const auto run = [&](detail::ToiSolver<MovingP, MovingQ>&& solver) {
    ToiResult<S> result = solver.solve();
    if (coherence && settings.warmStart) *coherence = solver.cache();
    return result;
  };
  requireInterval(t0, t1, "timeOfImpact");
  if (!(settings.collisionTolerance > S(0))) failInput("toiSettings.collisionTolerance", "must be positive");
  if (!(settings.acceptedDistance >= S(0)) || !std::isfinite(settings.acceptedDistance))
    failInput("toiSettings.acceptedDistance", "must be finite and not negative");
  if (settings.acceptedAfter < 0) failInput("toiSettings.acceptedAfter", "must not be negative");
  if constexpr (detail::CanTranslate<MovingP>::value && detail::CanTranslate<MovingQ>::value &&
                detail::CanRetime<MovingP>::value && detail::CanRetime<MovingQ>::value) {
    const Vector3<S> origin = settings.inFrameOfP ? detail::queryOrigin(P, t0) : Vector3<S>::Zero();
    const S duration = t1 - t0;
    const S clock = std::isfinite(duration) ? t0 : S(0);  // an interval too long for S stays on the caller's clock
    if (origin.squaredNorm() > S(0) || clock != S(0)) {  // already there: nothing to change
      const MovingP localP = detail::localBody(P, Vector3<S>(-origin), clock);
      const MovingQ localQ = detail::localBody(Q, Vector3<S>(-origin), clock);
      return run(detail::ToiSolver<MovingP, MovingQ>(localP, localQ, t0 - clock, t1 - clock, settings, trace, origin,
                                                     clock, coherence));
    }
  }
  return run(detail::ToiSolver<MovingP, MovingQ>(P, Q, t0, t1, settings, trace, Vector3<S>::Zero(), S(0), coherence));
}

}  // namespace gjkx
