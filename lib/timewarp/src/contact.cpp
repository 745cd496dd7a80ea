// The contact patch of two bodies (contact.hpp).
#include <gjkx/timewarp/contact.hpp>

#include <algorithm>
#include <limits>
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

ContactPatch contactPatch(const Shape<double>& shapeA, const Pose<double>& poseA, const Shape<double>& shapeB,
                          const Pose<double>& poseB, const Eigen::Vector3d& pointA, const Eigen::Vector3d& pointB,
                          const Eigen::Vector3d& normal, double depth) {
  const Eigen::Vector3d middle = 0.5 * (pointA + pointB);
  const auto featureA = touchingFeature(shapeA, poseA, normal, depth);
  const auto featureB = touchingFeature(shapeB, poseB, -normal, depth);
  // The closest points lie on the touching features, so a feature that does not reach
  // them is no contact: a corner of a floor 6 m wide is within `depth` of its top plane
  // along a normal tilted by 1e-4 (float's noise), but it touches nothing.
  const auto reaches = [&](const std::vector<Eigen::Vector3d>& feature) {
    double nearest = std::numeric_limits<double>::infinity();
    for (const auto& p : feature) nearest = std::min(nearest, ((p - middle) - normal * normal.dot(p - middle)).norm());
    return nearest <= diameter(feature) + 2 * depth;
  };
  const bool a = reaches(featureA), b = reaches(featureB);
  static const std::vector<Eigen::Vector3d> none;
  const auto& patch = a && b ? (diameter(featureA) <= diameter(featureB) ? featureA : featureB)
                             : a ? featureA : b ? featureB : none;
  ContactPatch out;
  if (patch.empty()) {
    out.centre = middle;
    out.points = {middle};
    return out;
  }
  // Onto the plane midway between the closest points.
  for (const auto& p : patch) out.points.push_back(p + normal * normal.dot(middle - p));
  out.centre = centroid(out.points);
  return out;
}

}  // namespace gjkx
