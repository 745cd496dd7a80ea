/// @file
/// @brief Where an impulse acts: the contact point of two bodies found within the tolerance (§6).
///
/// The time-of-impact solver returns one pair of closest points. For a corner against a
/// face that is the contact; for two faces or an edge on a face (a box resting on the
/// floor) it is one arbitrary point of the contact patch, and an impulse there would
/// spin the box for no physical reason. So the contact point is taken from the *patch*:
/// the points of each body within `depth` of its supporting plane along the normal (its
/// touching feature: a vertex, an edge, a face), the smaller of the two patches, its
/// centroid moved onto the plane midway between the closest points.
#pragma once

#include <gjkx/motion/pose.hpp>
#include <gjkx/support_mapping/shape.hpp>

#include <vector>

namespace gjkx {

/// The points of `shape` placed at `pose` within `depth` of its supporting plane along the
/// unit `direction` (the touching feature). A sphere gives its support point; a capsule
/// the ends of its axis that qualify, moved out by the radius; a box or polytope its vertices.
std::vector<Eigen::Vector3d> touchingFeature(const Shape<double>& shape, const Pose<double>& pose,
                                             const Eigen::Vector3d& direction, double depth);

/// The contact patch of two bodies: where an impulse acts, and the patch it stands for.
struct ContactPatch {
  /// The patch's centroid on the plane midway between the closest points (see the file comment).
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  /// The points of the smaller touching feature, on that plane (the centre alone when empty).
  std::vector<Eigen::Vector3d> points;
};

/// The contact patch of A and B given their closest points `pointA`, `pointB` and the unit
/// normal from A towards B (see the file comment).
ContactPatch contactPatch(const Shape<double>& shapeA, const Pose<double>& poseA, const Shape<double>& shapeB,
                          const Pose<double>& poseB, const Eigen::Vector3d& pointA, const Eigen::Vector3d& pointB,
                          const Eigen::Vector3d& normal, double depth);

}  // namespace gjkx
