// The GJK study's data read back (chapter 09): the rows of a group from its gjk-<group>.csv,
// so that --replot redraws the plots and writes the key figures without measuring again.
#pragma once

#include "../formatting.hpp"
#include "gjk_study_workloads.hpp"

#include <fstream>
#include <string>
#include <vector>

namespace gjk_study {

using gjkx::study::gjk_comparison::GjkRow;
using chapter::format;

/// The rows of one group back from its gjk-<group>.csv (for --replot: the plots redrawn
/// without measuring again); false when the file is missing or has no queries column.
inline bool readGroupCsv(const std::string& folder, const Group& g, std::vector<GjkRow>& rows) {
  std::ifstream csv(folder + "/gjk-" + g.file + ".csv");
  std::string line;
  if (!std::getline(csv, line) || line.find(",queries") == std::string::npos) return false;
  while (std::getline(csv, line)) {
    const std::vector<std::string> f = chapter::csvFields(line);
    if (f.size() < 18) return false;
    GjkRow r;
    r.workload = std::string("gjk_") + (g.boolean ? "boolean_" : "distance_") + f[1] + (g.warm ? "_warm" : "");
    r.method = f[3];
    r.warmStart = f[4];
    r.ours = r.method.rfind("ours", 0) == 0;
    r.medianNs = std::stod(f[5]);
    r.p99Ns = std::stod(f[6]);
    r.errorMedian = std::stod(f[7]);
    r.errorMax = std::stod(f[8]);
    r.judged = std::stoi(f[9]);
    r.wrong = std::stoi(f[10]);
    r.failures = std::stoi(f[11]);
    r.queries = std::stoi(f[17]);
    rows.push_back(r);
  }
  return !rows.empty();
}

}  // namespace gjk_study
