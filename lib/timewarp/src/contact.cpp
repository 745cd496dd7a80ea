// The contact patch of two bodies (contact.hpp).
#include <gjkx/timewarp/contact.hpp>

#include <type_traits>

namespace gjkx {

std::vector<Eigen::Vector3d> touchingFeature(const Shape<double>& shape, const Pose<double>& pose,
                                             const Eigen::Vector3d& direction, double depth) {
  std::vector<Eigen::Vector3d> candidates;
  double radius = 0;
  std::visit(
      [&](const auto& x) {
        using X = std::decay_t<decltype(x)>;
        if constexpr (std::is_same_v<X, Box<double>>) {
          for (int k = 0; k < 8; ++k)
            candidates.push_back(Eigen::Vector3d((k & 1) ? x.halfExtents.x() : -x.halfExtents.x(),
                                                 (k & 2) ? x.halfExtents.y() : -x.halfExtents.y(),
                                                 (k & 4) ? x.halfExtents.z() : -x.halfExtents.z()));
        } else if constexpr (std::is_same_v<X, Polytope<double>>) {
          for (int v = 0; v < x.vertexCount(); ++v) candidates.push_back(x.vertex(v));
        } else if constexpr (std::is_same_v<X, Capsule<double>>) {
          candidates = {x.axis.a, x.axis.b};
          radius = x.radius;
        } else if constexpr (std::is_same_v<X, Sphere<double>>) {
          candidates = {Eigen::Vector3d::Zero()};
          radius = x.radius;
        } else {
          candidates = {x.support(pose.toBodyDirection(direction))};
        }
      },
      shape.variant());
  double highest = -std::numeric_limits<double>::infinity();
  for (auto& p : candidates) {
    p = pose(p);
    highest = std::max(highest, direction.dot(p));
  }
  std::vector<Eigen::Vector3d> feature;
  for (const auto& p : candidates)
    if (direction.dot(p) >= highest - depth) feature.push_back(p + radius * direction);
  return feature;
}

namespace {

double diameter(const std::vector<Eigen::Vector3d>& points) {
  double d = 0;
  for (const auto& p : points)
    for (const auto& q : points) d = std::max(d, (p - q).norm());
  return d;
}

Eigen::Vector3d centroid(const std::vector<Eigen::Vector3d>& points) {
  Eigen::Vector3d c = Eigen::Vector3d::Zero();
  for (const auto& p : points) c += p;
  return c / double(points.size());
}

}  // namespace

Eigen::Vector3d contactPoint(const Shape<double>& shapeA, const Pose<double>& poseA, const Shape<double>& shapeB,
                             const Pose<double>& poseB, const Eigen::Vector3d& pointA, const Eigen::Vector3d& pointB,
                             const Eigen::Vector3d& normal, double depth) {
  const Eigen::Vector3d middle = 0.5 * (pointA + pointB);
  const auto featureA = touchingFeature(shapeA, poseA, normal, depth);
  const auto featureB = touchingFeature(shapeB, poseB, -normal, depth);
  const auto& patch = diameter(featureA) <= diameter(featureB) ? featureA : featureB;
  if (patch.empty()) return middle;
  const Eigen::Vector3d c = centroid(patch);
  return c + normal * normal.dot(middle - c);  // onto the plane midway between the closest points
}

}  // namespace gjkx
