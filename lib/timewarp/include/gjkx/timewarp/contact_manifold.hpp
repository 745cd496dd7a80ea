/// @file
/// @brief The contact manifold of two convex pieces (the hybrid contact model, contact_solver.hpp):
/// the overlap of their touching features, up to four points, each with its separation.
///
/// One pair of closest points (what GJK gives) is one point of a contact; a box resting on
/// a floor touches it with a face, and a solver that holds it still needs the face's
/// corners. The features are the points of each piece within a depth of its supporting
/// plane (contact.hpp's touchingFeature); projected on the contact plane, the manifold is
/// their overlap: the vertices of each inside the other, and the crossings of their edges.
#pragma once

#include <gjkx/motion/pose.hpp>
#include <gjkx/support_mapping/shape.hpp>

#include <Eigen/Core>

#include <cstdint>
#include <unordered_map>
#include <vector>

namespace gjkx {

/// One point of a contact manifold.
struct ManifoldPoint {
  Eigen::Vector3d point = Eigen::Vector3d::Zero();    ///< world, midway between the two surfaces
  double separation = 0;                              ///< along the normal (negative: overlap)
  Eigen::Vector3d anchorI = Eigen::Vector3d::Zero();  ///< the point in body i's frame (what a later solve matches)
  Eigen::Vector3d anchorJ = Eigen::Vector3d::Zero();  ///< the point in body j's frame
  double normalImpulse = 0;                           ///< accumulated normal impulse (N s)
  Eigen::Vector3d frictionImpulse = Eigen::Vector3d::Zero();  ///< accumulated friction impulse, world (N s)
};

/// The manifold of two convex pieces: the normal and up to four points.
struct Manifold {
  int i = -1;   ///< the first body
  int pi = 0;   ///< its piece
  int j = -1;   ///< the second body
  int pj = 0;   ///< its piece
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();  ///< unit, from i towards j
  double friction = 0;                                ///< the pair's μ (materialOf)
  std::vector<ManifoldPoint> points;                  ///< at most four
};

/// The manifold of convex shapes A and B at their poses, with unit `normal` from A to B: the
/// overlap of their touching features (the points of each within `depth` of its supporting
/// plane), projected on the plane normal to `normal`, reduced to at most four points that
/// keep the largest area; each point's separation is B's surface height minus A's there.
/// `fallback` (the closest points' midpoint) and `distance` give the one point of a pair whose
/// features do not overlap on the plane (round-off); when the pieces overlap (`distance` 0),
/// that point's separation is their overlap along `normal`, B's lowest point less A's
/// highest, never less deep than the overlap. Points are world; anchors are not set.
std::vector<ManifoldPoint> contactManifold(const Shape<double>& shapeA, const Pose<double>& poseA,
                                           const Shape<double>& shapeB, const Pose<double>& poseB,
                                           const Eigen::Vector3d& normal, double depth,
                                           const Eigen::Vector3d& fallback, double distance, double tolerance);

/// The contact normal of A and B refined to a face: where the touching feature of A or of B
/// (within `depth` of its supporting plane along `normal`) is a face, its own normal (the one
/// nearer `normal`, if within 10 degrees of it), else `normal`. GJK's closest points give the
/// normal to within its tolerance over their distance: between two boxes resting a fraction of
/// a millimetre apart, a few milliradians, enough to push a stack sideways; the face's normal
/// is exact, as the engines' face-clipping manifolds have it.
Eigen::Vector3d faceNormal(const Shape<double>& shapeA, const Pose<double>& poseA, const Shape<double>& shapeB,
                           const Pose<double>& poseB, const Eigen::Vector3d& normal, double depth);

/// The normal of two pieces that overlap (or nearly touch), where GJK's closest points give
/// none: of the candidate directions (the axes of both pieces' frames, both ways, and the
/// `hints`), the one along which A and B overlap least, pointing from A to B (the separating
/// axis test on those axes). For a box resting on a floor it is the floor's normal, where
/// the line between their centres may be far from it.
Eigen::Vector3d leastOverlapAxis(const Shape<double>& shapeA, const Pose<double>& poseA, const Shape<double>& shapeB,
                                 const Pose<double>& poseB, const std::vector<Eigen::Vector3d>& hints);

/// What the contact solver keeps from one solve to the next: per piece pair
/// (StepContext::piecePairKey), the manifold it last solved, with its impulses.
using ContactCache = std::unordered_map<std::uint64_t, Manifold>;

}  // namespace gjkx
