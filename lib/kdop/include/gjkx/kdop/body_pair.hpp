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

#include <gjkx/kdop/body_kdops.hpp>
#include <gjkx/kdop/bvh.hpp>
#include <gjkx/kdop/kdop_extrusion.hpp>
#include <gjkx/motion/motion.hpp>
#include <gjkx/motion/round_off.hpp>

#include <algorithm>
#include <cstdint>
#include <limits>
#include <memory>
#include <stdexcept>
#include <unordered_map>
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
  /// Support queries run for slab ends (a full 14-DOP is 14; a test that one slab settles
  /// needs 4, and fewer when other pairs of the same bodies have computed them at the pose).
  int supportQueries = 0;
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
    /// The slab side that proved it apart (2k for "B above A" along slab k, 2k + 1 for
    /// "A above B"), tried first next time; -1 if none.
    int slab;
    /// The BVTT parent (A's node in the high 32 bits, B's in the low), `kNoParent` for the root pair.
    std::uint64_t parent;
  };
  /// The parent of the root pair.
  static constexpr std::uint64_t kNoParent = ~std::uint64_t(0);

  /// A query over the hierarchies of A and B, with 14-DOP caches of its own. Throws
  /// std::invalid_argument for bad settings.
  BodyPairQuery(const Bvh<S>& a, const Bvh<S>& b, BodyPairSettings<S> settings = {})
      : settings_(settings),
        ownedA_(std::make_unique<BodyKdops<S>>(a)),
        ownedB_(std::make_unique<BodyKdops<S>>(b)),
        bodyA_(ownedA_.get()),
        bodyB_(ownedB_.get()) {
    settings_.validate();
  }
  /// A query over the bodies whose 14-DOP caches are `a` and `b`, shared with the other
  /// pairs these bodies are in (`body_kdops.hpp`); the caches must outlive the query.
  /// Throws std::invalid_argument for bad settings, or if `a` and `b` are the same cache.
  BodyPairQuery(BodyKdops<S>& a, BodyKdops<S>& b, BodyPairSettings<S> settings = {})
      : settings_(settings), bodyA_(&a), bodyB_(&b) {
    settings_.validate();
    if (&a == &b) throw std::invalid_argument("bodyPair: a body's 14-DOP cache cannot stand for both bodies");
  }

  /// The piece pairs of A (moving along `motionA`) and B (along `motionB`) that the k-DOP
  /// extrusion test cannot prove apart over \f$[t_0, t_1]\f$. Throws std::invalid_argument
  /// ("bodyPair.t0"/"bodyPair.t1") for a non-finite time or t1 < t0.
  BodyPairOutput<S> query(const Motion<S>& motionA, const Motion<S>& motionB, S t0, S t1) {
    return query(motionA, motionB, t0, t1, settings_.tolerance);
  }

  /// The same with a tolerance of its own for this query (>= 0): a pair is pruned only if a
  /// slab keeps it more than `tolerance` apart. (A simulation's contact test asks which
  /// pieces lie within a band wider than its collisions' tolerance, on the same front.)
  /// Throws std::invalid_argument ("bodyPair.tolerance") for a negative or non-finite one.
  BodyPairOutput<S> query(const Motion<S>& motionA, const Motion<S>& motionB, S t0, S t1, S tolerance) {
    requireInterval(t0, t1, "bodyPair");
    requireNonNegative(tolerance, "bodyPair.tolerance");
    tolerance_ = tolerance;
    ++stamp_;
    bodyA_->begin(motionA, t0, t1);
    bodyB_->begin(motionB, t0, t1);
    duration_ = t1 - t0;
    BodyPairOutput<S> out;
    counters_ = &out.counters;
    if (!settings_.frontTracking || front_.empty()) {
      front_.assign(1, FrontNode{Bvh<S>::root(), Bvh<S>::root(), false, -1, kNoParent});
      if (!settings_.frontTracking) parentOf_.clear();
    }
    std::vector<FrontNode>& next = next_;  // kept between queries, so that its memory is too
    next.clear();
    for (const FrontNode& node : front_) descend(node, next, out.pairs);
    if (settings_.frontTracking) climb(next);
    front_.swap(next);
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
  std::uint64_t key(int a, int b) const {
    return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(a)) << 32) | static_cast<std::uint32_t>(b);
  }

  // The BVTT's rule: open the larger node (ties: A), never a leaf.
  bool opensA(int a, int b) const {
    const BvhNode<S>& na = bodyA_->bvh().node(a);
    const BvhNode<S>& nb = bodyB_->bvh().node(b);
    if (na.isLeaf()) return false;
    if (nb.isLeaf()) return true;
    return na.size >= nb.size;
  }

  // Slab side `side` (2k: B above A along slab k; 2k + 1: A above B) over the interval:
  // the same gaps, in the same arithmetic, as `kdopExtrusionTest`.
  bool sideSeparates(int a, int b, int side) {
    const int k = side / 2;
    const bool bAbove = side % 2 == 0;
    const S scale = S(1) / Kdop14<S>::axisLength(k);
    int& c = counters_->supportQueries;
    const auto gap = [&](int end) {
      return bAbove ? (bodyB_->value(b, k, false, end, c) - bodyA_->value(a, k, true, end, c)) * scale
                    : (bodyA_->value(a, k, false, end, c) - bodyB_->value(b, k, true, end, c)) * scale;
    };
    const S gap0 = gap(0);
    if (!(gap0 > tolerance_)) return false;  // settled at t0: the t1 ends are not needed
    return slabSeparatesOverInterval(gap0, gap(1), duration_, bodyA_->acceleration(a), bodyB_->acceleration(b),
                                     settings_.variant, tolerance_);
  }

  // The k-DOP extrusion test of BVTT node (a, b): the slab side that proves it apart, or
  // -1. The side that did last time (`hint`) is tried first: when the bodies move little
  // it settles the test with 4 support queries.
  int apart(int a, int b, int hint) {
    ++counters_->nodesVisited;
    if (hint >= 0 && sideSeparates(a, b, hint)) return hint;
    for (int side = 0; side < 2 * Kdop14<S>::kSlabs; ++side)
      if (side != hint && sideSeparates(a, b, side)) return side;
    return -1;
  }

  // Tests BVTT node `start` and everything below it that is not proven apart; the nodes
  // where it stops go to `front`, the surviving leaf pairs to `pairs`.
  void descend(const FrontNode& start, std::vector<FrontNode>& front, std::vector<PiecePair>& pairs) {
    stack_.clear();
    stack_.push_back(start);
    while (!stack_.empty()) {
      const FrontNode n = stack_.back();
      stack_.pop_back();
      const int side = apart(n.a, n.b, n.slab);
      if (side >= 0) {
        front.push_back({n.a, n.b, true, side, n.parent});
        continue;
      }
      const BvhNode<S>& ni = bodyA_->bvh().node(n.a);
      const BvhNode<S>& nj = bodyB_->bvh().node(n.b);
      if (ni.isLeaf() && nj.isLeaf()) {
        front.push_back({n.a, n.b, false, -1, n.parent});
        pairs.push_back({ni.piece, nj.piece});
        continue;
      }
      FrontNode first{n.a, n.b, false, n.slab, key(n.a, n.b)}, second = first;
      if (opensA(n.a, n.b)) {
        first.a = ni.left;
        second.a = ni.right;
      } else {
        first.b = nj.left;
        second.b = nj.right;
      }
      if (settings_.frontTracking) parentOf_.try_emplace(key(n.a, n.b), n.parent);  // for when the front climbs to it
      stack_.push_back(second);
      stack_.push_back(first);
    }
  }

  // The front climbs back: where both children of a BVTT node are on the front and apart,
  // the node itself is tested, and if it is apart it replaces them; a node that climbed
  // may climb again. Two children of one node that are both on the front are neighbours in
  // it (a descent writes the first child's sub-front, then the second's, and later queries
  // keep that order), so one pass with a stack finds them, no search. A parent found not
  // apart is not tried again for a few queries (`kClimbRetry`): climbing is an economy,
  // never needed for the answer.
  void climb(std::vector<FrontNode>& front) {
    static constexpr unsigned kClimbRetry = 8;
    std::vector<FrontNode>& out = climbed_;
    out.clear();
    for (const FrontNode& node : front) {
      out.push_back(node);
      while (out.size() >= 2) {
        const FrontNode& x = out[out.size() - 2];
        const FrontNode& y = out.back();
        if (!x.disjoint || !y.disjoint || x.parent != y.parent || x.parent == kNoParent) break;
        const std::uint64_t parent = x.parent;
        const auto failed = climbFailed_.find(parent);
        if (failed != climbFailed_.end() && stamp_ - failed->second < kClimbRetry) break;
        const int pa = static_cast<int>(parent >> 32), pb = static_cast<int>(parent & 0xffffffffu);
        const int side = apart(pa, pb, x.slab);
        if (side < 0) {
          climbFailed_[parent] = stamp_;
          break;
        }
        const auto grand = parentOf_.find(parent);
        out.pop_back();
        out.pop_back();
        out.push_back({pa, pb, true, side, grand == parentOf_.end() ? kNoParent : grand->second});
        ++counters_->climbs;
      }
    }
    front.swap(out);
  }

  BodyPairSettings<S> settings_;
  std::unique_ptr<BodyKdops<S>> ownedA_, ownedB_;  // none when the caches are shared
  BodyKdops<S>* bodyA_;
  BodyKdops<S>* bodyB_;
  S duration_ = S(0);
  S tolerance_ = S(0);  // the tolerance of the query under way
  unsigned stamp_ = 0;
  std::vector<FrontNode> front_;
  std::unordered_map<std::uint64_t, std::uint64_t> parentOf_;
  std::unordered_map<std::uint64_t, unsigned> climbFailed_;
  std::vector<FrontNode> stack_, climbed_, next_;
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
