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
///
/// The normal comes from the closest points; where they (nearly) coincide or the pieces
/// overlap, their direction is round-off, and the pair's last reliable normal stands in
/// (for a first contact, the line of the centres of mass): `contactNormal`, the one place
/// that rule is written.
#pragma once

#include <gjkx/motion/pose.hpp>
#include <gjkx/gjk/gjk.hpp>
#include <gjkx/support_mapping/placed.hpp>
#include <gjkx/support_mapping/shape.hpp>
#include <gjkx/timewarp/step.hpp>

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


/// The contact patch of a hit (its pieces at the states si and sj), its depth
/// StepTuning::patchDepth tolerances: a box lying flat touches with its face (the impulse
/// acts at its centre); tilted by more than that, with its lowest edge or corner, where the
/// impulse rights it (Mirtich's microcollisions at the touching corners).
ContactPatch patchOf(const StepContext& step, const Hit& hit, const BodyState& si, const BodyState& sj);

/// The normal speed of j relative to i at the point of `patch` where the impulse acts
/// (negative: approaching), which it writes to `hit.contact`: the patch's centre, or, when
/// the centre leaves, the corner that closes fastest (a tilted body rocking onto its other
/// edge). The impulse acts at the same point, so a hit approaching here is never found
/// "separating" by the impulse.
double approachOn(const StepContext& step, Hit& hit, const ContactPatch& patch, const BodyState& si,
                  const BodyState& sj);

/// approachOn at the hit's own patch (timed as the impulses' part).
double approachAt(StepContext& step, Hit& hit, const BodyState& si, const BodyState& sj);

/// The contact normal of a hit whose closest points are `distance` apart and whose
/// `hit.normal` is their direction (zero if none): kept, and remembered as the piece pair's
/// last reliable normal, when the distance is above StepTuning::reliableNormal tolerances;
/// else replaced by the pair's last reliable normal, or centre to centre for a first
/// contact. True if the closest points gave it.
bool contactNormal(StepContext& step, Hit& hit, double distance, const BodyState& si, const BodyState& sj);

/// The contact of pieces pi of body i and pj of body j at time t, the bodies at states si
/// and sj, from a static GJK `g` of the two, written to `hit` (time, bodies, pieces, points,
/// normal by contactNormal; points midway between the centres when the normal is not the
/// closest points'). True if the closest points gave the normal.
bool contactFromGjk(StepContext& step, const GjkResult<double>& g, int i, int pi, int j, int pj, double t,
                    const BodyState& si, const BodyState& sj, Hit& hit);

/// The contact of pieces pi of body i and pj of body j at time t by a double GJK: true,
/// with the contact data in `hit` (contactFromGjk), if they are within the tolerance, or
/// under the hybrid within StepTuning::contactBand tolerances (the band in which its solver
/// takes pieces as in contact: the instant pass reaches every contact the solver holds).
bool contactAt(StepContext& step, int i, int pi, int j, int pj, double t, const BodyState& si, const BodyState& sj,
               Hit& hit);

}  // namespace gjkx
