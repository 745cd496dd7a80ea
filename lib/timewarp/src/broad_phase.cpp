// The broad phase: the pairs whose swept bounds meet (broad_phase.hpp).
#include <gjkx/timewarp/broad_phase.hpp>

#include <gjkx/timewarp/step.hpp>

namespace gjkx {

std::vector<std::pair<int, int>> candidatePairs(StepContext& step, double t0, double t1, int only, int also) {
  PartTimer timer(step.frame.report.parts.bounds);
  const std::vector<WorldBody>& bodies = step.bodies;
  std::vector<Bounds> boxes(bodies.size());
  for (std::size_t b = 0; b < bodies.size(); ++b) {
    boxes[b] = sweptBounds(bodies[b], bodies[b].path, t0, pathEnd(step, int(b), t1), step.scene.gravity);
    boxes[b].inflate(step.scene.collisionTolerance);
  }
  return overlappingPairs(boxes, [&](int i, int j) {
    if (bodies[i].resting() && bodies[j].resting()) return true;  // neither can move: no collision
    if (only < 0) return false;
    return !(i == only || j == only || i == also || j == also);
  });
}

}  // namespace gjkx
