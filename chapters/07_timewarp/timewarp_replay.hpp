// Timewarp's frames with every flight kept, for drawing each body at its own local time.
//
// World::trace() says when each body flew, collided and was rolled back (TraceEvent), but not
// where: the paths a rollback discards are gone when World::step returns. The frame's
// FrameState keeps them all (FrameState::paths: every flight of each body, cut where a
// rollback cut it), so this replay runs each frame through the same named parts the world
// calls (step.hpp: a StepContext, runTimewarp, settle) and keeps each frame's paths. It
// covers the case a small teaching scene needs: the Timewarp ordering, the paper's
// microcollisions, one interval a frame (no fast spin), no independent checks; anything
// else is refused. Its trace is then compared with a World's, event by event: a replay that
// no longer does what the world does is an error, not a wrong animation.
#pragma once

#include <gjkx/timewarp/narrow_phase.hpp>
#include <gjkx/timewarp/sleep.hpp>
#include <gjkx/timewarp/step.hpp>
#include <gjkx/timewarp/timewarp.hpp>
#include <gjkx/timewarp/world.hpp>

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

namespace animation {

/// One frame [T0, T1] of the replay.
struct ReplayFrame {
  double T0 = 0, T1 = 0;                                 ///< the frame's interval (s)
  std::vector<gjkx::TraceEvent> events;                  ///< what the ordering did, in order
  std::vector<std::vector<gjkx::PathPiece>> paths;       ///< per body, every flight of the frame in order
  std::vector<gjkx::BodyState> start;                    ///< per body, its state at T0
};

/// The replay of a scene's first frames (see the file comment).
struct Replay {
  std::vector<std::string> names;           ///< the bodies' names
  std::vector<bool> isStatic;               ///< per body
  std::vector<Eigen::Vector3d> frameOrigin;  ///< per body: its shape frame's origin in its body frame
  std::vector<ReplayFrame> frames;          ///< the frames run
};

namespace detail {

template <typename S>
void replayFrames(const gjkx::Scene& scene, const gjkx::WorldSettings& settings, int frames, Replay& replay) {
  std::vector<gjkx::WorldBody> bodies = gjkx::buildBodies(scene, double(gjkx::frameCount(scene)) / scene.frameRate);
  gjkx::NarrowPhase<S> narrow(bodies);
  gjkx::ImpulseSettings impulse = settings.impulse;  // as the world sets it: the scene's microcollision speed
  impulse.microcollisionSpeed = std::sqrt(2 * scene.gravity.norm() * scene.collisionTolerance);
  std::vector<gjkx::TraceEvent> trace;
  std::vector<gjkx::CollisionRecord> log;
  std::map<std::array<int, 4>, Eigen::Vector3d> normals;
  gjkx::ContactCache cache;
  for (const gjkx::WorldBody& b : bodies) {
    replay.names.push_back(b.name);
    replay.isStatic.push_back(b.rigid.isStatic());
    replay.frameOrigin.push_back(b.frameOrigin);
  }
  for (int f = 0; f < frames; ++f) {
    const double T0 = double(f) / scene.frameRate, T1 = double(f + 1) / scene.frameRate;
    ReplayFrame out;
    out.T0 = T0;
    out.T1 = T1;
    for (const gjkx::WorldBody& b : bodies) {
      out.start.push_back(b.path.stateAt(T0));
      // One interval a frame holds an eighth of a turn of the fastest body (world.cpp).
      if (!b.rigid.isStatic() && b.path.end.angularVelocity.norm() * (T1 - T0) > gjkx::eighthTurn)
        throw std::runtime_error("body '" + b.name + "' spins too fast for one interval a frame (the replay shows slow scenes)");
    }
    gjkx::FrameState frame(bodies.size());
    gjkx::StepContext step{scene, settings, impulse, bodies, trace, log, normals, frame, cache, T1};
    const std::size_t before = trace.size();
    gjkx::runTimewarp(step, narrow, T0, T1);
    if (step.abandoned()) throw std::runtime_error("frame " + std::to_string(f + 1) + ": " + frame.spinOverflow.what);
    gjkx::settle(step, T1);
    out.events.assign(trace.begin() + long(before), trace.end());
    out.paths = std::move(frame.paths);
    replay.frames.push_back(std::move(out));
  }
}

}  // namespace detail

/// Runs the first `frames` frames of `scene` under Timewarp with the paper's
/// microcollisions (whatever the scene asks: the replay shows that ordering), keeping every
/// flight, and checks the trace against a World's. Throws std::runtime_error naming what
/// the replay cannot show, or the first event where it and the world part.
inline Replay replayTimewarp(gjkx::Scene scene, int frames) {
  scene.run.ordering = gjkx::Ordering::Timewarp;
  scene.run.contact = gjkx::ContactModel::Microcollisions;
  frames = std::min(frames, gjkx::frameCount(scene));
  gjkx::WorldSettings settings;
  settings.trace = true;
  Replay replay;
  if (scene.run.scalar == gjkx::CollisionScalar::Float) detail::replayFrames<float>(scene, settings, frames, replay);
  else detail::replayFrames<double>(scene, settings, frames, replay);
  gjkx::World world(scene, settings);
  for (int f = 0; f < frames; ++f) world.step();
  std::size_t k = 0;
  for (const ReplayFrame& frame : replay.frames)
    for (const gjkx::TraceEvent& e : frame.events) {
      const bool same = k < world.trace().size() && world.trace()[k].kind == e.kind && world.trace()[k].body == e.body &&
                        world.trace()[k].other == e.other && world.trace()[k].from == e.from && world.trace()[k].to == e.to;
      if (!same)
        throw std::runtime_error("the replay of Timewarp parts from the world's trace at event " + std::to_string(k) +
                                 " (timewarp_replay.hpp must follow World::step)");
      ++k;
    }
  if (k != world.trace().size()) throw std::runtime_error("the world's trace has events the replay lacks");
  return replay;
}

}  // namespace animation
