// Google Benchmark of our GJK queries (chapter 09): distance and boolean, cold and
// warm-started, on the study's 100-vertex polytopes, boxes, spheres and capsules. The comparison with the
// peers is gjk_study; this is the fine-grained timer for the speed work on lib/gjk.
//
//   study_benchmarks [--benchmark_filter=...]
#include "gjk_comparisons.hpp"

#include <benchmark/benchmark.h>

namespace {

using namespace gjkx;
using namespace gjkx::study;
using namespace gjkx::study::gjk_comparison;

// The study's workloads (quick size), built once.
const GjkWorkload& workload(ShapeKind kind, int vertices) {
  static std::map<int, GjkWorkload> cache;
  const int key = int(kind) * 10000 + vertices;
  auto it = cache.find(key);
  if (it == cache.end()) {
    GjkStudyOptions options;
    options.quick = true;
    const char* name = kind == ShapeKind::Box       ? "box"
                       : kind == ShapeKind::Sphere  ? "sphere"
                       : kind == ShapeKind::Capsule ? "capsule"
                       : vertices == 12             ? "polytope12"
                       : vertices == 100            ? "polytope100"
                                                    : "polytope1000";
    it = cache.emplace(key, gjk_comparison::detail::makeWorkload(name, kind, vertices, options)).first;
  }
  return it->second;
}

template <typename T>
void runQueries(benchmark::State& state, ShapeKind kind, int vertices, bool warm, bool boolean) {
  using S = typename T::Scalar;
  const GjkWorkload& w = workload(kind, vertices);
  const auto& queries = warm ? w.warm : w.cold;
  std::vector<Placed<T>> P, Q;
  for (const auto& q : queries) {
    P.push_back(Placed<T>{gjk_comparison::detail::ourShapeAs<T>(w.shapes[q.shapeP]), q.poseP.cast<S>()});
    Q.push_back(Placed<T>{gjk_comparison::detail::ourShapeAs<T>(w.shapes[q.shapeQ]), q.poseQ.cast<S>()});
  }
  const GjkSettings<S> settings;
  const IntersectionSettings<S> intersection;
  GjkCache<S> cache;
  size_t k = 0;
  for (auto _ : state) {
    if (!warm || queries[k].startsTrajectory) cache.valid = false;
    if (boolean) {
      benchmark::DoNotOptimize(intersect(P[k], Q[k], intersection, warm ? &cache : nullptr));
    } else {
      benchmark::DoNotOptimize(gjk(P[k], Q[k], settings, warm ? &cache : nullptr));
    }
    k = (k + 1) % queries.size();
  }
}

void distancePolytope100(benchmark::State& s) { runQueries<Polytope<double>>(s, ShapeKind::Polytope, 100, false, false); }
void distancePolytope100Warm(benchmark::State& s) { runQueries<Polytope<double>>(s, ShapeKind::Polytope, 100, true, false); }
void booleanPolytope100(benchmark::State& s) { runQueries<Polytope<double>>(s, ShapeKind::Polytope, 100, false, true); }
void booleanPolytope100Warm(benchmark::State& s) { runQueries<Polytope<double>>(s, ShapeKind::Polytope, 100, true, true); }
void booleanPolytope100WarmFloat(benchmark::State& s) { runQueries<Polytope<float>>(s, ShapeKind::Polytope, 100, true, true); }
void distanceBox(benchmark::State& s) { runQueries<Box<double>>(s, ShapeKind::Box, 8, false, false); }
void distanceBoxWarm(benchmark::State& s) { runQueries<Box<double>>(s, ShapeKind::Box, 8, true, false); }
void distancePolytope1000(benchmark::State& s) { runQueries<Polytope<double>>(s, ShapeKind::Polytope, 1000, false, false); }
void distanceSphere(benchmark::State& s) { runQueries<Sphere<double>>(s, ShapeKind::Sphere, 0, false, false); }
void distanceCapsule(benchmark::State& s) { runQueries<Capsule<double>>(s, ShapeKind::Capsule, 0, false, false); }

}  // namespace

BENCHMARK(distancePolytope100);
BENCHMARK(distancePolytope100Warm);
BENCHMARK(booleanPolytope100);
BENCHMARK(booleanPolytope100Warm);
BENCHMARK(booleanPolytope100WarmFloat);
BENCHMARK(distanceBox);
BENCHMARK(distanceBoxWarm);
BENCHMARK(distancePolytope1000);
BENCHMARK(distanceSphere);
BENCHMARK(distanceCapsule);

BENCHMARK_MAIN();
