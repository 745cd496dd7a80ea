// Fig. 2, step by step: the 2D run of GJK that chapter 02_gjk draws, replayed
// step by step, iteration by iteration, against values derived by hand below.
//
// The scene (the same as chapters/02_gjk/main.cpp), in the plane z = 0:
//   P: the quadrilateral (0,0) (5,0) (6,6) (0,5)
//   Q: the pentagon      (11,3) (12,3) (14,5) (9,9) (10,5)
//   s_0 = (0,-1), "an arbitrary nonzero vector".
// At each iteration, S_P(s) maximises s.x over P's vertices, S_Q(-s) minimises it
// over Q's, w = S_Q(-s) - S_P(s) joins V_Z = V_Q - V_P, and
// SD(s) = s.w / |s| is the supporting distance (§2.3).
#include <gjkx/gjk/gjk.hpp>
#include <gjkx/support_mapping/polytope.hpp>

#include <catch2/catch.hpp>

#include <cmath>

using namespace gjkx;
using V = Vector3<double>;

namespace {

// The kept simplex contains exactly these w's (in any order).
void requireSimplex(const Simplex<double>& simplex, std::initializer_list<V> expected) {
  REQUIRE(simplex.size == static_cast<int>(expected.size()));
  for (const V& w : expected) {
    bool found = false;
    for (int k = 0; k < simplex.size; ++k) found = found || (simplex.vertices[k].w - w).norm() < 1e-12;
    INFO("expected simplex vertex (" << w.x() << ", " << w.y() << ")");
    CHECK(found);
  }
}

void requireXY(const V& actual, double x, double y) {
  CHECK(actual.x() == Approx(x).margin(1e-12));
  CHECK(actual.y() == Approx(y).margin(1e-12));
  CHECK(actual.z() == 0.0);
}

}  // namespace

TEST_CASE("Fig. 2: GJK in 2D, step by step", "[gjk][steps][fig2]") {
  const auto P = Polytope<double>::polygon({V(0, 0, 0), V(5, 0, 0), V(6, 6, 0), V(0, 5, 0)});
  const auto Q = Polytope<double>::polygon({V(11, 3, 0), V(12, 3, 0), V(14, 5, 0), V(9, 9, 0), V(10, 5, 0)});
  GjkSettings<double> settings;
  settings.initialDirection = V(0, -1, 0);
  GjkTrace<double> trace;
  const GjkResult<double> result = gjk(P, Q, settings, nullptr, trace);
  REQUIRE(trace.iterations.size() == 6);
  const auto& it = trace.iterations;

  SECTION("i = 0: s_0 = (0,-1) is not a separating vector") {
    // S_P(0,-1): the lowest vertices of P, (0,0) and (5,0), tie at -y = 0. Hill climbing
    // starts at vertex 0 = (0,0) and moves only to a strictly better one: (0,0).
    // S_Q(0,1): the highest vertex of Q, (9,9).  w0 = (9,9) - (0,0) = (9,9).
    // SD = (0,-1).(9,9) = -9: the planes overlap, s_0 separates nothing.
    requireXY(it[0].s, 0, -1);
    requireXY(it[0].supportP, 0, 0);
    requireXY(it[0].supportQ, 9, 9);
    CHECK(it[0].supportingDistance == Approx(-9));
    requireSimplex(it[0].simplex, {V(9, 9, 0)});
    requireXY(it[0].z, 9, 9);                                        // a single point is its own closest point
    CHECK(it[0].minkowskiDistance == Approx(9 * std::sqrt(2.0)));   // 12.73
  }
  SECTION("i = 1: s_1 = z = (9,9), the first separating vector") {
    // S_P(1,1): max x+y over P is 12 at (6,6). S_Q(-(1,1)): min x+y over Q is 14 at (11,3).
    // w1 = (11,3) - (6,6) = (5,-3). SD = (9*5 + 9*(-3)) / (9 sqrt 2) = sqrt 2 > 0.
    // Closest point of the segment w0 w1: d = w1 - w0 = (-4,-12),
    // t = -w0.d / |d|^2 = 144/160 = 0.9, z = w0 + 0.9 d = (5.4, -1.8); both ends kept.
    requireXY(it[1].s, 9, 9);
    requireXY(it[1].supportP, 6, 6);
    requireXY(it[1].supportQ, 11, 3);
    CHECK(it[1].supportingDistance == Approx(std::sqrt(2.0)));
    requireSimplex(it[1].simplex, {V(9, 9, 0), V(5, -3, 0)});
    requireXY(it[1].z, 5.4, -1.8);
    CHECK(it[1].minkowskiDistance == Approx(std::sqrt(32.4)));  // 5.69
  }
  SECTION("i = 2: the triangle drops w0") {
    // s_2 = (5.4,-1.8) ~ (3,-1). S_P: max 3x-y is 15 at (5,0). S_Q(-s): min 3x-y is 18 at (9,9).
    // w2 = (9,9) - (5,0) = (4,9). SD = (3*4 - 9)/sqrt 10 = 3/sqrt 10.
    // Triangle w0 w1 w2: the origin lies beyond edge w1 w2; d = w2 - w1 = (-1,12),
    // t = -w1.d/|d|^2 = 41/145, z = (684/145, 57/145) = 57/145 (12, 1); MD = 57/sqrt 145.
    requireXY(it[2].supportP, 5, 0);
    requireXY(it[2].supportQ, 9, 9);
    CHECK(it[2].supportingDistance == Approx(3 / std::sqrt(10.0)));
    requireSimplex(it[2].simplex, {V(5, -3, 0), V(4, 9, 0)});
    requireXY(it[2].z, 684.0 / 145, 57.0 / 145);
    CHECK(it[2].minkowskiDistance == Approx(57 / std::sqrt(145.0)));  // 4.73
  }
  SECTION("i = 3") {
    // s_3 ~ (12,1). S_P: max 12x+y is 78 at (6,6). S_Q(-s): min 12x+y is 117 at (9,9).
    // w3 = (3,3). SD = (36+3)/sqrt 145 = 39/sqrt 145.
    // Triangle w1 w2 w3: closest feature is edge w1 w3; d = (-2,6), t = 28/40 = 0.7,
    // z = (5,-3) + 0.7(-2,6) = (3.6, 1.2); MD = sqrt 14.4.
    requireXY(it[3].supportP, 6, 6);
    requireXY(it[3].supportQ, 9, 9);
    CHECK(it[3].supportingDistance == Approx(39 / std::sqrt(145.0)));
    requireSimplex(it[3].simplex, {V(5, -3, 0), V(3, 3, 0)});
    requireXY(it[3].z, 3.6, 1.2);
    CHECK(it[3].minkowskiDistance == Approx(std::sqrt(14.4)));  // 3.79
  }
  SECTION("i = 4: the closest edge") {
    // s_4 ~ (3,1). S_P: max 3x+y is 24 at (6,6). S_Q(-s): min 3x+y is 35 at (10,5).
    // w4 = (4,-1). SD = (12-1)/sqrt 10 = 11/sqrt 10.
    // Triangle w1 w3 w4: closest feature is edge w3 w4; d = (1,-4), t = 9/17,
    // z = (3,3) + 9/17 (1,-4) = (60/17, 15/17); MD = 15/sqrt 17.
    requireXY(it[4].supportP, 6, 6);
    requireXY(it[4].supportQ, 10, 5);
    CHECK(it[4].supportingDistance == Approx(11 / std::sqrt(10.0)));
    requireSimplex(it[4].simplex, {V(3, 3, 0), V(4, -1, 0)});
    requireXY(it[4].z, 60.0 / 17, 15.0 / 17);
    CHECK(it[4].minkowskiDistance == Approx(15 / std::sqrt(17.0)));  // 3.638
  }
  SECTION("i = 5: no progress, GJK stops") {
    // s_5 ~ (4,1), normal to Q's edge (9,9)-(10,5): both ends tie at 4x+y = 45 (which one
    // round-off picks does not matter). S_P is (6,6). Either w is already in the simplex
    // and SD = 15/sqrt 17 = MD: the lower and upper bounds meet.
    requireXY(it[5].supportP, 6, 6);
    const bool tie = (it[5].supportQ - V(9, 9, 0)).norm() < 1e-12 || (it[5].supportQ - V(10, 5, 0)).norm() < 1e-12;
    CHECK(tie);
    CHECK(it[5].supportingDistance == Approx(15 / std::sqrt(17.0)));
    CHECK(it[5].step == GjkStep::Converged);
    requireSimplex(it[5].simplex, {V(3, 3, 0), V(4, -1, 0)});
  }
  SECTION("s_1 through s_5 are separating vectors, s_0 is not (§2.3; the paper's run stops at s_4)") {
    CHECK(it[0].supportingDistance < 0);
    for (int i = 1; i <= 5; ++i) CHECK(it[i].supportingDistance > 0);
    // The Minkowski distance decreases monotonically (§2.2).
    for (int i = 1; i < 6; ++i) CHECK(it[i].minkowskiDistance <= it[i - 1].minkowskiDistance);
  }
  SECTION("the result: distance 15/sqrt 17 between (6,6) on P and (162/17, 117/17) on Q") {
    // z = 8/17 w3 + 9/17 w4; on P both are (6,6); on Q, 8/17 (9,9) + 9/17 (10,5).
    REQUIRE(result.status == GjkStatus::Separated);
    CHECK(result.distance == Approx(15 / std::sqrt(17.0)));
    requireXY(result.witnessP, 6, 6);
    requireXY(result.witnessQ, 162.0 / 17, 117.0 / 17);
    CHECK(result.iterations == 6);
  }
}
