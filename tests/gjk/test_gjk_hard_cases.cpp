// The field's hard cases for GJK (§2.2): contacts exactly at or below round-off,
// identical shapes, collinear and sliver simplices, extreme size ratios, large
// coordinates in float, curved shapes, zero-size shapes, and the ways a run can end
// other than with an answer (iteration cap, visitor, NaN support).
//
// Every run, whatever the case, must end with a status, within maxIterations, with no
// NaN, and not at the iteration cap (checkEnds).
#include "to_reference.hpp"

#include <gjkx/gjk/gjk.hpp>
#include <gjkx/motion/round_off.hpp>
#include <gjkx/support_mapping/placed.hpp>
#include <gjkx/support_mapping/polytope.hpp>
#include <gjkx/support_mapping/primitives.hpp>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

using namespace gjkx;
using gjkx::test::Real;
using gjkx::test::RVec;

namespace {

// A run ended properly: a real answer (Separated or Overlapping, never the cap), within
// the cap, and no NaN anywhere in what it says.
template <typename S>
void checkEnds(const GjkResult<S>& r, const GjkSettings<S>& settings = {}) {
  INFO("status " << toString(r.status) << ", distance " << r.distance << ", iterations " << r.iterations);
  CHECK((r.status == GjkStatus::Separated || r.status == GjkStatus::Overlapping));
  CHECK(r.iterations >= 1);
  CHECK(r.iterations <= settings.maxIterations);
  CHECK(std::isfinite(r.distance));
  CHECK(!std::isnan(r.lowerBound));
  CHECK(r.witnessP.allFinite());
  CHECK(r.witnessQ.allFinite());
  if (r.status == GjkStatus::Overlapping) CHECK(r.distance == S(0));
}

// The run says "touching": Overlapping, or Separated at a distance no more than `slack`.
template <typename S>
void checkTouching(const GjkResult<S>& r, S slack) {
  checkEnds(r);
  INFO("status " << toString(r.status) << ", distance " << r.distance);
  CHECK((r.status == GjkStatus::Overlapping || r.distance <= slack));
}

// The run found the distance `truth` within `tol` (and so Separated when truth > tol).
template <typename S>
void checkDistance(const GjkResult<S>& r, Real truth, Real tol) {
  checkEnds(r);
  INFO("status " << toString(r.status) << ", distance " << r.distance << ", truth " << double(truth) << ", tol "
                 << double(tol));
  CHECK(std::abs(Real(r.distance) - truth) <= tol);
  if (truth > tol) CHECK(r.status == GjkStatus::Separated);
}

template <typename S>
Pose<S> rotated(const Vector3<S>& axis, S angle, const Vector3<S>& translation) {
  return Pose<S>::fromAxisAngle(axis, angle, translation);
}

// A random rotation (double, then rounded to S).
template <typename S>
Matrix3<S> randomRotation(std::mt19937& rng) {
  std::normal_distribution<double> g(0, 1);
  const Eigen::Quaterniond q(g(rng), g(rng), g(rng), g(rng));
  return q.normalized().toRotationMatrix().cast<S>();
}

// Distances to a box [-h, h] from the reference library (gjkx/reference/closest_points.hpp).
using reference::pointBoxDistance;
using reference::segmentBoxDistance;

// A support mapping that returns NaN (or infinity): a broken shape GJK must report.
template <typename S>
struct BrokenShape {
  using Scalar = S;
  S value = std::numeric_limits<S>::quiet_NaN();
  Vector3<S> support(const Vector3<S>& /*s*/) const { return Vector3<S>::Constant(value); }
  Vector3<S> center() const { return Vector3<S>::Zero(); }
};

}  // namespace

// --- touching and sub-epsilon contacts -------------------------------------------------

TEMPLATE_TEST_CASE("hard: unit boxes exactly face to face touch", "[gjk][hard]", float, double) {
  // Box [-0.5, 0.5]^3 and the same box moved by 1 along x share a face: the distance is
  // 0, so GJK must say Overlapping or give a distance <= 1e-6, never a positive gap.
  // Then the same with Q slid along the face, and both turned by one random rotation
  // (touching up to the rounding of the rotated translation).
  using S = TestType;
  const Box<S> unit(Vector3<S>(S(0.5), S(0.5), S(0.5)));
  checkTouching(gjk(place(unit, Pose<S>::identity()), place(unit, Pose<S>::translate({1, 0, 0}))), S(1e-6));
  checkTouching(gjk(place(unit, Pose<S>::identity()), place(unit, Pose<S>::translate({1, S(0.3), S(-0.2)}))),
                S(1e-6));
  checkTouching(gjk(place(unit, Pose<S>::identity()), place(unit, Pose<S>::translate({0, -1, S(0.7)}))), S(1e-6));
  std::mt19937 rng(42);
  for (int trial = 0; trial < 200; ++trial) {
    Pose<S> poseP, poseQ;
    poseP.rotation = poseQ.rotation = randomRotation<S>(rng);
    poseQ.translation = poseQ.rotation * Vector3<S>(1, S(0.25), S(-0.1));
    INFO("trial " << trial);
    checkTouching(gjk(place(unit, poseP), place(unit, poseQ)), S(1e-6));
  }
}

TEMPLATE_TEST_CASE("hard: boxes a sub-epsilon gap apart", "[gjk][hard]", float, double) {
  // Unit boxes 1 + gap apart, gap = 1e-12 in double and 1e-7 in float (below float's
  // resolution near 1: the translation rounds to 1 + 1.19e-7). Axis-aligned, every
  // support point is exact, so the truth is the rounded translation minus 1; GJK must
  // give it within a few round-offs or call it Overlapping. Turned by a random rotation,
  // the pose's own rounding (an epsilon or so) blurs the truth by as much.
  using S = TestType;
  const S gap = sizeof(S) == sizeof(float) ? S(1e-7) : S(1e-12);
  const Box<S> unit(Vector3<S>(S(0.5), S(0.5), S(0.5)));
  const S x = S(1) + gap;
  const Real truth = Real(x) - 1;
  {
    const GjkResult<S> r = gjk(place(unit, Pose<S>::identity()), place(unit, Pose<S>::translate({x, 0, 0})));
    checkEnds(r);
    INFO("distance " << r.distance << ", truth " << double(truth));
    if (r.status == GjkStatus::Separated) CHECK(std::abs(Real(r.distance) - truth) <= 4 * machineEpsilon<S>());
  }
  std::mt19937 rng(42);
  for (int trial = 0; trial < 200; ++trial) {
    Pose<S> poseP, poseQ;
    poseP.rotation = poseQ.rotation = randomRotation<S>(rng);
    poseQ.translation = poseQ.rotation * Vector3<S>(x, S(0.3), S(0.1));
    const GjkResult<S> r = gjk(place(unit, poseP), place(unit, poseQ));
    INFO("trial " << trial << ": " << toString(r.status) << " at " << r.distance);
    checkEnds(r);
    if (r.status == GjkStatus::Separated) CHECK(std::abs(Real(r.distance) - truth) <= 64 * machineEpsilon<S>());
  }
}

TEMPLATE_TEST_CASE("hard: identical shapes at the same pose overlap", "[gjk][hard]", float, double) {
  // Coincident origins: s_0 = centre(Q) - centre(P) = 0 (GJK must pick another start),
  // and V_Q - V_P is symmetric about the origin. Every pair is Overlapping.
  using S = TestType;
  const Pose<S> pose = rotated<S>({1, 2, 3}, S(0.4), {S(0.2), S(-0.3), S(5)});
  const Box<S> box(Vector3<S>(S(0.5), S(1), S(2)));
  const Sphere<S> sphere(S(0.7));
  const Capsule<S> capsule({-1, 0, 0}, {1, 0, 0}, S(0.25));
  std::mt19937 rng(42);
  std::vector<Vector3<S>> points;
  std::normal_distribution<double> g(0, 1);
  for (int k = 0; k < 30; ++k) points.push_back(Eigen::Vector3d(g(rng), g(rng), g(rng)).cast<S>());
  const Polytope<S> polytope = Polytope<S>::hull(points);
  for (const auto& r : {gjk(place(box, pose), place(box, pose)), gjk(place(sphere, pose), place(sphere, pose)),
                        gjk(place(capsule, pose), place(capsule, pose)), gjk(place(polytope, pose), place(polytope, pose))}) {
    checkEnds(r);
    CHECK(r.status == GjkStatus::Overlapping);
  }
  // Same centre, different shapes: a small box inside a big one.
  const GjkResult<S> r = gjk(place(Box<S>(Vector3<S>(S(0.1), S(0.1), S(0.1))), pose), place(box, pose));
  checkEnds(r);
  CHECK(r.status == GjkStatus::Overlapping);
  // Two points at the same place.
  const GjkResult<S> rp = gjk(Point<S>(Vector3<S>(1, 2, 3)), Point<S>(Vector3<S>(1, 2, 3)));
  checkEnds(rp);
  CHECK(rp.status == GjkStatus::Overlapping);
}

TEMPLATE_TEST_CASE("hard: a polytope against itself turned slightly", "[gjk][hard]", float, double) {
  // The same hull at the same position, turned by 1e-3 and by 1e-6 rad about random
  // axes: deeply overlapping, with nearly coincident supports on every query.
  using S = TestType;
  std::mt19937 rng(42);
  std::normal_distribution<double> g(0, 1);
  for (int trial = 0; trial < 50; ++trial) {
    std::vector<Vector3<S>> points;
    for (int k = 0; k < 40; ++k) points.push_back(Eigen::Vector3d(g(rng), g(rng), g(rng)).cast<S>());
    const Polytope<S> shape = Polytope<S>::hull(points);
    const Vector3<S> at(S(g(rng)), S(g(rng)), S(g(rng)));
    const Vector3<S> axis(S(g(rng)), S(g(rng)), S(g(rng)));
    for (const S angle : {S(1e-3), S(1e-6)}) {
      const GjkResult<S> r = gjk(place(shape, Pose<S>::translate(at)), place(shape, rotated<S>(axis, angle, at)));
      INFO("trial " << trial << ", angle " << angle);
      checkEnds(r);
      CHECK(r.status == GjkStatus::Overlapping);
    }
  }
}

// --- collinear and sliver simplices ----------------------------------------------------

TEMPLATE_TEST_CASE("hard: a segment exactly in line with a box edge", "[gjk][hard]", float, double) {
  // The box [-0.5, 0.5]^3 has an edge from (-0.5, 0.5, 0.5) to (0.5, 0.5, 0.5).
  using S = TestType;
  const auto box = place(Box<S>(Vector3<S>(S(0.5), S(0.5), S(0.5))), Pose<S>::identity());
  const Real tol = 64 * machineEpsilon<S>();
  // On the edge's line, beyond its end: distance 0.5 (end to end, every simplex collinear).
  checkDistance(gjk(box, Segment<S>({1, S(0.5), S(0.5)}, {2, S(0.5), S(0.5)})), 0.5, tol);
  checkDistance(gjk(Segment<S>({2, S(0.5), S(0.5)}, {1, S(0.5), S(0.5)}), box), 0.5, tol);
  // On the edge's line, overlapping the edge: touching.
  checkTouching(gjk(box, Segment<S>({0, S(0.5), S(0.5)}, {2, S(0.5), S(0.5)})), S(1e-6));
  // Parallel to the edge, 0.5 above its face y = 0.5.
  checkDistance(gjk(box, Segment<S>({-2, 1, S(0.5)}, {2, 1, S(0.5)})), 0.5, tol);
  // Collinear segments end to end, 1 apart, and overlapping.
  checkDistance(gjk(Segment<S>({0, 0, 0}, {1, 0, 0}), Segment<S>({2, 0, 0}, {3, 0, 0})), 1.0, tol);
  checkTouching(gjk(Segment<S>({0, 0, 0}, {2, 0, 0}), Segment<S>({1, 0, 0}, {3, 0, 0})), S(1e-6));
  // The same, on a line off the axes (the supports are no longer exact).
  const Vector3<S> d = Vector3<S>(1, 2, 3).normalized();
  checkDistance(gjk(Segment<S>(Vector3<S>::Zero(), d), Segment<S>(S(2) * d, S(3) * d)), 1.0, 4 * tol);
}

TEMPLATE_TEST_CASE("hard: a sliver triangle against points", "[gjk][hard]", float, double) {
  // The triangle (-1,-h,0), (1,-h,0), (0,h,0) with h = 1e-9 (below float's resolution at
  // 1, so a segment there): 2e-9 wide, 2 long. Distances worked out by hand.
  using S = TestType;
  const S h = S(1e-9);
  const Triangle<S> sliver({-1, -h, 0}, {1, -h, 0}, {0, h, 0});
  const Real tol = 64 * machineEpsilon<S>();
  checkDistance(gjk(sliver, Point<S>(Vector3<S>(0, 0, 1))), 1.0, tol);              // above the inside
  checkDistance(gjk(sliver, Point<S>(Vector3<S>(S(0.3), 0, S(1e-3)))), 1e-3, tol);  // just above the inside
  checkDistance(gjk(sliver, Point<S>(Vector3<S>(3, 0, 0))), 2.0, tol);              // beyond a vertex, in line
  // Off the long edge y = -h: sqrt((1 - h)^2 + 0.5^2).
  const Real offEdge = std::sqrt((1 - Real(h)) * (1 - Real(h)) + 0.25L);
  checkDistance(gjk(Point<S>(Vector3<S>(0, -1, S(0.5))), sliver), offEdge, tol);
  // Turned off the axes by a rotation: the same distances.
  const Pose<S> pose = rotated<S>({S(0.3), S(-1), S(0.4)}, S(1.1), {S(0.5), 1, S(-2)});
  const auto placed = place(sliver, pose);
  checkDistance(gjk(placed, Point<S>(pose(Vector3<S>(0, 0, 1)))), 1.0, 16 * tol);
  checkDistance(gjk(placed, Point<S>(pose(Vector3<S>(S(0.3), 0, S(1e-3))))), 1e-3, 16 * tol);
  checkDistance(gjk(Point<S>(pose(Vector3<S>(0, -1, S(0.5)))), placed), offEdge, 16 * tol);
}

// --- scale ------------------------------------------------------------------------------

TEMPLATE_TEST_CASE("hard: a 1e-2 box next to a 1e2 box (size ratio 1e4)", "[gjk][hard]", float, double) {
  // Big box half-extent 50, small box half-extent 0.005 placed 1 off a face (distance 1),
  // off an edge (distance sqrt 2) and off a corner (distance sqrt 3).
  using S = TestType;
  const auto big = place(Box<S>(Vector3<S>(50, 50, 50)), Pose<S>::identity());
  const Box<S> small(Vector3<S>(S(0.005), S(0.005), S(0.005)));
  const S c = S(51.005);
  const Real tol = 64 * machineEpsilon<S>() * 50;
  checkDistance(gjk(big, place(small, Pose<S>::translate({c, 0, 0}))), 1.0, tol);
  checkDistance(gjk(big, place(small, Pose<S>::translate({c, c, 0}))), std::sqrt(2.0L), tol);
  checkDistance(gjk(place(small, Pose<S>::translate({-c, c, -c})), big), std::sqrt(3.0L), tol);
  // And with both turned by the same rotation.
  const Pose<S> turn = rotated<S>({1, 1, 0}, S(0.6), Vector3<S>::Zero());
  const auto bigTurned = place(Box<S>(Vector3<S>(50, 50, 50)), turn);
  checkDistance(gjk(bigTurned, place(small, Pose<S>{turn.rotation, turn(Vector3<S>(c, 0, 0))})), 1.0, 4 * tol);
  checkDistance(gjk(bigTurned, place(small, Pose<S>{turn.rotation, turn(Vector3<S>(c, c, c))})), std::sqrt(3.0L),
                4 * tol);
}

TEMPLATE_TEST_CASE("hard: unit boxes near x = 1e5 with a gap of 1", "[gjk][hard]", float, double) {
  // Boxes centred at 1e5 and 1e5 + 2: distance 1. In float the coordinates are good to
  // 1e5 * 6e-8 = 0.006, so the answer must be within 0.05; in double within 64 eps * 1e5.
  // Then both turned and moved to (1e5, 1e5, 1e5).
  using S = TestType;
  const Box<S> unit(Vector3<S>(S(0.5), S(0.5), S(0.5)));
  const Real tol = sizeof(S) == sizeof(float) ? Real(0.05) : Real(64 * machineEpsilon<double>() * 1e5);
  checkDistance(gjk(place(unit, Pose<S>::translate({S(1e5), 0, 0})), place(unit, Pose<S>::translate({S(1e5 + 2), 0, 0}))),
                1.0, tol);
  const Pose<S> turn = rotated<S>({1, 2, 3}, S(0.9), {S(1e5), S(1e5), S(1e5)});
  Pose<S> next = turn;
  next.translation = turn(Vector3<S>(2, 0, 0));
  checkDistance(gjk(place(unit, turn), place(unit, next)), 1.0, tol);
}

// --- curved shapes ----------------------------------------------------------------------

TEMPLATE_TEST_CASE("hard: spheres and capsules converge within the cap", "[gjk][hard][curved]", float, double) {
  // A curved shape has no vertex for GJK to settle on; it must still stop within the cap
  // with the right distance. References: |c2 - c1| - r1 - r2 for spheres, and for a
  // capsule (or sphere) against a box the segment-to-box (point-to-box) distance minus r.
  // Random sizes and poses, fixed seed; overlap whenever the reference is <= 0.
  using S = TestType;
  std::mt19937 rng(42);
  std::uniform_real_distribution<double> u(-1, 1);
  const Real tol = sizeof(S) == sizeof(float) ? Real(1e-4) : Real(1e-9);
  int maxIterations = 0;
  for (int trial = 0; trial < 300; ++trial) {
    INFO("trial " << trial);
    const double scale = std::pow(10.0, u(rng));
    // sphere - sphere
    const S r1 = S(scale * (0.55 + 0.45 * u(rng))), r2 = S(scale * (0.55 + 0.45 * u(rng)));
    const Vector3<S> c1 = (Eigen::Vector3d(u(rng), u(rng), u(rng)) * scale).cast<S>();
    const Vector3<S> c2 = (Eigen::Vector3d(u(rng), u(rng), u(rng)) * 3 * scale).cast<S>();
    const Real sphereTruth = (test::toReal(c2) - test::toReal(c1)).norm() - Real(r1) - Real(r2);
    const GjkResult<S> rs = gjk(place(Sphere<S>(r1), Pose<S>::translate(c1)), place(Sphere<S>(r2), Pose<S>::translate(c2)));
    maxIterations = std::max(maxIterations, rs.iterations);
    if (sphereTruth > tol * 3 * scale) {
      checkDistance(rs, sphereTruth, tol * 3 * scale);
    } else if (sphereTruth < -tol * 3 * scale) {
      checkEnds(rs);
      CHECK(rs.status == GjkStatus::Overlapping);
    }
    // capsule - box, sphere - box (box axis-aligned at the origin, capsule anywhere)
    const Vector3<S> h = (Eigen::Vector3d(0.6 + 0.4 * u(rng), 0.6 + 0.4 * u(rng), 0.6 + 0.4 * u(rng)) * scale).cast<S>();
    const Vector3<S> a = (Eigen::Vector3d(u(rng), u(rng), u(rng)) * 3 * scale).cast<S>();
    const Vector3<S> b = a + (Eigen::Vector3d(u(rng), u(rng), u(rng)) * scale).cast<S>();
    const S radius = S(scale * (0.3 + 0.2 * u(rng)));
    const auto box = place(Box<S>(h), Pose<S>::identity());
    const Real capsuleTruth = segmentBoxDistance(test::toReal(a), test::toReal(b), test::toReal(h)) - Real(radius);
    const GjkResult<S> rc = gjk(Capsule<S>(a, b, radius), box);
    maxIterations = std::max(maxIterations, rc.iterations);
    if (capsuleTruth > tol * 3 * scale) {
      checkDistance(rc, capsuleTruth, tol * 3 * scale);
    } else if (capsuleTruth < -tol * 3 * scale) {
      checkEnds(rc);
      CHECK(rc.status == GjkStatus::Overlapping);
    }
    const Real ballTruth = pointBoxDistance(test::toReal(a), test::toReal(h)) - Real(radius);
    const GjkResult<S> rb = gjk(box, place(Sphere<S>(radius), Pose<S>::translate(a)));
    maxIterations = std::max(maxIterations, rb.iterations);
    if (ballTruth > tol * 3 * scale) checkDistance(rb, ballTruth, tol * 3 * scale);
  }
  INFO("most iterations on a curved pair: " << maxIterations);
  CHECK(maxIterations < GjkSettings<S>{}.maxIterations);
  WARN("curved shapes (" << (sizeof(S) == sizeof(float) ? "float" : "double") << "): at most " << maxIterations
                         << " iterations");
}

TEMPLATE_TEST_CASE("hard: a capsule against a box, by hand", "[gjk][hard][curved]", float, double) {
  // Box [-0.5, 0.5]^3; capsule of radius 0.25 about a segment along y at x = 2: distance
  // 2 - 0.5 - 0.25 = 1.25. Tilted so its lower end points at the face x = 0.5 from
  // (1.5, 0, 0): distance 1 - 0.25 = 0.75. Lying on the face: touching, and here GJK
  // stops at its round-off floor: z = sum lambda_k w_k carries an error of about
  // eps |w| (|w| ~ 1.6), which tips the direction z once |z| is near sqrt(eps) |w|; the
  // tied supports of the face then repeat a vertex and the run ends there (3.3e-4 in
  // float, 2.8e-9 in double). So "touching" is allowed 4 sqrt(eps) here.
  using S = TestType;
  const auto box = place(Box<S>(Vector3<S>(S(0.5), S(0.5), S(0.5))), Pose<S>::identity());
  const Real tol = sizeof(S) == sizeof(float) ? Real(1e-5) : Real(1e-10);
  checkDistance(gjk(Capsule<S>({2, -1, 0}, {2, 1, 0}, S(0.25)), box), 1.25, tol);
  checkDistance(gjk(box, Capsule<S>({S(1.5), 0, 0}, {3, 1, S(0.5)}, S(0.25))), 0.75, tol);
  checkTouching(gjk(box, Capsule<S>({S(0.75), -1, 0}, {S(0.75), 1, 0}, S(0.25))), 4 * sqrtEpsilon<S>());
}

// --- zero-size shapes ---------------------------------------------------------------------

TEMPLATE_TEST_CASE("hard: zero-size shapes and degenerate segments", "[gjk][hard]", float, double) {
  // A sphere of radius 0, a box of zero extents, a capsule of radius 0 about a = b and a
  // segment with a = b are all single points: V_Q - V_P has one vertex (or is a box).
  using S = TestType;
  const Real tol = 64 * machineEpsilon<S>();
  const Sphere<S> dot(0);
  checkDistance(gjk(place(dot, Pose<S>::identity()), place(dot, Pose<S>::translate({3, 4, 0}))), 5.0, tol);
  const GjkResult<S> same = gjk(place(dot, Pose<S>::translate({1, 1, 1})), place(dot, Pose<S>::translate({1, 1, 1})));
  checkEnds(same);
  CHECK(same.status == GjkStatus::Overlapping);

  const Box<S> flat(Vector3<S>::Zero());
  const auto unit = place(Box<S>(Vector3<S>(S(0.5), S(0.5), S(0.5))), Pose<S>::identity());
  checkDistance(gjk(place(flat, Pose<S>::translate({2, 0, 0})), unit), 1.5, tol);
  checkDistance(gjk(unit, place(flat, Pose<S>::translate({2, 2, 0}))), std::sqrt(4.5L), tol);
  const GjkResult<S> inside = gjk(place(flat, Pose<S>::translate({S(0.1), 0, 0})), unit);
  checkEnds(inside);
  CHECK(inside.status == GjkStatus::Overlapping);
  const GjkResult<S> flats = gjk(place(flat, Pose<S>::identity()), place(flat, Pose<S>::identity()));
  checkEnds(flats);
  CHECK(flats.status == GjkStatus::Overlapping);

  const Segment<S> stub({2, 0, 0}, {2, 0, 0});
  checkDistance(gjk(stub, unit), 1.5, tol);
  checkDistance(gjk(stub, place(Sphere<S>(1), Pose<S>::translate({-1, 0, 0}))), 2.0, tol);
  checkDistance(gjk(Capsule<S>({0, 3, 0}, {0, 3, 0}, 0), unit), 2.5, tol);
  checkDistance(gjk(stub, Segment<S>({-1, 1, 0}, {3, 1, 0})), 1.0, tol);
}

// --- ways a run ends without an answer ------------------------------------------------------

TEMPLATE_TEST_CASE("hard: maxIterations = 2 ends at IterationCap", "[gjk][hard][status]", float, double) {
  // Two polytopes whose default run takes more than 2 iterations: with maxIterations = 2
  // the run must say IterationCap (never Separated), after exactly 2 iterations, with a
  // distance that is only an upper bound of the true one.
  using S = TestType;
  std::mt19937 rng(42);
  std::normal_distribution<double> g(0, 1);
  int capped = 0;
  for (int trial = 0; trial < 20; ++trial) {
    std::vector<Vector3<S>> a, b;
    for (int k = 0; k < 30; ++k) {
      a.push_back(Eigen::Vector3d(g(rng), g(rng), g(rng)).cast<S>());
      b.push_back(Eigen::Vector3d(g(rng), g(rng), g(rng)).cast<S>());
    }
    const auto P = place(Polytope<S>::hull(a), rotated<S>({1, 0, 1}, S(0.3), Vector3<S>::Zero()));
    const auto Q = place(Polytope<S>::hull(b), rotated<S>({0, 1, 1}, S(1.3), {6, S(2), S(1)}));
    const GjkResult<S> full = gjk(P, Q);
    checkEnds(full);
    if (full.iterations <= 2) continue;
    ++capped;
    GjkSettings<S> settings;
    settings.maxIterations = 2;
    const GjkResult<S> r = gjk(P, Q, settings);
    INFO("trial " << trial << ": full run " << full.iterations << " iterations");
    CHECK(r.status == GjkStatus::IterationCap);
    CHECK(r.iterations == 2);
    CHECK(std::isfinite(r.distance));
    CHECK(r.distance >= full.distance * (1 - S(1e-4)));
  }
  CHECK(capped >= 10);
}

TEMPLATE_TEST_CASE("hard: a visitor returning false stops the run", "[gjk][hard][status]", float, double) {
  // The visitor sees iteration 0 and says stop: StoppedByVisitor after 1 iteration.
  using S = TestType;
  const auto P = place(Sphere<S>(1), Pose<S>::identity());
  const auto Q = place(Box<S>(Vector3<S>(1, 1, 1)), rotated<S>({1, 1, 1}, S(0.5), {4, 1, 0}));
  int seen = 0;
  const GjkResult<S> r = gjk(P, Q, {}, nullptr, [&](const GjkIteration<S>&) {
    ++seen;
    return false;
  });
  CHECK(r.status == GjkStatus::StoppedByVisitor);
  CHECK(r.iterations == 1);
  CHECK(seen == 1);
  // A visitor that stops at iteration 2 (of a run that needs more: GJK on the curved
  // sphere, not on its core, which would end sooner).
  GjkSettings<S> curved;
  curved.roundedCores = false;
  const GjkResult<S> r2 = gjk(P, Q, curved, nullptr, [](const GjkIteration<S>& it) { return it.i < 2; });
  CHECK(r2.status == GjkStatus::StoppedByVisitor);
  CHECK(r2.iterations == 3);
}

TEMPLATE_TEST_CASE("hard: a support mapping that returns NaN gives NumericalFailure", "[gjk][hard][status]", float,
                   double) {
  // A broken shape (support = NaN, or infinity) as P or as Q: NumericalFailure on the
  // first query, and the warm-start cache is left untouched.
  using S = TestType;
  const auto box = place(Box<S>(Vector3<S>(1, 1, 1)), Pose<S>::translate({3, 0, 0}));
  BrokenShape<S> nan;
  BrokenShape<S> inf;
  inf.value = std::numeric_limits<S>::infinity();
  GjkCache<S> cache;
  const GjkResult<S> r1 = gjk(nan, box, {}, &cache);
  CHECK(r1.status == GjkStatus::NumericalFailure);
  CHECK(r1.iterations == 1);
  CHECK_FALSE(cache.valid);
  CHECK(gjk(box, nan).status == GjkStatus::NumericalFailure);
  CHECK(gjk(inf, box).status == GjkStatus::NumericalFailure);
  CHECK(gjk(box, inf).status == GjkStatus::NumericalFailure);
}

// --- warm start across an overlap ---------------------------------------------------------

TEMPLATE_TEST_CASE("hard: a warm start from an overlap still reports Overlapping", "[gjk][hard][warm]", float,
                   double) {
  // Two unit boxes overlapping by about 0.7, Q turning and drifting a little per step.
  // An overlap leaves a tetrahedron around the origin in the cache; re-asked at the next
  // pose it still holds the origin. The warm run must say Overlapping, like a cold one.
  using S = TestType;
  const Box<S> unit(Vector3<S>(S(0.5), S(0.5), S(0.5)));
  const auto P = place(unit, Pose<S>::identity());
  GjkCache<S> cache;
  for (int step = 0; step < 10; ++step) {
    const auto Q = place(unit, rotated<S>({1, 2, 3}, S(0.1) * S(step), {S(0.3) + S(0.01) * S(step), S(0.2), S(0.1)}));
    const GjkResult<S> cold = gjk(P, Q);
    const GjkResult<S> warm = gjk(P, Q, {}, &cache);
    INFO("step " << step << ": warm " << toString(warm.status) << " at " << warm.distance << ", "
                 << warm.simplex.size << " vertices");
    checkEnds(cold);
    checkEnds(warm);
    CHECK(cold.status == GjkStatus::Overlapping);
    CHECK(warm.status == GjkStatus::Overlapping);
  }
}

TEST_CASE("hard: a long segment piercing a tiny box is not reported separated (fuzz finding)", "[gjk][hard][fuzz]") {
  // Found by tests/fuzz/fuzz_time_of_impact. The segment from (-1000, -1000, -1000) to
  // (999.97, 999.97, 999.97) passes through a box 2e-4 wide near the origin (by 7.9e-6, the
  // brute-force signed distance). V_Q - V_P then holds sliver triangles 3464 long and 2e-4
  // wide. Their z, rebuilt as sum lambda_k w_k, had the right length but a direction off
  // by 3% (the lambda's round-off times |w| = 1732), so SD along it was -72 and GJK stalled
  // ("no decrease") at "Separated at 6.2e-6". Computing z as the projection itself, from
  // edges taken from the support points and the normal from the edges at the largest
  // angle (simplex.hpp, detail::triangle), keeps the direction good to ~1e-13 and GJK
  // finds the overlap.
  using V = Vector3<double>;
  const V lo(-0.0001908294677734375, -2.050781249999991e-06, -0.0001643585205078125);
  const V hi(9.1644287109375003e-06, 0.00019794311523437501, 3.5635375976562499e-05);
  const auto box = place(Box<double>((hi - lo) / 2), Pose<double>::translate((hi + lo) / 2));
  const Segment<double> segment(V(-1000, -1000, -1000), V(999.969482421875, 999.969482421875, 999.969482421875));
  const GjkResult<double> r = gjk(place(segment, Pose<double>::identity()), box);
  checkEnds(r);
  INFO("status " << toString(r.status) << ", distance " << r.distance << ", lowerBound " << r.lowerBound);
  CHECK(r.status == GjkStatus::Overlapping);
  // Whatever a run reports as Separated, its lower bound proves it.
  const GjkResult<double> back = gjk(box, place(segment, Pose<double>::identity()));
  checkEnds(back);
  CHECK((back.status == GjkStatus::Overlapping || back.lowerBound > 0));
}

TEMPLATE_TEST_CASE("hard: a polytope overlapping a box at sizes from 1e-8 to 1e7 (fuzz finding)", "[gjk][hard][fuzz]",
                   float, double) {
  // The finding, in float: a hull of 8 points about 1e-8 across, half inside a box of
  // half extent 4.3e-9, came out Separated at 2.1e-11: the sub-algorithm's sign tests
  // multiply up to six lengths, 1e-48, which underflows in float, and the tetrahedron
  // around the origin was taken for flat. The same pair scaled by 10^k must overlap at
  // every k, in both scalar types.
  using S = TestType;
  using V = Vector3<S>;
  const std::vector<Eigen::Vector3d> cloud = {
      {-8.630371e-09, -8.630371e-09, -8.932495e-09}, {-8.549658e-11, -7.731828e-09, -9.745542e-09},
      {-9.443418e-09, -8.549658e-11, -8.033952e-09}, {-8.985431e-10, 8.130465e-10, -8.846999e-09},
      {-7.731828e-09, -9.443418e-09, -3.876207e-10}, {8.130465e-10, -8.544875e-09, -1.200667e-09},
      {-8.544875e-09, -8.985431e-10, 5.109224e-10},  {6.430128e-17, 6.430128e-17, -3.021240e-10}};
  for (int k = 0; k <= 15; ++k) {
    const double scale = std::pow(10.0, k);
    std::vector<V> points;
    for (const auto& x : cloud) points.push_back((x * scale).cast<S>());
    const Polytope<S> P = Polytope<S>::hull(points);
    const Box<S> Q(V::Constant(S(4.3151855e-09 * scale)));
    const GjkResult<S> r = gjk(P, Q);
    INFO("size 1e" << (k - 8) << ": " << toString(r.status) << " at " << r.distance);
    checkEnds(r);
    CHECK(r.status == GjkStatus::Overlapping);
  }
}

namespace {
// A finite point set as a support mapping, by looking at every point (any point set,
// flat ones included).
struct PointCloud {
  using Scalar = double;
  std::vector<Vector3<double>> points;
  Vector3<double> support(const Vector3<double>& s) const {
    Vector3<double> best = points[0];
    for (const auto& x : points)
      if (x.dot(s) > best.dot(s)) best = x;
    return best;
  }
  Vector3<double> center() const {
    Vector3<double> c = Vector3<double>::Zero();
    for (const auto& x : points) c += x;
    return c / double(points.size());
  }
};
}  // namespace

TEST_CASE("hard: a tiny polytope through a flat rectangle 2000 wide is overlapping (fuzz finding)", "[gjk][hard][fuzz]") {
  // V_Q - V_P is a slab 2e-7 thick and 2000 wide. After three iterations z is 1.7e-8 from
  // the origin and the next support lies 3e-8 beyond it (SD < 0); the new triangle,
  // tilted across the origin, came out 1.5e-14 farther, and "until the distance no longer
  // decreases" stopped with Separated at 1.7e-8 while the shapes overlap by 9e-9. That
  // difference is round-off of the simplex's size (eps * 1000 = 2e-13), a tie: GJK takes
  // it and the next support finds the origin inside.
  using V = Vector3<double>;
  const PointCloud P{{V(7.7825927734375002e-08, 1.72564697265625e-07, -2.2283935546874999e-08),
                      V(1.048583984375001e-08, 4.2926025390625001e-08, -5.7070922851562499e-08),
                      V(1.349639892578125e-07, 7.4179077148437501e-08, 0),
                      V(9.99969482421875e-08, 9.99969482421875e-08, -6.2499999999999997e-08),
                      V(6.7269897460937499e-08, -3.0517578124951111e-12, -9.9999999999999995e-08),
                      V(1.696441650390625e-07, 3.87298583984375e-08, -4.0362548828124998e-08),
                      V(-3.0517578124951111e-12, -3.0517578124951111e-12, -1.6619873046875e-08),
                      V(1.99993896484375e-07, 1.99993896484375e-07, 0)}};
  const PointCloud Q{{V(-631.07433837310987, -69.609255376890232, 760.79874350162197),
                      V(763.96344537671143, -63.279851626711249, 627.9096364980204),
                      V(-763.96344537671143, 63.279851626711249, -627.9096364980204),
                      V(631.07433837310987, 69.609255376890232, -760.79874350162197)}};
  const GjkResult<double> r = gjk(P, Q);
  INFO(toString(r.status) << " at " << r.distance << ", lower bound " << r.lowerBound);
  checkEnds(r);
  CHECK(r.status == GjkStatus::Overlapping);
}
