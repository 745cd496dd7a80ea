/// @file
/// @brief One body's 14-DOPs at its recent poses, computed on demand and shared by every
/// body pair the body is in (§6).
///
/// A node's 14-DOP at a pose is the body's, not a pair's: the slab ends
/// \f$hi_k = \vec{d}_k\cdot S_X(\vec{d}_k) + \vec{a}_k\cdot p\f$ (`bvh.hpp`) depend on the node
/// and the pose only. In a simulation a body is in many pairs at once (a bone among its
/// neighbours: twenty or thirty), and after a collision every pair of the struck body is
/// queried again over the same interval \f$[t_c, t_1]\f$, at the same two poses. So each
/// body keeps one cache of its nodes' slab ends, and every `BodyPairQuery` the body is in
/// reads it: an end is computed (one support query) by the first pair that needs it at a
/// pose and read by the others.
///
/// The ends are kept in two banks, each tied to one pose. A query's two poses are looked
/// for in both; a pose found in neither replaces the bank that the query does not need
/// (frames that follow each other share a pose, a body at rest has one, and a rollback
/// at \f$t_c\f$ keeps the frame's end \f$t_1\f$).
#pragma once

#include <gjkx/kdop/bvh.hpp>
#include <gjkx/motion/motion.hpp>
#include <gjkx/motion/round_off.hpp>

#include <array>
#include <cstdint>
#include <optional>
#include <vector>

namespace gjkx {

/// The slab ends of one body's hierarchy nodes at its poses at the ends of a query's
/// interval, computed on demand and kept for the next query at the same poses (see the
/// file comment). Not thread safe; the hierarchy must outlive it.
template <typename S>
class BodyKdops {
 public:
  /// The cache of a body whose pieces are in `bvh`.
  explicit BodyKdops(const Bvh<S>& bvh)
      : bvh_(&bvh),
        values_(bvh.nodes().size()),
        known_(bvh.nodes().size(), {0, 0}),
        epochOf_(bvh.nodes().size(), {0, 0}),
        hints_(bvh.nodes().size()) {
    for (auto& hint : hints_) hint.fill(0);
    // Children come after their parent: a node without a hull takes its children's radius.
    radius_.resize(bvh.nodes().size());
    for (int i = int(bvh.nodes().size()) - 1; i >= 0; --i) {
      const BvhNode<S>& node = bvh.node(i);
      radius_[i] = node.hasHull() ? node.hull->boundingRadius() : std::max(radius_[node.left], radius_[node.right]);
    }
  }

  /// The hierarchy.
  const Bvh<S>& bvh() const { return *bvh_; }

  /// Sets the poses of the next reads: the body along `motion` at `t0` (end 0) and `t1`
  /// (end 1). Banks that hold either pose keep their ends.
  void begin(const Motion<S>& motion, S t0, S t1) {
    // The same motion over the same interval as the last call (another pair of this body,
    // queried at the same two poses): the banks are set already, and the poses, two
    // slerps, need not be computed again.
    if (lastMotion_ && t0 == lastT0_ && t1 == lastT1_ && *lastMotion_ == motion) return;
    lastMotion_ = motion;
    lastT0_ = t0;
    lastT1_ = t1;
    const Pose<S> pose0 = motion.pose(t0);
    const KdopFrame<S> frame0 = KdopFrame<S>::of(pose0);
    bound_ = motion.bound();
    if (t1 == t0 || motion.isStatic()) {
      const int b = bankHolding(frame0, pose0);
      bankOf_[0] = bankOf_[1] = b;
      return;
    }
    const Pose<S> pose1 = motion.pose(t1);
    const KdopFrame<S> frame1 = KdopFrame<S>::of(pose1);
    int b0 = bank_[0].holds(frame0) ? 0 : (bank_[1].holds(frame0) ? 1 : -1);
    int b1 = bank_[0].holds(frame1) ? 0 : (bank_[1].holds(frame1) ? 1 : -1);
    if (b0 < 0) {  // the bank end 1 does not need
      b0 = b1 == 0 ? 1 : 0;
      renew(b0, frame0, pose0);
    }
    if (b1 < 0) {
      b1 = 1 - b0;
      renew(b1, frame1, pose1);
    }
    bankOf_[0] = b0;
    bankOf_[1] = b1;
  }

  /// Slab end of node i: slab k, upper end (\f$hi_k\f$) or lower (\f$lo_k\f$), at end 0 (t0) or
  /// 1 (t1) of the last `begin`. \f$hi_k = \vec{d}_k\cdot S(\vec{d}_k) + \vec{a}_k\cdot p\f$ (bvh.hpp,
  /// kdopAt). An inner node's ends are widened by a few round-offs of their size, so that
  /// they hold their descendants' computed ends (hill climbing on two different hulls may
  /// round differently): the BVH then prunes exactly what the all-pairs test prunes.
  /// Support values are at most \f$\sqrt3 r + |p|_1\f$ in size, r the node's radius about the
  /// body origin. A support query computed here is counted in `supportQueries`.
  S value(int i, int k, bool upper, int end, int& supportQueries) {
    // Most reads find the end computed already (by this pair or another of the body's):
    // that path is kept small, so that it is inlined into the slab tests.
    const int b = bankOf_[end];
    const int side = 2 * k + (upper ? 0 : 1);
    if (epochOf_[i][b] == bank_[b].epoch && (known_[i][b] & (1u << side))) return values_[i][14 * b + side];
    ++supportQueries;
    return compute(i, k, side, b);
  }

  /// The bound on any point's acceleration of node i over the last `begin`'s motion
  /// (`MotionBound::pointAcceleration` at the node's radius).
  S acceleration(int i) const { return bound_.pointAcceleration(radius_[i]); }

 private:
  // Slab end `side` (2k: hi_k, 2k + 1: lo_k) of node i in bank b, by one support query;
  // kept for later reads.
  [[gnu::noinline]] S compute(int i, int k, int side, int b) {
    if (epochOf_[i][b] != bank_[b].epoch) {
      epochOf_[i][b] = bank_[b].epoch;
      known_[i][b] = 0;
    }
    const bool upper = side % 2 == 0;
    const int slot = 14 * b + side;
    known_[i][b] = static_cast<std::uint16_t>(known_[i][b] | (1u << side));
    const BvhNode<S>& node = bvh_->node(i);
    if (!node.hasHull()) {
      // No hull (InnerHulls::none): the support of a union is the larger of its parts', so
      // the end is the children's extreme, exactly as they are computed (each kept for later).
      const S l = valueIn(node.left, k, side, b), r = valueIn(node.right, k, side, b);
      return values_[i][slot] = upper ? std::max(l, r) : std::min(l, r);
    }
    const Vector3<S>& d = bank_[b].frame.direction[k];
    const Vector3<S> direction = upper ? d : Vector3<S>(-d);
    // After a large turn (`freshStart`), last time's vertex is far from the answer: the
    // climb starts from the node's table instead (a few steps from anywhere).
    if (bank_[b].freshStart) hints_[i][slot] = node.startFor(direction);
    S v = d.dot(node.hull->support(direction, hints_[i][slot])) + bank_[b].frame.offset[k];
    if (!node.isLeaf()) {
      const S pad = S(64) * machineEpsilon<S>() * (S(2) * radius_[i] + bank_[b].reach);
      v += upper ? pad : -pad;
    }
    values_[i][slot] = v;
    return v;
  }

  // Slab end `side` of node i in bank b: kept, or computed now.
  S valueIn(int i, int k, int side, int b) {
    if (epochOf_[i][b] == bank_[b].epoch && (known_[i][b] & (1u << side))) return values_[i][14 * b + side];
    return compute(i, k, side, b);
  }

  /// The slab ends of all nodes at one pose, valid for nodes whose epoch matches.
  struct Bank {
    /// The pose's slab directions and offsets.
    KdopFrame<S> frame;
    /// \f$\lVert p\rVert_1\f$ of the pose (the inner nodes' round-off allowance).
    S reach = S(0);
    /// Which computation of the ends is current.
    unsigned epoch = 0;
    /// False until a pose is set.
    bool valid = false;
    /// True if the pose turned by more than about 25 degrees since the bank's last pose
    /// (or has none): its climbs start from the nodes' tables, not from their hints.
    bool freshStart = true;
    /// True if the bank holds the ends at the pose of `f` (bit for bit the same frame).
    bool holds(const KdopFrame<S>& f) const {
      if (!valid) return false;
      for (int k = 0; k < Kdop14<S>::kSlabs; ++k)
        if (f.offset[k] != frame.offset[k] || f.direction[k] != frame.direction[k]) return false;
      return true;
    }
  };

  /// The bank holding the pose of `f`, or bank 0 renewed to it.
  int bankHolding(const KdopFrame<S>& f, const Pose<S>& pose) {
    if (bank_[0].holds(f)) return 0;
    if (bank_[1].holds(f)) return 1;
    renew(0, f, pose);
    return 0;
  }

  void renew(int b, const KdopFrame<S>& f, const Pose<S>& pose) {
    // The turn since the bank's last pose: the x, y and z axes seen from the body moved by
    // less than about 25 degrees each (cos 25 = 0.906) or the hints are stale.
    bool coherent = bank_[b].valid;
    for (int k = 0; k < 3 && coherent; ++k) coherent = f.direction[k].dot(bank_[b].frame.direction[k]) > S(0.906);
    bank_[b].freshStart = !coherent;
    bank_[b].frame = f;
    bank_[b].reach = pose.translation.template lpNorm<1>();
    bank_[b].epoch = ++epochs_;
    bank_[b].valid = true;
  }

  const Bvh<S>* bvh_;
  Bank bank_[2];
  int bankOf_[2] = {0, 0};
  unsigned epochs_ = 0;
  MotionBound<S> bound_;
  std::optional<Motion<S>> lastMotion_;  // the last begin's motion and interval
  S lastT0_ = S(0), lastT1_ = S(0);
  std::vector<std::array<S, 28>> values_;
  std::vector<std::array<std::uint16_t, 2>> known_;
  std::vector<std::array<unsigned, 2>> epochOf_;
  std::vector<std::array<SupportHint, 28>> hints_;
  std::vector<S> radius_;  // each node's bounding radius, side by side (read at every slab test)
};

}  // namespace gjkx
