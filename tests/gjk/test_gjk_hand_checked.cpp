// Hand-checkable GJK cases: answers a reader can verify with a ruler.
#include <gjkx/gjk/gjk.hpp>
#include <gjkx/support_mapping/placed.hpp>
#include <gjkx/support_mapping/primitives.hpp>
#include <gjkx/support_mapping/shape.hpp>

#include <catch2/catch.hpp>

using namespace gjkx;

TEMPLATE_TEST_CASE("two unit boxes two apart are at distance 1", "[gjk][hand]", float, double) {
  using S = TestType;
  const Box<S> unit(Vector3<S>(S(0.5), S(0.5), S(0.5)));
  const auto P = place(unit, Pose<S>::identity());
  const auto Q = place(unit, Pose<S>::translate(Vector3<S>(2, 0, 0)));
  const GjkResult<S> r = gjk(P, Q);
  REQUIRE(r.status == GjkStatus::Separated);
  CHECK(r.distance == Approx(1.0).epsilon(1e-5));
  CHECK(r.witnessP.x() == Approx(0.5));
  CHECK(r.witnessQ.x() == Approx(1.5));
  CHECK(r.lowerBound == Approx(1.0).epsilon(1e-5));
}

TEST_CASE("a sphere and a point: distance is |c| - r", "[gjk][hand]") {
  const auto P = place(Sphere<double>(1.0), Pose<double>::translate({3, 4, 0}));
  const Point<double> Q(Vector3<double>::Zero());
  const auto r = gjk(P, Q);
  REQUIRE(r.status == GjkStatus::Separated);
  CHECK(r.distance == Approx(4.0).epsilon(1e-9));
  CHECK(r.witnessP.x() == Approx(3.0 - 0.6).epsilon(1e-6));
}

TEST_CASE("overlapping boxes report Overlapping with distance 0", "[gjk][hand]") {
  const Box<double> unit(Vector3<double>(0.5, 0.5, 0.5));
  const auto P = place(unit, Pose<double>::identity());
  const auto Q = place(unit, Pose<double>::translate({0.5, 0.2, 0.1}));
  const auto r = gjk(P, Q);
  REQUIRE(r.status == GjkStatus::Overlapping);
  CHECK(r.distance == 0.0);
}
