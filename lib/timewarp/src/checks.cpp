// The independent checks (checks.hpp).
#include <gjkx/timewarp/checks.hpp>

#include <gjkx/gjk/gjk.hpp>
#include <gjkx/reference/polytope_distance.hpp>
#include <gjkx/reference/time_of_impact.hpp>

#include <algorithm>
#include <limits>
#include <tuple>
#include <vector>
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

/// The radius of a sphere about the shape's centre that holds it.
double radiusAboutCentre(const Shape<double>& shape) {
  return std::visit(
      [](const auto& x) {
        using X = std::decay_t<decltype(x)>;
        if constexpr (std::is_same_v<X, Polytope<double>>) {
          double r = 0;
          for (const auto& v : x.vertices()) r = std::max(r, (v - x.center()).norm());
          return r;
        } else {
          return double(x.boundingRadius()) + double(x.center().norm());
        }
      },
      shape.variant());
}

}  // namespace

double referenceSignedDistance(const WorldBody& a, const Pose<double>& poseA, const WorldBody& b,
                               const Pose<double>& poseB) {
  if (a.pieces.size() == 1 && b.pieces.size() == 1) return signedDistanceOfPieces(a.pieces[0], poseA, b.pieces[0], poseB);
  // Bodies of several convex pieces: the least over the piece pairs (the deepest
  // penetration). The pairs are taken nearest first by the gap between their bounding
  // spheres, a lower bound on their distance, and the search stops once that bound
  // exceeds the best found: a static plant of 8,640 pieces then costs a few exact
  // distances, not 8,640 per bone piece.
  struct Candidate {
    double bound;
    int a, b;
  };
  std::vector<Candidate> candidates;
  candidates.reserve(a.pieces.size() * b.pieces.size());
  std::vector<Eigen::Vector3d> centresB;
  std::vector<double> radiiB;
  for (const auto& pb : b.pieces) {
    centresB.push_back(poseB(pb.center()));
    radiiB.push_back(radiusAboutCentre(pb));
  }
  for (int ia = 0; ia < int(a.pieces.size()); ++ia) {
    const Eigen::Vector3d ca = poseA(a.pieces[ia].center());
    const double ra = radiusAboutCentre(a.pieces[ia]);
    for (int ib = 0; ib < int(b.pieces.size()); ++ib)
      candidates.push_back({(ca - centresB[ib]).norm() - ra - radiiB[ib], ia, ib});
  }
  // The nearest-looking pair's distance bounds the answer: only pairs that may beat it are sorted.
  const auto byBound = [](const Candidate& x, const Candidate& y) {
    return std::tie(x.bound, x.a, x.b) < std::tie(y.bound, y.a, y.b);
  };
  const Candidate first = *std::min_element(candidates.begin(), candidates.end(), byBound);
  double best = signedDistanceOfPieces(a.pieces[first.a], poseA, b.pieces[first.b], poseB);
  candidates.erase(std::remove_if(candidates.begin(), candidates.end(),
                                  [&](const Candidate& c) { return c.bound > best; }),
                   candidates.end());
  std::sort(candidates.begin(), candidates.end(), byBound);
  for (const Candidate& c : candidates) {
    if (c.bound > best) break;
    best = std::min(best, signedDistanceOfPieces(a.pieces[c.a], poseA, b.pieces[c.b], poseB));
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
