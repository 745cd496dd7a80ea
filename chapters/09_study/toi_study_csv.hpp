// The time-of-impact study's data read back (chapter 09): the rows of a workload from its
// toi-<workload>.csv, so that --replot redraws the plots and writes the key figures without
// measuring again.
#pragma once

#include "../formatting.hpp"
#include "toi_comparisons.hpp"

#include <cmath>
#include <fstream>
#include <string>
#include <vector>

namespace toi_study {

using namespace gjkx::study;
using chapter::formatOrDash;

/// The families the study implements itself (the rest are peers).
inline bool isOurs(const std::string& family) {
  return family == "static" || family == "swept" || family == "CA" || family == "ours" || family == "certified";
}

/// The rows of one workload back from its toi-<workload>.csv (for --replot: the plots
/// redrawn without measuring again). Returns the workload's query count, 0 if unreadable.
inline int readWorkloadCsv(const std::string& path, const std::string& workload, std::vector<ToiRow>& rows) {
  std::ifstream csv(path);
  std::string line;
  if (!std::getline(csv, line)) return 0;
  int queries = 0;
  while (std::getline(csv, line)) {
    const std::vector<std::string> f = chapter::csvFields(line);
    if (f.size() < 13) continue;
    ToiRow r;
    r.workload = workload;
    r.family = f[1];
    r.setting = f[2];
    r.scalar = f[3];
    r.ours = isOurs(r.family);
    r.medianUs = std::stod(f[4]);
    r.p99Us = std::stod(f[5]);
    r.errMedian = std::stod(f[6]);
    r.errMax = std::stod(f[7]);
    r.misses = std::stoi(f[8]);
    r.refHits = std::stoi(f[9]);
    r.falseAlarms = std::stoi(f[10]);
    r.clearMisses = std::stoi(f[11]);
    r.detectionOnly = std::isnan(r.errMedian) && std::stod(f[12]) == 1.0;
    r.queries = f.size() > 14 ? std::stoi(f[14]) : 0;
    queries = r.queries;
    rows.push_back(r);
  }
  return queries;
}

}  // namespace toi_study
