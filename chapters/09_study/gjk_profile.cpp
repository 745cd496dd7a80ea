// gjk_profile: our GJK query of one workload of the GJK comparison run once per query,
// without timing loops, so that an instruction count under callgrind is repeatable and
// per query (the GJK counterpart of toi_profile).
//
//   gjk_profile [--shape box|sphere|capsule|polytope12|polytope100|polytope1000]
//               [--query boolean|distance] [--cold] [--float] [--repeat N]
//
// Builds the quick workload of gjk_comparisons.hpp for the shape (the same shapes, poses
// and trajectories as study_summary's rows), then answers every query of its warm list
// (or cold list) `--repeat` times in order, as the study does: `intersect` for a boolean
// query, `gjk` for a distance, one GjkCache carried along each trajectory. It prints the
// queries, how the runs ended, and the mean GJK iterations. Under valgrind the counting is
// switched on only around the queries (callgrind client requests, when the header is there):
//
//   valgrind --tool=callgrind --instr-atstart=no build/chapters/09_study/gjk_profile --shape polytope100
//   callgrind_annotate --inclusive=yes callgrind.out.<pid>
//
// The total instruction count divided by the "calls" line is the instruction count per query.
#include "../command_line.hpp"
#include "callgrind_markers.hpp"
#include "gjk_comparisons.hpp"

#include <cstdio>
#include <map>
#include <string>
#include <vector>

using namespace gjkx;
using namespace gjkx::study;
using namespace gjkx::study::gjk_comparison;
namespace comparison = gjkx::study::gjk_comparison::detail;  // the GJK comparison's own parts

namespace {

struct Options {
  std::string shape = "polytope100";
  std::string query = "boolean";
  bool cold = false;
  bool single = false;
  int repeat = 1;
};

// The queries of one workload with shapes of type T, answered in order; prints how they ended.
template <typename T>
void run(const GjkWorkload& w, const Options& o) {
  using S = typename T::Scalar;
  const std::vector<GjkQuery>& queries = o.cold ? w.cold : w.warm;
  std::vector<Placed<T>> P, Q;
  for (const auto& q : queries) {
    P.push_back(Placed<T>{comparison::ourShapeAs<T>(w.shapes[q.shapeP]), q.poseP.cast<S>()});
    Q.push_back(Placed<T>{comparison::ourShapeAs<T>(w.shapes[q.shapeQ]), q.poseQ.cast<S>()});
  }
  const bool boolean = o.query == "boolean";
  GjkSettings<S> settings;
  IntersectionSettings<S> intersection;
  GjkCache<S> cache;
  GjkCache<S>* cachePtr = o.cold ? nullptr : &cache;
  std::map<std::string, long long> ends;
  long long iterations = 0;
  for (int r = 0; r < o.repeat; ++r) {
    for (size_t k = 0; k < queries.size(); ++k) {
      if (queries[k].startsTrajectory) cache.valid = false;
      GJKX_PROFILE_START();
      if (boolean) {
        const auto result = intersect(P[k], Q[k], intersection, cachePtr);
        GJKX_PROFILE_STOP();
        ++ends[toString(result.status)];
        iterations += result.iterations;
      } else {
        const auto result = gjk(P[k], Q[k], settings, cachePtr);
        GJKX_PROFILE_STOP();
        ++ends[toString(result.status)];
        iterations += result.iterations;
      }
    }
  }
  const long long calls = (long long)queries.size() * o.repeat;
  std::printf("PROFILE shape=%s query=%s start=%s scalar=%s calls=%lld iterations=%.3f", w.name.c_str(), o.query.c_str(),
              o.cold ? "cold" : "warm", sizeof(S) == 4 ? "float" : "double", calls, double(iterations) / double(calls));
  for (const auto& [status, count] : ends) std::printf(" %s=%lld", status.c_str(), count);
  std::printf("\n");
}

template <template <typename> class Shape>
void runScalar(const GjkWorkload& w, const Options& o) {
  if (o.single)
    run<Shape<float>>(w, o);
  else
    run<Shape<double>>(w, o);
}

}  // namespace

int main(int argc, char** argv) {
  Options o;
  CLI::App app{"Runs our GJK query once per query of one study workload (no timing), for callgrind."};
  app.add_option("--shape", o.shape, "the workload's shape")
      ->check(CLI::IsMember({"box", "sphere", "capsule", "polytope12", "polytope100", "polytope1000"}))
      ->capture_default_str();
  app.add_option("--query", o.query, "the query")->check(CLI::IsMember({"boolean", "distance"}))->capture_default_str();
  app.add_flag("--cold", o.cold, "the cold list (independent pairs, no cache) instead of the warm trajectories");
  app.add_flag("--float", o.single, "in float instead of double");
  app.add_option("--repeat", o.repeat, "passes over the queries")->type_name("N")->check(CLI::PositiveNumber)->capture_default_str();
  chapter::parseOrExit(app, argc, argv);

  GjkStudyOptions study;
  study.quick = true;
  const std::map<std::string, std::pair<ShapeKind, int>> kinds = {
      {"box", {ShapeKind::Box, 8}},           {"sphere", {ShapeKind::Sphere, 0}},          {"capsule", {ShapeKind::Capsule, 0}},
      {"polytope12", {ShapeKind::Polytope, 12}}, {"polytope100", {ShapeKind::Polytope, 100}}, {"polytope1000", {ShapeKind::Polytope, 1000}}};
  const auto [kind, vertices] = kinds.at(o.shape);
  const GjkWorkload w = comparison::makeWorkload(o.shape, kind, vertices, study);
  switch (kind) {
    case ShapeKind::Box: runScalar<Box>(w, o); break;
    case ShapeKind::Sphere: runScalar<Sphere>(w, o); break;
    case ShapeKind::Capsule: runScalar<Capsule>(w, o); break;
    default: runScalar<Polytope>(w, o); break;
  }
  return 0;
}
