// Mass properties against closed forms found in any mechanics text: the box, the sphere,
// the capsule, and Mirtich's polyhedral algorithm on a cube, a tetrahedron, an offset
// polytope and a finely tessellated capsule and sphere.
#include <gjkx/dynamics/mass_properties.hpp>

#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <random>

using namespace gjkx;
using Catch::Matchers::Contains;

namespace {
constexpr double kPi = 3.14159265358979323846;

bool close(const Eigen::Matrix3d& a, const Eigen::Matrix3d& b, double rel) {
  return (a - b).norm() <= rel * std::max(1.0, b.norm());
}

// The convex hull of a box's 8 corners as a polytope.
Polytope<double> boxPolytope(const Eigen::Vector3d& h, const Eigen::Vector3d& offset = Eigen::Vector3d::Zero()) {
  std::vector<Eigen::Vector3d> corners;
  for (int i = 0; i < 8; ++i)
    corners.emplace_back(offset + Eigen::Vector3d((i & 1) ? h.x() : -h.x(), (i & 2) ? h.y() : -h.y(), (i & 4) ? h.z() : -h.z()));
  return Polytope<double>::hull(corners);
}
}  // namespace

// A box 2 x 4 x 6 of density 3: m = 3 * 48 = 144, J_xx = m (b^2 + c^2) / 12 over full sides.
TEST_CASE("mass properties of a box", "[dynamics][mass]") {
  const MassProperties m = massProperties(Box<double>(Eigen::Vector3d(1, 2, 3)), 3.0);
  CHECK(m.mass == Approx(144.0).epsilon(1e-14));
  CHECK(m.centerOfMass.norm() == 0);
  CHECK(m.inertia(0, 0) == Approx(144.0 * (16 + 36) / 12).epsilon(1e-14));
  CHECK(m.inertia(1, 1) == Approx(144.0 * (4 + 36) / 12).epsilon(1e-14));
  CHECK(m.inertia(2, 2) == Approx(144.0 * (4 + 16) / 12).epsilon(1e-14));
  CHECK(m.inertia(0, 1) == 0);
}

// A ball of radius 2, density 0.5: m = 0.5 * 4/3 pi 8, J = 2/5 m r^2.
TEST_CASE("mass properties of a sphere", "[dynamics][mass]") {
  const MassProperties m = massProperties(Sphere<double>(2.0), 0.5);
  const double mass = 0.5 * 4.0 / 3.0 * kPi * 8;
  CHECK(m.mass == Approx(mass).epsilon(1e-14));
  CHECK(close(m.inertia, 0.4 * mass * 4 * Eigen::Matrix3d::Identity(), 1e-14));
}

// Mirtich's algorithm on the cube and on a box hull: exact up to round-off.
TEST_CASE("mass properties of a cube and a box as polytopes (Mirtich)", "[dynamics][mass]") {
  const Eigen::Vector3d h(0.5, 1.5, 2.5);
  const MassProperties closed = massProperties(Box<double>(h), 2.0);
  const MassProperties poly = massProperties(boxPolytope(h), 2.0);
  CHECK(poly.mass == Approx(closed.mass).epsilon(1e-13));
  CHECK(poly.centerOfMass.norm() < 1e-13);
  CHECK(close(poly.inertia, closed.inertia, 1e-13));

  const MassProperties unit = massProperties(boxPolytope(Eigen::Vector3d(0.5, 0.5, 0.5)), 1.0);
  CHECK(unit.mass == Approx(1.0).epsilon(1e-14));
  CHECK(close(unit.inertia, Eigen::Matrix3d::Identity() / 6, 1e-13));
}

// The tetrahedron with corners 0, e_x, e_y, e_z: V = 1/6, centroid (1/4,1/4,1/4); about the
// origin \int x^2 dV = 1/60 and \int xy dV = 1/120 (the classic integrals over the simplex:
// \int x^a y^b z^c = a! b! c! / (a + b + c + 3)!). About the centroid:
// J_xx = rho (2/60 - V 2/16), J_xy = -rho (1/120 - V/16).
TEST_CASE("mass properties of a tetrahedron (Mirtich)", "[dynamics][mass]") {
  const std::vector<Eigen::Vector3d> pts = {Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitY(),
                                            Eigen::Vector3d::UnitZ()};
  const double rho = 7.0;
  const MassProperties m = massProperties(Polytope<double>::hull(pts), rho);
  const double V = 1.0 / 6;
  CHECK(m.mass == Approx(rho * V).epsilon(1e-14));
  CHECK((m.centerOfMass - Eigen::Vector3d::Constant(0.25)).norm() < 1e-15);
  const double Jxx = rho * (2.0 / 60 - V * 2.0 / 16);
  const double Jxy = -rho * (1.0 / 120 - V / 16);
  Eigen::Matrix3d expected;
  expected << Jxx, Jxy, Jxy, Jxy, Jxx, Jxy, Jxy, Jxy, Jxx;
  CHECK(close(m.inertia, expected, 1e-13));
}

// A polytope far from its body origin, and turned: the centre of mass is where the
// shape is, and the inertia about it is the rotated box's R J R^T, whatever the offset.
TEST_CASE("mass properties of an offset, rotated polytope", "[dynamics][mass]") {
  const Eigen::Vector3d h(1, 2, 0.5);
  const Eigen::Matrix3d R = Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, -2, 0.5).normalized()).toRotationMatrix();
  const Eigen::Vector3d offset(100, -50, 3000);
  std::vector<Eigen::Vector3d> corners;
  for (int i = 0; i < 8; ++i)
    corners.emplace_back(offset + R * Eigen::Vector3d((i & 1) ? h.x() : -h.x(), (i & 2) ? h.y() : -h.y(), (i & 4) ? h.z() : -h.z()));
  const MassProperties m = massProperties(Polytope<double>::hull(corners), 1.5);
  const MassProperties box = massProperties(Box<double>(h), 1.5);
  CHECK(m.mass == Approx(box.mass).epsilon(1e-12));
  CHECK((m.centerOfMass - offset).norm() < 1e-9);
  CHECK(close(m.inertia, R * box.inertia * R.transpose(), 1e-10));
}

// The capsule's closed form (a cylinder and two hemispheres) against Mirtich's algorithm
// on a fine tessellation of the same capsule, turned to an arbitrary axis: they agree
// to the tessellation's error (inscribed polytope: a little less mass).
TEST_CASE("mass properties of a capsule against a tessellated capsule", "[dynamics][mass]") {
  const double r = 0.6, half = 1.1;
  const Eigen::Vector3d axis = Eigen::Vector3d(1, 2, -1).normalized();
  const Eigen::Vector3d center(0.3, -0.2, 0.9);
  const Capsule<double> capsule(center - half * axis, center + half * axis, r);
  const MassProperties closed = massProperties(capsule, 2.0);
  CHECK(closed.mass == Approx(2.0 * (kPi * r * r * 2 * half + 4.0 / 3.0 * kPi * r * r * r)).epsilon(1e-14));
  CHECK((closed.centerOfMass - center).norm() < 1e-14);

  // Points on the two hemispherical caps, on a fine latitude-longitude grid.
  const Eigen::Vector3d u = axis.unitOrthogonal(), v = axis.cross(u);
  std::vector<Eigen::Vector3d> pts;
  const int rings = 60, segments = 120;
  for (int side : {-1, 1}) {
    for (int i = 0; i <= rings; ++i) {
      const double lat = kPi / 2 * i / rings;  // 0 at the equator, pi/2 at the pole
      for (int j = 0; j < segments; ++j) {
        const double lon = 2 * kPi * j / segments;
        pts.push_back(center + side * half * axis + r * (std::cos(lat) * (std::cos(lon) * u + std::sin(lon) * v) +
                                                         side * std::sin(lat) * axis));
        if (i == rings) break;
      }
    }
  }
  const MassProperties poly = massProperties(Polytope<double>::hull(pts), 2.0);
  CHECK(poly.mass == Approx(closed.mass).epsilon(2e-3));
  CHECK((poly.centerOfMass - center).norm() < 1e-9);
  CHECK(close(poly.inertia, closed.inertia, 4e-3));

  // A capsule with a zero-length axis is a sphere.
  const MassProperties ball = massProperties(Capsule<double>(center, center, r), 2.0);
  const MassProperties sphere = massProperties(Sphere<double>(r), 2.0);
  CHECK(ball.mass == Approx(sphere.mass).epsilon(1e-14));
  CHECK(close(ball.inertia, sphere.inertia, 1e-14));
}

TEST_CASE("mass properties of a cylinder: the closed form, and against a fine prism", "[dynamics][mass]") {
  const double r = 0.3, h = 0.8, density = 7.0;
  const MassProperties closed = massProperties(Cylinder<double>(r, h), density);
  // The formula of any mechanics text: m = rho pi r^2 L, J_zz = m r^2 / 2,
  // J_xx = J_yy = m (3 r^2 + L^2) / 12 with L = 2h.
  const double mass = density * kPi * r * r * 2 * h;
  CHECK(closed.mass == Approx(mass).epsilon(1e-14));
  CHECK(closed.centerOfMass.norm() == 0);
  const Eigen::Matrix3d formula =
      Eigen::Vector3d(mass * (3 * r * r + 4 * h * h) / 12, mass * (3 * r * r + 4 * h * h) / 12, mass * r * r / 2)
          .asDiagonal();
  CHECK(close(closed.inertia, formula, 1e-14));
  // Mirtich's algorithm on the prism over a regular 720-gon inscribed in the cross-section:
  // its area is (n/2) r^2 sin(2 pi / n), 1.3e-5 short of the disc's.
  std::vector<Eigen::Vector3d> prism;
  const int n = 720;
  for (int k = 0; k < n; ++k)
    for (const double z : {-h, h}) prism.emplace_back(r * std::cos(2 * kPi * k / n), r * std::sin(2 * kPi * k / n), z);
  const MassProperties poly = massProperties(Polytope<double>::hull(prism), density);
  CHECK(poly.mass == Approx(closed.mass).epsilon(1e-4));
  CHECK(poly.centerOfMass.norm() < 1e-12);
  CHECK(close(poly.inertia, closed.inertia, 1e-4));
  REQUIRE_THROWS_WITH(massProperties(Cylinder<double>(0.0, 1.0), 1.0), Contains("shape"));
  REQUIRE_THROWS_WITH(massProperties(Cylinder<double>(1.0, 0.0), 1.0), Contains("shape"));
}

TEST_CASE("mass properties reject bad input", "[dynamics][mass][input]") {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const Box<double> box(Eigen::Vector3d(1, 1, 1));
  REQUIRE_THROWS_WITH(massProperties(box, 0.0), Contains("density"));
  REQUIRE_THROWS_WITH(massProperties(box, -1.0), Contains("density"));
  REQUIRE_THROWS_WITH(massProperties(box, nan), Contains("density"));
  REQUIRE_THROWS_WITH(massProperties(box, INFINITY), Contains("density"));
  REQUIRE_THROWS_AS(massProperties(Point<double>(Eigen::Vector3d::Zero()), 1.0), std::invalid_argument);
  REQUIRE_THROWS_WITH(massProperties(Point<double>(Eigen::Vector3d::Zero()), 1.0), Contains("shape"));
  REQUIRE_THROWS_WITH(massProperties(Segment<double>(Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitX()), 1.0),
                      Contains("shape"));
  REQUIRE_THROWS_WITH(massProperties(Triangle<double>(Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitX(),
                                                      Eigen::Vector3d::UnitY()),
                                     1.0),
                      Contains("shape"));
  REQUIRE_THROWS_WITH(massProperties(Box<double>(Eigen::Vector3d(1, 0, 1)), 1.0), Contains("shape"));
  REQUIRE_THROWS_WITH(massProperties(Sphere<double>(0.0), 1.0), Contains("shape"));
  REQUIRE_THROWS_WITH(massProperties(Capsule<double>(Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitX(), 0.0), 1.0),
                      Contains("shape"));
  const std::vector<Eigen::Vector3d> square = {Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(1, 0, 0),
                                               Eigen::Vector3d(1, 1, 0), Eigen::Vector3d(0, 1, 0)};
  REQUIRE_THROWS_WITH(massProperties(Polytope<double>::polygon(square), 1.0), Contains("shape"));
  // A surface turned inside out encloses a negative volume.
  const std::vector<Eigen::Vector3d> tet = {Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitY(),
                                            Eigen::Vector3d::UnitZ()};
  const std::vector<std::array<int, 3>> inward = {{0, 1, 2}, {0, 3, 1}, {0, 2, 3}, {1, 3, 2}};
  REQUIRE_THROWS_WITH(polyhedronMassProperties(tet, inward, 1.0), Contains("mesh"));
}
