/// @file
/// @brief The body-pair query: which convex piece pairs of two moving nonconvex bodies may
/// meet over \f$[t_0, t_1]\f$, with generalized front tracking between queries (§6).
///
/// Two bodies A and B, each a `Bvh` of convex pieces moving along a `Motion`, span a
/// *bounding volume test tree* (BVTT): its root is the pair of roots, and a node (a, b)
/// whose 14-DOPs are not proven apart by the k-DOP extrusion test (`kdop_extrusion.hpp`)
/// has as children the pairs of the larger node's children with the other node. The
/// leaves that survive are the piece pairs handed to the time-of-impact solver.
///
/// A traversal stops on a *front*: the BVTT nodes proven apart, and the surviving leaf
/// pairs. **Generalized front tracking** (Ehmann and Lin, "Accurate and fast proximity
/// queries between polyhedra using convex surface decomposition", 2001) keeps that front
/// between queries. The next query tests the front only: a node still apart stays; a node
/// no longer apart is opened where it stands (a fresh traversal below it); and where both
/// children of a BVTT node are apart, the parent is tested and, if it is apart too, takes
/// their place (the front climbs back). When the bodies move little from one frame to the
/// next, the front barely changes and a query costs about its size, not a traversal.
///
/// **Same answer as a fresh traversal.** A node's 14-DOP holds its descendants' (exact
/// support values of a hull that contains theirs, widened by round-off), and the test's
/// bound grows with the 14-DOP and shrinks with the node's radius, so a node proven apart
/// proves all its descendants apart. Every leaf pair lies under exactly one front node.
/// The surviving pairs are therefore those of a fresh traversal, which are those of the
/// all-pairs test of the pieces (`bruteForcePiecePairs`), and the tests check that they are.
#pragma once

#include <gjkx/kdop/bvh.hpp>
#include <gjkx/kdop/kdop_extrusion.hpp>
#include <gjkx/motion/motion.hpp>
#include <gjkx/motion/round_off.hpp>

#include <algorithm>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <unordered_map>
#include <unordered_set>
#include <utility>
#include <vector>

namespace gjkx {

/// A pair of convex pieces (indices into the two bodies' `Bvh::pieces`) that may meet.
struct PiecePair {
  /// The piece of body A.
  int a = -1;
  /// The piece of body B.
  int b = -1;
  /// Equal pieces.
  bool operator==(const PiecePair& o) const { return a == o.a && b == o.b; }
  /// Ordered by a, then b (the order of every query's output).
  bool operator<(const PiecePair& o) const { return a < o.a || (a == o.a && b < o.b); }
};

/// What a body-pair query did, for a scene's statistics.
struct BodyPairCounters {
  /// BVTT nodes tested (pairs of 14-DOPs put to the k-DOP extrusion test).
  int nodesVisited = 0;
  /// 14-DOPs computed (each: 14 hill climbs; twice for an interval, once for a static query).
  int kdopsComputed = 0;
  /// The size of the front the query ended on.
  int frontSize = 0;
  /// Piece pairs that survived.
  int pairsKept = 0;
  /// BVTT nodes the front climbed back to.
  int climbs = 0;
};

/// The outcome of a body-pair query.
enum class BodyPairStatus {
  Disjoint,   ///< every piece pair is proven apart over the interval
  PairsKept,  ///< some piece pairs survive: `pairs` lists them
};

/// How a body-pair query tests and what it keeps.
template <typename S>
struct BodyPairSettings {
  /// The extrusion test's variant: `Paper` is exact for linear motion only; `Certified`
  /// (the default) stays conservative for rotating and accelerating motion and equals
  /// `Paper` for linear motion.
  ExtrusionVariant variant = ExtrusionVariant::Certified;
  /// A pair is pruned only if a slab keeps it more than this apart (world units, >= 0).
  S tolerance = S(0);
  /// Keep the front between queries (generalized front tracking); off: every query is a fresh traversal.
  bool frontTracking = true;
  /// Throws std::invalid_argument naming the field for a negative or non-finite tolerance.
  void validate() const { requireNonNegative(tolerance, "bodyPair.tolerance"); }
};

/// The answer of a body-pair query.
template <typename S>
struct BodyPairOutput {
  /// Disjoint, or pairs kept.
  BodyPairStatus status = BodyPairStatus::Disjoint;
  /// The piece pairs that survive, sorted (`PiecePair::operator<`), ready for the time-of-impact solver.
  std::vector<PiecePair> pairs;
  /// Nodes visited, front size, pairs kept.
  BodyPairCounters counters;
};

/// The body-pair query of two bodies' piece hierarchies, keeping the front of its BVTT
/// between calls (see the file comment). One object per pair of bodies; the hierarchies
/// must outlive it. Not thread safe (it keeps per-body caches of 14-DOPs).
template <typename S>
class BodyPairQuery {
 public:
  /// A node of the front: a BVTT node (a node of A's hierarchy, a node of B's) and its
  /// last verdict.
  struct FrontNode {
    /// Node of A's `Bvh`.
    int a;
    /// Node of B's `Bvh`.
    int b;
    /// True if the last query proved it apart; false for a surviving leaf pair.
    bool disjoint;
  };

  /// A query over the hierarchies of A and B. Throws std::invalid_argument for bad settings.
  BodyPairQuery(const Bvh<S>& a, const Bvh<S>& b, BodyPairSettings<S> settings = {})
      : settings_(settings), bodyA_(a), bodyB_(b) {
    settings_.validate();
  }

  /// The piece pairs of A (moving along `motionA`) and B (along `motionB`) that the k-DOP
  /// extrusion test cannot prove apart over \f$[t_0, t_1]\f$. Throws std::invalid_argument
  /// ("bodyPair.t0"/"bodyPair.t1") for a non-finite time or t1 < t0.
  BodyPairOutput<S> query(const Motion<S>& motionA, const Motion<S>& motionB, S t0, S t1) {
    requireInterval(t0, t1, "bodyPair");
    ++stamp_;
    bodyA_.begin(motionA, t0, t1, stamp_);
    bodyB_.begin(motionB, t0, t1, stamp_);
    duration_ = t1 - t0;
    BodyPairOutput<S> out;
    counters_ = &out.counters;
    if (!settings_.frontTracking || front_.empty()) {
      front_.assign(1, FrontNode{Bvh<S>::root(), Bvh<S>::root(), false});
      parentOf_.clear();
    }
    std::vector<FrontNode> next;
    next.reserve(front_.size() + 16);
    for (const FrontNode& node : front_) descend(node.a, node.b, next, out.pairs);
    if (settings_.frontTracking) climb(next);
    front_ = std::move(next);
    std::sort(out.pairs.begin(), out.pairs.end());
    out.counters.frontSize = static_cast<int>(front_.size());
    out.counters.pairsKept = static_cast<int>(out.pairs.size());
    out.status = out.pairs.empty() ? BodyPairStatus::Disjoint : BodyPairStatus::PairsKept;
    counters_ = nullptr;
    return out;
  }

  /// The piece pairs whose 14-DOPs overlap with A at `poseA` and B at `poseB` (a static query).
  BodyPairOutput<S> queryAt(const Pose<S>& poseA, const Pose<S>& poseB) {
    return query(Motion<S>::fixed(poseA), Motion<S>::fixed(poseB), S(0), S(0));
  }

  /// The front the last query ended on.
  const std::vector<FrontNode>& front() const { return front_; }
  /// Forgets the front: the next query is a fresh traversal.
  void resetFront() { front_.clear(); }
  /// The settings.
  const BodyPairSettings<S>& settings() const { return settings_; }

 private:
  // One body's pose-dependent state: its 14-DOPs at t0 and t1, computed on demand (a
  // node's only when the traversal reaches it) and reused within one query.
  struct Body {
    explicit Body(const Bvh<S>& h)
        : bvh(&h), k0(h.nodes().size()), k1(h.nodes().size()), stamp(h.nodes().size(), 0), hints0(h.nodes().size()),
          hints1(h.nodes().size()) {
      for (auto& h0 : hints0) h0.fill(0);
      for (auto& h1 : hints1) h1.fill(0);
    }
    void begin(const Motion<S>& motion, S t0, S t1, unsigned current) {
      const Pose<S> pose0 = motion.pose(t0);
      frame0 = KdopFrame<S>::of(pose0);
      sameEnds = (t1 == t0) || motion.isStatic();
      const Pose<S> pose1 = sameEnds ? pose0 : motion.pose(t1);
      if (!sameEnds) frame1 = KdopFrame<S>::of(pose1);
      bound = motion.bound();
      // Round-off allowance of an inner node's 14-DOP (see `ensure`): support values are
      // at most sqrt(3) r + |p|_1 in size, r the node's radius about the body origin.
      reach = std::max(pose0.translation.template lpNorm<1>(), pose1.translation.template lpNorm<1>());
      stampNow = current;
    }
    // Node i's 14-DOPs at both ends. An inner node's are widened by a few round-offs of
    // their size, so that they hold their descendants' computed 14-DOPs (hill climbing on
    // two different hulls may round differently): the BVH then prunes exactly what the
    // all-pairs test prunes.
    void ensure(int i, BodyPairCounters& counters) {
      if (stamp[i] == stampNow) return;
      stamp[i] = stampNow;
      const BvhNode<S>& node = bvh->node(i);
      k0[i] = kdopAt(node.hull, frame0, hints0[i]);
      if (!sameEnds) k1[i] = kdopAt(node.hull, frame1, hints1[i]);
      counters.kdopsComputed += sameEnds ? 1 : 2;
      if (!node.isLeaf()) {
        const S pad = S(64) * machineEpsilon<S>() * (S(2) * node.hull.boundingRadius() + reach);
        k0[i].inflate(pad);
        if (!sameEnds) k1[i].inflate(pad);
      }
    }
    const Kdop14<S>& end1(int i) const { return sameEnds ? k0[i] : k1[i]; }
    S acceleration(int i) const { return bound.pointAcceleration(bvh->node(i).hull.boundingRadius()); }

    const Bvh<S>* bvh;
    KdopFrame<S> frame0, frame1;
    bool sameEnds = true;
    MotionBound<S> bound;
    S reach = S(0);
    unsigned stampNow = 0;
    std::vector<Kdop14<S>> k0, k1;
    std::vector<unsigned> stamp;
    std::vector<std::array<SupportHint, 14>> hints0, hints1;
  };

  std::uint64_t key(int a, int b) const {
    return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(a)) << 32) | static_cast<std::uint32_t>(b);
  }

  // The BVTT's rule: open the larger node (ties: A), never a leaf.
  bool opensA(int a, int b) const {
    const BvhNode<S>& na = bodyA_.bvh->node(a);
    const BvhNode<S>& nb = bodyB_.bvh->node(b);
    if (na.isLeaf()) return false;
    if (nb.isLeaf()) return true;
    return na.size >= nb.size;
  }

  bool apart(int a, int b) {
    ++counters_->nodesVisited;
    bodyA_.ensure(a, *counters_);
    bodyB_.ensure(b, *counters_);
    return kdopExtrusionTest(bodyA_.k0[a], bodyA_.end1(a), bodyB_.k0[b], bodyB_.end1(b), duration_,
                             bodyA_.acceleration(a), bodyB_.acceleration(b), settings_.variant, settings_.tolerance)
        .separated;
  }

  // Tests BVTT node (a, b) and everything below it that is not proven apart; the nodes
  // where it stops go to `front`, the surviving leaf pairs to `pairs`.
  void descend(int a, int b, std::vector<FrontNode>& front, std::vector<PiecePair>& pairs) {
    stack_.clear();
    stack_.push_back({a, b});
    while (!stack_.empty()) {
      const auto [i, j] = stack_.back();
      stack_.pop_back();
      if (apart(i, j)) {
        front.push_back({i, j, true});
        continue;
      }
      const BvhNode<S>& ni = bodyA_.bvh->node(i);
      const BvhNode<S>& nj = bodyB_.bvh->node(j);
      if (ni.isLeaf() && nj.isLeaf()) {
        front.push_back({i, j, false});
        pairs.push_back({ni.piece, nj.piece});
        continue;
      }
      std::pair<int, int> first, second;
      if (opensA(i, j)) {
        first = {ni.left, j};
        second = {ni.right, j};
      } else {
        first = {i, nj.left};
        second = {i, nj.right};
      }
      if (settings_.frontTracking) {
        parentOf_[key(first.first, first.second)] = key(i, j);
        parentOf_[key(second.first, second.second)] = key(i, j);
      }
      stack_.push_back(second);
      stack_.push_back(first);
    }
  }

  // The front climbs back: where both children of a BVTT node are on the front and apart,
  // the node itself is tested, and if it is apart it replaces them. Repeated until no
  // node climbs, so a front can fall back to the root when the bodies part.
  void climb(std::vector<FrontNode>& front) {
    for (bool changed = true; changed;) {
      changed = false;
      std::unordered_map<std::uint64_t, int> where;
      where.reserve(front.size() * 2);
      for (int i = 0; i < static_cast<int>(front.size()); ++i)
        if (front[i].disjoint) where[key(front[i].a, front[i].b)] = i;
      std::unordered_set<std::uint64_t> tried;
      std::vector<char> removed(front.size(), 0);
      const int count = static_cast<int>(front.size());
      for (int i = 0; i < count; ++i) {
        if (!front[i].disjoint || removed[i]) continue;
        const auto parent = parentOf_.find(key(front[i].a, front[i].b));
        if (parent == parentOf_.end() || !tried.insert(parent->second).second) continue;
        const int pa = static_cast<int>(parent->second >> 32), pb = static_cast<int>(parent->second & 0xffffffffu);
        const BvhNode<S>& na = bodyA_.bvh->node(pa);
        const BvhNode<S>& nb = bodyB_.bvh->node(pb);
        const bool a = opensA(pa, pb);
        const auto c1 = where.find(a ? key(na.left, pb) : key(pa, nb.left));
        const auto c2 = where.find(a ? key(na.right, pb) : key(pa, nb.right));
        if (c1 == where.end() || c2 == where.end() || removed[c1->second] || removed[c2->second]) continue;
        if (!apart(pa, pb)) continue;
        removed[c1->second] = removed[c2->second] = 1;
        front.push_back({pa, pb, true});
        removed.push_back(0);
        ++counters_->climbs;
        changed = true;
      }
      if (changed) {
        std::vector<FrontNode> kept;
        kept.reserve(front.size());
        for (size_t i = 0; i < front.size(); ++i)
          if (!removed[i]) kept.push_back(front[i]);
        front = std::move(kept);
      }
    }
  }

  BodyPairSettings<S> settings_;
  Body bodyA_, bodyB_;
  S duration_ = S(0);
  unsigned stamp_ = 0;
  std::vector<FrontNode> front_;
  std::unordered_map<std::uint64_t, std::uint64_t> parentOf_;
  std::vector<std::pair<int, int>> stack_;
  BodyPairCounters* counters_ = nullptr;
};

/// The piece pairs of A and B that may meet over \f$[t_0, t_1]\f$: one fresh traversal
/// (`BodyPairQuery` without a kept front). For the simulation: the two bodies' piece
/// sets, their motions and the interval in, the surviving pairs out.
template <typename S>
BodyPairOutput<S> survivingPiecePairs(const Bvh<S>& a, const Motion<S>& motionA, const Bvh<S>& b,
                                      const Motion<S>& motionB, S t0, S t1, BodyPairSettings<S> settings = {}) {
  settings.frontTracking = false;
  BodyPairQuery<S> query(a, b, settings);
  return query.query(motionA, motionB, t0, t1);
}

/// The reference the hierarchy is held to: every piece of A against every piece of B with
/// the same k-DOP extrusion test, no hierarchy. Sorted like a query's output.
template <typename S>
std::vector<PiecePair> bruteForcePiecePairs(const Bvh<S>& a, const Motion<S>& motionA, const Bvh<S>& b,
                                            const Motion<S>& motionB, S t0, S t1, BodyPairSettings<S> settings = {}) {
  requireInterval(t0, t1, "bodyPair");
  settings.validate();
  auto ends = [&](const Bvh<S>& bvh, const Motion<S>& motion) {
    const KdopFrame<S> f0 = KdopFrame<S>::of(motion.pose(t0)), f1 = KdopFrame<S>::of(motion.pose(t1));
    std::vector<std::pair<Kdop14<S>, Kdop14<S>>> k;
    for (const auto& piece : bvh.pieces()) {
      std::array<SupportHint, 14> h0, h1;
      h0.fill(0);
      h1.fill(0);
      k.push_back({kdopAt(piece, f0, h0), kdopAt(piece, f1, h1)});
    }
    return k;
  };
  const auto ka = ends(a, motionA), kb = ends(b, motionB);
  const MotionBound<S> boundA = motionA.bound(), boundB = motionB.bound();
  std::vector<PiecePair> pairs;
  for (int i = 0; i < static_cast<int>(ka.size()); ++i)
    for (int j = 0; j < static_cast<int>(kb.size()); ++j)
      if (!kdopExtrusionTest(ka[i].first, ka[i].second, kb[j].first, kb[j].second, t1 - t0,
                             boundA.pointAcceleration(a.pieces()[i].boundingRadius()),
                             boundB.pointAcceleration(b.pieces()[j].boundingRadius()), settings.variant,
                             settings.tolerance)
               .separated)
        pairs.push_back({i, j});
  return pairs;
}

}  // namespace gjkx
