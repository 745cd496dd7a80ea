// 14-DOPs by hand (§6): slab ends a reader can check with the shape's corners, the
// k-DOP of a placed shape, and the k-DOP extrusion test on boxes passing each other.
#include <gjkx/kdop/bvh.hpp>
#include <gjkx/kdop/kdop.hpp>
#include <gjkx/kdop/kdop_extrusion.hpp>
#include <gjkx/support_mapping/placed.hpp>
#include <gjkx/support_mapping/polytope.hpp>
#include <gjkx/support_mapping/primitives.hpp>

#include <catch2/catch.hpp>

#include <cmath>
#include <random>

using namespace gjkx;

// Axes: x, y, z, (1,1,1), (1,-1,1), (1,1,-1), (1,-1,-1).
TEMPLATE_TEST_CASE("a unit box's 14-DOP: half extents on the axes, 3/2 on the diagonals", "[kdop]", float, double) {
  using S = TestType;
  const Box<S> box(Vector3<S>(S(0.5), S(0.5), S(0.5)));
  const Kdop14<S> k = kdopOf(box);
  for (int i = 0; i < 3; ++i) {
    CHECK(k.hi[i] == Approx(0.5));
    CHECK(k.lo[i] == Approx(-0.5));
  }
  for (int i = 3; i < 7; ++i) {  // a corner (±1/2, ±1/2, ±1/2) along (±1, ±1, ±1): 3/2
    CHECK(k.hi[i] == Approx(1.5));
    CHECK(k.lo[i] == Approx(-1.5));
  }
}

TEMPLATE_TEST_CASE("the corner tetrahedron's 14-DOP, slab by slab", "[kdop]", float, double) {
  using S = TestType;
  // Vertices 0, e_x, e_y, e_z. Along (1,-1,1): 0, 1, -1, 1. Along (1,-1,-1): 0, 1, -1, -1.
  const auto tetra = Polytope<S>::hull({Vector3<S>(0, 0, 0), Vector3<S>(1, 0, 0), Vector3<S>(0, 1, 0), Vector3<S>(0, 0, 1)});
  const Kdop14<S> k = kdopOf(tetra);
  const S lo[7] = {0, 0, 0, 0, -1, -1, -1};
  const S hi[7] = {1, 1, 1, 1, 1, 1, 1};
  for (int i = 0; i < 7; ++i) {
    CHECK(k.lo[i] == lo[i]);
    CHECK(k.hi[i] == hi[i]);
  }
}

TEMPLATE_TEST_CASE("a sphere's 14-DOP: centre value plus and minus |a| r", "[kdop]", float, double) {
  using S = TestType;
  const auto sphere = place(Sphere<S>(S(1)), Pose<S>::translate(Vector3<S>(1, 2, 3)));
  const Kdop14<S> k = kdopOf(sphere);
  CHECK(k.lo[0] == Approx(0));
  CHECK(k.hi[0] == Approx(2));
  CHECK(k.lo[3] == Approx(6 - std::sqrt(3.0)));  // (1,1,1).(1,2,3) = 6
  CHECK(k.hi[3] == Approx(6 + std::sqrt(3.0)));
  CHECK(k.hi[6] == Approx(-4 + std::sqrt(3.0)));  // (1,-1,-1).(1,2,3) = -4
}

TEMPLATE_TEST_CASE("a box turned 45 degrees about z: x slab of half width sqrt(2)/2", "[kdop]", float, double) {
  using S = TestType;
  const S angle = S(3.14159265358979323846 / 4);
  const auto box = place(Box<S>(Vector3<S>(S(0.5), S(0.5), S(0.5))),
                         Pose<S>::fromAxisAngle(Vector3<S>(0, 0, 1), angle, Vector3<S>::Zero()));
  const Kdop14<S> k = kdopOf(box);
  CHECK(k.hi[0] == Approx(std::sqrt(0.5)).epsilon(1e-5));
  CHECK(k.hi[1] == Approx(std::sqrt(0.5)).epsilon(1e-5));
  CHECK(k.hi[2] == Approx(0.5).epsilon(1e-5));
}

TEMPLATE_TEST_CASE("kdopAt (climbs in the body frame) equals kdopOf the placed polytope", "[kdop]", float, double) {
  using S = TestType;
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int trial = 0; trial < 50; ++trial) {
    std::vector<Vector3<S>> points;
    for (int i = 0; i < 30; ++i) points.emplace_back(S(u(rng)), S(u(rng)), S(u(rng)));
    const auto x = Polytope<S>::hull(points);
    const Pose<S> pose = Pose<S>::fromAxisAngle(Vector3<S>(S(u(rng)), S(u(rng)), S(1)), S(3 * u(rng)),
                                                Vector3<S>(S(5 * u(rng)), S(5 * u(rng)), S(5 * u(rng))));
    std::array<SupportHint, 14> hints;
    hints.fill(0);
    const Kdop14<S> fast = kdopAt(x, KdopFrame<S>::of(pose), hints);
    const Kdop14<S> placed = kdopOf(place(x, pose));
    for (int k = 0; k < 7; ++k) {
      CHECK(fast.lo[k] == Approx(placed.lo[k]).margin(1e-4));
      CHECK(fast.hi[k] == Approx(placed.hi[k]).margin(1e-4));
    }
  }
}

TEST_CASE("gap and overlap: two unit boxes 2 apart in x, one slab at 1, the diagonals at 1/sqrt(3)", "[kdop]") {
  const Box<double> box(Vector3<double>(0.5, 0.5, 0.5));
  const Kdop14<double> a = kdopOf(box);
  const Kdop14<double> b = kdopOf(place(box, Pose<double>::translate(Vector3<double>(2, 0, 0))));
  CHECK(a.gap(b, 0) == Approx(1));
  CHECK(a.gap(b, 1) == Approx(-1));
  CHECK(a.gap(b, 3) == Approx((2 - 1.5 - 1.5) / std::sqrt(3.0)));  // 2 - 3: the diagonal slabs overlap
  CHECK(a.separatingSlab(b) == 0);
  CHECK_FALSE(a.overlaps(b));
  CHECK(a.overlaps(b, 1.0));  // within a tolerance of 1
  Kdop14<double> both = a;
  both.merge(b);
  CHECK(both.contains(a));
  CHECK(both.contains(b));
  CHECK_FALSE(a.contains(both));
}

// The k-DOP extrusion test: P a unit box at rest at the origin; Q a unit box moving
// from (3, y, 0) at t0 = 0 to (-3, y, 0) at t1 = 1.
TEST_CASE("k-DOP extrusion test: a box passing 1 above another is proven apart by the y slab", "[kdop]") {
  const Box<double> box(Vector3<double>(0.5, 0.5, 0.5));
  const Kdop14<double> p = kdopOf(box);
  const auto q0 = kdopOf(place(box, Pose<double>::translate({3, 2, 0})));
  const auto q1 = kdopOf(place(box, Pose<double>::translate({-3, 2, 0})));
  const auto r = kdopExtrusionTest(p, p, q0, q1, 1.0, 0.0, 0.0, ExtrusionVariant::Paper);
  CHECK(r.separated);
  CHECK(r.slab == 1);  // gap 2 - 1 = 1 along y at both ends
}

TEST_CASE("k-DOP extrusion test: a box passing through another is not pruned, though x separates at each end", "[kdop]") {
  const Box<double> box(Vector3<double>(0.5, 0.5, 0.5));
  const Kdop14<double> p = kdopOf(box);
  const auto q0 = kdopOf(place(box, Pose<double>::translate({3, 0, 0})));
  const auto q1 = kdopOf(place(box, Pose<double>::translate({-3, 0, 0})));
  CHECK(q0.separatingSlab(p) == 0);  // apart at t0 ...
  CHECK(q1.separatingSlab(p) == 0);  // ... and at t1, on the other side
  CHECK_FALSE(kdopExtrusionTest(p, p, q0, q1, 1.0, 0.0, 0.0, ExtrusionVariant::Paper).separated);
}

TEST_CASE("k-DOP extrusion test: the certified variant keeps a pair a fast turn may bring together", "[kdop]") {
  // Apart by 0.1 along x at both ends; a turn whose points accelerate by 10 can dip the
  // gap by 1^2/8 * 10 = 1.25 in between: the paper's variant prunes, the certified one does not.
  const Box<double> box(Vector3<double>(0.5, 0.5, 0.5));
  const Kdop14<double> p = kdopOf(box);
  const auto q = kdopOf(place(box, Pose<double>::translate({1.1, 0, 0})));
  CHECK(kdopExtrusionTest(p, p, q, q, 1.0, 10.0, 0.0, ExtrusionVariant::Paper).separated);
  CHECK_FALSE(kdopExtrusionTest(p, p, q, q, 1.0, 10.0, 0.0, ExtrusionVariant::Certified).separated);
  // With no acceleration the two variants agree.
  CHECK(kdopExtrusionTest(p, p, q, q, 1.0, 0.0, 0.0, ExtrusionVariant::Certified).separated);
}

TEST_CASE("a BVH of one piece is a leaf, an empty one is refused", "[kdop]") {
  const auto tetra = Polytope<double>::hull({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}});
  const Bvh<double> one({tetra});
  CHECK(one.nodes().size() == 1);
  CHECK(one.node(0).isLeaf());
  CHECK_THROWS_WITH(Bvh<double>(std::vector<Polytope<double>>{}), Catch::Contains("bvh.pieces"));
}

TEST_CASE("the BVH is balanced by the median split: 16 pieces, 31 nodes, 5 levels", "[kdop]") {
  std::vector<Polytope<double>> pieces;
  for (int i = 0; i < 16; ++i) {
    const double x = i * 2.0;
    pieces.push_back(Polytope<double>::hull({{x, 0, 0}, {x + 1, 0, 0}, {x, 1, 0}, {x, 0, 1}}));
  }
  const Bvh<double> bvh(pieces);
  CHECK(bvh.nodes().size() == 31);
  CHECK(bvh.height() == 5);
  // Every inner node's hull holds its children's vertices: its 14-DOP holds theirs.
  for (const auto& node : bvh.nodes()) {
    if (node.isLeaf()) continue;
    const auto parent = kdopOf(*node.hull);
    CHECK(parent.contains(kdopOf(*bvh.node(node.left).hull)));
    CHECK(parent.contains(kdopOf(*bvh.node(node.right).hull)));
  }
}
