/// @file
/// @brief The 14-DOP: a convex shape's bounding volume of 7 slabs, from its support mapping (§6).
///
/// §6 bounds the convex pieces of a nonconvex body, and groups of them, by k-DOPs with
/// k = 14: the intersection of 7 slabs, one per fixed direction \f$\vec{a}_k\f$, the three
/// coordinate axes and the four diagonals of the cube. Slab k is the interval
/// \f$[\min_{x\in X}\vec{a}_k\cdot x,\ \max_{x\in X}\vec{a}_k\cdot x]\f$, and both ends are support
/// values: \f$\max_x \vec{a}\cdot x = \vec{a}\cdot S_X(\vec{a})\f$ and \f$\min_x \vec{a}\cdot x = \vec{a}\cdot S_X(-\vec{a})\f$.
/// So the k-DOP of any shape the library has is exact (the smallest 14-DOP that holds
/// it) and costs 14 support queries, a few dot products each with hill climbing.
///
/// Two k-DOPs are disjoint when one slab separates them: \f$hi^P_k < lo^Q_k\f$ or
/// \f$hi^Q_k < lo^P_k\f$ for some k. The axes are kept unnormalised (entries 0 and ±1), as k-DOP
/// codes do, so that the support values of a point are sums of its coordinates;
/// `axisLength(k)` turns a slab's gap into a distance.
#pragma once

#include <gjkx/support_mapping/support.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace gjkx {

/// A 14-DOP: 7 slabs \f$[lo_k, hi_k]\f$ along the fixed directions `Kdop14::axis(k)`.
template <typename S>
struct Kdop14 {
  /// The scalar type.
  using Scalar = S;
  /// The number of slabs (k / 2).
  static constexpr int kSlabs = 7;
  /// The lower ends \f$lo_k = \min_x \vec{a}_k\cdot x\f$.
  std::array<S, kSlabs> lo;
  /// The upper ends \f$hi_k = \max_x \vec{a}_k\cdot x\f$.
  std::array<S, kSlabs> hi;

  /// Slab direction k: x, y, z, then the diagonals (1,1,1), (1,-1,1), (1,1,-1), (1,-1,-1).
  static Vector3<S> axis(int k) {
    static const int table[kSlabs][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 1}, {1, -1, 1}, {1, 1, -1}, {1, -1, -1}};
    return Vector3<S>(S(table[k][0]), S(table[k][1]), S(table[k][2]));
  }
  /// \f$\lVert\vec{a}_k\rVert\f$: 1 for the coordinate axes, \f$\sqrt3\f$ for the diagonals.
  static S axisLength(int k) { return k < 3 ? S(1) : std::sqrt(S(3)); }

  /// The empty k-DOP (every slab inverted), the neutral element of `merge`.
  static Kdop14 empty() {
    Kdop14 k;
    k.lo.fill(std::numeric_limits<S>::infinity());
    k.hi.fill(-std::numeric_limits<S>::infinity());
    return k;
  }
  /// The k-DOP of one point.
  static Kdop14 ofPoint(const Vector3<S>& p) {
    Kdop14 k;
    for (int i = 0; i < kSlabs; ++i) k.lo[i] = k.hi[i] = axis(i).dot(p);
    return k;
  }
  /// Grows this k-DOP to hold `other` as well.
  void merge(const Kdop14& other) {
    for (int i = 0; i < kSlabs; ++i) {
      lo[i] = std::min(lo[i], other.lo[i]);
      hi[i] = std::max(hi[i], other.hi[i]);
    }
  }
  /// Widens every slab by `pad` on each side (in units of the slab's axis).
  void inflate(S pad) {
    for (int i = 0; i < kSlabs; ++i) {
      lo[i] -= pad;
      hi[i] += pad;
    }
  }
  /// True if every slab of `other` lies within this one's.
  bool contains(const Kdop14& other) const {
    for (int i = 0; i < kSlabs; ++i)
      if (other.lo[i] < lo[i] || other.hi[i] > hi[i]) return false;
    return true;
  }
  /// The distance by which slab k separates this k-DOP from `other`
  /// (positive: a gap, along the unit direction of the slab; the larger of the two sides).
  S gap(const Kdop14& other, int k) const { return std::max(other.lo[k] - hi[k], lo[k] - other.hi[k]) / axisLength(k); }
  /// The first slab whose gap exceeds `tolerance`, or -1 if the k-DOPs overlap (within it).
  int separatingSlab(const Kdop14& other, S tolerance = S(0)) const {
    for (int k = 0; k < kSlabs; ++k)
      if (gap(other, k) > tolerance) return k;
    return -1;
  }
  /// True if no slab separates the two k-DOPs by more than `tolerance`.
  bool overlaps(const Kdop14& other, S tolerance = S(0)) const { return separatingSlab(other, tolerance) < 0; }
};

/// The 14-DOP of a support mapping X: \f$hi_k = \vec{a}_k\cdot S_X(\vec{a}_k)\f$,
/// \f$lo_k = \vec{a}_k\cdot S_X(-\vec{a}_k)\f$ (14 support queries). `hints` keeps one hill-climbing
/// start per query direction, so the next call for the same shape starts where this one ended.
template <typename X>
Kdop14<typename X::Scalar> kdopOf(const X& shape, std::array<SupportHint, 14>& hints) {
  using S = typename X::Scalar;
  Kdop14<S> k;
  for (int i = 0; i < Kdop14<S>::kSlabs; ++i) {
    const Vector3<S> a = Kdop14<S>::axis(i);
    k.hi[i] = a.dot(supportFrom(shape, a, hints[2 * i]));
    k.lo[i] = a.dot(supportFrom(shape, Vector3<S>(-a), hints[2 * i + 1]));
  }
  return k;
}

/// The 14-DOP of a support mapping X, hill climbing from vertex 0.
template <typename X>
Kdop14<typename X::Scalar> kdopOf(const X& shape) {
  std::array<SupportHint, 14> hints;
  hints.fill(0);
  return kdopOf(shape, hints);
}

}  // namespace gjkx
