// The running-time figures of chapter 08, drawn by gnuplot from runs read back
// (run_stats.hpp): Fig. 6 and its companions, each frame's wall time over its simulated
// time stacked by part (the script running_time.gp), and the torso scene in every
// simulator of the peers table, frame by frame (peers_frames.gp). Each writes its data
// into OUT/data and runs its script there.
#pragma once

#include "../chapter.hpp"
#include "run_stats.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#ifndef GJKX_TORSO_RUNNING_TIME_GP  // Fig. 6's gnuplot script, beside this file
#define GJKX_TORSO_RUNNING_TIME_GP "chapters/08_torso/running_time.gp"
#endif
#ifndef GJKX_PEERS_FRAMES_GP  // the peers' frames' gnuplot script, beside this file
#define GJKX_PEERS_FRAMES_GP "chapters/08_torso/peers_frames.gp"
#endif

namespace torso {

/// How `run` was made, in words, from its summary.txt (RUN scene=... bodies=N scalar=...):
/// "8 bodies, float, certified extrusion test, tolerance 0.000345, 24 frames/s" and the
/// scene's folder; "settings unknown" without summary.txt.
inline std::string runDescription(const Run& run) {
  std::map<std::string, std::string> key;
  std::stringstream words(run.settings);
  for (std::string w; words >> w;)
    if (const auto eq = w.find('='); eq != std::string::npos) key[w.substr(0, eq)] = w.substr(eq + 1);
  if (key.empty()) return run.folder + " (no summary.txt: settings unknown)";
  const std::filesystem::path scene(key["scene"]);
  return key["bodies"] + " bodies (" + scene.parent_path().filename().string() + "/" + scene.filename().string() +
         "), " + key["scalar"] + ", " + key["variant"] + " extrusion test, tolerance " + key["tolerance"] + ", " +
         key["frame_rate"] + " frames/s" + (key.count("contact") ? ", " + key["contact"] + " contact" : "");
}

/// A string for gnuplot: single-quoted, so that nothing in it is an escape ('' is a quote).
inline std::string gnuplotString(const std::string& text) {
  std::string quoted = "'";
  for (const char c : text) quoted += c == '\'' ? std::string("''") : std::string(1, c);
  return quoted + "'";
}

/// One word for the shell: single-quoted, a quote in it closed, escaped and reopened.
inline std::string shellWord(const std::string& text) {
  std::string quoted = "'";
  for (const char c : text) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return quoted + "'";
}

/// Runs the gnuplot script `script` in `folder` (where its data, `name`.csv, was written)
/// with the settings `set` (gnuplot -e), drawing `figure` into `out`. Returns false, and
/// says why, when gnuplot is missing or fails.
inline bool gnuplotFigure(const std::string& out, const std::string& folder, const std::string& name,
                   const std::string& figure, const std::string& set, const std::string& script) {
  if (std::system("gnuplot --version > /dev/null 2>&1") != 0) {
    std::cerr << "08_torso: gnuplot not found: wrote " << folder << "/" << name << ".csv, skipped " << figure << "\n";
    return false;
  }
  const std::string command = "cd " + shellWord(folder) + " && gnuplot -e " + shellWord(set) + " " + shellWord(script);
  if (std::system(command.c_str()) != 0) {
    std::cerr << "08_torso: gnuplot failed on " << script << " with " << set << "\n";
    return false;
  }
  chapter::wrote(out + "/" + figure);
  return true;
}

/// Fig. 6's axes (running_time.gp says what each is).
struct Fig6Axes {
  bool twoPanels = false;  ///< the frames and the paper's range span more than a factor 30
  double bottom = 0, top = 0;  ///< with two panels: the log axis's range
  double stackTop = 0;     ///< the linear axis's top
  double xmax = 0;         ///< the simulated time at the run's end
};

/// The axes that show every run of `runs` whole beside the paper's range.
inline Fig6Axes fig6Axes(const std::vector<const Run*>& runs) {
  using P = PaperFigures;
  double lo = P::ratioMin, hi = P::ratioMax, ours = 0;
  Fig6Axes axes;
  for (const Run* run : runs) {
    for (std::size_t k = 0; k < run->frames(); ++k) {
      const double r = run->ratio(k);
      if (r > 0) lo = std::min(lo, r);
      hi = std::max(hi, r);
      ours = std::max(ours, r);
    }
    axes.xmax = std::max(axes.xmax, run->at("time").back());
  }
  axes.twoPanels = hi / lo > 30;
  if (axes.twoPanels) {
    axes.bottom = std::pow(10.0, std::floor(std::log10(lo)));
    axes.top = std::pow(10.0, std::ceil(std::log10(hi * 1.5)));
    axes.stackTop = ours * 1.1;
  } else {
    axes.stackTop = hi * 1.1;
  }
  return axes;
}

/// Fig. 6 from `run`'s frames.csv: per frame, the method's wall time over the frame's
/// simulated time, stacked by part (methodParts()), against the time at the frame's end;
/// the real-time line y = 1 and the paper's range 1.0-7.9 for comparison. Writes
/// OUT/data/fig06-torso-running-time.csv (the stacked values), then runs the gnuplot script
/// running_time.gp beside this file there, passing it the data, the axes' ranges and the
/// texts (when the frames and the paper's range span more than a factor 30 it draws two
/// panels: see the script); returns false (and says why) when gnuplot is missing or fails.
/// `name` is the figure's file name; `axes` its axes (those of its own run, or, for the
/// companion figure of the hybrid run, Fig. 6's, so that the two compare at a glance).
inline bool runningTimeFigure(const std::string& out, const Run& run, const std::string& name, const Fig6Axes& axes) {
  using P = PaperFigures;
  const auto parts = run.parts();
  const std::string folder = out + "/data";
  std::filesystem::create_directories(folder);
  double wall = 0, checks = 0;
  for (std::size_t k = 0; k < run.frames(); ++k) {
    wall += run.at("wall_s")[k];
    checks += run.at("checks_s")[k];
  }
  std::ofstream csv(folder + "/" + name + ".csv");
  csv << "# written by 08_torso from the frames.csv of the run " << std::filesystem::path(run.folder).filename().string() << ": execution time of each frame over its simulated "
      << "time, the top of each part stacked bottom to top, at the frame's start and end (a step per frame)\ntime";
  for (const auto& part : parts) csv << ',' << part.first;
  csv << '\n';
  for (std::size_t k = 0; k < run.frames(); ++k) {
    std::string row;
    double sum = 0;
    for (const auto& part : parts) {
      sum += run.at(part.first)[k] / run.frameLength(k);
      row += chapter::format(",%.6g", sum);
    }
    csv << run.at("time")[k] - run.frameLength(k) << row << '\n' << run.at("time")[k] << row << '\n';
  }
  csv.close();

  // The script's settings (running_time.gp says what each is), numbers as C++ streams print them.
  std::ostringstream set;
  const std::string figure = name + "." + chapter::figureFormat();
  set << "data=" << gnuplotString(name + ".csv") << "; out=" << gnuplotString("../" + figure)
      << "; format=" << gnuplotString(chapter::figureFormat())
      << "; description=" << gnuplotString(runDescription(run)) << "; parts=" << parts.size();
  for (std::size_t p = 0; p < parts.size(); ++p) set << "; part" << p + 1 << "=" << gnuplotString(parts[p].second);
  set << "; checksNote="
      << gnuplotString(chapter::format("(not the method): %.0f%% of wall time", 100 * (wall > 0 ? checks / wall : 0)))
      << "; band=" << gnuplotString(chapter::format("paper (500 MHz Pentium III): %.1f to %.1f", P::ratioMin, P::ratioMax))
      << "; ratioMin=" << std::to_string(P::ratioMin) << "; ratioMax=" << std::to_string(P::ratioMax)
      << "; xmax=" << axes.xmax << "; twoPanels=" << (axes.twoPanels ? 1 : 0);
  if (axes.twoPanels)
    set << "; bottom=" << axes.bottom << "; top=" << axes.top << "; stackTop=" << axes.stackTop;
  else
    set << "; stackTop=" << axes.stackTop;
  return gnuplotFigure(out, folder, name, figure, set.str(), GJKX_TORSO_RUNNING_TIME_GP);
}

/// The torso scene in every simulator of the peers table (see the file's head): reads the
/// CSV of `gjkx_peers_table --frames` (scene, frame, time at its end, its wall time over its
/// simulated time, simulator last: a name may hold a comma), writes the torso's rows as
/// OUT/data/peers-torso-frames.csv (a step per frame, a column per simulator) and runs
/// peers_frames.gp there. Returns false (and says why) without the file, a torso row or gnuplot.
inline bool peersFramesFigure(const std::string& out, const std::string& path) {
  std::ifstream in(path);
  if (!in) {
    std::cerr << "08_torso: warning: no peers' frames at " << path << "; peers-torso-frames.png skipped\n";
    return false;
  }
  std::vector<std::string> names;
  std::vector<std::vector<std::pair<double, double>>> series;  // per simulator: (end time, ratio) per frame
  std::string line;
  std::getline(in, line);  // the header
  for (int row = 2; std::getline(in, line); ++row) {
    if (line.empty()) continue;
    std::string cell[4];
    std::size_t at = 0;
    for (std::string& c : cell) {
      const std::size_t comma = line.find(',', at);
      if (comma == std::string::npos) throw std::runtime_error(path + ":" + std::to_string(row) + ": fewer than 5 cells");
      c = line.substr(at, comma - at);
      at = comma + 1;
    }
    if (cell[0] != "torso") continue;
    const std::string name = line.substr(at);
    const std::size_t which = std::size_t(std::find(names.begin(), names.end(), name) - names.begin());
    if (which == names.size()) {
      names.push_back(name);
      series.emplace_back();
    }
    series[which].emplace_back(std::stod(cell[2]), std::stod(cell[3]));
  }
  if (names.empty()) {
    std::cerr << "08_torso: warning: no torso rows in " << path << "; peers-torso-frames.png skipped\n";
    return false;
  }
  std::size_t frames = series[0].size();
  double least = 1, most = 1;
  for (const auto& s : series) {
    frames = std::min(frames, s.size());
    for (const auto& [t, ratio] : s)
      if (ratio > 0) least = std::min(least, ratio), most = std::max(most, ratio);
  }
  const std::string folder = out + "/data", name = "peers-torso-frames";
  std::filesystem::create_directories(folder);
  std::ofstream csv(folder + "/" + name + ".csv");
  csv << "# written by 08_torso from " << std::filesystem::path(path).filename().string()
      << " (gjkx_peers_table --frames): the torso scene, each frame's wall time over its simulated time, at the "
         "frame's start and end (a step per frame); the columns: time";
  for (const std::string& n : names) csv << ", " << n;
  csv << '\n';
  for (std::size_t k = 0; k < frames; ++k) {
    std::string row;
    for (const auto& s : series) row += chapter::format(",%.6g", s[k].second);
    csv << (k == 0 ? 0.0 : series[0][k - 1].first) << row << '\n' << series[0][k].first << row << '\n';
  }
  csv.close();
  const std::string figure = name + "." + chapter::figureFormat();
  std::ostringstream set;
  set << "data=" << gnuplotString(name + ".csv") << "; out=" << gnuplotString("../" + figure)
      << "; format=" << gnuplotString(chapter::figureFormat()) << "; count=" << names.size();
  for (std::size_t i = 0; i < names.size(); ++i) set << "; name" << i + 1 << "=" << gnuplotString(names[i]);
  // The log axis: whole decades around every frame and real time.
  set << "; xmax=" << series[0][frames - 1].first << "; bottom=" << std::pow(10.0, std::floor(std::log10(least)))
      << "; top=" << std::pow(10.0, std::ceil(std::log10(most)));
  return gnuplotFigure(out, folder, name, figure, set.str(), GJKX_PEERS_FRAMES_GP);
}

}  // namespace torso
