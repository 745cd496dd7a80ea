// What the world's tests share: a run to its end, summed, and the settings with the
// independent checks on.
#pragma once

#include <gjkx/timewarp/world.hpp>

#include <algorithm>

namespace gjkx::world_test {

/// What a whole run did: its collisions, rollbacks and checks, and what the independent
/// checks found.
struct Run {
  long collisions = 0, rollbacks = 0, checks = 0;  ///< summed over the frames
  int tunnelled = 0;                               ///< pairs that passed through each other unreported
  double maxPenetration = 0;                       ///< the deepest overlap at a frame's end
};

/// Steps `world` to its end and sums its frames.
inline Run runAll(World& world) {
  Run run;
  while (!world.done()) {
    const FrameReport r = world.step();
    run.collisions += r.counters.collisions;
    run.rollbacks += r.counters.rollbacks;
    run.checks += r.counters.collisionChecks;
    run.tunnelled += r.counters.tunnelled;
    run.maxPenetration = std::max(run.maxPenetration, r.counters.maxPenetration);
  }
  return run;
}

/// The settings of these tests: the independent checks on (off by default), so that every
/// run is measured for penetration and tunnelling.
inline WorldSettings checked() {
  WorldSettings settings;
  settings.checks = true;
  return settings;
}

}  // namespace gjkx::world_test
