/// @file
/// @brief The independent checks' measure: the signed distance of two bodies of many convex
/// pieces by the reference, and the first time a distance falls below a threshold.
///
/// A simulation's claims are checked against the reference library (gjkx::reference, long
/// double, brute force over features), which shares no code with GJK or the
/// time-of-impact solver: the signed distance of two bodies at a pose (negative: the depth
/// of their penetration), and, over a frame, whether a pair interpenetrated at any time,
/// found by dense sampling with a proof between samples (reference::firstContact).
///
/// A body of many convex pieces (the plant of §6: 8,640) is measured against another by
/// the least signed distance over their piece pairs. Only the pairs that may be the least
/// are measured exactly: a ReferenceBody, prepared once per body, holds its pieces'
/// bounding spheres in a tree of its own (no code of the solver's 14-DOP hierarchy), and
/// the search takes pairs nearest first by lower bounds of their signed distance, stopping
/// once no bound is below the least found. The bounds are conservative (a margin covers
/// their round-off), so the answer is the least over all pairs, exactly.
#pragma once

#include <gjkx/motion/pose.hpp>
#include <gjkx/support_mapping/shape.hpp>

#include <array>
#include <algorithm>
#include <functional>
#include <string>
#include <optional>
#include <limits>
#include <vector>

namespace gjkx {

/// The signed distance of two convex pieces at the given poses, by the reference: their
/// distance when apart, minus their penetration depth when they overlap. Exact for
/// spheres, capsules, boxes and polytopes of up to 16 vertices (reference::signedDistance
/// on point clouds with radii). Any other piece (a polytope of more vertices, a point, a
/// segment, a triangle) is measured by GJK in double instead, which is not independent and
/// sees no penetration depth (0 when overlapping): the reference's cost grows as n^3 m,
/// too slow for every frame.
double referencePieceDistance(const Shape<double>& a, const Pose<double>& poseA, const Shape<double>& b,
                              const Pose<double>& poseB);

/// A body as the checks measure it, prepared once: its pieces, their point clouds in the
/// body frame (what the reference measures, placed by a pose on each call), their bounding
/// spheres, and a tree of those spheres (a median split of the centres, a few pieces a
/// leaf) through which the pieces near another body are found without visiting the rest.
class ReferenceBody {
 public:
  /// Prepares the convex `pieces` of the body `name` (body frame). Throws
  /// std::invalid_argument naming the body when it has none or a piece is not finite.
  ReferenceBody(const std::string& name, const std::vector<Shape<double>>& pieces);

  /// The number of convex pieces.
  int pieceCount() const { return int(pieces_.size()); }

  /// A piece in the body frame, as the bounds and the reference take it.
  struct Piece {
    /// conv(points) + ball(radius): the piece (a polytope's or a box's vertices, a capsule's
    /// axis ends, a sphere's centre, a segment's or a triangle's corners).
    std::vector<Eigen::Vector3d> points;
    double radius = 0;                     ///< the ball swept around the points
    std::vector<Eigen::Vector3d> normals;  ///< unit outward face normals (a polytope's, a box's), once each
    std::vector<std::array<int, 2>> edges;  ///< its edges as pairs of points (a lone point: {0, 0})
    bool exact = false;  ///< measured by the reference (else by GJK: referencePieceDistance)
    Eigen::Vector3d centre = Eigen::Vector3d::Zero();  ///< the bounding sphere's centre
    double sphereRadius = 0;                           ///< and radius
  };

 private:
  /// A node of the sphere tree: the box of its pieces' centres and their largest radius.
  struct Node {
    Eigen::Vector3d lo, hi;     ///< the box of the centres (not of the spheres)
    double maxRadius = 0;       ///< the largest sphere radius below the node
    int first = 0, count = 0;   ///< its pieces: order_[first, first + count)
    int left = -1, right = -1;  ///< children (both -1 at a leaf)
  };
  int build(int first, int count);

  std::vector<Shape<double>> shapes_;  // the pieces as given (GJK's input)
  std::vector<Piece> pieces_;
  double extent_ = 0;       // the largest |centre| + sphere radius
  std::vector<int> order_;  // piece indices, grouped by leaf
  std::vector<Node> nodes_; // nodes_[0] is the root

  friend double referenceSignedDistance(const ReferenceBody& a, const Pose<double>& poseA, const ReferenceBody& b,
                                        const Pose<double>& poseB, double enough);
};

/// The signed distance of two bodies at the given poses: the least referencePieceDistance
/// over their piece pairs (the deepest penetration when they overlap). Exact: the pieces
/// of the body with fewer are searched against the other's sphere tree, nearest first by
/// conservative lower bounds (the gap of bounding spheres, then the supporting distance
/// along the line of their centres, §2.3), and only pairs whose bound may beat the least
/// found are measured. Throws std::invalid_argument for a pose that is not finite.
///
/// `enough`: a caller that only needs the distance where it is below `enough` (the
/// penetration check, `enough` = 0) lets the search stop once every bound left proves the
/// pair at least that far apart; it then returns such a lower bound (at least `enough`, at
/// most the distance) instead of the distance. The default, minus infinity, never stops early.
double referenceSignedDistance(const ReferenceBody& a, const Pose<double>& poseA, const ReferenceBody& b,
                               const Pose<double>& poseB,
                               double enough = -std::numeric_limits<double>::infinity());

/// The depth a pair must reach within a frame, with no collision reported, to count as
/// having tunnelled: twice the collision tolerance, or, for a pair that starts the frame
/// already that deep (two bodies left resting in each other, whose depth the penetration
/// check reports), a tolerance deeper than it started.
inline double tunnellingThreshold(double distanceAtStart, double tolerance) {
  return std::min(-2 * tolerance, distanceAtStart - tolerance);
}

/// The first time d(t) falls to `threshold` or below in [t0, t1] (-1 if it never does), given that d changes at
/// most `lipschitz` per unit time (reference::firstContact, 8 samples and bisection down to a
/// time in which d changes by a twentieth of |threshold|, so a fast pass is proven clean
/// rather than reported for want of resolution).
double firstInterpenetration(const std::function<double(double)>& d, double lipschitz, double threshold, double t0,
                             double t1);

}  // namespace gjkx
