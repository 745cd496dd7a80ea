// The warm boolean query's lean first step (§2.3 with §2.2's temporal coherence) against
// the GJK loop it stands in for.
//
// A warm boolean query starts along the direction the last query ended on, and most often
// the first supporting distance along it is above the threshold: gjk then answers from
// that one support pair without the loop's bookkeeping (`detail::separatedAlongCachedDirection`).
// A visitor switches that shortcut off (the visitor must see every iteration), so the
// same query with a visitor that never stops is the loop alone. Along random trajectories,
// each query is asked both ways from the same cache, and everything must be equal: status,
// iterations, the separating vector and the supporting distance (to the bit: the shortcut
// does the loop's own arithmetic), the distance, and the cache each leaves for the next query.
#include <gjkx/gjk/gjk.hpp>
#include <gjkx/support_mapping/placed.hpp>
#include <gjkx/support_mapping/polytope.hpp>
#include <gjkx/support_mapping/primitives.hpp>

#include <catch2/catch.hpp>

#include <cmath>
#include <iostream>
#include <random>
#include <vector>

using namespace gjkx;

namespace {

// A visitor that never stops the run: with it gjk runs the loop alone.
struct EveryIteration {
  template <typename S>
  bool operator()(const GjkIteration<S>&) const {
    return true;
  }
};

// A convex polytope of 8 to 120 random points on an ellipsoid of about `size`.
template <typename S>
Polytope<S> randomPolytope(std::mt19937& rng, double size) {
  std::uniform_real_distribution<double> u(-1, 1);
  std::normal_distribution<double> g(0, 1);
  const int n = std::uniform_int_distribution<int>(8, 120)(rng);
  const Eigen::Vector3d axes(0.6 + 0.4 * u(rng), 0.6 + 0.4 * u(rng), 0.6 + 0.4 * u(rng));
  std::vector<Vector3<S>> points;
  for (int k = 0; k < n; ++k) points.push_back((size * axes.cwiseProduct(Eigen::Vector3d(g(rng), g(rng), g(rng)).normalized())).cast<S>());
  return Polytope<S>::hull(points);
}

Eigen::Matrix3d randomRotation(std::mt19937& rng, double angle) {
  std::normal_distribution<double> g(0, 1);
  return Eigen::AngleAxisd(angle, Eigen::Vector3d(g(rng), g(rng), g(rng)).normalized()).toRotationMatrix();
}

// How many queries of a run took the shortcut and how many went on into the loop.
struct Counts {
  long queries = 0, firstStep = 0, loop = 0;
};

// One trajectory: P turns in place, Q turns and moves from `gap` apart towards P and past
// it. Each query is asked with the shortcut (cache `lean`) and by the loop alone (cache
// `loop`), both caches equal before it; the answers and the caches after must be equal.
template <typename ShapeP, typename ShapeQ>
void compareAlongTrajectory(const ShapeP& shapeP, const ShapeQ& shapeQ, std::mt19937& rng, Counts& counts) {
  using S = typename ShapeP::Scalar;
  std::uniform_real_distribution<double> u(-1, 1);
  std::normal_distribution<double> g(0, 1);
  const Eigen::Vector3d towards = Eigen::Vector3d(g(rng), g(rng), g(rng)).normalized();
  Pose<double> poseP, poseQ;
  poseP.rotation = randomRotation(rng, M_PI * u(rng));
  poseQ.rotation = randomRotation(rng, M_PI * u(rng));
  poseQ.translation = -3.0 * towards;  // a few sizes apart
  const Eigen::Vector3d velocity = (towards + 0.3 * Eigen::Vector3d(g(rng), g(rng), g(rng))) * 0.05;
  const Eigen::Matrix3d turnP = randomRotation(rng, 0.02), turnQ = randomRotation(rng, 0.02);
  GjkSettings<S> settings;
  settings.separationThreshold = defaultCollisionTolerance<S>();  // a boolean query, as `intersect` asks it
  GjkCache<S> lean, loop;
  for (int step = 0; step < 120; ++step) {
    const Placed<ShapeP> P{shapeP, poseP.cast<S>()};
    const Placed<ShapeQ> Q{shapeQ, poseQ.cast<S>()};
    const bool warm = lean.valid;
    const GjkResult<S> a = gjk(P, Q, settings, &lean);
    const GjkResult<S> b = gjk(P, Q, settings, &loop, EveryIteration{});
    INFO("step " << step << ": with the shortcut " << toString(a.status) << " after " << a.iterations
                 << " iterations, SD " << a.lowerBound << "; the loop alone " << toString(b.status) << " after "
                 << b.iterations << " iterations, SD " << b.lowerBound);
    ++counts.queries;
    if (warm && a.status == GjkStatus::SeparatingVector && a.iterations == 1)
      ++counts.firstStep;
    else
      ++counts.loop;
    REQUIRE(a.status == b.status);
    CHECK(a.iterations == b.iterations);
    CHECK(a.separatingVector == b.separatingVector);
    CHECK(a.lowerBound == b.lowerBound);
    CHECK((a.distance == b.distance || (std::isnan(a.distance) && std::isnan(b.distance))));
    CHECK(a.simplex.size == b.simplex.size);
    CHECK(lean.valid == loop.valid);
    CHECK(lean.direction == loop.direction);
    CHECK(lean.hintP == loop.hintP);
    CHECK(lean.hintQ == loop.hintQ);
    CHECK(lean.simplex.size == loop.simplex.size);
    poseP.rotation = turnP * poseP.rotation;
    poseQ.rotation = turnQ * poseQ.rotation;
    poseQ.translation += velocity;
  }
}

}  // namespace

TEMPLATE_TEST_CASE("gjk: a warm boolean query's first step answers as the loop does", "[gjk][warm][boolean]", float,
                   double) {
  // 40 trajectories of 120 steps for each pair of kinds: two polytopes (the hill climbs
  // from the cached hints), a box and a polytope, a sphere and a polytope (rounded: the
  // shortcut runs on the cores, with the threshold raised by the radius). Most queries
  // must take the shortcut, and some must go on into the loop (the bodies come to overlap),
  // so that both sides of it are compared.
  using S = TestType;
  std::mt19937 rng(2027);
  std::uniform_real_distribution<double> u(-1, 1);
  Counts counts;
  for (int trajectory = 0; trajectory < 40; ++trajectory) {
    INFO("trajectory " << trajectory);
    const Polytope<S> P = randomPolytope<S>(rng, 1.0), Q = randomPolytope<S>(rng, 1.0);
    compareAlongTrajectory(P, Q, rng, counts);
    compareAlongTrajectory(Box<S>(Vector3<S>(S(0.8), S(0.5), S(0.3))), Q, rng, counts);
    compareAlongTrajectory(Sphere<S>(S(0.5 + 0.3 * u(rng))), Q, rng, counts);
  }
  std::cout << "gjk warm boolean (" << (sizeof(S) == 4 ? "float" : "double") << "): " << counts.queries << " queries, "
            << counts.firstStep << " answered by the first step alone, " << counts.loop << " by the loop\n";
  CHECK(counts.firstStep > counts.queries / 2);
  CHECK(counts.loop > counts.queries / 20);
}
