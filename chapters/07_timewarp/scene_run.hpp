// A run of gjkx_simulate read back for drawing: DIR/bodies.csv (per frame and body: the pose
// of the origin of the body's shape frame, as the scene gives it) matched to the bodies of
// the run's scene by name, and DIR/frames.csv's counts per frame. gjkx_bullet_scene writes
// the same bodies.csv columns, so its runs read the same way.
#pragma once

#include "../formatting.hpp"

#include <gjkx/timewarp/scene.hpp>

#include <Eigen/Geometry>

#include <fstream>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

namespace animation {

/// The bodies of a scene at one frame of a run.
struct RunFrame {
  int frame = 0;                                ///< 0: the scene's start; then 1, 2, ...
  double time = 0;                              ///< simulated seconds at the frame's end
  std::vector<Eigen::Vector3d> position;        ///< per body of the scene: its shape frame's origin
  std::vector<Eigen::Quaterniond> orientation;  ///< per body of the scene
  long collisions = 0;                          ///< collisions resolved in the frame (frames.csv)
  long rollbacks = 0;                           ///< rollbacks in the frame (frames.csv)
};

/// The scene's start as a frame: every body where the scene puts it.
inline RunFrame startOf(const gjkx::Scene& scene) {
  RunFrame f;
  for (const gjkx::BodySpec& b : scene.bodies) {
    f.position.push_back(b.position);
    f.orientation.push_back(b.orientation);
  }
  return f;
}

/// The start of the scene and every frame of the run in `folder` (bodies.csv and frames.csv
/// of gjkx_simulate, or gjkx_bullet_scene's bodies.csv and frames.csv) for the bodies of
/// `scene`, in the scene's order. Throws std::runtime_error naming the file and what is
/// wrong: a file missing or malformed, a body of the run that the scene lacks, or a frame
/// whose bodies are not the scene's (a run of another scene).
inline std::vector<RunFrame> readRun(const std::string& folder, const gjkx::Scene& scene) {
  const std::string bodiesPath = folder + "/bodies.csv", framesPath = folder + "/frames.csv";
  std::ifstream in(bodiesPath);
  if (!in) throw std::runtime_error(bodiesPath + ": cannot read the run's poses (gjkx_simulate SCENE --out " + folder + " writes it)");
  std::map<std::string, std::size_t> index;
  for (std::size_t b = 0; b < scene.bodies.size(); ++b) index[scene.bodies[b].name] = b;
  std::string line;
  std::getline(in, line);
  if (line.rfind("frame,time,name,x,y,z,qw,qx,qy,qz", 0) != 0)
    throw std::runtime_error(bodiesPath + ": not a bodies.csv of gjkx_simulate (its header is '" + line + "')");
  std::vector<RunFrame> frames{startOf(scene)};
  std::vector<std::size_t> seen;
  const auto complete = [&](const std::string& where) {
    if (frames.size() > 1 && seen.back() != scene.bodies.size())
      throw std::runtime_error(bodiesPath + where + ": frame " + std::to_string(frames.back().frame) + " has " +
                               std::to_string(seen.back()) + " bodies, the scene " + scene.source + " has " +
                               std::to_string(scene.bodies.size()) + ": a run of another scene?");
  };
  for (int row = 2; std::getline(in, line); ++row) {
    const std::string where = ":" + std::to_string(row);
    const std::vector<std::string> cell = chapter::csvFields(line);
    if (cell.size() < 10) throw std::runtime_error(bodiesPath + where + ": fewer than 10 columns");
    double x[10];
    try {
      for (int k = 0; k < 10; ++k) x[k] = k == 2 ? 0.0 : std::stod(cell[std::size_t(k)]);
    } catch (const std::exception&) {
      throw std::runtime_error(bodiesPath + where + ": a number is malformed");
    }
    const int frame = int(x[0]);
    if (frames.size() == 1 || frames.back().frame != frame) {
      complete(where);
      frames.push_back(startOf(scene));
      frames.back().frame = frame;
      frames.back().time = x[1];
      seen.push_back(0);
    }
    const auto found = index.find(cell[2]);
    if (found == index.end())
      throw std::runtime_error(bodiesPath + where + ": body '" + cell[2] + "' is not in the scene " + scene.source +
                               ": a run of another scene?");
    RunFrame& f = frames.back();
    f.position[found->second] = Eigen::Vector3d(x[3], x[4], x[5]);
    f.orientation[found->second] = Eigen::Quaterniond(x[6], x[7], x[8], x[9]).normalized();
    ++seen.back();
  }
  complete("");
  if (frames.size() == 1) throw std::runtime_error(bodiesPath + ": no frames");
  // The counts of each frame, by the columns' names.
  std::ifstream counts(framesPath);
  if (!counts) throw std::runtime_error(framesPath + ": cannot read the run's frames (gjkx_simulate SCENE --out " + folder + " writes it)");
  std::getline(counts, line);
  const std::vector<std::string> header = chapter::csvFields(line);
  std::map<std::string, std::size_t> column;
  for (std::size_t k = 0; k < header.size(); ++k) column[header[k]] = k;
  for (const char* name : {"frame", "collisions", "rollbacks"})
    if (!column.count(name)) throw std::runtime_error(framesPath + ": no column '" + name + "'");
  std::map<int, std::size_t> byFrame;
  for (std::size_t k = 1; k < frames.size(); ++k) byFrame[frames[k].frame] = k;
  for (int row = 2; std::getline(counts, line); ++row) {
    const std::vector<std::string> cell = chapter::csvFields(line);
    try {
      const auto f = byFrame.find(std::stoi(cell.at(column["frame"])));
      if (f == byFrame.end()) continue;
      frames[f->second].collisions = std::stol(cell.at(column["collisions"]));
      frames[f->second].rollbacks = std::stol(cell.at(column["rollbacks"]));
    } catch (const std::exception&) {
      throw std::runtime_error(framesPath + ":" + std::to_string(row) + ": a count is missing or malformed");
    }
  }
  return frames;
}

}  // namespace animation
