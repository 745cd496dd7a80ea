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
  const GjkProfile profile = profileOurs(w, o.query == "boolean", o.cold, o.single, o.repeat);
  std::printf("PROFILE shape=%s query=%s start=%s scalar=%s calls=%lld iterations=%.3f", w.name.c_str(), o.query.c_str(),
              o.cold ? "cold" : "warm", o.single ? "float" : "double", profile.calls,
              double(profile.iterations) / double(profile.calls));
  for (const auto& [status, count] : profile.ends) std::printf(" %s=%lld", status.c_str(), count);
  std::printf("\n");
  return 0;
}
