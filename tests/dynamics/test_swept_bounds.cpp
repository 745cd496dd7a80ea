// Swept bounds (swept_bounds.hpp) against the path they bound: the box holds the body at
// every sampled time of the interval, for bodies that fall, turn slowly and spin fast; and
// for a long bar turning slowly it is far tighter than the sphere about its centre of mass
// (the box every orientation could reach).
#include <gjkx/dynamics/swept_bounds.hpp>
#include <gjkx/dynamics/mass_properties.hpp>
#include <gjkx/support_mapping/placed.hpp>

#include <catch2/catch.hpp>

using namespace gjkx;

namespace {

// The body's own box at time t of the path (its support along each axis).
Bounds boxAt(const Shape<double>& shape, const FreeFlight& path, double t) {
  const Placed<Shape<double>> placed{shape, path.stateAt(t).worldFromBody};
  Bounds b;
  for (int k = 0; k < 3; ++k) {
    Eigen::Vector3d e = Eigen::Vector3d::Zero();
    e[k] = 1;
    b.add(Eigen::Vector3d(placed.support(e)));
    b.add(Eigen::Vector3d(placed.support(-e)));
  }
  return b;
}

bool holds(const Bounds& outer, const Bounds& inner) {
  return (outer.lo.array() <= inner.lo.array()).all() && (inner.hi.array() <= outer.hi.array()).all();
}

}  // namespace

TEST_CASE("swept bounds hold a falling, turning or spinning bar at every sampled time") {
  const Box<double> bar(Eigen::Vector3d(0.5, 0.02, 0.02));  // a bar 1 m long
  const Shape<double> shape(bar);
  const RigidBody body = RigidBody::dynamic(massProperties(bar, 1000.0));
  const double radius = Eigen::Vector3d(0.5, 0.02, 0.02).norm();
  const Eigen::Vector3d gravity(0, 0, -9.81);
  const double spin = GENERATE(0.0, 0.5, 3.0, 40.0);  // rad/s about an axis off every principal one
  BodyState start;
  start.worldFromBody = Pose<double>::fromRotationTranslation(
      Eigen::AngleAxisd(0.3, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix(), Eigen::Vector3d(0.1, -0.2, 1));
  start.velocity = Eigen::Vector3d(1.5, -0.5, 2);
  start.angularVelocity = spin * Eigen::Vector3d(0.2, 0.9, 0.4).normalized();
  const double T = 0.03;  // under half a turn at 40 rad/s
  const FreeFlight path = freeFlight(body, start, 0.0, T, gravity);
  for (const auto& [t0, t1] : {std::pair{0.0, T}, std::pair{0.01, 0.02}}) {
    const Bounds swept = sweptBounds(shape, radius, false, path, t0, t1, gravity);
    for (int k = 0; k <= 200; ++k) {
      const double t = t0 + (t1 - t0) * k / 200.0;
      INFO("spin " << spin << " rad/s, interval [" << t0 << ", " << t1 << "], t = " << t);
      CHECK(holds(swept, boxAt(shape, path, t)));
    }
  }
}

TEST_CASE("the swept box of a slowly turning bar is its own box, not the sphere of every orientation") {
  const Box<double> bar(Eigen::Vector3d(0.5, 0.02, 0.02));
  const Shape<double> shape(bar);
  const RigidBody body = RigidBody::dynamic(massProperties(bar, 1000.0));
  const double radius = Eigen::Vector3d(0.5, 0.02, 0.02).norm();
  BodyState start;
  start.angularVelocity = Eigen::Vector3d(0, 0, 0.5);  // 0.5 rad/s about z: 0.005 rad in 10 ms
  const FreeFlight path = freeFlight(body, start, 0.0, 0.01, Eigen::Vector3d::Zero());
  const Bounds swept = sweptBounds(shape, radius, false, path, 0.0, 0.01, Eigen::Vector3d::Zero());
  // Along y the bar is 0.04 m thick and its end sweeps 0.5 * 0.005 = 2.5 mm: the box is a
  // few millimetres wide, where the sphere's is a metre.
  CHECK(swept.hi.y() - swept.lo.y() < 0.05);
  CHECK(swept.hi.x() - swept.lo.x() < 1.01);
  CHECK(swept.hi.z() - swept.lo.z() < 0.041);
}

TEST_CASE("a box at a pose is the same climbed from vertex 0 or from the hints of a nearby pose") {
  std::vector<Eigen::Vector3d> points;
  for (int k = 0; k < 60; ++k)  // a lumpy polytope: points on a squashed sphere
    points.emplace_back(0.3 * std::cos(0.7 * k) * std::sin(0.11 * k + 0.2), 0.1 * std::sin(0.7 * k) * std::sin(0.11 * k + 0.2),
                        0.2 * std::cos(0.11 * k + 0.2));
  const Shape<double> shape(Polytope<double>::hull(points));
  SweepHints hints{};
  for (int step = 0; step < 50; ++step) {
    const Pose<double> pose = Pose<double>::fromRotationTranslation(
        Eigen::AngleAxisd(0.05 * step, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix(),
        Eigen::Vector3d(0.01 * step, 0, 1));
    const Bounds cold = boundsAt(shape, pose), warm = boundsAt(shape, pose, &hints);
    CHECK(cold.lo == warm.lo);
    CHECK(cold.hi == warm.hi);
  }
}
