/// @file
/// @brief The broad phase: which body pairs may meet over an interval, from their swept bounds (§6).
///
/// The time-of-impact solver (§5) answers for one pair; a scene of n bodies has n(n-1)/2.
/// The broad phase bounds each body over the interval by an axis-aligned box that holds
/// every place the body occupies on its path (gjkx/dynamics/swept_bounds.hpp), and keeps
/// the pairs whose boxes, grown by the collision tolerance, overlap (sweep and prune).
#pragma once

#include <gjkx/dynamics/swept_bounds.hpp>
#include <gjkx/timewarp/body.hpp>

#include <utility>
#include <vector>

namespace gjkx {

/// The swept bounds of `body` along `path` over [t0, t1] (dynamics' sweptBounds of its shape).
inline Bounds sweptBounds(const WorldBody& body, const FreeFlight& path, double t0, double t1,
                          const Eigen::Vector3d& gravity) {
  return sweptBounds(body.shape, body.radius, body.rigid.isStatic(), path, t0, t1, gravity, &body.boundsHints);
}

struct StepContext;

/// The body pairs whose swept bounds over [t0, t1] (grown by the collision tolerance)
/// overlap, but for pairs of two resting bodies (static or asleep: neither can move); with
/// `only` >= 0, only the pairs of bodies `only` and `also`. Timed as the bounds' part.
std::vector<std::pair<int, int>> candidatePairs(StepContext& step, double t0, double t1, int only = -1, int also = -1);

}  // namespace gjkx
