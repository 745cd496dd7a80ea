// The independent checks' distances (reference_body.hpp).
#include <gjkx/verify/reference_body.hpp>

#include <gjkx/gjk/gjk.hpp>
#include <gjkx/support_mapping/placed.hpp>
#include <gjkx/reference/polytope_distance.hpp>
#include <gjkx/reference/time_of_impact.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <queue>
#include <stdexcept>
#include <string>
#include <tuple>
#include <type_traits>
#include <unordered_map>
#include <utility>
#include <vector>

namespace gjkx {

namespace {

using reference::Cloud;
using reference::Real;
using reference::Vec;

constexpr double kInfinity = std::numeric_limits<double>::infinity();

/// A piece as the bounds and the reference see it, in the body frame (ReferenceBody::Piece).
/// The reference measures spheres, capsules, boxes and polytopes of up to 16 vertices;
/// GJK the rest (larger polytopes, cylinders).
ReferenceBody::Piece pieceOf(const Shape<double>& shape) {
  ReferenceBody::Piece piece;
  std::visit(
      [&](const auto& x) {
        using X = std::decay_t<decltype(x)>;
        if constexpr (std::is_same_v<X, Box<double>>) {
          for (int k = 0; k < 8; ++k)
            piece.points.emplace_back((k & 1) ? x.halfExtents.x() : -x.halfExtents.x(),
                                      (k & 2) ? x.halfExtents.y() : -x.halfExtents.y(),
                                      (k & 4) ? x.halfExtents.z() : -x.halfExtents.z());
          for (int k = 0; k < 3; ++k) {
            piece.normals.push_back(Eigen::Vector3d::Unit(k));
            piece.normals.push_back(-Eigen::Vector3d::Unit(k));
          }
          for (int k = 0; k < 8; ++k)
            for (int bit = 1; bit < 8; bit <<= 1)
              if (!(k & bit)) piece.edges.push_back({k, k | bit});
          piece.exact = true;
        } else if constexpr (std::is_same_v<X, Sphere<double>>) {
          piece.points.push_back(Eigen::Vector3d::Zero());
          piece.radius = x.radius;
          piece.edges.push_back({0, 0});
          piece.exact = true;
        } else if constexpr (std::is_same_v<X, Capsule<double>>) {
          piece.points.push_back(x.axis.a);
          piece.points.push_back(x.axis.b);
          piece.radius = x.radius;
          piece.edges.push_back({0, 1});
          piece.exact = true;
        } else if constexpr (std::is_same_v<X, Polytope<double>>) {
          piece.points = x.vertices();
          // Any unit s gives a lower bound: the normals only make it tight, so a flat
          // polygon (no outward side) takes both of its normals.
          for (const auto& t : x.triangles()) {
            for (int k = 0; k < 3; ++k) {
              const std::array<int, 2> edge{std::min(t[k], t[(k + 1) % 3]), std::max(t[k], t[(k + 1) % 3])};
              if (std::find(piece.edges.begin(), piece.edges.end(), edge) == piece.edges.end()) piece.edges.push_back(edge);
            }
            const Eigen::Vector3d n = (x.vertex(t[1]) - x.vertex(t[0])).cross(x.vertex(t[2]) - x.vertex(t[0]));
            if (!(n.norm() > 0)) continue;
            for (const double sign : {1.0, -1.0}) {
              const Eigen::Vector3d unit = sign * n.normalized();
              // Coplanar triangles of one face give one normal.
              if (std::none_of(piece.normals.begin(), piece.normals.end(),
                               [&](const Eigen::Vector3d& m) { return m.dot(unit) > 1 - 1e-12; }))
                piece.normals.push_back(unit);
              if (!x.planar()) break;
            }
          }
          piece.exact = x.vertexCount() <= 16;
        } else if constexpr (std::is_same_v<X, Cylinder<double>>) {
          // The reference measures hulls of points swept by a ball, which a cylinder is not
          // (flat caps, sharp rims): GJK measures it (not exact), and its bounds come from
          // the prism on the regular 16-gon circumscribed about its cross-section, which
          // holds it (the 16-gon's corners lie at r / cos(pi/16)), so every bound stays a
          // lower bound. Its faces give the normals: the caps' and the 16 sides'.
          constexpr int n = 16;
          const double outer = x.radius / std::cos(M_PI / n);
          for (int k = 0; k < n; ++k) {
            const double angle = 2 * M_PI * k / n;
            for (const double z : {-x.halfLength, x.halfLength})
              piece.points.emplace_back(outer * std::cos(angle), outer * std::sin(angle), z);
            const double mid = angle + M_PI / n;
            piece.normals.emplace_back(std::cos(mid), std::sin(mid), 0.0);
            const int bottom = 2 * k, top = 2 * k + 1, nextBottom = 2 * ((k + 1) % n), nextTop = nextBottom + 1;
            piece.edges.push_back({bottom, top});
            piece.edges.push_back({std::min(bottom, nextBottom), std::max(bottom, nextBottom)});
            piece.edges.push_back({std::min(top, nextTop), std::max(top, nextTop)});
          }
          piece.normals.push_back(Eigen::Vector3d::UnitZ());
          piece.normals.push_back(-Eigen::Vector3d::UnitZ());
          piece.exact = false;
        } else if constexpr (std::is_same_v<X, Point<double>>) {
          piece.points.push_back(x.a);
          piece.edges.push_back({0, 0});
        } else if constexpr (std::is_same_v<X, Segment<double>>) {
          piece.points = {x.a, x.b};
          piece.edges.push_back({0, 1});
        } else {
          static_assert(std::is_same_v<X, Triangle<double>>, "a shape the checks do not know");
          piece.points = {x.a, x.b, x.c};
          piece.edges = {{0, 1}, {1, 2}, {0, 2}};
        }
      },
      shape.variant());
  piece.centre = shape.center();
  for (const auto& p : piece.points) piece.sphereRadius = std::max(piece.sphereRadius, (p - piece.centre).norm());
  piece.sphereRadius += piece.radius;
  return piece;
}

/// A piece placed in the world: its points mapped by the pose in double (the reference
/// then widens them to long double: the same arithmetic for every caller, so a pair
/// measured through a ReferenceBody and through referencePieceDistance agrees to the bit).
struct PlacedPiece {
  std::vector<Eigen::Vector3d> points;
  std::vector<Eigen::Vector3d> normals;
  Eigen::Vector3d centre;
  double radius = 0;
  Cloud cloud() const {
    Cloud c;
    c.points.reserve(points.size());
    for (const auto& p : points) c.points.push_back(p.cast<Real>());
    c.radius = radius;
    return c;
  }
};

PlacedPiece placed(const ReferenceBody::Piece& piece, const Pose<double>& pose) {
  PlacedPiece out;
  out.points.reserve(piece.points.size());
  for (const auto& p : piece.points) out.points.push_back(pose(p));
  out.normals.reserve(piece.normals.size());
  for (const auto& n : piece.normals) out.normals.push_back(pose.rotation * n);
  out.centre = pose(piece.centre);
  out.radius = piece.radius;
  return out;
}

/// The piece pair's signed distance: the reference on clouds, GJK in double otherwise.
double pieceDistance(const ReferenceBody::Piece& a, const PlacedPiece& placedA, const Shape<double>& shapeA,
                     const Pose<double>& poseA, const ReferenceBody::Piece& b, const PlacedPiece& placedB,
                     const Shape<double>& shapeB, const Pose<double>& poseB) {
  if (a.exact && b.exact) return double(reference::signedDistance(placedA.cloud(), placedB.cloud()));
  const auto g = gjk(Placed<Shape<double>>{shapeA, poseA}, Placed<Shape<double>>{shapeB, poseB});
  return g.status == GjkStatus::Overlapping ? 0.0 : g.distance;
}

/// min_b s.b - max_a s.a over the pieces' points (their radii not taken off).
double supportGap(const PlacedPiece& a, const PlacedPiece& b, const Eigen::Vector3d& s) {
  double maxA = -kInfinity, minB = kInfinity;
  for (const auto& x : a.points) maxA = std::max(maxA, s.dot(x));
  for (const auto& y : b.points) minB = std::min(minB, s.dot(y));
  return minB - maxA;
}

/// The supporting distance SD(s) = min_b s.b - max_a s.a - rA - rB (§2.3) of two placed
/// pieces: a lower bound of their signed distance for every unit s. The largest over a
/// few directions: the line of their centres (never below the gap of their bounding
/// spheres) and, when `faces`, the outward face normals of a and, reversed, of b (the
/// separating axes that decide a face against a vertex, and a shallow overlap).
double supportingDistance(const PlacedPiece& a, const PlacedPiece& b, bool faces) {
  double best = -kInfinity;
  const Eigen::Vector3d line = b.centre - a.centre;
  const double n = line.norm();
  if (n > 0 && std::isfinite(n)) best = std::max(best, supportGap(a, b, line / n));
  if (faces) {
    for (const auto& s : a.normals) best = std::max(best, supportGap(a, b, s));
    for (const auto& s : b.normals) best = std::max(best, supportGap(a, b, -s));
  }
  return best - a.radius - b.radius;
}

/// The closest points of the segments [p1, q1] and [p2, q2] (a segment may be a point), by
/// GJK's closed form for segment cores (gjk.hpp, closestParametersOfSegments), in double.
/// Only a direction is wanted of them, and any direction gives a valid bound, so the
/// checks' answer does not rest on it; the reference's long-double copy costs twice the
/// checks' whole time on the torso in this loop over edge pairs.
std::pair<Eigen::Vector3d, Eigen::Vector3d> closestOnSegments(const Eigen::Vector3d& p1, const Eigen::Vector3d& q1,
                                                              const Eigen::Vector3d& p2, const Eigen::Vector3d& q2) {
  const auto [u, v] = detail::closestParametersOfSegments(CoreEnds<double>{p1, q1}, CoreEnds<double>{p2, q2});
  return {p1 + u * (q1 - p1), p2 + v * (q2 - p2)};
}

/// SD along the line between the closest points of the nearest pair of edges of a and b
/// (an edge may be a single point): for disjoint pieces, the direction of their distance
/// when the closest points lie on edges (vertex against vertex, vertex against edge, edge
/// against edge), where the directions of supportingDistance fall short; together they
/// make the bound nearly the distance. An edge pair is skipped when the spheres about
/// the edges are farther apart than the nearest pair found.
double edgeSupportingDistance(const ReferenceBody::Piece& pieceA, const PlacedPiece& a,
                              const ReferenceBody::Piece& pieceB, const PlacedPiece& b) {
  double nearest = kInfinity;
  Eigen::Vector3d line = Eigen::Vector3d::Zero();
  for (const auto& ea : pieceA.edges) {
    const Eigen::Vector3d &p1 = a.points[ea[0]], &q1 = a.points[ea[1]];
    const Eigen::Vector3d middle1 = (p1 + q1) / 2;
    const double half1 = (q1 - p1).norm() / 2;
    for (const auto& eb : pieceB.edges) {
      const Eigen::Vector3d &p2 = b.points[eb[0]], &q2 = b.points[eb[1]];
      if ((p2 + q2 - 2 * middle1).norm() / 2 - half1 - (q2 - p2).norm() / 2 >= nearest) continue;
      const auto [x, y] = closestOnSegments(p1, q1, p2, q2);
      const double d = (y - x).norm();
      if (d < nearest) {
        nearest = d;
        line = y - x;
      }
    }
  }
  const double n = line.norm();
  if (!(n > 0) || !std::isfinite(n)) return -kInfinity;
  return supportGap(a, b, line / n) - a.radius - b.radius;
}

/// How far a rotation matrix is from orthonormal (|R^T R - I|, Frobenius): a pose's
/// rotation may stretch a body by about this much, which the bounds below must allow for.
double stretch(const Pose<double>& pose) {
  return (pose.rotation.transpose() * pose.rotation - Eigen::Matrix3d::Identity()).norm();
}

/// The distance of point c from the box [lo, hi] (0 inside).
double boxGap(const Eigen::Vector3d& c, const Eigen::Vector3d& lo, const Eigen::Vector3d& hi) {
  return (c.cwiseMax(lo).cwiseMin(hi) - c).norm();
}

}  // namespace

double referencePieceDistance(const Shape<double>& a, const Pose<double>& poseA, const Shape<double>& b,
                              const Pose<double>& poseB) {
  const ReferenceBody::Piece pieceA = pieceOf(a), pieceB = pieceOf(b);
  return pieceDistance(pieceA, placed(pieceA, poseA), a, poseA, pieceB, placed(pieceB, poseB), b, poseB);
}

// ---------------------------------------------------------------------------------------
// ReferenceBody: the pieces prepared once

ReferenceBody::ReferenceBody(const std::string& name, const std::vector<Shape<double>>& pieces) : shapes_(pieces) {
  if (shapes_.empty()) throw std::invalid_argument("ReferenceBody: body '" + name + "' has no pieces");
  for (std::size_t k = 0; k < shapes_.size(); ++k) {
    pieces_.push_back(pieceOf(shapes_[k]));
    const Piece& piece = pieces_.back();
    if (!piece.centre.allFinite() || !std::isfinite(piece.sphereRadius))
      throw std::invalid_argument("ReferenceBody: body '" + name + "': piece " + std::to_string(k) +
                                  " is not finite");
    extent_ = std::max(extent_, piece.centre.norm() + piece.sphereRadius);
    order_.push_back(int(k));
  }
  nodes_.reserve(2 * pieces_.size());
  build(0, int(pieces_.size()));
}

/// Builds the node over order_[first, first + count) and returns its index: split at the
/// median centre along the box's longest side, down to 4 pieces a leaf.
int ReferenceBody::build(int first, int count) {
  const int index = int(nodes_.size());
  nodes_.emplace_back();
  Node node;
  node.first = first;
  node.count = count;
  node.lo = node.hi = pieces_[order_[first]].centre;
  for (int k = first; k < first + count; ++k) {
    const Piece& piece = pieces_[order_[k]];
    node.lo = node.lo.cwiseMin(piece.centre);
    node.hi = node.hi.cwiseMax(piece.centre);
    node.maxRadius = std::max(node.maxRadius, piece.sphereRadius);
  }
  if (count > 4) {
    int axis = 0;
    (node.hi - node.lo).maxCoeff(&axis);
    const int half = count / 2;
    // Ties by index: the same tree in every run.
    std::nth_element(order_.begin() + first, order_.begin() + first + half, order_.begin() + first + count,
                     [&](int x, int y) {
                       return std::make_pair(pieces_[x].centre[axis], x) < std::make_pair(pieces_[y].centre[axis], y);
                     });
    node.left = build(first, half);
    node.right = build(first + half, count - half);
  }
  nodes_[index] = node;
  return index;
}

// ---------------------------------------------------------------------------------------
// The least signed distance over piece pairs

double referenceSignedDistance(const ReferenceBody& a, const Pose<double>& poseA, const ReferenceBody& b,
                               const Pose<double>& poseB, double enough) {
  // The pieces of the body with fewer (the query) are searched against the other's tree,
  // in the tree body's frame; a pair is always measured as (a's piece, b's piece).
  const bool aQueries = a.pieceCount() <= b.pieceCount();
  const ReferenceBody& query = aQueries ? a : b;
  const ReferenceBody& tree = aQueries ? b : a;
  const Pose<double>& poseQuery = aQueries ? poseA : poseB;
  const Pose<double>& poseTree = aQueries ? poseB : poseA;
  const Pose<double> treeFromWorld = poseTree.inverse();

  // A bound is pruned only when it exceeds the least found by more than `margin`: the
  // bounds are computed in double, some in another frame than the reference's points
  // (round-off of a few ulps of the coordinates), and a rotation off orthonormal by δ
  // stretches a body by up to about δ its size; the margin is far more than either, far
  // less than any gap that matters.
  const double scale = poseA.translation.norm() + poseB.translation.norm() + a.extent_ + b.extent_;
  const double margin = 1e-9 * (1 + scale) + 2 * (stretch(poseA) + stretch(poseB)) * scale;
  // A NaN would fail every comparison below and leave the least at infinity, silently.
  if (!std::isfinite(margin))
    throw std::invalid_argument("referenceSignedDistance: a pose is not finite (poseA.translation " +
                                std::to_string(poseA.translation.norm()) + ", poseB.translation " +
                                std::to_string(poseB.translation.norm()) + ")");

  // The pieces placed in the world when first needed: a search looks at a few of the tree's.
  std::vector<std::optional<PlacedPiece>> queryPlaced(query.pieces_.size());
  std::unordered_map<int, PlacedPiece> treePlaced;
  auto queryPiece = [&](int q) -> const PlacedPiece& {
    if (!queryPlaced[q]) queryPlaced[q] = placed(query.pieces_[q], poseQuery);
    return *queryPlaced[q];
  };
  auto treePiece = [&](int p) -> const PlacedPiece& {
    auto found = treePlaced.find(p);
    if (found == treePlaced.end()) found = treePlaced.emplace(p, placed(tree.pieces_[p], poseTree)).first;
    return found->second;
  };

  // Best-first: entries ordered by a lower bound of the signed distance of a query piece
  // and (stage 0) a tree node, (stage 1) a tree piece bounded by their spheres, (stage 2)
  // a tree piece bounded by the supporting distance; popping a stage-2 entry measures the pair.
  struct Entry {
    double bound;
    int stage, q, item;
    bool operator>(const Entry& o) const {
      return std::tie(bound, stage, q, item) > std::tie(o.bound, o.stage, o.q, o.item);
    }
  };
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> heap;
  std::vector<Eigen::Vector3d> queryCentres;  // in the tree's frame
  for (int q = 0; q < query.pieceCount(); ++q) {
    queryCentres.push_back(treeFromWorld(poseQuery(query.pieces_[q].centre)));
    const ReferenceBody::Node& root = tree.nodes_[0];
    heap.push({boxGap(queryCentres[q], root.lo, root.hi) - query.pieces_[q].sphereRadius - root.maxRadius, 0, q, 0});
  }
  double best = kInfinity;
  while (!heap.empty()) {
    const Entry e = heap.top();
    if (e.bound > best + margin) break;  // no pair left can beat the least found
    // Every pair left is at least e.bound - margin apart, and so is every pair measured:
    // enough for a caller that asked only whether the distance is below `enough`.
    if (enough > -kInfinity && best >= enough && e.bound - margin >= enough) return std::min(best, e.bound - margin);
    heap.pop();
    const double reach = query.pieces_[e.q].sphereRadius;
    if (e.stage == 0) {
      const ReferenceBody::Node& node = tree.nodes_[e.item];
      if (node.left < 0) {
        for (int k = node.first; k < node.first + node.count; ++k) {
          const int p = tree.order_[k];
          const double bound = (queryCentres[e.q] - tree.pieces_[p].centre).norm() - reach - tree.pieces_[p].sphereRadius;
          if (bound <= best + margin) heap.push({bound, 1, e.q, p});
        }
      } else {
        for (const int child : {node.left, node.right}) {
          const ReferenceBody::Node& c = tree.nodes_[child];
          const double bound = boxGap(queryCentres[e.q], c.lo, c.hi) - reach - c.maxRadius;
          if (bound <= best + margin) heap.push({bound, 0, e.q, child});
        }
      }
      continue;
    }
    const PlacedPiece& pq = queryPiece(e.q);
    const PlacedPiece& pt = treePiece(e.item);
    const bool exact = query.pieces_[e.q].exact && tree.pieces_[e.item].exact;
    if (e.stage == 1) {
      // The faces' directions cost (faces x points) each: worth it before the reference
      // (n^3 m), not before GJK on a big piece, which costs about as much as a few of them.
      double bound = std::max(e.bound, aQueries ? supportingDistance(pq, pt, exact) : supportingDistance(pt, pq, exact));
      // The edges' directions cost (edges x edges): only for a pair the reference would measure.
      if (exact && bound <= best + margin)
        bound = std::max(bound, aQueries ? edgeSupportingDistance(query.pieces_[e.q], pq, tree.pieces_[e.item], pt)
                                         : edgeSupportingDistance(tree.pieces_[e.item], pt, query.pieces_[e.q], pq));
      if (bound <= best + margin) heap.push({bound, 2, e.q, e.item});
      continue;
    }
    const double d = aQueries ? pieceDistance(query.pieces_[e.q], pq, query.shapes_[e.q], poseA, tree.pieces_[e.item], pt,
                                              tree.shapes_[e.item], poseB)
                              : pieceDistance(tree.pieces_[e.item], pt, tree.shapes_[e.item], poseA, query.pieces_[e.q],
                                              pq, query.shapes_[e.q], poseB);
    best = std::min(best, d);
  }
  return best;
}

double firstInterpenetration(const std::function<double(double)>& d, double lipschitz, double threshold, double t0,
                             double t1) {
  // The search proves a gap free when d cannot dip to the threshold between its ends, and
  // reports a contact where a gap it cannot prove is narrower than its resolution. So the
  // resolution must be a time in which d changes by much less than the margin it proves:
  // a twentieth of |threshold| at the Lipschitz rate, not only a millionth of the frame.
  // (With the frame's millionth alone, a ball thrown at 10^6 m/s 2 mm above a box moved
  // 4 cm in one resolution, and its clean pass was reported as tunnelling.)
  reference::ContactSearch search;
  search.t0 = t0;
  search.t1 = t1;
  search.samples = 8;
  search.resolution = (t1 - t0) * 1e-6;
  if (lipschitz > 0) search.resolution = std::min(search.resolution, Real(0.05 * std::abs(threshold) / lipschitz));
  search.maxDepth = 60;
  const Real t = reference::firstContact([&](Real t) { return Real(d(double(t))); }, Real(lipschitz), Real(threshold),
                                         search);
  return double(t);
}

}  // namespace gjkx
