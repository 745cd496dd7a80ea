// The independent checks of a frame (checks.hpp: checkFrame).
#include <gjkx/timewarp/broad_phase.hpp>
#include <gjkx/timewarp/checks.hpp>

#include <algorithm>

namespace gjkx {

namespace {

/// The pieces of body b's path this frame (the frame's path, held in `unstruck`, when it was not struck).
const std::vector<PathPiece>& pathsOf(const StepContext& step, int b, double T1, std::vector<PathPiece>& unstruck) {
  if (!step.frame.paths[b].empty()) return step.frame.paths[b];
  unstruck = {PathPiece{step.bodies[b].path, T1}};
  return unstruck;
}

// How fast the distance of bodies i and j can change over a frame (the Lipschitz bound of
// the tunnelling check). A point of body b at x moves at v_b + w_b x (x - c_b), so the
// distance changes at most as fast as the largest relative speed of two points,
//   |d'(t)| <= |v_j(t) - v_i(t)| + |w_i| r_i + |w_j| r_j.
// The linear part. Over a piece of its path a body flies freely, so its velocity is linear
// in t (v(s) + g (t - s) awake, constant asleep or static) and is the line through the
// piece's end velocities. Over the time two pieces share, v_j - v_i is then linear too and
// its size, convex, is largest at an end of the shared time. The bound is the largest over
// the pieces that share time. Two bodies falling side by side (the paper's sweeping false
// alarm) get a bound near 0, since their gravity cancels, where the sum of their speeds,
// growing as g t, made the check crawl.
// The spin part. Over a piece the spin's size is bounded by its ends' largest (torque-free:
// |L| is fixed, but |w| within its ends' range is not guaranteed), so spare 10%.
double relativeSpeedBound(const StepContext& step, int i, int j, double T0, double T1) {
  std::vector<PathPiece> unstruckI, unstruckJ;
  const std::vector<PathPiece>& piecesI = pathsOf(step, i, T1, unstruckI);
  const std::vector<PathPiece>& piecesJ = pathsOf(step, j, T1, unstruckJ);
  double spin = 0;
  for (const auto& [b, pieces] : {std::pair{i, &piecesI}, std::pair{j, &piecesJ}}) {
    double w = 0;
    for (const PathPiece& piece : *pieces)
      w = std::max({w, piece.path.start.angularVelocity.norm(), piece.path.end.angularVelocity.norm()});
    if (w > 0) spin += 1.1 * w * step.bodies[b].radius;
  }
  // The velocity of a piece's path at t: the line through its end velocities.
  auto velocity = [](const PathPiece& piece, double t) -> Eigen::Vector3d {
    const FreeFlight& path = piece.path;
    if (!(path.t1 > path.t0)) return path.start.velocity;
    return path.start.velocity + (path.end.velocity - path.start.velocity) * ((t - path.t0) / (path.t1 - path.t0));
  };
  double linear = 0;
  for (const PathPiece& a : piecesI)
    for (const PathPiece& b : piecesJ) {
      const double lo = std::max({T0, a.path.t0, b.path.t0}), hi = std::min({T1, a.end, b.end});
      if (lo > hi) continue;  // never at the same time
      for (double t : {lo, hi}) linear = std::max(linear, (velocity(b, t) - velocity(a, t)).norm());
    }
  return linear + spin;
}

}  // namespace

void checkFrame(StepContext& step, const std::vector<std::shared_ptr<const ReferenceBody>>& references, double T0,
                double T1) {
  const std::vector<WorldBody>& bodies = step.bodies;
  const FrameState& frame = step.frame;
  FrameCounters& c = step.frame.report.counters;
  auto poseAt = [&](int b, double t) -> Pose<double> {
    if (bodies[b].rigid.isStatic() || frame.paths[b].empty()) return bodies[b].path.motion.pose(t);
    for (const PathPiece& piece : frame.paths[b])
      if (t <= piece.end) return piece.path.motion.pose(std::max(t, piece.path.t0));
    return frame.paths[b].back().path.motion.pose(t);
  };
  // The deepest penetration at the frame's end.
  std::vector<Bounds> boxes(bodies.size());
  for (std::size_t b = 0; b < bodies.size(); ++b) {
    if (bodies[b].rigid.isStatic() || frame.paths[b].empty()) {
      boxes[b] = sweptBounds(bodies[b], bodies[b].path, T0, T1, step.scene.gravity);
    } else {
      for (const PathPiece& piece : frame.paths[b])
        if (piece.end > piece.path.t0)
          boxes[b].add(sweptBounds(bodies[b], piece.path, piece.path.t0, piece.end, step.scene.gravity));
    }
    boxes[b].inflate(step.scene.collisionTolerance);
  }
  const auto pairs = overlappingPairs(boxes, [&](int i, int j) { return bodies[i].rigid.isStatic() && bodies[j].rigid.isStatic(); });
  for (const auto& [i, j] : pairs) {
    const double d = referenceSignedDistance(*references[i], poseAt(i, T1), *references[j], poseAt(j, T1));
    c.maxPenetration = std::max(c.maxPenetration, -d);
    // Tunnelling: a pair with no collision reported this frame that came closer than
    // minus twice the tolerance (interpenetrated) at some time of the frame (tunnellingThreshold).
    const bool reported = std::find(frame.collidedPairs.begin(), frame.collidedPairs.end(), std::make_pair(i, j)) !=
                          frame.collidedPairs.end();
    if (reported) continue;
    const double lipschitz = relativeSpeedBound(step, i, j, T0, T1);
    const int a = i, b = j;  // a lambda may not capture structured bindings in C++17
    const ReferenceBody &ra = *references[a], &rb = *references[b];
    const auto distanceAt = [&](double t) { return referenceSignedDistance(ra, poseAt(a, t), rb, poseAt(b, t)); };
    const double threshold = tunnellingThreshold(distanceAt(T0), step.scene.collisionTolerance);
    if (firstInterpenetration(distanceAt, lipschitz, threshold, T0, T1)) ++c.tunnelled;
  }
}

}  // namespace gjkx
