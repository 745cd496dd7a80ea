// The independent checks of a frame (frame_verifier.hpp).
#include <gjkx/verify/frame_verifier.hpp>

#include <algorithm>
#include <stdexcept>

namespace gjkx {

const char* findingName(Finding::Kind kind) {
  return kind == Finding::Kind::Penetration ? "penetration" : "tunnelling";
}

FrameVerifier::FrameVerifier(std::vector<VerifiedBody> bodies, double tolerance, const Eigen::Vector3d& gravity,
                             double speedSpare)
    : bodies_(std::move(bodies)), tolerance_(tolerance), gravity_(gravity), speedSpare_(speedSpare) {
  // Each body's piece clouds and sphere tree, made once rather than on each of the many
  // distances a frame's checks take.
  for (const VerifiedBody& body : bodies_)
    references_.push_back(std::make_shared<const ReferenceBody>(body.name, body.pieces));
}

double FrameVerifier::signedDistance(int i, const Pose<double>& poseI, int j, const Pose<double>& poseJ,
                                     double enough) const {
  return referenceSignedDistance(*references_[std::size_t(i)], poseI, *references_[std::size_t(j)], poseJ, enough);
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
double FrameVerifier::relativeSpeedBound(const std::vector<PathPiece>& pathsI, const std::vector<PathPiece>& pathsJ,
                                         int i, int j, double T0, double T1) const {
  double spin = 0;
  for (const auto& [b, pieces] : {std::pair{i, &pathsI}, std::pair{j, &pathsJ}}) {
    double w = 0;
    for (const PathPiece& piece : *pieces)
      w = std::max({w, piece.path.start.angularVelocity.norm(), piece.path.end.angularVelocity.norm()});
    if (w > 0) spin += 1.1 * w * bodies_[std::size_t(b)].radius;
  }
  // The velocity of a piece's path at t: the line through its end velocities.
  auto velocity = [](const PathPiece& piece, double t) -> Eigen::Vector3d {
    const FreeFlight& path = piece.path;
    if (!(path.t1 > path.t0)) return path.start.velocity;
    return path.start.velocity + (path.end.velocity - path.start.velocity) * ((t - path.t0) / (path.t1 - path.t0));
  };
  double linear = 0;
  for (const PathPiece& a : pathsI)
    for (const PathPiece& b : pathsJ) {
      const double lo = std::max({T0, a.path.t0, b.path.t0}), hi = std::min({T1, a.end, b.end});
      if (lo > hi) continue;  // never at the same time
      for (double t : {lo, hi}) linear = std::max(linear, (velocity(b, t) - velocity(a, t)).norm());
    }
  return speedSpare_ * (linear + spin);
}

FrameVerdict FrameVerifier::check(int frame, double T0, double T1, const std::vector<std::vector<PathPiece>>& paths,
                                  const std::function<bool(int, int)>& reported) const {
  if (paths.size() != bodies_.size())
    throw std::invalid_argument("FrameVerifier::check: paths: one list per body is needed");
  // A body's pose at t: the piece of its path followed at t.
  auto poseAt = [&](int b, double t) -> Pose<double> {
    for (const PathPiece& piece : paths[std::size_t(b)])
      if (t <= piece.end) return piece.path.motion.pose(std::max(t, piece.path.t0));
    return paths[std::size_t(b)].back().path.motion.pose(t);
  };
  // The pairs whose swept bounds over the frame meet (two static bodies never count).
  std::vector<Bounds> boxes(bodies_.size());
  for (std::size_t b = 0; b < bodies_.size(); ++b) {
    const VerifiedBody& body = bodies_[b];
    for (const PathPiece& piece : paths[b]) {
      const double from = body.isStatic ? T0 : piece.path.t0, to = body.isStatic ? T1 : piece.end;
      if (to > from || body.isStatic)
        boxes[b].add(sweptBounds(body.hull, body.radius, body.isStatic, piece.path, std::max(from, piece.path.t0),
                                 std::min(to, piece.path.t1), gravity_));
    }
    boxes[b].inflate(tolerance_);
  }
  // A body that does not move over the frame: static, or asleep (each piece of its path at
  // rest, without gravity, at one pose). Two such bodies keep one distance all frame, the one
  // measured at T1, so they cannot tunnel and the search over the frame is skipped.
  const auto still = [&](int b) {
    if (bodies_[std::size_t(b)].isStatic) return true;
    const std::vector<PathPiece>& pieces = paths[std::size_t(b)];
    if (pieces.empty()) return false;
    const Pose<double>& first = pieces.front().path.start.worldFromBody;
    return std::all_of(pieces.begin(), pieces.end(), [&](const PathPiece& piece) {
      const FreeFlight& f = piece.path;
      return f.start.velocity.isZero(0) && f.start.angularVelocity.isZero(0) && f.gravity.isZero(0) &&
             f.start.worldFromBody.translation == first.translation && f.start.worldFromBody.rotation == first.rotation;
    });
  };
  FrameVerdict verdict;
  const auto pairs = overlappingPairs(boxes, [&](int i, int j) { return bodies_[i].isStatic && bodies_[j].isStatic; });
  for (const auto& [i, j] : pairs) {
    // Only a penetration is reported: a pair proven apart needs no exact distance (a pile
    // at rest is hundreds of pairs a fraction of a millimetre apart).
    const double d = signedDistance(i, poseAt(i, T1), j, poseAt(j, T1), 0.0);
    verdict.maxPenetration = std::max(verdict.maxPenetration, -d);
    if (-d > tolerance_) verdict.findings.push_back({Finding::Kind::Penetration, frame, T1, i, j, -d});
    // Tunnelling: a pair with no contact reported this frame that came closer than minus
    // twice the tolerance (interpenetrated) at some time of the frame (tunnellingThreshold).
    if (reported(i, j) || (still(i) && still(j))) continue;
    const int a = i, b = j;  // a lambda may not capture structured bindings in C++17
    const double lipschitz = relativeSpeedBound(paths[std::size_t(a)], paths[std::size_t(b)], a, b, T0, T1);
    // d changes by at most lipschitz (T1 - T0) over the frame, so a distance at least that
    // above the threshold proves the whole frame clean: below it the distance is needed
    // exactly, above it a lower bound will do (referenceSignedDistance's `enough`).
    const double reach = lipschitz * (T1 - T0);
    const double d0 = signedDistance(a, poseAt(a, T0), b, poseAt(b, T0), std::max(-tolerance_, reach - 2 * tolerance_));
    const double threshold = tunnellingThreshold(d0, tolerance_);
    if (d0 >= threshold + reach) continue;  // proven clean by the bound alone
    const auto distanceAt = [&](double t) { return signedDistance(a, poseAt(a, t), b, poseAt(b, t), threshold + reach); };
    const double when = firstInterpenetration(distanceAt, lipschitz, threshold, T0, T1);
    if (when >= 0) {
      ++verdict.tunnelled;
      verdict.findings.push_back({Finding::Kind::Tunnelling, frame, when, a, b, -threshold});
    }
  }
  return verdict;
}

}  // namespace gjkx
