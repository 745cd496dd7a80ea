// Conservative advancement (§4's "popular way", the paper's reference [8]) on cases a
// reader can check by hand: two unit boxes (half extents 1/2) whose facing faces are 1
// apart and close at speed 2 touch at t = 1/2; a pass beside them never touches; a cap of
// one step ends in its own status; bad input is refused where it enters.
#include <gjkx/brent/conservative_advancement.hpp>
#include <gjkx/support_mapping/placed.hpp>
#include <gjkx/support_mapping/primitives.hpp>

#include <catch2/catch.hpp>

#include <stdexcept>

using namespace gjkx;

namespace {

template <typename S>
Moving<Box<S>> unitBoxMoving(const Vector3<S>& start, const Vector3<S>& velocity) {
  return moving(Box<S>(Vector3<S>(S(0.5), S(0.5), S(0.5))), Motion<S>::constantVelocity(Pose<S>::translate(start), velocity));
}

// P starts at x = -2 (its right face at -1.5), moving +x at speed 2; Q rests at the origin
// (its left face at -0.5), `side` off P's path in y: the faces are 1 apart, touching at t = 1/2.
template <typename S>
std::pair<Moving<Box<S>>, Moving<Box<S>>> approachingBoxes(S side = S(0)) {
  return {unitBoxMoving<S>(Vector3<S>(S(-2), side, S(0)), Vector3<S>(S(2), S(0), S(0))),
          unitBoxMoving<S>(Vector3<S>::Zero(), Vector3<S>::Zero())};
}

}  // namespace

TEMPLATE_TEST_CASE("conservative advancement finds two boxes' time of impact at t = 1/2", "[brent][ca]", double, float) {
  using S = TestType;
  const auto [P, Q] = approachingBoxes<S>();
  ConservativeAdvancementSettings<S> settings;
  settings.relativeSpeedBound = S(2);  // P's speed; Q rests; neither turns
  settings.collisionTolerance = S(1e-4);
  const auto r = conservativeAdvancement(P, Q, S(0), S(1), settings);
  REQUIRE(r.status == ConservativeAdvancementStatus::Hit);
  // Not after the contact, and no earlier than where the bodies come within the tolerance.
  CHECK(r.time <= S(0.5) + S(1e-6));
  CHECK(r.time >= S(0.5) - settings.collisionTolerance / S(2) - S(1e-6));
  // Face to face, GJK's lower bound is the exact gap 1: the first step lands on t = 1/2.
  CHECK(r.steps <= 3);
  CHECK(reportsCollision(r.status));
}

TEMPLATE_TEST_CASE("conservative advancement: a pass beside the box is no collision", "[brent][ca]", double, float) {
  using S = TestType;
  const auto [P, Q] = approachingBoxes<S>(S(1.5));  // 0.5 of clear space between the y faces
  ConservativeAdvancementSettings<S> settings;
  settings.relativeSpeedBound = S(2);
  const auto r = conservativeAdvancement(P, Q, S(0), S(1), settings);
  CHECK(r.status == ConservativeAdvancementStatus::NoCollision);
  CHECK(r.time == S(1));
  CHECK_FALSE(reportsCollision(r.status));
}

TEST_CASE("conservative advancement: nothing moves, decided at t0", "[brent][ca]") {
  const auto [P, Q] = approachingBoxes<double>();
  const auto still = unitBoxMoving<double>(Vector3<double>(-2, 0, 0), Vector3<double>::Zero());
  ConservativeAdvancementSettings<double> settings;  // L = 0
  const auto r = conservativeAdvancement(still, Q, 0.0, 1.0, settings);
  CHECK(r.status == ConservativeAdvancementStatus::NoCollision);
  CHECK(r.steps == 1);
  (void)P;
}

TEST_CASE("conservative advancement: the cap on steps is its own status, never no collision", "[brent][ca]") {
  const auto [P, Q] = approachingBoxes<double>();
  ConservativeAdvancementSettings<double> settings;
  settings.relativeSpeedBound = 2;
  settings.maxSteps = 1;  // one step reaches t = 1/2, not yet decided
  const auto r = conservativeAdvancement(P, Q, 0.0, 1.0, settings);
  CHECK(r.status == ConservativeAdvancementStatus::IterationCap);
  CHECK(r.steps == 1);
  CHECK(r.time == Approx(0.5));
  CHECK(reportsCollision(r.status));  // undecided: a caller that may not miss takes it as a hit
  CHECK(std::string(toString(r.status)) == "iteration-cap");
}

TEST_CASE("conservative advancement refuses bad input", "[brent][ca][input]") {
  const auto [P, Q] = approachingBoxes<double>();
  ConservativeAdvancementSettings<double> settings;
  settings.relativeSpeedBound = 2;
  CHECK_THROWS_AS(conservativeAdvancement(P, Q, 1.0, 0.0, settings), std::invalid_argument);  // t1 < t0
  CHECK_THROWS_WITH(conservativeAdvancement(P, Q, 1.0, 0.0, settings), Catch::Matchers::StartsWith("conservativeAdvancement.t1"));
  settings.relativeSpeedBound = -1;
  CHECK_THROWS_AS(conservativeAdvancement(P, Q, 0.0, 1.0, settings), std::invalid_argument);
  settings.relativeSpeedBound = 2;
  settings.maxSteps = 0;
  CHECK_THROWS_AS(conservativeAdvancement(P, Q, 0.0, 1.0, settings), std::invalid_argument);
}
