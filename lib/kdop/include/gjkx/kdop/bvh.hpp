/// @file
/// @brief The bounding volume hierarchy of a body's convex pieces, 14-DOPs at any pose (§6).
///
/// §6 puts the convex pieces of each nonconvex body into a hierarchy of 14-DOPs. Our
/// 14-DOPs are not stored: a body turns, and a 14-DOP of a turned body is not the turned
/// 14-DOP. Each node keeps instead the convex hull of its pieces (a `Polytope`), and its
/// 14-DOP at the body's pose comes from the hull's support mapping (`Kdop14`), exact
/// at every pose. With \f$\vec{d}_k = R^T\vec{a}_k\f$ the axis seen from the body,
/// \f[ hi_k = \max_{v} \vec{a}_k\cdot(Rv + p) = \vec{d}_k\cdot S_X(\vec{d}_k) + \vec{a}_k\cdot p, \f]
/// so a node costs 14 hill climbs in the body frame, started from last time's vertices.
///
/// **Construction: top-down, median split.** The pieces are sorted along the longest
/// extent of their centres and cut at the median, recursively. Why: the tree is
/// balanced (depth \f$\lceil\log_2 n\rceil\f$), so every query's descent is short and the
/// front's size is predictable; pieces from a decomposition are few (tens to hundreds)
/// and of similar size, where a surface-area heuristic, made for rays and skewed
/// primitive sizes, buys little; and the build is a few `nth_element` calls plus one
/// Qhull hull per node, of its two children's hull vertices. Bottom-up merging would give
/// tighter nodes at a quadratic cost. A static body's hierarchy keeps no inner hulls
/// (`InnerHulls::none`): at its one pose, an inner node's 14-DOP is its children's.
#pragma once

#include <gjkx/kdop/kdop.hpp>
#include <gjkx/motion/pose.hpp>
#include <gjkx/support_mapping/polytope.hpp>

#include <algorithm>
#include <numeric>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace gjkx {

/// A node of the hierarchy.
template <typename S>
struct BvhNode {
  /// The convex hull of the node's pieces (for a leaf: the piece itself). None for an inner
  /// node of a hierarchy built with `InnerHulls::none` (a static body's): its 14-DOP is its
  /// children's, slab by slab (`BodyKdops`).
  std::optional<Polytope<S>> hull;
  /// Children (indices into `Bvh::nodes`), -1 for a leaf.
  int left = -1;
  /// See `left`.
  int right = -1;
  /// The piece of a leaf (index into `Bvh::pieces`), -1 for an inner node.
  int piece = -1;
  /// The parent, -1 for the root.
  int parent = -1;
  /// Depth below the root (the root is 0).
  int depth = 0;
  /// The centre of the node's hull (without one: of the sphere holding its children's).
  Vector3<S> centre = Vector3<S>::Zero();
  /// The largest distance of a hull vertex from `centre` (without a hull: a bound on it):
  /// the node's size, which decides which side of a node pair a traversal opens (the larger).
  S size = S(0);
  /// Where hill climbing starts for a direction with no useful hint: for each of the 26
  /// directions \f$(i, j, k) \in \{-1, 0, 1\}^3\f$ (index \f$9(i+1) + 3(j+1) + (k+1)\f$), the hull's
  /// supporting vertex there (`startFor`).
  std::array<int, 27> startVertex{};
  /// True for a leaf.
  bool isLeaf() const { return piece >= 0; }
  /// True if the node keeps its hull (every leaf does).
  bool hasHull() const { return hull.has_value(); }
  /// A good first vertex for a climb along `d`: the supporting vertex of the nearest of the
  /// 26 directions (each component of d rounded to -1, 0 or 1 relative to the largest,
  /// at \f$\tan 22.5^\circ\f$). The climb then takes a few steps, not a walk across the hull.
  int startFor(const Vector3<S>& d) const {
    const S m = S(0.41421356) * d.cwiseAbs().maxCoeff();
    int index = 0;
    for (int i = 0; i < 3; ++i) index = 3 * index + (d[i] > m ? 2 : (d[i] < -m ? 0 : 1));
    return startVertex[index];
  }
};

/// Whether a hierarchy's inner nodes keep the hull of their pieces (a Qhull call each).
/// A 14-DOP needs no hull: the support of a union is the larger of its parts' supports, so
/// an inner node's slab ends are its children's extremes, exact at any pose. The hull makes
/// them one climb each instead of a walk down to the leaves, which pays for a body that
/// moves (new poses at every query) and not for a static one, whose ends are computed once:
/// the torso's plant, a prism per triangle, has one inner node fewer than it has triangles.
enum class InnerHulls {
  every,  ///< each inner node keeps its hull (a moving body)
  none    ///< no inner node keeps one (a static body)
};

/// The hierarchy of one body's convex pieces, in the body frame. Shared by every body
/// with the same shape; what depends on a body's pose lives in the query (`body_pair.hpp`).
template <typename S>
class Bvh {
 public:
  /// The scalar type.
  using Scalar = S;

  /// Builds the hierarchy of `pieces` (top-down, median split), its inner nodes with their
  /// hulls or without (`inner`: InnerHulls::none for a static body). Throws
  /// std::invalid_argument ("bvh.pieces: ...") for an empty list, or for a mix of solid
  /// pieces and polygons (a body is either solid or flat, in the plane z = 0).
  explicit Bvh(std::vector<Polytope<S>> pieces, InnerHulls inner = InnerHulls::every)
      : pieces_(std::move(pieces)), inner_(inner) {
    if (pieces_.empty()) throw std::invalid_argument("bvh.pieces: a body needs at least one convex piece");
    for (const auto& piece : pieces_)
      if (piece.planar() != pieces_.front().planar())
        throw std::invalid_argument("bvh.pieces: solid pieces and polygons (z = 0) cannot share a body");
    std::vector<int> order(pieces_.size());
    std::iota(order.begin(), order.end(), 0);
    nodes_.reserve(2 * pieces_.size());
    build(order, 0, static_cast<int>(order.size()), -1, 0);
  }

  /// The root node (always 0).
  static constexpr int root() { return 0; }
  /// All nodes; children after their parent.
  const std::vector<BvhNode<S>>& nodes() const { return nodes_; }
  /// Node i.
  const BvhNode<S>& node(int i) const { return nodes_[i]; }
  /// The convex pieces.
  const std::vector<Polytope<S>>& pieces() const { return pieces_; }
  /// The number of levels (a single piece: 1).
  int height() const {
    int h = 0;
    for (const auto& n : nodes_) h = std::max(h, n.depth + 1);
    return h;
  }

 private:
  int build(std::vector<int>& order, int first, int last, int parent, int depth) {
    const int index = static_cast<int>(nodes_.size());
    // A leaf's hull is its piece; an inner node's is filled in below, once its children's
    // are known (children after their parent: the node's place is taken first).
    nodes_.push_back(BvhNode<S>{pieces_[order[first]]});
    nodes_[index].parent = parent;
    nodes_[index].depth = depth;
    if (last - first == 1) {
      nodes_[index].piece = order[first];
      finish(nodes_[index]);
      return index;
    }
    // The longest extent of the pieces' centres, and the median along it.
    Vector3<S> lo = pieces_[order[first]].center(), hi = lo;
    for (int i = first; i < last; ++i) {
      lo = lo.cwiseMin(pieces_[order[i]].center());
      hi = hi.cwiseMax(pieces_[order[i]].center());
    }
    int axis = 0;
    (hi - lo).maxCoeff(&axis);
    const int middle = first + (last - first) / 2;
    std::nth_element(order.begin() + first, order.begin() + middle, order.begin() + last, [&](int a, int b) {
      const S ca = pieces_[a].center()[axis], cb = pieces_[b].center()[axis];
      return ca < cb || (ca == cb && a < b);  // ties by index: the same tree on every run
    });
    const int left = build(order, first, middle, index, depth + 1);
    const int right = build(order, middle, last, index, depth + 1);
    BvhNode<S>& node = nodes_[index];
    node.left = left;
    node.right = right;
    if (inner_ == InnerHulls::none) {
      // No hull: the node's centre and size are the least sphere holding its children's
      // spheres (each a centre and a size), which bounds its pieces as the hull's would.
      node.hull.reset();
      const BvhNode<S>&a = nodes_[left], &b = nodes_[right];
      const S apart = (b.centre - a.centre).norm();
      if (apart + b.size <= a.size || !(apart > S(0))) {
        node.centre = a.centre;
        node.size = std::max(a.size, b.size);
      } else if (apart + a.size <= b.size) {
        node.centre = b.centre;
        node.size = b.size;
      } else {
        node.size = (apart + a.size + b.size) / S(2);
        node.centre = a.centre + (node.size - a.size) / apart * (b.centre - a.centre);
      }
      return index;
    }
    // The hull of the pieces is the hull of the children's hulls: only their vertices are
    // handed to the hull (a static mesh of 8,640 prisms would give the root 51,840 points).
    std::vector<Vector3<S>> points = nodes_[left].hull->vertices();
    const auto& more = nodes_[right].hull->vertices();
    points.insert(points.end(), more.begin(), more.end());
    // Pieces in the plane z = 0 (a 2D figure's bodies) have a polygon as their hull.
    node.hull = pieces_[order[first]].planar() ? Polytope<S>::polygon(points) : Polytope<S>::hull(points);
    finish(node);
    return index;
  }

  /// The node's centre, size and its climbs' starting vertices, from its hull.
  static void finish(BvhNode<S>& node) {
    const Polytope<S>& hull = *node.hull;
    node.centre = hull.center();
    for (const auto& v : hull.vertices()) node.size = std::max(node.size, (v - hull.center()).norm());
    for (int i = 0; i < 27; ++i) {
      const Vector3<S> d(S(i / 9 - 1), S(i / 3 % 3 - 1), S(i % 3 - 1));
      node.startVertex[i] = i == 13 ? 0 : hull.supportIndexLinearScan(d);
    }
  }

  std::vector<Polytope<S>> pieces_;
  InnerHulls inner_;
  std::vector<BvhNode<S>> nodes_;
};

/// The 7 slab directions seen from a body at `worldFromBody`, \f$\vec{d}_k = R^T\vec{a}_k\f$, and
/// the offsets \f$\vec{a}_k\cdot p\f$: what every node's 14-DOP at that pose shares.
template <typename S>
struct KdopFrame {
  /// \f$\vec{d}_k = R^T\vec{a}_k\f$.
  std::array<Vector3<S>, Kdop14<S>::kSlabs> direction;
  /// \f$\vec{a}_k\cdot p\f$.
  std::array<S, Kdop14<S>::kSlabs> offset;
  /// The frame of a pose.
  static KdopFrame of(const Pose<S>& worldFromBody) {
    KdopFrame f;
    for (int k = 0; k < Kdop14<S>::kSlabs; ++k) {
      const Vector3<S> a = Kdop14<S>::axis(k);
      f.direction[k] = worldFromBody.rotation.transpose() * a;
      f.offset[k] = a.dot(worldFromBody.translation);
    }
    return f;
  }
};

/// The world 14-DOP of a body-frame polytope at the pose of `frame`:
/// \f$hi_k = \vec{d}_k\cdot S_X(\vec{d}_k) + \vec{a}_k\cdot p\f$, \f$lo_k = \vec{d}_k\cdot S_X(-\vec{d}_k) + \vec{a}_k\cdot p\f$.
/// The same numbers as `kdopOf(place(x, pose))` up to round-off, for 14 climbs in the body frame.
template <typename S>
Kdop14<S> kdopAt(const Polytope<S>& x, const KdopFrame<S>& frame, std::array<SupportHint, 14>& hints) {
  Kdop14<S> k;
  for (int i = 0; i < Kdop14<S>::kSlabs; ++i) {
    const Vector3<S>& d = frame.direction[i];
    k.hi[i] = d.dot(x.support(d, hints[2 * i])) + frame.offset[i];
    k.lo[i] = d.dot(x.support(Vector3<S>(-d), hints[2 * i + 1])) + frame.offset[i];
  }
  return k;
}

}  // namespace gjkx
