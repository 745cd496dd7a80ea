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
/// Three things beyond the paper make a query cheaper without changing what it proves:
/// each complete test after the first starts GJK from the last one's simplex (an
/// `ExtrusionCache`); each stored vector keeps where its support searches ended (its
/// hill-climbing hints); and after a restart the bracket's far end is the nearest known
/// point where the new vectors are below the tolerance (the last bracket's, or where the
/// distances of the last two complete tests extrapolate to it), so that Brent does not
/// creep towards a far t1 one restart at a time.
#pragma once

#include <gjkx/brent/root_finder.hpp>
#include <gjkx/extrusion/extrusion.hpp>

#include <cmath>
#include <limits>
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
  S timeTolerance = std::sqrt(std::numeric_limits<S>::epsilon());
  /// The paper's extrusion test or the certified one.
  ExtrusionVariant variant = ExtrusionVariant::Paper;
  /// The cap on Brent iterations over all restarts (the paper saw at most 43).
  int maxIterations = 100;
  /// Settings of every GJK run.
  GjkSettings<S> gjk;
};

/// One Brent iterate of the solver, as chapter 05 draws it.
template <typename S>
struct ToiStep {
  /// The iterate \f$t_x\f$.
  S t = S(0);
  /// The approximate maximum supporting distance at \f$t_x\f$ from the stored vectors (less the margin).
  S approximateMaxSd = S(0);
  /// The low end \f$t_a\f$ of the bracket the iterate was taken in: the last time proven free of contact.
  S bracketLow = S(0);
  /// The high end of that bracket.
  S bracketHigh = S(0);
  /// The rule that chose \f$t_x\f$.
  BrentStepKind kind = BrentStepKind::Bisection;
  /// True when the approximate maximum was at least the tolerance and a complete extrusion test followed.
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
  /// comment), at most the tolerance plus what the bodies move in one time tolerance.
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
template <typename S>
void takeContact(ToiResult<S>& result, S time, const ExtrusionResult<S>& test) {
  result.time = time;
  result.distance = test.distanceAtStart;
  result.witnessP = test.witnessP;
  result.witnessQ = test.witnessQ;
  const Vector3<S> z = test.witnessQ - test.witnessP;
  result.normal = z.norm() > S(0) ? Vector3<S>(z.normalized()) : Vector3<S>::Zero();
}
}  // namespace detail

/// Non-collision or the time of impact of two moving bodies over \f$[t_0, t_1]\f$ (§5); see
/// the file comment. The bodies are any types with `at(t)` and `accelerationBound()`
/// (`Moving<Shape>`, `DeformingSimplex`). Throws std::invalid_argument for a bad interval.
template <typename MovingP, typename MovingQ>
ToiResult<typename MovingP::Scalar> timeOfImpact(const MovingP& P, const MovingQ& Q, typename MovingP::Scalar t0,
                                                 typename MovingP::Scalar t1,
                                                 const ToiSettings<typename MovingP::Scalar>& settings = {},
                                                 ToiTrace<typename MovingP::Scalar>* trace = nullptr) {
  using S = typename MovingP::Scalar;
  requireInterval(t0, t1, "timeOfImpact");
  if (!(settings.collisionTolerance > S(0))) failInput("toiSettings.collisionTolerance", "must be positive");
  const S tol = settings.collisionTolerance;
  const S accelerationP = S(P.accelerationBound()), accelerationQ = S(Q.accelerationBound());
  const S accelerationBound = accelerationP + accelerationQ;
  ExtrusionSettings<S> extrusion;
  extrusion.collisionTolerance = tol;
  extrusion.variant = settings.variant;
  extrusion.gjk = settings.gjk;

  ToiResult<S> result;
  // Every complete test after the first starts where the last one ended (speed): GJK
  // from the last simplex, its supports re-asked at the new time (GjkCache), and the
  // searches at t1 from the last vertices found there. The restarts of §5 come at times
  // ever closer to the contact, where the closest features change little, so the warm
  // GJK needs a couple of iterations where a cold one needs five or more. The verdicts
  // are those of cold tests: GJK converges to the same tolerance from either start.
  ExtrusionCache<S> cache;
  // Every test ends at t1, where the bodies are placed once. A test at ta takes the bodies
  // placed at ta from its caller, who has usually just placed them there to evaluate the
  // approximate maximum SD (speed: a pose under rotation costs a sine and a cosine).
  const auto P1 = P.at(t1);
  const auto Q1 = Q.at(t1);
  auto completeTest = [&](const auto& Pa, const auto& Qa, S ta) {
    const S margin = extrusionMargin(settings.variant, t1 - ta, accelerationP, accelerationQ);
    ExtrusionResult<S> test = extrusionTestPlaced(Pa, Qa, P1, Q1, margin, extrusion, &cache);
    ++result.gjkRuns;
    result.sdEvaluations += test.sdEvaluations;
    if (trace) trace->intervals.push_back({ta, test.status, test.distanceAtStart, test.separating});
    return test;
  };

  // The first test over the whole interval.
  S ta = t0;
  ExtrusionResult<S> test = completeTest(P.at(t0), Q.at(t0), ta);
  switch (test.status) {
    case ExtrusionStatus::NoCollision:
      result.status = ToiStatus::NoCollision;
      return result;
    case ExtrusionStatus::NumericalFailure:
      result.status = ToiStatus::NumericalFailure;
      return result;
    case ExtrusionStatus::IterationCap:
      result.status = ToiStatus::IterationCap;
      result.time = t0;
      return result;
    case ExtrusionStatus::CollidingAtStart: {
      // Within the tolerance at t0. Along the closest direction n, the supporting distance
      // is at least its chord less the margin's parabola (certified_margin.hpp; linear and
      // per-vertex linear motion: less nothing). If that stays positive and it rises, the
      // bodies never touch: they are moving apart.
      detail::takeContact(result, t0, test);
      bool apart = false;
      if (result.distance > S(0) && result.normal.squaredNorm() > S(0)) {
        const S sd0 = supportingDistanceAt(P, Q, result.normal, t0);
        const S sd1 = supportingDistanceAt(P, Q, result.normal, t1);
        result.sdEvaluations += 2;
        apart = sd0 > S(0) && sd1 >= sd0 &&
                lowestSupportingDistance(settings.variant, sd0, sd1, t1 - t0, accelerationP, accelerationQ) > S(0);
      }
      result.status = apart ? ToiStatus::Separating : ToiStatus::StartsPenetrating;
      return result;
    }
    case ExtrusionStatus::Undecided: break;
  }

  // Brent on F(t) over [ta, t1], restarted on [tx, t1] after each complete test.
  const S timeTolerance = settings.timeTolerance * (t1 - t0);
  ExtrusionResult<S>& lastTest = test;           // the complete test at ta
  SeparatingVectors<S>& vectors = test.separating;  // its vectors (their hints change as they are used)
  S distanceAtTa = test.distanceAtStart;
  // The approximate maximum supporting distance at t from the stored vectors (§5). The
  // certified variant counts a vector only as far as it separates at both ta and t, less
  // the margin over [ta, t]: positive then proves [ta, t] free of contact.
  const bool certified = settings.variant == ExtrusionVariant::Certified;
  auto marginOver = [&](S duration) { return certified ? duration * duration / S(8) * accelerationBound : S(0); };
  // Each vector's support searches start where its last ones ended (its hints): the
  // bodies have moved little since, and the climbs are short (speed).
  auto approximateMaxSdOf = [&](const auto& Pt, const auto& Qt, S t) {
    S best = -std::numeric_limits<S>::infinity();
    for (int k = 0; k < vectors.count; ++k) {
      const S sd = supportingDistance(Pt, Qt, vectors.vectors[k], vectors.hintP[k], vectors.hintQ[k]);
      best = std::max(best, certified ? std::min(sd, vectors.sdStart[k]) : sd);
    }
    result.sdEvaluations += vectors.count;
    return best - marginOver(t - ta);
  };
  auto approximateMaxSd = [&](S t) { return approximateMaxSdOf(P.at(t), Q.at(t), t); };
  // The same at t1, from the values the complete test stored.
  auto approximateMaxSdAtEnd = [&] {
    S best = -std::numeric_limits<S>::infinity();
    for (int k = 0; k < vectors.count; ++k)
      best = std::max(best, certified ? std::min(vectors.sdEnd[k], vectors.sdStart[k]) : vectors.sdEnd[k]);
    return best - marginOver(t1 - ta);
  };

  S previousHigh = t1;      // the far end of the last Brent bracket, where F was negative
  S taBefore = t0;          // the complete test before the one at ta...
  S distanceBefore = S(0);  // ...and its distance
  bool creeping = false;    // the last restart came at an iterate where F was more than tol above 0
  for (;;) {
    // No stored vector separates at ta by the tolerance (GJK's own gap can leave the
    // distance just above tol with every SD just below it): nothing beyond ta can be
    // proven, and ta, where the distance is within round-off of tol, is the time of impact.
    if (vectors.count == 0) {
      result.status = ToiStatus::Hit;
      detail::takeContact(result, ta, lastTest);
      return result;
    }
    // F(ta) = exact distance - tol > 0; F(t1) = approximate max SD at t1 - margin - tol <= 0.
    // Brent's history is lost on a restart, and a first secant towards t1 creeps like
    // regula falsi where F bends away from the chord (accelerating or turning bodies:
    // each secant lands short, F is above the tolerance there, and every restart costs a
    // complete test). So the bracket's far end is the nearest of these where the new
    // vectors are below the tolerance:
    // - the last bracket's far end;
    // - after a restart at an iterate where F was well above zero (the secant landed
    //   short: the creep above), where the exact distances of the last two complete tests
    //   extrapolate to the tolerance (a secant on the distance). The distance bends
    //   towards contact there, so this lies past the contact, where F < 0. (Where the
    //   restart came at F's root, as under linear motion, it would lie short: not tried.)
    const S fLow = distanceAtTa - tol;
    S high = t1, fHigh = std::min(approximateMaxSdAtEnd() - tol, S(0));
    auto tryHigh = [&](S t) {
      if (!(t > ta && t < high)) return;
      const S f = approximateMaxSd(t) - tol;
      if (f < S(0)) {
        high = t;
        fHigh = f;
      }
    };
    tryHigh(previousHigh);
    if (creeping && distanceBefore > distanceAtTa)
      tryHigh(ta + (distanceAtTa - tol) * ((ta - taBefore) / (distanceBefore - distanceAtTa)));
    BrentStepper<S> brent(ta, fLow, high, fHigh, timeTolerance);
    bool restarted = false;
    while (!restarted) {
      if (brent.converged()) {
        // The contact time is bracketed within the time tolerance between ta, the last time
        // proven free of contact, and tb, where F < 0. If the stored vectors still prove the
        // bodies apart at tb (approximate maximum SD > 0) and the exact distance there is
        // within the tolerance, tb is the paper's time of impact ("its maximum supporting
        // distance is positive and smaller than the collision tolerance"). Otherwise ta is,
        // where the distance exceeds tol by at most what the bodies move in one time tolerance.
        result.status = ToiStatus::Hit;
        const S tb = brent.root() == ta ? brent.counterpart() : brent.root();
        if (tb > ta && vectors.count > 0) {
          const auto Pb = P.at(tb);
          const auto Qb = Q.at(tb);
          if (approximateMaxSdOf(Pb, Qb, tb) > S(0)) {
            const ExtrusionResult<S> atEnd = completeTest(Pb, Qb, tb);
            if (atEnd.status == ExtrusionStatus::CollidingAtStart) {
              detail::takeContact(result, tb, atEnd);
              return result;
            }
          }
        }
        detail::takeContact(result, ta, lastTest);
        return result;
      }
      if (result.brentIterations >= settings.maxIterations) {
        result.status = ToiStatus::IterationCap;
        detail::takeContact(result, ta, lastTest);
        return result;
      }
      const S tx = brent.next();
      ++result.brentIterations;
      const auto Px = P.at(tx);
      const auto Qx = Q.at(tx);
      const S approx = vectors.count > 0 ? approximateMaxSdOf(Px, Qx, tx) : S(0);
      // "Positive" means at least the tolerance (F(tx) >= 0), not merely above 0: only then
      // are the bodies proven no closer than the tolerance on all of [ta, tx] (see the
      // file comment). Between 0 and tol, Brent goes on with F(tx) < 0.
      const bool separates = approx >= tol;
      ToiStep<S> step{tx, approx, ta, std::max(brent.root(), brent.counterpart()), brent.nextKind(), separates};
      if (trace) trace->steps.push_back(step);
      if (!separates) {  // no stored vector separates at tx by the tolerance; keep iterating
        brent.update(approx - tol);
        continue;
      }
      // At least the tolerance: [ta, tx] is free of contact; the complete test on [tx, t1] decides.
      ++result.restarts;
      ExtrusionResult<S> next = completeTest(Px, Qx, tx);
      switch (next.status) {
        case ExtrusionStatus::NoCollision:
          result.status = ToiStatus::PhotoFinish;
          return result;
        case ExtrusionStatus::CollidingAtStart:  // exact distance at tx within the tolerance
          result.status = ToiStatus::Hit;
          detail::takeContact(result, tx, next);
          return result;
        case ExtrusionStatus::NumericalFailure:
          result.status = ToiStatus::NumericalFailure;
          return result;
        case ExtrusionStatus::IterationCap:
          result.status = ToiStatus::IterationCap;
          detail::takeContact(result, ta, lastTest);
          return result;
        case ExtrusionStatus::Undecided:
          previousHigh = std::max(brent.root(), brent.counterpart());
          taBefore = ta;
          distanceBefore = distanceAtTa;
          creeping = approx - tol > tol;
          ta = tx;
          distanceAtTa = next.distanceAtStart;
          lastTest = std::move(next);  // and with it `vectors`
          restarted = true;
          break;
      }
    }
  }
}

}  // namespace gjkx
