/// @file
/// @brief Per-vertex linear motion: a point, segment or triangle whose vertices each move on their own line (§3).
///
/// This is the motion of the continuous collision detection benchmark the project is
/// checked against: every vertex moves linearly from its position at t0 to its position
/// at t1, so a triangle or an edge deforms. It is not rigid, yet the extrusion test of
/// §3 stays sound for it: along a fixed direction s, \f$\vec{s}\cdot x_k(t)\f$ is linear in t
/// for every vertex, the support function \f$h(\vec{s}, t) = \max_k \vec{s}\cdot x_k(t)\f$ is a
/// maximum of linear functions (convex in t), and the supporting distance, a minimum
/// of linear functions minus such a maximum, is concave in t: positive at both ends
/// of an interval, it is positive throughout.
#pragma once

#include <gjkx/motion/motion.hpp>
#include <gjkx/support_mapping/support.hpp>

#include <array>
#include <vector>

namespace gjkx {

/// The convex hull of 1 to 4 points: a point, segment, triangle or tetrahedron at one instant.
template <typename S>
struct PointSet {
  /// The scalar type.
  using Scalar = S;
  /// The points; only the first `count` are used.
  std::array<Vector3<S>, 4> points;
  /// How many points (1 to 4).
  int count = 0;
  /// The point farthest along s (the first on a tie).
  Vector3<S> support(const Vector3<S>& s) const {
    int best = 0;
    S bestValue = s.dot(points[0]);
    for (int k = 1; k < count; ++k) {
      const S value = s.dot(points[k]);
      if (value > bestValue) {
        bestValue = value;
        best = k;
      }
    }
    return points[best];
  }
  /// The centroid.
  Vector3<S> center() const {
    Vector3<S> c = Vector3<S>::Zero();
    for (int k = 0; k < count; ++k) c += points[k];
    return c / S(count);
  }
};

/// A point, segment or triangle whose vertices move linearly and independently:
/// \f$x_k(t) = x_k(t_0) + \frac{t - t_0}{t_1 - t_0}\,(x_k(t_1) - x_k(t_0))\f$.
template <typename S>
class DeformingSimplex {
 public:
  /// The scalar type.
  using Scalar = S;

  /// Vertices `start[k]` at t0 moving to `end[k]` at t1 (1 to 4 vertices, all finite,
  /// t1 > t0); throws std::invalid_argument naming the field otherwise.
  DeformingSimplex(const std::vector<Vector3<S>>& start, const std::vector<Vector3<S>>& end, S t0 = 0, S t1 = 1)
      : t0_(t0), t1_(t1) {
    if (start.empty() || start.size() > 4)
      failInput("deformingSimplex.start", "needs 1 to 4 vertices, got " + std::to_string(start.size()));
    if (end.size() != start.size())
      failInput("deformingSimplex.end", "needs as many vertices as start (" + std::to_string(start.size()) + "), got " +
                                            std::to_string(end.size()));
    requireInterval(t0, t1, "deformingSimplex");
    if (!(t1 > t0)) failInput("deformingSimplex.t1", "must be after t0");
    count_ = static_cast<int>(start.size());
    for (int k = 0; k < count_; ++k) {
      requireFinite(start[k], "deformingSimplex.start[" + std::to_string(k) + "]");
      requireFinite(end[k], "deformingSimplex.end[" + std::to_string(k) + "]");
      start_[k] = start[k];
      end_[k] = end[k];
    }
  }

  /// The simplex at time t (vertices interpolated; t is not clamped).
  PointSet<S> at(S t) const {
    const S u = (t - t0_) / (t1_ - t0_);
    PointSet<S> set;
    set.count = count_;
    for (int k = 0; k < count_; ++k) set.points[k] = start_[k] + u * (end_[k] - start_[k]);
    return set;
  }
  /// \f$S_{X(t)}(\vec{s})\f$.
  Vector3<S> support(const Vector3<S>& s, S t) const { return at(t).support(s); }
  /// Vertices move on straight lines at constant speed: no acceleration, and the
  /// supporting distance is concave in t (see the file comment), so no margin is needed.
  S accelerationBound() const { return S(0); }
  /// The same simplex seen from a frame whose origin sits at `-offset`: every vertex moved
  /// by `offset` at both ends (see Motion::translated).
  DeformingSimplex translated(const Vector3<S>& offset) const {
    DeformingSimplex moved = *this;
    for (int k = 0; k < count_; ++k) {
      moved.start_[k] += offset;
      moved.end_[k] += offset;
    }
    return moved;
  }
  /// The same simplex on a clock that reads 0 at time `clock`: its start and end times
  /// moved back by `clock` (see Motion::retimed).
  DeformingSimplex retimed(S clock) const {
    DeformingSimplex moved = *this;
    moved.t0_ -= clock;
    moved.t1_ -= clock;
    return moved;
  }
  /// Number of vertices.
  int vertexCount() const { return count_; }
  /// Vertex k at t0.
  const Vector3<S>& startVertex(int k) const { return start_[k]; }
  /// Vertex k at t1.
  const Vector3<S>& endVertex(int k) const { return end_[k]; }

 private:
  std::array<Vector3<S>, 4> start_, end_;
  int count_ = 0;
  S t0_, t1_;
};

}  // namespace gjkx
