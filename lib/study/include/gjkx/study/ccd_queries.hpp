/// @file
/// @brief The CCD benchmark's sample queries: reading them and solving them with the §5 solver.
///
/// Holds (namespace gjkx::study::ccd, the benchmark's file format and queries): `QueryKind`,
/// `Query`, `QueryFile`, `InputError`, `readQueryFile`, `readQueryFolder`, `runQueries`.
///
/// Reading and solving the sample queries of the CCD benchmark of Wang, Ferguson,
/// Schneider, Jiang, Attene and Panozzo (ACM TOG 40(5), 2021): the external ground truth
/// of chapter 05. Shared by the program ccd_queries and tests/brent/test_ccd_queries.cpp.
///
/// The format (../shared/data/ccd-queries/README.md): no header; one query is 8
/// consecutive rows, one vertex a row, `xnum,xden,ynum,yden,znum,zden,truth`, each
/// coordinate being strtod(num) / strtod(den) (exact in double for this data). `truth`
/// (0 or 1, the same on all 8 rows) says whether the primitives touch in [0, 1].
///   vertex-face rows: v(t0), f0(t0), f1(t0), f2(t0), v(t1), f0(t1), f1(t1), f2(t1)
///   edge-edge rows:   a0(t0), a1(t0), b0(t0), b1(t0), a0(t1), a1(t1), b0(t1), b1(t1)
/// The kind of a file is the name of its folder (`vertex-face` or `edge-edge`).
///
/// Every vertex moves linearly, so both primitives are `DeformingSimplex`es: P is the
/// vertex (or edge a), Q the face (or edge b), over [0, 1].
#pragma once

#include <gjkx/brent/time_of_impact.hpp>
#include <gjkx/support_mapping/deforming_simplex.hpp>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace gjkx::study::ccd {

/// The two kinds of queries of the benchmark.
enum class QueryKind { VertexFace, EdgeEdge };

/// The folder name that holds files of this kind.
inline const char* toString(QueryKind kind) { return kind == QueryKind::VertexFace ? "vertex-face" : "edge-edge"; }

/// Bad input: the message is "file:line: field: what" (line 0 when the whole file is meant).
struct InputError : std::runtime_error {
  std::string file;   ///< the file
  int line = 0;       ///< its 1-based line
  std::string field;  ///< the offending field (xnum ... zden, truth, row, rows, kind)
  /// The error at `file_`:`line_` (0: the whole file) in `field_`.
  InputError(const std::string& file_, int line_, const std::string& field_, const std::string& what)
      : std::runtime_error(file_ + (line_ > 0 ? ":" + std::to_string(line_) : std::string()) + ": " + field_ + ": " +
                           what),
        file(file_),
        line(line_),
        field(field_) {}
};

/// One query: 8 vertices (rows in the file's order) and the ground truth.
struct Query {
  std::array<gjkx::Vector3<double>, 8> vertices;  ///< the 8 rows' vertices
  bool truth = false;                             ///< the benchmark's answer: the primitives touch in [0, 1]
  int line = 0;  ///< the line of its first row
};

/// One file of queries.
struct QueryFile {
  std::string path;     ///< as opened
  std::string name;     ///< as reported (relative to the searched folder, or the path)
  QueryKind kind = QueryKind::VertexFace;  ///< vertex-face or edge-edge (the folder's name)
  std::vector<Query> queries;              ///< its queries, in the file's order
};

/// The kind of a file from its parent folder's name; throws InputError otherwise.
inline QueryKind kindOf(const std::filesystem::path& file) {
  const std::string parent = file.parent_path().filename().string();
  if (parent == "vertex-face") return QueryKind::VertexFace;
  if (parent == "edge-edge") return QueryKind::EdgeEdge;
  throw InputError(file.string(), 0, "kind",
                   "the parent folder must be 'vertex-face' or 'edge-edge' (it says which primitives a row holds), "
                   "got '" + parent + "'");
}

namespace detail {
inline std::string trim(const std::string& text) {
  const auto first = text.find_first_not_of(" \t\r");
  if (first == std::string::npos) return "";
  const auto last = text.find_last_not_of(" \t\r");
  return text.substr(first, last - first + 1);
}

// strtod of the whole field; anything left over, or a value that is not finite, is an error.
inline double number(const std::string& text, const std::string& file, int line, const char* field) {
  const std::string t = trim(text);
  if (t.empty()) throw InputError(file, line, field, "empty, expected a number");
  char* end = nullptr;
  const double value = std::strtod(t.c_str(), &end);
  if (end != t.c_str() + t.size()) throw InputError(file, line, field, "'" + t + "' is not a number");
  if (!std::isfinite(value)) throw InputError(file, line, field, "'" + t + "' is not a finite number");
  return value;
}
}  // namespace detail

/// Parses one file (kind from its folder); throws InputError naming file:line and field.
inline QueryFile readQueryFile(const std::filesystem::path& path, const std::string& name = "") {
  QueryFile file;
  file.path = path.string();
  file.name = name.empty() ? file.path : name;
  file.kind = kindOf(path);
  std::ifstream in(path);
  if (!in) throw InputError(file.path, 0, "file", "cannot be opened");

  static const char* const fields[7] = {"xnum", "xden", "ynum", "yden", "znum", "zden", "truth"};
  std::vector<std::string> lines;
  for (std::string text; std::getline(in, text);) lines.push_back(text);
  while (!lines.empty() && detail::trim(lines.back()).empty()) lines.pop_back();  // blank lines at the end

  const int rows = static_cast<int>(lines.size());
  Query query;
  for (int r = 0; r < rows; ++r) {
    const int line = r + 1;
    std::vector<std::string> cells;
    std::string::size_type from = 0;
    for (;;) {
      const auto comma = lines[r].find(',', from);
      cells.push_back(lines[r].substr(from, comma == std::string::npos ? std::string::npos : comma - from));
      if (comma == std::string::npos) break;
      from = comma + 1;
    }
    if (cells.size() != 7)
      throw InputError(file.path, line, "row",
                       "expected 7 comma-separated fields (xnum,xden,ynum,yden,znum,zden,truth), got " +
                           std::to_string(cells.size()));
    gjkx::Vector3<double> vertex;
    for (int axis = 0; axis < 3; ++axis) {
      const double num = detail::number(cells[2 * axis], file.path, line, fields[2 * axis]);
      const double den = detail::number(cells[2 * axis + 1], file.path, line, fields[2 * axis + 1]);
      if (den == 0) throw InputError(file.path, line, fields[2 * axis + 1], "zero denominator");
      vertex[axis] = num / den;  // the README: strtod(num) / strtod(den), exact for this data
    }
    const std::string truthText = detail::trim(cells[6]);
    if (truthText != "0" && truthText != "1")
      throw InputError(file.path, line, "truth", "must be 0 or 1, got '" + truthText + "'");
    const bool truth = truthText == "1";
    if (r % 8 == 0) {
      query.line = line;
      query.truth = truth;
    } else if (truth != query.truth) {
      throw InputError(file.path, line, "truth",
                       std::string("is ") + truthText + " but the query's first row (line " +
                           std::to_string(query.line) + ") says " + (query.truth ? "1" : "0") +
                           ": truth must be the same on all 8 rows");
    }
    query.vertices[r % 8] = vertex;
    if (r % 8 == 7) file.queries.push_back(query);
  }
  // Checked after the rows, so a bad field in an incomplete query is reported at its line.
  if (rows % 8 != 0) {
    const int start = rows - rows % 8 + 1;
    throw InputError(file.path, start, "rows",
                     std::to_string(rows) + " rows is not a multiple of 8 (a query is 8 rows, one per vertex); the "
                     "last query, from this line, has only " + std::to_string(rows % 8));
  }
  return file;
}

/// The query files under a folder: every `*.csv` whose parent folder is `vertex-face`
/// or `edge-edge`, searched recursively, in sorted order, named relative to the folder.
inline std::vector<QueryFile> readQueryFolder(const std::filesystem::path& folder) {
  std::vector<std::filesystem::path> paths;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(folder)) {
    if (!entry.is_regular_file() || entry.path().extension() != ".csv") continue;
    const std::string parent = entry.path().parent_path().filename().string();
    if (parent == "vertex-face" || parent == "edge-edge") paths.push_back(entry.path());
  }
  std::sort(paths.begin(), paths.end());
  std::vector<QueryFile> files;
  for (const auto& path : paths) files.push_back(readQueryFile(path, path.lexically_relative(folder).string()));
  return files;
}

/// The two moving primitives of a query in scalar S (float rounds the double coordinates).
template <typename S>
struct QueryBodies {
  gjkx::DeformingSimplex<S> P;  ///< the vertex (edge-edge: edge a)
  gjkx::DeformingSimplex<S> Q;  ///< the face (edge-edge: edge b)
};

/// P = the vertex (edge a), Q = the face (edge b), over [0, 1].
template <typename S>
QueryBodies<S> bodiesOf(const Query& query, QueryKind kind) {
  auto at = [&](int row) { return gjkx::Vector3<S>(query.vertices[row].template cast<S>()); };
  if (kind == QueryKind::VertexFace)
    return {gjkx::DeformingSimplex<S>({at(0)}, {at(4)}), gjkx::DeformingSimplex<S>({at(1), at(2), at(3)},
                                                                                   {at(5), at(6), at(7)})};
  return {gjkx::DeformingSimplex<S>({at(0), at(1)}, {at(4), at(5)}),
          gjkx::DeformingSimplex<S>({at(2), at(3)}, {at(6), at(7)})};
}

/// What the solver said about the queries of one file, and how long it took.
template <typename S>
struct FileRun {
  std::vector<gjkx::ToiResult<S>> results;  ///< one per query
  double seconds = 0;                       ///< solver time only (parsing and set-up excluded)
  int positives = 0;            ///< queries counted as colliding (`positive`)
  int falseNegatives = 0;       ///< ground truth colliding, reported not
  int falsePositives = 0;       ///< reported colliding, ground truth not
  int capped = 0;               ///< iteration caps
  int photoFinishes = 0;        ///< photo finishes (§5)
  int maxBrentIterations = 0;   ///< the most Brent iterations of one query
  long long brentIterations = 0;  ///< Brent iterations of all queries
};

/// Counted as colliding: `reportsCollision` (hit, starting in contact, and the undecided
/// statuses — a caller that must not miss treats a cap or a failure as a collision).
inline bool positive(gjkx::ToiStatus status) { return gjkx::reportsCollision(status); }
/// Undecided: counted as positive and, separately, as capped.
inline bool undecided(gjkx::ToiStatus status) {
  return status == gjkx::ToiStatus::IterationCap || status == gjkx::ToiStatus::NumericalFailure;
}

/// Runs `timeOfImpact` over [0, 1] on every query of a file.
template <typename S>
FileRun<S> runQueries(const QueryFile& file, const gjkx::ToiSettings<S>& settings) {
  std::vector<QueryBodies<S>> bodies;
  bodies.reserve(file.queries.size());
  for (const Query& query : file.queries) {
    try {
      bodies.push_back(bodiesOf<S>(query, file.kind));
    } catch (const std::invalid_argument& e) {  // e.g. a double beyond float's range
      throw InputError(file.path, query.line, "vertices", e.what());
    }
  }
  FileRun<S> run;
  run.results.resize(bodies.size());
  const auto start = std::chrono::steady_clock::now();
  for (std::size_t k = 0; k < bodies.size(); ++k)
    run.results[k] = gjkx::timeOfImpact(bodies[k].P, bodies[k].Q, S(0), S(1), settings);
  run.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  for (std::size_t k = 0; k < bodies.size(); ++k) {
    const gjkx::ToiResult<S>& result = run.results[k];
    const bool said = positive(result.status), truth = file.queries[k].truth;
    run.positives += said;
    run.falseNegatives += truth && !said;
    run.falsePositives += !truth && said;
    run.capped += undecided(result.status);
    run.photoFinishes += result.status == gjkx::ToiStatus::PhotoFinish;
    run.brentIterations += result.brentIterations;
    run.maxBrentIterations = std::max(run.maxBrentIterations, result.brentIterations);
  }
  return run;
}

}  // namespace gjkx::study::ccd
