// The world's frame loop (world.hpp): the named parts of a step, called in order.
#include <gjkx/timewarp/world.hpp>

#include <gjkx/timewarp/broad_phase.hpp>
#include <gjkx/timewarp/contact_solver.hpp>
#include <gjkx/timewarp/fixed_step.hpp>
#include <gjkx/timewarp/sleep.hpp>
#include <gjkx/timewarp/step.hpp>
#include <gjkx/timewarp/timewarp.hpp>
#include <gjkx/timewarp/toi_heap.hpp>

#include <algorithm>
#include <chrono>
#include <ctime>
#include <cmath>
#include <stdexcept>

namespace gjkx {

namespace {

/// Mirtich's microcollisions: a resting body is a train of tiny bounces. A contact that
/// approaches slower than a body gains falling through the collision tolerance band,
/// sqrt(2 |g| tol), bounces out of it at that speed (to a height of one tolerance), so it
/// neither sinks into the other body nor collides endlessly. Without gravity: none.
double microcollisionSpeed(double gravity, double tolerance) { return std::sqrt(2 * gravity * tolerance); }

/// The settings, checked by name before anything is built (a decomposition can take seconds).
const WorldSettings& validated(const WorldSettings& settings) {
  settings.validate("settings");
  return settings;
}

/// What the world's settings say about meshes to decompose (body.hpp).
MeshBuildOptions meshOptionsOf(const WorldSettings& settings) {
  MeshBuildOptions options;
  options.cache = settings.meshCache.value_or(defaultDecompositionCacheDir());
  options.budgetSeconds = settings.decompositionBudget;
  options.progress = settings.decompositionProgress;
  return options;
}

/// The narrow phase of the scene's scalar: the one place the scalar is tested.
template <typename AnyNarrowPhase>
AnyNarrowPhase narrowPhaseOf(CollisionScalar scalar, const std::vector<WorldBody>& bodies) {
  if (scalar == CollisionScalar::Float) return AnyNarrowPhase(std::in_place_index<0>, bodies);
  return AnyNarrowPhase(std::in_place_index<1>, bodies);
}

}  // namespace

World::World(const Scene& scene, const WorldSettings& settings)
    : scene_(scene),
      settings_(validated(settings)),
      impulse_(settings.impulse),
      bodies_(buildBodies(scene, double(gjkx::frameCount(scene)) / scene.frameRate, meshOptionsOf(settings))),
      narrow_(narrowPhaseOf<AnyNarrowPhase>(scene.run.scalar, bodies_)),
      frameCount_(gjkx::frameCount(scene)) {
  impulse_.microcollisionSpeed = microcollisionSpeed(scene.gravity.norm(), scene.collisionTolerance);
  // The independent checks' own view of every body (gjkx/verify), made once: they measure
  // the start below, and each frame's end when settings.checks is on.
  verifier_ = std::make_unique<FrameVerifier>(verifiedBodies(bodies_), scene.collisionTolerance, scene.gravity);
  // Two bodies overlapping at the start are an error (static ones may meet: walls of a box).
  std::vector<Bounds> boxes;
  for (const WorldBody& body : bodies_) {
    Bounds b;
    b.add(body.path.start.worldFromBody.translation);
    b.inflate(body.radius + scene.collisionTolerance);
    boxes.push_back(b);
  }
  const auto pairs = overlappingPairs(boxes, [&](int i, int j) { return bodies_[i].rigid.isStatic() && bodies_[j].rigid.isStatic(); });
  for (const auto& [i, j] : pairs) {
    // Exact only where they overlap by more than the tolerance (the message says how far):
    // a pair proven no deeper needs no more (a pyramid of boxes placed touching is hundreds).
    const double d = verifier_->signedDistance(i, bodies_[i].path.start.worldFromBody, j,
                                               bodies_[j].path.start.worldFromBody, -scene.collisionTolerance);
    if (d < -scene.collisionTolerance)
      throw std::invalid_argument(scene.source + ": body '" + bodies_[i].name + "' (bodies[" + std::to_string(i) +
                                  "]) and body '" + bodies_[j].name + "' (bodies[" + std::to_string(j) +
                                  "]): field 'position' puts them overlapping at the start (by " +
                                  std::to_string(-d) + ")");
  }
}

World::~World() = default;

Eigen::Vector3d World::positionOf(int body) const {
  const Pose<double> pose = stateOf(body).worldFromBody;
  return pose(bodies_[body].frameOrigin);
}

FrameReport World::step() {
  if (done()) throw std::logic_error("World::step: the scene's duration is already simulated");
  const auto start = std::chrono::steady_clock::now();
  const std::clock_t cpuStart = std::clock();
  const double T0 = double(frame_) / scene_.frameRate, T1 = double(frame_ + 1) / scene_.frameRate;
  const StepTuning& tuning = settings_.tuning;
  // A free-flight path holds less than half a turn (motion.hpp, FreeFlightPath): when a
  // body spins fast (a ball rolling at speed), the frame is run as several intervals,
  // each an eighth of a turn of the fastest body at most.
  // Under Timewarp a body that spins faster takes steps of its own instead (timewarp.hpp),
  // and only some bodies count. Under the hybrid, the group bodies, whose velocities the
  // contact solver sets once an interval (a group body turning fast is solved again sooner;
  // its path is cut into eighths of a turn). Under microcollisions, the bodies that spin at
  // most StepTuning::spinIntervals eighths of a turn a frame: there resting contact is a
  // train of collisions, each checking its bodies' pairs again to the interval's end, and
  // intervals of a few eighths of a turn keep those checks short; a body spinning faster (a
  // cartilage of a gram thrown off the torso's crash at hundreds of radians a second) would
  // cut every body's frame into dozens of intervals, each a broad phase and a check of
  // every pair.
  const bool ownSteps = ownStepsOf(scene_);
  const bool hybrid = scene_.run.contact == ContactModel::Hybrid;
  const double cutsUpTo = tuning.spinIntervals * eighthTurn * scene_.frameRate;
  const auto cutsTheFrame = [&](const WorldBody& body, double spin) {
    if (body.rigid.isStatic()) return false;
    if (!ownSteps) return true;
    return hybrid ? body.contactFlight : spin <= cutsUpTo;
  };
  double fastest = 0;
  for (const WorldBody& body : bodies_) {
    const double spin = body.path.end.angularVelocity.norm();
    if (cutsTheFrame(body, spin)) fastest = std::max(fastest, spin);
  }
  const auto eighthTurns = [&](double speed) { return int(std::ceil(std::min(speed * (T1 - T0) / eighthTurn, 1e6))); };
  // The hybrid solves its contacts at each interval's start: a pair that lands inside one is a
  // collision until the next, so under gravity its frames are cut into
  // StepTuning::contactIntervals at least (fixed steps keep their own: `fixed_substeps` per frame).
  const bool cut = scene_.run.contact == ContactModel::Hybrid && scene_.gravity.squaredNorm() > 0 &&
                   scene_.run.ordering != Ordering::FixedStep;
  const int fewest = cut ? tuning.contactIntervals : 1;
  int intervals = std::clamp(std::max(fewest, eighthTurns(fastest)), 1, tuning.maxIntervals);
  // A collision can spin a light body up past that within an interval (a cartilage of a few
  // grams struck at the crash: 370 rad/s); then the frame is run again from its start in
  // intervals short enough for the new spin, from what the bodies were at T0. The same
  // snapshot leaves the world valid when a numerical failure stops the run.
  std::vector<FreeFlight> paths;
  std::vector<int> versions;
  std::vector<char> asleep;
  std::vector<int> groupsAsleep;
  std::vector<double> lastStruck;
  for (const WorldBody& body : bodies_) {
    paths.push_back(body.path);
    versions.push_back(body.version);
    asleep.push_back(body.asleep);
    groupsAsleep.push_back(body.sleepGroup);
    lastStruck.push_back(body.lastStruck);
  }
  const auto normals = pairNormals_;
  const ContactCache cache = contactCache_;
  const std::size_t traced = trace_.size(), logged = collisionLog_.size();
  const auto restore = [&](int versionBump) {
    for (std::size_t b = 0; b < bodies_.size(); ++b) {
      bodies_[b].setPath(paths[b]);
      bodies_[b].version = versions[b] + versionBump;  // events computed on the abandoned run are stale
      bodies_[b].asleep = asleep[b];
      bodies_[b].sleepGroup = groupsAsleep[b];
      bodies_[b].lastStruck = lastStruck[b];
    }
    pairNormals_ = normals;
    contactCache_ = cache;
    trace_.resize(traced);
    collisionLog_.resize(logged);
  };
  FrameState frame(bodies_.size());
  StepContext step{scene_, settings_, impulse_, bodies_, trace_, collisionLog_, pairNormals_, frame, contactCache_, T1};
  long spinRestarts = 0;
  try {
    for (;;) {
      frame.report.frame = frame_ + 1;
      frame.report.time = T1;
      // The scalar's narrow phase, visited here once for the frame: everything below runs
      // in one scalar type, chosen when the world was built.
      std::visit(
          [&](auto& narrow) {
            for (int k = 0; k < intervals && !step.abandoned(); ++k) {
              const double ta = k == 0 ? T0 : T0 + (T1 - T0) * k / intervals;
              const double tb = k + 1 == intervals ? T1 : T0 + (T1 - T0) * (k + 1) / intervals;
              step.intervalStart = ta;
              step.intervalEnd = tb;
              // The hybrid model: the resting contacts are solved first, their bodies' paths
              // set over the interval; the ordering then finds the collisions.
              if (step.hybrid() && !solveContacts(step, narrow, ta, tb)) break;
              switch (scene_.run.ordering) {
                case Ordering::Timewarp: runTimewarp(step, narrow, ta, tb); break;
                case Ordering::ToiHeap: runToiHeap(step, narrow, ta, tb); break;
                case Ordering::FixedStep: runFixedStep(step, narrow, ta, tb); break;
              }
            }
          },
          narrow_);
      if (!step.abandoned()) break;
      const FrameState::SpinOverflow spin = frame.spinOverflow;
      const int needed = std::max(2 * intervals, eighthTurns(spin.angularSpeed));
      if (needed > tuning.maxSpinIntervals)
        throw std::runtime_error(spin.what + " even in " + std::to_string(intervals) +
                                 " intervals of a frame; raise frame_rate");
      restore(1);
      intervals = needed;
      ++spinRestarts;
      const PartTimes parts = frame.report.parts;  // the abandoned run's wall time still counts
      frame = FrameState(bodies_.size());
      frame.report.parts = parts;
    }
  } catch (...) {
    restore(1);  // the world as it was at the frame's start, for a caller that reads it
    throw;
  }
  frame.report.counters.spinRestarts = spinRestarts;
  frame.report.counters.intervals = intervals;
  // The frame is final: the global virtual time has passed T1, its history is discarded.
  if (step.hybrid()) sleepGroups(step, T1);
  else settle(step, T1);
  if (settings_.checks) {  // the independent checks, attached at the frame's end
    PartTimer timer(frame.report.parts.checks);
    std::vector<std::vector<PathPiece>> paths = std::move(frame.paths);
    for (std::size_t b = 0; b < bodies_.size(); ++b)
      if (paths[b].empty()) paths[b].push_back({bodies_[b].path, T1});  // a static body: its one path
    // A pair reported by a collision, or held by the hybrid's contact solver, is in contact
    // this frame: the checks' tunnelling search leaves it out (as a peer's contact points).
    std::vector<std::pair<int, int>> reported = frame.collidedPairs;
    reported.insert(reported.end(), frame.heldPairs.begin(), frame.heldPairs.end());
    std::sort(reported.begin(), reported.end());
    FrameVerdict verdict = verifier_->check(frame_ + 1, T0, T1, paths, [&](int i, int j) {
      return std::binary_search(reported.begin(), reported.end(), std::make_pair(i, j));
    });
    frame.report.counters.maxPenetration = verdict.maxPenetration;
    frame.report.counters.tunnelled = verdict.tunnelled;
    frame.report.findings = std::move(verdict.findings);
    frame.report.checked = true;
  }
  ++frame_;
  frame.report.wallSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  frame.report.cpuSeconds = double(std::clock() - cpuStart) / CLOCKS_PER_SEC;
  PartTimes& parts = frame.report.parts;
  parts.ordering = std::max(0.0, frame.report.wallSeconds - parts.integration - parts.bounds -
                                     parts.collisionDetection - parts.impulses - parts.checks - parts.contacts);
  return frame.report;
}

}  // namespace gjkx
