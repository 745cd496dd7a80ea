// Tests of Pose<S>: the rigid transform worldFromBody, x_w = R x_b + p (§3).
#include <gjkx/motion/pose.hpp>

#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

using gjkx::Pose;
using Vec = gjkx::Vector3<double>;
using Mat = gjkx::Matrix3<double>;
using Catch::Matchers::Contains;

namespace {
constexpr double kPi = 3.14159265358979323846;
constexpr double kTol = 1e-12;

bool near(const Vec& a, const Vec& b, double tol = kTol) { return (a - b).norm() <= tol; }
}  // namespace

// The identity pose maps every point to itself; a translation only adds p.
TEST_CASE("pose identity and translate", "[pose]") {
  const Pose<double> id = Pose<double>::identity();
  const Vec x(1.5, -2.0, 3.25);
  CHECK(id(x) == x);
  CHECK(id.rotation == Mat::Identity());
  CHECK(id.translation == Vec::Zero());

  const Pose<double> t = Pose<double>::translate(Vec(1, 2, 3));
  CHECK(t(x) == Vec(2.5, 0.0, 6.25));
  CHECK(t.rotation == Mat::Identity());
  // Directions do not translate: the body direction of s under a translation is s.
  CHECK(t.toBodyDirection(Vec(0, 0, 1)) == Vec(0, 0, 1));
}

// A quarter turn about +z takes +x to +y and +y to -x (right-hand rule); the
// translation is added after the rotation.
TEST_CASE("pose fromAxisAngle quarter turn about z", "[pose]") {
  const Pose<double> r = Pose<double>::fromAxisAngle(Vec(0, 0, 1), kPi / 2, Vec::Zero());
  CHECK(near(r(Vec(1, 0, 0)), Vec(0, 1, 0)));
  CHECK(near(r(Vec(0, 1, 0)), Vec(-1, 0, 0)));
  CHECK(near(r(Vec(0, 0, 1)), Vec(0, 0, 1)));

  // The axis need not be unit length.
  const Pose<double> r2 = Pose<double>::fromAxisAngle(Vec(0, 0, 5), kPi / 2, Vec(10, 0, 0));
  CHECK(near(r2(Vec(1, 0, 0)), Vec(10, 1, 0)));
  // toBodyDirection is R^T: the world direction +y is +x in the body.
  CHECK(near(r2.toBodyDirection(Vec(0, 1, 0)), Vec(1, 0, 0)));

  // A zero or non-finite axis is bad input.
  REQUIRE_THROWS_WITH(Pose<double>::fromAxisAngle(Vec::Zero(), 1.0, Vec::Zero()), Contains("pose.axis"));
  REQUIRE_THROWS_WITH(Pose<double>::fromAxisAngle(Vec(0, 0, 1), std::nan(""), Vec::Zero()),
                      Contains("pose.angle"));
}

// Composition (a * b)(x) = a(b(x)), and a * a.inverse() is the identity (both orders).
TEST_CASE("pose composition and inverse", "[pose]") {
  const Pose<double> a = Pose<double>::fromAxisAngle(Vec(1, 2, 3), 0.7, Vec(1, -2, 0.5));
  const Pose<double> b = Pose<double>::fromAxisAngle(Vec(-1, 0, 1), -1.3, Vec(0, 4, -3));
  const Vec x(0.3, -0.8, 2.0);
  CHECK(near((a * b)(x), a(b(x))));
  CHECK(near((b * a)(x), b(a(x))));

  // Hand case: translate by (1,0,0) after a quarter turn about z maps (1,0,0) to (1,1,0).
  const Pose<double> turn = Pose<double>::fromAxisAngle(Vec(0, 0, 1), kPi / 2, Vec::Zero());
  const Pose<double> shift = Pose<double>::translate(Vec(1, 0, 0));
  CHECK(near((shift * turn)(Vec(1, 0, 0)), Vec(1, 1, 0)));
  // The other order turns the shifted point: (2,0,0) -> (0,2,0).
  CHECK(near((turn * shift)(Vec(1, 0, 0)), Vec(0, 2, 0)));

  for (const Pose<double>& p : {a, b, turn, shift}) {
    const Pose<double> left = p * p.inverse();
    const Pose<double> right = p.inverse() * p;
    CHECK(left.rotation.isIdentity(kTol));
    CHECK(left.translation.norm() <= kTol);
    CHECK(right.rotation.isIdentity(kTol));
    CHECK(right.translation.norm() <= kTol);
    CHECK(near(p.inverse()(p(x)), x));
  }
  // The inverse of a composition is the composition of the inverses in reverse order.
  const Pose<double> ab = a * b;
  const Pose<double> abInv = b.inverse() * a.inverse();
  CHECK(ab.inverse().rotation.isApprox(abInv.rotation, kTol));
  CHECK(near(ab.inverse().translation, abInv.translation));
}

// validate() rejects a rotation that is not orthonormal (or a reflection) and a
// non-finite translation; the message names the field that was wrong.
TEST_CASE("pose validate rejects bad input", "[pose][input]") {
  Pose<double> p = Pose<double>::identity();
  REQUIRE_NOTHROW(p.validate("body"));

  Pose<double> scaled = p;
  scaled.rotation(0, 0) = 1.1;  // a stretch, not a rotation
  REQUIRE_THROWS_AS(scaled.validate("body"), std::invalid_argument);
  REQUIRE_THROWS_WITH(scaled.validate("body"), Contains("body.rotation") && Contains("orthonormal"));

  Pose<double> mirror = p;
  mirror.rotation(2, 2) = -1.0;  // orthonormal but a reflection (determinant -1)
  REQUIRE_THROWS_WITH(mirror.validate("body"), Contains("body.rotation"));

  Pose<double> nanRotation = p;
  nanRotation.rotation(1, 0) = std::numeric_limits<double>::quiet_NaN();
  REQUIRE_THROWS_WITH(nanRotation.validate("body"), Contains("body.rotation"));

  Pose<double> nanTranslation = p;
  nanTranslation.translation.y() = std::numeric_limits<double>::quiet_NaN();
  REQUIRE_THROWS_AS(nanTranslation.validate("body"), std::invalid_argument);
  REQUIRE_THROWS_WITH(nanTranslation.validate("body"), Contains("body.translation"));

  // fromRotationTranslation validates under the name "pose".
  Mat shear = Mat::Identity();
  shear(0, 1) = 0.5;
  REQUIRE_THROWS_WITH(Pose<double>::fromRotationTranslation(shear, Vec::Zero()), Contains("pose.rotation"));
  REQUIRE_THROWS_WITH(Pose<double>::fromRotationTranslation(Mat::Identity(), Vec(0, 0, INFINITY)),
                      Contains("pose.translation"));
}

// A float pose built from a double one passes validation, and maps points the same.
TEST_CASE("pose in float", "[pose]") {
  const Pose<double> d = Pose<double>::fromAxisAngle(Vec(1, 1, 0), 2.0, Vec(3, 2, 1));
  const Pose<float> f = d.cast<float>();
  REQUIRE_NOTHROW(f.validate("pose"));
  const gjkx::Vector3<float> x(1, 2, 3);
  CHECK((f(x).cast<double>() - d(x.cast<double>())).norm() <= 1e-5);
  const Pose<float> q = Pose<float>::fromAxisAngle(gjkx::Vector3<float>(0, 0, 1), float(kPi / 2),
                                                   gjkx::Vector3<float>::Zero());
  CHECK((q(gjkx::Vector3<float>(1, 0, 0)) - gjkx::Vector3<float>(0, 1, 0)).norm() <= 1e-6f);
}
