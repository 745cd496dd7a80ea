// The separating hyperspace test of §3 ("extrusion test"), step by step on cases a reader
// can check with a ruler, its certified variant (beyond the paper), and the static and
// sweeping tests §1 sets it against.
//
// Conventions (the paper's): SD(P, Q, s) = s.S_Q(-s) - s.S_P(s) for a unit s, positive
// when the plane normal to s separates P and Q; GJK's first direction is s_0 = c_Q - c_P
// (centre of P to centre of Q), then s_{i+1} = z. A unit box has half extents 1/2, and
// its support in direction s is the corner in the octant of s (+1/2 on a zero component).
#include "../gjk/needle_slab.hpp"

#include <gjkx/extrusion/certified_margin.hpp>
#include <gjkx/extrusion/extrusion.hpp>
#include <gjkx/extrusion/static_sampling.hpp>
#include <gjkx/extrusion/sweeping.hpp>
#include <gjkx/support_mapping/deforming_simplex.hpp>
#include <gjkx/support_mapping/placed.hpp>
#include <gjkx/support_mapping/polytope.hpp>
#include <gjkx/support_mapping/primitives.hpp>

#include <catch2/catch.hpp>

#include <cmath>
#include <random>
#include <vector>

using namespace gjkx;

namespace {

const double kPi = 3.14159265358979323846;

template <typename S>
Box<S> unitBox() {
  return Box<S>(Vector3<S>(S(0.5), S(0.5), S(0.5)));
}

}  // namespace

// Q passes above P along -x, one unit box over the other with a gap of 1/2 in y.
// P: unit box at the origin, fixed. Q: unit box from (1, 1.5, 0) at t0 = 0 to
// (-1, 1.5, 0) at t1 = 1 (velocity (-2, 0, 0)).
//
// Step 0: s_0 = c_Q - c_P = (1, 1.5, 0), unit (2, 3, 0)/sqrt(13).
//   S_P(s_0) = (0.5, 0.5, 0.5); at t0 S_Q(-s_0) = (1, 1.5, 0) + (-0.5, -0.5, 0.5) = (0.5, 1, 0.5),
//   w = (0, 0.5, 0): SD(t0) = 1.5/sqrt(13) = 0.416 > 0, a separating vector at t0.
//   At t1 S_Q(-s_0) = (-1.5, 1, 0.5), w = (-2, 0.5, 0): SD(t1) = (-4 + 1.5)/sqrt(13) = -2.5/sqrt(13) < 0.
// Step 1: z = w_0 = (0, 0.5, 0), s_1 = +y.
//   S_P(+y) = (0.5, 0.5, 0.5); S_Q(-y) = c_Q + (0.5, -0.5, 0.5) (zero components take +1/2).
//   SD(t0) = 1 - 0.5 = 0.5, SD(t1) = 0.5: separates at both ends: no collision.
TEST_CASE("extrusion test, step by step: a box passing above another", "[extrusion][hand]") {
  const auto P = fixedAt(unitBox<double>(), Vector3<double>(0, 0, 0));
  const auto Q = translating(unitBox<double>(), Vector3<double>(1, 1.5, 0), Vector3<double>(-2, 0, 0));
  ExtrusionTrace<double> trace;
  const auto r = extrusionTest(P, Q, 0.0, 1.0, {}, nullptr, trace);

  REQUIRE(r.status == ExtrusionStatus::NoCollision);
  REQUIRE(trace.steps.size() == 2);
  const auto& s0 = trace.steps[0];
  CHECK(s0.i == 0);
  CHECK(s0.s.isApprox(Vector3<double>(2, 3, 0) / std::sqrt(13.0), 1e-14));
  CHECK(s0.sdStart == Approx(1.5 / std::sqrt(13.0)).epsilon(1e-14));
  CHECK(s0.sdEnd == Approx(-2.5 / std::sqrt(13.0)).epsilon(1e-14));
  CHECK(s0.separatesStart);
  CHECK_FALSE(s0.separatesEnd);
  const auto& s1 = trace.steps[1];
  CHECK(s1.i == 1);
  CHECK(s1.s.isApprox(Vector3<double>(0, 1, 0), 1e-14));
  CHECK(s1.sdStart == Approx(0.5).epsilon(1e-14));
  CHECK(s1.sdEnd == Approx(0.5).epsilon(1e-14));
  CHECK(s1.separatesStart);
  CHECK(s1.separatesEnd);

  CHECK(r.separatingVector.isApprox(Vector3<double>(0, 1, 0), 1e-14));
  CHECK(r.gjkIterations == 2);
  CHECK(r.margin == 0.0);  // linear motion
  CHECK_FALSE(r.usedRememberedVector);
  // SD(t0) once per GJK iteration, SD(t1) once per vector separating at t0.
  CHECK(r.sdEvaluations == 4);
}

// Q runs into P along -x. P: unit box at the origin; Q: unit box from (3, 0, 0) to
// (-1, 0, 0) over [0, 1] (velocity (-4, 0, 0)).
// Step 0: s_0 = c_Q - c_P = +x. S_P(+x) = (0.5, 0.5, 0.5); S_Q(-x) at t0 = (2.5, 0.5, 0.5):
//   SD(t0) = 2.5 - 0.5 = 2 (also the distance). At t1 S_Q(-x) = (-1.5, 0.5, 0.5): SD(t1) = -2.
// Step 1: z = w_0 = (2, 0, 0), s_1 = +x again: GJK finds nothing new and converges with
//   distance 2. No vector separates at t1: the test is undecided (§3: "this extrusion test
//   fails"), with maxSdEnd = -2 for the time-of-impact solver (§5).
TEST_CASE("extrusion test, step by step: a box running into another", "[extrusion][hand]") {
  const auto P = fixedAt(unitBox<double>(), Vector3<double>(0, 0, 0));
  const auto Q = translating(unitBox<double>(), Vector3<double>(3, 0, 0), Vector3<double>(-4, 0, 0));
  ExtrusionTrace<double> trace;
  const auto r = extrusionTest(P, Q, 0.0, 1.0, {}, nullptr, trace);

  REQUIRE(r.status == ExtrusionStatus::Undecided);
  REQUIRE(trace.steps.size() == 2);
  for (const auto& step : trace.steps) {
    CHECK(step.s.isApprox(Vector3<double>(1, 0, 0), 1e-14));
    CHECK(step.sdStart == Approx(2.0).epsilon(1e-14));
    CHECK(step.sdEnd == Approx(-2.0).epsilon(1e-14));
    CHECK(step.separatesStart);
    CHECK_FALSE(step.separatesEnd);
  }
  CHECK(r.distanceAtStart == Approx(2.0).epsilon(1e-14));
  CHECK(r.witnessP.x() == Approx(0.5));
  CHECK(r.witnessQ.x() == Approx(2.5));
  CHECK(r.maxSdEnd == Approx(-2.0).epsilon(1e-14));
}

// Undecided keeps the separating vectors found at t0, each with SD(t1), and maxSdEnd is
// the largest of those SD(t1) (§5's approximate maximum supporting distance at t1).
// Q passes above P but far: from (3, 1.5, 0) to (-3, 1.5, 0) (velocity (-6, 0, 0)).
// Step 0: s_0 = (3, 1.5, 0), unit (2, 1, 0)/sqrt(5). S_P = (0.5, 0.5, 0.5), at t0
//   S_Q(-s_0) = (2.5, 1, 0.5), w = (2, 0.5, 0): SD(t0) = 4.5/sqrt(5);
//   at t1 S_Q(-s_0) = (-3.5, 1, 0.5), w = (-4, 0.5, 0): SD(t1) = -7.5/sqrt(5).
// Step 1: s_1 = z = (2, 0.5, 0), unit (4, 1, 0)/sqrt(17): the same support points, so
//   SD(t0) = 8.5/sqrt(17) = sqrt(4.25) (the distance), SD(t1) = (-16 + 0.5)/sqrt(17);
//   GJK converges. The pair never collides (the gap in y stays 1/2), but neither vector
//   GJK met at t0 separates at t1: the test fails without a collision (§3).
TEST_CASE("an undecided test returns the separating vectors found at t0", "[extrusion][hand]") {
  const auto P = fixedAt(unitBox<double>(), Vector3<double>(0, 0, 0));
  const auto Q = translating(unitBox<double>(), Vector3<double>(3, 1.5, 0), Vector3<double>(-6, 0, 0));
  ExtrusionTrace<double> trace;
  const auto r = extrusionTest(P, Q, 0.0, 1.0, {}, nullptr, trace);

  REQUIRE(r.status == ExtrusionStatus::Undecided);
  REQUIRE(r.separating.count == 2);
  REQUIRE(trace.steps.size() == 2);
  CHECK(r.separating.vectors[0].isApprox(Vector3<double>(2, 1, 0) / std::sqrt(5.0), 1e-14));
  CHECK(r.separating.sdStart[0] == Approx(4.5 / std::sqrt(5.0)).epsilon(1e-14));
  CHECK(r.separating.sdEnd[0] == Approx(-7.5 / std::sqrt(5.0)).epsilon(1e-14));
  CHECK(r.separating.vectors[1].isApprox(Vector3<double>(4, 1, 0) / std::sqrt(17.0), 1e-14));
  CHECK(r.separating.sdStart[1] == Approx(std::sqrt(4.25)).epsilon(1e-14));
  CHECK(r.separating.sdEnd[1] == Approx(-15.5 / std::sqrt(17.0)).epsilon(1e-14));
  CHECK(r.maxSdEnd == Approx(-7.5 / std::sqrt(5.0)).epsilon(1e-14));
  CHECK(r.maxSdEnd == std::max(r.separating.sdEnd[0], r.separating.sdEnd[1]));
  CHECK(r.distanceAtStart == Approx(std::sqrt(4.25)).epsilon(1e-12));
  // Every stored vector separates at t0 (above the tolerance).
  for (int k = 0; k < r.separating.count; ++k) CHECK(r.separating.sdStart[k] > defaultCollisionTolerance<double>());
}

// Temporal coherence: the vector that decided one interval is tried first on the next,
// and decides it without GJK. The box passing above (first test case) over [0, 1], then
// over [1, 2]: from (-1, 1.5, 0) to (-3, 1.5, 0), where +y still separates by 0.5.
TEST_CASE("the remembered vector decides the next interval without GJK", "[extrusion][cache]") {
  const auto P = fixedAt(unitBox<double>(), Vector3<double>(0, 0, 0));
  const auto Q = translating(unitBox<double>(), Vector3<double>(1, 1.5, 0), Vector3<double>(-2, 0, 0));
  ExtrusionCache<double> cache;
  const auto first = extrusionTest(P, Q, 0.0, 1.0, {}, &cache);
  REQUIRE(first.status == ExtrusionStatus::NoCollision);
  REQUIRE(cache.valid);
  CHECK(cache.separatingVector.isApprox(Vector3<double>(0, 1, 0), 1e-14));

  ExtrusionTrace<double> trace;
  const auto second = extrusionTest(P, Q, 1.0, 2.0, {}, &cache, trace);
  CHECK(second.status == ExtrusionStatus::NoCollision);
  CHECK(second.usedRememberedVector);
  CHECK(second.gjkIterations == 0);
  CHECK(second.sdEvaluations == 2);
  REQUIRE(trace.steps.size() == 1);
  CHECK(trace.steps[0].i == -1);
  CHECK(trace.steps[0].sdStart == Approx(0.5).epsilon(1e-14));
  CHECK(trace.steps[0].sdEnd == Approx(0.5).epsilon(1e-14));
  CHECK(second.separatingVector.isApprox(Vector3<double>(0, 1, 0), 1e-14));

  // A remembered vector that does not separate (here the cache is reused for a box R
  // that runs into P along the x axis, where SD(+y) = -1) costs one SD; GJK then runs,
  // and the cache forgets the vector since nothing separated both ends.
  const auto R = translating(unitBox<double>(), Vector3<double>(3, 0, 0), Vector3<double>(-2, 0, 0));
  ExtrusionCache<double> stale = cache;
  const auto third = extrusionTest(P, R, 0.0, 2.0, {}, &stale);
  CHECK(third.status == ExtrusionStatus::Undecided);
  CHECK_FALSE(third.usedRememberedVector);
  CHECK(third.gjkIterations > 0);
  CHECK_FALSE(stale.valid);
}

// CollidingAtStart: overlapping at t0, and also merely within the tolerance at t0.
TEST_CASE("bodies within the tolerance at t0 are colliding at start", "[extrusion]") {
  const auto P = fixedAt(unitBox<double>(), Vector3<double>(0, 0, 0));
  const auto overlapping = translating(unitBox<double>(), Vector3<double>(0.5, 0.2, 0.1), Vector3<double>(5, 0, 0));
  CHECK(extrusionTest(P, overlapping, 0.0, 1.0).status == ExtrusionStatus::CollidingAtStart);

  const double tol = 1e-6;
  ExtrusionSettings<double> settings;
  settings.collisionTolerance = tol;
  // Gap 0.5 tol along x at t0, moving away: still "colliding at start" for the
  // extrusion test, which judges only t0 (the time-of-impact solver decides it is separating).
  const auto close = translating(unitBox<double>(), Vector3<double>(1 + 0.5 * tol, 0, 0), Vector3<double>(1, 0, 0));
  const auto r = extrusionTest(P, close, 0.0, 1.0, settings);
  CHECK(r.status == ExtrusionStatus::CollidingAtStart);
  CHECK(r.distanceAtStart == Approx(0.5 * tol).margin(1e-12));
  // Gap 2 tol: not within the tolerance, and moving away: no collision.
  const auto apart = translating(unitBox<double>(), Vector3<double>(1 + 2 * tol, 0, 0), Vector3<double>(1, 0, 0));
  CHECK(extrusionTest(P, apart, 0.0, 1.0, settings).status == ExtrusionStatus::NoCollision);
}

TEST_CASE("touching bodies on which GJK stalls are not declared free of contact (fuzz finding)", "[extrusion][stall]") {
  // The needle slab (tests/gjk/needle_slab.hpp), at rest: a triangle 1.4e6 long and 1e-4
  // thick touching a segment at a shared vertex. GJK at t0 stalls at 1e-4, above the
  // tolerance, with its lower bound below 0: no vector separates, so the test cannot say
  // "no collision", and it says that its distance at t0 is only an upper bound.
  const auto P = fixedAt(test::needle(1e6, 1e-4), Vector3<double>::Zero());
  const auto Q = fixedAt(test::segmentTo(1e6, 0.5), Vector3<double>::Zero());
  const auto r = extrusionTest(P, Q, 0.0, 1.0);
  INFO(toString(r.status) << ", GJK " << toString(r.gjkStatus) << " at " << r.distanceAtStart);
  CHECK(r.status != ExtrusionStatus::NoCollision);
  CHECK(r.gjkStatus == GjkStatus::Stalled);
  CHECK(r.distanceAtStart >= 0.0);
}

// The certified margin m = Δ²/8 (D_P + D_Q), with D = a + α r + ω² r (certified_margin.hpp),
// is what the result reports: for a screw motion D = ω² r (r: the bounding radius about
// the body origin); for linear motion and per-vertex linear motion it is 0; the paper's
// variant asks for no margin at all.
TEST_CASE("the certified margin is Δ²/8 (D_P + D_Q)", "[extrusion][certified]") {
  const Box<double> box(Vector3<double>(1, 0.5, 0.25));  // r = |h| = sqrt(1.3125)
  const double r = std::sqrt(1.0 + 0.25 + 0.0625);
  const double omegaP = 2.0, omegaQ = 3.0;
  const auto P = moving(box, Motion<double>::screw(Pose<double>::identity(), Vector3<double>(0.1, 0, 0),
                                                   Vector3<double>(0, 0, omegaP)));
  const auto Q = moving(box, Motion<double>::screw(Pose<double>::translate({10, 0, 0}), Vector3<double>(0, 0.2, 0),
                                                   Vector3<double>(omegaQ, 0, 0)));
  CHECK(P.accelerationBound() == Approx(omegaP * omegaP * r).epsilon(1e-14));
  CHECK(Q.accelerationBound() == Approx(omegaQ * omegaQ * r).epsilon(1e-14));

  ExtrusionSettings<double> certified;
  certified.variant = ExtrusionVariant::Certified;
  for (const auto& interval : {std::pair<double, double>{0.0, 1.0}, {0.5, 0.75}, {2.0, 2.1}}) {
    const double delta = interval.second - interval.first;
    const double expected = delta * delta / 8 * (omegaP * omegaP * r + omegaQ * omegaQ * r);
    const auto result = extrusionTest(P, Q, interval.first, interval.second, certified);
    CHECK(result.margin == Approx(expected).epsilon(1e-14));
    CHECK(extrusionMargin(ExtrusionVariant::Certified, delta, P.accelerationBound(), Q.accelerationBound()) ==
          Approx(expected).epsilon(1e-14));
    // The paper's variant asks for none.
    CHECK(extrusionTest(P, Q, interval.first, interval.second).margin == 0.0);
  }

  // Linear motion: no margin, even for the certified variant.
  const auto A = translating(box, Vector3<double>(0, 0, 0), Vector3<double>(1, 2, 3));
  const auto B = translating(box, Vector3<double>(5, 0, 0), Vector3<double>(-1, 0, 0));
  CHECK(extrusionTest(A, B, 0.0, 1.0, certified).margin == 0.0);
  // Per-vertex linear motion (DeformingSimplex): no margin either.
  using V = Vector3<double>;
  const DeformingSimplex<double> tri({V(0, 0, 0), V(1, 0, 0), V(0, 1, 0)}, {V(0, 0, 1), V(2, 0, 1), V(0, 1, 3)});
  const DeformingSimplex<double> point({V(5, 5, 5)}, {V(5, 5, -5)});
  CHECK(tri.accelerationBound() == 0.0);
  CHECK(extrusionTest(tri, point, 0.0, 1.0, certified).margin == 0.0);
}

TEST_CASE("the lowest supporting distance under the margin's parabola", "[extrusion][certified]") {
  // Paper variant: no margin, the chord's lower end.
  CHECK(lowestSupportingDistance(ExtrusionVariant::Paper, 0.3, 0.1, 1.0, 5.0, 5.0) == 0.1);
  CHECK(lowestSupportingDistance(ExtrusionVariant::Paper, 1e-6, 2.0, 1.0, 5.0, 5.0) == 1e-6);
  // Certified: the least of g(τ) = sd0 + (sd1 - sd0)τ - c τ(1 - τ), c = Δ²/2 (D_P + D_Q),
  // against a dense sampling of g, on rising, falling and flat chords.
  const double D = 0.4 + 0.6, delta = 0.5, c = delta * delta / 2 * D;
  for (const auto& ends : {std::pair<double, double>{1e-6, 1.0}, {1e-6, 0.01}, {0.2, 0.2}, {0.3, -0.1}, {0.0, 0.5}}) {
    double least = std::min(ends.first, ends.second);
    for (int k = 0; k <= 100000; ++k) {
      const double tau = k / 100000.0;
      least = std::min(least, ends.first + (ends.second - ends.first) * tau - c * tau * (1 - tau));
    }
    INFO("sd0 " << ends.first << " sd1 " << ends.second);
    CHECK(lowestSupportingDistance(ExtrusionVariant::Certified, ends.first, ends.second, delta, 0.4, 0.6) ==
          Approx(least).margin(1e-9));
  }
  // Rising faster than c: the margin never bites, the bodies stay at least sd0 apart, where
  // the flat bound min(sd0, sd1) - c/4 would be negative.
  CHECK(lowestSupportingDistance(ExtrusionVariant::Certified, 1e-6, 1.0, delta, 0.4, 0.6) == 1e-6);
  CHECK(1e-6 - extrusionMargin(ExtrusionVariant::Certified, delta, 0.4, 0.6) < 0);
}

// Under fast rotation the paper's test accepts a vector the certified test declines.
// P: a thin rod (box of half extents (2, 0.05, 0.05)) at the origin turning a half turn
// about z over [0, 1] (ω = π). Q: a sphere of radius 0.5 fixed at (0, 1.5, 0).
// At t0 and t1 the rod lies along x (a half turn maps the box onto itself), so s_0 = +y
// gives SD = 1.5 - 0.5 - 0.05 = 0.95 at both ends, and the paper's test says "no
// collision" at step 0. Yet at t = 1/2 the rod points along y and runs through the
// sphere. The certified test asks SD > tol + m with m = π² r/8 = 2.47 (r = |h| = 2.0012):
// 0.95 is not enough, so it declines the vector and stays undecided.
TEST_CASE("the certified test declines a vector the paper's test accepts under fast rotation",
          "[extrusion][certified][hand]") {
  const Box<double> rod(Vector3<double>(2, 0.05, 0.05));
  const auto P = moving(rod, Motion<double>::screw(Pose<double>::identity(), Vector3<double>::Zero(),
                                                   Vector3<double>(0, 0, kPi)));
  const auto Q = fixedAt(Sphere<double>(0.5), Vector3<double>(0, 1.5, 0));
  // The collision the paper's test misses is real: at t = 1/2 the rod crosses the sphere.
  CHECK(intersect(P.at(0.5), Q.at(0.5)).status == IntersectionStatus::Intersecting);

  ExtrusionTrace<double> paperTrace;
  const auto paper = extrusionTest(P, Q, 0.0, 1.0, {}, nullptr, paperTrace);
  CHECK(paper.status == ExtrusionStatus::NoCollision);
  REQUIRE(paperTrace.steps.size() == 1);
  CHECK(paperTrace.steps[0].s.isApprox(Vector3<double>(0, 1, 0), 1e-12));
  CHECK(paperTrace.steps[0].sdStart == Approx(0.95).epsilon(1e-12));
  CHECK(paperTrace.steps[0].sdEnd == Approx(0.95).epsilon(1e-12));

  ExtrusionSettings<double> settings;
  settings.variant = ExtrusionVariant::Certified;
  ExtrusionTrace<double> certifiedTrace;
  const auto certified = extrusionTest(P, Q, 0.0, 1.0, settings, nullptr, certifiedTrace);
  const double r = std::sqrt(4 + 0.0025 + 0.0025);
  CHECK(certified.margin == Approx(kPi * kPi * r / 8).epsilon(1e-12));
  CHECK(certified.status == ExtrusionStatus::Undecided);
  REQUIRE_FALSE(certifiedTrace.steps.empty());
  CHECK(certifiedTrace.steps[0].s.isApprox(Vector3<double>(0, 1, 0), 1e-12));
  CHECK(certifiedTrace.steps[0].separatesStart);   // it does separate at t0...
  CHECK_FALSE(certifiedTrace.steps[0].separatesEnd);  // ...but not by the margin
  for (const auto& step : certifiedTrace.steps) CHECK_FALSE(step.separatesEnd);
  // The stored vectors are still there for §5 (they separate at t0).
  CHECK(certified.separating.count >= 1);
}

// §1's complaint about the sweeping test, and Fig. 1's about the static test.
//
// Sweeping false alarm: two unit boxes whose paths cross at the origin at different
// times. Q sits at the origin at t0 and leaves towards (2.5, 1.5, 0); P arrives at the
// origin at t1 from (-2, -2, 0). Both swept hulls contain the unit box at the origin, so
// the sweeping test reports an intersection, but they never meet: along
// s = (1, 1, 0)/sqrt(2) (the first GJK direction, c_Q - c_P = (2, 2, 0) at t0)
//   t0: S_P(s) = (-1.5, -1.5, 0.5), S_Q(-s) = (-0.5, -0.5, 0.5): SD = 2/sqrt(2) = sqrt(2);
//   t1: S_P(s) = (0.5, 0.5, 0.5),   S_Q(-s) = (2, 1, 0.5):       SD = 2/sqrt(2) = sqrt(2).
// The extrusion test proves no collision at step 0.
TEST_CASE("the sweeping test gives a false alarm where the extrusion test is right", "[extrusion][sweeping]") {
  const auto P = translating(unitBox<double>(), Vector3<double>(-2, -2, 0), Vector3<double>(2, 2, 0));
  const auto Q = translating(unitBox<double>(), Vector3<double>(0, 0, 0), Vector3<double>(2.5, 1.5, 0));
  CHECK(sweepingTest(P, Q, 0.0, 1.0).status == IntersectionStatus::Intersecting);  // false alarm
  CHECK_FALSE(staticTest(P, Q, 0.0, 1.0, 101));  // c_Q - c_P = (2 + t/2, 2 - t/2, 0): never within 1 in x
  ExtrusionTrace<double> trace;
  const auto r = extrusionTest(P, Q, 0.0, 1.0, {}, nullptr, trace);
  CHECK(r.status == ExtrusionStatus::NoCollision);
  REQUIRE(trace.steps.size() == 1);
  CHECK(trace.steps[0].sdStart == Approx(std::sqrt(2.0)).epsilon(1e-14));
  CHECK(trace.steps[0].sdEnd == Approx(std::sqrt(2.0)).epsilon(1e-14));
  CHECK(r.separatingVector.isApprox(Vector3<double>(1, 1, 0) / std::sqrt(2.0), 1e-14));
  // The swept hulls do overlap: both contain the box at the origin.
  const auto hullP = sweptHull(P, 0.0, 1.0), hullQ = sweptHull(Q, 0.0, 1.0);
  CHECK(hullP.support(Vector3<double>(1, 1, 0)).isApprox(Vector3<double>(0.5, 0.5, 0.5)));
  CHECK(hullQ.support(Vector3<double>(-1, -1, 0)).isApprox(Vector3<double>(-0.5, -0.5, 0.5)));
}

// Static miss: a small sphere (r = 0.1) crosses a thin plate (half thickness 0.01) from
// x = -2 to x = 2 in one interval. At the ends (and at 10 samples: x = -2 + 4k/9, never
// within 0.11 of the plate) the static test sees it apart. The sweeping test and the
// extrusion test are right: along s_0 = -x (c_Q - c_P at t0), SD(t0) = 2 - 0.1 - 0.01 = 1.89
// but SD(t1) = -2 - 0.1 - 0.01 = -2.11, and no vector separates both ends, because none exists.
TEST_CASE("the static test misses a thin fast pass-through where the extrusion test is right",
          "[extrusion][static]") {
  const auto plate = fixedAt(Box<double>(Vector3<double>(0.01, 1, 1)), Vector3<double>(0, 0, 0));
  const auto bullet = translating(Sphere<double>(0.1), Vector3<double>(-2, 0, 0), Vector3<double>(4, 0, 0));
  CHECK_FALSE(staticTest(plate, bullet, 0.0, 1.0));      // 2 samples
  CHECK_FALSE(staticTest(plate, bullet, 0.0, 1.0, 10));  // 10 samples
  CHECK(sweepingTest(plate, bullet, 0.0, 1.0).status == IntersectionStatus::Intersecting);
  ExtrusionTrace<double> trace;
  const auto r = extrusionTest(plate, bullet, 0.0, 1.0, {}, nullptr, trace);
  CHECK(r.status == ExtrusionStatus::Undecided);
  REQUIRE_FALSE(trace.steps.empty());
  CHECK(trace.steps[0].s.isApprox(Vector3<double>(-1, 0, 0), 1e-14));
  CHECK(trace.steps[0].sdStart == Approx(1.89).epsilon(1e-14));
  CHECK(trace.steps[0].sdEnd == Approx(-2.11).epsilon(1e-14));
  for (const auto& step : trace.steps) CHECK_FALSE(step.separatesEnd);
  CHECK(staticTest(plate, bullet, 0.0, 1.0, 101));  // dense enough sampling does see it (x = 0 at k = 50)
}

// The static test's sample count is checked.
TEST_CASE("staticTest refuses fewer than two samples", "[extrusion][static][input]") {
  const auto P = fixedAt(unitBox<double>(), Vector3<double>(0, 0, 0));
  CHECK_THROWS_WITH(staticTest(P, P, 0.0, 1.0, 1), Catch::Matchers::StartsWith("staticTest.samples"));
}

// The extrusion test runs in float too, with float's tolerance sqrt(eps) = 3.5e-4.
TEST_CASE("the extrusion test in float: the box passing above", "[extrusion][float]") {
  const auto P = fixedAt(unitBox<float>(), Vector3<float>(0, 0, 0));
  const auto Q = translating(unitBox<float>(), Vector3<float>(1, 1.5f, 0), Vector3<float>(-2, 0, 0));
  const auto r = extrusionTest(P, Q, 0.0f, 1.0f);
  CHECK(r.status == ExtrusionStatus::NoCollision);
  CHECK(r.separatingVector.isApprox(Vector3<float>(0, 1, 0), 1e-6f));
  const auto R = translating(unitBox<float>(), Vector3<float>(3, 0, 0), Vector3<float>(-4, 0, 0));
  CHECK(extrusionTest(P, R, 0.0f, 1.0f).status == ExtrusionStatus::Undecided);
}

TEST_CASE("the extrusion test takes a rigid body and a deforming simplex together (fuzz finding)",
          "[extrusion][deforming]") {
  // Found by tests/fuzz/fuzz_extrusion: extrusionTest(P, Q, ...) with P a Moving<Box> and Q
  // a DeformingSimplex did not compile (their at(t) return different types, and one `auto`
  // declaration held both). A unit box fixed at the origin; a point falling from (0, 3, 0)
  // to (0, 2, 0): SD along +y is 2.5 - 0.5 = 2 at t0 and 1.5 at t1, no collision; falling
  // to (0, 0, 0) instead, it ends inside the box: undecided.
  using V = Vector3<double>;
  const auto box = fixedAt(unitBox<double>(), V::Zero());
  const DeformingSimplex<double> slow({V(0, 3, 0)}, {V(0, 2, 0)});
  const ExtrusionResult<double> apart = extrusionTest(box, slow, 0.0, 1.0);
  CHECK(apart.status == ExtrusionStatus::NoCollision);
  CHECK(extrusionTest(slow, box, 0.0, 1.0).status == ExtrusionStatus::NoCollision);
  const DeformingSimplex<double> fast({V(0, 3, 0)}, {V(0, 0, 0)});
  CHECK(extrusionTest(box, fast, 0.0, 1.0).status == ExtrusionStatus::Undecided);
}

// What the time-of-impact solver relies on when it runs many tests on [t_x, t1] (§5):
// - `extrusionTestPlaced` on the bodies placed at both ends is `extrusionTest`;
// - each stored vector's hints are where its supports at t1 are: a search started there
//   does not move, and gives the stored SD(t1);
// - an ExtrusionCache carried from one test to the next (GJK's warm start, the hints at
//   t1) changes no verdict and no distance beyond GJK's tolerance.
// On two polytopes turning and closing in (a screw motion each), tested on [t, 1] for t
// stepping towards the contact, as the solver's restarts do.
TEST_CASE("tests on [t, t1] with the bodies placed once, hints kept per vector and a cache carried along",
          "[extrusion][cache][hints]") {
  using V = Vector3<double>;
  std::mt19937 rng(5);
  std::normal_distribution<double> normal(0, 1);
  auto cloud = [&](int n, double size) {
    std::vector<V> points;
    for (int k = 0; k < n; ++k) points.push_back(V(normal(rng), normal(rng), normal(rng)).normalized() * size);
    return Polytope<double>::hull(points);
  };
  const auto P = moving(cloud(200, 0.5), Motion<double>::screw(Pose<double>::identity(), V(0, 0, 0), V(0, 0, 1.5)));
  const auto Q = moving(cloud(60, 0.4), Motion<double>::screw(Pose<double>::translate(V(2.5, 0.2, 0.1)), V(-3, 0, 0),
                                                              V(1, 0.5, 0)));
  const double t1 = 1;
  const auto P1 = P.at(t1);
  const auto Q1 = Q.at(t1);
  ExtrusionSettings<double> settings;
  ExtrusionCache<double> cache;
  int undecided = 0;
  for (double t = 0; t < 0.55; t += 0.05) {
    INFO("interval [" << t << ", 1]");
    const auto cold = extrusionTest(P, Q, t, t1, settings);
    const auto placed = extrusionTestPlaced(P.at(t), Q.at(t), P1, Q1, 0.0, settings);
    CHECK(placed.status == cold.status);
    CHECK(placed.distanceAtStart == cold.distanceAtStart);
    CHECK(placed.separating.count == cold.separating.count);
    const auto warm = extrusionTestPlaced(P.at(t), Q.at(t), P1, Q1, 0.0, settings, &cache);
    CHECK(warm.status == cold.status);
    CHECK(warm.distanceAtStart == Approx(cold.distanceAtStart).epsilon(1e-9));
    undecided += warm.status == ExtrusionStatus::Undecided;
    for (const auto* r : {&cold, &warm}) {
      for (int k = 0; k < r->separating.count; ++k) {
        SupportHint hintP = r->separating.hintP[k], hintQ = r->separating.hintQ[k];
        const SupportHint storedP = hintP, storedQ = hintQ;
        CHECK(supportingDistance(P1, Q1, r->separating.vectors[k], hintP, hintQ) == r->separating.sdEnd[k]);
        CHECK(hintP == storedP);
        CHECK(hintQ == storedQ);
      }
    }
  }
  CHECK(undecided >= 5);  // the intervals do reach the contact
}
