// The GJK tests' bridge to the exact references (gjkx::reference, long double): the
// library's vectors, point sets and posed polytopes as the references take them. The
// conversions live here, in the tests, because the reference library links no stage.
#pragma once

#include <gjkx/motion/pose.hpp>
#include <gjkx/reference/closest_points.hpp>
#include <gjkx/reference/polytope_distance.hpp>
#include <gjkx/support_mapping/polytope.hpp>

#include <array>
#include <vector>

namespace gjkx::test {

using Real = reference::Real;
using RVec = reference::Vec;

template <typename S>
RVec toReal(const Vector3<S>& v) {
  return v.template cast<Real>();
}

/// The closest point of conv(points) (at most 4) to the origin, by the reference's brute force.
template <typename S>
reference::HullPoint closestToOrigin(const std::vector<Vector3<S>>& points) {
  std::array<RVec, 4> w;
  for (std::size_t k = 0; k < points.size(); ++k) w[k] = toReal(points[k]);
  return reference::closestToOrigin(w, static_cast<int>(points.size()));
}

/// The polytope's vertices mapped by the pose in long double, from the very same float or
/// double numbers GJK sees, with its triangles.
template <typename S>
reference::WorldPolytope toWorld(const Polytope<S>& shape, const Pose<S>& pose) {
  const Eigen::Matrix<Real, 3, 3> R = pose.rotation.template cast<Real>();
  const RVec t = toReal(pose.translation);
  std::vector<RVec> vertices;
  for (const auto& v : shape.vertices()) vertices.push_back(R * toReal(v) + t);
  return reference::WorldPolytope::fromTriangles(std::move(vertices), shape.triangles());
}

}  // namespace gjkx::test
