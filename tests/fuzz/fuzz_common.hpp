// Shared by the libFuzzer targets of tests/fuzz: decoding the fuzzer's bytes into shape
// pairs and motions, an independent brute-force reference in long double, and the
// checks every target makes.
//
// Decoding. Every value comes from the bytes through FuzzedDataProvider, so every input
// decodes to *something*: a precision byte, then for each body a shape kind (point,
// segment, triangle, box, sphere, capsule, polytope of 4-12 points), a size scale from
// 0 and 1e-7 up to 1e6, coordinates at that scale (with exact zeros, +-scale and
// repeats of the previous value mixed in, so degenerate and equal values are common),
// a pose, and for the moving targets a motion (fixed, constant velocity, constant
// acceleration, screw, interpolation) or a per-vertex linear DeformingSimplex. Inputs
// the library refuses (std::invalid_argument: a flat polytope, a zero rotation axis,
// an empty interval) end the run quietly: refusing bad input is a correct answer.
//
// The reference. Every shape here is a convex hull of a few points plus a ball of
// radius r (a sphere is one point and r, a capsule two points and r): a
// gjkx::reference::Cloud, whose signed distance (distance when apart, minus the
// penetration depth when overlapping) the reference library computes by brute force in
// long double (gjkx/reference/polytope_distance.hpp: every candidate direction of the
// supporting distance, every feature pair's closest points). Nothing of the library's GJK
// or simplex code is used; this file only turns the decoded bodies into clouds.
//
// Tolerances. A result is compared with the reference within
//     slack = 1000 * eps(S) * R   (+ 16 x GJK's relative tolerance times the distance)
// where R is the size of the coordinates involved (the largest |vertex| + radius of
// either body in the world): a float computation near 1e5 cannot resolve better than
// about eps * 1e5, and the check must not blame the library for that. A GJK result may
// also be off by the resolution of its final simplex (closestPointResolution: round-off
// amplified by a sliver), and rounded shapes by sqrt(eps) relative (kRelativeAllowance). Any violation
// prints what was expected and found and calls abort(), which libFuzzer reports as a
// crash with the input saved.
#pragma once

#include <gjkx/brent/time_of_impact.hpp>
#include <gjkx/extrusion/extrusion.hpp>
#include <gjkx/gjk/gjk.hpp>
#include <gjkx/motion/round_off.hpp>
#include <gjkx/reference/polytope_distance.hpp>
#include <gjkx/support_mapping/deforming_simplex.hpp>
#include <gjkx/support_mapping/placed.hpp>
#include <gjkx/support_mapping/shape.hpp>

#include <fuzzer/FuzzedDataProvider.h>

#include <algorithm>
#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <optional>
#include <string>
#include <stdexcept>
#include <variant>
#include <vector>

namespace gjkx::fuzz {

using Real = reference::Real;
using RVec = reference::Vec;
using reference::Cloud;
using reference::signedDistance;

/// How many round-offs of the coordinates a result may be off by (GJKX_FUZZ_SLACK overrides).
inline Real slackFactor() {
  static const Real factor = [] {
    const char* text = std::getenv("GJKX_FUZZ_SLACK");
    return text ? Real(std::atof(text)) : Real(checkSlackRoundOffs);
  }();
  return factor;
}

// ---------------------------------------------------------------------------------------
// Violations.

/// GJK's convergence test bounds the gap between its upper and lower bounds by
/// relativeTolerance * distance; on polytopes the checks allow 16 times that. On rounded
/// shapes (sphere, capsule) GJK converges slowly and a run ends earlier, when the distance
/// "no longer decreases" in round-off, with the gap still open: a capsule-capsule distance
/// 2.5e-9 off (relative, double; 1400 times the tolerance) was seen. For those the checks
/// allow sqrt(eps) relative.
constexpr Real kRelativeAllowance = checkRelativeAllowance;

/// False when GJKX_FUZZ_ACCURACY=0: the distance-accuracy checks (a GJK distance against
/// the reference) are then skipped and only crashes, sanitizer reports, NaN, hangs and
/// the soundness checks remain. The CTest campaigns run with them on; turning them off
/// lets a long campaign by hand hunt crashes and unsound answers alone.
inline bool checkAccuracy() {
  static const bool on = [] {
    const char* text = std::getenv("GJKX_FUZZ_ACCURACY");
    return !(text && text[0] == '0');
  }();
  return on;
}

/// What the current input decoded to, printed with a violation.
inline std::string& context() {
  static std::string text;
  return text;
}

[[noreturn]] inline void violation(const char* format, ...) {
  std::fprintf(stderr, "\n*** gjkx fuzz: input: %s", context().c_str());
  std::fprintf(stderr, "\n*** gjkx fuzz: VIOLATION: ");
  va_list args;
  va_start(args, format);
  std::vfprintf(stderr, format, args);
  va_end(args);
  std::fprintf(stderr, "\n");
  std::abort();
}

template <typename S>
void requireNotNan(S value, const char* field) {
  if (std::isnan(value)) violation("%s is NaN", field);
}
template <typename S>
void requireNotNan(const Vector3<S>& v, const char* field) {
  if (v.hasNaN()) violation("%s has a NaN component", field);
}

// ---------------------------------------------------------------------------------------
// Decoding.

/// Reads numbers at a chosen scale from the fuzzer's bytes.
class Decoder {
 public:
  explicit Decoder(const uint8_t* data, size_t size) : in_(data, size) {}

  bool empty() { return in_.remaining_bytes() == 0; }
  uint8_t byte() { return in_.ConsumeIntegral<uint8_t>(); }
  bool flag() { return in_.ConsumeBool(); }
  int pick(int n) { return in_.ConsumeIntegralInRange<int>(0, n - 1); }

  /// A size scale: zero, tiny, ordinary and huge.
  double scale() {
    static constexpr double scales[] = {0.0, 1e-7, 1e-4, 1e-2, 0.5, 1.0, 3.0, 10.0, 1e3, 1e5, 1e6};
    return scales[pick(int(sizeof(scales) / sizeof(scales[0])))];
  }
  /// A number in [-scale, scale]; zero, +-scale and the previous number come up often.
  double number(double scale) {
    const uint8_t mode = byte();
    double value;
    if (mode < 16) {
      value = 0;
    } else if (mode < 28) {
      value = scale;
    } else if (mode < 40) {
      value = -scale;
    } else if (mode < 56) {
      value = last_;
    } else {
      value = scale * double(in_.ConsumeIntegral<int16_t>()) / 32768.0;
    }
    last_ = value;
    return value;
  }
  /// A vector at the scale; sometimes exactly the previous vector.
  Eigen::Vector3d vector(double scale) {
    if (byte() < 24) return lastVector_;
    Eigen::Vector3d v(number(scale), number(scale), number(scale));
    lastVector_ = v;
    return v;
  }
  /// A non-negative size at the scale.
  double size(double scale) { return std::abs(number(scale)); }

 private:
  FuzzedDataProvider in_;
  double last_ = 0;
  Eigen::Vector3d lastVector_ = Eigen::Vector3d::Zero();
};

template <typename S>
Vector3<S> toS(const Eigen::Vector3d& v) {
  return v.cast<S>();
}

/// A shape of any kind, its size and coordinates from the bytes. Throws std::invalid_argument
/// when the library refuses it (a flat polytope).
template <typename S>
Shape<S> decodeShape(Decoder& in) {
  const int kind = in.pick(7);
  const double scale = in.scale();
  switch (kind) {
    case 0: return Point<S>(toS<S>(in.vector(scale)));
    case 1: {
      const auto a = in.vector(scale);
      return Segment<S>(toS<S>(a), toS<S>(in.vector(scale)));
    }
    case 2: {
      const auto a = in.vector(scale), b = in.vector(scale);
      return Triangle<S>(toS<S>(a), toS<S>(b), toS<S>(in.vector(scale)));
    }
    case 3: return Box<S>(Vector3<S>(S(in.size(scale)), S(in.size(scale)), S(in.size(scale))));
    case 4: return Sphere<S>(S(in.size(scale)));
    case 5: {
      const auto a = in.vector(scale), b = in.vector(scale);
      return Capsule<S>(toS<S>(a), toS<S>(b), S(in.size(scale)));
    }
    default: {
      const int n = 4 + in.pick(9);
      std::vector<Vector3<S>> points;
      for (int k = 0; k < n; ++k) points.push_back(toS<S>(in.vector(scale)));
      return Polytope<S>::hull(points);
    }
  }
}

/// A rotation: the identity, or an axis and an angle (a zero axis throws).
template <typename S>
Matrix3<S> decodeRotation(Decoder& in) {
  if (in.flag()) return Matrix3<S>::Identity();
  const auto axis = in.vector(1.0);
  const double angle = in.number(4.0);
  return Pose<S>::fromAxisAngle(toS<S>(axis), S(angle), Vector3<S>::Zero()).rotation;
}

/// A pose: a rotation and a translation at a scale of its own.
template <typename S>
Pose<S> decodePose(Decoder& in) {
  Pose<S> pose;
  pose.rotation = decodeRotation<S>(in);
  pose.translation = toS<S>(in.vector(in.scale()));
  pose.validate("fuzz.pose");
  return pose;
}

/// A time interval [t0, t1] (possibly empty).
template <typename S>
struct Interval {
  S t0, t1;
};
template <typename S>
Interval<S> decodeInterval(Decoder& in) {
  static constexpr double starts[] = {0.0, 1.0, -1.0, 1e3};
  static constexpr double durations[] = {1.0, 1e-3, 1e-6, 10.0, 0.0, 0.25};
  const S t0 = S(starts[in.pick(4)]);
  return {t0, S(t0 + S(durations[in.pick(6)]))};
}

/// A rigid motion of any kind, starting at the interval's start.
template <typename S>
Motion<S> decodeMotion(Decoder& in, const Interval<S>& interval) {
  const Pose<S> start = decodePose<S>(in);
  const S t0 = interval.t0;
  switch (in.pick(5)) {
    case 0: return Motion<S>::fixed(start);
    case 1: return Motion<S>::constantVelocity(start, toS<S>(in.vector(in.scale())), t0);
    case 2: {
      const auto v = in.vector(in.scale());
      return Motion<S>::constantAcceleration(start, toS<S>(v), toS<S>(in.vector(in.scale())), t0);
    }
    case 3: {
      const auto v = in.vector(in.scale());
      static constexpr double spins[] = {0.0, 1e-3, 0.1, 1.0, 3.14159, 30.0};
      return Motion<S>::screw(start, toS<S>(v), toS<S>(in.vector(spins[in.pick(6)])), t0);
    }
    default: {
      Pose<S> to;
      to.rotation = in.flag() ? start.rotation : decodeRotation<S>(in);
      to.translation = toS<S>(in.vector(in.scale()));
      return Motion<S>::interpolate(start, to, interval.t0, interval.t1);
    }
  }
}

/// A per-vertex linear simplex of 1-4 vertices over the interval.
template <typename S>
DeformingSimplex<S> decodeDeforming(Decoder& in, const Interval<S>& interval) {
  const int n = 1 + in.pick(4);
  const double scale = in.scale();
  const double moveScale = in.scale();
  std::vector<Vector3<S>> start, end;
  for (int k = 0; k < n; ++k) {
    const auto a = in.vector(scale);
    start.push_back(toS<S>(a));
    end.push_back(toS<S>(a + in.vector(moveScale)));
  }
  return DeformingSimplex<S>(start, end, interval.t0, interval.t1);
}

/// A moving body: a rigid shape on a motion, or a deforming simplex.
template <typename S>
using Body = std::variant<Moving<Shape<S>>, DeformingSimplex<S>>;

template <typename S>
Body<S> decodeBody(Decoder& in, const Interval<S>& interval) {
  if (in.byte() < 48) return decodeDeforming<S>(in, interval);
  const Shape<S> shape = decodeShape<S>(in);
  return moving(shape, decodeMotion<S>(in, interval));
}

/// What the moving-pair targets (extrusion, time of impact) decode first, in this order:
/// the interval, the bodies P and Q, the extrusion variant and a collision tolerance.
template <typename S>
struct MovingPair {
  Interval<S> interval;
  Body<S> P, Q;
  ExtrusionVariant variant;
  double tolerance;  ///< 0: the settings' default
  /// Sets the variant and the tolerance of an extrusion or time-of-impact query.
  template <typename Settings>
  void configure(Settings& settings) const {
    settings.variant = variant;
    if (tolerance > 0) settings.collisionTolerance = S(tolerance);
  }
};
template <typename S>
MovingPair<S> decodeMovingPair(Decoder& in) {
  const Interval<S> interval = decodeInterval<S>(in);
  Body<S> P = decodeBody<S>(in, interval);
  Body<S> Q = decodeBody<S>(in, interval);
  const ExtrusionVariant variant = in.flag() ? ExtrusionVariant::Certified : ExtrusionVariant::Paper;
  static constexpr double tolerances[] = {0, 1e-2, 1e-6, 1.0};
  const double tolerance = tolerances[in.pick(4)];
  return {interval, std::move(P), std::move(Q), variant, tolerance};
}

template <typename S>
S accelerationBound(const Body<S>& body) {
  return std::visit([](const auto& b) { return S(b.accelerationBound()); }, body);
}

// ---------------------------------------------------------------------------------------
// The reference: a body as points plus a radius, in long double.

/// A cloud as text, for the context of a violation.
inline std::string describe(const Cloud& c) {
  std::string text = "{";
  char buffer[160];
  for (const auto& p : c.points) {
    std::snprintf(buffer, sizeof buffer, "(%.17Lg, %.17Lg, %.17Lg) ", p.x(), p.y(), p.z());
    text += buffer;
  }
  std::snprintf(buffer, sizeof buffer, "r=%.17Lg}", c.radius);
  return text + buffer;
}

/// The body-frame points and radius of a shape.
template <typename S>
void corePoints(const Shape<S>& shape, std::vector<Vector3<S>>& points, S& radius) {
  radius = S(0);
  std::visit(
      [&](const auto& x) {
        using X = std::decay_t<decltype(x)>;
        if constexpr (std::is_same_v<X, Point<S>>) {
          points = {x.a};
        } else if constexpr (std::is_same_v<X, Segment<S>>) {
          points = {x.a, x.b};
        } else if constexpr (std::is_same_v<X, Triangle<S>>) {
          points = {x.a, x.b, x.c};
        } else if constexpr (std::is_same_v<X, Box<S>>) {
          points.clear();
          for (int k = 0; k < 8; ++k)
            points.push_back(Vector3<S>((k & 1) ? x.halfExtents.x() : -x.halfExtents.x(),
                                        (k & 2) ? x.halfExtents.y() : -x.halfExtents.y(),
                                        (k & 4) ? x.halfExtents.z() : -x.halfExtents.z()));
        } else if constexpr (std::is_same_v<X, Sphere<S>>) {
          points = {Vector3<S>::Zero()};
          radius = x.radius;
        } else if constexpr (std::is_same_v<X, Capsule<S>>) {
          points = {x.axis.a, x.axis.b};
          radius = x.radius;
        } else if constexpr (std::is_same_v<X, Cylinder<S>>) {
          throw std::logic_error("the fuzz targets make no cylinders (no hull of points swept by a ball)");
        } else {
          points = x.vertices();
        }
      },
      shape.variant());
}

/// A shape at a pose, as the library's Placed sees it (R and p exactly as stored in S).
template <typename S>
Cloud cloudOf(const Shape<S>& shape, const Pose<S>& pose) {
  std::vector<Vector3<S>> points;
  S radius;
  corePoints(shape, points, radius);
  const Eigen::Matrix<Real, 3, 3> R = pose.rotation.template cast<Real>();
  const RVec p = pose.translation.template cast<Real>();
  Cloud cloud;
  for (const auto& x : points) cloud.points.push_back(R * x.template cast<Real>() + p);
  cloud.radius = Real(radius);
  return cloud;
}

template <typename S>
Cloud cloudOf(const PointSet<S>& set) {
  Cloud cloud;
  for (int k = 0; k < set.count; ++k) cloud.points.push_back(set.points[k].template cast<Real>());
  return cloud;
}

/// A body at time t.
template <typename S>
Cloud cloudAt(const Body<S>& body, S t) {
  if (const auto* m = std::get_if<Moving<Shape<S>>>(&body)) return cloudOf(m->shape, m->motion.pose(t));
  return cloudOf(std::get<DeformingSimplex<S>>(body).at(t));
}

/// The round-off scale of a pair of clouds in precision S.
template <typename S>
Real slackFor(Real extent) {
  return slackFactor() * Real(machineEpsilon<S>()) * extent + Real(std::numeric_limits<S>::min()) * 1e6L;
}

// ---------------------------------------------------------------------------------------
// Checks shared by the targets.

/// How far the computed closest point z of GJK's final simplex can be from the true one:
/// the round-off of its vertices, eps * max |w_k|, amplified by how thin the simplex is
/// (for a triangle, its longest edge over its width). A sliver in V_Q - V_P (a segment
/// 3464 long piercing a box 2e-4 wide) makes GJK's distance uncertain by ~1e-5 in double;
/// see the sliver findings in findings/README.md.
template <typename S>
Real closestPointResolution(const Simplex<S>& x) {
  Real wMax = 0;
  for (int k = 0; k < x.size; ++k) wMax = std::max(wMax, Real(x.vertices[k].w.norm()));
  Real condition = 1;
  if (x.size == 3) {
    const RVec a = (x.vertices[1].w - x.vertices[0].w).template cast<Real>();
    const RVec b = (x.vertices[2].w - x.vertices[0].w).template cast<Real>();
    const Real longest = std::max({a.norm(), b.norm(), (b - a).norm()});
    const Real width = longest > 0 ? a.cross(b).norm() / longest : Real(0);
    condition = width > 0 ? longest / width : std::numeric_limits<Real>::infinity();
  }
  return Real(closestPointRoundOff<S>()) * wMax * condition;
}

/// How far a GJK distance may be from the reference distance `ref` (see kRelativeAllowance).
template <typename S>
Real distanceAllowance(Real ref, Real extent, bool rounded, S relativeTolerance) {
  const Real distance = std::max(Real(0), ref);
  if (rounded) return slackFor<S>(extent) + Real(roundedShapeAllowance<S>()) * distance;
  return slackFor<S>(extent) + kRelativeAllowance * Real(relativeTolerance) * distance;
}

/// The checks of one GJK result against the reference signed distance `ref` (scale R).
template <typename S>
void checkGjk(const GjkResult<S>& r, const GjkSettings<S>& settings, Real ref, Real extent, bool rounded,
              const char* what) {
  requireNotNan(r.distance, "gjk.distance");
  requireNotNan(r.lowerBound, "gjk.lowerBound");
  requireNotNan(r.separatingVector, "gjk.separatingVector");
  requireNotNan(r.z, "gjk.z");
  requireNotNan(r.witnessP, "gjk.witnessP");
  requireNotNan(r.witnessQ, "gjk.witnessQ");
  const Real slack = slackFor<S>(extent);
  const Real distance = Real(r.distance);
  // The resolution of the final simplex (a sliver amplifies round-off) bounds how well
  // any distance from it can be known.
  const Real resolution = 2 * closestPointResolution(r.simplex);
  const Real relative = distanceAllowance(ref, extent, rounded, settings.relativeTolerance) - slack + resolution;
  const Real refDistance = std::max(Real(0), ref);
  // The largest supporting distance seen is a lower bound, always.
  if (std::isfinite(r.lowerBound) && Real(r.lowerBound) > refDistance + slack)
    violation("%s: lowerBound %.9Lg above the reference distance %.9Lg (slack %.3Lg)", what, Real(r.lowerBound), ref,
              slack);
  switch (r.status) {
    case GjkStatus::Separated:
      if (!checkAccuracy()) break;
      if (std::abs(distance - refDistance) > slack + relative)
        violation("%s: Separated at distance %.12Lg, reference %.12Lg (slack %.3Lg)", what, distance, ref,
                  slack + relative);
      if (std::abs(Real((r.witnessQ - r.witnessP).norm()) - distance) > slack + relative)
        violation("%s: |witnessQ - witnessP| = %.12Lg but distance %.12Lg", what, Real((r.witnessQ - r.witnessP).norm()),
                  distance);
      break;
    case GjkStatus::Overlapping: {
      // Touching within the resolution of the final simplex counts.
      if (ref > slack + resolution)
        violation("%s: Overlapping, but the reference distance is %.12Lg (slack %.3Lg, simplex resolution %.3Lg)", what,
                  ref, slack, resolution);
      break;
    }
    case GjkStatus::SeparatingVector:
      if (!(r.lowerBound > settings.separationThreshold))
        violation("%s: SeparatingVector with lowerBound %.9g not above the threshold %.9g", what, double(r.lowerBound),
                  double(settings.separationThreshold));
      if (ref < Real(settings.separationThreshold) - slack)
        violation("%s: SeparatingVector above %.9g, but the reference distance is %.12Lg", what,
                  double(settings.separationThreshold), ref);
      break;
    case GjkStatus::IterationCap:
    case GjkStatus::Stalled:
      // Undecided is allowed, said as such; the distance is still an upper bound. A stall
      // says its gap between the bounds is open.
      if (checkAccuracy() && distance < refDistance - slack - relative)
        violation("%s: %s distance %.12Lg below the reference %.12Lg", what, toString(r.status), distance, ref);
      if (r.status == GjkStatus::Stalled && !(r.lowerBound < r.distance))
        violation("%s: Stalled with its bounds closed (lowerBound %.12Lg, distance %.12Lg)", what,
                  Real(r.lowerBound), distance);
      break;
    case GjkStatus::NumericalFailure:
      violation("%s: NumericalFailure on finite input (extent %.3Lg)", what, extent);
    case GjkStatus::StoppedByVisitor: violation("%s: StoppedByVisitor without a visitor", what);
  }
}

/// A point cloud plus a ball in double: the support mapping GJK samples an interval with.
struct CloudShape {
  using Scalar = double;
  std::vector<Vector3<double>> points;
  double radius = 0;
  Vector3<double> support(const Vector3<double>& s) const {
    std::size_t best = 0;
    for (std::size_t k = 1; k < points.size(); ++k)
      if (s.dot(points[k]) > s.dot(points[best])) best = k;
    const double n = s.norm();
    return n > 0 ? Vector3<double>(points[best] + s * (radius / n)) : points[best];
  }
  Vector3<double> center() const {
    Vector3<double> c = Vector3<double>::Zero();
    for (const auto& p : points) c += p;
    return c / double(points.size());
  }
};

/// The body at time t in double (the library's own pose or vertices at t in S, cast).
template <typename S>
CloudShape cloudShapeAt(const Body<S>& body, S t) {
  CloudShape c;
  if (const auto* m = std::get_if<Moving<Shape<S>>>(&body)) {
    std::vector<Vector3<S>> points;
    S radius;
    corePoints(m->shape, points, radius);
    const Pose<S> pose = m->motion.pose(t);
    const Matrix3<double> R = pose.rotation.template cast<double>();
    const Vector3<double> p = pose.translation.template cast<double>();
    for (const auto& x : points) c.points.push_back(R * x.template cast<double>() + p);
    c.radius = double(radius);
  } else {
    const PointSet<S> set = std::get<DeformingSimplex<S>>(body).at(t);
    for (int k = 0; k < set.count; ++k) c.points.push_back(set.points[k].template cast<double>());
  }
  return c;
}

/// Sample k of n evenly spaced times of [t0, t1] (both ends included).
template <typename S>
S sampleTime(S t0, S t1, int k, int n) {
  return n == 1 ? t0 : (k == n - 1 ? t1 : S(t0 + (t1 - t0) * S(k) / S(n - 1)));
}

/// The largest |coordinate| of either body at `samples` evenly spaced times of [t0, t1].
template <typename S>
Real extentOver(const Body<S>& P, const Body<S>& Q, S t0, S t1, int samples) {
  Real extent = 0;
  for (int k = 0; k < samples; ++k) {
    const S t = sampleTime(t0, t1, k, samples);
    extent = std::max({extent, cloudAt(P, t).extent(), cloudAt(Q, t).extent()});
  }
  return extent;
}

/// The signed distance at time t: GJK in double, confirmed by the brute force when it is
/// below `confirmBelow` (or GJK did not converge).
template <typename S>
Real signedDistanceAt(const Body<S>& P, const Body<S>& Q, S t, Real confirmBelow) {
  const auto r = gjk(cloudShapeAt(P, t), cloudShapeAt(Q, t));
  if (r.status == GjkStatus::Separated && Real(r.distance) >= confirmBelow) return Real(r.distance);
  return signedDistance(cloudAt(P, t), cloudAt(Q, t));
}

/// One fuzz input: the first flag byte picks float or double, then the target's checks
/// run. A std::invalid_argument is the library refusing decoded input (a flat polytope,
/// a zero axis, an empty interpolation): a correct answer, not a finding.
template <typename RunFloat, typename RunDouble>
int runOneInput(const uint8_t* data, size_t size, RunFloat runFloat, RunDouble runDouble) {
  Decoder in(data, size);
  try {
    if (in.flag())
      runFloat(in);
    else
      runDouble(in);
  } catch (const std::invalid_argument&) {
  }
  return 0;
}

}  // namespace gjkx::fuzz
