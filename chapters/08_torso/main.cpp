// Chapter 08: the paper's §6 experiment, "a skeletal model of a human torso separated into
// its individual bones and vertebrae, with 80 nonconvex rigid bodies", dropped "from a
// random position" onto "an aquatic plant fixed in space". Figures:
//   torso-model.png:        the generated torso (front, side, back) and the plant, with
//                           their bone and triangle counts (torso_model.hpp);
//   fig05-torso-crash.png:  Fig. 5, "Skeletal torso in freefall crashing into aquatic
//                           plant": the scene at the start, at the impact, scattered and
//                           settled, read from a kept run of gjkx_simulate on the scene of
//                           gjkx_generate_torso (seed 1), figures/data/torso-run/bodies.csv.
//                           Without that run only the start is drawn, and a warning says so.
//   fig06-torso-running-time.png: Fig. 6, "Running Time for Torso-Plant Simulation": the
//                           execution time of each frame over its simulated time, stacked
//                           by part, against simulated time, drawn by gnuplot from the same
//                           run's frames.csv (the script running_time.gp beside this file,
//                           its data in data/ of the figures folder). Without the run, or
//                           without gnuplot, it is skipped.
//   fig06-torso-running-time-hybrid.png: its companion, on the same axes: the same scene
//                           under the hybrid contact model (the paper's future work), from
//                           the kept run figures/data/torso-run-hybrid/frames.csv
//                           (--hybrid-run DIR); skipped without it.
//   fig06-torso-running-time-paper.png: the reproduction, on the same axes: the same scene
//                           with §5 as the paper wrote it (gjkx_simulate --solver paper), from
//                           the kept run figures/data/torso-run-paper/frames.csv
//                           (--paper-run DIR); skipped without it.
//   peers-torso-frames.png: the torso scene in every simulator of the peers table, frame by
//                           frame: each frame's wall time over its simulated time, a line per
//                           simulator, from figures/data/peers-frames.csv (gjkx_peers_table
//                           --frames; --peers-frames FILE), drawn by gnuplot (peers_frames.gp);
//                           skipped without it.
// Options: --run DIR reads DIR/bodies.csv and DIR/frames.csv instead; --frames DIR writes one
// PNG per frame of the run (an animation); --seed N and --reduced must match how the run's
// scene was made. --stats [LABEL=]RUN... --table OUT.md draws nothing: it writes the table
// of the paper's statistics for the runs (run_stats.hpp).
#include "../chapter.hpp"
#include "close_up.hpp"
#include "run_stats.hpp"
#include "running_time.hpp"
#include "torso_model.hpp"

#include <gjkx/render/canvas.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <map>
#include <optional>
#include <sstream>

using namespace gjkx::render;
using torso::V3;

#ifndef GJKX_TORSO_RUN
#define GJKX_TORSO_RUN "figures/data/torso-run"
#endif
#ifndef GJKX_TORSO_RUN_HYBRID  // the same scene under the hybrid contact model (Fig. 6's companion)
#define GJKX_TORSO_RUN_HYBRID "figures/data/torso-run-hybrid"
#endif
#ifndef GJKX_TORSO_RUN_PAPER  // the same scene with §5 as the paper wrote it (Fig. 6 reproduced)
#define GJKX_TORSO_RUN_PAPER "figures/data/torso-run-paper"
#endif
#ifndef GJKX_PEERS_FRAMES  // every peer's frames on the peers table's scenes (gjkx_peers_table --frames)
#define GJKX_PEERS_FRAMES "figures/data/peers-frames.csv"
#endif

namespace {

const Color boneColor = Color::hex(0xE6D9B8);
const Color plantColor = Color::hex(0x5E9E3A);
const Color floorColor = Color::hex(0xE8E8E8);

/// The poses of every bone at one frame of a run.
struct Frame {
  int frame = 0;                                ///< 1, 2, ... (0: the start)
  double time = 0;                              ///< simulated seconds
  std::vector<V3> position;                     ///< per bone of the layout
  std::vector<Eigen::Quaterniond> orientation;  ///< per bone of the layout
  std::vector<V3> velocity;                     ///< per bone of the layout
};

/// The start of the run: the bones as the scene places them, at rest.
Frame startFrame(const torso::SceneLayout& layout) {
  Frame f;
  for (const auto& b : layout.bones) {
    f.position.push_back(b.position);
    f.orientation.push_back(b.orientation);
    f.velocity.push_back(V3::Zero());
  }
  return f;
}

/// The frames of gjkx_simulate's bodies.csv (frame,time,name,x,y,z,qw,qx,qy,qz,vx,vy,vz,...)
/// for the bones of `layout`; a row of another body (the floor, the plant) is skipped.
/// Throws std::runtime_error naming the file and line for a malformed row or a bone missing.
std::vector<Frame> readRun(const std::string& path, const torso::SceneLayout& layout) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error(path + ": cannot read the run");
  std::map<std::string, int> index;
  for (std::size_t b = 0; b < layout.bones.size(); ++b) index[layout.bones[b].name] = int(b);
  std::string line;
  std::getline(in, line);
  if (line.rfind("frame,time,name,x,y,z,qw,qx,qy,qz,vx,vy,vz", 0) != 0)
    throw std::runtime_error(path + ": not a bodies.csv of gjkx_simulate (header " + line + ")");
  std::vector<Frame> frames;
  std::vector<int> seen;
  for (int row = 2; std::getline(in, line); ++row) {
    const std::vector<std::string> cell = chapter::csvFields(line);
    if (cell.size() < 13) throw std::runtime_error(path + ":" + std::to_string(row) + ": fewer than 13 columns");
    const int frame = std::stoi(cell[0]);
    if (frames.empty() || frames.back().frame != frame) {
      if (!frames.empty() && seen.back() != int(layout.bones.size()))
        throw std::runtime_error(path + ": frame " + std::to_string(frames.back().frame) + " lacks some bones");
      frames.push_back(startFrame(layout));
      frames.back().frame = frame;
      frames.back().time = std::stod(cell[1]);
      seen.push_back(0);
    }
    const auto found = index.find(cell[2]);
    if (found == index.end()) continue;
    double x[10];
    for (int k = 0; k < 10; ++k) x[k] = std::stod(cell[std::size_t(3 + k)]);
    Frame& f = frames.back();
    f.position[std::size_t(found->second)] = V3(x[0], x[1], x[2]);
    f.orientation[std::size_t(found->second)] = Eigen::Quaterniond(x[3], x[4], x[5], x[6]).normalized();
    f.velocity[std::size_t(found->second)] = V3(x[7], x[8], x[9]);
    ++seen.back();
  }
  if (frames.empty()) throw std::runtime_error(path + ": no frames");
  if (seen.back() != int(layout.bones.size())) throw std::runtime_error(path + ": the last frame lacks some bones");
  return frames;
}

/// The first frame where some bone no longer falls freely: its velocity differs from
/// g t by more than 5 cm/s (every bone starts at rest).
std::size_t impactFrame(const std::vector<Frame>& frames) {
  for (std::size_t i = 0; i < frames.size(); ++i)
    for (const V3& v : frames[i].velocity)
      if ((v - V3(0, 0, -9.81 * frames[i].time)).norm() > 0.05) return i;
  return frames.size() - 1;
}

Mesh placed(const gjkx::TriangleMesh& m, const V3& position, const Eigen::Quaterniond& orientation) {
  Mesh out{{}, m.triangles};
  for (const V3& v : m.vertices) out.vertices.push_back(orientation * v + position);
  return out;
}

/// The box holding the plant, the floor's middle and the bones at every one of `frames`:
/// one framing for all panels, so that they share a scale. A bone that slid off the
/// floor and fell (below its top) is left out of the framing: it falls for ever.
std::pair<V3, V3> bounds(const torso::SceneLayout& layout, const std::vector<Frame>& frames) {
  V3 lo(-0.35, -0.35, 0), hi(0.35, 0.35, layout.drop.plantTop);
  for (const Frame& f : frames)
    for (std::size_t b = 0; b < layout.bones.size(); ++b)
      for (const V3& v : layout.bones[b].mesh.vertices) {
        const V3 p = f.orientation[b] * v + f.position[b];
        if (p.z() < -0.05) continue;
        lo = lo.cwiseMin(p);
        hi = hi.cwiseMax(p);
      }
  return {lo, hi};
}

/// Draws the scene at one frame in the current panel, the camera framing the box `box`.
void drawScene(Canvas& canvas, const torso::SceneLayout& layout, const Frame& f, const std::pair<V3, V3>& box) {
  const auto& [lo, hi] = box;
  canvas.setCamera(Camera::orbit(0.5 * (lo + hi), 0.5 * (hi - lo).norm(), -0.9, 0.3, 0.6, canvas.plotAspect()));
  const double r = torso::floorHalfWidth;  // the floor as the scene has it
  canvas.polygon3({V3(-r, -r, 0), V3(r, -r, 0), V3(r, r, 0), V3(-r, r, 0)}, ShapeStyle{floorColor, style::noStroke});
  canvas.mesh(placed(layout.plant, V3::Zero(), Eigen::Quaterniond::Identity()),
              MeshStyle{plantColor, Stroke{palette::ink, 0.5}, false, true});
  for (std::size_t b = 0; b < layout.bones.size(); ++b)
    canvas.mesh(placed(layout.bones[b].mesh, f.position[b], f.orientation[b]),
                MeshStyle{boneColor, Stroke{palette::ink, 0.5}, false, true});
}

void modelFigure(const std::string& out) {
  const std::vector<torso::Bone> bones = torso::buildTorso();
  const gjkx::TriangleMesh plant = torso::buildPlant(12);
  long triangles = 0;
  for (const auto& b : bones) triangles += long(b.mesh.triangles.size());
  const int W = 420, H = 560;
  Canvas canvas(4 * W, H);
  const char* views[3] = {"front", "right side", "back"};
  const double azimuths[3] = {M_PI / 2, 0.0, -M_PI / 2};
  for (int view = 0; view < 3; ++view) {
    canvas.setPanel({view * W, 0, W, H});
    char title[120];
    std::snprintf(title, sizeof title, "%s: %zu bones, %ld triangles", views[view], bones.size(), triangles);
    canvas.title(view == 0 ? title : views[view]);
    canvas.setCamera(Camera::orbit(V3(0, 0.03, 0.33), 0.33, azimuths[view], 0.12, 0.6, canvas.plotAspect()));
    for (const auto& b : bones)
      canvas.mesh(placed(b.mesh, V3::Zero(), Eigen::Quaterniond::Identity()),
                  MeshStyle{boneColor, Stroke{palette::ink, 0.5}, false, true});
  }
  canvas.setPanel({3 * W, 0, W, H});
  char title[120];
  std::snprintf(title, sizeof title, "the plant: %zu triangles", plant.triangles.size());
  canvas.title(title);
  canvas.setCamera(Camera::orbit(V3(0, 0, 0.5), 0.62, -0.4, 0.35, 0.6, canvas.plotAspect()));
  canvas.mesh(placed(plant, V3::Zero(), Eigen::Quaterniond::Identity()),
              MeshStyle{plantColor, Stroke{palette::ink, 0.5}, false, true});
  chapter::save(canvas, out, "torso-model");
}

/// The statistics table of the runs `specs` ("LABEL=DIR" or "DIR", labelled by the folder's
/// name) written to `table`.
void statsTable(const std::vector<std::string>& specs, const std::string& table, const std::string& command) {
  std::vector<std::pair<std::string, torso::Run>> runs;
  for (const std::string& spec : specs) {
    const auto eq = spec.find('=');
    const std::string dir = eq == std::string::npos ? spec : spec.substr(eq + 1);
    const std::string label =
        eq == std::string::npos ? std::filesystem::path(dir).lexically_normal().filename().string() : spec.substr(0, eq);
    runs.emplace_back(label, torso::readRun(dir));
  }
  const std::string md = torso::statsTable(runs, command);
  if (table.empty() || table == "-") {
    std::cout << md;
    return;
  }
  if (std::filesystem::path(table).has_parent_path()) std::filesystem::create_directories(std::filesystem::path(table).parent_path());
  std::ofstream file(table);
  if (!(file << md)) throw std::runtime_error(table + ": cannot write the table");
  chapter::wrote(table);
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Draws chapter 08's figures: the generated torso and plant, and Fig. 5 (the torso crashing into "
               "the plant) from a kept run of gjkx_simulate."};
  std::string out = ".", run = GJKX_TORSO_RUN, hybridRun = GJKX_TORSO_RUN_HYBRID, paperRun = GJKX_TORSO_RUN_PAPER,
              framesDir, peersFrames = GJKX_PEERS_FRAMES;
  std::uint32_t seed = 1;
  bool reduced = false;
  std::vector<std::string> statsRuns;
  std::string table;
  chapter::addFigureOptions(app, out);
  app.add_option("--run", run, "the folder of the run (bodies.csv of gjkx_simulate)")->capture_default_str();
  app.add_option("--hybrid-run", hybridRun,
                 "the folder of the same scene's run under the hybrid contact model (frames.csv), drawn beside Fig. 6")
      ->capture_default_str();
  app.add_option("--paper-run", paperRun,
                 "the folder of the same scene's run with §5 as the paper wrote it (frames.csv; gjkx_simulate "
                 "--solver paper), drawn beside Fig. 6 as the reproduction")
      ->capture_default_str();
  app.add_option("--frames", framesDir, "also write one figure per frame of the run into this folder");
  app.add_option("--peers-frames", peersFrames,
                 "the frames of every simulator on the peers table's scenes (gjkx_peers_table --frames), drawn for the torso")
      ->capture_default_str();
  app.add_option("--seed", seed, "the seed the run's scene was generated with (gjkx_generate_torso --seed)")
      ->capture_default_str();
  app.add_flag("--reduced", reduced, "the run is of the reduced scene (gjkx_generate_torso --reduced)");
  app.add_option("--stats", statsRuns,
                 "draw nothing: tabulate the paper's statistics for these runs (folders of gjkx_simulate, each "
                 "LABEL=DIR or DIR), one column each")
      ->type_name("[LABEL=]DIR ...");
  app.add_option("--table", table, "with --stats: the markdown file to write (default: standard output)");
  chapter::parseOrExit(app, argc, argv);
  try {
    if (!statsRuns.empty()) {
      std::string command = "08_torso";
      for (int a = 1; a < argc; ++a) {
        const std::string arg = argv[a];
        command += arg.find(' ') == std::string::npos ? " " + arg : " \"" + arg + "\"";
      }
      statsTable(statsRuns, table, command);
      return 0;
    }
    std::filesystem::create_directories(out);
    modelFigure(out);
    const torso::SceneLayout layout = torso::layoutScene(seed, reduced);
    std::vector<Frame> frames;
    if (std::filesystem::exists(run + "/bodies.csv")) {
      frames = readRun(run + "/bodies.csv", layout);
    } else {
      std::cerr << "08_torso: warning: no kept run at " << run
                << "/bodies.csv; Fig. 5 shows only the start (run gjkx_simulate on gjkx_generate_torso's scene)\n";
    }
    const int W = 420, H = 600;
    if (frames.empty()) {
      Canvas canvas(W, H);
      canvas.title("t = 0 s: dropped (no run kept)");
      drawScene(canvas, layout, startFrame(layout), bounds(layout, {startFrame(layout)}));
      chapter::save(canvas, out, "fig05-torso-crash");
    } else {
      const std::size_t impact = impactFrame(frames);
      std::size_t scattered = impact;
      while (scattered + 1 < frames.size() && frames[scattered].time < frames[impact].time + 0.5) ++scattered;
      const Frame panels[4] = {startFrame(layout), frames[impact], frames[scattered], frames.back()};
      const char* names[4] = {"dropped", "the impact", "scattered", "settled"};
      // Framed on the plant and the falling torso: the crash is what the figure shows, and
      // bones thrown far across the floor would shrink it to a speck.
      const auto box = bounds(layout, {panels[0], panels[1]});
      Canvas canvas(4 * W, H + torso::closeUpHeight);  // the bones close up below (close_up.hpp)
      for (int p = 0; p < 4; ++p) {
        canvas.setPanel({p * W, 0, W, H});
        char title[80];
        std::snprintf(title, sizeof title, "t = %.2f s: %s", panels[p].time, names[p]);
        canvas.title(title);
        drawScene(canvas, layout, panels[p], box);
      }
      torso::closeUpRow(canvas, layout, std::vector<Frame>(panels, panels + 4), std::vector<const char*>(names, names + 4), W, H, drawScene);
      chapter::save(canvas, out, "fig05-torso-crash");
    }
    // Fig. 6 and its companion, the same scene under the hybrid contact model, on the same
    // axes (those that show both runs whole), so that the two compare at a glance.
    std::optional<torso::Run> kept, hybrid, paper;
    if (std::filesystem::exists(run + "/frames.csv"))
      kept = torso::readRun(run);
    else
      std::cerr << "08_torso: warning: no kept run at " << run
                << "/frames.csv; Fig. 6 (fig06-torso-running-time.png) skipped\n";
    if (std::filesystem::exists(hybridRun + "/frames.csv"))
      hybrid = torso::readRun(hybridRun);
    else
      std::cerr << "08_torso: warning: no kept run at " << hybridRun
                << "/frames.csv; fig06-torso-running-time-hybrid.png skipped\n";
    if (std::filesystem::exists(paperRun + "/frames.csv"))
      paper = torso::readRun(paperRun);
    else
      std::cerr << "08_torso: warning: no kept run at " << paperRun
                << "/frames.csv; fig06-torso-running-time-paper.png skipped\n";
    std::vector<const torso::Run*> shown;
    for (const auto* r : {&kept, &hybrid, &paper})
      if (*r) shown.push_back(&**r);
    if (kept) torso::runningTimeFigure(out, *kept, "fig06-torso-running-time", torso::fig6Axes(shown));
    if (hybrid) torso::runningTimeFigure(out, *hybrid, "fig06-torso-running-time-hybrid", torso::fig6Axes(shown));
    if (paper) torso::runningTimeFigure(out, *paper, "fig06-torso-running-time-paper", torso::fig6Axes(shown));
    torso::peersFramesFigure(out, peersFrames);
    if (!framesDir.empty()) {
      if (frames.empty()) throw std::runtime_error("--frames needs a run: " + run + "/bodies.csv is missing");
      std::filesystem::create_directories(framesDir);
      std::vector<Frame> all{startFrame(layout)};
      all.insert(all.end(), frames.begin(), frames.end());
      const auto box = bounds(layout, all);
      for (const Frame& f : frames) {
        Canvas canvas(640, 640);
        char title[40], name[40];
        std::snprintf(title, sizeof title, "t = %.3f s", f.time);
        std::snprintf(name, sizeof name, "/frame-%04d.", f.frame);
        canvas.title(title);
        drawScene(canvas, layout, f, box);
        canvas.save(framesDir + name + chapter::figureFormat());
      }
      std::printf("wrote %zu frames to %s\n", frames.size(), framesDir.c_str());
    }
  } catch (const std::exception& e) {
    std::cerr << "08_torso: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
