// Fixed steps with discrete collision detection (fixed_step.hpp).
#include <gjkx/timewarp/fixed_step.hpp>

#include <gjkx/timewarp/broad_phase.hpp>
#include <gjkx/timewarp/contact.hpp>
#include <gjkx/timewarp/response.hpp>

namespace gjkx {

template <typename S>
void runFixedStep(StepContext& step, NarrowPhase<S>& narrow, double T0, double T1) {
  const int steps = step.scene.run.fixedSubsteps;
  FrameCounters& c = step.frame.report.counters;
  for (int s = 0; s < steps; ++s) {
    const double ta = T0 + (T1 - T0) * s / steps, tb = s + 1 == steps ? T1 : T0 + (T1 - T0) * (s + 1) / steps;
    if (!flyAll(step, ta, tb)) return;
    step.intervalEnd = tb;  // a collision flies its bodies on to the step's end
    // Discrete collision detection: the pairs as they stand at the step's end.
    for (const auto& [i, j] : candidatePairs(step, tb, tb)) {
      const BodyState si = step.bodies[i].path.stateAt(tb), sj = step.bodies[j].path.stateAt(tb);
      Hit hit;
      if (!narrow.touchingAt(step, i, j, tb, si, sj, hit) || approachAt(step, hit, si, sj) >= 0) continue;
      ++c.events;
      // One impulse per pair and step, as a discrete engine's single pass over its
      // contacts; no instant pass (the baseline stays the simple one).
      resolve(step, hit, false);  // flies both bodies on from tb
      if (step.abandoned()) return;
    }
  }
}

template void runFixedStep<float>(StepContext&, NarrowPhase<float>&, double, double);
template void runFixedStep<double>(StepContext&, NarrowPhase<double>&, double, double);

}  // namespace gjkx
