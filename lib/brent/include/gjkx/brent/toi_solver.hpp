/// @file
/// @brief The time-of-impact solver of §5 step by step: one query as an object whose
/// members are the steps of the paper's paragraph (`detail::ToiSolver`).
///
/// Part of the solver of gjkx/brent/time_of_impact.hpp, the header to include: its file
/// comment is §5's paragraph and what the solver proves, and its `timeOfImpact` builds and
/// runs this object. The members beyond the paper that shape Brent's bracket after a
/// restart (`bracket`, `probe` and their helpers) are declared here and defined in
/// toi_refinements.hpp, which time_of_impact.hpp includes too.
#pragma once

#include <gjkx/brent/toi_result.hpp>
#include <gjkx/extrusion/extrusion.hpp>
#include <gjkx/root_solver/brent_method.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <utility>

namespace gjkx {

namespace detail {

/// The contact data at `time`, from the GJK run that ended with `status` there: the closest
/// distance (an upper bound of it where GJK stalled), the witness points and the unit normal
/// from P towards Q, into `result`. GJK ran in the query's frame, whose origin is at
/// `origin` in the world: the witnesses move back there.
template <typename S>
void takeContact(ToiResult<S>& result, S time, GjkStatus status, S distance, const Vector3<S>& witnessP,
                 const Vector3<S>& witnessQ, const Vector3<S>& origin) {
  result.time = time;
  result.distance = distance;
  result.distanceIsUpperBound = status == GjkStatus::Stalled;
  result.witnessP = witnessP + origin;
  result.witnessQ = witnessQ + origin;
  const Vector3<S> z = witnessQ - witnessP;
  result.normal = z.norm() > S(0) ? Vector3<S>(z.normalized()) : Vector3<S>::Zero();
}

/// The contact data of a GJK run `run` at `time`.
template <typename S>
void takeContact(ToiResult<S>& result, S time, const GjkResult<S>& run, const Vector3<S>& origin) {
  takeContact(result, time, run.status, run.distance, run.witnessP, run.witnessQ, origin);
}

/// The contact data of the complete test `test` at its start `time` (its GJK run's there).
template <typename S>
void takeContact(ToiResult<S>& result, S time, const ExtrusionResult<S>& test, const Vector3<S>& origin) {
  takeContact(result, time, test.gjkStatus, test.distanceAtStart, test.witnessP, test.witnessQ, origin);
}

/// One query of the time-of-impact solver of §5, one step of the paragraph a member (see
/// time_of_impact.hpp's file comment): the complete extrusion test, the Brent step, the
/// restart at \f$t_x\f$, the photo finish and the hit. Built for one query and run once by `solve()`.
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
        cache_(carried && settings.warmStart && settings.coherence ? *carried : ExtrusionCache<S>{}),
        P1_(P.at(t1)),
        Q1_(Q.at(t1)),
        ta_(t0),
        last_(completeTest(P.at(t0), Q.at(t0), t0)),
        previousHigh_(t1),
        taBefore_(t0),
        taBefore2_(t0) {}

  /// Where the query's last complete test ended (its separating vector, GJK simplex and
  /// hints): what the next query of the same pair may start from (`timeOfImpact`'s `coherence`).
  const ExtrusionCache<S>& cache() const { return cache_; }

  /// §5 from start to end: the complete test over \f$[t_0, t_1]\f$ (run on construction);
  /// if it fails, Brent's method on F over \f$[t_a, t_1]\f$ (first \f$t_a = t_0\f$), one Brent
  /// step at a time, until a step lands where the stored vectors still separate by the
  /// tolerance: there a complete test on \f$[t_x, t_1]\f$ gives a photo finish, a hit at
  /// \f$t_x\f$, or a restart at \f$t_x\f$.
  ToiResult<S> solve() {
    if (last_.status != ExtrusionStatus::Undecided) return verdictOfFirstTest();
    for (;;) {  // one Brent run per interval [ta, t1]: the first, then one per restart
      if (last_.separating.count == 0) return hit(ta_, last_);
      if (settings_.acceptedBand && result_.restarts > 0 && result_.brentIterations >= settings_.acceptedAfter &&
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
    extrusion.supportHints = settings.supportHints;
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
        result_.status =
            settings_.separatingAtStart && movingApart() ? ToiStatus::Separating : ToiStatus::StartsPenetrating;
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
      SupportHint coldP = 0, coldQ = 0;  // without supportHints every climb starts at the first vertex
      const bool hinted = settings_.supportHints;
      const S sd = supportingDistance(Pt, Qt, vectors.vectors[k], hinted ? vectors.hintP[k] : coldP,
                                      hinted ? vectors.hintQ[k] : coldQ);
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

  /// Brent's bracket on \f$[t_a, t_1]\f$ after a restart, its far end the nearest known time
  /// where the stored vectors are below the tolerance, with a leap past a creeping restart
  /// (toi_refinements.hpp).
  BrentStepper<S> bracket(std::optional<BrentIterate>& leap, const ProbeOutcome& probed);

  /// Makes t the bracket's far end if F is negative there (toi_refinements.hpp).
  void tryNearerFarEnd(S t, S& high, S& fHigh);

  /// The probe after a restart: a complete test where the exact distances extrapolate to
  /// the tolerance, and the proof of the interval up to it (toi_refinements.hpp).
  ProbeOutcome probe();

  /// How far past \f$t_a\f$ the exact distances extrapolate to the tolerance (toi_refinements.hpp).
  S stepToContact() const;

  /// The proof of \f$[t_a, t_S]\f$ by the vectors found at \f$t_S\f$ (toi_refinements.hpp).
  S backwardProof(const SeparatingVectors<S>& vectors, S ts);

  /// The Brent step: the next iterate \f$t_x\f$, the bodies placed there, and the approximate
  /// maximum SD there. "Positive" means at least the tolerance (\f$F(t_x) \ge 0\f$), not merely
  /// above 0: only then are the bodies proven no closer than the tolerance on all of
  /// \f$[t_a, t_x]\f$ (see time_of_impact.hpp's file comment). Records the step in the trace.
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

}  // namespace detail

}  // namespace gjkx
