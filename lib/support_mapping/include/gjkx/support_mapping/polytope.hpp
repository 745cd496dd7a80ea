/// @file
/// @brief The convex polytope and its supporting vertex by hill climbing (§2.1).
#pragma once

#include <gjkx/support_mapping/convex_hull.hpp>
#include <gjkx/support_mapping/support.hpp>

#include <algorithm>
#include <memory>
#include <vector>

namespace gjkx {

/// A convex polytope X, the convex hull of a point set, with the adjacency of its vertices.
///
/// §2.1: "\f$S_X(\vec{s}) \in \mathrm{vert}(X)\f$ where \f$\vec{s}\cdot S_X(\vec{s}) =
/// \max\{\vec{s}\cdot x : x \in \mathrm{vert}(X)\}\f$ [...] It can be found efficiently with a
/// technique called *hill climbing*, which uses adjacency information of each vertex
/// to search for a local (and also global) maximum." On a convex polytope a vertex
/// that no neighbour beats along s is a global maximum, so the climb is exact. Started
/// from the vertex found by the previous query (the hint), it costs a few dot products
/// when the direction changed little: GJK's temporal coherence.
///
/// Copies are cheap: the vertex data is shared and never changes.
template <typename S>
class Polytope {
 public:
  /// The scalar type.
  using Scalar = S;

  /// The convex hull of a solid point set (Qhull). Throws std::invalid_argument
  /// ("polytope.points: ...") for a non-finite point, fewer than 4 points, or a flat set.
  static Polytope hull(const std::vector<Vector3<S>>& points) {
    return Polytope(convexHull3d(toDouble(points), "polytope.points"));
  }

  /// The hull of a triangular prism (convex_hull.hpp's prismHull): a triangle's three
  /// points and their copies moved off its plane, in that order; no Qhull call. Points that
  /// are no prism to within round-off get Qhull's hull (`hull`), and its errors.
  static Polytope prism(const std::vector<Vector3<S>>& points) {
    const std::vector<Eigen::Vector3d> exact = toDouble(points);
    const std::optional<ConvexHull> known = prismHull(exact, "polytope.points");
    return Polytope(known ? *known : convexHull3d(exact, "polytope.points"));
  }

  /// The convex polygon spanned by points in the plane z = 0, for the paper's 2D
  /// figures (a 2D set is a 3D set in the plane z = 0). Throws std::invalid_argument
  /// ("polygon.points: ...") for a non-finite point, z != 0, fewer than 3 points or a line.
  static Polytope polygon(const std::vector<Vector3<S>>& points) {
    return Polytope(convexHull2d(toDouble(points), "polygon.points"));
  }

  /// \f$S_X(\vec{s})\f$ by hill climbing from vertex 0.
  Vector3<S> support(const Vector3<S>& s) const {
    SupportHint hint = 0;
    return support(s, hint);
  }

  /// \f$S_X(\vec{s})\f$ by hill climbing from `hint`; on return `hint` is the vertex found.
  /// Steepest ascent: move to the best neighbour while it is strictly better along s.
  Vector3<S> support(const Vector3<S>& s, SupportHint& hint) const {
    hint = climb(s, hint, nullptr);
    return data_->vertices[hint];
  }

  /// The hill-climbing path from `hint` to the supporting vertex, vertex by vertex
  /// (drawn by chapter 01).
  std::vector<int> climbPath(const Vector3<S>& s, SupportHint hint) const {
    std::vector<int> path;
    climb(s, hint, &path);
    return path;
  }

  /// \f$S_X(\vec{s})\f$ by looking at every vertex: the reference the tests hold hill climbing to.
  int supportIndexLinearScan(const Vector3<S>& s) const {
    // Fix (tests): s·(x - c) from the centred vertices, as in climb() below, so that the
    // reference keeps its accuracy for a polytope far from the origin.
    int best = 0;
    S bestValue = s.dot(data_->centred[0]);
    for (int v = 1; v < vertexCount(); ++v) {
      const S value = s.dot(data_->centred[v]);
      if (value > bestValue) {
        bestValue = value;
        best = v;
      }
    }
    return best;
  }

  /// The centroid of the vertices (a point inside).
  Vector3<S> center() const { return data_->centroid; }
  /// The largest distance of a vertex from the body origin (§3, certified margin).
  S boundingRadius() const { return data_->radius; }
  /// The number of hull vertices.
  int vertexCount() const { return static_cast<int>(data_->vertices.size()); }
  /// Hull vertex v.
  const Vector3<S>& vertex(int v) const { return data_->vertices[v]; }
  /// All hull vertices.
  const std::vector<Vector3<S>>& vertices() const { return data_->vertices; }
  /// The boundary triangles (counter-clockwise seen from outside; for a polygon, a fan facing +z).
  const std::vector<std::array<int, 3>>& triangles() const { return data_->triangles; }
  /// The vertices that share an edge with v.
  std::vector<int> neighbours(int v) const {
    return std::vector<int>(data_->neighbours.begin() + data_->firstNeighbour[v],
                            data_->neighbours.begin() + data_->firstNeighbour[v + 1]);
  }
  /// True for a polygon in the plane z = 0.
  bool planar() const { return data_->planar; }

 private:
  struct Data {
    std::vector<Vector3<S>> vertices;
    std::vector<Vector3<S>> centred;  // vertices - centroid, for the climb's comparisons
    std::vector<int> firstNeighbour, neighbours;
    // The rings of neighbours again, with their centred coordinates beside them, one
    // array per coordinate, in the order of `neighbours` (speed: a climb step then reads
    // a ring as three runs of numbers, not an index and then a vertex elsewhere).
    std::vector<S> ringX, ringY, ringZ;
    std::vector<std::array<int, 3>> triangles;
    Vector3<S> centroid;
    bool planar;
    S radius;
  };

  explicit Polytope(const ConvexHull& hull) {
    auto data = std::make_shared<Data>();
    data->centroid = Vector3<S>::Zero();
    for (const auto& v : hull.vertices) {
      data->vertices.push_back(v.cast<S>());
      data->centroid += data->vertices.back();
    }
    data->centroid /= S(hull.vertices.size());
    for (const auto& v : data->vertices) data->centred.push_back(v - data->centroid);
    data->radius = S(0);
    for (const auto& v : data->vertices) data->radius = std::max(data->radius, v.norm());
    data->firstNeighbour = hull.firstNeighbour;
    data->neighbours = hull.neighbours;
    for (const int n : data->neighbours) {
      data->ringX.push_back(data->centred[n].x());
      data->ringY.push_back(data->centred[n].y());
      data->ringZ.push_back(data->centred[n].z());
    }
    data->triangles = hull.triangles;
    data->planar = hull.planar;
    data_ = std::move(data);
  }

  static std::vector<Eigen::Vector3d> toDouble(const std::vector<Vector3<S>>& points) {
    std::vector<Eigen::Vector3d> out;
    out.reserve(points.size());
    for (const auto& p : points) out.push_back(p.template cast<double>());
    return out;
  }

  int climb(const Vector3<S>& s, int start, std::vector<int>* path) const {
    const Data& d = *data_;
    int v = (start >= 0 && start < vertexCount()) ? start : 0;
    // Fix (tests): compare s·(x - c), not s·x, c the centroid. For a polytope far from the
    // origin (coordinates near 10^5 in float) s·x rounds to a grid coarser than the gain of
    // an uphill edge, the neighbour then ties and the climb stopped far below the top
    // (shortfalls of nearly the polytope's diameter were seen). The vertices are kept
    // relative to c as well (`centred`, rounded once, to the precision of the polytope's
    // size), so the values keep that precision at no cost per step; each vertex has one
    // value, so the climb rises strictly and always ends.
    const S sx = s.x(), sy = s.y(), sz = s.z();
    // Every value by the one expression below, so that a vertex has one value wherever it is read.
    S best = sx * d.centred[v].x() + sy * d.centred[v].y() + sz * d.centred[v].z();
    if (path) path->push_back(v);
    for (;;) {
      int bestK = -1;
      const int end = d.firstNeighbour[v + 1];
      for (int k = d.firstNeighbour[v]; k < end; ++k) {
        const S value = sx * d.ringX[k] + sy * d.ringY[k] + sz * d.ringZ[k];  // s · (neighbour - c)
        if (value > best) {
          best = value;
          bestK = k;
        }
      }
      if (bestK < 0) return v;  // no neighbour is better: a local, hence global, maximum
      v = d.neighbours[bestK];
      if (path) path->push_back(v);
    }
  }

  std::shared_ptr<const Data> data_;
};

}  // namespace gjkx
