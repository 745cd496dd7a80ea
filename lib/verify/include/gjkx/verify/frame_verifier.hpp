/// @file
/// @brief The independent checks of a run, as an observer any runner attaches at a frame's end:
/// the deepest penetration at the frame's end, and the pairs that went through each other
/// during the frame with no collision reported (tunnelling), measured without the solver.
///
/// A simulation's claims are checked against the reference library (gjkx::reference, long
/// double, brute force over features), which shares no code with GJK or the time-of-impact
/// solver. The verifier is given each body's path over the frame (its pieces of free
/// flight, gjkx/dynamics/swept_bounds.hpp) and which pairs the runner reported in contact;
/// gjkx_simulate (through the world, WorldSettings::checks) and the Bullet runner of
/// chapter 08 attach the same one, so the two are measured alike.
///
/// - **Penetration.** The signed distance of every pair whose swept bounds meet, at the
///   frame's end (ReferenceBody: the least over their piece pairs); the deepest is the
///   frame's, and a pair deeper than one tolerance is a finding.
/// - **Tunnelling.** A pair with no contact reported in the frame whose distance fell to
///   tunnellingThreshold at some time of the frame: found by dense sampling with a proof
///   between samples (firstInterpenetration), given how fast their distance can change
///   (the Lipschitz bound below).
///
/// Every finding names the pair, the frame and the time.
#pragma once

#include <gjkx/dynamics/swept_bounds.hpp>
#include <gjkx/verify/reference_body.hpp>

#include <functional>
#include <limits>
#include <memory>
#include <string>
#include <vector>

namespace gjkx {

/// A body as the checks see it.
struct VerifiedBody {
  std::string name;                        ///< its name (in findings)
  std::vector<Shape<double>> pieces;       ///< its convex pieces, body frame at the centre of mass
  Shape<double> hull = Sphere<double>(0);  ///< the hull of its pieces (its swept bounds)
  double radius = 0;                       ///< its bounding radius about the centre of mass
  bool isStatic = false;                   ///< never moves
};

/// What the checks found wrong with one pair.
struct Finding {
  /// Which check.
  enum class Kind {
    Penetration,  ///< deeper than one tolerance at the frame's end
    Tunnelling,   ///< went through each other in the frame, no contact reported
  };
  Kind kind = Kind::Penetration;  ///< which check
  int frame = 0;                  ///< the frame (1, 2, ...)
  double time = 0;                ///< when (the frame's end, or the first time past the threshold)
  int i = -1;                     ///< the first body
  int j = -1;                     ///< the second body
  double depth = 0;               ///< how deep (m): the penetration, or the threshold crossed
};

/// The name of a finding's kind in the CSV ("penetration", "tunnelling").
const char* findingName(Finding::Kind kind);

/// What the checks found in one frame.
struct FrameVerdict {
  double maxPenetration = 0;      ///< the deepest penetration at the frame's end (0 if none)
  long tunnelled = 0;             ///< pairs that tunnelled
  std::vector<Finding> findings;  ///< each deep penetration and each tunnelling
};

/// The independent checks, prepared once for a run's bodies (see the file comment).
class FrameVerifier {
 public:
  /// Prepares the bodies' reference pieces. `tolerance` is the run's collision tolerance;
  /// `speedSpare` scales the Lipschitz bound (Bullet's float poses need 5%). Throws
  /// std::invalid_argument naming a body without pieces or with one not finite.
  FrameVerifier(std::vector<VerifiedBody> bodies, double tolerance, const Eigen::Vector3d& gravity,
                double speedSpare = 1.0);

  /// Checks the frame [T0, T1]: `paths[b]` are body b's pieces of path in the frame, in
  /// order (at least one each); `reported(i, j)` says whether the runner reported pair
  /// (i, j), i < j, in contact in the frame.
  FrameVerdict check(int frame, double T0, double T1, const std::vector<std::vector<PathPiece>>& paths,
                     const std::function<bool(int, int)>& reported) const;

  /// The signed distance of bodies i and j at the given poses (the reference's), or, where
  /// it is at least `enough`, a lower bound at least `enough` (referenceSignedDistance).
  double signedDistance(int i, const Pose<double>& poseI, int j, const Pose<double>& poseJ,
                        double enough = -std::numeric_limits<double>::infinity()) const;

  /// The bodies.
  const std::vector<VerifiedBody>& bodies() const { return bodies_; }

 private:
  double relativeSpeedBound(const std::vector<PathPiece>& pathsI, const std::vector<PathPiece>& pathsJ, int i, int j,
                            double T0, double T1) const;

  std::vector<VerifiedBody> bodies_;
  std::vector<std::shared_ptr<const ReferenceBody>> references_;
  double tolerance_;
  Eigen::Vector3d gravity_;
  double speedSpare_;
};

}  // namespace gjkx
