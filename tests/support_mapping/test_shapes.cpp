// Tests of the support mappings of §2.1: S_X(s) is a point of X farthest along s,
// s·S_X(s) = max{s·x : x in X}. Hand values in the six axis directions first, then
// the defining property on random directions, then placement, the run-time variant,
// moving shapes and bad input.
#include <gjkx/support_mapping/placed.hpp>
#include <gjkx/support_mapping/polytope.hpp>
#include <gjkx/support_mapping/primitives.hpp>
#include <gjkx/support_mapping/shape.hpp>

#include <catch2/catch.hpp>

#include "shape_test_helpers.hpp"

#include <cmath>
#include <functional>
#include <limits>
#include <random>
#include <vector>

using namespace gjkx;
using gjkx::test::kPi;
using gjkx::test::randomDirection;
using gjkx::test::tol;
using Catch::Matchers::Contains;

namespace {
template <typename S>
using Vec = Vector3<S>;

template <typename S>
bool near(const Vec<S>& a, const Vec<S>& b, S scale = S(1)) {
  return (a - b).norm() <= tol<S>() * scale;
}

// The six axis directions in the order +x, -x, +y, -y, +z, -z.
template <typename S>
std::vector<Vec<S>> axisDirections() {
  return {Vec<S>(1, 0, 0), Vec<S>(-1, 0, 0), Vec<S>(0, 1, 0), Vec<S>(0, -1, 0), Vec<S>(0, 0, 1), Vec<S>(0, 0, -1)};
}

template <typename S>
S uniform(std::mt19937& rng, S lo, S hi) {
  return std::uniform_real_distribution<S>(lo, hi)(rng);
}

// A random point of the unit ball.
template <typename S>
Vec<S> inBall(std::mt19937& rng) {
  Vec<S> x;
  do x = Vec<S>(uniform<S>(rng, -1, 1), uniform<S>(rng, -1, 1), uniform<S>(rng, -1, 1));
  while (x.squaredNorm() > S(1));
  return x;
}

// Checks each axis direction against its hand value.
template <typename X>
void checkAxes(const X& shape, const std::vector<Vec<typename X::Scalar>>& expected) {
  using S = typename X::Scalar;
  const auto dirs = axisDirections<S>();
  REQUIRE(expected.size() == dirs.size());
  for (size_t i = 0; i < dirs.size(); ++i) {
    INFO("direction " << dirs[i].transpose() << ": got " << shape.support(dirs[i]).transpose() << ", expected "
                      << expected[i].transpose());
    CHECK(near<S>(shape.support(dirs[i]), expected[i]));
  }
}

// The support property on random directions: s·S(s) >= s·x for every sample point x of
// the shape, and s·S(s) equals `value(s)` (the shape's closed-form support value).
template <typename X>
void checkSupportProperty(const X& shape, const std::function<Vec<typename X::Scalar>(std::mt19937&)>& sample,
                          const std::function<typename X::Scalar(const Vec<typename X::Scalar>&)>& value) {
  using S = typename X::Scalar;
  std::mt19937 rng(12345);
  std::vector<Vec<S>> samples;
  for (int i = 0; i < 200; ++i) samples.push_back(sample(rng));
  int failures = 0;
  for (int k = 0; k < 500; ++k) {
    const Vec<S> s = randomDirection<S>(rng);
    const S top = s.dot(shape.support(s));
    if (std::abs(top - value(s)) > tol<S>() * S(10) * s.norm()) ++failures;
    for (const Vec<S>& x : samples)
      if (s.dot(x) > top + tol<S>() * S(10) * s.norm()) ++failures;
  }
  CHECK(failures == 0);
}

template <typename S>
Polytope<S> octahedron() {
  // Half axes 1, 2, 3 so that each axis direction has one supporting vertex.
  return Polytope<S>::hull({Vec<S>(1, 0, 0), Vec<S>(-1, 0, 0), Vec<S>(0, 2, 0), Vec<S>(0, -2, 0), Vec<S>(0, 0, 3),
                            Vec<S>(0, 0, -3)});
}
}  // namespace

// Each shape in the six axis directions, against values read off a sketch. On a tie
// (an edge or face facing s) the documented rule picks: the first end/vertex for
// segments and triangles, +h on a zero component for the box.
TEMPLATE_TEST_CASE("support of each shape in the six axis directions", "[shapes]", float, double) {
  using S = TestType;
  using V = Vec<S>;

  SECTION("point: always the point") {
    const Point<S> p(V(1, 2, 3));
    checkAxes(p, std::vector<V>(6, V(1, 2, 3)));
    CHECK(p.center() == V(1, 2, 3));
  }
  SECTION("segment: the end farther along s, a on a tie") {
    const Segment<S> seg(V(-1, 0, 0), V(1, 2, 0));
    checkAxes(seg, {V(1, 2, 0), V(-1, 0, 0), V(1, 2, 0), V(-1, 0, 0), V(-1, 0, 0), V(-1, 0, 0)});
    CHECK(near<S>(seg.center(), V(0, 1, 0)));
  }
  SECTION("triangle: the vertex farthest along s, the first on a tie") {
    const Triangle<S> tri(V(0, 0, 0), V(2, 0, 0), V(0, 3, 1));
    // -x ties a and c (both x = 0): a. -y ties a and b: a. -z ties a and b: a.
    checkAxes(tri, {V(2, 0, 0), V(0, 0, 0), V(0, 3, 1), V(0, 0, 0), V(0, 3, 1), V(0, 0, 0)});
    CHECK(near<S>(tri.center(), V(S(2) / 3, 1, S(1) / 3)));
  }
  SECTION("box: the corner in the octant of s, +h on a zero component") {
    const Box<S> box(V(1, 2, 3));
    checkAxes(box, {V(1, 2, 3), V(-1, 2, 3), V(1, 2, 3), V(1, -2, 3), V(1, 2, 3), V(1, 2, -3)});
    CHECK(box.center() == V::Zero());
  }
  SECTION("sphere: r s / |s|") {
    const Sphere<S> ball(S(2));
    checkAxes(ball, {V(2, 0, 0), V(-2, 0, 0), V(0, 2, 0), V(0, -2, 0), V(0, 0, 2), V(0, 0, -2)});
    // The length of s does not matter.
    CHECK(near<S>(ball.support(V(0, 0, 100)), V(0, 0, 2)));
    CHECK(ball.support(V::Zero()) == V::Zero());  // the centre for s = 0
  }
  SECTION("capsule: axis end plus r s / |s|") {
    const Capsule<S> cap(V(0, 0, -1), V(0, 0, 1), S(0.5));
    // Sideways the two ends tie: the first end a = (0,0,-1) is kept.
    checkAxes(cap, {V(0.5, 0, -1), V(-0.5, 0, -1), V(0, 0.5, -1), V(0, -0.5, -1), V(0, 0, 1.5), V(0, 0, -1.5)});
    CHECK(cap.center() == V::Zero());
    CHECK(cap.support(V::Zero()) == V(0, 0, -1));  // s = 0: just the axis end
  }
  SECTION("cylinder: a rim point, the top on a zero s_z, a cap's centre along the axis") {
    const Cylinder<S> cyl(S(0.5), S(2));
    checkAxes(cyl, {V(0.5, 0, 2), V(-0.5, 0, 2), V(0, 0.5, 2), V(0, -0.5, 2), V(0, 0, 2), V(0, 0, -2)});
    CHECK(cyl.center() == V::Zero());
    CHECK(cyl.support(V::Zero()) == V(0, 0, 2));  // s = 0: the top cap's centre
    CHECK(near<S>(cyl.support(V(3, 4, -1)), V(0.3, 0.4, -2)));  // by hand: r (3, 4) / 5, bottom
    CHECK(cyl.boundingRadius() == Approx(std::sqrt(4.25)));
  }
  SECTION("polytope: the octahedron with half axes 1, 2, 3") {
    const Polytope<S> oct = octahedron<S>();
    REQUIRE(oct.vertexCount() == 6);
    checkAxes(oct, {V(1, 0, 0), V(-1, 0, 0), V(0, 2, 0), V(0, -2, 0), V(0, 0, 3), V(0, 0, -3)});
    CHECK(near<S>(oct.center(), V::Zero()));
    // The same from every hint.
    for (SupportHint h = -1; h <= 6; ++h) {
      SupportHint hint = h;
      CHECK(oct.support(V(0, 0, -1), hint) == V(0, 0, -3));
      CHECK(oct.vertex(hint) == V(0, 0, -3));  // the hint is now the vertex found
    }
  }
}

// The defining property on random directions: no sample point of the shape lies
// farther along s than S(s), and s·S(s) is the closed-form support value
// (box: sum |s_k| h_k; sphere: r|s|; capsule: max(s·a, s·b) + r|s|; polytope: max over vertices).
TEMPLATE_TEST_CASE("support property on random directions", "[shapes]", float, double) {
  using S = TestType;
  using V = Vec<S>;

  SECTION("point") {
    const V a(1, -2, 0.5);
    checkSupportProperty<Point<S>>(
        Point<S>(a), [&](std::mt19937&) { return a; }, [&](const V& s) { return s.dot(a); });
  }
  SECTION("segment") {
    const V a(-1, 0.5, 2), b(3, 1, -1);
    checkSupportProperty<Segment<S>>(
        Segment<S>(a, b), [&](std::mt19937& rng) { return V(a + uniform<S>(rng, 0, 1) * (b - a)); },
        [&](const V& s) { return std::max(s.dot(a), s.dot(b)); });
  }
  SECTION("triangle") {
    const V a(0, 0, 0), b(2, 1, 0), c(-1, 3, 2);
    checkSupportProperty<Triangle<S>>(
        Triangle<S>(a, b, c),
        [&](std::mt19937& rng) {
          S u = uniform<S>(rng, 0, 1), v = uniform<S>(rng, 0, 1);
          if (u + v > 1) u = 1 - u, v = 1 - v;
          return V(a + u * (b - a) + v * (c - a));
        },
        [&](const V& s) { return std::max({s.dot(a), s.dot(b), s.dot(c)}); });
  }
  SECTION("box") {
    const V h(0.5, 2, 1);
    checkSupportProperty<Box<S>>(
        Box<S>(h),
        [&](std::mt19937& rng) {
          // Corners included: the extreme points of the box.
          return V(uniform<S>(rng, -1, 1) * h.x(), uniform<S>(rng, -1, 1) * h.y(), uniform<S>(rng, -1, 1) * h.z());
        },
        [&](const V& s) { return s.cwiseAbs().dot(h); });
  }
  SECTION("sphere") {
    const S r = 1.5;
    checkSupportProperty<Sphere<S>>(
        Sphere<S>(r), [&](std::mt19937& rng) { return V(r * inBall<S>(rng)); },
        [&](const V& s) { return r * s.norm(); });
  }
  SECTION("capsule") {
    const V a(1, 0, 0), b(-1, 2, 1);
    const S r = 0.75;
    checkSupportProperty<Capsule<S>>(
        Capsule<S>(a, b, r),
        [&](std::mt19937& rng) { return V(a + uniform<S>(rng, 0, 1) * (b - a) + r * inBall<S>(rng)); },
        [&](const V& s) { return std::max(s.dot(a), s.dot(b)) + r * s.norm(); });
  }
  SECTION("cylinder") {
    const S r = 0.75, h = 1.25;
    checkSupportProperty<Cylinder<S>>(
        Cylinder<S>(r, h),
        [&](std::mt19937& rng) {
          // Points of the solid, the rims included (its extreme points).
          const S angle = uniform<S>(rng, 0, S(2 * kPi)), rho = r * std::sqrt(uniform<S>(rng, 0, 1));
          return V(rho * std::cos(angle), rho * std::sin(angle), uniform<S>(rng, -1, 1) * h);
        },
        [&](const V& s) { return r * std::hypot(s.x(), s.y()) + h * std::abs(s.z()); });
  }
  SECTION("polytope") {
    std::mt19937 pointRng(7);
    std::vector<V> points;
    for (int i = 0; i < 40; ++i) points.push_back(V(S(2) * inBall<S>(pointRng)));
    const Polytope<S> poly = Polytope<S>::hull(points);
    checkSupportProperty<Polytope<S>>(
        poly,
        [&](std::mt19937& rng) {
          // Every input point is in the hull, and so are convex combinations of two.
          const V& p = points[rng() % points.size()];
          const V& q = points[rng() % points.size()];
          return V(p + uniform<S>(rng, 0, 1) * (q - p));
        },
        [&](const V& s) {
          S best = -std::numeric_limits<S>::infinity();
          for (const V& x : points) best = std::max(best, s.dot(x));
          return best;
        });
  }
}

// The cylinder against brute force: its two rims sampled at 4,096 points each (a
// cylinder's extreme points are its rims). Along every direction the best sample may fall
// short of the support value by at most the sampling's sag, r (1 - cos(pi / 4096)) |s|,
// never pass it, and the support point itself is a point of the cylinder.
TEMPLATE_TEST_CASE("cylinder: support against brute force on a sampled cylinder", "[shapes]", float, double) {
  using S = TestType;
  using V = Vec<S>;
  const S r = 0.4, h = 0.9;
  const Cylinder<S> cyl(r, h);
  const int n = 4096;
  std::vector<V> rims;
  for (int k = 0; k < n; ++k) {
    const double angle = 2 * kPi * k / n;
    for (const S z : {-h, h}) rims.push_back(V(S(r * std::cos(angle)), S(r * std::sin(angle)), z));
  }
  std::mt19937 rng(2024);
  const S sag = S(r * (1 - std::cos(kPi / n)));
  for (int k = 0; k < 300; ++k) {
    const V s = randomDirection<S>(rng);
    const V x = cyl.support(s);
    S best = -std::numeric_limits<S>::infinity();
    for (const V& p : rims) best = std::max(best, s.dot(p));
    INFO("s = " << s.transpose() << ", S(s) = " << x.transpose());
    CHECK(s.dot(x) >= best - tol<S>() * S(10) * s.norm());
    CHECK(s.dot(x) <= best + (sag + tol<S>() * S(10)) * s.norm());
    CHECK(std::hypot(x.x(), x.y()) <= r * (1 + tol<S>() * S(10)));
    CHECK(std::abs(x.z()) == h);
  }
}

// Placed: S_{RX+p}(s) = R S_X(R^T s) + p, checked on a box with half extents (1,2,3)
// turned a quarter about z (R: x -> y, y -> -x) and moved to (10,0,0). By hand the turn
// swaps the x and y extents: the placed box is [8,12] x [-1,1] x [-3,3].
// Along s = (1, 0.5, 0.25): R^T s = (0.5, -1, 0.25), the body corner (1,-2,3), turned
// (2,1,3), placed (12,1,3). Along -s the opposite corner: (8,-1,-3).
// (Along an axis direction, R^T s has components that are zero only up to the rounding
// of cos(pi/2), so which tied corner comes out is down to rounding: there only the
// support value, the coordinate along the axis, is checked.)
TEMPLATE_TEST_CASE("placed support is R S(R^T s) + p", "[shapes][placed]", float, double) {
  using S = TestType;
  using V = Vec<S>;
  const Box<S> box(V(1, 2, 3));
  const Pose<S> pose = Pose<S>::fromAxisAngle(V(0, 0, 1), S(kPi / 2), V(10, 0, 0));
  const Placed<Box<S>> placed = place(box, pose);

  CHECK(near<S>(placed.support(V(1, 0.5, 0.25)), V(12, 1, 3), S(10)));
  CHECK(near<S>(placed.support(V(-1, -0.5, -0.25)), V(8, -1, -3), S(10)));
  const S along[6] = {12, -8, 1, 1, 3, 3};  // s·S(s) for +x, -x, +y, -y, +z, -z
  const auto dirs = axisDirections<S>();
  for (int i = 0; i < 6; ++i) CHECK(std::abs(dirs[i].dot(placed.support(dirs[i])) - along[i]) <= tol<S>() * 10);
  CHECK(near<S>(placed.center(), V(10, 0, 0), S(10)));

  // Against the box written by hand in the world: half extents (2,1,3) at (10,0,0).
  // Random directions have no zero component, so there are no ties and the points agree.
  const Placed<Box<S>> byHand = place(Box<S>(V(2, 1, 3)), Pose<S>::translate(V(10, 0, 0)));
  std::mt19937 rng(99);
  for (int k = 0; k < 200; ++k) {
    const V s = randomDirection<S>(rng);
    CHECK(near<S>(placed.support(s), byHand.support(s), S(10)));
    // And literally the formula.
    CHECK(near<S>(placed.support(s), V(pose.rotation * box.support(pose.rotation.transpose() * s) + pose.translation),
                  S(10)));
  }

  // A placed polytope with a hint gives the same point as without, and updates the hint.
  const Placed<Polytope<S>> oct = place(octahedron<S>(), pose);
  SupportHint hint = -1;
  // World +y is body +x (R^T y = x): the vertex (1,0,0), at R(1,0,0) + p = (10,1,0).
  CHECK(near<S>(oct.support(V(0, 1, 0), hint), V(10, 1, 0), S(10)));
  CHECK(near<S>(oct.support(V(0, 1, 0)), V(10, 1, 0), S(10)));
  CHECK(octahedron<S>().vertex(hint) == V(1, 0, 0));

  // A bad pose is rejected where it enters.
  Pose<S> bad = pose;
  bad.rotation(0, 0) = S(2);
  REQUIRE_THROWS_WITH(place(box, bad), Contains("place.worldFromBody.rotation"));
}

// Shape<S>, the run-time variant, answers exactly as the concrete shape it holds.
TEMPLATE_TEST_CASE("Shape variant agrees with the concrete shapes", "[shapes][variant]", float, double) {
  using S = TestType;
  using V = Vec<S>;
  std::mt19937 rng(2024);
  std::vector<V> dirs = axisDirections<S>();
  for (int k = 0; k < 100; ++k) dirs.push_back(randomDirection<S>(rng));

  auto same = [&](const auto& concrete) {
    const Shape<S> shape(concrete);
    int mismatches = 0;
    for (const V& s : dirs) {
      if (shape.support(s) != concrete.support(s)) ++mismatches;
      SupportHint h1 = -1, h2 = -1;
      if (shape.support(s, h1) != supportFrom(concrete, s, h2) || h1 != h2) ++mismatches;
    }
    CHECK(mismatches == 0);
    CHECK(shape.center() == concrete.center());
  };
  same(Point<S>(V(1, 2, 3)));
  same(Segment<S>(V(-1, 0, 0), V(1, 2, 0)));
  same(Triangle<S>(V(0, 0, 0), V(2, 0, 0), V(0, 3, 1)));
  same(Box<S>(V(1, 2, 3)));
  same(Sphere<S>(S(2)));
  same(Capsule<S>(V(0, 0, -1), V(0, 0, 1), S(0.5)));
  same(Cylinder<S>(S(0.5), S(2)));
  same(octahedron<S>());

  // The variant holds the alternative it was given.
  const Shape<S> sphere = Sphere<S>(S(1));
  CHECK(std::holds_alternative<Sphere<S>>(sphere.variant()));
  // The hinted support of a polytope inside the variant moves the hint to the vertex found.
  const Shape<S> oct = octahedron<S>();
  SupportHint hint = 0;
  CHECK(oct.support(V(0, 0, 1), hint) == V(0, 0, 3));
  CHECK(octahedron<S>().vertex(hint) == V(0, 0, 3));
  // A shape without vertices leaves the hint alone.
  SupportHint untouched = 42;
  CHECK(sphere.support(V(1, 0, 0), untouched) == V(1, 0, 0));
  CHECK(untouched == 42);
}

// Moving: a unit sphere leaving the origin at velocity (1,0,0) at t = 0. At t = 2 its
// centre is (2,0,0), so its support along +x is (3,0,0) and along -x is (1,0,0).
TEMPLATE_TEST_CASE("moving support on a constant velocity motion", "[shapes][moving]", float, double) {
  using S = TestType;
  using V = Vec<S>;
  const Moving<Sphere<S>> ball{Sphere<S>(S(1)), Motion<S>::constantVelocity(Pose<S>::identity(), V(1, 0, 0))};
  CHECK(near<S>(ball.support(V(1, 0, 0), S(0)), V(1, 0, 0)));
  CHECK(near<S>(ball.support(V(1, 0, 0), S(2)), V(3, 0, 0)));
  CHECK(near<S>(ball.support(V(-1, 0, 0), S(2)), V(1, 0, 0)));
  CHECK(near<S>(ball.support(V(0, 0, 1), S(0.5)), V(0.5, 0, 1)));
  CHECK(near<S>(ball.at(S(2)).center(), V(2, 0, 0)));

  // A box with a start rotation keeps it while it slides: support = R S(R^T s) + p0 + v t.
  const Pose<S> start = Pose<S>::fromAxisAngle(V(0, 0, 1), S(kPi / 2), V(0, 0, 0));
  const Moving<Box<S>> box{Box<S>(V(1, 2, 3)), Motion<S>::constantVelocity(start, V(0, 0, -1), S(1))};
  // At t = 3 it has moved (0,0,-2); along (1, 0.5, 0.25) the turned box's corner is
  // (2,1,3) (see the placed test above), so the moving one is at (2,1,1).
  CHECK(near<S>(box.support(V(1, 0.5, 0.25), S(3)), V(2, 1, 1)));
  CHECK(near<S>(box.support(V(1, 0.5, 0.25), S(1)), V(2, 1, 3)));
}

// Bad input gets a clear error where it enters; the message names the field.
TEMPLATE_TEST_CASE("shapes reject bad input", "[shapes][input]", float, double) {
  using S = TestType;
  using V = Vec<S>;
  const S nan = std::numeric_limits<S>::quiet_NaN();
  REQUIRE_THROWS_AS(Point<S>(V(0, nan, 0)), std::invalid_argument);
  REQUIRE_THROWS_WITH(Point<S>(V(0, nan, 0)), Contains("point.a"));
  REQUIRE_THROWS_WITH(Segment<S>(V::Zero(), V(nan, 0, 0)), Contains("segment.b"));
  REQUIRE_THROWS_WITH(Triangle<S>(V::Zero(), V(1, 0, 0), V(0, 0, nan)), Contains("triangle.c"));

  REQUIRE_THROWS_AS(Sphere<S>(S(-1)), std::invalid_argument);
  REQUIRE_THROWS_WITH(Sphere<S>(S(-1)), Contains("sphere.radius") && Contains("negative"));
  REQUIRE_THROWS_WITH(Sphere<S>(nan), Contains("sphere.radius") && Contains("finite"));
  REQUIRE_NOTHROW(Sphere<S>(S(0)));  // a sphere of radius 0 is a point

  REQUIRE_THROWS_AS(Box<S>(V(1, -1, 1)), std::invalid_argument);
  REQUIRE_THROWS_WITH(Box<S>(V(1, -1, 1)), Contains("box.halfExtents[1]"));
  REQUIRE_THROWS_WITH(Box<S>(V(1, 1, std::numeric_limits<S>::infinity())), Contains("box.halfExtents[2]"));

  REQUIRE_THROWS_AS(Capsule<S>(V::Zero(), V(0, 0, 1), S(-0.5)), std::invalid_argument);
  REQUIRE_THROWS_WITH(Capsule<S>(V::Zero(), V(0, 0, 1), S(-0.5)), Contains("capsule.radius"));
  REQUIRE_THROWS_WITH(Cylinder<S>(S(-0.5), S(1)), Contains("cylinder.radius"));
  REQUIRE_THROWS_WITH(Cylinder<S>(S(0.5), std::numeric_limits<S>::quiet_NaN()), Contains("cylinder.halfLength"));
  REQUIRE_THROWS_WITH(Capsule<S>(V(nan, 0, 0), V(0, 0, 1), S(0.5)), Contains("capsule.a"));
  REQUIRE_THROWS_WITH(Capsule<S>(V(0, 0, 0), V(0, nan, 1), S(0.5)), Contains("capsule.b"));
}
