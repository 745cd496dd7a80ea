// GJK on random convex polytope pairs against brute force (§2.2).
//
// Each pair is two hulls of 4 to 60 random points (on or in spheres and ellipsoids) at
// random poses, some apart and some overlapping. The reference (gjkx/reference) is
// computed in long double from the very numbers GJK sees: overlap by a separating-axis
// test over face normals and edge-edge cross products, distance as the nearest of all
// vertex-triangle, triangle-vertex and edge-edge pairs. A Separated answer must also
// satisfy the optimality condition of the closest-distance problem: along
// z = witnessQ - witnessP the supporting planes of P and Q are exactly |z| apart
// (SD(P, Q, z) = |z|, §2.3), with the witnesses on their shapes.
#include "to_reference.hpp"

#include <gjkx/gjk/gjk.hpp>
#include <gjkx/support_mapping/placed.hpp>
#include <gjkx/support_mapping/polytope.hpp>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <limits>
#include <random>
#include <string>
#include <vector>

using namespace gjkx;
using gjkx::test::Real;
using gjkx::test::RVec;

namespace {

template <typename S>
const char* scalarName() {
  return sizeof(S) == sizeof(float) ? "float" : "double";
}

// Relative tolerance of a distance, to be multiplied by the size of the coordinates:
// GJK stops at a relative gap of eps^(3/4) (1.8e-12 in double, 6.4e-6 in float), and
// float round-off in the poses alone is 1e-7 of the coordinates.
template <typename S>
Real tolerance() {
  return sizeof(S) == sizeof(float) ? Real(1e-4) : Real(1e-9);
}

// A convex polytope from 4 to 60 random points on or in a sphere or an ellipsoid of
// about `size`, in its body frame.
template <typename S>
Polytope<S> randomPolytope(std::mt19937& rng, double size) {
  std::uniform_real_distribution<double> u(-1, 1);
  std::normal_distribution<double> g(0, 1);
  const int n = std::uniform_int_distribution<int>(4, 60)(rng);
  const int kind = std::uniform_int_distribution<int>(0, 3)(rng);  // sphere/ball/ellipsoid surface/solid
  Eigen::Vector3d axes(1, 1, 1);
  if (kind >= 2) axes = Eigen::Vector3d(0.6 + 0.5 * u(rng), 0.6 + 0.5 * u(rng), 0.6 + 0.5 * u(rng));
  std::vector<Vector3<S>> points;
  for (int k = 0; k < n; ++k) {
    Eigen::Vector3d x(g(rng), g(rng), g(rng));
    x.normalize();
    if (kind % 2 == 1) x *= std::cbrt(0.5 * (1 + u(rng)));  // solid: a radius inside
    points.push_back((size * axes.cwiseProduct(x)).cast<S>());
  }
  return Polytope<S>::hull(points);
}

template <typename S>
Pose<S> randomPose(std::mt19937& rng, const Eigen::Vector3d& translation) {
  std::uniform_real_distribution<double> u(-1, 1);
  Eigen::Vector3d axis(u(rng), u(rng), u(rng));
  if (axis.norm() < 1e-3) axis = Eigen::Vector3d::UnitZ();
  return Pose<double>::fromAxisAngle(axis, M_PI * u(rng), translation).cast<S>();
}

// One random pair: P somewhere near the origin, Q at a centre distance between 0.3 and
// 1.6 times the sum of their sizes in a random direction (so some touch, some do not).
template <typename S>
struct RandomPair {
  Polytope<S> P, Q;
  Pose<S> poseP, poseQ;
};

template <typename S>
RandomPair<S> randomPair(std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-1, 1);
  std::normal_distribution<double> g(0, 1);
  const double scale = std::pow(10.0, u(rng));  // pairs of sizes 0.1 to 10
  const double sizeP = scale * (0.5 + 0.4 * u(rng)), sizeQ = scale * (0.5 + 0.4 * u(rng));
  const Eigen::Vector3d centreP = Eigen::Vector3d(u(rng), u(rng), u(rng)) * 2 * scale;
  const Eigen::Vector3d direction = Eigen::Vector3d(g(rng), g(rng), g(rng)).normalized();
  const Eigen::Vector3d centreQ = centreP + direction * (sizeP + sizeQ) * (0.95 + 0.65 * u(rng));
  Polytope<S> P = randomPolytope<S>(rng, sizeP);
  Polytope<S> Q = randomPolytope<S>(rng, sizeQ);
  return RandomPair<S>{P, Q, randomPose<S>(rng, centreP), randomPose<S>(rng, centreQ)};
}

// The independent truth about a pair.
struct Truth {
  bool overlapping = false;
  bool nearContact = false;  // within the tolerance of touching: either answer will do
  Real distance = 0;         // when apart
  Real size = 1;             // the largest world coordinate: what the tolerances scale with
};

template <typename S>
Truth truthOf(const reference::WorldPolytope& P, const reference::WorldPolytope& Q) {
  Truth t;
  for (const RVec& v : P.vertices) t.size = std::max(t.size, v.cwiseAbs().maxCoeff());
  for (const RVec& v : Q.vertices) t.size = std::max(t.size, v.cwiseAbs().maxCoeff());
  const Real gap = reference::separatingAxisGap(P, Q);
  const reference::FeatureDistance boundary = reference::boundaryDistance(P, Q);
  t.overlapping = !(gap > 0);
  t.distance = t.overlapping ? Real(0) : boundary.distance;
  // Either reference alone could be fooled by a near contact; flag those.
  const Real band = 10 * tolerance<S>() * t.size;
  // (The boundary distance counts only when apart: intersecting boundaries cross
  // edge-to-face, a pair it does not look at.)
  t.nearContact = std::abs(gap) <= band || (!t.overlapping && boundary.distance <= band);
  if (!t.overlapping) CHECK(boundary.distance >= gap - band);  // the references agree: SAT's gap is a lower bound
  return t;
}

// SD(P, Q, s) = min_Q s.q - max_P s.p for a unit s (§2.3), over the world vertices.
inline Real supportingDistance(const reference::WorldPolytope& P, const reference::WorldPolytope& Q, const RVec& s) {
  const RVec unit = s.normalized();
  return -Q.supportValue(-unit) - P.supportValue(unit);
}

// What every run must satisfy: an answer, within the cap, no NaN.
template <typename S>
void checkWellFormed(const GjkResult<S>& r, const GjkSettings<S>& settings = {}) {
  INFO("status " << toString(r.status) << ", iterations " << r.iterations);
  CHECK((r.status == GjkStatus::Separated || r.status == GjkStatus::Overlapping));
  CHECK(r.iterations >= 1);
  CHECK(r.iterations <= settings.maxIterations);
  CHECK(std::isfinite(r.distance));
  CHECK(r.witnessP.allFinite());
  CHECK(r.witnessQ.allFinite());
}

// The optimality (KKT) condition of a Separated result: |z| is the distance and
// SD(P, Q, z) = |z| (the planes normal to z through the witnesses support P and Q); the
// witnesses lie on the boundaries of their shapes and differ by z. SD is checked along the
// z GJK returns, the direction it claims: witnessQ - witnessP is a convex combination of
// the simplex's w, good only to about eps * (coordinates), so its direction is good to
// eps * size / |z|, which in float and at |z| = size / 300 moves SD by more than the
// tolerance (KKT along it failed by 2.4e-4 where SD(z) - |z| was 2e-8).
template <typename S>
void checkOptimality(const GjkResult<S>& r, const reference::WorldPolytope& P, const reference::WorldPolytope& Q, Real size) {
  const Real tol = tolerance<S>() * size;
  const RVec p = test::toReal(r.witnessP), q = test::toReal(r.witnessQ);
  const RVec z = test::toReal(r.z);
  INFO("distance " << r.distance << ", |z| " << double(z.norm()) << ", |q - p| " << double((q - p).norm()));
  CHECK(std::abs(z.norm() - Real(r.distance)) <= tol);
  CHECK((q - p - z).norm() <= tol);
  REQUIRE(z.norm() > 0);
  CHECK(std::abs(supportingDistance(P, Q, z) - z.norm()) <= tol);
  CHECK(std::abs(P.planeDistance(p)) <= tol);
  CHECK(std::abs(Q.planeDistance(q)) <= tol);
}

struct Stats {
  long runs = 0, iterations = 0, maxIterations = 0;
  void add(int i) {
    ++runs, iterations += i;
    maxIterations = std::max<long>(maxIterations, i);
  }
  double mean() const { return runs ? double(iterations) / double(runs) : 0.0; }
};

// A shape that counts its support queries (the hinted ones too), to compare warm and
// cold runs by the work they do as well as by iterations.
template <typename X>
struct Counted {
  using Scalar = typename X::Scalar;
  const X* x;
  long* calls;
  Vector3<Scalar> support(const Vector3<Scalar>& s) const {
    ++*calls;
    return x->support(s);
  }
  Vector3<Scalar> support(const Vector3<Scalar>& s, SupportHint& hint) const {
    ++*calls;
    return supportFrom(*x, s, hint);
  }
  Vector3<Scalar> center() const { return x->center(); }
};

}  // namespace

TEMPLATE_TEST_CASE("gjk: random polytope pairs match the brute-force distance", "[gjk][random]", float, double) {
  // 300 pairs (fixed seed). Apart: Separated, the distance within tolerance * size of the
  // brute force, the optimality condition, and lowerBound <= distance. Overlapping:
  // Overlapping with distance 0. Near contacts (within 10 tolerances) may go either way.
  using S = TestType;
  std::mt19937 rng(42);
  Stats separated, overlapping;
  int apart = 0, inside = 0, near = 0;
  for (int trial = 0; trial < 300; ++trial) {
    const RandomPair<S> pair = randomPair<S>(rng);
    const reference::WorldPolytope P = test::toWorld(pair.P, pair.poseP), Q = test::toWorld(pair.Q, pair.poseQ);
    const Truth truth = truthOf<S>(P, Q);
    const GjkResult<S> r = gjk(place(pair.P, pair.poseP), place(pair.Q, pair.poseQ));
    INFO("trial " << trial << " (" << pair.P.vertexCount() << " and " << pair.Q.vertexCount()
                  << " vertices): truth " << (truth.overlapping ? "overlapping" : "apart") << " at "
                  << double(truth.distance) << ", size " << double(truth.size) << "; GJK " << toString(r.status)
                  << " at " << r.distance << " after " << r.iterations << " iterations");
    checkWellFormed(r);
    if (r.status == GjkStatus::Separated) separated.add(r.iterations);
    if (r.status == GjkStatus::Overlapping) overlapping.add(r.iterations);
    if (truth.nearContact) {
      ++near;
      CHECK(r.distance <= truth.distance + tolerance<S>() * truth.size);
      continue;
    }
    if (truth.overlapping) {
      ++inside;
      CHECK(r.status == GjkStatus::Overlapping);
      CHECK(r.distance == S(0));
    } else {
      ++apart;
      REQUIRE(r.status == GjkStatus::Separated);
      CHECK(std::abs(Real(r.distance) - truth.distance) <= tolerance<S>() * truth.size);
      CHECK(Real(r.lowerBound) <= truth.distance + tolerance<S>() * truth.size);
      CHECK(Real(r.lowerBound) >= truth.distance - tolerance<S>() * truth.size);
      checkOptimality(r, P, Q, truth.size);
    }
  }
  std::cout << "gjk random polytopes (" << scalarName<S>() << "): " << apart << " apart, " << inside
            << " overlapping, " << near << " near contact; iterations when separated mean " << separated.mean()
            << " max " << separated.maxIterations << ", when overlapping mean " << overlapping.mean() << " max "
            << overlapping.maxIterations << "\n";
  CHECK(apart >= 50);  // the generator does make both kinds
  CHECK(inside >= 50);
}

TEMPLATE_TEST_CASE("gjk: warm start on small pose changes gives the cold distances in fewer iterations",
                   "[gjk][random][warm]", float, double) {
  // 40 trajectories of 25 small steps: Q turns 0.02 rad per step about a fixed axis
  // and moves 6% of its size per step straight towards P's centre from 2 sizes away
  // (separated, then overlapping), or 4% sideways (mostly separated). At each step a cold run (no cache) and a warm run (GjkCache
  // carried along the trajectory) must agree: same status away from contact, distances
  // within tolerance, and the warm Separated answers satisfy the optimality condition.
  // The warm runs must take fewer iterations on average.
  using S = TestType;
  std::mt19937 rng(42);
  std::uniform_real_distribution<double> u(-1, 1);
  std::normal_distribution<double> g(0, 1);
  Stats cold, warm;
  long coldSupports = 0, warmSupports = 0;
  for (int trajectory = 0; trajectory < 40; ++trajectory) {
    const double size = std::pow(10.0, u(rng));
    const Polytope<S> shapeP = randomPolytope<S>(rng, size), shapeQ = randomPolytope<S>(rng, size);
    const Pose<S> poseP = randomPose<S>(rng, Eigen::Vector3d(u(rng), u(rng), u(rng)) * size);
    const Eigen::Vector3d centreP = poseP.translation.template cast<double>();
    const Eigen::Vector3d start = centreP + Eigen::Vector3d(g(rng), g(rng), g(rng)).normalized() * 2.0 * size;
    Eigen::Vector3d velocity = (centreP - start).normalized() * 0.06 * size;  // towards P's centre
    if (trajectory % 2 == 1)  // or sideways, past it
      velocity = velocity.cross(Eigen::Vector3d(g(rng), g(rng), g(rng))).normalized() * 0.04 * size;
    const Eigen::Vector3d axis = Eigen::Vector3d(g(rng), g(rng), g(rng)).normalized();
    const Pose<double> startPose = randomPose<double>(rng, start);
    GjkCache<S> cache;
    for (int step = 0; step < 25; ++step) {
      Pose<double> poseQd = startPose;
      poseQd.rotation = Eigen::AngleAxisd(0.02 * step, axis).toRotationMatrix() * startPose.rotation;
      poseQd.translation = start + velocity * step;
      const Pose<S> poseQ = poseQd.cast<S>();
      const auto P = place(shapeP, poseP);
      const auto Q = place(shapeQ, poseQ);
      long coldCalls = 0, warmCalls = 0;
      const GjkResult<S> c = gjk(Counted<decltype(P)>{&P, &coldCalls}, Counted<decltype(Q)>{&Q, &coldCalls});
      const GjkResult<S> w =
          gjk(Counted<decltype(P)>{&P, &warmCalls}, Counted<decltype(Q)>{&Q, &warmCalls}, {}, &cache);
      const reference::WorldPolytope wP = test::toWorld(shapeP, poseP), wQ = test::toWorld(shapeQ, poseQ);
      Real scale = 1;
      for (const RVec& v : wP.vertices) scale = std::max(scale, v.cwiseAbs().maxCoeff());
      for (const RVec& v : wQ.vertices) scale = std::max(scale, v.cwiseAbs().maxCoeff());
      const Real tol = tolerance<S>() * scale;
      INFO("trajectory " << trajectory << " step " << step << ": cold " << toString(c.status) << " at " << c.distance
                         << " (" << c.iterations << " iterations), warm " << toString(w.status) << " at "
                         << w.distance << " (" << w.iterations << " iterations)");
      checkWellFormed(c);
      checkWellFormed(w);
      cold.add(c.iterations);
      warm.add(w.iterations);
      coldSupports += coldCalls;
      warmSupports += warmCalls;
      CHECK(std::abs(Real(w.distance) - Real(c.distance)) <= tol);
      const bool nearContact = std::min(c.distance, w.distance) <= 10 * tol;
      if (!nearContact) CHECK(w.status == c.status);
      if (w.status == GjkStatus::Separated && !nearContact) checkOptimality(w, wP, wQ, scale);
    }
  }
  std::cout << "gjk warm start (" << scalarName<S>() << "): cold iterations mean " << cold.mean() << " max "
            << cold.maxIterations << ", warm mean " << warm.mean() << " max " << warm.maxIterations
            << "; support queries per run cold " << double(coldSupports) / double(cold.runs) << ", warm "
            << double(warmSupports) / double(warm.runs) << "\n";
  CHECK(warm.mean() < cold.mean());
}

TEMPLATE_TEST_CASE("gjk: warm start on large and small pose changes agrees with cold runs", "[gjk][random][warm]",
                   float, double) {
  // 400 trajectories of 40 steps, each with its own step: a turn of 1e-3 to 3 rad (about a
  // half turn per step at the top) and a move of 1e-3 to 0.1 of the size, from up to 3
  // sizes away, through or past P; elongated and flattened hulls. A warm run may start
  // far from the answer; it must still agree with the cold run and, when Separated,
  // satisfy the optimality condition with its own witnesses.
  using S = TestType;
  std::mt19937 rng(99);
  std::uniform_real_distribution<double> u(-1, 1);
  std::normal_distribution<double> g(0, 1);
  int checkedOptimality = 0;
  for (int trajectory = 0; trajectory < 400; ++trajectory) {
    const double size = std::pow(10.0, u(rng));
    auto stretched = [&]() {
      const int n = std::uniform_int_distribution<int>(4, 40)(rng);
      Eigen::Vector3d axes(std::pow(10.0, 0.7 * u(rng)), std::pow(10.0, 0.7 * u(rng)), 1);
      std::vector<Vector3<S>> points;
      for (int k = 0; k < n; ++k) {
        Eigen::Vector3d x(g(rng), g(rng), g(rng));
        x.normalize();
        points.push_back((size * axes.cwiseProduct(x)).cast<S>());
      }
      return Polytope<S>::hull(points);
    };
    const Polytope<S> shapeP = stretched(), shapeQ = stretched();
    const double turn = std::pow(10.0, -3 + 3.5 * std::abs(u(rng)));
    const double move = size * std::pow(10.0, -3 + 2 * std::abs(u(rng)));
    Eigen::Vector3d axis(g(rng), g(rng), g(rng));
    axis.normalize();
    Eigen::Vector3d direction(g(rng), g(rng), g(rng));
    direction.normalize();
    const Eigen::Vector3d start =
        -direction * size * 3 * std::abs(u(rng)) + Eigen::Vector3d(u(rng), u(rng), u(rng)) * size;
    const Pose<S> poseP =
        Pose<double>::fromAxisAngle(Eigen::Vector3d(g(rng), g(rng), g(rng)), 3 * u(rng), Eigen::Vector3d::Zero())
            .cast<S>();
    GjkCache<S> cache;
    for (int step = 0; step < 40; ++step) {
      const Pose<S> poseQ = Pose<double>::fromAxisAngle(axis, turn * step, start + direction * move * step).cast<S>();
      const auto P = place(shapeP, poseP);
      const auto Q = place(shapeQ, poseQ);
      const GjkResult<S> c = gjk(P, Q);
      const GjkResult<S> w = gjk(P, Q, {}, &cache);
      const reference::WorldPolytope wP = test::toWorld(shapeP, poseP), wQ = test::toWorld(shapeQ, poseQ);
      Real scale = 1;
      for (const RVec& v : wP.vertices) scale = std::max(scale, v.cwiseAbs().maxCoeff());
      for (const RVec& v : wQ.vertices) scale = std::max(scale, v.cwiseAbs().maxCoeff());
      const Real tol = tolerance<S>() * scale;
      INFO("trajectory " << trajectory << " step " << step << ": cold " << toString(c.status) << " at " << c.distance
                         << ", warm " << toString(w.status) << " at " << w.distance << " after " << w.iterations
                         << " iterations");
      checkWellFormed(w);
      CHECK(std::abs(Real(w.distance) - Real(c.distance)) <= tol);
      const bool nearContact = std::min(c.distance, w.distance) <= 10 * tol;
      if (!nearContact) CHECK(w.status == c.status);
      if (w.status == GjkStatus::Separated && !nearContact) {
        checkOptimality(w, wP, wQ, scale);
        ++checkedOptimality;
      }
    }
  }
  CHECK(checkedOptimality > 1000);
}
