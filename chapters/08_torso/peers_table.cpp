// gjkx_peers_table: the simulators a user would otherwise pick, side by side with ours on
// the same scene files (docs/08_torso.md, "The peers side by side"): gjkx_simulate under
// the hybrid contact model with the independent checks on, gjkx_bullet_scene,
// gjkx_mujoco_scene and gjkx_ode_scene (those that were built), one run each, measured by
// the same checks (gjkx::FrameVerifier), written as one markdown table.
//
//   gjkx_peers_table NAME=SCENE.json ... [--duration S] [--work DIR] [--bin DIR] [--reuse] --table OUT.md
//                    [--frames OUT.csv]
//
// For each scene and simulator it runs `PROGRAM SCENE --out WORK/NAME-PROGRAM --quiet`
// (gjkx_simulate with `--contact hybrid --checks`; a scene longer than --duration is cut
// to it with each program's --duration), one after the other, its standard output and
// error kept in that folder, and reads the run's frames.csv and bodies.csv (every runner
// writes the columns read). With --reuse, a run whose folder already holds all its frames
// is read without running it again. The columns:
// - wall time per simulated second: the simulator's own wall time (gjkx_simulate's frames
//   less their checks_s; a peer's wall_s, which leaves its checks out);
// - deepest penetration at any frame's end and pairs tunnelled: the SUMMARY's, by the checks;
// - energy drift: the bodies' total mechanical energy (kinetic, from bodies.csv, plus
//   gravity's potential -m g.c of each centre of mass c, the masses our world gives the
//   bodies) at the last frame less at the start, and its largest rise above the start
//   over the frames: a resting pile loses energy where contacts absorb its fall; a rise is
//   energy the simulator made;
// - the slowest frame and the median frame: each frame's own wall time (as above) over the
//   simulated time it covers, the largest (and which frame) and the median. Real time is 1:
//   a run can be fast on the whole and still stall at one frame (a crash).
// With --frames, every run's frames go to a CSV file too, one row each (scene, frame, time
// at its end, its wall time over its simulated time, simulator last: its name may hold a
// comma), which 08_torso draws for the torso (peers-torso-frames.png).
// A program that fails is a row saying so, with its exit status and the last line it wrote
// on standard error (each run's standard error is kept in its folder, stderr.txt). Where
// MuJoCo fails, a second row runs it again with its implicit integrator
// (gjkx_mujoco_scene --integrator implicit), which takes a spin's gyroscopic terms into the
// step. A bad command line exits 2, a scene that cannot be read 1.
#include "../command_line.hpp"
#include "../formatting.hpp"
#include "peer_run.hpp"
#include "run_stats.hpp"

#include <gjkx/timewarp/body.hpp>
#include <gjkx/timewarp/scene.hpp>

#include <sys/wait.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <numeric>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

namespace {

/// One simulator's run of one scene, as the table reports it.
struct Row {
  std::string scene, simulator, command;
  int status = 0;                        ///< the program's exit status
  std::string reason;                    ///< why it failed: the last line it wrote on standard error
  double simulated = 0, wall = 0;        ///< simulated seconds; the simulator's wall seconds
  double penetration = 0;                ///< deepest penetration at a frame's end (m)
  long tunnelled = 0;                    ///< pairs tunnelled
  double energyDrift = 0, energyRise = 0;  ///< J: end less start; largest rise above the start
  double slowest = 0, median = 0;        ///< a frame's wall time over its simulated time: the largest, the median
  int slowestFrame = 0;                  ///< the frame of the largest
  std::vector<std::pair<double, double>> frames;  ///< each frame's end time and its ratio, as in `slowest`
  bool reused = false;                   ///< read from an earlier run in WORK (--reuse), not run now
};

/// The last line of a file (empty if none): a failed program's reason.
std::string lastLine(const std::string& path) {
  std::ifstream in(path);
  std::string line, last;
  while (std::getline(in, line))
    if (!line.empty()) last = line;
  return last;
}

/// `word` as one word of a shell command: as it is when it holds only characters the shell
/// takes literally, else in single quotes (a scene's label may hold a space: "thin plate").
std::string shellWord(const std::string& word) {
  const bool plain = !word.empty() && std::all_of(word.begin(), word.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || std::strchr("_./=:,+-", c) != nullptr;
  });
  if (plain) return word;
  std::string quoted = "'";
  for (char c : word) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return quoted + "'";
}

/// Runs a shell command (its output redirected by the command itself); its exit status in `status`.
void runCommand(const std::string& command, int& status) {
  const int raw = std::system(command.c_str());
  status = raw != -1 && WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
}

/// The columns of frames.csv that every runner writes (gjkx_simulate's and the peers'), and
/// this table reads.
const std::vector<std::string> kFramesColumns = {"frame", "time", "wall_s", "max_penetration", "tunnelled", "checks_s"};

/// Each frame's wall time over the simulated time it covers (frames.csv's `time` is its end;
/// the first starts at 0), `wall[k]` the frame's wall seconds: {largest, its frame number, median}.
std::tuple<double, int, double> frameRatios(const std::vector<double>& frame, const std::vector<double>& time,
                                            const std::vector<double>& wall, std::vector<std::pair<double, double>>& each) {
  std::vector<double> ratios;
  double largest = 0, start = 0;
  int which = 0;
  for (std::size_t k = 0; k < time.size(); ++k) {
    const double ratio = wall[k] / (time[k] - start);
    start = time[k];
    ratios.push_back(ratio);
    each.emplace_back(time[k], ratio);
    if (ratio > largest) {
      largest = ratio;
      which = int(std::lround(frame[k]));
    }
  }
  std::sort(ratios.begin(), ratios.end());
  const std::size_t n = ratios.size();
  const double median = n == 0 ? 0.0 : n % 2 == 1 ? ratios[n / 2] : 0.5 * (ratios[n / 2 - 1] + ratios[n / 2]);
  return {largest, which, median};
}

/// A body's mechanical energy: kinetic plus gravity's potential of its centre of mass.
double potential(const gjkx::WorldBody& body, const Eigen::Vector3d& centre, const Eigen::Vector3d& gravity) {
  return body.rigid.isStatic() ? 0.0 : -body.rigid.massProperties().mass * gravity.dot(centre);
}

/// The energy drift of a run (see the file's head) from its bodies.csv: {end - start, largest rise}.
std::pair<double, double> energyDrift(const peer_run::PeerScene& scene, const std::string& bodiesCsv) {
  std::map<std::string, std::size_t> index;
  double start = 0;
  for (std::size_t b = 0; b < scene.bodies.size(); ++b) {
    index[scene.bodies[b].name] = b;
    const gjkx::BodyState s = scene.bodies[b].path.stateAt(0.0);
    if (!scene.bodies[b].rigid.isStatic())
      start += scene.bodies[b].rigid.kineticEnergy(s) + potential(scene.bodies[b], s.worldFromBody.translation, scene.scene.gravity);
  }
  std::ifstream in(bodiesCsv);
  if (!in) throw std::runtime_error(bodiesCsv + ": cannot read");
  std::string line;
  std::getline(in, line);  // frame,time,name,x,y,z,qw,qx,qy,qz,vx,vy,vz,wx,wy,wz,kinetic_energy
  std::map<int, double> energy;
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    const std::vector<std::string> f = chapter::csvFields(line);
    if (f.size() < 17) throw std::runtime_error(bodiesCsv + ": a row of " + std::to_string(f.size()) + " cells");
    const auto found = index.find(f[2]);
    if (found == index.end()) throw std::runtime_error(bodiesCsv + ": no body '" + f[2] + "' in the scene");
    const gjkx::WorldBody& body = scene.bodies[found->second];
    if (body.rigid.isStatic()) continue;
    const Eigen::Vector3d x(std::stod(f[3]), std::stod(f[4]), std::stod(f[5]));
    const Eigen::Quaterniond q(std::stod(f[6]), std::stod(f[7]), std::stod(f[8]), std::stod(f[9]));
    const Eigen::Vector3d centre = x - q.normalized().toRotationMatrix() * body.frameOrigin;
    energy[std::stoi(f[0])] += std::stod(f[16]) + potential(body, centre, scene.scene.gravity);
  }
  if (energy.empty()) throw std::runtime_error(bodiesCsv + ": no frames");
  double rise = 0;
  for (const auto& frame : energy) rise = std::max(rise, frame.second - start);
  return {energy.rbegin()->second - start, rise};
}

/// The machine's load averages over 1, 5 and 15 minutes (/proc/loadavg), as text ("unknown" without it).
std::string loadAverage() {
  std::ifstream in("/proc/loadavg");
  double one = 0, five = 0, fifteen = 0;
  if (!(in >> one >> five >> fifteen)) return "unknown";
  return chapter::format("%.1f, ", one) + chapter::format("%.1f, ", five) + chapter::format("%.1f", fifteen);
}

/// The table (see the file's head); `load` says how busy the machine was.
std::string table(const std::vector<Row>& rows, double duration, const std::string& command, const std::string& load) {
  using chapter::format;
  std::ostringstream md;
  md << "| scene | simulator | simulated | wall time per simulated second | deepest penetration | pairs tunnelled "
        "| energy drift, end − start (largest rise) | slowest frame over its simulated time | median frame over its "
        "simulated time |\n| --- | --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: |\n";
  for (const Row& r : rows) {
    md << "| " << r.scene << " | " << r.simulator << " | ";
    if (r.status != 0) {
      md << "failed (exit status " << r.status << (r.reason.empty() ? "" : ": " + r.reason) << ") | | | | | | |\n";
      continue;
    }
    md << format("%.3g s", r.simulated) << " | " << format("%.3g s", r.wall / r.simulated) << " | "
       << format("%.3g mm", 1000 * r.penetration) << " | " << r.tunnelled << " | "
       << format("%.4g J", r.energyDrift) << format(" (%.3g J)", r.energyRise) << " | "
       << format("%.3g", r.slowest) << " (frame " << r.slowestFrame << ") | " << format("%.3g", r.median) << " |\n";
  }
  const bool anyReused = std::any_of(rows.begin(), rows.end(), [](const Row& r) { return r.reused; });
  md << "\nOne run each, one after the other, on one core of a shared 2-core machine";
  if (anyReused) md << " (those marked *earlier* were read from runs made before, with `--reuse`; the load is this call's)";
  if (duration > 0) md << format("; scenes longer than %g s cut to it", duration);
  md << " (its load averages over 1, 5 and 15 minutes: " << load
     << "; wall times grow with the load, the other columns do not). Runs:\n\n";
  for (const Row& r : rows) md << "- `" << r.command << "`" << (r.reused ? " (*earlier*)" : "") << "\n";
  md << "\nMade by `" << command << "`.\n";
  return md.str();
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Runs gjkx (hybrid contact), Bullet, MuJoCo and ODE on the same scene files and writes one table of "
               "wall time (in all, and its slowest and median frame), penetration, tunnelling and energy drift by the same "
               "independent checks.",
               "gjkx_peers_table"};
  std::vector<std::string> scenes;
  std::string work = "peers-runs", bin, tableOut;
  double duration = 0;
  app.add_option("scenes", scenes, "NAME=SCENE.json, one per scene (a row per simulator)")->required();
  app.add_option("--duration", duration, "cut every scene longer than this (s)")->check(CLI::PositiveNumber);
  app.add_option("--work", work, "folder for the runs (one folder each)")->capture_default_str();
  app.add_option("--bin", bin, "folder of the programs (default: this program's)");
  app.add_option("--table", tableOut, "the markdown table to write")->required();
  std::string framesOut;
  app.add_option("--frames", framesOut, "also write every run's frames (wall time over simulated time) to this CSV file");
  bool reuse = false;
  app.add_flag("--reuse", reuse, "read a run already complete in WORK (all its frames) instead of running it again");
  chapter::parseOrExit(app, argc, argv);
  if (bin.empty()) bin = std::filesystem::canonical("/proc/self/exe").parent_path().string();

  std::string command = "gjkx_peers_table";
  for (int k = 1; k < argc; ++k) {
    const std::string a = argv[k];
    command += " " + (a.find(' ') == std::string::npos ? a : "\"" + a + "\"");
  }
  // The simulators, each where it was built: the program, its extra options, its name, and
  // the name of the run's folder. A run with `after` set is a second try, made only when
  // the run of that name failed on the scene: MuJoCo with its implicit integrator, which
  // takes a spin's gyroscopic terms into the step, where its default blew up (mujoco_scene.cpp).
  struct Simulator {
    std::string program, options, name, folder, after;
  };
  std::vector<Simulator> simulators = {
      {"gjkx_simulate", " --contact hybrid --checks", "gjkx (hybrid)", "gjkx_simulate", ""},
      {"gjkx_bullet_scene", "", "Bullet", "gjkx_bullet_scene", ""},
      {"gjkx_mujoco_scene", "", "MuJoCo", "gjkx_mujoco_scene", ""},
      {"gjkx_mujoco_scene", " --integrator implicit", "MuJoCo, implicit integrator", "gjkx_mujoco_scene-implicit",
       "MuJoCo"},
      {"gjkx_ode_scene", "", "ODE", "gjkx_ode_scene", ""}};
  const std::string loadBefore = loadAverage();
  std::vector<Row> rows;
  for (const std::string& item : scenes) {
    const auto eq = item.find('=');
    if (eq == std::string::npos || eq == 0) {
      std::cerr << "gjkx_peers_table: scenes: '" << item << "' is not NAME=SCENE.json\n";
      return 2;
    }
    const std::string name = item.substr(0, eq), path = item.substr(eq + 1);
    peer_run::PeerScene scene;  // for the bodies' masses (and the checks, unused here)
    bool cut = false;
    try {
      cut = duration > 0 && gjkx::loadScene(path).duration > duration;
      scene = peer_run::loadPeerScene(path, cut ? duration : 0);
    } catch (const std::exception& e) {
      std::cerr << "gjkx_peers_table: " << name << ": " << e.what() << "\n";
      return 1;
    }
    for (const Simulator& sim : simulators) {
      const std::string program = bin + "/" + sim.program;
      if (!std::filesystem::exists(program)) continue;
      if (!sim.after.empty()) {
        const auto first = std::find_if(rows.begin(), rows.end(),
                                        [&](const Row& r) { return r.scene == name && r.simulator == sim.after; });
        if (first == rows.end() || first->status == 0) continue;
      }
      const std::string out = work + "/" + name + "-" + sim.folder;
      Row row;
      row.scene = name;
      row.simulator = sim.name;
      row.command = sim.program + " " + shellWord(path) + sim.options +
                    (cut ? chapter::format(" --duration %g", duration) : "") + " --out " + shellWord(out) + " --quiet";
      const std::string frames = out + "/frames.csv";
      bool done = false;  // --reuse: a complete run is already there
      if (reuse && std::filesystem::exists(frames)) {
        try {
          done = int(torso::readRun(out, kFramesColumns).frames()) == scene.frames;
        } catch (const std::exception&) {
          done = false;
        }
      }
      row.reused = done;
      if (!done) {
        std::cerr << "gjkx_peers_table: " << row.command << "\n";
        std::filesystem::remove_all(out);
        std::filesystem::create_directories(out);
        runCommand(shellWord(bin) + "/" + row.command + " > " + shellWord(out + "/stdout.txt") + " 2> " +
                       shellWord(out + "/stderr.txt"),
                   row.status);
        if (row.status != 0) row.reason = lastLine(out + "/stderr.txt");
      }
      if (row.status == 0) {
        try {
          const torso::Run run = torso::readRun(out, kFramesColumns);
          if (int(run.frames()) != scene.frames)
            throw std::runtime_error(frames + ": " + std::to_string(run.frames()) + " frames of " +
                                     std::to_string(scene.frames));
          const auto sum = [&](const char* name) {
            const std::vector<double>& values = run.at(name);
            return std::accumulate(values.begin(), values.end(), 0.0);
          };
          row.simulated = run.at("time").back();
          // gjkx_simulate's wall_s holds its checks; a peer's leaves them out.
          std::vector<double> frameWall = run.at("wall_s");
          if (sim.program == "gjkx_simulate")
            for (std::size_t k = 0; k < frameWall.size(); ++k) frameWall[k] -= run.at("checks_s")[k];
          row.wall = std::accumulate(frameWall.begin(), frameWall.end(), 0.0);
          std::tie(row.slowest, row.slowestFrame, row.median) = frameRatios(run.at("frame"), run.at("time"), frameWall, row.frames);
          const std::vector<double>& depth = run.at("max_penetration");
          row.penetration = std::max(0.0, *std::max_element(depth.begin(), depth.end()));
          row.tunnelled = std::lround(sum("tunnelled"));
          std::tie(row.energyDrift, row.energyRise) = energyDrift(scene, out + "/bodies.csv");
        } catch (const std::exception& e) {
          std::cerr << "gjkx_peers_table: " << row.command << ": " << e.what() << "\n";
          row.status = -1;
          row.reason = e.what();
        }
      }
      rows.push_back(row);
    }
  }
  if (!framesOut.empty()) {
    std::ofstream csv(framesOut);
    csv << "scene,frame,time,frame_over_real_time,simulator\n";
    for (const Row& r : rows)
      for (std::size_t k = 0; k < r.frames.size(); ++k)
        csv << r.scene << ',' << k + 1 << ',' << chapter::format("%.6g", r.frames[k].first) << ','
            << chapter::format("%.6g", r.frames[k].second) << ',' << r.simulator << '\n';
    if (!csv) {
      std::cerr << "gjkx_peers_table: cannot write " << framesOut << "\n";
      return 1;
    }
  }
  std::ofstream file(tableOut);
  if (!(file << table(rows, duration, command, "before the runs " + loadBefore + ", after them " + loadAverage()))) {
    std::cerr << "gjkx_peers_table: cannot write " << tableOut << "\n";
    return 1;
  }
  return 0;
}
