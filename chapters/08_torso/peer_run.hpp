// What the runners of a scene file in another simulator share (gjkx_bullet_scene,
// gjkx_mujoco_scene, gjkx_ode_scene; docs/08_torso.md, "The peers side by side"): the scene
// and its bodies as our world builds them, the same independent checks as gjkx_simulate
// --checks (gjkx::FrameVerifier) after every frame, the CSV files and the SUMMARY line.
// Each runner only builds its world and steps it; this header measures it.
//
// The checks take a body's path over the frame. Between frames our world moves a body on
// a free-flight path: a parabola under gravity for its centre of mass and a rotation
// turning at a constant rate along the shortest arc (gjkx::FreeFlightPath). A peer gives
// only the poses at the frame's ends, and a free-flight path is fitted to them: the same
// rotation, and the one parabola under the scene's gravity that joins the two centres
// (velocity (p1 - p0)/dt - g dt/2 at the start). For a body in free flight this is the path
// it flew; for one that collided within the frame the pair is exempt anyway, as in our run.
// Like ours, the fit cannot represent a body turning half a turn or more within a frame.
#pragma once

#include "../command_line.hpp"

#include <gjkx/timewarp/body.hpp>
#include <gjkx/timewarp/scene.hpp>
#include <gjkx/verify/frame_verifier.hpp>

#include <Eigen/Eigenvalues>

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <memory>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace peer_run {

/// The body pairs (i < j, indices of the scene's bodies) a peer had in contact.
using ContactPairs = std::set<std::pair<int, int>>;

/// Adds the pair of bodies a and b to `pairs` (in order; nothing for a body with itself or
/// for an index below 0, a peer's ground or world body).
inline void addPair(ContactPairs& pairs, int a, int b) {
  if (a >= 0 && b >= 0 && a != b) pairs.insert({std::min(a, b), std::max(a, b)});
}

/// The free-flight path that joins two poses over [t0, t1] (see the file's head).
inline gjkx::Motion<double> fittedPath(const gjkx::Pose<double>& from, const gjkx::Pose<double>& to,
                                       const Eigen::Vector3d& gravity, double t0, double t1) {
  const double dt = t1 - t0;
  const Eigen::Vector3d velocity = (to.translation - from.translation) / dt - 0.5 * gravity * dt;
  return gjkx::Motion<double>::freeFlight(from, velocity, gravity, to.rotation, t0, t1);
}

/// A body's path over the frame as the checks take it: the fitted free-flight path, its
/// centre's velocity at both ends (a parabola's: v0 and v0 + g dt) and the slerp's constant
/// turning rate as its spin at both ends.
inline gjkx::PathPiece checkedPath(const gjkx::Motion<double>& motion, const gjkx::Pose<double>& from,
                                   const gjkx::Pose<double>& to, double t0, double t1) {
  gjkx::FreeFlight path;
  path.t0 = t0;
  path.t1 = t1;
  path.motion = motion;
  path.start.worldFromBody = from;
  path.end.worldFromBody = to;
  if (const auto* f = std::get_if<gjkx::FreeFlightPath<double>>(&motion.variant())) {
    path.start.velocity = f->velocity;
    path.end.velocity = f->velocity + f->acceleration * (t1 - t0);
    const double spin = motion.bound().angularSpeed;
    path.start.angularVelocity = path.end.angularVelocity = Eigen::Vector3d(spin, 0, 0);
  }
  return {path, t1};
}

/// Our inertia in a peer's terms: a peer (Bullet, MuJoCo, ODE) takes a diagonal inertia in
/// the body's own axes. Our body frame is at the centre of mass but along the shape's axes,
/// where a polytope or a mesh has products of inertia; their principal axes (the
/// eigenvectors, turned to a right-handed frame) become the peer's body axes: the rotation
/// bodyFromPrincipal and the principal moments. A diagonal inertia keeps our axes.
inline std::pair<Eigen::Matrix3d, Eigen::Vector3d> principalAxes(const Eigen::Matrix3d& inertia) {
  const Eigen::Matrix3d off = inertia - Eigen::Matrix3d(inertia.diagonal().asDiagonal());
  if (off.cwiseAbs().maxCoeff() <= 1e-12 * inertia.trace()) return {Eigen::Matrix3d::Identity(), inertia.diagonal()};
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(inertia);
  Eigen::Matrix3d axes = solver.eigenvectors();
  if (axes.determinant() < 0) axes.col(2) = -axes.col(2);
  return {axes, solver.eigenvalues()};
}

/// The vertices of a convex piece (a polytope), in the peer's body frame.
inline std::vector<Eigen::Vector3d> principalVertices(const gjkx::Shape<double>& piece,
                                                      const Eigen::Matrix3d& bodyFromPrincipal) {
  const auto& polytope = std::get<gjkx::Polytope<double>>(piece.variant());
  std::vector<Eigen::Vector3d> out;
  for (int v = 0; v < polytope.vertexCount(); ++v) out.push_back(bodyFromPrincipal.transpose() * polytope.vertex(v));
  return out;
}

/// A scene file as every runner takes it: the scene, its bodies built by gjkx::buildBodies
/// (our mass, inertia, centre of mass and convex pieces), and the checks prepared for them.
struct PeerScene {
  gjkx::Scene scene;                               ///< the parsed scene file
  std::vector<gjkx::WorldBody> bodies;             ///< its bodies as our world builds them
  std::unique_ptr<gjkx::FrameVerifier> verifier;   ///< the independent checks of gjkx_simulate --checks
  int frames = 0;                                  ///< frames of the run
  double frameDt = 0;                              ///< a frame's length (s)
};

/// Reads a scene file and prepares its checks. `duration` > 0 overrides the scene's. The
/// checks get 5% spare on their speed bound, for a peer's float poses. Throws what the
/// parser throws (naming the body and the field).
inline PeerScene loadPeerScene(const std::string& path, double duration = 0) {
  PeerScene out;
  out.scene = gjkx::loadScene(path);
  if (duration > 0) out.scene.duration = duration;
  out.frames = gjkx::frameCount(out.scene);
  out.frameDt = 1.0 / out.scene.frameRate;
  out.bodies = gjkx::buildBodies(out.scene, out.frames * out.frameDt);
  out.verifier = std::make_unique<gjkx::FrameVerifier>(gjkx::verifiedBodies(out.bodies), out.scene.collisionTolerance,
                                                       out.scene.gravity, 1.05);
  return out;
}

/// The command line every runner takes: the scene file, --out, --substeps, --duration, --quiet.
struct CommandLine {
  std::string scenePath;  ///< the scene file
  std::string out = ".";  ///< the folder of the CSV files
  int substeps = 0;       ///< the peer's steps per frame (0: the runner's default)
  double duration = 0;    ///< the scene's duration overridden (0: the scene's)
  bool quiet = false;     ///< no progress bar

  /// Adds the options to `app`; `steps` says the runner's default steps (for --help).
  void addTo(CLI::App& app, const std::string& steps) {
    app.add_option("scene", scenePath, "the scene file (JSON)")->required();
    app.add_option("--out", out, "folder for frames.csv and bodies.csv (created)");
    app.add_option("--substeps", substeps, "the simulator's steps per frame (default: " + steps + ")")
        ->check(CLI::Range(1, 100000));
    app.add_option("--duration", duration, "override the scene's duration (s)")->check(CLI::PositiveNumber);
    app.add_flag("--quiet", quiet, "no progress bar");
  }

  /// Loads the scene (loadPeerScene) into `scene`; false, with the reason on standard
  /// error after `program`'s name, when it cannot.
  bool load(const std::string& program, PeerScene& scene) const {
    try {
      scene = loadPeerScene(scenePath, duration);
      return true;
    } catch (const std::exception& e) {
      std::cerr << program << ": " << e.what() << "\n";
      return false;
    }
  }
};

/// A peer as the measured run drives it.
struct Peer {
  /// Advances the peer over one frame, adding every pair it had a contact for in its steps
  /// (timed: the peer's wall time).
  std::function<void(ContactPairs&)> stepFrame;
  /// Body b's state now, in our body frame (centre of mass, our axes).
  std::function<gjkx::BodyState(std::size_t)> state;
  /// Untimed, after the frame: whether the peer finds bodies i and j touching where they are
  /// now, for a pair it had no contact for in the frame's steps (a peer that detects at the
  /// start of a step answers a contact of the frame's last step only in the next frame).
  std::function<bool(int, int)> touchingAtEnd;
};

/// Runs every frame of `scene` in `peer` and measures it: writes OUT/frames.csv (frame,
/// time, the peer's wall seconds, deepest penetration, kinetic energy, pairs the peer had
/// in contact, pairs that tunnelled, seconds of the checks), OUT/bodies.csv (gjkx_simulate's
/// columns) and OUT/checks.csv (each finding), names each tunnelling on standard error, and
/// prints the SUMMARY line with `stepsPerFrame` steps a frame. Returns the exit status (1
/// with a message naming `program` when a file cannot be written or the checks throw).
inline int measure(const std::string& program, PeerScene& scene, const Peer& peer, int stepsPerFrame,
                   const std::string& out, bool quiet) {
  using Clock = std::chrono::steady_clock;
  const std::vector<gjkx::WorldBody>& bodies = scene.bodies;
  std::filesystem::create_directories(out);
  std::ofstream framesCsv(out + "/frames.csv"), bodiesCsv(out + "/bodies.csv"), checksCsv(out + "/checks.csv");
  if (!framesCsv || !bodiesCsv || !checksCsv) {
    std::cerr << program << ": cannot write to " << out << "\n";
    return 1;
  }
  framesCsv << "frame,time,wall_s,max_penetration,kinetic_energy,contact_pairs,tunnelled,checks_s\n";
  bodiesCsv << "frame,time,name,x,y,z,qw,qx,qy,qz,vx,vy,vz,wx,wy,wz,kinetic_energy\n";
  checksCsv << "frame,time,kind,body,other,depth\n";

  auto kineticEnergy = [&]() {
    double sum = 0;
    for (std::size_t b = 0; b < bodies.size(); ++b) sum += bodies[b].rigid.kineticEnergy(peer.state(b));
    return sum;
  };
  const double kineticStart = kineticEnergy();
  double kineticEnd = kineticStart, kineticMax = kineticStart, maxPenetration = 0, wall = 0;
  long tunnelled = 0;
  std::vector<gjkx::Pose<double>> before(bodies.size());
  for (std::size_t b = 0; b < bodies.size(); ++b) before[b] = peer.state(b).worldFromBody;
  const bool bar = !quiet && isatty(fileno(stderr));
  const int frames = scene.frames;
  ContactPairs contacts;
  try {
    for (int frame = 1; frame <= frames; ++frame) {
      const double T0 = double(frame - 1) * scene.frameDt, T1 = double(frame) * scene.frameDt;
      contacts.clear();
      const auto start = Clock::now();
      peer.stepFrame(contacts);
      const double frameWall = std::chrono::duration<double>(Clock::now() - start).count();
      wall += frameWall;

      // The checks (not timed as the peer's work).
      const auto checksStart = Clock::now();
      std::vector<gjkx::BodyState> states(bodies.size());
      std::vector<std::vector<gjkx::PathPiece>> paths(bodies.size());
      for (std::size_t b = 0; b < bodies.size(); ++b) {
        states[b] = peer.state(b);
        const gjkx::Pose<double>& after = states[b].worldFromBody;
        const gjkx::Motion<double> motion = bodies[b].rigid.isStatic()
                                                ? gjkx::Motion<double>::fixed(after)
                                                : fittedPath(before[b], after, scene.scene.gravity, T0, T1);
        paths[b].push_back(checkedPath(motion, before[b], after, T0, T1));
        before[b] = after;
      }
      const gjkx::FrameVerdict verdict = scene.verifier->check(frame, T0, T1, paths, [&](int i, int j) {
        return contacts.count({i, j}) > 0 || peer.touchingAtEnd(i, j);
      });
      for (const gjkx::Finding& f : verdict.findings) {
        const std::string& a = bodies[std::size_t(f.i)].name;
        const std::string& b = bodies[std::size_t(f.j)].name;
        checksCsv << f.frame << ',' << f.time << ',' << gjkx::findingName(f.kind) << ',' << a << ',' << b << ','
                  << f.depth << '\n';
        if (f.kind == gjkx::Finding::Kind::Tunnelling)
          std::cerr << program << ": frame " << f.frame << ", t = " << f.time << ": '" << a << "' and '" << b
                    << "' interpenetrated with no contact\n";
      }
      const double checks = std::chrono::duration<double>(Clock::now() - checksStart).count();
      maxPenetration = std::max(maxPenetration, verdict.maxPenetration);
      tunnelled += verdict.tunnelled;
      kineticEnd = 0;
      for (std::size_t b = 0; b < bodies.size(); ++b) kineticEnd += bodies[b].rigid.kineticEnergy(states[b]);
      kineticMax = std::max(kineticMax, kineticEnd);
      framesCsv << frame << ',' << T1 << ',' << frameWall << ',' << verdict.maxPenetration << ',' << kineticEnd << ','
                << contacts.size() << ',' << verdict.tunnelled << ',' << checks << '\n';
      for (std::size_t b = 0; b < bodies.size(); ++b) {
        const gjkx::BodyState& s = states[b];
        const Eigen::Vector3d x = s.worldFromBody(bodies[b].frameOrigin);  // the scene frame's origin
        const Eigen::Quaterniond q(s.worldFromBody.rotation);
        bodiesCsv << frame << ',' << T1 << ',' << bodies[b].name << ',' << x.x() << ',' << x.y() << ',' << x.z() << ','
                  << q.w() << ',' << q.x() << ',' << q.y() << ',' << q.z() << ',' << s.velocity.x() << ','
                  << s.velocity.y() << ',' << s.velocity.z() << ',' << s.angularVelocity.x() << ','
                  << s.angularVelocity.y() << ',' << s.angularVelocity.z() << ','
                  << bodies[b].rigid.kineticEnergy(s) << '\n';
      }
      if (bar) chapter::progress(frame, frames, wall);
    }
  } catch (const std::exception& e) {
    if (bar) std::fprintf(stderr, "\n");
    std::cerr << program << ": " << e.what() << "\n";
    return 1;
  }
  if (bar) std::fprintf(stderr, "\n");
  std::printf("SUMMARY frames=%d sim_s=%.6g wall_s=%.6g steps=%ld max_penetration=%.6g tunnelled=%ld "
              "kinetic_start=%.6g kinetic_end=%.6g kinetic_max=%.6g\n",
              frames, double(frames) * scene.frameDt, wall, long(frames) * stepsPerFrame, maxPenetration, tunnelled,
              kineticStart, kineticEnd, kineticMax);
  return 0;
}

}  // namespace peer_run
