// The signed-volume sub-algorithm reduceToClosestFeature (§2.2; Montanari et al. 2017).
//
// Hand-checkable simplices first (a point, segments, triangles, tetrahedra, each with
// the closest point and barycentric coordinates worked out in the comments), then the
// degenerate ones where Johnson's sub-algorithm is known to fail (coincident ends,
// collinear triangle, flat tetrahedron, sliver triangle, needle tetrahedron, thin
// triangles), then a randomized property test. Every result is also held to an independent brute-force closest point
// (gjkx::reference::closestToOrigin: every sub-simplex projected by least squares in long double).
#include "to_reference.hpp"

#include <gjkx/gjk/simplex.hpp>
#include <gjkx/motion/round_off.hpp>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <limits>
#include <random>
#include <vector>

using namespace gjkx;
using gjkx::test::Real;

namespace {

// A tolerance a few dozen round-offs wide, for answers that are exact in real arithmetic.
template <typename S>
S tight() {
  return S(64) * machineEpsilon<S>();
}

// A simplex whose vertices are the given points w (p = 0, q = w, so witnessQ = z).
template <typename S>
Simplex<S> makeSimplex(const std::vector<Vector3<S>>& points) {
  Simplex<S> simplex;
  for (const auto& w : points) {
    SimplexVertex<S> v;
    v.p = Vector3<S>::Zero();
    v.q = w;
    v.w = w;
    v.s = -w;
    simplex.push(v);
  }
  return simplex;
}

template <typename S>
Simplex<S> reduced(const std::vector<Vector3<S>>& points) {
  Simplex<S> simplex = makeSimplex(points);
  reduceToClosestFeature(simplex);
  return simplex;
}

// What every reduction must satisfy, whatever the input: 1 <= size <= n, the kept
// vertices are input vertices in their input order, lambda finite, >= 0, summing to 1.
// Returns the indices of the kept input vertices.
template <typename S>
std::vector<int> checkWellFormed(const std::vector<Vector3<S>>& points, const Simplex<S>& simplex) {
  const int n = static_cast<int>(points.size());
  REQUIRE(simplex.size >= 1);
  REQUIRE(simplex.size <= n);
  std::vector<int> kept;
  int next = 0;
  for (int k = 0; k < simplex.size; ++k) {
    while (next < n && !(points[next] == simplex.vertices[k].w)) ++next;
    REQUIRE(next < n);  // an input vertex, after the previous kept one
    kept.push_back(next++);
  }
  S sum = S(0);
  for (int k = 0; k < simplex.size; ++k) {
    INFO("lambda[" << k << "] = " << simplex.lambda[k]);
    REQUIRE(std::isfinite(simplex.lambda[k]));
    CHECK(simplex.lambda[k] >= S(0));
    sum += simplex.lambda[k];
  }
  CHECK(std::abs(sum - S(1)) <= tight<S>());
  REQUIRE(simplex.closestPoint().allFinite());
  return kept;
}

// The result against the brute-force closest point: the distances agree within
// `tolerance * scale` (scale = the largest |w|), and so do the points within
// `pointTolerance * scale`. (A point of the simplex at distance d + e from the origin is
// within sqrt(2 d e + e^2) of the true closest point, so the point check is looser.)
template <typename S>
void checkAgainstBruteForce(const std::vector<Vector3<S>>& points, const Simplex<S>& simplex, Real tolerance,
                            Real pointTolerance, Real* worstDistanceError = nullptr) {
  const reference::HullPoint ref = test::closestToOrigin(points);
  Real scale = 0;
  for (const auto& w : points) scale = std::max(scale, test::toReal(w).norm());
  if (scale == 0) scale = 1;
  const test::RVec z = test::toReal(simplex.closestPoint());
  const Real error = std::abs(z.norm() - ref.distance) / scale;
  if (worstDistanceError) *worstDistanceError = std::max(*worstDistanceError, error);
  INFO("brute-force distance " << double(ref.distance) << ", sub-algorithm " << double(z.norm()) << ", scale "
                               << double(scale));
  CHECK(error <= tolerance);
  CHECK((z - ref.point).norm() / scale <= pointTolerance);
  // Only a tetrahedron that holds the origin stays a tetrahedron.
  if (simplex.size == 4) CHECK(ref.distance <= tolerance * scale);
}

}  // namespace

// --- hand-checkable simplices ------------------------------------------------------

TEMPLATE_TEST_CASE("simplex: a single point is its own closest point", "[gjk][simplex]", float, double) {
  using S = TestType;
  const std::vector<Vector3<S>> w{{1, 2, 2}};
  const Simplex<S> r = reduced(w);
  checkWellFormed(w, r);
  REQUIRE(r.size == 1);
  CHECK(r.lambda[0] == S(1));
  CHECK(r.closestPoint().norm() == Approx(3.0).epsilon(tight<S>()));
}

TEMPLATE_TEST_CASE("simplex: segment whose closest point is interior", "[gjk][simplex]", float, double) {
  // A = (-1,1,0), B = (3,1,0): the origin projects onto the line y = 1 at (0,1,0), a
  // quarter of the way from A to B, so lambda_A = 3/4, lambda_B = 1/4, distance 1.
  using S = TestType;
  const std::vector<Vector3<S>> w{{-1, 1, 0}, {3, 1, 0}};
  const Simplex<S> r = reduced(w);
  checkWellFormed(w, r);
  REQUIRE(r.size == 2);
  CHECK(r.lambda[0] == Approx(0.75).margin(tight<S>()));
  CHECK(r.lambda[1] == Approx(0.25).margin(tight<S>()));
  CHECK((r.closestPoint() - Vector3<S>(0, 1, 0)).norm() <= tight<S>());
  checkAgainstBruteForce(w, r, tight<S>(), tight<S>());
}

TEMPLATE_TEST_CASE("simplex: segment whose closest point is an end", "[gjk][simplex]", float, double) {
  // A = (1,1,0), B = (3,1,0): the projection (0,1,0) lies before A, so A is closest
  // (distance sqrt 2). Given in the other order, the kept vertex is the second one.
  using S = TestType;
  const std::vector<Vector3<S>> ab{{1, 1, 0}, {3, 1, 0}};
  const Simplex<S> r = reduced(ab);
  REQUIRE(checkWellFormed(ab, r) == std::vector<int>{0});
  CHECK(r.lambda[0] == S(1));
  CHECK(r.closestPoint() == Vector3<S>(1, 1, 0));

  const std::vector<Vector3<S>> ba{{3, 1, 0}, {1, 1, 0}};
  const Simplex<S> r2 = reduced(ba);
  REQUIRE(checkWellFormed(ba, r2) == std::vector<int>{1});
  CHECK(r2.closestPoint() == Vector3<S>(1, 1, 0));
}

TEMPLATE_TEST_CASE("simplex: triangle with the origin projecting inside", "[gjk][simplex]", float, double) {
  // A = (-1,-1,2), B = (3,-1,2), C = (-1,1,2) in the plane z = 2; the origin projects
  // to (0,0,2). Solving -lA + 3lB - lC = 0, -lA - lB + lC = 0, lA + lB + lC = 1 gives
  // lambda = (1/4, 1/4, 1/2); distance 2.
  using S = TestType;
  const std::vector<Vector3<S>> w{{-1, -1, 2}, {3, -1, 2}, {-1, 1, 2}};
  const Simplex<S> r = reduced(w);
  REQUIRE(checkWellFormed(w, r) == std::vector<int>{0, 1, 2});
  CHECK(r.lambda[0] == Approx(0.25).margin(tight<S>()));
  CHECK(r.lambda[1] == Approx(0.25).margin(tight<S>()));
  CHECK(r.lambda[2] == Approx(0.5).margin(tight<S>()));
  CHECK((r.closestPoint() - Vector3<S>(0, 0, 2)).norm() <= tight<S>());
  checkAgainstBruteForce(w, r, tight<S>(), tight<S>());
}

TEMPLATE_TEST_CASE("simplex: triangle with the origin beyond one edge", "[gjk][simplex]", float, double) {
  // A = (1,-1,1), B = (3,0,1), C = (1,1,1): the projection (0,0,1) lies beyond edge AC
  // (the line x = 1), whose closest point is its midpoint (1,0,1): keep {A, C},
  // lambda = (1/2, 1/2), distance sqrt 2.
  using S = TestType;
  const std::vector<Vector3<S>> w{{1, -1, 1}, {3, 0, 1}, {1, 1, 1}};
  const Simplex<S> r = reduced(w);
  REQUIRE(checkWellFormed(w, r) == std::vector<int>{0, 2});
  CHECK(r.lambda[0] == Approx(0.5).margin(tight<S>()));
  CHECK(r.lambda[1] == Approx(0.5).margin(tight<S>()));
  CHECK((r.closestPoint() - Vector3<S>(1, 0, 1)).norm() <= tight<S>());
  checkAgainstBruteForce(w, r, tight<S>(), tight<S>());
}

TEMPLATE_TEST_CASE("simplex: triangle with the origin in a vertex region", "[gjk][simplex]", float, double) {
  // A = (1,1,1), B = (3,1,1), C = (1,3,1): both edges from A run away from the
  // projection (0,0,1) (x >= 1 and y >= 1 on the triangle), so A is closest: distance sqrt 3.
  using S = TestType;
  const std::vector<Vector3<S>> w{{1, 1, 1}, {3, 1, 1}, {1, 3, 1}};
  const Simplex<S> r = reduced(w);
  REQUIRE(checkWellFormed(w, r) == std::vector<int>{0});
  CHECK(r.closestPoint() == Vector3<S>(1, 1, 1));
}

TEMPLATE_TEST_CASE("simplex: tetrahedron containing the origin stays a tetrahedron", "[gjk][simplex]", float,
                   double) {
  // The regular tetrahedron (1,1,1), (1,-1,-1), (-1,1,-1), (-1,-1,1) is centred on the
  // origin: all four kept, lambda = 1/4 each, z = 0.
  using S = TestType;
  const std::vector<Vector3<S>> w{{1, 1, 1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1}};
  const Simplex<S> r = reduced(w);
  REQUIRE(checkWellFormed(w, r) == std::vector<int>{0, 1, 2, 3});
  for (int k = 0; k < 4; ++k) CHECK(r.lambda[k] == Approx(0.25).margin(tight<S>()));
  CHECK(r.closestPoint().norm() <= tight<S>());

  // Moved off-centre (the origin still inside): lambda are the origin's barycentric
  // coordinates, so sum lambda_k w_k = 0.
  std::vector<Vector3<S>> shifted = w;
  for (auto& v : shifted) v += Vector3<S>(S(0.3), S(-0.2), S(0.1));
  const Simplex<S> r2 = reduced(shifted);
  REQUIRE(checkWellFormed(shifted, r2).size() == 4);
  CHECK(r2.closestPoint().norm() <= tight<S>());
}

TEMPLATE_TEST_CASE("simplex: tetrahedron whose closest feature is a face, an edge or a vertex", "[gjk][simplex]",
                   float, double) {
  using S = TestType;
  {
    // Face: the triangle of the "inside" case above with an apex at (0,0,5) away from the
    // origin: keep A, B, C with lambda (1/4, 1/4, 1/2), distance 2.
    const std::vector<Vector3<S>> w{{-1, -1, 2}, {3, -1, 2}, {-1, 1, 2}, {0, 0, 5}};
    const Simplex<S> r = reduced(w);
    REQUIRE(checkWellFormed(w, r) == std::vector<int>{0, 1, 2});
    CHECK(r.lambda[2] == Approx(0.5).margin(tight<S>()));
    CHECK((r.closestPoint() - Vector3<S>(0, 0, 2)).norm() <= tight<S>());
    checkAgainstBruteForce(w, r, tight<S>(), tight<S>());
  }
  {
    // Edge: every point has x >= 1 and z >= 1, with x = z = 1 only on edge AC
    // (A = (1,-1,1), C = (1,1,1)); its midpoint (1,0,1) is closest, distance sqrt 2.
    const std::vector<Vector3<S>> w{{1, -1, 1}, {3, 0, 1}, {1, 1, 1}, {2, 0, 3}};
    const Simplex<S> r = reduced(w);
    REQUIRE(checkWellFormed(w, r) == std::vector<int>{0, 2});
    CHECK((r.closestPoint() - Vector3<S>(1, 0, 1)).norm() <= tight<S>());
    checkAgainstBruteForce(w, r, tight<S>(), tight<S>());
  }
  {
    // Vertex: every point has x, y, z >= 1, with equality only at A = (1,1,1): distance sqrt 3.
    const std::vector<Vector3<S>> w{{1, 1, 1}, {3, 1, 1}, {1, 3, 1}, {1, 1, 3}};
    const Simplex<S> r = reduced(w);
    REQUIRE(checkWellFormed(w, r) == std::vector<int>{0});
    CHECK(r.closestPoint() == Vector3<S>(1, 1, 1));
  }
}

// --- degenerate simplices ------------------------------------------------------------

TEMPLATE_TEST_CASE("simplex: degenerate segment with coincident ends", "[gjk][simplex][degenerate]", float, double) {
  // A = B = (1,2,2): a point, distance 3.
  using S = TestType;
  const std::vector<Vector3<S>> w{{1, 2, 2}, {1, 2, 2}};
  const Simplex<S> r = reduced(w);
  checkWellFormed(w, r);
  CHECK((r.closestPoint() - Vector3<S>(1, 2, 2)).norm() <= tight<S>());
  checkAgainstBruteForce(w, r, tight<S>(), tight<S>());
}

TEMPLATE_TEST_CASE("simplex: collinear triangle", "[gjk][simplex][degenerate]", float, double) {
  // Three points on the line y = 1, z = 0: the closest point is (0,1,0), distance 1,
  // whichever edge holds it. With the middle point first or repeated the answer is the same.
  using S = TestType;
  const std::vector<std::vector<Vector3<S>>> cases{
      {{-1, 1, 0}, {1, 1, 0}, {3, 1, 0}},
      {{1, 1, 0}, {-1, 1, 0}, {3, 1, 0}},
      {{-1, 1, 0}, {-1, 1, 0}, {3, 1, 0}},
      {{-3, 1, 0}, {-2, 1, 0}, {3, 1, 0}},
  };
  for (const auto& w : cases) {
    const Simplex<S> r = reduced(w);
    checkWellFormed(w, r);
    CHECK((r.closestPoint() - Vector3<S>(0, 1, 0)).norm() <= tight<S>());
    checkAgainstBruteForce(w, r, tight<S>(), tight<S>());
  }
  // All three on a line through the origin: distance 0.
  const std::vector<Vector3<S>> through{{-1, -2, 3}, {1, 2, -3}, {2, 4, -6}};
  const Simplex<S> r = reduced(through);
  checkWellFormed(through, r);
  CHECK(r.closestPoint().norm() <= tight<S>());
}

TEMPLATE_TEST_CASE("simplex: flat (coplanar) tetrahedron", "[gjk][simplex][degenerate]", float, double) {
  using S = TestType;
  {
    // In the plane z = 1, D inside triangle ABC: the closest point is the projection
    // (0,0,1), inside the flat tetrahedron; distance 1.
    const std::vector<Vector3<S>> w{{-1, -1, 1}, {3, -1, 1}, {-1, 3, 1}, {1, 1, 1}};
    const Simplex<S> r = reduced(w);
    checkWellFormed(w, r);
    CHECK(r.size <= 3);
    CHECK((r.closestPoint() - Vector3<S>(0, 0, 1)).norm() <= tight<S>());
    checkAgainstBruteForce(w, r, tight<S>(), tight<S>());
  }
  {
    // In the plane z = 0 around the origin: distance 0.
    const std::vector<Vector3<S>> w{{-1, -1, 0}, {2, -1, 0}, {-1, 2, 0}, {S(0.5), S(0.5), 0}};
    const Simplex<S> r = reduced(w);
    checkWellFormed(w, r);
    CHECK(r.closestPoint().norm() <= tight<S>());
  }
  {
    // In the plane x + y + z = 3 (not axis aligned): the origin projects to (1,1,1), the
    // midpoint of the edge from (2,0,1) to (0,2,1), on the boundary: distance sqrt 3.
    const std::vector<Vector3<S>> w{{2, 0, 1}, {0, 2, 1}, {3, 1, -1}, {1, 3, -1}};
    const Simplex<S> r = reduced(w);
    checkWellFormed(w, r);
    CHECK((r.closestPoint() - Vector3<S>(1, 1, 1)).norm() <= tight<S>());
    checkAgainstBruteForce(w, r, tight<S>(), tight<S>());
  }
}

TEMPLATE_TEST_CASE("simplex: sliver triangle with a tiny area", "[gjk][simplex][degenerate]", float, double) {
  using S = TestType;
  {
    // A = (-1,-h,1), B = (1,-h,1), C = (0,h,1), h = 1e-9: the projection (0,0,1) is
    // inside (or, in float where h is lost against 1, on) the sliver: distance 1.
    const S h = S(1e-9);
    const std::vector<Vector3<S>> w{{-1, -h, 1}, {1, -h, 1}, {0, h, 1}};
    const Simplex<S> r = reduced(w);
    checkWellFormed(w, r);
    CHECK((r.closestPoint() - Vector3<S>(0, 0, 1)).norm() <= tight<S>());
    checkAgainstBruteForce(w, r, tight<S>(), tight<S>());
  }
  {
    // The same sliver, long (length 2) and tilted out of the axes by a rotation; the
    // origin 1e-3 off its plane. Only the brute force knows the answer.
    const Matrix3<S> R = Eigen::AngleAxis<S>(S(0.7), Vector3<S>(1, 2, 3).normalized()).toRotationMatrix();
    const Vector3<S> offset(S(0.1), S(0.2), S(1e-3));
    const std::vector<Vector3<S>> w{R * Vector3<S>(-1, S(-1e-9), 0) + R * offset,
                                    R * Vector3<S>(1, S(-1e-9), 0) + R * offset,
                                    R * Vector3<S>(S(0.3), S(1e-9), 0) + R * offset};
    const Simplex<S> r = reduced(w);
    checkWellFormed(w, r);
    checkAgainstBruteForce(w, r, tight<S>(), std::sqrt(tight<S>()));
  }
}

TEMPLATE_TEST_CASE("simplex: needle tetrahedra (four points on a line)", "[gjk][simplex][degenerate]", float,
                   double) {
  // Four points c + t_k d on the line with direction d = (0.3, -0.7, 0.45) through
  // c = 0.01 n, n a unit vector normal to d (so the origin projects onto the line at c,
  // at distance 0.01). Rounding leaves them a hair off the line: a tetrahedron whose
  // volume is round-off, so the signs of its sub-volumes are noise. The hull is the
  // segment from t_min to t_max: its closest point is c when t_min <= 0 <= t_max,
  // else the nearer end.
  using S = TestType;
  std::mt19937 rng(42);
  std::uniform_real_distribution<double> u(-1.5, 1.5);
  const Eigen::Vector3d d(0.3, -0.7, 0.45);
  const Eigen::Vector3d c = 0.01 * d.cross(Eigen::Vector3d(0.2, 0.9, -0.3)).normalized();
  for (int trial = 0; trial < 200; ++trial) {
    std::vector<Vector3<S>> w;
    double tMin = 1e300, tMax = -1e300;
    for (int k = 0; k < 4; ++k) {
      const double t = u(rng);
      w.push_back((c + t * d).cast<S>());
      tMin = std::min(tMin, t), tMax = std::max(tMax, t);
    }
    const double tClosest = std::min(std::max(0.0, tMin), tMax);
    const Vector3<S> expected = (c + tClosest * d).cast<S>();
    INFO("trial " << trial << ": t in [" << tMin << ", " << tMax << "]");
    const Simplex<S> r = reduced(w);
    checkWellFormed(w, r);
    // The points themselves are c + t d only to round-off (1e-16 / 1e-7 of 3).
    CHECK((r.closestPoint() - expected).norm() <= S(16) * tight<S>());
    CHECK(r.size < 4);  // GJK would read a kept tetrahedron as "the origin is inside"
  }
}

TEMPLATE_TEST_CASE("simplex: thin triangles keep lambda summing to 1", "[gjk][simplex][degenerate]", float,
                   double) {
  // Triangles 1e-3 as wide as they are long, the origin next to a random point of them.
  // Their signed areas are good only to about epsilon / 1e-3 of their size, so the
  // distance is held to 1e3 times the usual tolerance; but lambda must still be >= 0
  // and sum to 1 (so z is a point of the triangle) to round-off.
  using S = TestType;
  std::mt19937 rng(42);
  std::uniform_real_distribution<double> u(-1, 1);
  const Real tolerance = Real(1024) * Real(1e3) * machineEpsilon<S>();
  for (int trial = 0; trial < 2000; ++trial) {
    const double scale = std::pow(10.0, 2 * u(rng));
    const Eigen::Vector3d a = Eigen::Vector3d(u(rng), u(rng), u(rng)) * scale;
    const Eigen::Vector3d b = Eigen::Vector3d(u(rng), u(rng), u(rng)) * scale;
    const Eigen::Vector3d side = (b - a).cross(Eigen::Vector3d(u(rng), u(rng), u(rng))).normalized();
    const Eigen::Vector3d c = a + (b - a) * (1.5 * u(rng)) + side * (1e-3 * (b - a).norm());
    const double la = std::abs(u(rng)), lb = std::abs(u(rng)), lc = std::abs(u(rng));
    const Eigen::Vector3d origin = (la * a + lb * b + lc * c) / (la + lb + lc) +
                                   Eigen::Vector3d(u(rng), u(rng), u(rng)) * scale * std::pow(10.0, -4 * std::abs(u(rng)));
    const std::vector<Vector3<S>> w{(a - origin).cast<S>(), (b - origin).cast<S>(), (c - origin).cast<S>()};
    INFO("trial " << trial);
    const Simplex<S> r = reduced(w);
    checkWellFormed(w, r);
    checkAgainstBruteForce(w, r, tolerance, std::sqrt(tolerance));
  }
}

// --- randomized property test --------------------------------------------------------

namespace {

// Random simplices of 1 to 4 points, about half of them exactly or nearly degenerate
// (a repeated point, collinear, coplanar, a sliver, a needle), of sizes 1e-2 to 1e2.
// Half are placed at random (the origin far, near or inside), half with the origin
// moved next to a random point of the hull (1e-6 to 1 of the size away), where the
// sub-volumes' signs are the least clear.
template <typename S>
std::vector<Vector3<S>> randomSimplex(std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-1, 1);
  const int n = std::uniform_int_distribution<int>(1, 4)(rng);
  const double scale = std::pow(10.0, 2 * u(rng));
  std::vector<Eigen::Vector3d> p;
  for (int k = 0; k < n; ++k) p.push_back(Eigen::Vector3d(u(rng), u(rng), u(rng)) * scale);
  const int mode = std::uniform_int_distribution<int>(0, 9)(rng);  // 5..9: general position
  if (n >= 2 && mode == 0) p[n - 1] = p[0];                                             // repeated point
  if (n >= 3 && mode == 1) p[n - 1] = p[0] + (p[1] - p[0]) * (1.5 * u(rng));           // collinear
  if (n == 4 && mode == 2) p[3] = p[0] + (p[1] - p[0]) * u(rng) + (p[2] - p[0]) * u(rng);  // coplanar
  if (n >= 3 && mode == 3) {  // sliver: the last point 1e-9 of the size off a line
    const Eigen::Vector3d side = (p[1] - p[0]).cross(Eigen::Vector3d(u(rng), u(rng), u(rng))).normalized();
    p[n - 1] = p[0] + (p[1] - p[0]) * (1.5 * u(rng)) + side * (1e-9 * scale);
  }
  if (n == 4 && mode == 4) {  // needle: the last two points on the line through the first two
    p[2] = p[0] + (p[1] - p[0]) * (1.5 * u(rng));
    p[3] = p[0] + (p[1] - p[0]) * (1.5 * u(rng));
  }
  Eigen::Vector3d origin;  // where the origin goes
  if (u(rng) < 0) {
    origin = Eigen::Vector3d(u(rng), u(rng), u(rng)) * scale * (1 + u(rng));
  } else {
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    double weight = 0;
    for (const auto& x : p) {
      const double a = std::abs(u(rng));
      sum += a * x, weight += a;
    }
    origin = sum / weight + Eigen::Vector3d(u(rng), u(rng), u(rng)) * scale * std::pow(10.0, -6 * std::abs(u(rng)));
  }
  std::vector<Vector3<S>> out;
  for (const auto& x : p) out.push_back((x - origin).cast<S>());
  return out;
}

}  // namespace

TEMPLATE_TEST_CASE("simplex: random simplices match the brute-force closest point", "[gjk][simplex][random]",
                   float, double) {
  // Distances agree within 1e3 round-offs of the simplex's size; the points within
  // sqrt of that (see checkAgainstBruteForce). Sizes and counts are printed.
  using S = TestType;
  std::mt19937 rng(42);
  const Real tolerance = Real(1024) * machineEpsilon<S>();
  const Real pointTolerance = std::sqrt(tolerance);
  Real worst = 0;
  int sizes[5] = {0, 0, 0, 0, 0};
  for (int trial = 0; trial < 4000; ++trial) {
    const std::vector<Vector3<S>> w = randomSimplex<S>(rng);
    INFO("trial " << trial << ", " << w.size() << " points");
    const Simplex<S> r = reduced(w);
    checkWellFormed(w, r);
    checkAgainstBruteForce(w, r, tolerance, pointTolerance, &worst);
    ++sizes[r.size];
  }
  std::cout << "simplex random (" << (sizeof(S) == 4 ? "float" : "double") << "): kept sizes 1/2/3/4 = " << sizes[1]
            << "/" << sizes[2] << "/" << sizes[3] << "/" << sizes[4]
            << ", worst distance error / scale = " << double(worst) << "\n";
  CHECK(sizes[4] > 0);  // the generator does put the origin inside some tetrahedra
}

TEMPLATE_TEST_CASE("simplex: the same answer at every scale (powers of two)", "[gjk][simplex][random][scale]", float,
                   double) {
  // Scaling every w by a power of two is exact, so the reduction must keep the same
  // vertices with the same coordinates and scale z by the same power. The signs are
  // trusted by comparing products of up to six lengths, which in float underflow on
  // shapes 1e-8 across and overflow at 1e7 (a fuzz finding: a tetrahedron around the
  // origin at size 1e-8 was taken for flat); the sub-algorithm works in units of the
  // simplex's size. Scales 2^-60 to 2^60 in float (1e-18 to 1e18), 2^-400 to 2^400 in double.
  using S = TestType;
  std::mt19937 rng(7);
  const int reach = sizeof(S) == 4 ? 60 : 400;
  for (int trial = 0; trial < 1000; ++trial) {
    const std::vector<Vector3<S>> w = randomSimplex<S>(rng);
    const Simplex<S> unit = reduced(w);
    for (int e = -reach; e <= reach; e += reach / 4) {
      std::vector<Vector3<S>> scaled;
      for (const auto& x : w) scaled.push_back(x * std::ldexp(S(1), e));
      const Simplex<S> r = reduced(scaled);
      INFO("trial " << trial << ", " << w.size() << " points, scale 2^" << e);
      REQUIRE(r.size == unit.size);
      for (int k = 0; k < r.size; ++k) {
        CHECK(r.vertices[k].w == scaled[std::distance(w.begin(), std::find(w.begin(), w.end(), unit.vertices[k].w))]);
        CHECK(r.lambda[k] == unit.lambda[k]);
      }
      CHECK(r.z == Vector3<S>(unit.z * std::ldexp(S(1), e)));
    }
  }
}

TEMPLATE_TEST_CASE("simplex: the sub-algorithm's units, a power of two read from the exponent", "[gjk][simplex]",
                   float, double) {
  // unitsFor(x) brings x into [1, 2); 1 where there is no such power or none is needed.
  using S = TestType;
  CHECK(detail::unitsFor(S(1)) == S(1));
  CHECK(detail::unitsFor(S(3)) == S(0.5));
  CHECK(detail::unitsFor(S(0.75)) == S(2));
  CHECK(detail::unitsFor(S(1e-8)) * S(1e-8) >= S(1));
  CHECK(detail::unitsFor(S(1e-8)) * S(1e-8) < S(2));
  CHECK(detail::unitsFor(S(1e30)) * S(1e30) >= S(1));
  CHECK(detail::unitsFor(S(1e30)) * S(1e30) < S(2));
  CHECK(detail::unitsFor(std::numeric_limits<S>::min()) * std::numeric_limits<S>::min() == S(1));
  CHECK(detail::unitsFor(S(0)) == S(1));
  CHECK(detail::unitsFor(std::numeric_limits<S>::denorm_min()) == S(1));
  CHECK(detail::unitsFor(std::numeric_limits<S>::infinity()) == S(1));
  CHECK(detail::unitsFor(std::numeric_limits<S>::max()) == S(1));  // 2^-max_exponent is subnormal
  for (int e = std::numeric_limits<S>::min_exponent; e < std::numeric_limits<S>::max_exponent - 1; ++e) {
    const S x = std::ldexp(S(1.5), e - 1);
    INFO("x = 1.5 * 2^" << (e - 1));
    CHECK(detail::unitsFor(x) == std::ldexp(S(1), 1 - e));
  }
}

// A fuzz finding (finding-gjk_tiny_triangle_far): a triangle 5e-5 across at x = -748138.4375,
// a sliver, in float. Its normal is about 1e-22 in the sub-algorithm's units, and its
// square fell into float's subnormals: the projection of the origin onto the plane came
// out at 0.69 of its distance. Every point of the triangle is at least 748138.4375 from
// the origin, so |z| must be too (up to float's rounding there).
TEMPLATE_TEST_CASE("simplex: a tiny triangle far from the origin keeps its distance", "[gjk][simplex][scale]", float,
                   double) {
  using S = TestType;
  const S x = S(-748138.4375);
  const std::vector<Vector3<S>> points{Vector3<S>(x, S(2.6276335e-05), S(6.3955784e-05)),
                                       Vector3<S>(x, S(-2.6304275e-05), S(-6.3955784e-05)),
                                       Vector3<S>(x, S(-2.6155263e-05), S(-6.3756015e-05))};
  const Simplex<S> simplex = reduced(points);
  checkWellFormed(points, simplex);
  INFO((sizeof(S) == sizeof(float) ? "float" : "double") << ": |z| = " << simplex.z.norm());
  CHECK(double(simplex.z.norm()) >= 748138.4375 * (1 - 4 * double(machineEpsilon<S>())));
  CHECK(double(simplex.z.norm()) <= 748138.4375 * (1 + 4 * double(machineEpsilon<S>())) + 1e-3);
}
