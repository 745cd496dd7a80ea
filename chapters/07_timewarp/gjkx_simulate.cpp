// gjkx_simulate: runs a scene file (gjkx/timewarp/scene.hpp) and writes what happened.
//
//   gjkx_simulate SCENE.json --out DIR
//
// writes DIR/frames.csv (per frame: frame, time, wall seconds, collision checks,
// collisions, rollbacks, Brent iterations, photo finishes, deepest penetration, then the
// other counters, the wall time by part and the queries that ran Brent), DIR/bodies.csv (per frame and body: name,
// position, orientation [w x y z], velocity, angular velocity, kinetic energy), shows a
// progress bar on a terminal, and ends with one line a script can read:
//
//   SUMMARY frames=N sim_s=... wall_s=... collisions=N rollbacks=N brent_mean=...
//           brent_max=N photo_finish=... max_penetration=... tunnelled=N
//
// which is also written to DIR/summary.txt, followed by a line saying how the run was made
// (RUN scene=... bodies=N scalar=... solver=... variant=... ordering=... tolerance=... frame_rate=...
// checks=on|off ... impulse_tolerance=... sticking_tolerance=..., then tuning.NAME=VALUE for
// each --tuning), so that a kept run says
// what it is, and by a WORK line of counts that do not depend on the machine's load (and the
// process's peak resident memory, at its end).
//
// With --checks, the independent checks (gjkx/verify) measure every frame: the SUMMARY's
// max_penetration and tunnelled, and each finding (a pair deeper than one tolerance, or a
// pair that went through each other unreported) on standard error and in DIR/checks.csv
// (frame,time,kind,body,other,depth). Without them (the default) both are -1 and the
// SUMMARY line ends with "(not checked)".
//
// A scene with bad input is rejected before the run (exit status 1, the message names the
// body and the field); a bad command line exits 2.
#include "../command_line.hpp"

#include <gjkx/timewarp/scene.hpp>
#include <gjkx/timewarp/world.hpp>

#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>

namespace {

/// The process's peak resident memory so far, in megabytes (getrusage's ru_maxrss, which
/// Linux gives in kilobytes): the scene's meshes, their hierarchies and the run together.
double peakMemoryMb() {
  rusage usage{};
  if (getrusage(RUSAGE_SELF, &usage) != 0) return -1;
  return double(usage.ru_maxrss) / 1024.0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Runs a gjkx scene file: bodies in free flight, collisions found by the paper's solver and "
               "ordered by Timewarp (or the scene's ordering), written as CSV.",
               "gjkx_simulate"};
  std::string scenePath, out = ".", ordering, contact, scalar, variant = "certified", solver = "gjkx", logPath, meshCache;
  double tolerance = 0, duration = 0, frameRate = 0, decomposeBudget = 0;
  bool checks = false, noChecks = false, quiet = false, coldStarts = false, noFronts = false, noCoherence = false;
  gjkx::ImpulseSettings impulse;
  std::vector<std::string> tunings;
  app.add_option("scene", scenePath, "the scene file (JSON)")->required();
  app.footer("Every key of the scene file, every option and every column of the outputs: docs/07_timewarp.md in "
             "the source tree (the Doxygen page '07 Timewarp': cmake --build build --target docs).");
  app.add_option("--out", out, "folder for frames.csv and bodies.csv (created)")->capture_default_str();
  const auto positiveNumber = CLI::Validator(
      [](const std::string& text) {
        double value = 0;
        const bool parsed = CLI::detail::lexical_cast(text, value);
        return parsed && std::isfinite(value) && value > 0 ? std::string() : "must be positive and finite, got " + text;
      },
      "POSITIVE");
  app.add_option("--duration", duration, "override the scene's duration (s)")->check(positiveNumber);
  app.add_option("--frame-rate", frameRate, "override the scene's frames per second")->check(positiveNumber);
  app.add_option("--log", logPath,
                 "write every collision to this CSV file: time, the two bodies and their pieces, the closing "
                 "normal speed, the impulse's size, microcollision or not");
  app.add_option("--mesh-cache", meshCache,
                 "folder of the mesh decomposition cache (default: $GJKX_MESH_CACHE, else $XDG_CACHE_HOME/gjkx, "
                 "else ~/.cache/gjkx; an empty string: no cache)");
  app.add_option("--contact", contact,
                 "override the scene's model of resting contact: the paper's microcollisions, or the hybrid "
                 "(collisions as events, resting contacts by a contact solver; the default of a scene without the key)")
      ->check(CLI::IsMember({"microcollisions", "hybrid"}));
  app.add_option("--decompose-budget", decomposeBudget,
                 "seconds each mesh's convex decomposition may take before the mesh's convex hull is used instead "
                 "(over the scene's decomposition.budget_s; default: the scene's, else 30)")
      ->check(positiveNumber);
  app.add_option("--ordering", ordering, "override the scene's ordering")
      ->check(CLI::IsMember({"timewarp", "toi_heap", "fixed_step"}));
  app.add_option("--scalar", scalar, "override the scene's scalar type")->check(CLI::IsMember({"float", "double"}));
  app.add_option("--solver", solver,
                 "the time-of-impact solver: §5 exactly as the paper wrote it (paper: the paper's extrusion test, no "
                 "refinement, no warm start) or this project's (gjkx: its refinements, --variant's test); default: "
                 "the scene's \"solver\", else gjkx")
      ->check(CLI::IsMember({"paper", "gjkx"}));
  app.add_option("--variant", variant, "the extrusion test of the gjkx solver: the paper's or the certified one")
      ->check(CLI::IsMember({"paper", "certified"}))
      ->capture_default_str();
  app.add_option("--tolerance", tolerance, "override the scene's collision tolerance (length units)")
      ->check(positiveNumber);
  app.add_flag("--checks", checks,
               "run the independent checks at each frame's end (penetration, tunnelling, by the reference library): "
               "what they find goes to standard error and DIR/checks.csv; they cost more than the method on the torso");
  app.add_flag("--no-checks", noChecks, "no independent checks (the default): reported as -1, the SUMMARY says (not checked)");
  app.add_flag("--cold-starts", coldStarts,
               "run every complete extrusion test of a time-of-impact query cold (no warm start from the last, nor from the pair's last query)");
  app.add_flag("--no-coherence", noCoherence,
               "start each piece pair's time-of-impact query cold, not where the pair's last query ended");
  app.add_flag("--no-front-tracking", noFronts,
               "traverse the 14-DOP hierarchies afresh at every query (no front kept between frames)");
  app.add_option("--impulse-tolerance", impulse.absoluteTolerance,
                 "absolute and relative tolerance of the impulse integration (gjkx::ImpulseSettings)")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  app.add_option("--sticking-tolerance", impulse.stickingTolerance,
                 "tangential speed counted as zero in the impulse integration, a fraction of the approach speed")
      ->check(CLI::Range(1e-300, 0.999999))
      ->capture_default_str();
  app.add_option("--tuning", tunings,
                 "set a constant of the step, NAME=VALUE (repeatable): NAME a field of gjkx::StepTuning, e.g. "
                 "contactSettled=0.25; the run's RUN line lists them (every name and why its default is what it is: "
                 "lib/timewarp/include/gjkx/timewarp/settings.hpp)")
      ->type_name("NAME=VALUE");
  app.add_flag("--quiet", quiet, "no progress bar");
  chapter::parseOrExit(app, argc, argv);

  gjkx::Scene scene;
  std::unique_ptr<gjkx::World> world;
  try {
    scene = gjkx::loadScene(scenePath);
    // The solver: the scene's (its key "solver"), unless --solver overrides it.
    if (app.count("--solver")) scene.run.solver = solver == "paper" ? gjkx::ToiSolverMode::Paper : gjkx::ToiSolverMode::Gjkx;
    solver = gjkx::toString(scene.run.solver);
    if (solver == "paper") {
      if (app.count("--variant") && variant != "paper") {
        std::cerr << "gjkx_simulate: --solver paper runs the paper's extrusion test (as does a scene's \"solver\": "
                     "\"paper\"); --variant "
                  << variant << " needs --solver gjkx\n";
        return 2;
      }
      variant = "paper";
    }
    if (ordering == "timewarp") scene.run.ordering = gjkx::Ordering::Timewarp;
    if (ordering == "toi_heap") scene.run.ordering = gjkx::Ordering::ToiHeap;
    if (ordering == "fixed_step") scene.run.ordering = gjkx::Ordering::FixedStep;
    if (contact == "microcollisions") scene.run.contact = gjkx::ContactModel::Microcollisions;
    if (contact == "hybrid") scene.run.contact = gjkx::ContactModel::Hybrid;
    if (scalar == "float") scene.run.scalar = gjkx::CollisionScalar::Float;
    if (scalar == "double") scene.run.scalar = gjkx::CollisionScalar::Double;
    if (tolerance > 0) scene.collisionTolerance = tolerance;
    if (duration > 0) scene.duration = duration;
    if (frameRate > 0) scene.frameRate = frameRate;
    gjkx::WorldSettings settings;
    settings.variant = variant == "paper" ? gjkx::ExtrusionVariant::Paper : gjkx::ExtrusionVariant::Certified;
    settings.solver = scene.run.solver;
    noChecks = noChecks || !checks;
    settings.checks = !noChecks;
    settings.warmStarts = !coldStarts;
    settings.coherence = !noCoherence;
    settings.frontTracking = !noFronts;
    impulse.relativeTolerance = impulse.absoluteTolerance;
    settings.impulse = impulse;
    if (app.count("--mesh-cache")) settings.meshCache = meshCache;
    for (const std::string& t : tunings) {
      const std::size_t eq = t.find('=');
      if (eq == std::string::npos) {
        std::cerr << "gjkx_simulate: --tuning " << t << ": expected NAME=VALUE\n";
        return 2;
      }
      try {
        gjkx::setTuning(settings.tuning, t.substr(0, eq), t.substr(eq + 1));
      } catch (const std::invalid_argument& e) {
        std::cerr << "gjkx_simulate: --tuning: " << e.what() << "\n";
        return 2;
      }
    }
    settings.decompositionBudget = decomposeBudget;
    if (!quiet && isatty(fileno(stderr)))  // the run's progress bar, while a mesh is decomposed
      settings.decompositionProgress = [](const std::string& mesh, const gjkx::DecompositionProgress& p) {
        chapter::decompositionProgress(mesh, p.phase, p.fraction, p.seconds, p.budgetSeconds);
      };
    world = std::make_unique<gjkx::World>(scene, settings);
  } catch (const std::exception& e) {
    std::cerr << "gjkx_simulate: " << e.what() << "\n";
    return 1;
  }
  std::filesystem::create_directories(out);
  std::ofstream frames(out + "/frames.csv"), bodies(out + "/bodies.csv");
  std::ofstream findings;
  if (!noChecks) {
    findings.open(out + "/checks.csv");
    findings << "frame,time,kind,body,other,depth\n";
  }
  if (!frames || !bodies || (!noChecks && !findings)) {
    std::cerr << "gjkx_simulate: cannot write to " << out << "\n";
    return 1;
  }
  frames << gjkx::frameHeader() << '\n';
  bodies << "frame,time,name,x,y,z,qw,qx,qy,qz,vx,vy,vz,wx,wy,wz,kinetic_energy\n";
  const bool bar = !quiet && isatty(fileno(stderr));
  // The collision log (--log): one row per collision, in the order they were resolved.
  const auto writeLog = [&]() {
    if (logPath.empty()) return true;
    std::ofstream log(logPath);
    log << "time,body,other,piece,other_piece,approach_speed,impulse,microcollision,contact,separation_speed\n";
    for (const gjkx::CollisionRecord& c : world->collisionLog())
      log << c.time << ',' << world->bodies()[std::size_t(c.i)].name << ',' << world->bodies()[std::size_t(c.j)].name
          << ',' << c.pieceI << ',' << c.pieceJ << ',' << c.approachSpeed << ',' << c.impulse << ','
          << (c.microcollision ? 1 : 0) << ',' << (c.contact ? 1 : 0) << ',' << c.separationSpeed << '\n';
    if (!log) std::cerr << "gjkx_simulate: cannot write the collision log " << logPath << "\n";
    return bool(log);
  };
  gjkx::FrameCounters total;  // the whole run's counts
  double wall = 0;
  try {
    while (!world->done()) {
      const gjkx::FrameReport r = world->step();
      wall += r.wallSeconds;
      total += r.counters;
      frames << gjkx::frameRow(r) << '\n';
      for (const gjkx::Finding& f : r.findings) {  // the independent checks' findings, each named
        const std::string& a = world->bodies()[std::size_t(f.i)].name;
        const std::string& b = world->bodies()[std::size_t(f.j)].name;
        findings << f.frame << ',' << f.time << ',' << gjkx::findingName(f.kind) << ',' << a << ',' << b << ','
                 << f.depth << '\n';
        if (bar) std::fprintf(stderr, "\n");
        std::cerr << "gjkx_simulate: frame " << f.frame << ", t = " << f.time << ": '" << a << "' and '" << b << "' "
                  << (f.kind == gjkx::Finding::Kind::Tunnelling ? "went through each other unreported (tunnelled)"
                                                                : "penetrate by")
                  << (f.kind == gjkx::Finding::Kind::Tunnelling ? "" : " " + std::to_string(f.depth) + " m") << "\n";
      }
      if (r.status == gjkx::FrameStatus::EventCap)
        std::cerr << "gjkx_simulate: frame " << r.frame << " reached the event cap; its remaining events were dropped\n";
      for (std::size_t b = 0; b < world->bodies().size(); ++b) {
        const gjkx::BodyState s = world->stateOf(int(b));
        const Eigen::Vector3d x = world->positionOf(int(b));
        const Eigen::Quaterniond q(s.worldFromBody.rotation);
        bodies << r.frame << ',' << r.time << ',' << world->bodies()[b].name << ',' << x.x() << ',' << x.y() << ','
               << x.z() << ',' << q.w() << ',' << q.x() << ',' << q.y() << ',' << q.z() << ',' << s.velocity.x()
               << ',' << s.velocity.y() << ',' << s.velocity.z() << ',' << s.angularVelocity.x() << ','
               << s.angularVelocity.y() << ',' << s.angularVelocity.z() << ','
               << world->bodies()[b].rigid.kineticEnergy(s) << '\n';
      }
      if (bar) chapter::progress(r.frame, world->frameCount(), wall);
    }
  } catch (const std::exception& e) {
    if (bar) std::fprintf(stderr, "\n");
    std::cerr << "gjkx_simulate: stopped at t = " << world->time() << ": " << e.what() << "\n";
    writeLog();  // what happened up to the stop
    return 1;
  }
  if (bar) std::fprintf(stderr, "\n");
  if (!writeLog()) return 1;
  // Brent's iterations per query that needed it (the paper: 2.2 on average, 43 at worst),
  // and the share of those that ended in a photo finish (the paper: 70% false alarms).
  char line[512];
  std::snprintf(line, sizeof line,
                "SUMMARY frames=%d sim_s=%.6g wall_s=%.6g collisions=%ld rollbacks=%ld brent_mean=%.4g brent_max=%d "
                "photo_finish=%.4g max_penetration=%.6g tunnelled=%d",
                world->frameCount(), world->time(), wall, total.collisions, total.rollbacks,
                total.brentQueries > 0 ? double(total.brentIterations) / double(total.brentQueries) : 0.0,
                int(total.brentMax),
                total.brentQueries > 0 ? double(total.photoFinishes) / double(total.brentQueries) : 0.0,
                noChecks ? -1.0 : total.maxPenetration, noChecks ? -1 : int(total.tunnelled));
  if (noChecks) std::snprintf(line + std::strlen(line), sizeof line - std::strlen(line), " (not checked)");
  std::printf("%s\n", line);
  std::ofstream summary(out + "/summary.txt");
  summary << line << "\nRUN scene=" << scenePath << " bodies=" << world->bodies().size()
          << " scalar=" << (scene.run.scalar == gjkx::CollisionScalar::Float ? "float" : "double") << " solver=" << solver << " variant=" << variant
          << " ordering=" << gjkx::orderingName(scene.run.ordering)
          << " contact=" << gjkx::contactModelName(scene.run.contact) << " tolerance=" << scene.collisionTolerance << " frame_rate=" << scene.frameRate
          << " checks=" << (noChecks ? "off" : "on") << " warm_starts=" << (coldStarts || solver == "paper" ? "off" : "on")
          << " coherence=" << (coldStarts || noCoherence || solver == "paper" ? "off" : "on")
          << " front_tracking=" << (noFronts ? "off" : "on") << " impulse_tolerance=" << impulse.absoluteTolerance
          << " sticking_tolerance=" << impulse.stickingTolerance;
  for (const std::string& t : tunings) summary << " tuning." << t;
  summary << "\n";
  // The work done, in counts that do not depend on the machine's load: what a change to the
  // solver or the hierarchy buys shows here even where wall times are noisy.
  summary << "WORK complete_tests=" << total.completeTests << " sd_evaluations=" << total.sdEvaluations
          << " piece_pairs=" << total.piecePairs << " kdop_nodes=" << total.kdopNodes << " settled=" << total.settled
          << " impulse_steps=" << total.impulseSteps << " impulse_caps=" << total.impulseCaps
          << " spin_restarts=" << total.spinRestarts << " event_caps=" << total.eventCaps
          << " peak_memory_mb=" << peakMemoryMb() << "\n";
  return 0;
}
