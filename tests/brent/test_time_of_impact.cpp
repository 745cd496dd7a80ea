// The time-of-impact solver of §5 (the extrusion test of §3 driven by Brent's method):
// the hand-checked cases, whose time of impact and first Brent iterates are derived in
// the comments, and the field's hard cases (starting inside the tolerance, spinning rods,
// a half turn per interval, very fast approach, tunnelling, the iteration cap, bad input).
// The random workloads against an independent reference are in
// test_time_of_impact_random.cpp.
#include "toi_test_support.hpp"

#include <gjkx/brent/time_of_impact.hpp>
#include <gjkx/support_mapping/placed.hpp>
#include <gjkx/support_mapping/shape.hpp>

#include <catch2/catch.hpp>

#include <cmath>
#include <iostream>
#include <random>
#include <string>
#include <vector>

using namespace gjkx;
using namespace gjkx::toi_test;

// =======================================================================================
// Hand-checked cases.

// Boxes approaching head-on at constant speed 4. P: unit box at the origin, fixed. Q: unit
// box from (3, 0, 0), velocity (-4, 0, 0). The gap is 2 - 4t, so the bodies come within the
// tolerance at t* = (2 - tol)/4. The extrusion test fails (SD(+x) = 2 at t0, -2 at t1);
// F(t) = SD(+x, t) - tol = 2 - 4t - tol is linear, so Brent's first step, a secant through
// (0, 2 - tol) and (1, -2 - tol), lands on t* itself:
//   t_x = 0 - (2 - tol)(0 - 1) / ((2 - tol) - (-2 - tol)) = (2 - tol)/4,
// where the stored vector gives SD = tol (up to round-off): t* is bracketed, and the
// time of impact is t* within the time tolerance, with normal +x and the bodies within
// the tolerance there.
TEMPLATE_TEST_CASE("time of impact, by hand: boxes approaching head-on", "[toi][hand]", float, double) {
  using S = TestType;
  const auto P = fixedAt(unitBox<S>(), Vector3<S>(0, 0, 0));
  const auto Q = translating(unitBox<S>(), Vector3<S>(3, 0, 0), Vector3<S>(-4, 0, 0));
  ToiSettings<S> settings;
  const S tol = settings.collisionTolerance;
  const S timeTol = settings.timeTolerance;
  ToiTrace<S> trace;
  const auto r = timeOfImpact(P, Q, S(0), S(1), settings, &trace);
  const double expected = (2.0 - double(tol)) / 4.0;
  INFO(scalarName<S>() << ": status " << toString(r.status) << ", time " << r.time << ", expected " << expected);
  REQUIRE(r.status == ToiStatus::Hit);
  CHECK(std::abs(double(r.time) - expected) <= double(tol) / 4 + double(timeTol));
  CHECK(r.normal.isApprox(Vector3<S>(1, 0, 0), S(1e-5)));
  CHECK(r.distance <= tol * S(1.001));
  CHECK(r.distance > S(0));
  CHECK(r.witnessQ.x() - r.witnessP.x() == Approx(double(r.distance)).margin(1e-5));

  // The trace: one failed test over [0, 1], then the secant step.
  REQUIRE(trace.intervals.size() >= 1);
  CHECK(trace.intervals[0].start == S(0));
  CHECK(trace.intervals[0].status == ExtrusionStatus::Undecided);
  CHECK(trace.intervals[0].distanceAtStart == Approx(2.0).epsilon(1e-6));
  REQUIRE(trace.steps.size() >= 1);
  CHECK(trace.steps[0].kind == BrentStepKind::Secant);
  CHECK(double(trace.steps[0].t) == Approx(expected).epsilon(1e-6));
  CHECK(trace.steps[0].bracketLow == S(0));
  CHECK(trace.steps[0].bracketHigh == S(1));
  CHECK(double(trace.steps[0].approximateMaxSd) == Approx(double(tol)).margin(1e-6));
  // SD = tol at t_x up to round-off: whether it counts as separating there (and a complete
  // test follows at t_x itself) is decided by the last bit; either way the hit is at t*.
  CHECK(trace.steps[0].completeTest == (trace.steps[0].approximateMaxSd >= tol));
  CHECK(r.brentIterations == static_cast<int>(trace.steps.size()));
  std::cout << "TOI head-on (" << scalarName<S>() << "): brent=" << r.brentIterations << " gjk=" << r.gjkRuns
            << " time=" << r.time << " expected=" << expected << "\n";
}

// The same in double with the tolerance 2^-10: every number in the first step is now a
// short dyadic fraction, so the trace can be checked to round-off: t_x = 1/2 - 2^-12,
// Q's face then at 3 - 4 t_x - 1/2 = 1/2 + 2^-10, SD = 2^-10 = tol, and the complete test
// at t_x reports the bodies within the tolerance: a hit at t_x after one Brent step.
TEST_CASE("time of impact, by hand: the head-on trace with a dyadic tolerance", "[toi][hand]") {
  const auto P = fixedAt(unitBox<double>(), Vector3<double>(0, 0, 0));
  const auto Q = translating(unitBox<double>(), Vector3<double>(3, 0, 0), Vector3<double>(-4, 0, 0));
  ToiSettings<double> settings;
  settings.collisionTolerance = 1.0 / 1024;
  ToiTrace<double> trace;
  const auto r = timeOfImpact(P, Q, 0.0, 1.0, settings, &trace);
  REQUIRE(r.status == ToiStatus::Hit);
  REQUIRE(trace.steps.size() == 1);
  CHECK(trace.steps[0].t == Approx(0.5 - 1.0 / 4096).epsilon(1e-15));
  CHECK(trace.steps[0].approximateMaxSd == Approx(1.0 / 1024).epsilon(1e-12));
  REQUIRE(trace.intervals.size() == 2);
  CHECK(trace.intervals[1].start == trace.steps[0].t);
  CHECK(trace.intervals[1].status == ExtrusionStatus::CollidingAtStart);
  CHECK(r.time == trace.steps[0].t);
  CHECK(r.distance == Approx(1.0 / 1024).epsilon(1e-12));
  CHECK(r.brentIterations == 1);
  CHECK(r.gjkRuns == 2);
  CHECK(r.restarts == 1);
}

// A near miss: Q passes above P at a gap of 0.1 (Q from (3, 1.1, 0), velocity (-6, 0, 0)).
// No collision; the solver may prove it at once or by a photo finish.
TEMPLATE_TEST_CASE("time of impact, by hand: a near miss at 0.1", "[toi][hand]", float, double) {
  using S = TestType;
  const auto P = fixedAt(unitBox<S>(), Vector3<S>(0, 0, 0));
  const auto Q = translating(unitBox<S>(), Vector3<S>(3, S(1.1), 0), Vector3<S>(-6, 0, 0));
  const auto r = timeOfImpact(P, Q, S(0), S(1));
  INFO("status " << toString(r.status));
  CHECK((r.status == ToiStatus::NoCollision || r.status == ToiStatus::PhotoFinish));
  CHECK_FALSE(reportsCollision(r.status));
}

// The Brent iterates step by step, on a pass where the stored vectors mislead.
// P: unit box at the origin. Q: unit box from (3, 1.5, 0), velocity (-6, 0, 0): it passes
// above P with a gap of 1/2 and never collides. The first extrusion test (see
// tests/extrusion/test_extrusion.cpp, "undecided ... separating vectors") stores
//   s_0 = (2, 1, 0)/sqrt(5):  SD_0(t) = (2 (2 - 6t) + 0.5)/sqrt(5) = (4.5 - 12 t)/sqrt(5),
//   s_1 = (4, 1, 0)/sqrt(17): SD_1(t) = (4 (2 - 6t) + 0.5)/sqrt(17) = (8.5 - 24 t)/sqrt(17),
// with distance d0 = sqrt(4.25) at t0. F(0) = d0 - tol, F(1) = max_k SD_k(1) - tol =
// -7.5/sqrt(5) - tol. |F(0)| < |F(1)|, so Brent's best estimate is b = 0, and the first
// step is the secant
//   t_1 = F(0) / (F(0) - F(1)) = (sqrt(4.25) - tol) / (sqrt(4.25) + 7.5/sqrt(5)) = 2.06155/5.41566 = 0.380665...
// There SD_0 = (4.5 - 12 t_1)/sqrt(5) = -0.0304 and SD_1 < SD_0: no stored vector
// separates, Brent goes on. Now f(t_1) < 0 has the sign of f(1), so the bracket becomes
// [0, t_1] and the second step is the secant through (0, F(0)) and (t_1, F(t_1)):
//   t_2 = t_1 - F(t_1) t_1 / (F(t_1) - F(0)) = 0.375133...
// still just past the root of SD_0 (t = 0.375). Brent then closes in from the right until
// an iterate t_x < 0.375 has SD_0(t_x) > 0: a complete test at t_x finds +y, which
// separates [t_x, 1] (SD = 1/2 at both ends): a photo finish.
TEST_CASE("time of impact, step by step: Brent's iterates on a pass above", "[toi][hand]") {
  const auto P = fixedAt(unitBox<double>(), Vector3<double>(0, 0, 0));
  const auto Q = translating(unitBox<double>(), Vector3<double>(3, 1.5, 0), Vector3<double>(-6, 0, 0));
  ToiSettings<double> settings;
  const double tol = settings.collisionTolerance;
  ToiTrace<double> trace;
  const auto r = timeOfImpact(P, Q, 0.0, 1.0, settings, &trace);

  REQUIRE(r.status == ToiStatus::PhotoFinish);
  const double d0 = std::sqrt(4.25);
  const double F0 = d0 - tol, F1 = -7.5 / std::sqrt(5.0) - tol;
  const auto sd0 = [](double t) { return (4.5 - 12 * t) / std::sqrt(5.0); };
  const double t1 = F0 / (F0 - F1);
  const double Ft1 = sd0(t1) - tol;
  const double t2 = t1 - Ft1 * t1 / (Ft1 - F0);
  REQUIRE(trace.steps.size() >= 3);
  CHECK(trace.steps[0].kind == BrentStepKind::Secant);
  CHECK(trace.steps[0].t == Approx(t1).epsilon(1e-12));
  CHECK(trace.steps[0].t == Approx(0.380665).epsilon(1e-5));
  CHECK(trace.steps[0].approximateMaxSd == Approx(sd0(t1)).epsilon(1e-10));
  CHECK_FALSE(trace.steps[0].completeTest);
  CHECK(trace.steps[0].bracketLow == 0.0);
  CHECK(trace.steps[0].bracketHigh == 1.0);
  CHECK(trace.steps[1].kind == BrentStepKind::Secant);
  CHECK(trace.steps[1].t == Approx(t2).epsilon(1e-12));
  CHECK(trace.steps[1].t == Approx(0.375133).epsilon(1e-5));
  CHECK(trace.steps[1].bracketHigh == Approx(t1).epsilon(1e-15));
  // Every iterate lies in its bracket; the last one is the complete test at t_x < 0.375.
  for (const auto& step : trace.steps) {
    CHECK(step.t >= step.bracketLow);
    CHECK(step.t <= step.bracketHigh);
  }
  const auto& last = trace.steps.back();
  CHECK(last.completeTest);
  CHECK(last.t < 0.375);
  CHECK(last.approximateMaxSd > 0);
  REQUIRE(trace.intervals.size() == 2);
  CHECK(trace.intervals[1].start == last.t);
  CHECK(trace.intervals[1].status == ExtrusionStatus::NoCollision);
  CHECK(trace.intervals[1].distanceAtStart == Approx(0.5).epsilon(1e-12));
  CHECK(r.restarts == 1);
  CHECK(r.gjkRuns == 2);
  std::cout << "TOI pass-above step by step: brent=" << r.brentIterations << " iterates:";
  for (const auto& step : trace.steps) std::cout << " " << step.t << "(" << toString(step.kind) << ")";
  std::cout << "\n";
}

// A unit box falling onto the floor under gravity (g = 10), from rest or thrown down at v0,
// drifting sideways at 0.3: its bottom is at gap(t) = 2 - v0 t - 5 t^2 above the floor's
// top face, so the bodies come within the tolerance at
//   t* = (-v0 + sqrt(v0^2 + 20 (2 - tol))) / 10.
// The motion is a translation, so along the floor's normal +z the supporting distance is
// the gap itself, and F(t) = gap(t) - tol bends down, away from its chord: every secant
// from a restart towards t1 lands short of t*, where F is still positive, and a restart
// follows. Started afresh from [t_x, t1] each time, the solver crept towards t* like
// regula falsi (14 to 19 complete tests in double); with the far end taken from the
// nearest point known below the tolerance, and from the second restart on the probe at
// the parabola through the last three exact distances (exact for this quadratic gap),
// it closes in within 6 complete tests.
TEMPLATE_TEST_CASE("time of impact, by hand: a box falling onto the floor under gravity", "[toi][hand][accelerating]",
                   float, double) {
  using S = TestType;
  using V = Vector3<S>;
  const auto floor = fixedAt(Box<S>(V(5, 5, S(0.5))), V(0, 0, S(-0.5)));
  for (const double v0 : {0.0, 1.0, 2.0}) {
    for (const ExtrusionVariant variant : {ExtrusionVariant::Paper, ExtrusionVariant::Certified}) {
      const auto box = moving(unitBox<S>(), Motion<S>::constantAcceleration(Pose<S>::translate(V(0, 0, S(2.5))),
                                                                            V(S(0.3), 0, S(-v0)), V(0, 0, -10)));
      ToiSettings<S> settings;
      settings.variant = variant;
      const double tol = settings.collisionTolerance, timeTol = settings.timeTolerance;
      const auto r = timeOfImpact(box, floor, S(0), S(1), settings);
      const double expected = (-v0 + std::sqrt(v0 * v0 + 20 * (2 - tol))) / 10;
      const double T = double(r.time), gap = 2 - v0 * T - 5 * T * T, speed = v0 + 10 * expected;
      const double roundoff = sizeof(S) == sizeof(float) ? 2e-5 : 1e-12;
      INFO(scalarName<S>() << ", v0 " << v0 << ", " << toString(variant) << ": " << toString(r.status) << " at " << T
                           << ", expected " << expected << ", gap " << gap << ", complete tests " << r.gjkRuns);
      REQUIRE(r.status == ToiStatus::Hit);
      CHECK(T <= expected + timeTol);                  // no later than the first time within tol
      CHECK(gap > 0);                                  // and never inside the floor
      CHECK(gap <= tol + speed * timeTol + roundoff);  // nor earlier than the time tolerance allows
      // From the box down to the floor (in float, the witnesses' rounding, 1e-7 of the
      // coordinates, tilts a normal measured across a gap of 3e-4 by about 1e-3).
      CHECK(r.normal.isApprox(V(0, 0, -1), sizeof(S) == sizeof(float) ? S(1e-2) : S(1e-6)));
      CHECK(r.gjkRuns <= 9);
    }
  }
}


TEMPLATE_TEST_CASE("starting inside the tolerance: separating or starts-penetrating", "[toi][hard]", float, double) {
  using S = TestType;
  const S tol = defaultCollisionTolerance<S>();
  const auto P = fixedAt(unitBox<S>(), Vector3<S>(0, 0, 0));
  const Vector3<S> touching(1 + tol / 2, 0, 0);  // gap tol/2 along x
  const auto apart = timeOfImpact(P, translating(unitBox<S>(), touching, Vector3<S>(1, S(0.5), 0)), S(0), S(1));
  CHECK(apart.status == ToiStatus::Separating);
  CHECK_FALSE(reportsCollision(apart.status));
  CHECK(apart.time == S(0));
  CHECK(apart.normal.isApprox(Vector3<S>(1, 0, 0), S(1e-4)));

  const auto closing = timeOfImpact(P, translating(unitBox<S>(), touching, Vector3<S>(-1, 0, 0)), S(0), S(1));
  CHECK(closing.status == ToiStatus::StartsPenetrating);
  CHECK(closing.time == S(0));
  CHECK(reportsCollision(closing.status));

  // Sliding along the face at the same gap: SD(+x) stays tol/2 > 0, so they never touch;
  // the solver calls this "separating" too (no new contact), though the gap stays tol/2.
  const auto sliding = timeOfImpact(P, translating(unitBox<S>(), touching, Vector3<S>(0, 1, 0)), S(0), S(1));
  CHECK(sliding.status == ToiStatus::Separating);

  const auto overlapping =
      timeOfImpact(P, translating(unitBox<S>(), Vector3<S>(S(0.5), 0, 0), Vector3<S>(5, 0, 0)), S(0), S(1));
  CHECK(overlapping.status == ToiStatus::StartsPenetrating);
}

// A thin rod spinning in place next to a small sphere. P: box of half extents
// (2, 0.05, 0.05) at the origin, turning about z at w = π (a half turn per interval),
// along x at t0. Q: a sphere of radius 0.2 fixed at (0, 1.5, 0). When the rod has turned
// by θ, the sphere's centre lies at 1.5 cos θ from the rod's axis (and 1.5 sin θ <= 2
// along it, so the nearest point is on the rod's long face): the distance is
// 1.5 cos θ - 0.05 - 0.2, which reaches tol at θ* = acos((0.25 + tol)/1.5), i.e. at
// t* = θ*/π = 0.4467. The face approaches the sphere at 1.5 sin θ* π = 4.65 per unit time.
// The certified variant finds the hit; the paper's sees the same configuration at t0
// and t1 (SD(+y) = 1.25 at both) and says "no collision", the miss §3 warns of.
TEMPLATE_TEST_CASE("a thin rod spinning next to a small sphere", "[toi][hard][rotation]", float, double) {
  using S = TestType;
  const auto rod = spinning(Box<S>(Vector3<S>(2, S(0.05), S(0.05))), Vector3<S>(0, 0, 0), Vector3<S>(0, 0, S(kPi)));
  const auto ball = fixedAt(Sphere<S>(S(0.2)), Vector3<S>(0, S(1.5), 0));
  ToiSettings<S> settings;
  settings.variant = ExtrusionVariant::Certified;
  const double tol = settings.collisionTolerance, timeTol = settings.timeTolerance;
  const double thetaStar = std::acos((0.25 + tol) / 1.5);
  const double tStar = thetaStar / kPi, speed = 1.5 * std::sin(thetaStar) * kPi;
  const auto certified = timeOfImpact(rod, ball, S(0), S(1), settings);
  INFO(scalarName<S>() << " certified: " << toString(certified.status) << " at " << certified.time << ", expected "
                       << tStar);
  REQUIRE(certified.status == ToiStatus::Hit);
  CHECK(double(certified.time) <= tStar + timeTol);
  CHECK(double(certified.time) >= tStar - tol / speed - 2 * timeTol);
  CHECK(double(certified.distance) <= tol + speed * timeTol + 1e-5);

  settings.variant = ExtrusionVariant::Paper;
  const auto paper = timeOfImpact(rod, ball, S(0), S(1), settings);
  std::cout << "TOI spinning rod (" << scalarName<S>() << "): certified " << toString(certified.status) << " at "
            << certified.time << " (expected " << tStar << ", brent " << certified.brentIterations << ", gjk "
            << certified.gjkRuns << "); paper " << toString(paper.status) << "\n";
  CHECK(paper.status == ToiStatus::NoCollision);  // the paper's test is blind to this (§3)
}

// A half turn per interval, both bodies turning. Two rods (half extents (2, 0.05, 0.05)),
// one at the origin, one at (0, 3, 0), both turning about z at w = π, in phase: at t0 and
// t1 both lie along x, 3 apart. Turned by θ they stay parallel, their axes 3 cos θ apart
// (and 3 sin θ < 4 along each other, so their long faces overlap): the distance is
// 3 cos θ - 0.1, which reaches tol at t* = acos((0.1 + tol)/3)/π = 0.48939.
TEMPLATE_TEST_CASE("a half turn per interval: two rods turning in phase", "[toi][hard][rotation]", float, double) {
  using S = TestType;
  const Box<S> rod(Vector3<S>(2, S(0.05), S(0.05)));
  const auto P = spinning(rod, Vector3<S>(0, 0, 0), Vector3<S>(0, 0, S(kPi)));
  const auto Q = spinning(rod, Vector3<S>(0, 3, 0), Vector3<S>(0, 0, S(kPi)));
  ToiSettings<S> settings;
  settings.variant = ExtrusionVariant::Certified;
  const double tol = settings.collisionTolerance, timeTol = settings.timeTolerance;
  const double thetaStar = std::acos((0.1 + tol) / 3);
  const double tStar = thetaStar / kPi, speed = 3 * std::sin(thetaStar) * kPi;
  const auto certified = timeOfImpact(P, Q, S(0), S(1), settings);
  INFO(scalarName<S>() << " certified: " << toString(certified.status) << " at " << certified.time << ", expected "
                       << tStar);
  REQUIRE(certified.status == ToiStatus::Hit);
  CHECK(double(certified.time) <= tStar + timeTol);
  CHECK(double(certified.time) >= tStar - tol / speed - 2 * timeTol);
  settings.variant = ExtrusionVariant::Paper;
  const auto paper = timeOfImpact(P, Q, S(0), S(1), settings);
  std::cout << "TOI rods in phase (" << scalarName<S>() << "): certified " << toString(certified.status) << " at "
            << certified.time << " (expected " << tStar << ", brent " << certified.brentIterations << "); paper "
            << toString(paper.status) << "\n";
  CHECK(paper.status == ToiStatus::NoCollision);  // same configuration at both ends
}

// A grazing spin: a 32-sided prism (radius 0.05, half length 0.5, axis x) spinning about its
// own axis at 400 rad/s (the torso's fastest cartilages turn at 400-450) next to a sphere of
// radius 0.2 fixed above it, with tolerance 1e-3. The sphere's centre is at
// y = 0.05 + 0.2 + 1.25 tol: the distance is 1.25 tol where a vertex of the prism points
// at the sphere and 1.25 tol + 0.05 (1 - cos(π/32)) = 1.49 tol where a face does, so it
// never comes within the tolerance: no collision. But the support along any fixed
// direction falls at up to ω r = 20 per unit time as the prism turns, so each stored vector
// proves a link of only about (d - tol) / 20 = 1.3e-5: §5's proof over the 0.01 interval
// (four radians) is a chain of hundreds of links, and the solver runs into its cap.
// With `acceptedDistance` = 1.5 tol (what the world sets) the first restart, already
// within the band, ends the query: a hit at a time proven free of contact, at a distance
// between the tolerance and the band.
TEMPLATE_TEST_CASE("a grazing spin: acceptedDistance ends the chain of links", "[toi][hard][rotation][grazing]", float,
                   double) {
  using S = TestType;
  const double r = 0.05, tol = 1e-3;
  std::vector<Vector3<S>> points;
  for (int k = 0; k < 32; ++k) {
    const double a = 2 * kPi * (k + 0.5) / 32;
    for (const double x : {-0.5, 0.5}) points.push_back(Vector3<double>(x, r * std::cos(a), r * std::sin(a)).cast<S>());
  }
  const auto prism = spinning(Polytope<S>::hull(points), Vector3<S>::Zero(), Vector3<S>(S(400), 0, 0));
  const auto ball = fixedAt(Sphere<S>(S(0.2)), Vector3<S>(0, S(r + 0.2 + 1.25 * tol), 0));
  ToiSettings<S> settings;
  settings.variant = ExtrusionVariant::Certified;
  settings.collisionTolerance = S(tol);
  const auto proof = timeOfImpact(prism, ball, S(0), S(0.01), settings);
  settings.acceptedDistance = S(1.5 * tol);
  const auto band = timeOfImpact(prism, ball, S(0), S(0.01), settings);
  std::cout << "TOI grazing spin (" << scalarName<S>() << "): without the band " << toString(proof.status) << " after "
            << proof.brentIterations << " Brent iterations; with it " << toString(band.status) << " at "
            << band.time << ", distance " << band.distance / tol << " tol, after " << band.brentIterations << "\n";
  // Without the band: never "hit" (the distance stays above the tolerance), and never a
  // silent no: a photo finish proven link by link, or the cap.
  CHECK((proof.status == ToiStatus::PhotoFinish || proof.status == ToiStatus::IterationCap));
  // With it: a hit within the band, at a time the solver proved free of contact, for a
  // handful of iterations.
  REQUIRE(band.status == ToiStatus::Hit);
  CHECK(double(band.distance) > tol);
  CHECK(double(band.distance) <= 1.5 * tol);
  CHECK(band.brentIterations <= 5);
  CHECK(band.brentIterations < proof.brentIterations);
  // From the 24th iteration on (what the world sets): the chain runs as §5 runs it until
  // then, and ends at the first restart in the band after it, well short of the cap.
  settings.acceptedAfter = 24;
  const auto late = timeOfImpact(prism, ball, S(0), S(0.01), settings);
  REQUIRE(late.status == ToiStatus::Hit);
  CHECK(double(late.distance) > tol);
  CHECK(double(late.distance) <= 1.5 * tol);
  CHECK(late.brentIterations >= 24);
  CHECK(late.brentIterations < settings.maxIterations);
  CHECK(double(late.time) >= double(band.time));
}

// Both bodies fast toward each other: unit boxes from x = -250 and x = +250 (offset 0.3 in
// y, 0.2 in z: faces still overlap) at 500 per unit time each, a relative speed of 1000
// sizes per interval. The gap is 500 - 1 - 1000 t: within tol at t* = (499 - tol)/1000.
TEMPLATE_TEST_CASE("both bodies fast toward each other", "[toi][hard][fast]", float, double) {
  using S = TestType;
  const auto P = translating(unitBox<S>(), Vector3<S>(-250, 0, 0), Vector3<S>(500, 0, 0));
  const auto Q = translating(unitBox<S>(), Vector3<S>(250, S(0.3), S(0.2)), Vector3<S>(-500, 0, 0));
  const ToiSettings<S> settings;
  const double tol = settings.collisionTolerance, timeTol = settings.timeTolerance;
  const double tStar = (499 - tol) / 1000;
  const auto r = timeOfImpact(P, Q, S(0), S(1), settings);
  INFO(scalarName<S>() << ": " << toString(r.status) << " at " << r.time << ", expected " << tStar);
  REQUIRE(r.status == ToiStatus::Hit);
  // Float places the boxes to 250 eps = 3e-5: the time to 3e-8 more.
  CHECK(std::abs(double(r.time) - tStar) <= tol / 1000 + timeTol + 1e-7);
  CHECK(r.normal.isApprox(Vector3<S>(1, 0, 0), S(1e-3)));
  CHECK(double(r.distance) <= tol + 1000 * timeTol);
}

// The paper's tunnelling case: a tiny fast sphere (radius 0.01, from x = -5 to x = 5 in one
// interval) through a thin plate (half thickness 0.001) at the origin. Within tol when the
// centre reaches x = -(0.011 + tol): t* = (5 - 0.011 - tol)/10.
TEMPLATE_TEST_CASE("a tiny fast sphere through a thin plate is a hit", "[toi][hard][tunnelling]", float, double) {
  using S = TestType;
  const auto plate = fixedAt(Box<S>(Vector3<S>(S(0.001), 1, 1)), Vector3<S>(0, 0, 0));
  const auto bullet = translating(Sphere<S>(S(0.01)), Vector3<S>(-5, S(0.3), S(0.2)), Vector3<S>(10, 0, 0));
  const ToiSettings<S> settings;
  const double tol = settings.collisionTolerance, timeTol = settings.timeTolerance;
  const double tStar = (5 - 0.011 - tol) / 10;
  const auto r = timeOfImpact(plate, bullet, S(0), S(1), settings);
  INFO(scalarName<S>() << ": " << toString(r.status) << " at " << r.time << ", expected " << tStar);
  REQUIRE(r.status == ToiStatus::Hit);
  CHECK(std::abs(double(r.time) - tStar) <= tol / 10 + timeTol + 1e-6);
  CHECK(r.normal.isApprox(Vector3<S>(-1, 0, 0), S(1e-3)));  // from the plate towards the bullet, still at x < 0
}

// The iteration cap: with maxIterations = 1, cases that need more Brent iterations end
// with IterationCap (which reports a possible collision), never with "no collision".
TEST_CASE("the iteration cap never says no collision", "[toi][hard][cap]") {
  ToiSettings<double> settings;
  settings.maxIterations = 1;
  // The pass above (a photo finish after several iterations, see above).
  const auto P = fixedAt(unitBox<double>(), Vector3<double>(0, 0, 0));
  const auto Q = translating(unitBox<double>(), Vector3<double>(3, 1.5, 0), Vector3<double>(-6, 0, 0));
  const auto pass = timeOfImpact(P, Q, 0.0, 1.0, settings);
  CHECK(pass.status == ToiStatus::IterationCap);
  CHECK(pass.brentIterations == 1);
  CHECK(reportsCollision(pass.status));
  CHECK(pass.time == 0.0);  // the last time proven free of contact
  // The spinning rod with the certified variant (a hit after several restarts).
  settings.variant = ExtrusionVariant::Certified;
  const auto rod = spinning(Box<double>(Vector3<double>(2, 0.05, 0.05)), Vector3<double>(0, 0, 0),
                            Vector3<double>(0, 0, kPi));
  const auto ball = fixedAt(Sphere<double>(0.2), Vector3<double>(0, 1.5, 0));
  const auto capped = timeOfImpact(rod, ball, 0.0, 1.0, settings);
  CHECK(capped.status == ToiStatus::IterationCap);
  CHECK(reportsCollision(capped.status));
  CHECK(capped.time < 0.4467);  // never past the contact
  // With the default cap both are decided.
  settings.maxIterations = 100;
  CHECK(timeOfImpact(rod, ball, 0.0, 1.0, settings).status == ToiStatus::Hit);
}

// The query runs in the frame of P (timeOfImpact's comment): the same head-on approach far
// from the world's origin, at x, y = 10^5 where float's spacing is 0.0078, gives the time it
// gives at the origin, and its witness points in the world. Without the frame, GJK's support
// points at 10^5 carry that spacing and the time was off by up to 3e-3 in float.
TEMPLATE_TEST_CASE("time of impact in P's frame: as accurate far from the origin as at it", "[toi][hard][origin]", float,
                   double) {
  using S = TestType;
  ToiSettings<S> settings;
  const S tol = settings.collisionTolerance;
  const double expected = (2.0 - double(tol)) / 4.0;
  for (const double offset : {0.0, 1e5, -3e5}) {
    const Vector3<S> at{S(offset), S(offset), S(0)};
    const auto P = fixedAt(unitBox<S>(), at);
    const auto Q = translating(unitBox<S>(), Vector3<S>(at + Vector3<S>(3, 0.25, 0)), Vector3<S>(-4, 0, 0));
    const auto r = timeOfImpact(P, Q, S(0), S(1), settings);
    INFO(scalarName<S>() << " at " << offset << ": status " << toString(r.status) << ", time " << r.time);
    REQUIRE(r.status == ToiStatus::Hit);
    CHECK(std::abs(double(r.time) - expected) <= double(tol) / 4 + double(settings.timeTolerance));
    // The witnesses are in the world: on P's right face and Q's left face, near `at`.
    CHECK(double(r.witnessP.x()) == Approx(offset + 0.5).margin(1e-2));
    CHECK(double(r.witnessQ.x()) == Approx(offset + 0.5 + double(r.distance)).margin(1e-2));
  }
}

// The query runs on its own clock, tau = t - t0 (timeOfImpact's comment): a short interval
// late in time gives the hit it gives at t0 = 0, as early as the caller's times allow. A
// point falls towards a unit box (face at x = 0.5) over tau1 = 2^-10, from x = 5.5 at 3 per
// interval and accelerating by 3.5 per interval squared: x(u) = 5.5 - 3u - 1.75u^2,
// u = tau/tau1, and the gap 5 - 3u - 1.75u^2 (0.25 at t1) reaches tol = 1.25 at
// u* = (-3 + sqrt(35.25))/3.5 = 0.8392. In float at t0 = 1000 the caller's times are 6.1e-5
// apart, 1/16 of the interval: u* lies between the times at u = 13/16 and 14/16. On the
// caller's clock Brent's bracket stopped at its round-off, 2 * 2 eps * 1000 = 2.4e-4 (four
// of those spacings), and the converged bracket's far end, t1, within the tolerance there,
// was reported: a hit at u = 1 where the gap is 0.25, the late hit the fuzzer found
// (corpus finding-toi_float_late_hit_at_t1000); or, where the far end did not qualify,
// its near end, spacings early. Now the hit is never after u*, at most one spacing before
// it, and its distance is the distance at the time reported.
TEMPLATE_TEST_CASE("time of impact on the query's clock: a late start time costs no accuracy", "[toi][hard][clock]",
                   float, double) {
  using S = TestType;
  const double tau1 = std::ldexp(1.0, -10);
  const double tol = 1.25;
  const double uStar = (-3 + std::sqrt(35.25)) / 3.5;
  for (const double start : {0.0, 1.0, 1000.0, -1000.0}) {
    const S t0 = S(start), t1 = S(t0 + S(tau1));
    REQUIRE(double(t1) - double(t0) == tau1);  // the interval is exact in S at every start
    const auto box = fixedAt(unitBox<S>(), Vector3<S>(0, 0, 0));
    const auto point = moving(Point<S>(),
                              Motion<S>::constantAcceleration(Pose<S>::translate(Vector3<S>(S(5.5), S(0.1), S(0.2))),
                                                              Vector3<S>(S(-3 / tau1), 0, 0),
                                                              Vector3<S>(S(-3.5 / (tau1 * tau1)), 0, 0), t0));
    for (const ExtrusionVariant variant : {ExtrusionVariant::Paper, ExtrusionVariant::Certified}) {
      ToiSettings<S> settings;
      settings.collisionTolerance = S(tol);
      settings.variant = variant;
      const auto r = timeOfImpact(box, point, t0, t1, settings);
      const double u = (double(r.time) - double(t0)) / tau1;
      const double spacing = double(std::nextafter(std::abs(t0), std::numeric_limits<S>::infinity()) - std::abs(t0));
      const double gapThere = 5 - 3 * u - 1.75 * u * u;
      INFO(scalarName<S>() << ", t0 = " << start << ", " << toString(variant) << ": " << toString(r.status)
                           << " at u = " << u << " (u* = " << uStar << "), distance " << r.distance << ", gap there "
                           << gapThere);
      REQUIRE(r.status == ToiStatus::Hit);
      const double timeTol = double(settings.timeTolerance);
      CHECK(u <= uStar + timeTol);                         // never late
      CHECK(u >= uStar - timeTol - spacing / tau1 - 1e-5);  // early by one of the caller's spacings at most
      CHECK(double(r.distance) == Approx(gapThere).margin(1e-4));
      CHECK(double(r.distance) >= tol - (3 + 3.5 * u) * timeTol - 1e-4);  // not past the contact by more than the time tolerance
    }
  }
}

// The contact data at a time snapped to the caller's clock are GJK's there (ToiSolver::
// contactAt). The fuzzer's input (corpus finding-toi_snapped_hit_distance_inf): in float on
// [1000, 1000 + 2^-10], a tetrahedron's vertex sweeps from x = 0.96 to x = -1e6 towards a
// point at x = -1e6, 6e4 per spacing of the caller's times. The hit lies within the last
// spacing before t1 and is reported at the latest time before it, 1000.00092, where the
// bodies are 62501 apart. Those data once came from a complete test there, which succeeded
// and so stopped GJK early: a hit at distance infinity.
TEST_CASE("time of impact on the query's clock: a snapped hit reports the distance there", "[toi][hard][clock]") {
  using S = float;
  using V = Vector3<S>;
  const S t0 = 1000, t1 = t0 + S(std::ldexp(1.0, -10));
  const DeformingSimplex<S> P({V(-0.803009033f, -1, -0.738769531f), V(-1, -1, -1), V(-0.111846924f, -0.507049561f, -0.703979492f),
                               V(0.958099365f, -1, 0)},
                              {V(108214.531f, -502442.406f, -0.738769531f), V(129820.781f, -131867.453f, 218077.609f),
                               V(-0.223693848f, -1.01409912f, -1.40795898f), V(-999999.062f, -1, 0)},
                              t0, t1);
  const DeformingSimplex<S> Q({V(-1000000, 0, 0)}, {V(-1000000, -1.00000001e-07f, 5.35491935e-08f)}, t0, t1);
  ToiSettings<S> settings;
  settings.collisionTolerance = 1;
  settings.variant = ExtrusionVariant::Certified;
  const auto r = timeOfImpact(P, Q, t0, t1, settings);
  INFO(toString(r.status) << " at " << r.time << ", distance " << r.distance);
  REQUIRE(r.status == ToiStatus::Hit);
  REQUIRE(r.time < t1);
  const auto there = gjk(P.at(r.time), Q.at(r.time));
  REQUIRE(there.status == GjkStatus::Separated);
  CHECK(std::isfinite(r.distance));
  CHECK(double(r.distance) == Approx(double(there.distance)).epsilon(1e-5));
  CHECK(r.distance >= settings.collisionTolerance);  // before the contact, as the time reported is
}

// Bad input names the field.
TEST_CASE("time of impact refuses a bad interval or tolerance", "[toi][input]") {
  const auto P = fixedAt(unitBox<double>(), Vector3<double>(0, 0, 0));
  const auto Q = translating(unitBox<double>(), Vector3<double>(3, 0, 0), Vector3<double>(-4, 0, 0));
  const auto backwards = invalidArgumentMessage([&] { timeOfImpact(P, Q, 1.0, 0.0); });
  CHECK(backwards.rfind("timeOfImpact.t1", 0) == 0);
  const auto nan = invalidArgumentMessage([&] { timeOfImpact(P, Q, 0.0, std::nan("")); });
  CHECK(nan.rfind("timeOfImpact.t1", 0) == 0);
  for (double bad : {0.0, -1e-3, std::nan("")}) {
    ToiSettings<double> settings;
    settings.collisionTolerance = bad;
    const auto message = invalidArgumentMessage([&] { timeOfImpact(P, Q, 0.0, 1.0, settings); });
    INFO("tolerance " << bad << ": " << message);
    CHECK(message.rfind("toiSettings.collisionTolerance", 0) == 0);
  }
  for (double bad : {-1e-3, std::nan(""), std::numeric_limits<double>::infinity()}) {
    ToiSettings<double> settings;
    settings.acceptedDistance = bad;
    const auto message = invalidArgumentMessage([&] { timeOfImpact(P, Q, 0.0, 1.0, settings); });
    INFO("accepted distance " << bad << ": " << message);
    CHECK(message.rfind("toiSettings.acceptedDistance", 0) == 0);
  }
  ToiSettings<double> settings;
  settings.acceptedAfter = -1;
  CHECK(invalidArgumentMessage([&] { timeOfImpact(P, Q, 0.0, 1.0, settings); }).rfind("toiSettings.acceptedAfter", 0) == 0);
}
