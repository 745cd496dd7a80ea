/// @file
/// @brief The convex hull of a point set, through Qhull: the data a polytope's hill climbing needs (§2.1).
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <array>
#include <optional>
#include <vector>

namespace gjkx {

/// A convex hull: its vertices, its triangulated boundary and which vertices share an edge.
struct ConvexHull {
  /// Hull vertices (a subset of the input points, in input order).
  std::vector<Eigen::Vector3d> vertices;
  /// For each hull vertex, the index of the input point it came from.
  std::vector<int> inputIndex;
  /// Boundary triangles (indices into `vertices`), counter-clockwise seen from outside.
  /// For a planar hull: the polygon fanned into triangles, facing +z.
  std::vector<std::array<int, 3>> triangles;
  /// Vertex adjacency in compressed rows: the neighbours of vertex v are
  /// `neighbours[firstNeighbour[v] .. firstNeighbour[v + 1])`.
  std::vector<int> firstNeighbour;
  /// See `firstNeighbour`.
  std::vector<int> neighbours;
  /// True for a convex polygon in the plane z = 0 (a 2D figure's shape).
  bool planar = false;
};

/// The convex hull of a solid point set (Qhull). Throws std::invalid_argument naming
/// `field` if a point is not finite, there are fewer than 4 points, or all points lie
/// in one plane to within round-off (no volume: thinner than 64 round-offs of the
/// coordinates). A thin set (thinner than 1e-6 of its length, where Qhull could leave
/// points out) gets its exact hull all the same: Qhull runs on the set stretched to a fat
/// one, which has the same hull. Every hull is checked against its input: one that
/// leaves an input point outside a boundary plane by more than round-off throws,
/// never returns.
ConvexHull convexHull3d(const std::vector<Eigen::Vector3d>& points, const char* field = "polytope.points");

/// The hull of a triangular prism: `points` are a triangle a, b, c and its copy a', b', c'
/// moved off its plane (a static mesh's piece at the polygonal level, §6). Its faces are
/// known, so no Qhull call is needed (the torso's plant has 8,640 such pieces): all six
/// points in input order, the two triangles, and each side quad split along its convex
/// diagonal; every corner is checked to lie on or below every face, as convexHull3d checks
/// Qhull's. Nothing (std::nullopt) when the points are no prism to within round-off (a
/// triangle with no area, a copy near its plane): Polytope::prism then asks convexHull3d.
/// Throws std::invalid_argument naming `field` for a non-finite point or other than 6 points.
std::optional<ConvexHull> prismHull(const std::vector<Eigen::Vector3d>& points, const char* field = "polytope.points");

/// The convex hull of points in the plane z = 0 (Qhull in 2D), a convex polygon whose
/// vertices are in counter-clockwise order, each adjacent to the next. Throws
/// std::invalid_argument naming `field` if a point is not finite or has z != 0, there
/// are fewer than 3 points, or all points lie on one line.
ConvexHull convexHull2d(const std::vector<Eigen::Vector3d>& points, const char* field = "polygon.points");

}  // namespace gjkx
