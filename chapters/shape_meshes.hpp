// Convex shapes as the triangle meshes the 3D figures draw: a curved shape (a sphere, a
// capsule, a cylinder) from nothing but its support mapping, the hull of its support points
// over many directions (§2.1); a polytope from its own hull. Chapter 01 draws its shapes
// with them, gjkx_animate the bodies of any scene.
#pragma once

#include <gjkx/render/canvas.hpp>
#include <gjkx/support_mapping/polytope.hpp>

#include <cmath>
#include <vector>

namespace chapter {

/// `n` directions spread evenly over the unit sphere (a Fibonacci lattice).
inline std::vector<gjkx::Vector3<double>> sphereDirections(int n) {
  std::vector<gjkx::Vector3<double>> dirs;
  const double golden = M_PI * (3 - std::sqrt(5.0));
  for (int k = 0; k < n; ++k) {
    const double z = 1 - 2 * (k + 0.5) / n, r = std::sqrt(1 - z * z);
    dirs.emplace_back(r * std::cos(golden * k), r * std::sin(golden * k), z);
  }
  return dirs;
}

/// The mesh of a convex polytope: its hull's vertices and triangles.
inline gjkx::render::Mesh meshOf(const gjkx::Polytope<double>& polytope) {
  return gjkx::render::Mesh{polytope.vertices(), polytope.triangles()};
}

/// The mesh of a solid convex shape, from nothing but its support mapping: the hull of its
/// support points in `directions` directions.
template <typename X>
gjkx::render::Mesh meshFromSupport(const X& shape, int directions = 600) {
  std::vector<gjkx::Vector3<double>> points;
  for (const auto& s : sphereDirections(directions)) points.push_back(shape.support(s));
  return meshOf(gjkx::Polytope<double>::hull(points));
}

}  // namespace chapter
