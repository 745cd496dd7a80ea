// GJK on rounded shapes (spheres, capsules): a core swept by a ball. By default GJK runs
// on the cores (a point, a segment) and subtracts the radii (gjk.hpp, detail::gjkOnCores);
// the paper's way, GJK on the curved supports, is kept behind roundedCores = false.
//
// Every case is checked against a closed form in long double: the distance between the
// cores (point-point, point-segment, segment-segment, point-box, segment-box) less the
// radii. And what the result says must hold together: the witnesses lie on the surfaces,
// they differ by z, the lower bound is a lower bound, the status says overlap exactly when
// the reference does (outside a round-off band).
#include "to_reference.hpp"

#include <gjkx/gjk/gjk.hpp>
#include <gjkx/gjk/trace.hpp>
#include <gjkx/support_mapping/placed.hpp>
#include <gjkx/support_mapping/polytope.hpp>
#include <gjkx/support_mapping/primitives.hpp>
#include <gjkx/support_mapping/shape.hpp>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

using namespace gjkx;
using gjkx::test::Real;
using gjkx::test::RVec;

namespace {

template <typename S>
Real tolerance() {
  return sizeof(S) == sizeof(float) ? Real(2e-5) : Real(1e-12);
}

// The exact distances of the reference library (gjkx/reference/closest_points.hpp).
using reference::pointBoxDistance;
using reference::pointSegmentDistance;
using reference::segmentBoxDistance;
using reference::segmentSegmentDistance;

template <typename S>
RVec world(const Pose<S>& pose, const Vector3<S>& x) {
  return pose.rotation.template cast<Real>() * test::toReal(x) + test::toReal(pose.translation);
}

template <typename S>
Pose<S> randomPose(std::mt19937& rng, double spread) {
  std::normal_distribution<double> g(0, 1);
  const Eigen::Vector3d axis(g(rng), g(rng), g(rng));
  const Eigen::Vector3d t(g(rng), g(rng), g(rng));
  return Pose<double>::fromAxisAngle(axis, g(rng), spread * t).cast<S>();
}

// The result agrees with the reference distance `truth` and holds together.
template <typename S>
void checkAgainst(const GjkResult<S>& r, Real truth, Real scale) {
  const Real tol = tolerance<S>() * scale;
  INFO("status " << toString(r.status) << ", distance " << r.distance << ", truth " << double(truth) << ", lower bound "
                 << r.lowerBound << ", iterations " << r.iterations);
  REQUIRE((r.status == GjkStatus::Separated || r.status == GjkStatus::Overlapping));
  CHECK(std::abs(Real(r.distance) - std::max(truth, Real(0))) <= tol);
  if (truth > tol) CHECK(r.status == GjkStatus::Separated);
  if (truth < -tol) CHECK(r.status == GjkStatus::Overlapping);
  CHECK(Real(r.lowerBound) <= std::max(truth, Real(0)) + tol);
  if (r.status == GjkStatus::Separated) {
    CHECK((test::toReal(r.witnessQ) - test::toReal(r.witnessP) - test::toReal(r.z)).norm() <= tol);
    CHECK(std::abs(test::toReal(r.z).norm() - Real(r.distance)) <= tol);
    CHECK(Real(r.lowerBound) >= Real(r.distance) - tol);  // converged: the bounds meet
  }
}

}  // namespace

TEMPLATE_TEST_CASE("rounded: spheres and capsules against a closed form", "[gjk][rounded]", float, double) {
  // 300 random pairs of each kind at random poses, from deep overlap to a few sizes apart.
  using S = TestType;
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0.05, 1.5);
  int separated = 0, overlapping = 0, maxIterations = 0;
  for (int trial = 0; trial < 300; ++trial) {
    INFO("trial " << trial);
    const Sphere<S> sphereP(S(u(rng))), sphereQ(S(u(rng)));
    const Capsule<S> capsuleP({0, 0, S(-u(rng))}, {0, 0, S(u(rng))}, S(u(rng)));
    const Capsule<S> capsuleQ({S(-u(rng)), 0, 0}, {S(u(rng)), 0, 0}, S(u(rng)));
    const Box<S> box(Vector3<S>(S(u(rng)), S(u(rng)), S(u(rng))));
    const Pose<S> poseP = randomPose<S>(rng, 1.5), poseQ = randomPose<S>(rng, 1.5);
    const RVec cP = world(poseP, Vector3<S>(Vector3<S>::Zero())), cQ = world(poseQ, Vector3<S>(Vector3<S>::Zero()));
    const RVec aP = world(poseP, capsuleP.axis.a), bP = world(poseP, capsuleP.axis.b);
    const RVec aQ = world(poseQ, capsuleQ.axis.a), bQ = world(poseQ, capsuleQ.axis.b);
    const Real scale = 1 + std::max(cP.cwiseAbs().maxCoeff(), cQ.cwiseAbs().maxCoeff());

    const auto ss = gjk(place(sphereP, poseP), place(sphereQ, poseQ));
    checkAgainst(ss, (cQ - cP).norm() - Real(sphereP.radius) - Real(sphereQ.radius), scale);
    CHECK(ss.iterations <= 2);  // two points: one support query each, then converged

    const auto sc = gjk(place(sphereP, poseP), place(capsuleQ, poseQ));
    checkAgainst(sc, pointSegmentDistance(cP, aQ, bQ) - Real(sphereP.radius) - Real(capsuleQ.radius), scale);

    const auto cc = gjk(place(capsuleP, poseP), place(capsuleQ, poseQ));
    checkAgainst(cc, segmentSegmentDistance(aP, bP, aQ, bQ) - Real(capsuleP.radius) - Real(capsuleQ.radius), scale);

    // Against a box (not rounded: its core is itself), in the box's frame.
    const RVec h = test::toReal(box.halfExtents);
    const Matrix3<Real> Rq = poseQ.rotation.template cast<Real>();
    auto inBox = [&](const RVec& x) { RVec y = Rq.transpose() * (x - test::toReal(poseQ.translation)); return y; };
    const auto sb = gjk(place(sphereP, poseP), place(box, poseQ));
    checkAgainst(sb, pointBoxDistance(inBox(cP), h) - Real(sphereP.radius), scale);
    const auto cb = gjk(place(capsuleP, poseP), place(box, poseQ));
    checkAgainst(cb, segmentBoxDistance(inBox(aP), inBox(bP), h) - Real(capsuleP.radius), scale);

    for (const auto* r : {&ss, &sc, &cc, &sb, &cb}) {
      (r->status == GjkStatus::Separated ? separated : overlapping) += 1;
      maxIterations = std::max(maxIterations, r->iterations);
    }
    // The witnesses of a separated sphere lie on its surface.
    if (ss.status == GjkStatus::Separated) {
      CHECK(std::abs((test::toReal(ss.witnessP) - cP).norm() - Real(sphereP.radius)) <= tolerance<S>() * scale);
      CHECK(std::abs((test::toReal(ss.witnessQ) - cQ).norm() - Real(sphereQ.radius)) <= tolerance<S>() * scale);
    }
  }
  INFO(separated << " separated, " << overlapping << " overlapping");
  CHECK(separated > 200);  // both kinds of answer were exercised
  CHECK(overlapping > 200);
  CHECK(maxIterations <= 8);  // cores are polytopes: GJK ends in a few iterations
}

TEMPLATE_TEST_CASE("rounded: the cores' answer agrees with GJK on the curved surfaces", "[gjk][rounded]", float, double) {
  // roundedCores = false is the paper's GJK on the full supports; it converges to the same
  // distance (within its relative tolerance), only in more iterations.
  using S = TestType;
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(0.1, 1.0);
  GjkSettings<S> paper;
  paper.roundedCores = false;
  long coreIterations = 0, paperIterations = 0;
  for (int trial = 0; trial < 200; ++trial) {
    const Capsule<S> P({0, 0, S(-u(rng))}, {0, 0, S(u(rng))}, S(u(rng)));
    const Sphere<S> Q(S(u(rng)));
    const Pose<S> poseP = randomPose<S>(rng, 2), poseQ = randomPose<S>(rng, 2);
    const auto cores = gjk(place(P, poseP), place(Q, poseQ));
    const auto curved = gjk(place(P, poseP), place(Q, poseQ), paper);
    INFO("trial " << trial << ": cores " << toString(cores.status) << " at " << cores.distance << ", curved "
                  << toString(curved.status) << " at " << curved.distance);
    const Real tol = sizeof(S) == sizeof(float) ? Real(1e-4) : Real(1e-8);
    CHECK(std::abs(Real(cores.distance) - Real(curved.distance)) <= tol);
    if (cores.distance > tol && curved.distance > tol) CHECK(cores.status == curved.status);
    coreIterations += cores.iterations;
    paperIterations += curved.iterations;
  }
  INFO("iterations: cores " << coreIterations << ", curved " << paperIterations);
  CHECK(coreIterations * 2 < paperIterations);
}

TEMPLATE_TEST_CASE("rounded: a run-time Shape, a warm start, a boolean query and a trace", "[gjk][rounded]", float, double) {
  using S = TestType;
  const Capsule<S> capsule({0, 0, -1}, {0, 0, 1}, S(0.25));
  const Sphere<S> sphere(S(0.5));
  // Q moves past P along x, 0.01 per step: from 1.25 apart to overlapping and out again.
  GjkCache<S> cache;
  for (int step = 0; step <= 300; ++step) {
    const S x = S(-1.5) + S(0.01) * S(step);
    const Pose<S> poseQ = Pose<S>::translate({x, S(0.3), S(0.5)});
    const Real truth = pointSegmentDistance(test::toReal(poseQ.translation), RVec(0, 0, -1), RVec(0, 0, 1)) - Real(0.75);
    INFO("step " << step << ", x = " << x);
    // The concrete types, the run-time Shape, and a warm start all give the same answer.
    const auto concrete = gjk(place(capsule, Pose<S>::identity()), place(sphere, poseQ));
    const auto variant = gjk(place(Shape<S>(capsule), Pose<S>::identity()), place(Shape<S>(sphere), poseQ));
    const auto warm = gjk(place(capsule, Pose<S>::identity()), place(sphere, poseQ), {}, &cache);
    checkAgainst(concrete, truth, 2);
    checkAgainst(variant, truth, 2);
    checkAgainst(warm, truth, 2);
    CHECK(warm.iterations <= concrete.iterations + 1);
    // The boolean query (§2.3): stop at the first s with SD above a threshold; the
    // radii are in the threshold, so a separating vector separates the shapes themselves.
    GjkSettings<S> boolean;
    boolean.separationThreshold = S(1e-3);
    const auto b = gjk(place(capsule, Pose<S>::identity()), place(sphere, poseQ), boolean);
    if (truth > 2e-3) CHECK((b.status == GjkStatus::SeparatingVector || b.status == GjkStatus::Separated));
    if (b.status == GjkStatus::SeparatingVector) CHECK(Real(b.lowerBound) <= truth + tolerance<S>());
    if (b.status == GjkStatus::SeparatingVector) CHECK(b.lowerBound > S(1e-3));
    if (truth < 0) CHECK(b.status == GjkStatus::Overlapping);
  }
  // The trace of a rounded run shows the shapes' distances: each iteration's supporting
  // distance is a lower bound of the shapes' distance (not the cores').
  GjkTrace<S> trace;
  const auto r = gjk(place(capsule, Pose<S>::identity()), place(sphere, Pose<S>::translate({2, 0, S(1.5)})), {}, nullptr,
                     std::ref(trace));
  REQUIRE(r.status == GjkStatus::Separated);
  REQUIRE(!trace.iterations.empty());
  for (const auto& it : trace.iterations) CHECK(it.supportingDistance <= r.distance + S(tolerance<S>()));
  CHECK(trace.iterations.back().minkowskiDistance == Approx(double(r.distance)).margin(double(tolerance<S>())));
}

TEST_CASE("rounded: a boolean query that stops before any simplex says nothing NaN", "[gjk][rounded][fuzz]") {
  // Found by tests/fuzz/fuzz_gjk: a boolean query whose first direction already separates
  // stops at iteration 0, before any simplex, with an infinite distance (an upper bound)
  // and z = 0; taking the radii off must leave those as they are (it gave z = 0 * inf).
  GjkSettings<double> boolean;
  boolean.separationThreshold = 0;
  const auto r = gjk(place(Sphere<double>(1), Pose<double>::identity()), place(Sphere<double>(1), Pose<double>::translate({5, 0, 0})),
                     boolean);
  CHECK(r.status == GjkStatus::SeparatingVector);
  CHECK(r.iterations == 1);
  CHECK(r.lowerBound == Approx(3.0));
  CHECK(!std::isnan(r.distance));
  CHECK(r.distance >= r.lowerBound);
  CHECK(r.z.allFinite());
  CHECK(r.witnessP.allFinite());
  CHECK(r.witnessQ.allFinite());
}

TEST_CASE("rounded: touching and zero-radius shapes", "[gjk][rounded]") {
  // Two unit spheres exactly 2 apart touch: Overlapping or a distance of round-off. A
  // sphere of radius 0 is a point; a capsule of radius 0 a segment.
  const Sphere<double> unit(1);
  const auto touching = gjk(place(unit, Pose<double>::identity()), place(unit, Pose<double>::translate({2, 0, 0})));
  CHECK((touching.status == GjkStatus::Overlapping || touching.distance <= 1e-15));
  const auto point = gjk(place(Sphere<double>(0), Pose<double>::identity()), place(unit, Pose<double>::translate({3, 4, 0})));
  CHECK(point.status == GjkStatus::Separated);
  CHECK(point.distance == Approx(4.0).epsilon(1e-14));
  const auto segment = gjk(place(Capsule<double>({0, 0, -1}, {0, 0, 1}, 0), Pose<double>::identity()),
                           place(Capsule<double>({0, -1, 0}, {0, 1, 0}, 0), Pose<double>::translate({3, 0, 0.5})));
  CHECK(segment.status == GjkStatus::Separated);
  CHECK(segment.distance == Approx(3.0).epsilon(1e-14));
  // Concentric: the cores coincide (distance 0), so the shapes overlap.
  const auto concentric = gjk(place(unit, Pose<double>::identity()), place(Sphere<double>(0.1), Pose<double>::identity()));
  CHECK(concentric.status == GjkStatus::Overlapping);
  CHECK(concentric.distance == 0);
}

TEMPLATE_TEST_CASE("rounded: the closed form on point and segment cores agrees with the loop it replaces", "[gjk][rounded]", float,
                   double) {
  // Two spheres or capsules skip GJK's loop (gjk.hpp, detail::gjkOnSegmentCores); a visitor
  // forces the loop. Both must give the same distance and status, the closed form's
  // simplex must be a true convex combination giving the cores' z, and the witnesses must
  // differ by z. Parallel, collinear, crossing and point-like axes are included: they
  // are where a closed form for two segments goes wrong.
  using S = TestType;
  std::mt19937 rng(23);
  std::uniform_real_distribution<double> u(-1, 1);
  const auto loop = [](const GjkIteration<S>&) { return true; };
  const Real tol = sizeof(S) == sizeof(float) ? Real(1e-4) : Real(1e-10);
  int edgeEdge = 0;
  for (int trial = 0; trial < 400; ++trial) {
    const int kind = trial % 5;  // 0 random, 1 parallel, 2 collinear, 3 a point-like axis, 4 crossing
    const Vector3<S> a0(S(u(rng)), S(u(rng)), S(u(rng))), d(S(u(rng)), S(u(rng)), S(u(rng)));
    Vector3<S> b0(S(u(rng)), S(u(rng)), S(u(rng))), e(S(u(rng)), S(u(rng)), S(u(rng)));
    if (kind == 1) e = S(-0.7) * d;
    if (kind == 2) b0 = a0 + S(0.5 + u(rng)) * d, e = S(2) * d;
    if (kind == 3) e = Vector3<S>::Zero();
    if (kind == 4) b0 = a0 + S(0.5) * d - S(0.5) * e + Vector3<S>(S(0), S(0), S(0.01 * u(rng)));
    const Capsule<S> P(a0, Vector3<S>(a0 + d), S(0.05 + 0.1 * (u(rng) + 1)));
    const Capsule<S> Q(b0, Vector3<S>(b0 + e), S(0.05 + 0.1 * (u(rng) + 1)));
    const auto placedP = place(P, Pose<S>::identity()), placedQ = place(Q, Pose<S>::identity());
    const auto closed = gjk(placedP, placedQ);
    const auto looped = gjk(placedP, placedQ, {}, nullptr, loop);
    const Real truth = segmentSegmentDistance(test::toReal(P.axis.a), test::toReal(P.axis.b), test::toReal(Q.axis.a),
                                              test::toReal(Q.axis.b)) -
                       Real(P.radius) - Real(Q.radius);
    INFO("trial " << trial << " kind " << kind << ": closed " << toString(closed.status) << " at " << closed.distance
                  << ", loop " << toString(looped.status) << " at " << looped.distance << ", truth " << double(truth));
    checkAgainst(closed, truth, 2);
    CHECK(std::abs(Real(closed.distance) - Real(looped.distance)) <= tol);
    if (std::abs(truth) > tol) CHECK(closed.status == looped.status);
    // The simplex: lambdas in [0, 1] summing to 1, sum of lambda_k w_k = the cores' z.
    const Simplex<S>& x = closed.simplex;
    REQUIRE(x.size >= 1);
    REQUIRE(x.size <= 3);
    edgeEdge += x.size == 3;
    Real sum = 0;
    RVec z = RVec::Zero();
    for (int k = 0; k < x.size; ++k) {
      CHECK(x.lambda[k] >= S(0));
      sum += Real(x.lambda[k]);
      z += Real(x.lambda[k]) * test::toReal(x.vertices[k].w);
    }
    CHECK(std::abs(sum - 1) <= tol);
    CHECK((z - test::toReal(x.z)).norm() <= tol);
  }
  CHECK(edgeEdge > 20);  // the parallelogram case was exercised
}
