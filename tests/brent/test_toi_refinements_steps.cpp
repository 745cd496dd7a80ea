// The time-of-impact solver's refinements beyond §5, step by step: §5 exactly as the paper
// wrote it (ToiSettings::paper()), then the paper with one refinement turned on, on cases
// whose iterates are derived by hand below, so that a reader sees what each switch changes.
//
// The cases. P is a floor, a 4 x 4 x 1 box whose top face is z = 0. Q is a unit box whose
// bottom face is gap(t) above it, falling straight down (a translation, so the supporting
// distance along the floor's normal +z is the gap itself, and the first extrusion test,
// GJK at t0 on two aligned boxes, stores exactly that one vector, +z). The collision
// tolerance is tol = 2^-10, the time tolerance sqrt(eps) = 1.49e-8 of [0, 1].
//  - *Falling*: from rest under g = 10: gap(t) = 2 - 5 t^2, concave. It comes within the
//    tolerance at t* = sqrt((2 - tol)/5) = 0.6323011...
//  - *Braking*: down at 4, decelerating at 3: gap(t) = 2 - 4 t + 1.5 t^2, convex, within the
//    tolerance at t* = (4 - sqrt(16 - 6 (2 - tol)))/3 = 0.6661785...
#include <gjkx/brent/time_of_impact.hpp>
#include <gjkx/support_mapping/placed.hpp>
#include <gjkx/support_mapping/shape.hpp>

#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

using namespace gjkx;

namespace {

using V = Vector3<double>;
constexpr double kTol = 1.0 / 1024;

Moving<Box<double>> floorBox() {
  return moving(Box<double>(V(2, 2, 0.5)), Motion<double>::fixed(Pose<double>::translate(V(0, 0, -0.5))));
}
// Q's bottom starts at 2 above the floor: its centre at 2.5.
Moving<Box<double>> fallingBox(double v0, double a) {
  return moving(Box<double>(V(0.5, 0.5, 0.5)),
                Motion<double>::constantAcceleration(Pose<double>::translate(V(0, 0, 2.5)), V(0, 0, -v0), V(0, 0, a)));
}

ToiSettings<double> paperWith(bool ToiSettings<double>::*refinement = nullptr) {
  ToiSettings<double> settings = ToiSettings<double>::paper();
  settings.collisionTolerance = kTol;
  if (refinement) settings.*refinement = true;
  return settings;
}

double gapFalling(double t) { return 2 - 5 * t * t; }
double gapBraking(double t) { return 2 - 4 * t + 1.5 * t * t; }

struct Run {
  ToiResult<double> result;
  ToiTrace<double> trace;
};
Run run(const Moving<Box<double>>& Q, const ToiSettings<double>& settings) {
  Run r;
  r.result = timeOfImpact(floorBox(), Q, 0.0, 1.0, settings, &r.trace);
  return r;
}

}  // namespace

TEST_CASE("the paper's presets: paper() turns every refinement off, gjkx() is the default", "[toi][refinements]") {
  const ToiSettings<double> paper = ToiSettings<double>::paper(), ours = ToiSettings<double>::gjkx(), plain;
  for (bool ToiSettings<double>::*m :
       {&ToiSettings<double>::warmStart, &ToiSettings<double>::coherence, &ToiSettings<double>::supportHints,
        &ToiSettings<double>::farEndReuse, &ToiSettings<double>::probe, &ToiSettings<double>::leap,
        &ToiSettings<double>::acceptedBand, &ToiSettings<double>::separatingAtStart, &ToiSettings<double>::inFrameOfP,
        &ToiSettings<double>::onQueryClock}) {
    CHECK_FALSE(paper.*m);
    CHECK(ours.*m);
    CHECK(plain.*m);
  }
  CHECK(paper.variant == ExtrusionVariant::Paper);
  CHECK(ToiSettings<double>::of(ToiSolverMode::Paper).probe == false);
  CHECK(ToiSettings<double>::of(ToiSolverMode::Gjkx).probe == true);
  CHECK(std::string(toString(ToiSolverMode::Paper)) == "paper");
  CHECK(std::string(toString(ToiSolverMode::Gjkx)) == "gjkx");
}

// §5 as written, on the falling box. F(t) = gap(t) - tol along the one stored vector +z.
// F(0) = 2 - tol, F(1) = -3 - tol: the first Brent step is the secant
//   t_1 = F(0) / (F(0) - F(1)) = (2 - tol)/5 = 0.3998046875,
// where +z still separates by gap(t_1) = 1.2008 >= tol: [0, t_1] is free, and a complete
// test on [t_1, 1] fails again (gap(1) = -3). Brent restarts on [t_1, 1] with F(t_1) > 0 and
// F(1) < 0, and its first step is again the secant
//   t_{k+1} = t_k + (gap(t_k) - tol)(1 - t_k) / (gap(t_k) + 3)
// (t_2 = 0.5712292, t_3 = 0.6180091, ...). F is concave, so its chord lies below it and
// every secant lands short of t*: each restart closes the gap to t* by a constant factor,
// about 1 - 10 t* (1 - t*)/3 = 0.22 (regula falsi's linear rate), and the query creeps
// to t* in 13 restarts, one complete test each, ending with Brent's minimal step.
TEST_CASE("§5 as written, step by step: regula falsi's creep on a falling box", "[toi][refinements][steps]") {
  const Run r = run(fallingBox(0, -10), paperWith());
  const double tStar = std::sqrt((2 - kTol) / 5);
  REQUIRE(r.result.status == ToiStatus::Hit);
  CHECK(r.result.time == Approx(tStar).margin(1e-7));
  REQUIRE(r.trace.steps.size() == 14);
  double t = 0;
  for (int k = 0; k < 13; ++k) {  // every step a secant from the restart towards t1 = 1
    const double expected = t + (gapFalling(t) - kTol) * (1 - t) / (gapFalling(t) + 3);
    INFO("step " << k);
    CHECK(r.trace.steps[k].kind == BrentStepKind::Secant);
    CHECK(r.trace.steps[k].bracketLow == Approx(t).epsilon(1e-12));
    CHECK(r.trace.steps[k].bracketHigh == 1.0);
    CHECK(r.trace.steps[k].t == Approx(expected).epsilon(1e-10));
    CHECK(r.trace.steps[k].approximateMaxSd == Approx(gapFalling(expected)).epsilon(1e-8));
    CHECK(r.trace.steps[k].completeTest);
    CHECK(r.trace.steps[k].t < tStar);  // short of t*, always
    t = r.trace.steps[k].t;
  }
  CHECK(r.trace.steps[0].t == Approx((2 - kTol) / 5).epsilon(1e-15));
  CHECK(r.trace.steps[13].kind == BrentStepKind::MinimalStep);
  CHECK(r.result.restarts == 13);
  CHECK(r.result.gjkRuns == 15);  // the first test, 13 restarts, the test at the converged end
  // Every complete test stores the one vector +z.
  for (const ToiInterval<double>& test : r.trace.intervals) CHECK(test.separating.count <= 1);
}

// warmStart: the same iterates (a warm GJK converges to the same distances), fewer
// supporting distances. Each restart's GJK starts from the last test's simplex, the
// closest features of the two faces, which are still the closest features: it converges
// at once instead of climbing from the centres' direction again.
TEST_CASE("warmStart, step by step: the same iterates on the falling box, fewer supporting distances",
          "[toi][refinements][steps]") {
  const Run cold = run(fallingBox(0, -10), paperWith());
  const Run warm = run(fallingBox(0, -10), paperWith(&ToiSettings<double>::warmStart));
  REQUIRE(warm.trace.steps.size() == cold.trace.steps.size());
  for (std::size_t k = 0; k < cold.trace.steps.size(); ++k) CHECK(warm.trace.steps[k].t == Approx(cold.trace.steps[k].t).epsilon(1e-12));
  CHECK(warm.result.gjkRuns == cold.result.gjkRuns);
  CHECK(warm.result.sdEvaluations < cold.result.sdEvaluations);
}

// probe: after the second restart the solver knows the exact distance at three times,
// 0, t_1 and t_2, all on the parabola gap(t) = 2 - 5 t^2 itself; Muller's method on them is
// exact: it reaches the tolerance at t*. The probe goes half a time tolerance short of it,
// to t* - 0.5 timeTol, where the complete test's vector +z separates by the tolerance back
// to t_2 (proven: a restart there), and the next probe goes one time tolerance on
// (t* + 0.5 timeTol), where the bodies are within the tolerance: not proven, a far end, and
// the bracket between the two is within the time tolerance: the hit, after 4 iterates and 3
// restarts instead of 14 and 13.
TEST_CASE("probe, step by step: Muller's parabola lands on the falling box's contact at once",
          "[toi][refinements][steps]") {
  const Run r = run(fallingBox(0, -10), paperWith(&ToiSettings<double>::probe));
  const double tStar = std::sqrt((2 - kTol) / 5), timeTol = ToiSettings<double>{}.timeTolerance;
  REQUIRE(r.result.status == ToiStatus::Hit);
  REQUIRE(r.trace.steps.size() == 4);
  CHECK(r.trace.steps[0].kind == BrentStepKind::Secant);  // t_1, t_2: as in the paper's run
  CHECK(r.trace.steps[1].kind == BrentStepKind::Secant);
  CHECK(r.trace.steps[1].t == Approx(0.5712292452).epsilon(1e-9));
  CHECK(r.trace.steps[2].kind == BrentStepKind::DistanceSecant);
  CHECK(r.trace.steps[2].t == Approx(tStar - 0.5 * timeTol).margin(1e-12));
  CHECK(r.trace.steps[2].completeTest);  // proven free back to t_2
  CHECK(r.trace.steps[3].kind == BrentStepKind::DistanceSecant);
  CHECK(r.trace.steps[3].t == Approx(tStar + 0.5 * timeTol).margin(1e-12));
  CHECK_FALSE(r.trace.steps[3].completeTest);  // within the tolerance there
  CHECK(r.result.time == r.trace.steps[3].t);
  CHECK(r.result.distance <= kTol);
  CHECK(r.result.restarts == 3);
  CHECK(r.result.brentIterations == 4);
}

// leap: after the third restart, at t_3 = 0.6180091, the advance t_3 - t_2 = 0.0467798 is less
// than a quarter of what is left of the bracket, (1 - t_3)/4 = 0.0954977: a creeping restart.
// The leap goes twice that advance ahead, to t_3 + 2 (t_3 - t_2) = 0.7115687, where gap =
// -0.5307 < tol: not free, so it becomes the bracket's far end, and the secant on
// [t_3, 0.7115687] lands at 0.6314490, much nearer t* than the paper's 0.6290532.
TEST_CASE("leap, step by step: a creeping restart leaps twice its advance ahead", "[toi][refinements][steps]") {
  const Run paper = run(fallingBox(0, -10), paperWith());
  const Run r = run(fallingBox(0, -10), paperWith(&ToiSettings<double>::leap));
  REQUIRE(r.result.status == ToiStatus::Hit);
  REQUIRE(r.trace.steps.size() >= 5);
  const double t2 = r.trace.steps[1].t, t3 = r.trace.steps[2].t;
  CHECK(t3 == Approx(0.6180090752).epsilon(1e-9));
  CHECK(t3 - t2 < 0.25 * (1 - t3));
  CHECK(r.trace.steps[3].kind == BrentStepKind::Leap);
  CHECK(r.trace.steps[3].t == Approx(t3 + 2 * (t3 - t2)).epsilon(1e-14));
  CHECK(r.trace.steps[3].approximateMaxSd == Approx(gapFalling(t3 + 2 * (t3 - t2))).epsilon(1e-9));
  CHECK_FALSE(r.trace.steps[3].completeTest);
  // The leap is the far end of the next bracket, and its secant lands past the paper's iterate.
  CHECK(r.trace.steps[4].bracketHigh == r.trace.steps[3].t);
  const double fa = gapFalling(t3) - kTol, fb = gapFalling(r.trace.steps[3].t) - kTol;
  CHECK(r.trace.steps[4].t == Approx(t3 - fa * (r.trace.steps[3].t - t3) / (fb - fa)).epsilon(1e-10));
  CHECK(r.trace.steps[4].t > paper.trace.steps[3].t);
  CHECK(r.result.restarts < paper.result.restarts);  // 7 against 13
}

// farEndReuse, on the braking box. F(0) = 2 - tol, F(1) = gap(1) - tol = -0.5 - tol; the first
// secant t_1 = (2 - tol)/2.5 = 0.799609375 overshoots (F convex: its chord lies above it):
// gap(t_1) = -0.2394, so the bracket becomes [0, t_1], and Brent's next step (inverse
// quadratic interpolation through 0, t_1 and 1) lands at t_2 = 0.6346418, where gap = 0.0656
// >= tol: a restart. The paper's Brent starts afresh on [t_2, 1]; with farEndReuse the far end
// is t_1, the nearest time known below the tolerance (gap(t_1) < tol along the new test's +z
// too), and the query ends in 6 iterates instead of 9.
TEST_CASE("farEndReuse, step by step: the braking box's restart keeps the last bracket's far end",
          "[toi][refinements][steps]") {
  const Run paper = run(fallingBox(4, 3), paperWith());
  const Run r = run(fallingBox(4, 3), paperWith(&ToiSettings<double>::farEndReuse));
  const double t1 = (2 - kTol) / 2.5;
  for (const Run* x : {&paper, &r}) {
    REQUIRE(x->result.status == ToiStatus::Hit);
    REQUIRE(x->trace.steps.size() >= 3);
    CHECK(x->trace.steps[0].t == Approx(t1).epsilon(1e-15));
    CHECK(x->trace.steps[0].approximateMaxSd == Approx(gapBraking(t1)).epsilon(1e-9));
    CHECK_FALSE(x->trace.steps[0].completeTest);
    CHECK(x->trace.steps[1].kind == BrentStepKind::InverseQuadratic);
    CHECK(x->trace.steps[1].bracketHigh == x->trace.steps[0].t);
    CHECK(x->trace.steps[1].t == Approx(0.6346418012).epsilon(1e-9));
    CHECK(x->trace.steps[1].completeTest);
  }
  CHECK(paper.trace.steps[2].bracketHigh == 1.0);
  CHECK(r.trace.steps[2].bracketHigh == r.trace.steps[0].t);
  CHECK(r.result.brentIterations < paper.result.brentIterations);
  const double tStar = (4 - std::sqrt(16 - 6 * (2 - kTol))) / 3;
  CHECK(r.result.time == Approx(tStar).margin(1e-7));
  CHECK(paper.result.time == Approx(tStar).margin(1e-7));
}

// acceptedBand: the paper's restarts on the falling box find the exact distances 2, 1.2008,
// 0.3685, 0.0903, 0.0215, 0.0056, 0.00202, 0.00121, 0.00103, 0.000989, ... (the gap at each
// t_k above). With a band of 1.5 tol = 0.00146, the first restart inside it is the 7th (at
// t_7 = 0.6322639, distance 0.00121 = 1.24 tol): the query ends there with a hit after 7
// iterates. With acceptedAfter = 10 the band waits for the 10th iterate: the hit is at t_10,
// distance 0.000979 (already within 1.003 tol). Without acceptedBand the switch ignores both.
TEST_CASE("acceptedBand, step by step: the falling box ends at the first restart inside the band",
          "[toi][refinements][steps]") {
  ToiSettings<double> settings = paperWith(&ToiSettings<double>::acceptedBand);
  settings.acceptedDistance = 1.5 * kTol;
  const Run paper = run(fallingBox(0, -10), paperWith());
  const Run r = run(fallingBox(0, -10), settings);
  REQUIRE(r.result.status == ToiStatus::Hit);
  CHECK(r.result.brentIterations == 7);
  CHECK(r.result.time == paper.trace.steps[6].t);
  CHECK(r.result.distance == Approx(gapFalling(paper.trace.steps[6].t)).epsilon(1e-9));
  CHECK(r.result.distance > kTol);
  CHECK(r.result.distance <= 1.5 * kTol);
  settings.acceptedAfter = 10;
  const Run later = run(fallingBox(0, -10), settings);
  CHECK(later.result.brentIterations == 10);
  CHECK(later.result.time == paper.trace.steps[9].t);
  settings.acceptedBand = false;
  const Run off = run(fallingBox(0, -10), settings);
  CHECK(off.result.brentIterations == paper.result.brentIterations);
}

// separatingAtStart: Q's bottom starts tol/2 above the floor and rises at 1: within the
// tolerance at t0. Along the closest direction +z, SD(0) = tol/2 > 0 and SD(1) = tol/2 + 1 >=
// SD(0): the bodies provably move apart. The paper's solver, which assumes bodies apart at
// t0, reports StartsPenetrating; with the switch, Separating (no new contact).
TEST_CASE("separatingAtStart, step by step: a contact leaving at t0 is told apart", "[toi][refinements][steps]") {
  const auto Q = moving(Box<double>(V(0.5, 0.5, 0.5)),
                        Motion<double>::constantVelocity(Pose<double>::translate(V(0, 0, 0.5 + kTol / 2)), V(0, 0, 1)));
  const auto paper = timeOfImpact(floorBox(), Q, 0.0, 1.0, paperWith());
  const auto ours = timeOfImpact(floorBox(), Q, 0.0, 1.0, paperWith(&ToiSettings<double>::separatingAtStart));
  CHECK(paper.status == ToiStatus::StartsPenetrating);
  CHECK(ours.status == ToiStatus::Separating);
  CHECK(paper.distance == Approx(kTol / 2).epsilon(1e-9));
  CHECK(ours.time == 0.0);
}

// coherence: two queries of one pair, Q sliding at 1 along x a gap of 1 above the floor. The
// first, over [0, 1], ends at once (+z separates at both ends) and leaves +z in the pair's
// cache; the second, over [1, 2], tries it first: two supporting distances (at t = 1 and
// t = 2) and no GJK iteration. Without coherence the second query runs GJK again.
TEST_CASE("coherence, step by step: the pair's last separating vector decides its next query", "[toi][refinements][steps]") {
  const auto Q = moving(Box<double>(V(0.5, 0.5, 0.5)),
                        Motion<double>::constantVelocity(Pose<double>::translate(V(0, 0, 1.5)), V(1, 0, 0)));
  for (const bool coherent : {false, true}) {
    ToiSettings<double> settings = paperWith(&ToiSettings<double>::warmStart);
    settings.coherence = coherent;
    ExtrusionCache<double> cache;
    const auto first = timeOfImpact(floorBox(), Q, 0.0, 1.0, settings, nullptr, &cache);
    const auto second = timeOfImpact(floorBox(), Q, 1.0, 2.0, settings, nullptr, &cache);
    INFO("coherence " << coherent);
    CHECK(first.status == ToiStatus::NoCollision);
    CHECK(second.status == ToiStatus::NoCollision);
    CHECK(cache.valid == coherent);
    if (coherent) CHECK(second.sdEvaluations == 2);
    else CHECK(second.sdEvaluations == first.sdEvaluations);
  }
}

// supportHints: a stored vector keeps the vertex its last support search ended on. Q is an
// octahedron (vertices at 0.5 along each axis, as a polytope, where hill climbing walks the
// edges) falling as the box did: its lowest vertex (0, 0, -0.5) starts 2 above the floor.
// The first test stores +z with the hint of Q's search at t1, S_Q(-z): the lowest vertex.
// The search along the same vector at the next iterate starts there: a climb of one
// vertex, where one from the first vertex, (0.5, 0, 0), needs two (it steps down to the
// lowest vertex). Where the climb ends, and so every SD and every iterate, is the same
// either way.
TEST_CASE("supportHints, step by step: the stored vector's climb starts on its supporting vertex",
          "[toi][refinements][steps]") {
  const Polytope<double> octahedron = Polytope<double>::hull(
      std::vector<V>{V(0.5, 0, 0), V(-0.5, 0, 0), V(0, 0.5, 0), V(0, -0.5, 0), V(0, 0, 0.5), V(0, 0, -0.5)});
  REQUIRE(octahedron.vertex(0) == V(0.5, 0, 0));
  const auto Q = moving(octahedron, Motion<double>::constantAcceleration(Pose<double>::translate(V(0, 0, 2.5)),
                                                                         V(0, 0, 0), V(0, 0, -10)));
  ToiTrace<double> withHints, without;
  const auto a = timeOfImpact(floorBox(), Q, 0.0, 1.0, paperWith(&ToiSettings<double>::supportHints), &withHints);
  const auto b = timeOfImpact(floorBox(), Q, 0.0, 1.0, paperWith(), &without);
  REQUIRE(a.status == ToiStatus::Hit);
  CHECK(a.time == b.time);
  REQUIRE(withHints.steps.size() == without.steps.size());
  for (std::size_t k = 0; k < without.steps.size(); ++k) CHECK(withHints.steps[k].t == without.steps[k].t);
  const SeparatingVectors<double>& stored = withHints.intervals[0].separating;
  REQUIRE(stored.count == 1);
  CHECK(stored.vectors[0].isApprox(V(0, 0, 1), 1e-12));
  const V down(0, 0, -1);
  const std::vector<int> fromHint = octahedron.climbPath(down, stored.hintQ[0]);
  const std::vector<int> fromFirst = octahedron.climbPath(down, 0);
  CHECK(fromHint.size() == 1);  // already on the supporting vertex
  CHECK(fromFirst.size() == 2);  // (0.5, 0, 0), then down to (0, 0, -0.5)
  CHECK(fromHint.back() == fromFirst.back());
  CHECK(octahedron.vertex(fromHint.back()) == V(0, 0, -0.5));
}
