// The independent checks (checks.hpp).
#include <gjkx/timewarp/checks.hpp>

#include <gjkx/gjk/gjk.hpp>
#include <gjkx/reference/polytope_distance.hpp>
#include <gjkx/reference/time_of_impact.hpp>

#include <limits>
#include <optional>
#include <type_traits>

namespace gjkx {

namespace {

using reference::Cloud;
using reference::Real;
using reference::Vec;

Vec toReference(const Eigen::Vector3d& p) { return p.cast<Real>(); }

/// The body as the reference sees it: conv(points) + ball(radius) in the world; none for a
/// polytope of more than 16 vertices.
std::optional<Cloud> cloudOf(const Shape<double>& shape, const Pose<double>& pose) {
  Cloud cloud;
  bool fits = true;
  std::visit(
      [&](const auto& x) {
        using X = std::decay_t<decltype(x)>;
        if constexpr (std::is_same_v<X, Box<double>>) {
          for (int k = 0; k < 8; ++k)
            cloud.points.push_back(toReference(pose(Eigen::Vector3d((k & 1) ? x.halfExtents.x() : -x.halfExtents.x(),
                                                                    (k & 2) ? x.halfExtents.y() : -x.halfExtents.y(),
                                                                    (k & 4) ? x.halfExtents.z() : -x.halfExtents.z()))));
        } else if constexpr (std::is_same_v<X, Sphere<double>>) {
          cloud.points.push_back(toReference(pose.translation));
          cloud.radius = x.radius;
        } else if constexpr (std::is_same_v<X, Capsule<double>>) {
          cloud.points.push_back(toReference(pose(x.axis.a)));
          cloud.points.push_back(toReference(pose(x.axis.b)));
          cloud.radius = x.radius;
        } else if constexpr (std::is_same_v<X, Polytope<double>>) {
          if (x.vertexCount() > 16) {
            fits = false;
            return;
          }
          for (int v = 0; v < x.vertexCount(); ++v) cloud.points.push_back(toReference(pose(x.vertex(v))));
        } else {
          fits = false;
        }
      },
      shape.variant());
  if (!fits) return std::nullopt;
  return cloud;
}

}  // namespace

namespace {

double signedDistanceOfPieces(const Shape<double>& a, const Pose<double>& poseA, const Shape<double>& b,
                              const Pose<double>& poseB) {
  const auto cloudA = cloudOf(a, poseA), cloudB = cloudOf(b, poseB);
  if (cloudA && cloudB) return double(reference::signedDistance(*cloudA, *cloudB));
  const auto g = gjk(Placed<Shape<double>>{a, poseA}, Placed<Shape<double>>{b, poseB});
  return g.status == GjkStatus::Overlapping ? 0.0 : g.distance;
}

}  // namespace

double referenceSignedDistance(const WorldBody& a, const Pose<double>& poseA, const WorldBody& b,
                               const Pose<double>& poseB) {
  if (a.pieces.size() == 1 && b.pieces.size() == 1) return signedDistanceOfPieces(a.pieces[0], poseA, b.pieces[0], poseB);
  // Bodies of several convex pieces: the least over the piece pairs (the deepest
  // penetration), pairs whose bounding spheres are farther apart than the best so far skipped.
  double best = std::numeric_limits<double>::infinity();
  for (const auto& pa : a.pieces) {
    const Eigen::Vector3d ca = poseA(pa.center());
    const double ra = pa.boundingRadius() + (pa.center()).norm();
    for (const auto& pb : b.pieces) {
      const Eigen::Vector3d cb = poseB(pb.center());
      const double rb = pb.boundingRadius() + (pb.center()).norm();
      if ((ca - cb).norm() - ra - rb > best) continue;
      best = std::min(best, signedDistanceOfPieces(pa, poseA, pb, poseB));
    }
  }
  return best;
}

bool firstInterpenetration(const std::function<double(double)>& d, double lipschitz, double threshold, double t0,
                           double t1) {
  reference::ContactSearch search;
  search.t0 = t0;
  search.t1 = t1;
  search.samples = 8;
  search.resolution = (t1 - t0) * 1e-6;
  search.maxDepth = 24;
  const Real t = reference::firstContact([&](Real t) { return Real(d(double(t))); }, Real(lipschitz), Real(threshold),
                                         search);
  return t >= 0;
}

}  // namespace gjkx
