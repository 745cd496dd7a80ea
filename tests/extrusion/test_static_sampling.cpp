// Static sampling (§1's static test over an interval) on cases a reader can check by hand:
// two unit boxes (half extents 1/2) whose facing faces are 1 apart and close at speed 2
// touch at t = 1/2; sampling finds the first instant at or after that, within one
// spacing; a fast box through a thin plate between two instants is missed (§1's "passed
// straight through each other"); bad input is refused where it enters.
#include <gjkx/extrusion/static_sampling.hpp>
#include <gjkx/support_mapping/placed.hpp>
#include <gjkx/support_mapping/primitives.hpp>

#include <catch2/catch.hpp>

#include <stdexcept>

using namespace gjkx;

namespace {

template <typename S>
Moving<Box<S>> boxMoving(const Vector3<S>& half, const Vector3<S>& start, const Vector3<S>& velocity) {
  return moving(Box<S>(half), Motion<S>::constantVelocity(Pose<S>::translate(start), velocity));
}

}  // namespace

TEMPLATE_TEST_CASE("static sampling finds the first sampled instant of contact", "[extrusion][static]", double, float) {
  using S = TestType;
  const Vector3<S> half(S(0.5), S(0.5), S(0.5));
  // Contact at t = 0.45: P's right face starts 0.9 from Q's left face, closing at speed 2.
  const auto P = boxMoving<S>(half, Vector3<S>(S(-1.9), S(0), S(0)), Vector3<S>(S(2), S(0), S(0)));
  const auto Q = boxMoving<S>(half, Vector3<S>::Zero(), Vector3<S>::Zero());
  const auto r = staticSampling(P, Q, S(0), S(1), 11);  // instants 0, 0.1, ..., 1
  REQUIRE(r.status == StaticSamplingStatus::Hit);
  CHECK(r.time == Approx(0.5));  // the first instant at or after 0.45
  CHECK(r.samplesRun == 6);
  CHECK(r.intersection == IntersectionStatus::Intersecting);
  // On [0.2, 0.7] with 6 instants (0.2, 0.3, ..., 0.7) the same first instant, 0.5.
  const auto shifted = staticSampling(P, Q, S(0.2), S(0.7), 6);
  REQUIRE(shifted.status == StaticSamplingStatus::Hit);
  CHECK(shifted.time == Approx(0.5));
  CHECK(staticTest(P, Q, S(0), S(1), 11));
}

TEST_CASE("static sampling misses a box passing through a plate between two instants", "[extrusion][static]") {
  // A box of half size 0.05 from x = -1 to x = 1 through a plate |x| <= 0.01: inside it only
  // for |t - 1/2| <= 0.03, between the instants 0.4 and 0.6 of 6 samples.
  const auto P = boxMoving<double>(Vector3<double>(0.05, 0.05, 0.05), Vector3<double>(-1, 0, 0), Vector3<double>(2, 0, 0));
  const auto plate = boxMoving<double>(Vector3<double>(0.01, 1, 1), Vector3<double>::Zero(), Vector3<double>::Zero());
  const auto coarse = staticSampling(P, plate, 0.0, 1.0, 6);
  CHECK(coarse.status == StaticSamplingStatus::NoCollision);
  CHECK(coarse.time == 1.0);
  CHECK(coarse.samplesRun == 6);
  CHECK_FALSE(reportsCollision(coarse.status));
  const auto fine = staticSampling(P, plate, 0.0, 1.0, 101);  // instant 0.5 is a sample
  CHECK(fine.status == StaticSamplingStatus::Hit);
  CHECK(fine.time == Approx(0.47).margin(0.011));  // the first sample with |t - 1/2| <= 0.03
}

TEST_CASE("static sampling refuses bad input", "[extrusion][static][input]") {
  const auto P = boxMoving<double>(Vector3<double>(0.5, 0.5, 0.5), Vector3<double>(-2, 0, 0), Vector3<double>(2, 0, 0));
  CHECK_THROWS_AS(staticSampling(P, P, 1.0, 0.0, 8), std::invalid_argument);  // t1 < t0
  CHECK_THROWS_WITH(staticSampling(P, P, 1.0, 0.0, 8), Catch::Matchers::StartsWith("staticSampling.t1"));
  CHECK_THROWS_AS(staticSampling(P, P, 0.0, 1.0, 0), std::invalid_argument);  // zero samples
  CHECK_THROWS_WITH(staticSampling(P, P, 0.0, 1.0, 0), Catch::Matchers::StartsWith("staticSampling.samples"));
  CHECK_THROWS_AS(staticSampling(P, P, 0.0, 1.0, 1), std::invalid_argument);  // one instant cannot span an interval
}
