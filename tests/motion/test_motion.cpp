// Tests of Motion<S>: the pose of a moving body at time t (§3, §5), against values
// worked out by hand.
#include <gjkx/motion/motion.hpp>

#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

using gjkx::Motion;
using gjkx::Pose;
using Catch::Matchers::Contains;

namespace {
constexpr double kPi = 3.14159265358979323846;

template <typename S>
using Vec = gjkx::Vector3<S>;

// Tolerance for hand values: tight in double, looser in float.
template <typename S>
S tol() {
  return std::is_same_v<S, float> ? S(1e-5) : S(1e-12);
}

template <typename S>
bool near(const Vec<S>& a, const Vec<S>& b) {
  return (a - b).norm() <= tol<S>();
}

// The angle of the rotation R^T_a R_b between two rotations.
template <typename S>
S angleBetween(const gjkx::Matrix3<S>& a, const gjkx::Matrix3<S>& b) {
  return Eigen::AngleAxis<S>(gjkx::Matrix3<S>(a.transpose() * b)).angle();
}
}  // namespace

// A fixed body is the same pose at every time and reports itself static; the default
// Motion is the identity at rest.
TEMPLATE_TEST_CASE("motion fixed", "[motion]", float, double) {
  using S = TestType;
  const Pose<S> p = Pose<S>::fromAxisAngle(Vec<S>(0, 1, 0), S(0.5), Vec<S>(1, 2, 3));
  const Motion<S> m = Motion<S>::fixed(p);
  CHECK(m.isStatic());
  for (S t : {S(-3), S(0), S(1), S(100)}) {
    CHECK(m.pose(t).rotation == p.rotation);
    CHECK(m.pose(t).translation == p.translation);
  }
  const Motion<S> rest;
  CHECK(rest.isStatic());
  CHECK(rest.pose(S(7)).translation == Vec<S>::Zero());
  CHECK(rest.pose(S(7)).rotation.isIdentity());
}

// Constant velocity: p(t) = p0 + v (t - t0), rotation unchanged.
TEMPLATE_TEST_CASE("motion constant velocity", "[motion]", float, double) {
  using S = TestType;
  const Pose<S> start = Pose<S>::fromAxisAngle(Vec<S>(1, 0, 0), S(0.3), Vec<S>(1, 0, 0));
  const Motion<S> m = Motion<S>::constantVelocity(start, Vec<S>(2, -1, 0), S(1));
  CHECK_FALSE(m.isStatic());
  CHECK(near<S>(m.pose(S(1)).translation, Vec<S>(1, 0, 0)));       // at t0 the start pose
  CHECK(near<S>(m.pose(S(3)).translation, Vec<S>(5, -2, 0)));      // 2 time units later
  CHECK(near<S>(m.pose(S(0.5)).translation, Vec<S>(0, 0.5, 0)));   // before t0 too
  CHECK(m.pose(S(3)).rotation == start.rotation);                  // no rotation work
  // A body point moves with the origin: the body point (0,0,0) is at p(t).
  CHECK(near<S>(m.pose(S(2))(Vec<S>::Zero()), Vec<S>(3, -1, 0)));
}

// Constant acceleration: p0 + v t + a t^2 / 2 (t0 = 0). With p0 = (0,0,10),
// v = (1,0,2), a = (0,0,-10): at t = 2, (2, 0, 10 + 4 - 20) = (2, 0, -6).
TEMPLATE_TEST_CASE("motion constant acceleration", "[motion]", float, double) {
  using S = TestType;
  const Motion<S> m = Motion<S>::constantAcceleration(Pose<S>::translate(Vec<S>(0, 0, 10)), Vec<S>(1, 0, 2),
                                                      Vec<S>(0, 0, -10));
  CHECK_FALSE(m.isStatic());
  CHECK(near<S>(m.pose(S(0)).translation, Vec<S>(0, 0, 10)));
  CHECK(near<S>(m.pose(S(1)).translation, Vec<S>(1, 0, 7)));
  CHECK(near<S>(m.pose(S(2)).translation, Vec<S>(2, 0, -6)));
  CHECK(m.pose(S(2)).rotation.isIdentity());
  // With t0 = 1 the clock starts at 1: pose(3) is pose(2) of the motion above.
  const Motion<S> late = Motion<S>::constantAcceleration(Pose<S>::translate(Vec<S>(0, 0, 10)), Vec<S>(1, 0, 2),
                                                         Vec<S>(0, 0, -10), S(1));
  CHECK(near<S>(late.pose(S(3)).translation, Vec<S>(2, 0, -6)));
}

// Screw: angular velocity pi about z is a half turn per unit time, so at t = 0.5 the
// body has turned a quarter: body +x points along world +y. The origin moves with v.
TEMPLATE_TEST_CASE("motion screw", "[motion]", float, double) {
  using S = TestType;
  const Motion<S> m = Motion<S>::screw(Pose<S>::translate(Vec<S>(1, 0, 0)), Vec<S>(0, 0, 2),
                                       Vec<S>(0, 0, S(kPi)));
  CHECK_FALSE(m.isStatic());
  const Pose<S> half = m.pose(S(0.5));
  CHECK(near<S>(half.translation, Vec<S>(1, 0, 1)));
  CHECK(near<S>(half.rotation * Vec<S>(1, 0, 0), Vec<S>(0, 1, 0)));
  CHECK(near<S>(half(Vec<S>(1, 0, 0)), Vec<S>(1, 1, 1)));
  // At t = 1 a half turn: +x -> -x.
  CHECK(near<S>(m.pose(S(1)).rotation * Vec<S>(1, 0, 0), Vec<S>(-1, 0, 0)));
  // The rotation is applied on top of the start rotation: R(t) = exp([w] t) R0.
  const Pose<S> tilted = Pose<S>::fromAxisAngle(Vec<S>(1, 0, 0), S(kPi / 2), Vec<S>::Zero());  // y -> z
  const Motion<S> m2 = Motion<S>::screw(tilted, Vec<S>::Zero(), Vec<S>(0, 0, S(kPi)));
  // body +y -> world +z by R0; the turn about world z leaves +z alone.
  CHECK(near<S>(m2.pose(S(0.5)).rotation * Vec<S>(0, 1, 0), Vec<S>(0, 0, 1)));
  // body +x stays +x under R0, then a quarter turn about z -> +y.
  CHECK(near<S>(m2.pose(S(0.5)).rotation * Vec<S>(1, 0, 0), Vec<S>(0, 1, 0)));
  // Zero angular velocity is a pure translation.
  const Motion<S> slide = Motion<S>::screw(Pose<S>::identity(), Vec<S>(1, 0, 0), Vec<S>::Zero());
  CHECK(slide.pose(S(4)).rotation.isIdentity());
  CHECK(near<S>(slide.pose(S(4)).translation, Vec<S>(4, 0, 0)));
}

// Interpolation from the identity at t0 = 0 to a 90-degree turn about z at (2,4,0) at
// t1 = 1: the ends are the two poses, and at t = 0.5 the translation is halfway and the
// slerp angle is 45 degrees from each end. Outside [t0, t1] the ends are held.
TEMPLATE_TEST_CASE("motion interpolation", "[motion]", float, double) {
  using S = TestType;
  const Pose<S> from = Pose<S>::identity();
  const Pose<S> to = Pose<S>::fromAxisAngle(Vec<S>(0, 0, 1), S(kPi / 2), Vec<S>(2, 4, 0));
  const Motion<S> m = Motion<S>::interpolate(from, to, S(0), S(1));
  CHECK_FALSE(m.isStatic());

  CHECK(m.pose(S(0)).rotation.isApprox(from.rotation, tol<S>()));
  CHECK(near<S>(m.pose(S(0)).translation, from.translation));
  CHECK(m.pose(S(1)).rotation.isApprox(to.rotation, tol<S>()));
  CHECK(near<S>(m.pose(S(1)).translation, to.translation));

  const Pose<S> mid = m.pose(S(0.5));
  CHECK(near<S>(mid.translation, Vec<S>(1, 2, 0)));
  CHECK(std::abs(angleBetween<S>(from.rotation, mid.rotation) - S(kPi / 4)) <= tol<S>() * 10);
  CHECK(std::abs(angleBetween<S>(mid.rotation, to.rotation) - S(kPi / 4)) <= tol<S>() * 10);
  const S c = std::sqrt(S(0.5));
  CHECK(near<S>(mid.rotation * Vec<S>(1, 0, 0), Vec<S>(c, c, 0)));  // 45 degrees about z

  // Held at the ends outside the interval.
  CHECK(near<S>(m.pose(S(-1)).translation, from.translation));
  CHECK(near<S>(m.pose(S(5)).translation, to.translation));

  // Over [2, 4] the same motion is at its midpoint at t = 3.
  const Motion<S> shifted = Motion<S>::interpolate(from, to, S(2), S(4));
  CHECK(near<S>(shifted.pose(S(3)).translation, Vec<S>(1, 2, 0)));
}

// A rotation of more than a half turn between the ends goes the short way round:
// from identity to 270 degrees about z is -90 degrees, so halfway is -45 degrees.
TEST_CASE("motion interpolation takes the shortest arc", "[motion]") {
  const Pose<double> to = Pose<double>::fromAxisAngle(Vec<double>(0, 0, 1), 1.5 * kPi, Vec<double>::Zero());
  const Motion<double> m = Motion<double>::interpolate(Pose<double>::identity(), to);
  const double c = std::sqrt(0.5);
  CHECK(near<double>(m.pose(0.5).rotation * Vec<double>(1, 0, 0), Vec<double>(c, -c, 0)));
}

// Bad input enters through the named constructors, and the message names the field.
// retimed(c): the same motion on a clock that reads 0 at time c (the time-of-impact query's
// own clock). Every kind at every tau: the pose at c + tau; a motion that starts at c
// reads tau exactly (its own start time becomes 0), so in double the poses are equal.
TEMPLATE_TEST_CASE("motion retimed: the pose at tau is the pose at c + tau", "[motion][clock]", float, double) {
  using S = TestType;
  const Pose<S> start = Pose<S>::translate(Vec<S>(1, 2, 3));
  Pose<S> to = Pose<S>::translate(Vec<S>(-2, 0, 5));
  to.rotation = Eigen::AngleAxis<S>(S(0.7), Vec<S>(0, 0, 1)).toRotationMatrix();
  const S c = S(1000);
  const Motion<S> motions[] = {
      Motion<S>::fixed(start),
      Motion<S>::constantVelocity(start, Vec<S>(3, -1, 2), c),
      Motion<S>::constantAcceleration(start, Vec<S>(3, -1, 2), Vec<S>(0, 0, -9.81f), c),
      Motion<S>::screw(start, Vec<S>(3, -1, 2), Vec<S>(0, S(0.5), 1), c),
      Motion<S>::interpolate(start, to, c, c + 2),
      Motion<S>::freeFlight(start, Vec<S>(3, -1, 2), Vec<S>(0, 0, -9.81f), to.rotation, c, c + 2),
      Motion<S>::constantVelocity(start, Vec<S>(3, -1, 2), c - 1),  // starts before c: its own tau is tau + 1
  };
  for (const Motion<S>& m : motions) {
    const Motion<S> r = m.retimed(c);
    CHECK(r.isStatic() == m.isStatic());
    for (const S tau : {S(0), S(0.25), S(1), S(2)}) {
      const Pose<S> a = m.pose(c + tau), b = r.pose(tau);
      INFO("motion " << m.variant().index() << ", tau " << tau);
      CHECK(near(a.translation, b.translation));
      CHECK((a.rotation - b.rotation).norm() <= tol<S>());
    }
  }
}

TEST_CASE("motion rejects bad input", "[motion][input]") {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const Pose<double> id = Pose<double>::identity();
  REQUIRE_THROWS_AS(Motion<double>::constantVelocity(id, Vec<double>(nan, 0, 0)), std::invalid_argument);
  REQUIRE_THROWS_WITH(Motion<double>::constantVelocity(id, Vec<double>(nan, 0, 0)), Contains("motion.velocity"));
  REQUIRE_THROWS_WITH(Motion<double>::constantVelocity(id, Vec<double>(1, 0, 0), nan), Contains("motion.t0"));
  REQUIRE_THROWS_WITH(Motion<double>::constantAcceleration(id, Vec<double>::Zero(), Vec<double>(0, INFINITY, 0)),
                      Contains("motion.acceleration"));
  REQUIRE_THROWS_WITH(Motion<double>::screw(id, Vec<double>::Zero(), Vec<double>(0, 0, nan)),
                      Contains("motion.angularVelocity"));

  // Interpolation needs t1 > t0.
  REQUIRE_THROWS_AS(Motion<double>::interpolate(id, id, 1.0, 0.0), std::invalid_argument);
  REQUIRE_THROWS_WITH(Motion<double>::interpolate(id, id, 1.0, 0.0), Contains("motion.t1"));
  REQUIRE_THROWS_WITH(Motion<double>::interpolate(id, id, 1.0, 1.0), Contains("motion.t1"));
  REQUIRE_THROWS_WITH(Motion<double>::interpolate(id, id, nan, 1.0), Contains("motion.t0"));

  // A bad pose is named after its role in the motion.
  Pose<double> bad = id;
  bad.translation.x() = nan;
  REQUIRE_THROWS_WITH(Motion<double>::fixed(bad), Contains("motion.start.translation"));
  REQUIRE_THROWS_WITH(Motion<double>::interpolate(id, bad), Contains("motion.to.translation"));
  Pose<double> skew = id;
  skew.rotation(0, 1) = 0.2;
  REQUIRE_THROWS_WITH(Motion<double>::interpolate(skew, id), Contains("motion.from.rotation"));

  // requireInterval on its own.
  REQUIRE_NOTHROW(gjkx::requireInterval(0.0, 0.0, "sweep"));
  REQUIRE_THROWS_WITH(gjkx::requireInterval(2.0, 1.0, "sweep"), Contains("sweep.t1"));
}

// Free flight over [1, 3]: ballistic translation p0 + v tau + a tau^2 / 2 at any t, and a
// rotation from a quarter turn about z to a three-quarter turn about z: halfway it has
// turned a quarter turn more (constant rate), the ends are the two rotations exactly, and
// outside [t0, t1] the rotation is held while the translation stays ballistic.
TEMPLATE_TEST_CASE("motion free flight", "[motion]", float, double) {
  using S = TestType;
  const Pose<S> start = Pose<S>::fromAxisAngle(Vec<S>(0, 0, 1), S(kPi / 4), Vec<S>(1, 2, 3));
  const gjkx::Matrix3<S> end = Eigen::AngleAxis<S>(S(3 * kPi / 4), Vec<S>(0, 0, 1)).toRotationMatrix();
  const Vec<S> v(1, 0, 2), a(0, 0, -10);
  const Motion<S> m = Motion<S>::freeFlight(start, v, a, end, S(1), S(3));
  CHECK_FALSE(m.isStatic());

  CHECK(m.pose(S(1)).rotation == start.rotation);
  CHECK(m.pose(S(3)).rotation == end);
  for (S t : {S(0), S(1), S(1.5), S(3), S(4)}) {
    const S tau = t - S(1);
    CHECK(near<S>(m.pose(t).translation, Vec<S>(start.translation + v * tau + a * (tau * tau / 2))));
  }
  CHECK(std::abs(angleBetween<S>(start.rotation, m.pose(S(2)).rotation) - S(kPi / 4)) <= tol<S>() * 10);
  CHECK(std::abs(angleBetween<S>(start.rotation, m.pose(S(1.5)).rotation) - S(kPi / 8)) <= tol<S>() * 10);
  CHECK(near<S>(m.pose(S(2)).rotation * Vec<S>(1, 0, 0), Vec<S>(0, 1, 0)));  // 45 + 45 degrees about z
  CHECK(m.pose(S(0)).rotation == start.rotation);
  CHECK(m.pose(S(10)).rotation == end);

  // The bound is the path's own: |a|, the angle over the interval, no angular acceleration.
  const gjkx::MotionBound<S> b = m.bound();
  CHECK(std::abs(b.linearAcceleration - S(10)) <= tol<S>() * 10);
  CHECK(std::abs(b.angularSpeed - S(kPi / 4)) <= tol<S>() * 10);
  CHECK(b.angularAcceleration == S(0));

  // Seen from a frame moved by an offset, only the translation changes.
  const Motion<S> moved = m.translated(Vec<S>(10, 0, 0));
  CHECK(near<S>(moved.pose(S(2)).translation, Vec<S>(m.pose(S(2)).translation + Vec<S>(10, 0, 0))));
  CHECK(moved.pose(S(2)).rotation == m.pose(S(2)).rotation);
}

// Equality of motions (what a cache of poses keys on, kdop's BodyKdops): the same kind with
// every parameter equal, and nothing else.
TEMPLATE_TEST_CASE("motion equality: same kind, same parameters", "[motion]", float, double) {
  using S = TestType;
  const Pose<S> start = Pose<S>::fromAxisAngle(Vec<S>(0, 0, 1), S(kPi / 4), Vec<S>(1, 2, 3));
  const gjkx::Matrix3<S> end = Eigen::AngleAxis<S>(S(3 * kPi / 4), Vec<S>(0, 0, 1)).toRotationMatrix();
  const Motion<S> flight = Motion<S>::freeFlight(start, Vec<S>(1, 0, 2), Vec<S>(0, 0, -10), end, S(1), S(3));
  CHECK(flight == Motion<S>::freeFlight(start, Vec<S>(1, 0, 2), Vec<S>(0, 0, -10), end, S(1), S(3)));
  CHECK(flight != Motion<S>::freeFlight(start, Vec<S>(1, 0, 2), Vec<S>(0, 0, -10), end, S(1), S(3.5)));
  CHECK(flight != Motion<S>::freeFlight(start, Vec<S>(1, 0, 2), Vec<S>(0, 0, -9), end, S(1), S(3)));
  CHECK(flight != flight.translated(Vec<S>(0, 0, 1e-3)));
  const Motion<S> screw = Motion<S>::screw(start, Vec<S>(1, 0, 0), Vec<S>(0, 0, 1));
  CHECK(screw == Motion<S>::screw(start, Vec<S>(1, 0, 0), Vec<S>(0, 0, 1)));
  CHECK(screw != Motion<S>::screw(start, Vec<S>(1, 0, 0), Vec<S>(0, 0, 2)));
  CHECK(Motion<S>::fixed(start) == Motion<S>::fixed(start));
  // Different kinds are different motions, even where their poses agree.
  CHECK(Motion<S>::fixed(start) != Motion<S>::constantVelocity(start, Vec<S>::Zero()));
  CHECK(start == Pose<S>(start));
  CHECK(start != Pose<S>::identity());
}

// The free flight's bound really bounds it: the angle turned between nearby samples never
// exceeds angularSpeed * dt, and the translation's second difference is |a|.
TEST_CASE("motion free flight turns at the rate its bound states", "[motion]") {
  const Pose<double> start = Pose<double>::fromAxisAngle(Vec<double>(1, 2, 3), 0.4, Vec<double>::Zero());
  const gjkx::Matrix3<double> end =
      Eigen::AngleAxis<double>(1.1, Vec<double>(-1, 0.5, 2).normalized()).toRotationMatrix() * start.rotation;
  const Motion<double> m = Motion<double>::freeFlight(start, Vec<double>(3, 0, 0), Vec<double>(0, -9.81, 0), end, 0.0, 0.5);
  const double w = m.bound().angularSpeed;
  CHECK(std::abs(w - 1.1 / 0.5) < 1e-12);
  const double dt = 0.5 / 100;
  for (int i = 0; i < 100; ++i) {
    const double turned = angleBetween<double>(m.pose(i * dt).rotation, m.pose((i + 1) * dt).rotation);
    CHECK(std::abs(turned - w * dt) < 1e-9);
  }
}

TEST_CASE("motion free flight rejects bad input", "[motion][input]") {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const Pose<double> id = Pose<double>::identity();
  const gjkx::Matrix3<double> I = gjkx::Matrix3<double>::Identity();
  const Vec<double> z = Vec<double>::Zero();
  REQUIRE_THROWS_WITH(Motion<double>::freeFlight(id, Vec<double>(nan, 0, 0), z, I, 0.0, 1.0), Contains("motion.velocity"));
  REQUIRE_THROWS_WITH(Motion<double>::freeFlight(id, z, Vec<double>(0, nan, 0), I, 0.0, 1.0),
                      Contains("motion.acceleration"));
  gjkx::Matrix3<double> skew = I;
  skew(0, 1) = 0.3;
  REQUIRE_THROWS_WITH(Motion<double>::freeFlight(id, z, z, skew, 0.0, 1.0), Contains("motion.endRotation"));
  REQUIRE_THROWS_WITH(Motion<double>::freeFlight(id, z, z, gjkx::Matrix3<double>(-I), 0.0, 1.0),
                      Contains("motion.endRotation"));
  REQUIRE_THROWS_WITH(Motion<double>::freeFlight(id, z, z, I, 1.0, 1.0), Contains("motion.t1"));
  REQUIRE_THROWS_WITH(Motion<double>::freeFlight(id, z, z, I, 1.0, 0.0), Contains("motion.t1"));
  Pose<double> bad = id;
  bad.translation.y() = nan;
  REQUIRE_THROWS_WITH(Motion<double>::freeFlight(bad, z, z, I, 0.0, 1.0), Contains("motion.start.translation"));
}

// The certified extrusion test trusts the bound: every body point's acceleration along a
// free flight, measured by second differences, stays within pointAcceleration(r).
TEST_CASE("motion free flight's bound covers every point's acceleration", "[motion]") {
  const Pose<double> start = Pose<double>::fromAxisAngle(Vec<double>(0, 1, 1), 0.2, Vec<double>(1, 1, 1));
  const gjkx::Matrix3<double> end =
      Eigen::AngleAxis<double>(2.5, Vec<double>(1, -1, 0.3).normalized()).toRotationMatrix() * start.rotation;
  const Motion<double> m = Motion<double>::freeFlight(start, Vec<double>(0, 2, 0), Vec<double>(0, 0, -9.81), end, 0.0, 0.25);
  const gjkx::MotionBound<double> b = m.bound();
  const Vec<double> bodyPoint(0.3, -0.4, 1.2);
  const double r = bodyPoint.norm(), h = 1e-4;
  double largest = 0;
  for (int i = 1; i < 100; ++i) {
    const double t = 0.25 * i / 100;
    const Vec<double> acc = (m.pose(t + h)(bodyPoint) - 2 * m.pose(t)(bodyPoint) + m.pose(t - h)(bodyPoint)) / (h * h);
    largest = std::max(largest, acc.norm());
  }
  CHECK(largest <= b.pointAcceleration(r) * (1 + 1e-4));
  CHECK(largest >= 0.5 * b.pointAcceleration(r));  // and the bound is not loose
}
