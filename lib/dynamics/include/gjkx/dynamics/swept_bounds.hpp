/// @file
/// @brief Swept bounds: an axis-aligned box that holds a body along a piece of its free-flight
/// path, and the pairs whose boxes overlap (§6). The broad phase of the world and the
/// independent checks (gjkx/verify) both bound a path this way, so it is written once, here.
///
/// A box is conservative: it holds the body at both ends of the interval, grown by how far
/// any of its points can bulge off its chord between them: a point whose acceleration stays
/// below a lies within a T^2 / 8 of its chord (for a ballistic path turning at a constant
/// rate w, a = |g| + w^2 r at distance r from the centre of mass). A body turning far is
/// held by the sphere about its centre of mass as well, and gets the two boxes' overlap.
/// The pairs are found by sweep and prune along x (the boxes sorted by their low x, each
/// compared with those that start before it ends).
#pragma once

#include <gjkx/dynamics/free_flight.hpp>
#include <gjkx/support_mapping/shape.hpp>

#include <algorithm>
#include <array>
#include <limits>
#include <utility>
#include <vector>

namespace gjkx {

/// Where the six support climbs of a body's box (along +x, -x, +y, -y, +z, -z) last ended.
using SweepHints = std::array<SupportHint, 6>;

/// An axis-aligned box in the world.
struct Bounds {
  /// The low corner.
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
  /// The high corner.
  Eigen::Vector3d hi = Eigen::Vector3d::Constant(-std::numeric_limits<double>::infinity());
  /// Grows the box to hold p.
  void add(const Eigen::Vector3d& p) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  /// Grows the box to hold b.
  void add(const Bounds& b) {
    lo = lo.cwiseMin(b.lo);
    hi = hi.cwiseMax(b.hi);
  }
  /// Grows the box by r on every side.
  void inflate(double r) {
    lo.array() -= r;
    hi.array() += r;
  }
  /// True when the two boxes share a point.
  bool overlaps(const Bounds& b) const {
    return (lo.array() <= b.hi.array()).all() && (b.lo.array() <= hi.array()).all();
  }
};

/// A piece of a body's path within a frame: `path` flown from path.t0, followed until `end`
/// (when a collision replaced it, or the frame's end).
struct PathPiece {
  FreeFlight path;  ///< the flight
  double end = 0;   ///< until when it was followed
};

/// The box of `shape` at `pose`: its support along each axis. `hints`, when given, is
/// where the six climbs (along +x, -x, +y, -y, +z, -z) start, and is left where they ended
/// (a body's next box, at a pose near this one, then takes a step or two per climb: the
/// answer is the same).
Bounds boundsAt(const Shape<double>& shape, const Pose<double>& pose, SweepHints* hints = nullptr);

/// The box of `shape` (body frame at the centre of mass, bounding radius `radius`) along
/// `path` over [t0, t1]: a static body's own box at t0 (tight, its support along each
/// axis); a moving body's own box at both ends, grown by the bulge
/// `path.motion.bound().pointAcceleration(radius)` T^2 / 8 of its points off their chords;
/// for a turning body, cut down to the box of the sphere about its centre of mass at both
/// ends (grown by the ballistic bulge |g| T^2 / 8), which holds every orientation.
/// `hints` as for boundsAt.
Bounds sweptBounds(const Shape<double>& shape, double radius, bool isStatic, const FreeFlight& path, double t0,
                   double t1, const Eigen::Vector3d& gravity, SweepHints* hints = nullptr);

/// The pairs (i, j), i < j, whose boxes overlap, by sweep and prune along x. `skip(i, j)`
/// drops a pair (two static bodies, say). Sorted by (i, j), so the order is the same in every run.
template <typename Skip>
std::vector<std::pair<int, int>> overlappingPairs(const std::vector<Bounds>& boxes, Skip&& skip) {
  std::vector<int> order(boxes.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = static_cast<int>(i);
  std::sort(order.begin(), order.end(), [&](int a, int b) { return boxes[a].lo.x() < boxes[b].lo.x(); });
  std::vector<std::pair<int, int>> pairs;
  for (std::size_t k = 0; k < order.size(); ++k) {
    const Bounds& a = boxes[order[k]];
    for (std::size_t m = k + 1; m < order.size() && boxes[order[m]].lo.x() <= a.hi.x(); ++m) {
      int i = order[k], j = order[m];
      if (i > j) std::swap(i, j);
      if (a.overlaps(boxes[order[m]]) && !skip(i, j)) pairs.emplace_back(i, j);
    }
  }
  std::sort(pairs.begin(), pairs.end());
  return pairs;
}

}  // namespace gjkx
