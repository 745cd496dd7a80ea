// The exact closest points of gjkx::reference (closest_points.hpp): cases checked by hand,
// the slivers of the fuzz findings against closed forms, and random features against an
// independent search (ternary search on convex functions, in long double).
#include <gjkx/reference/closest_points.hpp>

#include <catch2/catch.hpp>

#include <Eigen/Geometry>

#include <random>

using namespace gjkx::reference;

namespace {

// A fixed generic rotation and offset: the closed forms below hold in any frame, up to the
// round-off of moving the points there (a few eps_ld times their size).
struct Frame {
  Eigen::Matrix<Real, 3, 3> R = Eigen::AngleAxis<Real>(Real(0.7), Vec(1, 2, 3).normalized()).toRotationMatrix();
  Vec offset = Vec(Real(1234.5), Real(-678.25), Real(91.125));
  Vec operator()(const Vec& x) const { return R * x + offset; }
};

// The minimum over u in [lo, hi] of a convex f, by ternary search (200 steps: (2/3)^200 = 1e-35).
template <typename F>
Real convexMin(F f, Real lo, Real hi) {
  for (int it = 0; it < 200; ++it) {
    const Real m1 = lo + (hi - lo) / 3, m2 = hi - (hi - lo) / 3;
    if (f(m1) < f(m2))
      hi = m2;
    else
      lo = m1;
  }
  return f((lo + hi) / 2);
}

Vec randomVec(std::mt19937& rng, Real scale) {
  std::uniform_real_distribution<double> u(-1, 1);
  return Vec(Real(u(rng)), Real(u(rng)), Real(u(rng))) * scale;
}

}  // namespace

TEST_CASE("reference: point-segment by hand", "[reference]") {
  const Vec a(0, 0, 0), b(2, 0, 0);
  CHECK(pointSegmentDistance(Vec(1, 3, 4), a, b) == Approx(5.0));   // above the inside
  CHECK(pointSegmentDistance(Vec(-3, 4, 0), a, b) == Approx(5.0));  // beyond a
  CHECK(pointSegmentDistance(Vec(5, 0, 4), a, b) == Approx(5.0));   // beyond b
  CHECK(pointSegmentDistance(Vec(1, 1, 0), a, a) == Approx(std::sqrt(2.0)));  // a point
  CHECK((closestOnSegment(Vec(1.5L, 7, 0), a, b) - Vec(1.5L, 0, 0)).norm() == 0);
}

TEST_CASE("reference: point-triangle by hand", "[reference]") {
  const Vec a(0, 0, 0), b(4, 0, 0), c(0, 4, 0);
  CHECK(pointTriangleDistance(Vec(1, 1, 3), a, b, c) == Approx(3.0));    // above the inside
  CHECK(pointTriangleDistance(Vec(2, -3, 4), a, b, c) == Approx(5.0));   // beside edge ab
  CHECK(pointTriangleDistance(Vec(-3, -4, 0), a, b, c) == Approx(5.0));  // beyond vertex a
  CHECK(pointTriangleDistance(Vec(3, 3, 0), a, b, c) == Approx(std::sqrt(2.0)));  // beside edge bc, in the plane
  CHECK(pointTriangleDistance(Vec(1, 1, 0), a, b, c) == 0);              // in it
  CHECK(pointTriangleDistance(Vec(1, 2, 0), a, a, c) == Approx(1.0));    // degenerate: a segment
  CHECK(triangleNormal(a, b, c).normalized().isApprox(Vec(0, 0, 1)));
  CHECK(!projectionInsideTriangle(Vec(5, 5, 1), a, b, c));
}

TEST_CASE("reference: segment-segment by hand", "[reference]") {
  // Skew: x axis and a line parallel to y at height 3 crossing above x = 1.
  const SegmentPair skew = closestSegmentSegment(Vec(0, 0, 0), Vec(2, 0, 0), Vec(1, -1, 3), Vec(1, 1, 3));
  CHECK(skew.distance == Approx(3.0));
  CHECK((skew.onFirst - Vec(1, 0, 0)).norm() < 1e-15);
  CHECK((skew.onSecond - Vec(1, 0, 3)).norm() < 1e-15);
  // Parallel and overlapping: 2 apart.
  CHECK(segmentSegmentDistance(Vec(0, 0, 0), Vec(4, 0, 0), Vec(1, 2, 0), Vec(6, 2, 0)) == Approx(2.0));
  // Collinear, apart: end to end.
  CHECK(segmentSegmentDistance(Vec(0, 0, 0), Vec(1, 0, 0), Vec(3, 0, 0), Vec(5, 0, 0)) == Approx(2.0));
  // Crossing: 0.
  CHECK(segmentSegmentDistance(Vec(-1, 0, 0), Vec(1, 0, 0), Vec(0, -1, 0), Vec(0, 1, 0)) == 0);
  // The nearest points beyond an end: (3,4) from the end (0,0) of the first.
  CHECK(segmentSegmentDistance(Vec(0, 0, 0), Vec(-1, 0, 0), Vec(3, 4, -1), Vec(3, 4, 1)) == Approx(5.0));
  // Points as segments.
  CHECK(segmentSegmentDistance(Vec(0, 0, 0), Vec(0, 0, 0), Vec(3, 4, 0), Vec(3, 4, 0)) == Approx(5.0));
}

TEST_CASE("reference: box distances by hand", "[reference]") {
  const Vec h(1, 2, 3);
  CHECK(pointBoxDistance(Vec(0, 0, 0), h) == 0);
  CHECK(pointBoxDistance(Vec(4, 6, 3), h) == Approx(5.0));
  CHECK(segmentBoxDistance(Vec(4, -10, 0), Vec(4, 10, 0), h) == Approx(3.0));
  CHECK(segmentBoxDistance(Vec(-5, 0, 0), Vec(5, 0, 0), h) == 0);
}

TEST_CASE("reference: a point near a sliver triangle 47000 x 1e-7 (finding reference_sliver_triangle)",
          "[reference][sliver]") {
  // The triangle lies in z = 0, 47000 long and 1e-7 wide; the points' distances are exact
  // in that frame (2.1e-8 above the inside, (3e-8, 4e-8) beside the long edge: 5e-8).
  // Moved to a generic frame, the coordinates carry a round-off of a few eps_ld * 5e4 =
  // 5e-15, which bounds the error allowed (1e-14 absolute). Ericson's region tests say
  // 4.4e-8 for the first, twice the truth.
  const Frame f;
  const Vec a = f(Vec(0, 0, 0)), b = f(Vec(47000, 0, 0)), c = f(Vec(23500, Real(1e-7), 0));
  const Vec above = f(Vec(20000, Real(5e-8), Real(2.1e-8)));
  const Vec beside = f(Vec(20000, Real(-3e-8), Real(4e-8)));
  CHECK(std::abs(pointTriangleDistance(above, a, b, c) - Real(2.1e-8)) < Real(1e-14));
  CHECK(std::abs(pointTriangleDistance(beside, a, b, c) - Real(5e-8)) < Real(1e-14));
  // Every vertex order gives the same answer.
  CHECK(std::abs(pointTriangleDistance(above, c, a, b) - Real(2.1e-8)) < Real(1e-14));
  CHECK(std::abs(pointTriangleDistance(above, b, c, a) - Real(2.1e-8)) < Real(1e-14));
  // The normal from the largest angle is normal to all three edges within eps_ld.
  const Vec n = triangleNormal(a, b, c).normalized();
  CHECK(std::abs(n.dot((b - a).normalized())) < Real(1e-17));
  CHECK(std::abs(n.dot((c - a).normalized())) < Real(1e-17));
}

TEST_CASE("reference: two nearly parallel edges 2.7e5 long", "[reference][sliver]") {
  // The first edge on the x axis; the second in the plane z = h, from y = -delta to +delta
  // over a slightly longer run, so its projection crosses the first at x = 135000: the
  // distance is exactly h. The angle between them is 2 delta / 272000 (7.4e-9 and 7.4e-15
  // rad below), where Ericson's |d1|^2 |d2|^2 - (d1.d2)^2 is round-off. Bound as above:
  // a few eps_ld * 3e5 = 1e-13 from moving the points.
  const Frame f;
  for (const Real delta : {Real(1e-3), Real(1e-9)})
    for (const Real h : {Real(1e-6), Real(1e-9), Real(0.25)}) {
      const Vec p1 = f(Vec(0, 0, 0)), q1 = f(Vec(270000, 0, 0));
      const Vec p2 = f(Vec(-1000, -delta, h)), q2 = f(Vec(271000, delta, h));
      INFO("delta " << double(delta) << ", h " << double(h));
      const SegmentPair s = closestSegmentSegment(p1, q1, p2, q2);
      CHECK(std::abs(s.distance - h) < Real(1e-13));
      CHECK(std::abs((s.onSecond - s.onFirst).norm() - s.distance) == 0);
      CHECK(std::abs(segmentSegmentDistance(p2, q2, p1, q1) - h) < Real(1e-13));
      // The points lie on their segments (within the frame's round-off).
      CHECK(pointSegmentDistance(s.onFirst, p1, q1) < Real(1e-13));
      CHECK(pointSegmentDistance(s.onSecond, p2, q2) < Real(1e-13));
    }
}

TEST_CASE("reference: random features against a ternary search", "[reference]") {
  // The distance from a + u (b - a) to a convex set is convex in u (and the minimum over v
  // of a convex function of (u, v) is convex in u), so nested ternary searches find the
  // minima independently of the closest-point algebra. Half of the segment pairs are
  // nearly parallel (angle ~1e-9), a quarter of the triangles slivers 1e-6 wide. Both
  // searches stop at 1e-35 brackets, so they agree within the round-off of the norms:
  // 1e-15 times the scale is generous.
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0, 1);
  for (int trial = 0; trial < 300; ++trial) {
    const Real scale = std::pow(Real(10), Real(int(trial % 7) - 2));
    const Vec p1 = randomVec(rng, scale), q1 = randomVec(rng, scale);
    Vec p2 = randomVec(rng, scale), q2 = randomVec(rng, scale);
    if (trial % 2) q2 = p2 + (q1 - p1) * Real(1 + 0.5 * u(rng)) + randomVec(rng, scale * Real(1e-9));
    const Real search = convexMin([&](Real s) { return pointSegmentDistance(p1 + s * (q1 - p1), p2, q2); }, 0, 1);
    INFO("trial " << trial);
    CHECK(std::abs(segmentSegmentDistance(p1, q1, p2, q2) - search) <= Real(1e-15) * scale);

    const Vec a = randomVec(rng, scale), b = randomVec(rng, scale);
    Vec c = randomVec(rng, scale);
    if (trial % 4 == 0) c = a + (b - a) * Real(u(rng)) + randomVec(rng, scale * Real(1e-6));
    const Vec x = randomVec(rng, scale);
    auto inTriangle = [&](Real s) {
      return convexMin([&](Real t) { return (a + s * (b - a) + t * (c - a) - x).norm(); }, 0, 1 - s);
    };
    CHECK(std::abs(pointTriangleDistance(x, a, b, c) - convexMin(inTriangle, 0, 1)) <= Real(1e-15) * scale);
  }
}

TEST_CASE("reference: the closest point of a small hull to the origin", "[reference]") {
  // A triangle above the origin: the closest point is its interior point (0, 0, 1).
  std::array<Vec, 4> w{Vec(-1, -1, 1), Vec(2, -1, 1), Vec(-1, 2, 1), Vec::Zero()};
  HullPoint p = closestToOrigin(w, 3);
  CHECK(p.distance == Approx(1.0));
  CHECK((p.point - Vec(0, 0, 1)).norm() < 1e-15);
  CHECK(p.lambda[0] + p.lambda[1] + p.lambda[2] == Approx(1.0));
  // A tetrahedron around the origin: distance 0.
  w[3] = Vec(0, 0, -1);
  CHECK(closestToOrigin(w, 4).distance < 1e-15);
  // A segment beside the origin: its interior point (0, 1, 0).
  const std::array<Vec, 4> s{Vec(-1, 1, 0), Vec(3, 1, 0), Vec::Zero(), Vec::Zero()};
  CHECK(closestToOrigin(s, 2).distance == Approx(1.0));
}
