// Mirtich's Timewarp (timewarp.hpp).
#include <gjkx/timewarp/timewarp.hpp>

#include <gjkx/timewarp/broad_phase.hpp>
#include <gjkx/timewarp/response.hpp>

#include <algorithm>
#include <functional>
#include <queue>

namespace gjkx {

long eventCapOf(const StepContext& step) {
  return step.settings.tuning.eventCap + step.settings.tuning.eventCapPerBody * long(step.bodies.size());
}

void reachEventCap(StepContext& step) {
  step.frame.report.status = FrameStatus::EventCap;
  ++step.frame.report.counters.eventCaps;
}

template <typename S>
void runTimewarp(StepContext& step, NarrowPhase<S>& narrow, double T0, double T1) {
  std::vector<WorldBody>& bodies = step.bodies;
  FrameState& frame = step.frame;
  // Every body runs ahead to the interval's end on its own: its local time is T1.
  if (!flyAll(step, T0, T1)) return;
  std::priority_queue<Hit, std::vector<Hit>, std::greater<Hit>> queue;
  {
    Hit hit;
    for (const auto& [i, j] : candidatePairs(step, T0, T1))
      if (narrow.checkPair(step, i, j, T0, T1, hit)) queue.push(hit);
  }
  // The swept bounds stay valid for every body a collision leaves alone: only the bodies
  // its impulses struck (its two, and those the instant pass reached) get new ones (from
  // t_c), and only their pairs are looked at.
  std::vector<Bounds> boxes(bodies.size());
  const auto sweep = [&](int b, double t0) {
    boxes[b] = sweptBounds(bodies[b], bodies[b].path, t0, T1, step.scene.gravity);
    boxes[b].inflate(step.scene.collisionTolerance);
  };
  {
    PartTimer timer(frame.report.parts.bounds);
    for (std::size_t b = 0; b < bodies.size(); ++b) sweep(int(b), T0);
  }
  const auto pairsOf = [&](const std::vector<int>& struck, double tc) {
    PartTimer timer(frame.report.parts.bounds);
    for (int b : struck) sweep(b, tc);
    std::vector<std::pair<int, int>> pairs;
    for (int b : struck)
      for (int k = 0; k < int(bodies.size()); ++k)
        if (k != b && !(bodies[b].resting() && bodies[k].resting()) && boxes[b].overlaps(boxes[k]))
          pairs.emplace_back(std::min(b, k), std::max(b, k));  // (as in candidatePairs)
    std::sort(pairs.begin(), pairs.end());
    pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
    return pairs;
  };
  FrameCounters& c = frame.report.counters;
  const long cap = eventCapOf(step);
  while (!queue.empty()) {
    Hit hit;
    {
      PartTimer timer(frame.report.parts.ordering);
      hit = queue.top();
      queue.pop();
    }
    if (++c.events > cap) return reachEventCap(step);
    // Stale: computed on a path that a later-processed, earlier collision replaced.
    if (hit.versionI != bodies[hit.i].version || hit.versionJ != bodies[hit.j].version) continue;
    // The collision rolls back only the bodies it strikes (their local time was T1): its
    // two, and any that its impulses reach at the same instant (resolve) ...
    if (std::max(bodies[hit.i].path.t1, bodies[hit.j].path.t1) > hit.time) ++c.rollbacks;
    const std::vector<int> struck = resolve(step, hit);
    if (step.abandoned()) return;
    // ... and re-checks only the pairs that touch the bodies it struck, from t_c on.
    Hit next;
    for (const auto& [i, j] : pairsOf(struck, hit.time))
      if (narrow.checkPair(step, i, j, hit.time, T1, next)) queue.push(next);
  }
}

template void runTimewarp<float>(StepContext&, NarrowPhase<float>&, double, double);
template void runTimewarp<double>(StepContext&, NarrowPhase<double>&, double, double);

}  // namespace gjkx
