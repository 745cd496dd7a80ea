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
inline void computeReference(ToiCase& c) {
  computeReference(c.query);
  ref::DistanceFunction d(c.query);
  c.lipschitz = double(d.lipschitz());
  if (c.hasPlanarForm) computeReference(c.planar);
}

/// The ten time-of-impact cases, references computed.
inline std::vector<ToiCase> makeToiCases() {
  using build::rotAxis;
  using build::rotZ;
  using V = Eigen::Vector3d;
  std::vector<ToiCase> out;
  auto add = [&](ToiCase c, bool planar) {
    if (planar) {
      c.hasPlanarForm = true;
      c.planar = build::planarTwin(c.query);
    }
    computeReference(c);
    out.push_back(std::move(c));
  };
  const ShapeDescription unitP = boxDescription(V(0.5, 0.5, 0.3)), unitQ = boxDescription(V(0.5, 0.5, 0.5));
  {
    ToiCase c;
    c.name = "touching faces";
    c.setup = "unit boxes; P's face comes down flush on Q's face and stops there exactly at t = 1 (d(1) = 0)";
    c.query.P = unitP;
    c.query.Q = unitQ;
    c.query.motionP.p0 = V(0.3, 1.5, 0);
    c.query.motionP.v = V(0.2, -0.5, 0);
    c.closedForm = 1 - 1e-10 / 0.5;  // d(t) = 0.5 (1 - t) reaches 1e-10 at 1 - 2e-10
    c.deltaWhy = "1% of the boxes' size";
    add(c, true);
  }
  {
    ToiCase c;
    c.name = "sub-epsilon separation";
    c.setup = "unit boxes; P slides along Q's face at a gap of 1e-12 all the interval";
    c.query.P = unitP;
    c.query.Q = unitQ;
    c.query.motionP.p0 = V(-0.6, 1 + 1e-12, 0);
    c.query.motionP.v = V(1.2, 0, 0);
    c.expect = Expect::Either;
    c.closedForm = 0;  // the gap (1 + 1e-12) - 1 is under 1e-10 from the start
    c.deltaWhy = "1% of the boxes' size";
    add(c, true);
  }
  {
    ToiCase c;
    c.name = "coincident origins";
    c.setup = "P and Q start with the same origin (deeply overlapping), P leaves at speed 1.6 turning 2 rad";
    c.query.P = boxDescription(V(0.5, 0.25, 0.3));
    c.query.Q = boxDescription(V(0.4, 0.4, 0.5));
    c.query.motionP.R0 = rotZ(0.3);
    c.query.motionP.v = V(1.5, 0.5, 0);
    c.query.motionP.w = V(0, 0, 2);
    c.closedForm = 0;
    c.deltaWhy = "1% of the boxes' size";
    add(c, true);
  }
  {
    ToiCase c;
    c.name = "degenerate simplices";
    c.setup = "two squares of zero thickness in one plane (flat Minkowski difference), edges meeting parallel";
    c.query.P = build::rectangle(0.5, 0.5);
    c.query.Q = build::rectangle(0.5, 0.5);
    c.query.planar = true;  // the reference in 2D (the shapes are flat)
    c.query.motionP.p0 = V(-2, 0.3, 0);
    c.query.motionP.v = V(2.2, 0, 0);
    c.closedForm = (1 - 1e-10) / 2.2;  // P's right edge x = -1.5 + 2.2 t meets Q's left edge x = -0.5
    c.deltaWhy = "1% of the squares' size";
    add(c, false);
    out.back().hasPlanarForm = true;  // it is its own 2D form
    out.back().planar = out.back().query;
  }
  {
    ToiCase c;
    c.name = "size ratio 10^4";
    c.setup = "a box of half size 0.01 turning 3 rad falls at speed 1.1 on a box of half size 100";
    c.query.P = boxDescription(V(0.01, 0.01, 0.01));
    c.query.Q = boxDescription(V(100, 100, 100));
    c.query.motionP.p0 = V(3, 100.51, 0);
    c.query.motionP.v = V(0.4, -1, 0);
    c.query.motionP.w = V(0, 0, 3);
    c.closedForm = build::firstRoot([](LD t) { return LD(100.51) - t + build::lowestY(LD(0.01), LD(0.01), 3 * t) - 100 - LD(1e-10); });
    c.delta = 1e-3;
    c.deltaWhy = "5% of the small box's size";
    add(c, true);
  }
  {
    ToiCase c;
    c.name = "coordinates near 10^5";
    c.setup = "unit boxes at x, y = 1e5 (float spacing there: 0.0078); P turning 0.5 rad meets Q at speed 2";
    c.query.P = unitP;
    c.query.Q = unitQ;
    c.query.motionQ.p0 = V(1e5, 1e5, 0);
    c.query.motionP.p0 = V(1e5 - 2, 1e5 + 0.25, 0);
    c.query.motionP.v = V(2, 0, 0);
    c.query.motionP.w = V(0, 0, 0.5);
    // P's rightmost point reaches Q's left face x = 1e5 - 0.5 (within Q's y-range: checked by the reference).
    c.closedForm = build::firstRoot([](LD t) { return LD(1e5) - 0.5L - (LD(1e5) - 2 + 2 * t + build::rightmostX(0.5L, 0.5L, 0.5L * t)) - LD(1e-10); });
    // No float allowance: the default 1% holds for a method that works in the frame of one
    // body (timeOfImpact does; with world coordinates its float run was 3.2e-3 early here).
    c.deltaWhy = "1% of the boxes' size; float spacing at 1e5 is 0.0078";
    add(c, true);
  }
  {
    ToiCase c;
    c.name = "half a turn per interval";
    c.setup = "a rod (half size 1 x 0.05) turns by pi about z: the same set at t = 0 and 1, sweeping through Q on the way";
    c.query.P = boxDescription(V(1, 0.05, 0.3));
    c.query.Q = boxDescription(V(0.1, 0.1, 0.5));
    c.query.motionP.w = V(0, 0, M_PI);
    c.query.motionQ.p0 = V(0.3, 0.75, 0);
    c.deltaWhy = "1% of the boxes' size";
    add(c, true);
  }
  {
    ToiCase c;
    c.name = "thin rod spinning";
    c.setup = "a rod 2 long and 0.004 thick spins 12 rad about a tilted axis; its end sweeps through a cube of side 0.06";
    c.query.P = boxDescription(V(1, 0.002, 0.002));
    c.query.Q = boxDescription(V(0.03, 0.03, 0.03));
    c.query.motionP.v = V(0.1, 0.05, 0);
    c.query.motionP.w = 12 * V(0.2, 0.3, 0.93).normalized();
    // Q stands where the rod's point at 0.8 along it passes at t = 0.37.
    const auto [R, p] = c.query.motionP.poseAt(0.37);
    c.query.motionQ.p0 = p + R * V(0.8, 0, 0);
    c.query.motionQ.R0 = rotAxis(0.6, V(1, 1, 0));
    c.delta = 1e-3;
    c.deltaWhy = "a quarter of the rod's thickness";
    add(c, false);
  }
  {
    ToiCase c;
    c.name = "starting within tolerance, separating";
    // The gap is inside the tolerance (1e-5) and 32 float ulps wide: above the round-off GJK calls an
    // overlap (16 eps times the size; below it, sub-epsilon separation is the case).
    c.setup = "unit boxes 2^-18 = 3.8e-6 apart at t = 0 (inside the tolerances, 1e-5), P moving away and turning 0.2 rad";
    c.query.P = unitP;
    c.query.Q = unitQ;
    c.query.motionP.p0 = V(0, 1 + std::ldexp(1.0, -18), 0);
    c.query.motionP.v = V(0.3, 0.5, 0);
    c.query.motionP.w = V(0, 0, 0.2);
    c.expect = Expect::NoHit;
    add(c, true);
  }
  {
    ToiCase c;
    c.name = "two fast bodies";
    c.setup = "a capsule and a box, each at speed 100 (over 100 body lengths per interval) and tumbling, meet head on";
    c.query.P = capsuleDescription(0.3, 0.1);
    c.query.Q = boxDescription(V(0.2, 0.15, 0.1));
    c.query.motionP.p0 = V(-50, 0.1, 0.05);
    c.query.motionP.R0 = rotAxis(0.9, V(1, 0, 1));
    c.query.motionP.v = V(100, 0, 0);
    c.query.motionP.w = V(1.5, 2, 0);  // turns under half a revolution: the peers' end poses tell the motion
    c.query.motionQ.p0 = V(50, -0.05, 0);
    c.query.motionQ.R0 = rotAxis(0.4, V(0, 1, 1));
    c.query.motionQ.v = V(-100, 0, 0);
    c.query.motionQ.w = V(0, 1, 2.5);
    c.deltaWhy = "about 3% of the smaller body's size";
    add(c, false);
  }
  return out;
}

/// The long-double distance between two shapes at two poses (workloads.hpp's brute force).
inline double referenceDistance(const StaticCase& c) {
  ToiQuery q;
  q.P = c.P;
  q.Q = c.Q;
  q.motionP.p0 = c.poseP.translation;
  q.motionP.R0 = c.poseP.rotation;
  q.motionQ.p0 = c.poseQ.translation;
  q.motionQ.R0 = c.poseQ.rotation;
  q.planar = c.P.kind == ShapeKind::Polygon && c.Q.kind == ShapeKind::Polygon && c.poseP.translation.z() == 0 &&
             c.poseQ.translation.z() == 0;
  ref::DistanceFunction d(q);
  return double(d(0));
}

/// The six static cases, references computed.
inline std::vector<StaticCase> makeStaticCases() {
  using build::rotAxis;
  using build::rotZ;
  using V = Eigen::Vector3d;
  std::vector<StaticCase> out;
  auto pose = [](const Eigen::Matrix3d& R, const V& p) {
    Pose<double> x;
    x.rotation = R;
    x.translation = p;
    return x;
  };
  auto add = [&](StaticCase c) {
    c.reference = referenceDistance(c);
    c.scale = std::max({1.0, c.poseP.translation.norm() + c.P.boundingRadius(), c.poseQ.translation.norm() + c.Q.boundingRadius()});
    c.tau = 1e-6 * c.scale;
    out.push_back(std::move(c));
  };
  const ShapeDescription unitP = boxDescription(V(0.5, 0.5, 0.3)), unitQ = boxDescription(V(0.5, 0.5, 0.5));
  const Eigen::Matrix3d R = rotAxis(0.7, V(1, 2, 3));
  {
    StaticCase c{"touching faces", "unit boxes face to face, P slid half a face sideways (exact: d = 0)", unitP, unitQ,
                 pose(Eigen::Matrix3d::Identity(), V(0.5, 1, 0)), pose(Eigen::Matrix3d::Identity(), V::Zero())};
    c.closedForm = 0;
    add(c);
  }
  {
    StaticCase c{"sub-epsilon separation", "the same, turned together by 0.7 rad, a gap of 1e-12 (under float's resolution)", unitP,
                 unitQ, pose(R, R * V(0.2, 1 + 1e-12, 0.1)), pose(R, V::Zero())};
    c.closedForm = 1e-12;
    add(c);
  }
  {
    const ShapeDescription box = boxDescription(V(0.5, 0.4, 0.3));
    StaticCase c{"coincident origins", "two identical boxes at the same pose (centre-to-centre direction zero)", box, box,
                 pose(R, V(0.1, 0.2, 0.3)), pose(R, V(0.1, 0.2, 0.3))};
    c.closedForm = 0;
    add(c);
  }
  {
    StaticCase c{"degenerate simplices", "two squares of zero thickness in one plane, overlapping (flat Minkowski difference)",
                 build::rectangle(0.5, 0.5), build::rectangle(0.5, 0.5), pose(rotZ(0.4), V(0.8, 0.3, 0)),
                 pose(Eigen::Matrix3d::Identity(), V::Zero())};
    c.closedForm = 0;
    add(c);
  }
  {
    const ShapeDescription small = boxDescription(V(0.01, 0.01, 0.01)), big = boxDescription(V(100, 100, 100));
    // The small box's lowest point (turned by R) 0.005 above the big box's top face y = 100.
    const double below = 0.01 * (std::abs(R(1, 0)) + std::abs(R(1, 1)) + std::abs(R(1, 2)));
    StaticCase c{"size ratio 10^4", "a box of half size 0.01, turned, 0.005 above a box of half size 100", small, big,
                 pose(R, V(3, 100 + 0.005 + below, 0.7)), pose(Eigen::Matrix3d::Identity(), V::Zero())};
    c.closedForm = 0.005;
    add(c);
  }
  {
    // P turned by Rz(0.3) Rx(0.2), its corner of lowest x placed 0.3 right of Q's face x = 1e5 + 0.5, at
    // (y, z) = (1e5 + 0.1, 0.05) on that face, so the closest points are that corner and the face.
    const Eigen::Matrix3d Rp = rotZ(0.3) * rotAxis(0.2, V(1, 0, 0));
    const V corner = Rp * V(Rp(0, 0) > 0 ? -0.5 : 0.5, Rp(0, 1) > 0 ? -0.5 : 0.5, Rp(0, 2) > 0 ? -0.3 : 0.3);
    StaticCase c{"coordinates near 10^5", "unit boxes at 1e5 (float spacing 0.0078), P turned, a corner 0.3 from Q's face", unitP,
                 unitQ, pose(Rp, V(1e5 + 0.5 + 0.3, 1e5 + 0.1, 0.05) - corner), pose(Eigen::Matrix3d::Identity(), V(1e5, 1e5, 0))};
    c.closedForm = 0.3;
    add(c);
  }
  return out;
}

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
inline std::vector<ToiMethod> ourToiMethods() {
  const double tol = kTolerance;
  std::vector<ToiMethod> m;
  m.push_back({"static N=32", false, false, false, [](const ToiQuery& q) {
                 return withMoving<double>(q, [](const auto& P, const auto& Q, double) { return answerOf(staticSampling(P, Q, 0.0, 1.0, 32)); });
               }});
  m.push_back({"swept", false, false, true, [](const ToiQuery& q) {
                 return withMoving<double>(q, [](const auto& P, const auto& Q, double) { return answerOf(sweepingTest(P, Q, 0.0, 1.0)); });
               }});
  m.push_back({"CA", false, false, false, [tol](const ToiQuery& q) {
                 return withMoving<double>(q, [tol](const auto& P, const auto& Q, double L) {
                   return answerOf(conservativeAdvancement(P, Q, 0.0, 1.0, caSettings(tol, L)));
                 });
               }});
  auto ours = [tol](const char* name, ExtrusionVariant variant, bool useFloat, bool inFrameOfP = true) {
    std::function<ToiAnswer(const ToiQuery&)> run;
    if (useFloat)
      run = [tol, variant, inFrameOfP](const ToiQuery& q) {
        return withMoving<float>(q, [&](const auto& P, const auto& Q, float) {
          ToiSettings<float> settings = toiSettings<float>(tol, variant);
          settings.inFrameOfP = inFrameOfP;
          return answerOf(timeOfImpact(P, Q, 0.0f, 1.0f, settings));
        });
      };
    else
      run = [tol, variant](const ToiQuery& q) {
        return withMoving<double>(q, [&](const auto& P, const auto& Q, double) {
          return answerOf(timeOfImpact(P, Q, 0.0, 1.0, toiSettings<double>(tol, variant)));
        });
      };
    return ToiMethod{name, inFrameOfP, false, false, run};
  };
  m.push_back(ours("ours double", ExtrusionVariant::Paper, false));
  m.push_back(ours("ours float", ExtrusionVariant::Paper, true));
  // The same in world coordinates, not in P's frame: what the frame buys (not a library
  // default, so the test does not hold it to the table).
  m.push_back(ours("ours float, world frame", ExtrusionVariant::Paper, true, false));
  m.push_back(ours("certified double", ExtrusionVariant::Certified, false));
  m.push_back(ours("certified float", ExtrusionVariant::Certified, true));
  return m;
}

/// The static methods of ours: GJK's distance in double and float.
inline std::vector<GjkMethod> ourGjkMethods() {
  return {{"ours double", true, [](const StaticCase& c) { return oursGjk<double>(c); }},
          {"ours float", true, [](const StaticCase& c) { return oursGjk<float>(c); }}};
}

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
inline std::vector<std::string> referenceProblems(const std::vector<ToiCase>& cases, const std::vector<StaticCase>& statics) {
  std::vector<std::string> out;
  for (const ToiCase& c : cases) {
    const bool hit = c.query.refHit;
    if ((c.expect == Expect::NoHit) == hit) out.push_back(c.name + ": the reference says " + (hit ? "hit" : "no hit"));
    if (!std::isnan(c.closedForm) && std::abs(c.closedForm - c.query.tRef) > 1e-9)
      out.push_back(c.name + ": closed form t = " + sci(c.closedForm, 12) + ", brute force t = " + sci(c.query.tRef, 12));
    if (c.hasPlanarForm && (c.planar.refHit != hit || std::abs(c.planar.tRef - c.query.tRef) > 1e-9))
      out.push_back(c.name + ": the 2D form's reference t = " + sci(c.planar.tRef, 12) + " differs");
  }
  for (const StaticCase& c : statics)
    if (std::abs(c.closedForm - c.reference) > 1e-9 * c.scale)
      out.push_back(c.name + " (static): closed form " + sci(c.closedForm, 12) + ", brute force " + sci(c.reference, 12));
  return out;
}

}  // namespace gjkx::study
