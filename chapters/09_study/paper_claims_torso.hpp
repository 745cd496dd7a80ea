// gjkx_paper_claims, §6: the torso scene's size, counted from the model gjkx_generate_torso
// writes (chapters/08_torso/torso_model.hpp), and the statistics of two kept runs of it
// (gjkx_simulate's summary.txt and frames.csv) for paper_claims.cpp's table.
#pragma once

#include "../08_torso/torso_model.hpp"
#include "../formatting.hpp"

#include <algorithm>
#include <fstream>
#include <map>
#include <sstream>
#include <string>

namespace claims {

/// The size of the §6 scene as gjkx_generate_torso makes it (seed 1; the seed only turns
/// and places the torso, the meshes are the same for every seed).
struct TorsoSize {
  long bodies = 0;          ///< the moving bodies: one per bone
  long boneTriangles = 0;   ///< the triangles of every bone's mesh, summed
  long plantTriangles = 0;  ///< the triangles of the static plant
};

/// Counts the bones and triangles of the full torso scene (torso::layoutScene, not reduced).
inline TorsoSize countTorso() {
  const torso::SceneLayout layout = torso::layoutScene(1, false);
  TorsoSize size;
  size.bodies = long(layout.bones.size());
  for (const auto& bone : layout.bones) size.boneTriangles += long(bone.mesh.triangles.size());
  size.plantTriangles = long(layout.plant.triangles.size());
  return size;
}

/// A kept run of the torso scene: SUMMARY's key=value pairs, and from frames.csv the
/// ratio of each frame's wall time to its simulated time and the time of the slowest frame.
struct TorsoRun {
  bool found = false;                          ///< both files were read
  std::map<std::string, std::string> summary;  ///< SUMMARY's key=value pairs
  double ratioMin = 0, ratioMax = 0;           ///< over every frame
  double peakTime = 0;                         ///< simulated time at the end of the slowest frame
};

/// Reads `dir`/summary.txt and `dir`/frames.csv (gjkx_simulate --out `dir`); not found
/// when `dir` is empty or either file is missing.
inline TorsoRun readTorso(const std::string& dir) {
  TorsoRun run;
  if (dir.empty()) return run;
  std::ifstream summary(dir + "/summary.txt"), frames(dir + "/frames.csv");
  std::string line;
  if (!summary || !std::getline(summary, line)) return run;
  std::istringstream words(line);
  for (std::string word; words >> word;) {
    const auto eq = word.find('=');
    if (eq != std::string::npos) run.summary[word.substr(0, eq)] = word.substr(eq + 1);
  }
  // frames.csv: the wall time of each frame over its simulated time (1/24 s at the paper's rate).
  std::string header;
  if (!frames || !std::getline(frames, header)) return run;
  double lastTime = 0, peak = -1;
  run.ratioMin = 1e300;
  while (std::getline(frames, line)) {
    std::istringstream fields(line);
    std::string frame, time, wall;
    std::getline(fields, frame, ',');
    std::getline(fields, time, ',');
    std::getline(fields, wall, ',');
    const double t = std::stod(time), w = std::stod(wall), ratio = w / (t - lastTime);
    lastTime = t;
    run.ratioMin = std::min(run.ratioMin, ratio);
    run.ratioMax = std::max(run.ratioMax, ratio);
    if (w > peak) {
      peak = w;
      run.peakTime = t;
    }
  }
  run.found = true;
  return run;
}

/// One cell of a torso row: "brent" (mean and max), "photo" (the photo-finish rate),
/// "ratio" (execution over simulation time) or "peak" (the slowest frame's time).
inline std::string torsoValue(const TorsoRun& run, const std::string& what) {
  using chapter::format;
  if (!run.found) return "not run (see the command)";
  if (what == "brent") return "mean " + run.summary.at("brent_mean") + ", max " + run.summary.at("brent_max");
  if (what == "photo")
    return format("%.1f", 100 * std::stod(run.summary.at("photo_finish"))) + "% of the queries that ran Brent";
  if (what == "ratio")
    return format("%.2f", run.ratioMin) + " to " + format("%.1f", run.ratioMax) + " (this machine, shared)";
  if (what == "peak") return "t = " + format("%.2f", run.peakTime) + " s";
  return "?";
}

}  // namespace claims
