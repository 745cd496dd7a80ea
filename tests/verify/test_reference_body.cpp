// The independent checks' distance of two many-piece bodies (gjkx/verify/reference_body.hpp): the search that
// measures only the piece pairs its bounds cannot rule out gives the least over all piece
// pairs, to the bit, measured pair by pair with referencePieceDistance.
#include <gjkx/verify/reference_body.hpp>

#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

using namespace gjkx;

namespace {

/// A body as the checks take it: a name and its convex pieces.
struct Body {
  std::string name;
  std::vector<Shape<double>> pieces;
};

ReferenceBody prepared(const Body& body) { return ReferenceBody(body.name, body.pieces); }

/// A ball about a piece in its body's frame: about its axis-aligned box, which the support
/// mapping gives exactly (the extreme points along the six axis directions).
std::pair<Eigen::Vector3d, double> ballAbout(const Shape<double>& piece) {
  Eigen::Vector3d lo, hi;
  for (int k = 0; k < 3; ++k) {
    const Eigen::Vector3d axis = Eigen::Vector3d::Unit(k);
    hi[k] = piece.support(axis)[k];
    lo[k] = piece.support(-axis)[k];
  }
  return {(lo + hi) / 2, (hi - lo).norm() / 2};
}

/// The least referencePieceDistance over every piece pair: what the search must equal.
/// A pair whose balls are farther apart than the least so far (with a margin for rounding)
/// cannot be the least, so it is not measured: the answer is the same.
double allPairs(const Body& a, const Pose<double>& poseA, const Body& b, const Pose<double>& poseB) {
  double least = std::numeric_limits<double>::infinity();
  for (const auto& pa : a.pieces) {
    const auto [centreA, radiusA] = ballAbout(pa);
    for (const auto& pb : b.pieces) {
      const auto [centreB, radiusB] = ballAbout(pb);
      if ((poseA(centreA) - poseB(centreB)).norm() - radiusA - radiusB > least + 1e-9) continue;
      least = std::min(least, referencePieceDistance(pa, poseA, pb, poseB));
    }
  }
  return least;
}

Eigen::Vector3d uniform(std::mt19937& rng, double lo, double hi) {
  std::uniform_real_distribution<double> u(lo, hi);
  return {u(rng), u(rng), u(rng)};
}

Pose<double> randomPose(std::mt19937& rng, const Eigen::Vector3d& lo, const Eigen::Vector3d& hi) {
  std::uniform_real_distribution<double> u(0, 1);
  const Eigen::Quaterniond q(Eigen::Vector4d(u(rng) - 0.5, u(rng) - 0.5, u(rng) - 0.5, u(rng) - 0.5).normalized());
  Pose<double> pose;
  pose.rotation = q.toRotationMatrix();
  for (int k = 0; k < 3; ++k) pose.translation[k] = lo[k] + (hi[k] - lo[k]) * u(rng);
  return pose;
}

/// A bone-like body: small hulls (the reference measures them), two hulls of more than 16
/// vertices (GJK measures them), a box, a sphere and a capsule, about a 0.2-wide cluster.
Body boneLike(std::mt19937& rng) {
  Body body;
  body.name = "bone";
  for (int k = 0; k < 6; ++k) {
    const Eigen::Vector3d centre = uniform(rng, -0.08, 0.08);
    std::vector<Eigen::Vector3d> points;
    for (int p = 0; p < 7; ++p) points.push_back(centre + uniform(rng, -0.03, 0.03));
    body.pieces.push_back(Polytope<double>::hull(points));
  }
  for (int k = 0; k < 2; ++k) {
    const Eigen::Vector3d centre = uniform(rng, -0.08, 0.08);
    std::vector<Eigen::Vector3d> points;
    for (int p = 0; p < 40; ++p) points.push_back(centre + 0.03 * uniform(rng, -1, 1).normalized());
    body.pieces.push_back(Polytope<double>::hull(points));
  }
  body.pieces.push_back(Box<double>(Eigen::Vector3d(0.03, 0.02, 0.01)));
  body.pieces.push_back(Sphere<double>(0.02));
  body.pieces.push_back(Capsule<double>(Eigen::Vector3d(-0.05, 0.05, 0), Eigen::Vector3d(0.05, 0.05, 0), 0.01));
  return body;
}

/// A plant-like body: thin prisms on the triangles of a wavy sheet in z in [0, 0.1], the
/// triangles sharing vertices as a leaf's do (pairs of pieces at equal distance).
Body plantLike(int cells) {
  Body body;
  body.name = "plant";
  auto sheet = [&](int i, int j) {
    const double x = 0.4 * i / cells - 0.2, y = 0.4 * j / cells - 0.2;
    return Eigen::Vector3d(x, y, 0.05 + 0.05 * std::sin(9 * x) * std::cos(7 * y));
  };
  for (int i = 0; i < cells; ++i)
    for (int j = 0; j < cells; ++j)
      for (int half = 0; half < 2; ++half) {
        const Eigen::Vector3d a = sheet(i, j), b = half ? sheet(i + 1, j + 1) : sheet(i + 1, j),
                              c = half ? sheet(i, j + 1) : sheet(i + 1, j + 1);
        const Eigen::Vector3d back = -1e-3 * (b - a).cross(c - a).normalized();
        body.pieces.push_back(Polytope<double>::hull({a, b, c, a + back, b + back, c + back}));
      }
  return body;
}

}  // namespace

TEST_CASE("checks: the pruned search equals the least over all piece pairs, bone against plant") {
  std::mt19937 rng(11);
  const Body bone = boneLike(rng), plant = plantLike(7);  // 11 pieces against 98
  const ReferenceBody boneRef = prepared(bone), plantRef = prepared(plant);
  REQUIRE(boneRef.pieceCount() == 11);
  REQUIRE(plantRef.pieceCount() == 98);
  int overlapping = 0, apart = 0;
  for (int k = 0; k < 18; ++k) {
    // Over the sheet, from well inside it to well clear of it; the plant moved and turned too.
    const Pose<double> poseBone = randomPose(rng, {-0.2, -0.2, -0.05}, {0.2, 0.2, 0.3});
    const Pose<double> posePlant = k % 3 == 0 ? Pose<double>::identity() : randomPose(rng, {0, 0, 0}, {1e-3, 1e-3, 1e-3});
    const double expected = allPairs(bone, poseBone, plant, posePlant);
    CAPTURE(k, expected);
    // Either order: the body with fewer pieces queries the other's tree.
    CHECK(referenceSignedDistance(boneRef, poseBone, plantRef, posePlant) == expected);
    CHECK(referenceSignedDistance(plantRef, posePlant, boneRef, poseBone) == allPairs(plant, posePlant, bone, poseBone));
    (expected < 0 ? overlapping : apart) += 1;
  }
  // The poses must cover both sides of contact, or the test says little.
  CHECK(overlapping >= 3);
  CHECK(apart >= 3);
}

TEST_CASE("checks: the pruned search equals the least over all piece pairs, near ties of two bones") {
  std::mt19937 rng(5);
  const Body a = boneLike(rng), b = boneLike(rng);
  const ReferenceBody refA = prepared(a), refB = prepared(b);
  for (int k = 0; k < 24; ++k) {
    const Pose<double> poseA = randomPose(rng, {0, 0, 0}, {0, 0, 0});
    const Pose<double> poseB = randomPose(rng, {-0.25, -0.25, -0.25}, {0.25, 0.25, 0.25});
    CAPTURE(k);
    CHECK(referenceSignedDistance(refA, poseA, refB, poseB) == allPairs(a, poseA, b, poseB));
  }
  // A body against itself at the same pose: every piece overlaps its twin.
  const Pose<double> pose = randomPose(rng, {-1, -1, -1}, {1, 1, 1});
  CHECK(referenceSignedDistance(refA, pose, refA, pose) == allPairs(a, pose, a, pose));
  CHECK(referenceSignedDistance(refA, pose, refA, pose) < 0);
}

TEST_CASE("checks: asked only below a floor, the search gives the distance below it and a bound above it") {
  // The penetration check asks with enough = 0: an overlap must come out exact, a gap as a
  // lower bound between 0 and the distance (a pile at rest is hundreds of such gaps).
  std::mt19937 rng(13);
  const Body bone = boneLike(rng), plant = plantLike(7);
  const ReferenceBody boneRef = prepared(bone), plantRef = prepared(plant);
  int overlapping = 0, apart = 0;
  for (int k = 0; k < 18; ++k) {
    const Pose<double> poseBone = randomPose(rng, {-0.2, -0.2, -0.05}, {0.2, 0.2, 0.3});
    const double exact = referenceSignedDistance(boneRef, poseBone, plantRef, Pose<double>::identity());
    for (const double enough : {0.0, 0.01}) {
      const double bounded = referenceSignedDistance(boneRef, poseBone, plantRef, Pose<double>::identity(), enough);
      CAPTURE(k, enough, exact, bounded);
      if (exact < enough) {
        CHECK(bounded == exact);
      } else {
        CHECK(bounded >= enough);
        CHECK(bounded <= exact);
      }
    }
    (exact < 0 ? overlapping : apart) += 1;
  }
  CHECK(overlapping >= 3);
  CHECK(apart >= 3);
}

TEST_CASE("checks: a convex body against a convex body is their piece distance") {
  Body a, b;
  a.pieces = {Sphere<double>(0.5)};
  b.pieces = {Box<double>(Eigen::Vector3d(1, 1, 1))};
  const Pose<double> poseA = Pose<double>::translate(Eigen::Vector3d(0, 0, 2)), poseB = Pose<double>::identity();
  CHECK(referenceSignedDistance(prepared(a), poseA, prepared(b), poseB) == Approx(0.5).epsilon(1e-12));
  CHECK(referenceSignedDistance(prepared(a), poseA, prepared(b), poseB) == referencePieceDistance(a.pieces[0], poseA, b.pieces[0], poseB));
}

TEST_CASE("checks: a cylinder against a box, standing, lying and overlapping, by hand") {
  // The cylinder r = 0.1, h = 0.15 over a box whose top is z = 0. Standing at height z its
  // cap is z - h above the top; lying (its axis along x), its side is z - r above it; and
  // the same with the cylinder turned about its axis, which must not matter.
  Body cylinder, floor;
  cylinder.pieces = {Cylinder<double>(0.1, 0.15)};
  floor.pieces = {Box<double>(Eigen::Vector3d(5, 5, 0.5))};
  const ReferenceBody c = prepared(cylinder), f = prepared(floor);
  const Pose<double> poseFloor = Pose<double>::translate(Eigen::Vector3d(0, 0, -0.5));
  const Eigen::Vector3d y = Eigen::Vector3d::UnitY(), z = Eigen::Vector3d::UnitZ();
  // (GJK measures a cylinder: an overlap is a distance of 0, not a depth.)
  const auto expected = [](double distance) { return Approx(std::max(distance, 0.0)).margin(1e-6); };
  for (const double height : {0.3, 0.1501, 0.12, 0.09}) {
    INFO("height " << height);
    const Pose<double> standing = Pose<double>::translate(Eigen::Vector3d(0.2, 0, height));
    CHECK(referenceSignedDistance(c, standing, f, poseFloor) == expected(height - 0.15));
    for (const double spin : {0.0, 0.3, 1.0}) {
      INFO("spin " << spin);
      const Pose<double> lying = Pose<double>::fromAxisAngle(y, M_PI / 2, Eigen::Vector3d(0, 0, height)) *
                                 Pose<double>::fromAxisAngle(z, spin, Eigen::Vector3d::Zero());
      CHECK(referenceSignedDistance(c, lying, f, poseFloor) == expected(height - 0.1));
    }
  }
}

TEST_CASE("checks: a pose that is not finite is refused, not measured as infinitely far") {
  Body a;
  a.pieces = {Sphere<double>(0.5), Box<double>(Eigen::Vector3d(0.1, 0.1, 0.1))};
  const ReferenceBody ref = prepared(a);
  Pose<double> bad = Pose<double>::identity();
  bad.translation.x() = std::nan("");
  CHECK_THROWS_WITH(referenceSignedDistance(ref, bad, ref, Pose<double>::identity()), Catch::Contains("not finite"));
  CHECK_THROWS_WITH(referenceSignedDistance(ref, Pose<double>::identity(), ref, bad), Catch::Contains("not finite"));
}

TEST_CASE("checks: a body with no pieces is refused by name") {
  Body empty;
  empty.name = "ghost";
  empty.pieces.clear();
  CHECK_THROWS_WITH(prepared(empty), Catch::Contains("ghost") && Catch::Contains("no pieces"));
}
