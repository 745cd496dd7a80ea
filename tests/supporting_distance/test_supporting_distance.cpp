// The supporting distance SD(P, Q, s) and the static intersection test (§2.3, §4).
#include "../gjk/needle_slab.hpp"

#include <gjkx/supporting_distance/intersection.hpp>
#include <gjkx/supporting_distance/supporting_distance.hpp>
#include <gjkx/support_mapping/placed.hpp>
#include <gjkx/support_mapping/polytope.hpp>
#include <gjkx/support_mapping/primitives.hpp>

#include <catch2/catch.hpp>

#include <cmath>
#include <random>
#include <vector>

using namespace gjkx;

namespace {
template <typename S>
std::vector<Vector3<S>> circleDirections(int n) {
  std::vector<Vector3<S>> dirs;
  for (int k = 0; k < n; ++k) {
    const double a = 2 * M_PI * k / n;
    dirs.emplace_back(S(std::cos(a)), S(std::sin(a)), S(0));
  }
  return dirs;
}
}  // namespace

TEMPLATE_TEST_CASE("SD of two unit boxes two apart, by hand", "[sd][hand]", float, double) {
  using S = TestType;
  const Box<S> unit(Vector3<S>(S(0.5), S(0.5), S(0.5)));
  const auto P = place(unit, Pose<S>::identity());
  const auto Q = place(unit, Pose<S>::translate(Vector3<S>(2, 0, 0)));
  // Along +x: the supporting planes are x = 0.5 (of P) and x = 1.5 (of Q): 1 apart, separating.
  CHECK(supportingDistance(P, Q, Vector3<S>(1, 0, 0)) == Approx(1));
  // Along -x: Q's plane at x = 2.5 and P's at -0.5 face the wrong way: -3, the union's width.
  CHECK(supportingDistance(P, Q, Vector3<S>(-1, 0, 0)) == Approx(-3));
  // Along +y: the slabs y in [-0.5, 0.5] coincide: -1, they overlap by the whole height.
  CHECK(supportingDistance(P, Q, Vector3<S>(0, 1, 0)) == Approx(-1));
  // SD is measured for the unit vector: scaling s changes nothing.
  CHECK(supportingDistance(P, Q, Vector3<S>(7, 0, 0)) == Approx(1));
  // Diagonal: planes through (0.5,0.5,0) and (1.5,-0.5,0) along (1,1,0)/sqrt 2: SD = 0.
  CHECK(supportingDistance(P, Q, Vector3<S>(1, 1, 0)) == Approx(0).margin(1e-6));
  // A zero direction separates nothing.
  CHECK(supportingDistance(P, Q, Vector3<S>::Zero()) == -std::numeric_limits<S>::infinity());
}

TEST_CASE("maximum SD over directions: the distance when disjoint, minus the penetration when not (Fig. 3)",
          "[sd][max]") {
  const auto square = Polytope<double>::polygon(
      {Vector3<double>(-1, -1, 0), Vector3<double>(1, -1, 0), Vector3<double>(1, 1, 0), Vector3<double>(-1, 1, 0)});
  const auto dirs = circleDirections<double>(3600);
  SECTION("disjoint: max SD = GJK's closest distance") {
    const auto P = place(square, Pose<double>::identity());
    const auto Q = place(square, Pose<double>::translate({3, 0.5, 0}));
    const auto best = maximumSupportingDistance(P, Q, dirs);
    const auto run = gjk(P, Q);
    REQUIRE(run.status == GjkStatus::Separated);
    CHECK(best.value == Approx(1.0).epsilon(1e-9));
    CHECK(run.distance == Approx(best.value).epsilon(1e-9));
    CHECK(best.direction.x() == Approx(1.0));
  }
  SECTION("overlapping by 0.25 along x: max SD = -0.25, the penetration depth") {
    const auto P = place(square, Pose<double>::identity());
    const auto Q = place(square, Pose<double>::translate({1.75, 0.5, 0}));
    const auto best = maximumSupportingDistance(P, Q, dirs);
    CHECK(best.value == Approx(-0.25).epsilon(1e-9));
    CHECK(gjk(P, Q).status == GjkStatus::Overlapping);
  }
}

TEMPLATE_TEST_CASE("the static test: disjoint, intersecting, and within the collision tolerance", "[sd][static]",
                   float, double) {
  using S = TestType;
  const S tol = defaultCollisionTolerance<S>();
  CHECK(tol == Approx(std::sqrt(std::numeric_limits<S>::epsilon())));
  const Box<S> unit(Vector3<S>(S(0.5), S(0.5), S(0.5)));
  const auto P = place(unit, Pose<S>::identity());
  auto at = [&](S gap) { return place(unit, Pose<S>::translate(Vector3<S>(S(1) + gap, S(0.1), S(0.2)))); };

  const auto apart = intersect(P, at(S(0.5)));
  REQUIRE(apart.status == IntersectionStatus::Disjoint);
  // The vector returned really separates: its SD exceeds the tolerance.
  CHECK(supportingDistance(P, at(S(0.5)), apart.separatingVector) > tol);
  CHECK(apart.supportingDistance > tol);

  CHECK(intersect(P, at(S(-0.25))).status == IntersectionStatus::Intersecting);   // overlapping
  CHECK(intersect(P, at(S(0.5) * tol)).status == IntersectionStatus::Intersecting);  // closer than the tolerance
  CHECK(intersect(P, at(S(4) * tol)).status == IntersectionStatus::Disjoint);      // farther than it
}

TEST_CASE("the static test on touching bodies where GJK stalls: intersecting, as §2.3 argues", "[sd][static][stall]") {
  // §2.3: "If the GJK algorithm finds a local minimum for the Minkowski distance and halts
  // before a separating vector can be found, then such a vector provably doesn't exist".
  // The needle slab (tests/gjk/needle_slab.hpp: a triangle 1.4e6 long and 1e-4 thick
  // touching a segment at a shared vertex) makes GJK halt so, with its distance 1e-4 far
  // above the tolerance: the boolean query still answers intersecting.
  const Triangle<double> P = test::needle(1e6, 1e-4);
  const Segment<double> Q = test::segmentTo(1e6, 0.5);
  REQUIRE(gjk(P, Q).status == GjkStatus::Stalled);
  const IntersectionResult<double> r = intersect(P, Q);
  CHECK(r.status == IntersectionStatus::Intersecting);
  CHECK(r.supportingDistance <= defaultCollisionTolerance<double>());
}

// The supporting distance and the static test, step by step, on Fig. 2's scene (P the
// quadrilateral (0,0) (5,0) (6,6) (0,5), Q the pentagon (11,3) (12,3) (14,5) (9,9) (10,5)):
//  s_0 = (0, -1): S_P(s_0) is P's lowest vertex, s_0 . (0,0) = 0 (a tie with (5,0));
//    S_Q(-s_0) = S_Q(0, 1), Q's highest, (9,9): SD = s_0 . (9,9) - 0 = -9: no separation.
//  s_1 = (1, 1)/sqrt 2 (GJK's z = (9,9), normalised): S_P(s_1) = (6,6), s_1 . (6,6) = 12/sqrt 2;
//    S_Q(-s_1) minimises x + y over Q: (11,3), 14 (the others 15, 15, 18, 19), so
//    SD = (14 - 12)/sqrt 2 = sqrt 2 > tol: s_1 separates, and the boolean query stops there.
TEST_CASE("the static test, step by step: SD along s_0 and s_1 of Fig. 2, and the stop at the first separating vector",
          "[sd][static][fig2][steps]") {
  using V = Vector3<double>;
  const auto P = Polytope<double>::polygon({V(0, 0, 0), V(5, 0, 0), V(6, 6, 0), V(0, 5, 0)});
  const auto Q = Polytope<double>::polygon({V(11, 3, 0), V(12, 3, 0), V(14, 5, 0), V(9, 9, 0), V(10, 5, 0)});
  CHECK(supportingDistance(P, Q, V(0, -1, 0)) == Approx(-9));
  CHECK(Q.support(V(0, 1, 0)) == V(9, 9, 0));
  CHECK(supportingDistance(P, Q, V(1, 1, 0).normalized()) == Approx(std::sqrt(2.0)));
  CHECK(P.support(V(1, 1, 0)) == V(6, 6, 0));
  CHECK(Q.support(V(-1, -1, 0)) == V(11, 3, 0));
  IntersectionSettings<double> settings;
  settings.gjk.initialDirection = V(0, -1, 0);
  const auto boolean = intersect(P, Q, settings);
  // s_0 = (0,-1) has SD = -9; s_1 = (9,9) has SD = sqrt 2 > tolerance: stop after 2 iterations,
  // where the distance query needs 6 (see test_gjk_figure2_steps.cpp).
  REQUIRE(boolean.status == IntersectionStatus::Disjoint);
  CHECK(boolean.iterations == 2);
  CHECK(boolean.supportingDistance == Approx(std::sqrt(2.0)));
  CHECK(boolean.separatingVector.isApprox(V(1, 1, 0).normalized()));
}

TEST_CASE("a warm-started static test finds the remembered separating vector at once", "[sd][static][warm]") {
  const Box<double> unit(Vector3<double>(0.5, 0.5, 0.5));
  const auto P = place(unit, Pose<double>::identity());
  GjkCache<double> cache;
  const auto first = intersect(P, place(unit, Pose<double>::translate({1.5, 0.3, 0})), {}, &cache);
  REQUIRE(first.status == IntersectionStatus::Disjoint);
  // Q moves a little: the last separating vector still separates, one support query each.
  const auto second = intersect(P, place(unit, Pose<double>::translate({1.49, 0.31, 0.01})), {}, &cache);
  REQUIRE(second.status == IntersectionStatus::Disjoint);
  CHECK(second.iterations == 1);
}

// The hill-climbing hints (§2.1) change where each support search starts, never its end:
// from any starting vertex the supporting distance is the one without hints, and the
// hints come back on vertices that support the polytope along s (held to a linear scan).
// The time-of-impact solver keeps such hints per stored separating vector (§5).
TEMPLATE_TEST_CASE("SD with hill-climbing hints: the same value from any start, the hints on supporting vertices",
                   "[sd][hints]", float, double) {
  using S = TestType;
  using V = Vector3<S>;
  std::mt19937 rng(17);
  std::normal_distribution<double> normal(0, 1);
  std::uniform_real_distribution<double> u(0, 1);
  auto unit = [&] { return V(S(normal(rng)), S(normal(rng)), S(normal(rng))).normalized(); };
  auto cloud = [&](int n, const V& scale) {
    std::vector<V> points;
    for (int k = 0; k < n; ++k) points.push_back(unit().cwiseProduct(scale));
    return Polytope<S>::hull(points);
  };
  const auto P = place(cloud(300, V(1, S(0.6), S(0.4))), Pose<S>::fromAxisAngle(V(1, 2, 3), S(0.7), V(0, 0, 0)));
  const auto Q = place(cloud(120, V(S(0.5), S(0.5), S(0.8))), Pose<S>::fromAxisAngle(V(-1, 0, 2), S(2.1), V(3, 1, 0)));
  const S roundoff = std::is_same_v<S, float> ? S(1e-5) : S(1e-13);
  // The projection of the placed polytope's vertex v on s.
  auto along = [](const auto& X, int v, const V& s) { return s.dot(X.worldFromBody(X.shape.vertex(v))); };
  SupportHint hintP = 0, hintQ = 0;
  for (int trial = 0; trial < 200; ++trial) {
    const V s = unit();
    if (trial % 3 == 0) {  // a cold start from any vertex, else the hints of the last direction
      hintP = int(u(rng) * P.shape.vertexCount());
      hintQ = int(u(rng) * Q.shape.vertexCount());
    }
    const S plain = supportingDistance(P, Q, s);
    const S hinted = supportingDistance(P, Q, s, hintP, hintQ);
    INFO("trial " << trial);
    CHECK(hinted == Approx(plain).margin(roundoff));
    // The hints end on supporting vertices: P's along s, Q's along -s.
    const int scanP = P.shape.supportIndexLinearScan(P.worldFromBody.toBodyDirection(s));
    const int scanQ = Q.shape.supportIndexLinearScan(Q.worldFromBody.toBodyDirection(V(-s)));
    CHECK(along(P, hintP, s) == Approx(along(P, scanP, s)).margin(roundoff));
    CHECK(along(Q, hintQ, V(-s)) == Approx(along(Q, scanQ, V(-s))).margin(roundoff));
  }
  // A zero direction separates nothing, and leaves the hints alone.
  hintP = 7;
  hintQ = 11;
  CHECK(supportingDistance(P, Q, V::Zero(), hintP, hintQ) == -std::numeric_limits<S>::infinity());
  CHECK(hintP == 7);
  CHECK(hintQ == 11);
}
