// ccd_queries: the time-of-impact solver of §5 against an external ground truth, the
// sample queries of the CCD benchmark of Wang et al. (ACM TOG 2021).
//
//   ccd_queries [--tolerance X] [--float] [--quiet] FOLDER|FILE...
//
// A folder is searched recursively for `*.csv` in `vertex-face/` and `edge-edge/`
// folders; a file's kind is its folder's name. Each query (8 rows: a vertex and a
// triangle, or two edges, at t0 and t1) becomes two `DeformingSimplex`es over [0, 1],
// and `timeOfImpact` (the paper's variant: per-vertex linear motion keeps the
// supporting distance along a fixed direction concave in t, so the extrusion test is
// sound) decides it. Positive = `reportsCollision(status)`; an undecided query (cap or
// numerical failure) is positive and also counted in `capped`.
//
// Output: one row per file (`file kind queries positives fn fp capped us_per_query`),
// every false negative in full, then the totals, ending with exactly one line
//   total queries=N positives=N fn=N fp=N us_per_query=X
// Time is measured around the solver calls only. Bad input stops the program with a
// message naming file:line and field, exit status 2.
#include "../command_line.hpp"

#include <gjkx/study/ccd_queries.hpp>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <limits>
#include <string>
#include <vector>

using namespace gjkx;
namespace ccd = gjkx::study::ccd;  // the benchmark's file format and queries

namespace {

struct Options {
  double tolerance = 0;  // 0: the library default, sqrt(eps) of the scalar
  bool useFloat = false;
  bool quiet = false;
  std::vector<std::string> inputs;
};

// A finite number above zero, as --tolerance needs ("1e-3"; not "0", "-1", "inf" or "1e-3x").
const CLI::Validator positiveNumber(
    [](std::string& text) -> std::string {
      char* end = nullptr;
      const double value = std::strtod(text.c_str(), &end);
      if (text.empty() || *end != '\0' || !std::isfinite(value) || !(value > 0))
        return "'" + text + "' is not a positive number";
      return "";
    },
    "POSITIVE");

// The command line; a bad one (an unknown option, no FOLDER|FILE, a bad value) exits with status 2.
Options parse(int argc, char** argv) {
  Options options;
  CLI::App app{"Runs the time-of-impact solver (§5) on the CCD benchmark's sample queries."};
  app.add_option("--tolerance", options.tolerance, "collision tolerance (default sqrt(eps) of the scalar type)")
      ->type_name("X")
      ->check(positiveNumber);
  app.add_flag("--float", options.useFloat, "solve in float (coordinates rounded from double)");
  app.add_flag("--quiet", options.quiet, "print the totals only");
  app.add_option("paths", options.inputs,
                 "a FOLDER, searched recursively for *.csv under vertex-face/ and edge-edge/, or a .csv FILE "
                 "whose folder is vertex-face or edge-edge")
      ->type_name("FOLDER|FILE")
      ->required();
  chapter::parseOrExit(app, argc, argv);
  return options;
}

std::vector<ccd::QueryFile> readInputs(const std::vector<std::string>& inputs) {
  std::vector<ccd::QueryFile> files;
  for (const std::string& input : inputs) {
    const std::filesystem::path path(input);
    if (std::filesystem::is_directory(path)) {
      std::vector<ccd::QueryFile> found = ccd::readQueryFolder(path);
      if (found.empty())
        throw ccd::InputError(input, 0, "folder", "holds no *.csv file under a vertex-face or edge-edge folder");
      for (auto& file : found) files.push_back(std::move(file));
    } else if (std::filesystem::is_regular_file(path)) {
      files.push_back(ccd::readQueryFile(path));
    } else {
      throw ccd::InputError(input, 0, "path", "is neither a folder nor a file");
    }
  }
  return files;
}

const char* rowName(ccd::QueryKind kind, int row) {
  static const char* const vf[8] = {"v(t0)", "f0(t0)", "f1(t0)", "f2(t0)", "v(t1)", "f0(t1)", "f1(t1)", "f2(t1)"};
  static const char* const ee[8] = {"a0(t0)", "a1(t0)", "b0(t0)", "b1(t0)", "a0(t1)", "a1(t1)", "b0(t1)", "b1(t1)"};
  return kind == ccd::QueryKind::VertexFace ? vf[row] : ee[row];
}

// A false negative in full: where it is, what the solver said, and the vertices (exact).
template <typename S>
void printFalseNegative(const ccd::QueryFile& file, const ccd::Query& query, const ToiResult<S>& result) {
  std::printf("false negative: %s:%d (%s) status=%s brent_iterations=%d restarts=%d gjk_runs=%d\n", file.path.c_str(),
              query.line, toString(file.kind), toString(result.status), result.brentIterations, result.restarts,
              result.gjkRuns);
  for (int row = 0; row < 8; ++row)
    std::printf("  %-7s % .17g % .17g % .17g\n", rowName(file.kind, row), query.vertices[row].x(),
                query.vertices[row].y(), query.vertices[row].z());
}

template <typename S>
int run(const Options& options, const std::vector<ccd::QueryFile>& files) {
  ToiSettings<S> settings;  // the paper's variant, default time tolerance and caps
  if (options.tolerance > 0) settings.collisionTolerance = S(options.tolerance);
  if (!(settings.collisionTolerance > S(0))) {
    std::fprintf(stderr, "ccd_queries: --tolerance %g is zero in this scalar type\n", options.tolerance);
    return 2;
  }
  std::printf("ccd_queries: scalar=%s tolerance=%.3g variant=paper files=%zu\n", options.useFloat ? "float" : "double",
              double(settings.collisionTolerance), files.size());

  std::size_t nameWidth = 4;
  for (const auto& file : files) nameWidth = std::max(nameWidth, file.name.size());
  if (!options.quiet)
    std::printf("%-*s %-11s %7s %9s %5s %5s %6s %12s\n", int(nameWidth), "file", "kind", "queries", "positives", "fn",
                "fp", "capped", "us_per_query");

  long long queries = 0, truthPositives = 0, positives = 0, fn = 0, fp = 0, capped = 0, photoFinishes = 0;
  long long brentIterations = 0, brentQueries = 0;
  int maxBrentIterations = 0;
  double seconds = 0;
  long long statusCounts[7] = {};
  std::vector<std::string> falseNegatives;
  for (const auto& file : files) {
    const ccd::FileRun<S> result = ccd::runQueries(file, settings);
    const std::size_t n = file.queries.size();
    if (!options.quiet)
      std::printf("%-*s %-11s %7zu %9d %5d %5d %6d %12.3g\n", int(nameWidth), file.name.c_str(), toString(file.kind), n,
                  result.positives, result.falseNegatives, result.falsePositives, result.capped,
                  n ? 1e6 * result.seconds / double(n) : 0.0);
    queries += static_cast<long long>(n);
    positives += result.positives;
    fn += result.falseNegatives;
    fp += result.falsePositives;
    capped += result.capped;
    photoFinishes += result.photoFinishes;
    brentIterations += result.brentIterations;
    maxBrentIterations = std::max(maxBrentIterations, result.maxBrentIterations);
    seconds += result.seconds;
    for (std::size_t k = 0; k < n; ++k) {
      truthPositives += file.queries[k].truth;
      brentQueries += result.results[k].brentIterations > 0;
      ++statusCounts[static_cast<int>(result.results[k].status)];
    }
    if (!options.quiet)
      for (std::size_t k = 0; k < n; ++k)
        if (file.queries[k].truth && !ccd::positive(result.results[k].status))
          printFalseNegative(file, file.queries[k], result.results[k]);
  }

  std::printf("statuses:");
  for (int s = 0; s < 7; ++s) std::printf(" %s=%lld", toString(static_cast<ToiStatus>(s)), statusCounts[s]);
  std::printf("\n");
  std::printf("truth positives=%lld negatives=%lld capped=%lld\n", truthPositives, queries - truthPositives, capped);
  // Brent's statistics as gjkx_simulate's SUMMARY and the paper-claims table define them:
  // over the queries that ran Brent (brentIterations > 0), not over all queries.
  std::printf("brent_queries=%lld brent_mean=%.3g brent_max=%d photo_finish=%.3g\n", brentQueries,
              brentQueries ? double(brentIterations) / double(brentQueries) : 0.0, maxBrentIterations,
              brentQueries ? double(photoFinishes) / double(brentQueries) : 0.0);
  std::printf("total queries=%lld positives=%lld fn=%lld fp=%lld us_per_query=%.3g\n", queries, positives, fn, fp,
              queries ? 1e6 * seconds / double(queries) : 0.0);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  const Options options = parse(argc, argv);
  try {
    const std::vector<ccd::QueryFile> files = readInputs(options.inputs);
    return options.useFloat ? run<float>(options, files) : run<double>(options, files);
  } catch (const ccd::InputError& e) {
    std::fprintf(stderr, "ccd_queries: bad input: %s\n", e.what());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "ccd_queries: error: %s\n", e.what());
  }
  return 2;
}
