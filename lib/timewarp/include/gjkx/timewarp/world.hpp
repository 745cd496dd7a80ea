/// @file
/// @brief The world: a scene's bodies run frame by frame, their collisions found by the paper's
/// solver (§5) and ordered by Mirtich's Timewarp, or by the two orderings it is compared with (§6).
///
/// A frame [T0, T1] (1/24 s, the paper's frames) is a short loop over the named parts of a
/// step, each in its own file, sharing one StepContext (step.hpp):
///
/// ```
/// scene ──> buildBodies (body.hpp)                 narrow phase in the scene's scalar (narrow_phase.hpp)
/// frame [T0, T1], in intervals of at most an eighth of a turn of the fastest body:
///   hybrid contact model only: contacts, groups, the contact solver (contact_solver.hpp)
///   ordering: timewarp.hpp | toi_heap.hpp | fixed_step.hpp
///     ├─ free flight of the moving bodies (step.hpp)
///     ├─ broad phase: swept bounds (broad_phase.hpp)
///     ├─ narrow phase: extrusion + Brent on the piece pairs (narrow_phase.hpp), contact data (contact.hpp)
///     └─ response: Mirtich's impulse, the instant pass, Zeno's wedge (response.hpp)
///   settling of slow bodies at rest (sleep.hpp), or, hybrid, sleeping groups (contact_solver.hpp)
///   the independent checks (gjkx/verify/frame_verifier.hpp), when on
///   ──> FrameReport (frame.hpp): counters, status, wall time by part
/// ```
///
/// The scalar of collision detection is chosen once, when the world is built: it holds one
/// narrow phase, float or double, and the frame loop visits it at one place. A spin that
/// overflows an interval is not an error: the frame is run again in shorter intervals
/// (FrameCounters::spinRestarts). A frame that reaches the event cap ends with
/// FrameStatus::EventCap. What stops a run is a numerical failure (a non-finite support
/// point, an integrator out of steps), thrown as std::runtime_error naming the bodies and
/// the time; the world is then left as it was at the frame's start.
#pragma once

#include <gjkx/timewarp/body.hpp>
#include <gjkx/timewarp/contact_manifold.hpp>
#include <gjkx/timewarp/frame.hpp>
#include <gjkx/timewarp/narrow_phase.hpp>
#include <gjkx/timewarp/scene.hpp>
#include <gjkx/timewarp/settings.hpp>

#include <array>
#include <map>
#include <memory>
#include <variant>
#include <vector>

namespace gjkx {

/// The world of a scene, run frame by frame.
class World {
 public:
  /// Builds the bodies of `scene` (buildBodies), the narrow phase in the scene's scalar, and
  /// checks them: a bad setting is named ("settings.tuning.caughtAfter: ..."), and two
  /// bodies overlapping at the start (one of them not static) is an error naming both.
  /// Throws std::invalid_argument.
  explicit World(const Scene& scene, const WorldSettings& settings = {});
  ~World();

  /// Runs one frame and reports it.
  FrameReport step();
  /// True once the scene's duration is simulated.
  bool done() const { return frame_ >= frameCount_; }
  /// Frames in the scene's duration.
  int frameCount() const { return frameCount_; }
  /// Simulated time.
  double time() const { return double(frame_) / scene_.frameRate; }
  /// The bodies.
  const std::vector<WorldBody>& bodies() const { return bodies_; }
  /// A body's state now (at `time()`).
  BodyState stateOf(int body) const { return bodies_[body].path.stateAt(time()); }
  /// Where the origin of a body's scene frame is now (the position as the scene file gives it).
  Eigen::Vector3d positionOf(int body) const;
  /// The scene.
  const Scene& scene() const { return scene_; }
  /// The settings it runs with.
  const WorldSettings& settings() const { return settings_; }
  /// The trace of every frame so far (empty unless WorldSettings::trace).
  const std::vector<TraceEvent>& trace() const { return trace_; }
  /// The collisions of every frame so far, in the order they were resolved.
  const std::vector<CollisionRecord>& collisionLog() const { return collisionLog_; }

 private:
  Scene scene_;
  WorldSettings settings_;
  ImpulseSettings impulse_;  // settings_.impulse with the scene's microcollision speed
  std::vector<WorldBody> bodies_;
  /// The narrow phase of the scene's scalar, chosen when the world is built.
  using AnyNarrowPhase = std::variant<NarrowPhase<float>, NarrowPhase<double>>;
  AnyNarrowPhase narrow_;
  /// The independent checks, prepared once (they also measure the start).
  std::unique_ptr<FrameVerifier> verifier_;
  int frame_ = 0;
  int frameCount_ = 0;
  std::vector<TraceEvent> trace_;
  std::vector<CollisionRecord> collisionLog_;
  std::map<std::array<int, 4>, Eigen::Vector3d> pairNormals_;
  /// The hybrid's manifolds of the last solve, with their impulses (contact_solver.hpp).
  ContactCache contactCache_;
};

}  // namespace gjkx
