// The GJK study's workloads and rows (chapter 09): a workload's name taken apart, the four
// groups of the figures and tables (distance or boolean, cold or warm-started), and the
// rows the tables, plots and key figures look up (a method's, the fastest peer's, ours in
// float beside ours in double).
#pragma once

#include "../formatting.hpp"
#include "gjk_comparisons.hpp"

#include <algorithm>
#include <string>
#include <vector>

namespace gjk_study {

using gjkx::study::gjk_comparison::GjkRow;
using chapter::format;

/// A workload name gjk_<distance|boolean>_<shape>[_warm], taken apart.
struct WorkloadName {
  bool boolean = false, warm = false;
  std::string shape;
};
inline WorkloadName split(const std::string& workload) {
  WorkloadName n;
  std::string rest = workload.substr(4);  // after "gjk_"
  n.boolean = rest.rfind("boolean_", 0) == 0;
  rest = rest.substr(n.boolean ? 8 : 9);
  n.warm = rest.size() > 5 && rest.compare(rest.size() - 5, 5, "_warm") == 0;
  n.shape = n.warm ? rest.substr(0, rest.size() - 5) : rest;
  return n;
}

/// The four workload groups, in the order of the figures and tables.
struct Group {
  bool boolean, warm;
  const char* file;   // gjk-<file>.png
  const char* title;  // for titles and headings
};
constexpr Group kGroups[] = {{false, false, "distance-cold", "distance queries, cold"},
                             {false, true, "distance-warm", "distance queries, warm-started"},
                             {true, false, "boolean-cold", "boolean queries, cold"},
                             {true, true, "boolean-warm", "boolean queries, warm-started"}};

/// The fastest peer of a workload (median time), 0 when it has none.
inline double bestPeerNs(const std::vector<GjkRow>& rows, const std::string& workload) {
  double best = 0;
  for (const auto& r : rows)
    if (r.workload == workload && !r.ours && (best == 0 || r.medianNs < best)) best = r.medianNs;
  return best;
}

/// Ours in double against ours in float, workload by workload.
struct ScalarPair {
  std::string workload;
  const GjkRow *d = nullptr, *f = nullptr;
};

inline std::vector<ScalarPair> scalarPairs(const std::vector<GjkRow>& rows) {
  std::vector<ScalarPair> pairs;
  for (const auto& r : rows) {
    if (r.method != "ours-double" && r.method != "ours-float") continue;
    if (pairs.empty() || pairs.back().workload != r.workload) pairs.push_back({r.workload});
    (r.method == "ours-double" ? pairs.back().d : pairs.back().f) = &r;
  }
  return pairs;
}

inline std::string statusCounts(const GjkRow& r) {
  std::string s = std::to_string(r.iterationCap) + " / " + std::to_string(r.numericalFailure);
  if (r.otherFailure) s += " (+" + std::to_string(r.otherFailure) + " other)";
  return s;
}

/// The shapes in the order of the rows.
inline std::vector<std::string> shapesOf(const std::vector<GjkRow>& rows) {
  std::vector<std::string> shapes;
  for (const auto& r : rows) {
    const std::string s = split(r.workload).shape;
    if (std::find(shapes.begin(), shapes.end(), s) == shapes.end()) shapes.push_back(s);
  }
  return shapes;
}

/// The row of a method on a workload, or nullptr.
inline const GjkRow* rowOf(const std::vector<GjkRow>& rows, const std::string& workload, const std::string& method) {
  for (const auto& r : rows)
    if (r.workload == workload && r.method == method) return &r;
  return nullptr;
}

/// The fastest peer's row on a workload, or nullptr.
inline const GjkRow* bestPeerRow(const std::vector<GjkRow>& rows, const std::string& workload) {
  const GjkRow* best = nullptr;
  for (const auto& r : rows)
    if (r.workload == workload && !r.ours && (!best || r.medianNs < best->medianNs)) best = &r;
  return best;
}

inline std::string workloadName(bool boolean, const std::string& shape, bool warm) {
  return std::string("gjk_") + (boolean ? "boolean_" : "distance_") + shape + (warm ? "_warm" : "");
}

}  // namespace gjk_study
