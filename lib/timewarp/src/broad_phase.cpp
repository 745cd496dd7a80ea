// The broad phase: swept bounds and the pairs whose bounds meet (broad_phase.hpp).
#include <gjkx/timewarp/broad_phase.hpp>

#include <gjkx/support_mapping/placed.hpp>
#include <gjkx/timewarp/step.hpp>

namespace gjkx {

Bounds sweptBounds(const WorldBody& body, const FreeFlight& path, double t0, double t1, const Eigen::Vector3d& gravity) {
  // The shape's box at a pose: its support along each axis.
  const auto addShapeBox = [&](Bounds& box, const Pose<double>& pose) {
    const Placed<Shape<double>> placed{body.shape, pose};
    for (int k = 0; k < 3; ++k) {
      Eigen::Vector3d e = Eigen::Vector3d::Zero();
      e[k] = 1;
      box.add(Eigen::Vector3d(placed.support(e)));
      box.add(Eigen::Vector3d(placed.support(-e)));
    }
  };
  const BodyState a = path.stateAt(t0), z = path.stateAt(t1);
  if (body.rigid.isStatic()) {  // a static body's box is tight (its support along each axis), with no bulge
    Bounds tight;
    const Placed<Shape<double>> placed{body.shape, a.worldFromBody};
    for (int k = 0; k < 3; ++k) {
      Eigen::Vector3d e = Eigen::Vector3d::Zero();
      e[k] = 1;
      tight.hi[k] = placed.support(e)[k];
      tight.lo[k] = placed.support(-e)[k];
    }
    return tight;
  }
  Bounds box;
  if (path.start.angularVelocity.squaredNorm() > 0) {
    // Turning: every orientation may occur, the sphere about the centre of mass.
    box.add(a.worldFromBody.translation);
    box.add(z.worldFromBody.translation);
    box.inflate(body.radius);
  } else {
    // Not turning: the shape's own box at both ends (the box moves with the centre of mass).
    addShapeBox(box, a.worldFromBody);
    addShapeBox(box, z.worldFromBody);
  }
  // The ballistic bulge of the path off its chord: |g| T^2 / 8.
  const double T = t1 - t0;
  box.inflate(gravity.norm() * T * T / 8);
  return box;
}

std::vector<std::pair<int, int>> candidatePairs(StepContext& step, double t0, double t1, int only, int also) {
  PartTimer timer(step.frame.report.parts.bounds);
  const std::vector<WorldBody>& bodies = step.bodies;
  std::vector<Bounds> boxes(bodies.size());
  for (std::size_t b = 0; b < bodies.size(); ++b) {
    boxes[b] = sweptBounds(bodies[b], bodies[b].path, t0, t1, step.scene.gravity);
    boxes[b].inflate(step.scene.collisionTolerance);
  }
  return overlappingPairs(boxes, [&](int i, int j) {
    if (bodies[i].resting() && bodies[j].resting()) return true;  // neither can move: no collision
    if (only < 0) return false;
    return !(i == only || j == only || i == also || j == also);
  });
}

}  // namespace gjkx
