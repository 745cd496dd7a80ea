/// @file
/// @brief The narrow phase (§5–§6): does a pair of bodies collide in [t0, t1], and where. The
/// paper's extrusion test and Brent's method on each convex piece pair the 14-DOP hierarchies
/// cannot prove apart, in the scalar type of collision detection.
///
/// One `NarrowPhase<S>` owns everything collision detection keeps in its scalar S (the paper
/// ran in 4-byte floats): each body's convex pieces in S, a mesh body's 14-DOP hierarchy and
/// its nodes' slabs at recent poses, each mesh pair's front (generalized front tracking),
/// each piece pair's coherence cache (where its last query ended), and each body's path
/// rounded to S. The world builds one, for the scene's scalar, and never tests the scalar
/// again. Whatever S is, a hit's contact data (normal, closest points) are given in double:
/// in float, the time comes from the float solver and the contact data from a double GJK at
/// that time (float's witnesses at one tolerance tilt the normal by 1e-3).
#pragma once

#include <gjkx/brent/time_of_impact.hpp>
#include <gjkx/kdop/body_kdops.hpp>
#include <gjkx/kdop/body_pair.hpp>
#include <gjkx/kdop/bvh.hpp>
#include <gjkx/timewarp/step.hpp>

#include <cstdint>
#include <map>
#include <memory>
#include <unordered_map>
#include <vector>

namespace gjkx {

/// The narrow phase in scalar type S (float or double). See the file comment.
template <typename S>
class NarrowPhase {
 public:
  /// Makes the pieces of every body in S (a double narrow phase uses the bodies' own) and
  /// the hierarchies of the mesh bodies.
  explicit NarrowPhase(const std::vector<WorldBody>& bodies);

  /// The earliest collision of bodies i and j (i < j) in [t0, t1]: true, with the hit in
  /// `hit` (its contact data in double), if one of their piece pairs comes within the
  /// tolerance and approaches. A piece pair within the tolerance that is leaving is looked
  /// at again once it can have left the band (StepTuning::minLookAhead, maxLookAhead).
  /// Throws std::runtime_error naming the pair and the time when the solver meets a
  /// non-finite support point.
  /// A contact pair of the hybrid model (FrameState::contactPairs), held apart by the contact
  /// solver, is checked with a band of StepTuning::contactCheckBand tolerances instead: it is
  /// a collision only where the solver's path fails to hold it (nothing passes through).
  bool checkPair(StepContext& step, int i, int j, double t0, double t1, Hit& hit);

  /// The static test of fixed steps (discrete collision detection): bodies i and j at the
  /// states si and sj at time t. True, with the contact of the first piece pair found within
  /// the tolerance in `hit`, if any is.
  bool touchingAt(StepContext& step, int i, int j, double t, const BodyState& si, const BodyState& sj, Hit& hit);

  /// The piece pairs of bodies i and j at the states si and sj (time t) that lie within
  /// `distance` of each other or overlap, each with its GJK in double, appended to `out`
  /// (the hybrid's contacts, contact_solver.hpp).
  void piecesWithin(StepContext& step, int i, int j, double t, const BodyState& si, const BodyState& sj,
                    double distance, std::vector<std::pair<PiecePair, GjkResult<double>>>& out);

 private:
  /// The piece pairs of bodies i and j that may come within `tolerance` over [t0, t1].
  std::vector<PiecePair> piecePairs(StepContext& step, int i, int j, double t0, double t1, double tolerance);
  /// The earliest collision of pieces pi of i and pj of j in [t0, t1] within `tolerance`;
  /// `pathsEnd` (>= t1) is where both bodies' paths end, which a landing is checked to.
  bool checkPieces(StepContext& step, int i, int pi, int j, int pj, double t0, double t1, double pathsEnd,
                   double tolerance, Hit& hit);
  /// The hybrid's landing (docs 07): pieces pi of i and pj of j met at tc, closing at vn (< 0).
  /// True if the meeting is left to the next interval's contact solve: a pair that is not a
  /// contact pair, closing slower than the contact speed, that the extrusion test proves
  /// stays beyond the rest separation over [tc, t1].
  bool landsAsContact(StepContext& step, int i, int pi, int j, int pj, double tc, double t1, double vn);
  ToiResult<double> query(StepContext& step, int i, int pi, int j, int pj, double t0, double t1, double tolerance);
  const std::vector<Shape<S>>& piecesOf(const std::vector<WorldBody>& bodies, int b) const;
  const Motion<S>& motionOf(const WorldBody& body, int b);

  /// Per body, its pieces in S (float only: a double narrow phase reads WorldBody::pieces).
  std::vector<std::vector<Shape<S>>> pieces_;
  /// Per body, its 14-DOP hierarchy (a mesh body) or null.
  std::vector<std::shared_ptr<const Bvh<S>>> bvh_;
  /// Per mesh body, its nodes' 14-DOPs at its recent poses, shared by all its body pairs
  /// (kdop's `BodyKdops`; made when a pair first needs it).
  std::vector<std::unique_ptr<BodyKdops<S>>> kdops_;
  /// Per pair of mesh bodies, the body-pair query that keeps its front between frames.
  std::map<long long, std::unique_ptr<BodyPairQuery<S>>> fronts_;
  /// Per convex piece pair, where its last time-of-impact query ended (WorldSettings::coherence).
  std::unordered_map<std::uint64_t, ExtrusionCache<S>> coherence_;
  /// Per convex piece pair, the simplex its last static distance test ended on (piecesWithin):
  /// a pair in contact is measured at every interval's start, each time from where it was,
  /// so that GJK takes one or two iterations (§2.2's coherence) rather than a cold run.
  std::unordered_map<std::uint64_t, GjkCache<double>> staticCoherence_;
  /// Per body, its path's motion in S and the path it was made from (WorldBody::pathSerial):
  /// made once per path for all the queries that read it (float only).
  std::vector<std::pair<long, Motion<S>>> motions_;
};

extern template class NarrowPhase<float>;
extern template class NarrowPhase<double>;

}  // namespace gjkx
