// Shared by the time-of-impact tests (test_time_of_impact.cpp, the hand-checked and hard
// cases; test_time_of_impact_random.cpp, the random workloads): small builders, random
// bodies described in double, and the reference the random workloads are held to.
//
// The reference (below) is a branch-and-bound over time in double. It measures the
// static distance with GJK on the shapes' polytope cores (a sphere is a point and a capsule
// a segment, inflated by their radii; GJK is exact to round-off on polytopes, where on a
// curved shape near contact it is not: see checkHit), at 256 even samples, then
// subdivides, bounding the distance from below on each subinterval [a, b] in two
// independent ways:
//  - Lipschitz: every body point moves at most V = |v_P| + |w_P| r_P + |v_Q| + |w_Q| r_Q, so
//    d >= (d(a) + d(b) - V (b - a)) / 2 on [a, b];
//  - second order: for any fixed unit s, SD(s, t) >= min(SD(s, a), SD(s, b)) - (b-a)^2/8 D,
//    D = w_P^2 r_P + w_Q^2 r_Q (D = 0 for linear motion, where SD(s, t) is linear), and
//    d >= SD(s, t); s is tried along the closest directions found at a and at b.
// (D and V are computed here from the motions, not taken from the library.) Subdividing
// where the bound is lowest, it ends with one of three verdicts:
//  - Contact: a sample with distance <= tol/2 was found: the bodies do come within half the
//    tolerance (or penetrate); the solver must report a collision;
//  - Clear: the distance is proven above `hi` = 2 tol + 2 V timeTol everywhere (the solver
//    resolves time to timeTol, in which the bodies move V timeTol); the solver must not
//    report a hit;
//  - Grazing: the minimum distance is pinned within tol/16 and lies between the two:
//    either answer is fine (these are counted separately, never as misses).
// A grazing verdict therefore needs a true minimum above tol/2 - tol/16: nothing that
// comes within 7/16 of the tolerance can hide in the band. (Should an interval shrink to
// 1e-14 before the bound is pinned, it is called grazing too; the printed counts show how
// many pairs fell in the band.)
#pragma once

#include <gjkx/brent/time_of_impact.hpp>
#include <gjkx/support_mapping/placed.hpp>
#include <gjkx/support_mapping/shape.hpp>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <limits>
#include <queue>
#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace gjkx::toi_test {

using namespace gjkx;

inline constexpr double kPi = 3.14159265358979323846;

template <typename S>
const char* scalarName() {
  return sizeof(S) == sizeof(float) ? "float" : "double";
}

template <typename Shape>
Moving<Shape> spinning(const Shape& shape, const Vector3<typename Shape::Scalar>& position,
                       const Vector3<typename Shape::Scalar>& angularVelocity) {
  using S = typename Shape::Scalar;
  return moving(shape, Motion<S>::screw(Pose<S>::translate(position), Vector3<S>::Zero(), angularVelocity));
}

template <typename S>
Box<S> unitBox() {
  return Box<S>(Vector3<S>(S(0.5), S(0.5), S(0.5)));
}

// The message of the std::invalid_argument thrown by `call`, or "" if none.
template <typename F>
std::string invalidArgumentMessage(F&& call) {
  try {
    call();
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

// ---------------------------------------------------------------------------------------
// Random bodies, described in double and built in either scalar type.

struct BodySpec {
  int kind = 0;  // 0 box, 1 sphere, 2 capsule, 3 polytope
  Eigen::Vector3d halfExtents = Eigen::Vector3d::Ones();
  double radius = 1;
  Eigen::Vector3d a = Eigen::Vector3d::Zero(), b = Eigen::Vector3d::Zero();
  std::vector<Eigen::Vector3d> points;
  Pose<double> start;
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();
  Eigen::Vector3d angularVelocity = Eigen::Vector3d::Zero();
  double boundingRadius = 0;  // about the body origin (the centre of rotation), computed here
};

inline const char* kindName(int kind) {
  static const char* names[] = {"box", "sphere", "capsule", "polytope"};
  return names[kind];
}

template <typename S>
Shape<S> makeShape(const BodySpec& spec) {
  switch (spec.kind) {
    case 0: return Box<S>(spec.halfExtents.cast<S>());
    case 1: return Sphere<S>(S(spec.radius));
    case 2: return Capsule<S>(spec.a.cast<S>(), spec.b.cast<S>(), S(spec.radius));
    default: {
      std::vector<Vector3<S>> points;
      for (const auto& p : spec.points) points.push_back(p.cast<S>());
      return Polytope<S>::hull(points);
    }
  }
}

template <typename S>
Moving<Shape<S>> makeBody(const BodySpec& spec) {
  const Pose<S> start = spec.start.cast<S>();
  if (spec.angularVelocity.squaredNorm() > 0)
    return moving(makeShape<S>(spec),
                  Motion<S>::screw(start, spec.velocity.cast<S>(), spec.angularVelocity.cast<S>()));
  return moving(makeShape<S>(spec), Motion<S>::constantVelocity(start, spec.velocity.cast<S>()));
}

inline Eigen::Vector3d randomUnit(std::mt19937& rng) {
  std::normal_distribution<double> g(0, 1);
  Eigen::Vector3d v(g(rng), g(rng), g(rng));
  while (v.norm() < 1e-6) v = Eigen::Vector3d(g(rng), g(rng), g(rng));
  return v.normalized();
}

inline BodySpec randomShape(std::mt19937& rng) {
  std::uniform_real_distribution<double> u(0, 1);
  BodySpec spec;
  spec.kind = std::uniform_int_distribution<int>(0, 3)(rng);
  const double size = 0.3 + 0.9 * u(rng);
  switch (spec.kind) {
    case 0:
      spec.halfExtents = size * Eigen::Vector3d(0.05 + 0.95 * u(rng), 0.05 + 0.95 * u(rng), 0.05 + 0.95 * u(rng));
      spec.boundingRadius = spec.halfExtents.norm();
      break;
    case 1:
      spec.radius = size * (0.1 + 0.9 * u(rng));
      spec.boundingRadius = spec.radius;
      break;
    case 2: {
      spec.a = randomUnit(rng) * size * (0.1 + 0.9 * u(rng));
      spec.b = -spec.a;
      spec.radius = size * (0.05 + 0.45 * u(rng));
      spec.boundingRadius = spec.a.norm() + spec.radius;
      break;
    }
    default: {
      const int n = std::uniform_int_distribution<int>(4, 30)(rng);
      spec.boundingRadius = 0;
      for (int k = 0; k < n; ++k) {
        spec.points.push_back(randomUnit(rng) * size * std::cbrt(0.2 + 0.8 * u(rng)));
        spec.boundingRadius = std::max(spec.boundingRadius, spec.points.back().norm());
      }
      break;
    }
  }
  spec.start = Pose<double>::fromAxisAngle(randomUnit(rng), kPi * u(rng), Eigen::Vector3d::Zero());
  return spec;
}

// A pair aimed at a meeting: both bodies pass near a common point M at about the same
// time t_m (in [-0.2, 1.2]), each offset from M by up to 2 units, at speeds 0.5 to 6.
// About half of them collide. With `maxTurn` > 0 each body also turns at a random
// angular velocity of up to `maxTurn` radians per unit time about its origin.
struct PairSpec {
  BodySpec P, Q;
};

inline PairSpec randomPair(std::mt19937& rng, double maxTurn) {
  std::uniform_real_distribution<double> u(0, 1);
  PairSpec pair{randomShape(rng), randomShape(rng)};
  const Eigen::Vector3d meeting = randomUnit(rng) * u(rng);
  const double tm = -0.2 + 1.4 * u(rng);
  for (BodySpec* body : {&pair.P, &pair.Q}) {
    body->velocity = randomUnit(rng) * (0.5 + 5.5 * u(rng));
    body->start.translation = meeting + randomUnit(rng) * 2 * u(rng) * u(rng) - body->velocity * tm;
    if (maxTurn > 0) body->angularVelocity = randomUnit(rng) * maxTurn * u(rng);
  }
  return pair;
}

// A pair of neighbours turning fast and moving slowly, where rotation decides: elongated
// shapes (boxes and capsules stretched 1.5 to 3 times along one axis, or any shape) with
// their centres 0.6 to 1.1 times the sum of their bounding radii apart, moving at up to
// 0.5 per unit time, each turning at up to `maxTurn` radians per unit time.
inline PairSpec spinningPair(std::mt19937& rng, double maxTurn) {
  std::uniform_real_distribution<double> u(0, 1);
  PairSpec pair{randomShape(rng), randomShape(rng)};
  for (BodySpec* body : {&pair.P, &pair.Q}) {
    const double stretch = 1.5 + 1.5 * u(rng);
    if (body->kind == 0) {
      body->halfExtents.x() *= stretch;
      body->boundingRadius = body->halfExtents.norm();
    } else if (body->kind == 2) {
      body->a *= stretch;
      body->b *= stretch;
      body->boundingRadius = body->a.norm() + body->radius;
    }
    body->velocity = randomUnit(rng) * 0.5 * u(rng);
    body->angularVelocity = randomUnit(rng) * maxTurn * u(rng);
  }
  pair.P.start.translation = Eigen::Vector3d::Zero();
  pair.Q.start.translation =
      randomUnit(rng) * (pair.P.boundingRadius + pair.Q.boundingRadius) * (0.6 + 0.5 * u(rng));
  return pair;
}

// ---------------------------------------------------------------------------------------
// The reference (see the file comment), in double.

// The reference sees a sphere as a point and a capsule as a segment, inflated by their
// radii: the distance of the shapes is max(0, distance of the cores - r_P - r_Q), and their
// supporting distance is the cores' minus r_P + r_Q. The cores are polytopes (point,
// segment, box, hull), on which GJK's distance is exact to round-off even at the
// tolerance's scale; GJK run directly on a sphere or capsule near contact stalls with a
// distance up to 1e-7 too large in double (see the report of these tests).
struct Body {
  Moving<Shape<double>> core;
  double radius = 0;
};

inline Body referenceBody(const BodySpec& spec) {
  Body body{makeBody<double>(spec), 0.0};
  if (spec.kind == 1 || spec.kind == 2) {
    const Shape<double> core = spec.kind == 1 ? Shape<double>(Point<double>(Eigen::Vector3d::Zero()))
                                              : Shape<double>(Segment<double>(spec.a, spec.b));
    body.core = moving(core, body.core.motion);
    body.radius = spec.radius;
  }
  return body;
}

// SD(P(t), Q(t), s) of the inflated shapes, for a unit s.
inline double referenceSd(const Body& P, const Body& Q, const Eigen::Vector3d& s, double t) {
  return supportingDistance(P.core.at(t), Q.core.at(t), s) - P.radius - Q.radius;
}

struct Sample {
  double t = 0;
  double upper = 0;  // an upper bound of the distance (0 when overlapping): GJK's, exact to round-off
  double lower = 0;  // a lower bound: max(0, SD along the closest direction)
  Eigen::Vector3d closest = Eigen::Vector3d::UnitX();  // unit direction from P to Q at t
};

inline Sample sampleAt(const Body& P, const Body& Q, double t) {
  const auto r = gjk(P.core.at(t), Q.core.at(t));
  REQUIRE(r.status != GjkStatus::NumericalFailure);
  const double radii = P.radius + Q.radius;
  Sample s;
  s.t = t;
  s.upper = r.status == GjkStatus::Overlapping ? 0.0 : std::max(0.0, r.distance - radii);
  if (r.z.norm() > 0) {
    s.closest = r.z.normalized();
  } else if (r.separatingVector.norm() > 0) {
    s.closest = r.separatingVector;
  }
  s.lower = std::max({0.0, r.lowerBound - radii, referenceSd(P, Q, s.closest, t)});
  return s;
}

enum class Verdict { Contact, Clear, Grazing };

inline const char* toString(Verdict v) {
  return v == Verdict::Contact ? "contact" : v == Verdict::Clear ? "clear" : "grazing";
}

struct Reference {
  Verdict verdict = Verdict::Clear;
  double minUpper = std::numeric_limits<double>::infinity();  // smallest distance sampled
  double minLower = 0;                                        // proven lower bound of the minimum
  double tMin = 0;                                            // where minUpper was sampled
  Eigen::Vector3d closestAtMin = Eigen::Vector3d::UnitX();
  int samples = 0;
};

struct Bounds {
  double V = 0;  // bound of the relative speed of body points
  double D = 0;  // bound of the acceleration of body points (P's plus Q's)
};

inline Bounds boundsOf(const PairSpec& pair) {
  Bounds b;
  for (const BodySpec* body : {&pair.P, &pair.Q}) {
    const double w = body->angularVelocity.norm();
    b.V += body->velocity.norm() + w * body->boundingRadius;
    b.D += w * w * body->boundingRadius;
  }
  return b;
}

// Branch and bound over [t0, t1] (see the file comment).
inline Reference classify(const Body& P, const Body& Q, double t0, double t1, const Bounds& bounds, double lo, double hi,
                   double gap) {
  struct Interval {
    Sample a, b;
    double bound;
    bool operator<(const Interval& other) const { return bound > other.bound; }  // min-heap
  };
  Reference ref;
  auto lowerBoundOn = [&](const Sample& a, const Sample& b) {
    const double h = b.t - a.t;
    double best = 0.5 * (a.lower + b.lower - bounds.V * h);
    for (const Eigen::Vector3d& s : {a.closest, b.closest}) {
      const double sa = referenceSd(P, Q, s, a.t);
      const double sb = referenceSd(P, Q, s, b.t);
      best = std::max(best, std::min(sa, sb) - h * h / 8 * bounds.D);
    }
    return best;
  };
  auto note = [&](const Sample& s) {
    ++ref.samples;
    if (s.upper < ref.minUpper) {
      ref.minUpper = s.upper;
      ref.tMin = s.t;
      ref.closestAtMin = s.closest;
    }
  };
  std::priority_queue<Interval> heap;
  const int n = 256;
  Sample previous = sampleAt(P, Q, t0);
  note(previous);
  for (int k = 1; k <= n; ++k) {
    const Sample next = sampleAt(P, Q, t0 + (t1 - t0) * k / n);
    note(next);
    heap.push({previous, next, lowerBoundOn(previous, next)});
    previous = next;
  }
  for (;;) {
    if (ref.minUpper <= lo) {
      ref.verdict = Verdict::Contact;
      ref.minLower = 0;
      return ref;
    }
    const Interval top = heap.top();
    ref.minLower = std::min(top.bound, ref.minUpper);
    if (top.bound > hi) {
      ref.verdict = Verdict::Clear;
      return ref;
    }
    if (top.bound >= ref.minUpper - gap || top.b.t - top.a.t < 1e-14) {
      ref.verdict = Verdict::Grazing;
      return ref;
    }
    REQUIRE(ref.samples < 400000);  // the reference itself must end
    heap.pop();
    const Sample mid = sampleAt(P, Q, 0.5 * (top.a.t + top.b.t));
    note(mid);
    heap.push({top.a, mid, lowerBoundOn(top.a, mid)});
    heap.push({mid, top.b, lowerBoundOn(mid, top.b)});
  }
}

// For linear motion the distance is convex in t (the relative motion is a translation),
// so {t : d(t) <= thr} is an interval: its start, by bisection from t0 to a time inside.
inline double firstTimeWithin(const Body& P, const Body& Q, double t0, double inside, double thr) {
  if (sampleAt(P, Q, t0).upper <= thr) return t0;
  double a = t0, b = inside;
  for (int k = 0; k < 80 && b - a > 1e-15; ++k) {
    const double m = 0.5 * (a + b);
    (sampleAt(P, Q, m).upper <= thr ? b : a) = m;
  }
  return b;
}

// The closest approach of a linear motion over [0, 1] by golden-section search (the
// distance is convex in t): used only to build the grazing pairs.
inline Sample closestApproach(const Body& P, const Body& Q) {
  const double g = (std::sqrt(5.0) - 1) / 2;
  double a = 0, b = 1;
  double x1 = b - g * (b - a), x2 = a + g * (b - a);
  double f1 = sampleAt(P, Q, x1).upper, f2 = sampleAt(P, Q, x2).upper;
  for (int k = 0; k < 80; ++k) {
    if (f1 <= f2) {
      b = x2;
      x2 = x1;
      f2 = f1;
      x1 = b - g * (b - a);
      f1 = sampleAt(P, Q, x1).upper;
    } else {
      a = x1;
      x1 = x2;
      f1 = f2;
      x2 = a + g * (b - a);
      f2 = sampleAt(P, Q, x2).upper;
    }
  }
  return sampleAt(P, Q, 0.5 * (a + b));
}

// ---------------------------------------------------------------------------------------
// Statistics of a workload.

struct Stats {
  std::string workload;
  int queries = 0;
  long brentTotal = 0;
  int brentMax = 0;
  long gjkTotal = 0;
  int photoFinishes = 0, hits = 0, noCollisions = 0, caps = 0, afterBrent = 0, other = 0;
  int contact = 0, clear = 0, grazing = 0;
  int misses = 0, falseAlarms = 0;

  template <typename S>
  void add(const ToiResult<S>& r) {
    ++queries;
    brentTotal += r.brentIterations;
    brentMax = std::max(brentMax, r.brentIterations);
    gjkTotal += r.gjkRuns;
    const bool brent = r.brentIterations > 0 || r.restarts > 0;
    afterBrent += brent;
    switch (r.status) {
      case ToiStatus::PhotoFinish: ++photoFinishes; break;
      case ToiStatus::Hit: ++hits; break;
      case ToiStatus::NoCollision: ++noCollisions; break;
      case ToiStatus::IterationCap: ++caps; break;
      default: ++other; break;
    }
  }
  void print() const {
    // photo finishes / (queries the first extrusion test left to Brent: photo finishes,
    // hits and caps decided after Brent iterations)
    const double rate = afterBrent > 0 ? double(photoFinishes) / afterBrent : 0.0;
    std::ostringstream line;
    line << "TOI-STATS workload=" << workload << " queries=" << queries
         << " brent_mean=" << double(brentTotal) / std::max(queries, 1) << " brent_max=" << brentMax
         << " gjk_mean=" << double(gjkTotal) / std::max(queries, 1) << " photo_finish_rate=" << rate
         << " (no_collision=" << noCollisions << " photo_finish=" << photoFinishes << " hit=" << hits
         << " iteration_cap=" << caps << " other=" << other << "; reference contact=" << contact
         << " clear=" << clear << " grazing=" << grazing << "; misses=" << misses
         << " false_alarms=" << falseAlarms << ")";
    std::cout << line.str() << "\n";
  }
};

inline bool saysNoCollision(ToiStatus status) {
  return status == ToiStatus::NoCollision || status == ToiStatus::PhotoFinish || status == ToiStatus::Separating;
}

// What every reported hit must satisfy, against the reference at the reported time T:
//  - the bodies do not interpenetrate at T;
//  - they are within the tolerance, plus what they can move in one time tolerance (Brent
//    stops with the contact bracketed that finely), plus GJK's own uncertainty at T: the
//    gap between its distance (an upper bound) and its best supporting distance (a lower
//    bound) when it stops, which near contact is not round-off for curved shapes (GJK
//    stalls on a sphere or a capsule with a gap of up to 1e-7 in double) and with which
//    the solver's stored vectors fall short of the true distance;
//  - the reported distance is GJK's: an upper bound of the true one, within that gap;
//  - the normal points from P to Q along the reference's closest direction (to within
//    what GJK's gap allows).
// Returns the true distance at T in tolerances.
template <typename S>
double checkHit(const ToiResult<S>& r, const Moving<Shape<S>>& P, const Moving<Shape<S>>& Q, const Body& refP,
                const Body& refQ, const Bounds& bounds, double tol, double timeTol) {
  // What the float solver's rounding of the geometry can move a distance by.
  const double roundoff = sizeof(S) == sizeof(float) ? 2e-5 : 1e-12;
  const double T = double(r.time);
  const Sample at = sampleAt(refP, refQ, T);
  const auto run = gjk(P.at(r.time), Q.at(r.time));
  const double gjkGap =
      run.status == GjkStatus::Overlapping ? 0.0 : double(run.distance) - std::max(0.0, double(run.lowerBound));
  INFO("hit at " << T << ": reference distance " << at.upper << ", reported " << r.distance << ", GJK gap "
                 << gjkGap << ", tol " << tol << ", V timeTol " << bounds.V * timeTol);
  CHECK(at.upper > 0);
  CHECK(at.lower <= tol + bounds.V * timeTol + gjkGap + roundoff);
  CHECK(double(r.distance) >= at.lower - roundoff);
  CHECK(double(r.distance) <= at.upper + gjkGap + roundoff);
  // A direction off by θ from the true normal gives a Minkowski distance about d/cos θ, so
  // GJK's gap bounds 1 - cos θ by about gap/d (in float, round-off adds to the gap).
  if (at.upper > roundoff)
    CHECK(r.normal.template cast<double>().dot(at.closest) >= 1 - 1e-2 - 2 * (gjkGap + roundoff) / at.upper);
  return at.upper / tol;
}

}  // namespace gjkx::toi_test
