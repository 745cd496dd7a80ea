// Mirtich's Timewarp (timewarp.hpp).
#include <gjkx/timewarp/timewarp.hpp>

#include <gjkx/timewarp/broad_phase.hpp>
#include <gjkx/timewarp/response.hpp>

#include <algorithm>
#include <functional>
#include <queue>
#include <tuple>

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
  // Every body runs ahead to the interval's end on its own: its local time is T1. A body
  // spinning faster than the interval allows runs an eighth of a turn at a time (a path holds
  // less than half a turn): where its step ends, before T1, is an event of its own, where it
  // flies on (a *step end*). (Which bodies cut the frame into shorter intervals instead:
  // world.cpp.)
  if (!flyAll(step, T0, T1)) return;
  struct StepEnd {
    double time;  // where the body's path ends
    int body;
    int version;  // the path's: a body flown again meanwhile has a new step end
    bool operator>(const StepEnd& o) const { return std::tie(time, body) > std::tie(o.time, o.body); }
  };
  std::priority_queue<StepEnd, std::vector<StepEnd>, std::greater<StepEnd>> stepEnds;
  const auto stepEndOf = [&](int b) {
    if (!bodies[b].rigid.isStatic() && bodies[b].path.t1 < T1) stepEnds.push({bodies[b].path.t1, b, bodies[b].version});
  };
  for (std::size_t b = 0; b < bodies.size(); ++b) stepEndOf(int(b));
  // A pair is checked as far as both its bodies' paths reach.
  const auto check = [&](int i, int j, double t0, Hit& hit) {
    const double t1 = std::min(pathEnd(step, i, T1), pathEnd(step, j, T1));
    return t1 > t0 && narrow.checkPair(step, i, j, t0, t1, hit);
  };
  FrameCounters& c = frame.report.counters;
  std::priority_queue<Hit, std::vector<Hit>, std::greater<Hit>> queue;
  {
    Hit hit;
    for (const auto& [i, j] : candidatePairs(step, T0, T1)) {
      ++c.checkedAtIntervalStarts;
      if (check(i, j, T0, hit)) queue.push(hit);
    }
  }
  // The swept bounds stay valid for every body a collision leaves alone: only the bodies
  // its impulses struck (its two, and those the instant pass reached) get new ones (from
  // t_c), and only their pairs are looked at.
  std::vector<Bounds> boxes(bodies.size());
  const auto sweep = [&](int b, double t0) {
    boxes[b] = sweptBounds(bodies[b], bodies[b].path, t0, pathEnd(step, b, T1), step.scene.gravity);
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
  const long cap = eventCapOf(step);
  while (!queue.empty() || !stepEnds.empty()) {
    // A step end before the earliest collision: the body flies on from it, and its pairs are
    // checked again from there (the collisions of its last step are all taken by now).
    if (!stepEnds.empty() && (queue.empty() || stepEnds.top().time < queue.top().time)) {
      const StepEnd end = stepEnds.top();
      stepEnds.pop();
      if (end.version != bodies[end.body].version) continue;  // flown again since
      if (!flyOwnStep(step, end.body, end.time, T1)) return;
      ++c.stepEnds;
      stepEndOf(end.body);
      Hit next;
      for (const auto& [i, j] : pairsOf({end.body}, end.time)) {
        ++c.recheckedAtStepEnds;
        if (check(i, j, end.time, next)) queue.push(next);
      }
      continue;
    }
    Hit hit;
    {
      PartTimer timer(frame.report.parts.ordering);
      hit = queue.top();
      queue.pop();
    }
    if (++c.events > cap) {
      // The remaining events are dropped; the bodies whose steps end before T1 fly on to it
      // unchecked, so that the next interval starts where every path reaches.
      for (std::size_t b = 0; b < bodies.size(); ++b)
        while (!bodies[b].rigid.isStatic() && bodies[b].path.t1 < T1)
          if (!flyOwnStep(step, int(b), bodies[b].path.t1, T1)) return;
      return reachEventCap(step);
    }
    // Stale: computed on a path that a later-processed, earlier collision replaced.
    if (hit.versionI != bodies[hit.i].version || hit.versionJ != bodies[hit.j].version) continue;
    // The collision rolls back only the bodies it strikes (their local time was T1): its
    // two, and any that its impulses reach at the same instant (resolve) ...
    if (std::max(bodies[hit.i].path.t1, bodies[hit.j].path.t1) > hit.time) ++c.rollbacks;
    const std::vector<int> struck = resolve(step, hit);
    if (step.abandoned()) return;
    for (int b : struck) stepEndOf(b);
    // ... and re-checks only the pairs that touch the bodies it struck, from t_c on.
    Hit next;
    for (const auto& [i, j] : pairsOf(struck, hit.time)) {
      ++c.recheckedAfterCollisions;
      if (check(i, j, hit.time, next)) queue.push(next);
    }
  }
}

template void runTimewarp<float>(StepContext&, NarrowPhase<float>&, double, double);
template void runTimewarp<double>(StepContext&, NarrowPhase<double>&, double, double);

}  // namespace gjkx
