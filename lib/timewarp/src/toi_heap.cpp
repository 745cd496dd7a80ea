// The time-of-impact heap (toi_heap.hpp).
#include <gjkx/timewarp/toi_heap.hpp>

#include <gjkx/timewarp/broad_phase.hpp>
#include <gjkx/timewarp/response.hpp>
#include <gjkx/timewarp/timewarp.hpp>

namespace gjkx {

template <typename S>
void runToiHeap(StepContext& step, NarrowPhase<S>& narrow, double T0, double T1) {
  std::vector<WorldBody>& bodies = step.bodies;
  if (!flyAll(step, T0, T1)) return;
  FrameCounters& c = step.frame.report.counters;
  const long cap = eventCapOf(step);
  double t = T0;
  for (;;) {
    // Every pair, from the current time: the earliest impact of all.
    Hit earliest, hit;
    bool found = false;
    for (const auto& [i, j] : candidatePairs(step, t, T1))
      if (narrow.checkPair(step, i, j, t, T1, hit) && (!found || earliest > hit)) {
        earliest = hit;
        found = true;
      }
    if (!found) return;
    if (++c.events > cap) return reachEventCap(step);
    // Every body is advanced to the impact: its path is cut there and flown on.
    t = earliest.time;
    for (std::size_t b = 0; b < bodies.size(); ++b) {
      if (bodies[b].rigid.isStatic() || int(b) == earliest.i || int(b) == earliest.j) continue;
      if (t < T1 && t > bodies[b].path.t0) {  // an impact at the frame's very end cuts nothing
        if (!fly(step, int(b), t, T1)) return;
        ++c.bodiesRolledBack;
      }
    }
    resolve(step, earliest);
    if (step.abandoned()) return;
  }
}

template void runToiHeap<float>(StepContext&, NarrowPhase<float>&, double, double);
template void runToiHeap<double>(StepContext&, NarrowPhase<double>&, double, double);

}  // namespace gjkx
