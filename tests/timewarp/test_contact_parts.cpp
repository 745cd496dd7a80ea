// The hybrid's parts one at a time (contact_manifold.hpp, coulomb_friction.hpp): two
// pieces that overlap read an overlap in their manifold, never a gap, as deep as the
// solver's, at random poses; and a point's friction step is the least kinetic energy on
// Coulomb's disc, sliding against its slip.
#include <gjkx/gjk/gjk.hpp>
#include <gjkx/support_mapping/placed.hpp>
#include <gjkx/support_mapping/shape.hpp>
#include <gjkx/timewarp/contact_manifold.hpp>
#include <gjkx/timewarp/coulomb_friction.hpp>

#include <catch2/catch.hpp>

#include <Eigen/Geometry>

#include <cmath>
#include <random>

using namespace gjkx;

namespace {

const double tol = 3.4526698e-4;  // the scene's default collision tolerance

/// A pose at `at`, turned at random (a unit quaternion of four uniform numbers).
Pose<double> randomPose(std::mt19937& random, const Eigen::Vector3d& at) {
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  Pose<double> p;
  p.rotation = Eigen::Quaterniond(Eigen::Vector4d(unit(random), unit(random), unit(random), unit(random)).normalized())
                   .toRotationMatrix();
  p.translation = at;
  return p;
}

/// GJK on two placed pieces, cold.
GjkResult<double> closestPoints(const Shape<double>& a, const Pose<double>& poseA, const Shape<double>& b,
                                const Pose<double>& poseB) {
  return gjk(Placed<ShapeRef<double>>{a, poseA}, Placed<ShapeRef<double>>{b, poseB}, GjkSettings<double>{}, nullptr);
}

}  // namespace

TEST_CASE("hybrid: pieces that overlap read an overlap in their manifold, never a gap") {
  // The projection parts a pair by what its manifold reads, so an overlap read as a gap
  // stays. Overlapping pieces' normal is the axis of least overlap, not a closest points'
  // direction, and their touching features can miss each other on its plane: the manifold
  // then has one point, and read at the pieces' distance, 0, it would hold a sphere inside
  // a polytope (as in a 250-body pile, timewarp_benchmark --bodies 250). Random convex
  // polytopes of ten points (the pile's) against a sphere, a box and another such
  // polytope, moved into each other by a tolerance along the normal of their closest
  // points; the solver's normal (the axis of least overlap, then a face's own normal).
  std::mt19937 random(2026);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  const auto polytope = [&] {
    std::vector<Eigen::Vector3d> points;
    for (int k = 0; k < 10; ++k) points.push_back(0.1 * Eigen::Vector3d(unit(random), unit(random), unit(random)));
    return Shape<double>(Polytope<double>::hull(points));
  };
  int overlaps = 0, missed = 0;
  for (int trial = 0; trial < 300; ++trial) {
    const Shape<double> a = polytope();
    const Shape<double> b = trial % 3 == 0   ? Shape<double>(Sphere<double>(0.1))
                            : trial % 3 == 1 ? Shape<double>(Box<double>(Eigen::Vector3d(0.1, 0.07, 0.04)))
                                             : polytope();
    const Pose<double> poseA = randomPose(random, Eigen::Vector3d::Zero());
    Pose<double> poseB = randomPose(random, 0.5 * Eigen::Vector3d(unit(random), unit(random), unit(random)).normalized());
    const auto closest = [&] { return closestPoints(a, poseA, b, poseB); };
    const GjkResult<double> far = closest();
    REQUIRE(far.status == GjkStatus::Separated);
    const Eigen::Vector3d n = far.z / far.distance;  // from A to B
    poseB.translation -= (far.distance + tol) * n;
    // (Past a sharp corner of A - B the move can leave the pieces a hair apart: not counted.)
    if (closest().status != GjkStatus::Overlapping) continue;
    const Eigen::Vector3d normal =
        faceNormal(a, poseA, b, poseB, leastOverlapAxis(a, poseA, b, poseB, {n}), 2 * tol + 1e-3);
    // The features as deep as the contact band, a resting pair's (docs 07's known limits:
    // far deeper, a feature spanning several faces can read a chord's gap).
    const auto points = contactManifold(a, poseA, b, poseB, normal, 2 * tol, Eigen::Vector3d::Zero(), 0.0, tol);
    REQUIRE(!points.empty());
    double nearest = 1e300;
    for (const ManifoldPoint& p : points) nearest = std::min(nearest, p.separation);
    INFO("trial " << trial << ": " << points.size() << " points, the nearest at " << nearest);
    CHECK(nearest < 0);
    ++overlaps;
    missed += points.size() == 1 && points.front().point == Eigen::Vector3d::Zero();  // the features missed
  }
  CHECK(overlaps >= 200);
  CHECK(missed > 0);  // the case this test is for occurs
}

TEST_CASE("hybrid: pieces that overlap read an overlap in a manifold as deep as the solver's") {
  // The solver's features reach as deep as a pair can close over the interval (the band and
  // the pair's motion: up to twenty tolerances in the torso's crash). So deep, the feature of
  // a curved piece spans several of its faces, and the plane of its hull (a chord) lies off
  // its surface by up to that depth: overlapping pieces could read a gap of ten tolerances,
  // and the projection would leave them inside each other. Flat random polytopes of ten to
  // forty points (a bone's pieces), moved into each other by 0.1 to 3 tolerances along the
  // normal of their closest points, their features 2 to 20 tolerances deep.
  std::mt19937 random(7);
  std::uniform_real_distribution<double> unit(-1.0, 1.0), fraction(0.0, 1.0);
  const auto polytope = [&](int points) {
    std::vector<Eigen::Vector3d> cloud;
    for (int k = 0; k < points; ++k)
      cloud.push_back(0.05 * Eigen::Vector3d(unit(random), 0.5 * unit(random), 0.3 * unit(random)));
    return Shape<double>(Polytope<double>::hull(cloud));
  };
  int overlaps = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    const Shape<double> a = polytope(10 + trial % 30), b = polytope(10 + (trial / 7) % 30);
    const Pose<double> poseA = randomPose(random, Eigen::Vector3d::Zero());
    Pose<double> poseB = randomPose(random, 0.3 * Eigen::Vector3d(unit(random), unit(random), unit(random)).normalized());
    const auto closest = [&] { return closestPoints(a, poseA, b, poseB); };
    const GjkResult<double> far = closest();
    REQUIRE(far.status == GjkStatus::Separated);
    const Eigen::Vector3d n = far.z / far.distance;  // from A to B
    poseB.translation -= (far.distance + (0.1 + 2.9 * fraction(random)) * tol) * n;
    const double depth = (2 + 18 * fraction(random)) * tol;
    if (closest().status != GjkStatus::Overlapping) continue;  // (past a sharp corner: a hair apart)
    const Eigen::Vector3d normal = faceNormal(a, poseA, b, poseB, leastOverlapAxis(a, poseA, b, poseB, {n}), depth);
    const auto points = contactManifold(a, poseA, b, poseB, normal, depth, Eigen::Vector3d::Zero(), 0.0, tol);
    REQUIRE(!points.empty());
    double nearest = 1e300;
    for (const ManifoldPoint& p : points) nearest = std::min(nearest, p.separation);
    INFO("trial " << trial << ": " << points.size() << " points, features " << depth / tol
                  << " tolerances deep, the nearest at " << nearest / tol << " tolerances");
    CHECK(nearest < 0);
    ++overlaps;
  }
  CHECK(overlaps >= 1500);
}

TEST_CASE("hybrid: a point's friction step is the least energy on Coulomb's disc, and slides against its slip") {
  // frictionInDisc against a search of the disc: random tangent blocks K (well and badly
  // conditioned), impulses inside the disc and slips. φ(f) = s·(f − f0) + ½ (f − f0)ᵀ K (f − f0)
  // is the change of kinetic energy; no point of a fine polar grid of the disc may beat the step.
  std::mt19937 random(7);
  std::uniform_real_distribution<double> unit(-1, 1);
  int sticks = 0, slides = 0;
  for (int trial = 0; trial < 200; ++trial) {
    Eigen::Matrix2d A;
    A << unit(random), unit(random), unit(random), unit(random);
    const double spread = trial % 2 ? 1e-3 : 1.0;  // every other block nearly singular along one axis
    const Eigen::Matrix2d K = A * A.transpose() + spread * Eigen::Matrix2d::Identity();
    const double limit = 0.05 + std::abs(unit(random));
    const Eigen::Vector2d old = limit * std::abs(unit(random)) * Eigen::Vector2d(unit(random), unit(random)).normalized();
    const Eigen::Vector2d slip = (trial % 3 ? 3.0 : 0.05) * Eigen::Vector2d(unit(random), unit(random));
    const auto phi = [&](const Eigen::Vector2d& f) {
      const Eigen::Vector2d d = f - old;
      return slip.dot(d) + 0.5 * d.dot(K * d);
    };
    const Eigen::Vector2d f = frictionInDisc(TangentBlock::of(K), old, slip, limit);
    INFO("trial " << trial << ": K = [" << K(0, 0) << " " << K(0, 1) << "; " << K(1, 0) << " " << K(1, 1) << "], limit "
                  << limit << ", f = (" << f.x() << ", " << f.y() << ")");
    REQUIRE(f.allFinite());
    CHECK(f.norm() <= limit * (1 + 1e-12));
    CHECK(phi(f) <= 1e-15);  // never above the energy of the impulse it started from
    double best = 0;
    for (int r = 0; r <= 400; ++r)
      for (int a = 0; a < 720; ++a) {
        const double radius = limit * r / 400.0, angle = a * M_PI / 360.0;
        best = std::min(best, phi(radius * Eigen::Vector2d(std::cos(angle), std::sin(angle))));
      }
    CHECK(phi(f) <= best + 1e-12);
    const Eigen::Vector2d left = slip + K * (f - old);  // the slip the step leaves
    if (f.norm() < limit * (1 - 1e-9)) {
      ++sticks;
      CHECK(left.norm() <= 1e-9 * (1 + slip.norm()));  // inside the disc: the point sticks
    } else {
      ++slides;
      if (left.norm() > 1e-9) CHECK(left.normalized().dot(f.normalized()) < -1 + 1e-9);  // against the slip
    }
  }
  CHECK(sticks > 20);
  CHECK(slides > 20);
}
