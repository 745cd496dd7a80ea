/// @file
/// @brief The stiff and extreme cases of the study (chapters/09_study): ten time-of-impact
/// queries and six static pairs built to break a method, each with an independent
/// reference, a stated rule for "right", and the methods of ours that the table runs.
///
/// Holds (namespace gjkx::study): the cases (`ToiCase`, `StaticCase`, `makeToiCases`,
/// `makeStaticCases`, their builders in `build`), the answers and verdicts (`ToiAnswer`,
/// `GjkAnswer`, `Verdict`, `Cell`, `judgeToi`, `judgeGjk`), the methods of ours
/// (`ourToiMethods`, `ourGjkMethods`: the library's static sampling, swept test,
/// conservative advancement and time-of-impact solver, called directly) and the guarded
/// cells (`runToiCell`, `runGjkCell`, through watchdog.hpp).
///
/// The methods of ours are here (the test tests/brent/test_extreme_cases.cpp runs them
/// without any peer); the peers are added by chapters/09_study/extreme_cases.cpp, which
/// prints the table.
///
/// References (independent of every method; no GJK, no support mapping):
/// - time of impact: workloads.hpp's long-double brute force (feature pairs of the cores,
///   a Lipschitz bound on d(t), bisection to 1e-13): t_ref is the first time the bodies
///   come within 1e-10; and a closed form where the geometry gives one, which must agree;
/// - static pairs: the same long-double distance at the two poses, and a closed form.
/// A 2D form ("planar twin", for Box2D) is given where the case is a prism problem:
/// boxes moving in the plane z = 0 and turning about z, Q's z-range holding P's, so the
/// bodies touch exactly when their cross-sections do; the twin's own 2D reference must
/// give the same t_ref.
///
/// "Right", per cell:
/// - time of impact, the reference has contact (Expect::Hit): the method reports a hit at
///   a time t with d_ref(t) <= delta (not early: the bodies are within delta of touching)
///   and t <= t_ref + delta / L (not late: past the first contact they can have
///   interpenetrated by at most delta; L bounds how fast d(t) changes). delta is stated per
///   case. A yes/no method (the swept test) is judged on its yes/no only.
/// - no contact (Expect::NoHit): the method reports no hit.
/// - a gap below every method's resolution (Expect::Either): no hit, or a hit that meets
///   the hit rule above (t_ref being the first time the gap is under 1e-10).
/// - static distance methods: |d - d_ref| <= tau (an overlap counts as d = 0), with
///   tau = 1e-6 times the case's scale (its largest coordinate, at least 1): 8 float ulps;
///   boolean methods: "intersecting" exactly when d_ref = 0, "disjoint" when d_ref > tau,
///   either in between.
/// Otherwise the cell is wrong (with why), NaN (a non-finite answer or a numerical-failure
/// status), cap (an iteration-cap status), hang (the watchdog's limit ran out) or crash (a
/// signal, or an exception thrown on these valid inputs).
#pragma once

#include <gjkx/study/our_settings.hpp>
#include <gjkx/study/shape_description.hpp>
#include <gjkx/study/watchdog.hpp>
#include <gjkx/study/workloads.hpp>

#include <gjkx/reference/time_of_impact.hpp>

#include <gjkx/brent/conservative_advancement.hpp>
#include <gjkx/brent/time_of_impact.hpp>
#include <gjkx/extrusion/static_sampling.hpp>
#include <gjkx/extrusion/sweeping.hpp>
#include <gjkx/gjk/gjk.hpp>
#include <gjkx/support_mapping/placed.hpp>
#include <gjkx/supporting_distance/intersection.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <functional>
#include <limits>
#include <stdexcept>
#include <string>
#include <variant>
#include <vector>

namespace gjkx::study {

/// What a correct method must say about a time-of-impact case (see the file comment).
enum class Expect { Hit, NoHit, Either };

/// One time-of-impact case with its reference.
struct ToiCase {
  std::string name;   ///< e.g. "touching faces"
  std::string setup;  ///< what the bodies do, in one line
  ToiQuery query;     ///< the 3D query; refHit and tRef from the long-double reference
  bool hasPlanarForm = false;  ///< the case has a 2D form (for Box2D)
  ToiQuery planar;    ///< the 2D form (cross-sections in z = 0), when hasPlanarForm
  Expect expect = Expect::Hit;  ///< what a correct method must say
  double delta = 0.01;  ///< the judging tolerance of a hit (a length)
  std::string deltaWhy;  ///< why delta is what it is, in words
  double closedForm = std::numeric_limits<double>::quiet_NaN();  ///< t_ref by a closed form, NaN if none
  double lipschitz = 0;  ///< L of the reference: |d'(t)| <= L
};

/// One static pair with its reference.
struct StaticCase {
  std::string name;        ///< e.g. "touching faces"
  std::string setup;       ///< what the pair is, in one line
  ShapeDescription P;      ///< the first shape
  ShapeDescription Q;      ///< the second shape
  Pose<double> poseP;      ///< P's pose
  Pose<double> poseQ;      ///< Q's pose
  double reference = 0;  ///< long-double brute-force distance (0: touching or overlapping)
  double closedForm = std::numeric_limits<double>::quiet_NaN();  ///< the distance by a closed form
  double scale = 1;  ///< largest coordinate (at least 1)
  double tau = 1e-6;  ///< 1e-6 * scale
};

// ---------------------------------------------------------------------------------------
// Building the cases

/// Builders of the cases.
namespace build {

/// A rotation by a about z.
inline Eigen::Matrix3d rotZ(double a) { return Eigen::AngleAxisd(a, Eigen::Vector3d::UnitZ()).toRotationMatrix(); }
/// A rotation by a about `axis` (any nonzero length).
inline Eigen::Matrix3d rotAxis(double a, const Eigen::Vector3d& axis) {
  return Eigen::AngleAxisd(a, axis.normalized()).toRotationMatrix();
}

/// A square (or rectangle) of zero thickness in z = 0: a polygon.
inline ShapeDescription rectangle(double hx, double hy) {
  ShapeDescription s;
  s.kind = ShapeKind::Polygon;
  s.hull = std::make_shared<const Polytope<double>>(
      Polytope<double>::polygon({{-hx, -hy, 0}, {hx, -hy, 0}, {hx, hy, 0}, {-hx, hy, 0}}));
  return s;
}

/// The cross-section in z = 0 of a box moving in that plane.
inline ShapeDescription crossSection(const ShapeDescription& s) {
  if (s.kind != ShapeKind::Box) throw std::logic_error("extreme cases: only boxes have a planar twin here");
  return rectangle(s.halfExtents.x(), s.halfExtents.y());
}

/// Whether a motion stays in the plane z = 0 and turns about z only.
inline bool inPlane(const MotionSpec& m) {
  const Eigen::Matrix3d R = m.R0;
  return m.p0.z() == 0 && m.v.z() == 0 && m.a.z() == 0 && m.w.x() == 0 && m.w.y() == 0 && R(2, 2) == 1 && R(0, 2) == 0 &&
         R(1, 2) == 0;
}

/// The 2D form of a prism query: same motions, cross-sections for the shapes.
inline ToiQuery planarTwin(const ToiQuery& q) {
  if (!inPlane(q.motionP) || !inPlane(q.motionQ)) throw std::logic_error("extreme cases: a planar twin needs motions in z = 0");
  // Contact of the prisms is contact of the cross-sections only if Q's z-range holds P's.
  if (q.P.halfExtents.z() > q.Q.halfExtents.z()) throw std::logic_error("extreme cases: P must be thinner in z than Q");
  ToiQuery t = q;
  t.planar = true;
  t.P = crossSection(q.P);
  t.Q = crossSection(q.Q);
  return t;
}

// The first root in [0, 1] of a gap function g(t) (g(0) > 0), by scanning and bisection in
// long double (the reference library's): the closed forms below are "gap(t) = 0" for one
// moving feature.
using reference::firstRoot;

/// The lowest y of a z-rotated box's cross-section (half extents hx, hy, angle a), relative to its centre.
inline LD lowestY(LD hx, LD hy, LD a) { return -(hx * std::abs(std::sin(a)) + hy * std::abs(std::cos(a))); }
/// The largest x of a z-rotated box's cross-section, relative to its centre.
inline LD rightmostX(LD hx, LD hy, LD a) { return hx * std::abs(std::cos(a)) + hy * std::abs(std::sin(a)); }

}  // namespace build

/// Fills the references of a time-of-impact case (and of its twin), and L.
void computeReference(ToiCase& c);

/// The ten time-of-impact cases, references computed.
std::vector<ToiCase> makeToiCases();

/// The long-double distance between two shapes at two poses (workloads.hpp's brute force).
double referenceDistance(const StaticCase& c);

/// The six static cases, references computed.
std::vector<StaticCase> makeStaticCases();

// ---------------------------------------------------------------------------------------
// Answers and the watchdog

/// A time-of-impact answer.
struct ToiAnswer {
  AnswerKind kind = AnswerKind::Answer;  ///< how it came back
  bool hit = false;                      ///< the method reports a collision
  double time = 1;                       ///< its time of impact
  char status[48] = "";   ///< the method's own status name, if it has one
  char message[160] = "";  ///< an exception's what()
};

/// A static answer: a distance (overlap: <= 0) or a yes/no.
struct GjkAnswer {
  AnswerKind kind = AnswerKind::Answer;  ///< how it came back
  bool boolean = false;                  ///< a yes/no method (else a distance)
  bool overlap = false;  ///< boolean methods
  double distance = 0;   ///< distance methods (<= 0: overlapping)
  char status[48] = "";    ///< the method's own status name, if it has one
  char message[160] = "";  ///< an exception's what()
};

// ---------------------------------------------------------------------------------------
// Verdicts

/// A cell of the table.
enum class Verdict { Right, Wrong, NaN, Hang, Crash, Cap, NotApplicable };

/// The verdict's word in the table.
inline const char* toString(Verdict v) {
  switch (v) {
    case Verdict::Right: return "right";
    case Verdict::Wrong: return "wrong";
    case Verdict::NaN: return "NaN";
    case Verdict::Hang: return "hang";
    case Verdict::Crash: return "crash";
    case Verdict::Cap: return "cap";
    case Verdict::NotApplicable: return "n/a";
  }
  return "?";
}

/// A judged cell: the verdict, a short reason ("miss", "late +3e-02"), and what the method said.
struct Cell {
  Verdict verdict = Verdict::NotApplicable;  ///< the verdict
  std::string reason;  ///< short, for the table
  std::string said;    ///< what the method answered, for the notes
  double seconds = 0;  ///< wall time of the guarded run
  /// "verdict: reason", for the table.
  std::string text() const { return reason.empty() ? toString(verdict) : std::string(toString(verdict)) + ": " + reason; }
};

/// x in scientific notation with `digits` digits after the point.
inline std::string sci(double x, int digits = 1) {
  char s[32];
  std::snprintf(s, sizeof s, "%.*e", digits, x);
  return s;
}

/// The parts of a guarded run that do not depend on the answer: hang, crash, exception.
template <typename Answer>
bool judgeRun(const GuardedRun& run, const Answer& a, Cell& cell) {
  cell.seconds = run.seconds;
  if (run.timedOut) {
    cell.verdict = Verdict::Hang;
    cell.said = "killed by the watchdog after " + sci(run.seconds, 1) + " s";
    return true;
  }
  if (run.signal) {
    cell.verdict = Verdict::Crash;
    cell.reason = strsignal(run.signal);
    cell.said = "died of signal " + std::to_string(run.signal);
    return true;
  }
  if (!run.finished) {
    cell.verdict = Verdict::Crash;
    cell.reason = "no answer";
    return true;
  }
  if (a.kind == AnswerKind::Exception) {
    cell.verdict = Verdict::Crash;
    cell.reason = "throws";
    cell.said = std::string("exception: ") + a.message;
    return true;
  }
  if (a.kind == AnswerKind::Cap) {
    cell.verdict = Verdict::Cap;
    cell.said = std::string("status ") + a.status;
    return true;
  }
  if (a.kind == AnswerKind::NumericalFailure) {
    cell.verdict = Verdict::NaN;
    cell.said = std::string("status ") + a.status;
    return true;
  }
  return false;
}

/// Judges a time-of-impact answer against the query it ran on (the case's 3D query or its
/// 2D form); see the file comment.
inline Cell judgeToi(const ToiCase& c, const ToiQuery& q, const GuardedRun& run, const ToiAnswer& a, bool detectionOnly) {
  Cell cell;
  if (judgeRun(run, a, cell)) return cell;
  cell.said = std::string(a.hit ? "hit" : "no hit") + (a.hit && !detectionOnly ? " at t = " + sci(a.time, 6) : "") +
              (a.status[0] ? std::string(" (") + a.status + ")" : "");
  if (a.hit && !detectionOnly && !std::isfinite(a.time)) {
    cell.verdict = Verdict::NaN;
    return cell;
  }
  if (!a.hit) {
    const bool right = c.expect != Expect::Hit;
    cell.verdict = right ? Verdict::Right : Verdict::Wrong;
    if (!right) cell.reason = "miss";
    return cell;
  }
  if (c.expect == Expect::NoHit) {
    cell.verdict = Verdict::Wrong;
    cell.reason = "false alarm";
    return cell;
  }
  if (detectionOnly) {
    cell.verdict = Verdict::Right;
    return cell;
  }
  if (a.time < 0 || a.time > 1) {
    cell.verdict = Verdict::Wrong;
    cell.reason = "t outside [0, 1]";
    return cell;
  }
  ref::DistanceFunction d(q);
  const double dAt = double(d(LD(a.time)));
  const double late = a.time - q.tRef;
  cell.said += ", d_ref(t) = " + sci(dAt, 2) + ", t - t_ref = " + sci(late, 2);
  if (late > c.delta / c.lipschitz) {
    cell.verdict = Verdict::Wrong;
    cell.reason = "late " + sci(late, 0);
  } else if (dAt > c.delta) {
    cell.verdict = Verdict::Wrong;
    cell.reason = "early, d=" + sci(dAt, 0);
  } else {
    cell.verdict = Verdict::Right;
  }
  return cell;
}

/// Judges a static answer; see the file comment.
inline Cell judgeGjk(const StaticCase& c, const GuardedRun& run, const GjkAnswer& a) {
  Cell cell;
  if (judgeRun(run, a, cell)) return cell;
  if (a.boolean) {
    cell.said = a.overlap ? "intersecting" : "disjoint";
    const bool right = c.reference == 0 ? a.overlap : (c.reference > c.tau ? !a.overlap : true);
    cell.verdict = right ? Verdict::Right : Verdict::Wrong;
    if (!right) cell.reason = a.overlap ? "says intersecting" : "says disjoint";
    return cell;
  }
  cell.said = "distance " + sci(a.distance, 3) + (a.status[0] ? std::string(" (") + a.status + ")" : "");
  if (!std::isfinite(a.distance)) {
    cell.verdict = Verdict::NaN;
    return cell;
  }
  const double error = std::abs(std::max(a.distance, 0.0) - c.reference);
  if (error <= c.tau) {
    cell.verdict = Verdict::Right;
  } else {
    cell.verdict = Verdict::Wrong;
    cell.reason = "error " + sci(error, 0);
  }
  return cell;
}

// ---------------------------------------------------------------------------------------
// The methods of ours

/// The collision tolerance of the methods of ours in the table (float and double alike,
/// so the two columns answer the same question).
constexpr double kTolerance = 1e-5;
/// The watchdog's limit per cell (seconds).
constexpr double kWatchdog = 5;


/// Calls `method(P, Q, L)` on the query's two moving bodies, in scalar S, with L the
/// query's relative speed bound (workloads.hpp's relativeSpeedBound).
template <typename S, typename F>
ToiAnswer withMoving(const ToiQuery& q, F&& method) {
  const AnyShape<S> P = ourShape<S>(q.P), Q = ourShape<S>(q.Q);
  const Motion<S> mp = toMotion<S>(q.motionP), mq = toMotion<S>(q.motionQ);
  const S L = S(relativeSpeedBound(q));
  return std::visit([&](const auto& a, const auto& b) { return method(moving(a, mp), moving(b, mq), L); }, P, Q);
}

/// A time-of-impact answer: whether and when the method reports a hit, its status name,
/// and whether that status is its iteration cap or a numerical failure.
inline ToiAnswer toiAnswer(bool hit, double time, const std::string& status, bool cap, bool numericalFailure) {
  ToiAnswer out;
  out.kind = cap ? AnswerKind::Cap : numericalFailure ? AnswerKind::NumericalFailure : AnswerKind::Answer;
  out.hit = hit;
  out.time = time;
  setText(out.status, sizeof out.status, status);
  return out;
}

/// The table's answer for static sampling: the first instant not proven disjoint, with
/// the static test's status there.
template <typename S>
ToiAnswer answerOf(const StaticSamplingResult<S>& r) {
  if (r.status == StaticSamplingStatus::NoCollision) return ToiAnswer{};
  return toiAnswer(true, double(r.time), toString(r.intersection), r.status == StaticSamplingStatus::IterationCap,
                   r.status == StaticSamplingStatus::NumericalFailure);
}

/// The table's answer for the swept test: yes/no, with its status.
template <typename S>
ToiAnswer answerOf(const IntersectionResult<S>& r) {
  return toiAnswer(r.status != IntersectionStatus::Disjoint, 0, toString(r.status), r.status == IntersectionStatus::IterationCap,
                   r.status == IntersectionStatus::NumericalFailure);
}

/// The table's answer for conservative advancement, keeping its cap and numerical failure.
template <typename S>
ToiAnswer answerOf(const ConservativeAdvancementResult<S>& r) {
  switch (r.status) {
    case ConservativeAdvancementStatus::NoCollision: return ToiAnswer{};
    case ConservativeAdvancementStatus::NumericalFailure: return toiAnswer(false, 1, "gjk numerical-failure", false, true);
    case ConservativeAdvancementStatus::IterationCap: return toiAnswer(true, double(r.time), std::to_string(r.steps) + " steps", true, false);
    case ConservativeAdvancementStatus::Hit: break;
  }
  return toiAnswer(true, double(r.time), "", false, false);
}

/// The table's answer for the paper's solver (gjkx::timeOfImpact), keeping its status.
template <typename S>
ToiAnswer answerOf(const ToiResult<S>& r) {
  return toiAnswer(reportsCollision(r.status), double(r.time), toString(r.status), r.status == ToiStatus::IterationCap,
                   r.status == ToiStatus::NumericalFailure);
}

/// GJK's distance (gjkx::gjk, default settings) at the case's poses, in scalar S.
template <typename S>
GjkAnswer oursGjk(const StaticCase& c) {
  const AnyShape<S> P = ourShape<S>(c.P), Q = ourShape<S>(c.Q);
  const Pose<S> pp = c.poseP.template cast<S>(), pq = c.poseQ.template cast<S>();
  return std::visit(
      [&](const auto& a, const auto& b) {
        const GjkResult<S> r = gjk(place(a, pp), place(b, pq));
        GjkAnswer out;
        setText(out.status, sizeof out.status, toString(r.status));
        if (r.status == GjkStatus::IterationCap) out.kind = AnswerKind::Cap;
        if (r.status == GjkStatus::NumericalFailure) out.kind = AnswerKind::NumericalFailure;
        out.distance = double(r.distance);
        return out;
      },
      P, Q);
}

/// A time-of-impact method of the table.
struct ToiMethod {
  std::string name;           ///< column header
  bool library = false;       ///< a solver of the library (the test asserts these)
  bool planarOnly = false;    ///< runs on the 2D form only (Box2D)
  bool detectionOnly = false;  ///< yes/no, no time
  std::function<ToiAnswer(const ToiQuery&)> run;  ///< the method on a query
};

/// A static method of the table.
struct GjkMethod {
  std::string name;                                 ///< column header
  bool library = false;                             ///< a solver of the library (the test asserts these)
  std::function<GjkAnswer(const StaticCase&)> run;  ///< the method on a case
};

/// The time-of-impact methods of ours: static sampling, swept, CA, the paper's solver and
/// the certified one (tolerance kTolerance).
std::vector<ToiMethod> ourToiMethods();

/// The static methods of ours: GJK's distance in double and float.
std::vector<GjkMethod> ourGjkMethods();

/// Runs one time-of-impact method on one case, guarded, and judges it.
inline Cell runToiCell(const ToiCase& c, const ToiMethod& m, double limit = kWatchdog) {
  if (m.planarOnly && !c.hasPlanarForm) return Cell{Verdict::NotApplicable, "", "no 2D form", 0};
  const ToiQuery& q = m.planarOnly ? c.planar : c.query;
  ToiAnswer a;
  const GuardedRun run = guarded([&] { return m.run(q); }, limit, a);
  return judgeToi(c, q, run, a, m.detectionOnly);
}

/// Runs one static method on one case, guarded, and judges it.
inline Cell runGjkCell(const StaticCase& c, const GjkMethod& m, double limit = kWatchdog) {
  GjkAnswer a;
  const GuardedRun run = guarded([&] { return m.run(c); }, limit, a);
  return judgeGjk(c, run, a);
}

/// Disagreements between a case's references (the brute force, its 2D form, the closed
/// form, and the expectation), one line each; empty when they agree.
std::vector<std::string> referenceProblems(const std::vector<ToiCase>& cases, const std::vector<StaticCase>& statics);

}  // namespace gjkx::study
