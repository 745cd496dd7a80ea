/// @file
/// @brief The sweeping test, one of the two tests §1 sets the extrusion test against (Fig. 1);
/// the other, the static test, is in static_sampling.hpp.
///
/// "Static intersection tests check for intersection at specific instances in time.
/// [...] they often miss collisions, especially for small or flat objects [...] Sweeping
/// intersection tests detect the intersection between the sweeping volumes of objects
/// over time [...] they also conservatively report false alarms that never actually
/// occur, because they do not account for the displacement of objects as they move."
/// The figures of chapter 04, the comparative study and its table of extreme cases call
/// `sweepingTest` directly.
#pragma once

#include <gjkx/supporting_distance/intersection.hpp>

#include <utility>

namespace gjkx {

/// The convex hull of a moving body at two times, \f$\mathrm{conv}(X(t_0) \cup X(t_1))\f$: the
/// volume a translating convex body sweeps (for rotation, the hull of the two poses,
/// which need not cover the whole sweep). Its support mapping is the better of the two:
/// \f$S(\vec{s}) = \arg\max\{\vec{s}\cdot S_{X(t_0)}(\vec{s}),\ \vec{s}\cdot S_{X(t_1)}(\vec{s})\}\f$.
template <typename Moving>
struct SweptHull {
  /// The scalar type.
  using Scalar = typename Moving::Scalar;
  /// The body at the start.
  decltype(std::declval<const Moving&>().at(Scalar(0))) start;
  /// The body at the end.
  decltype(std::declval<const Moving&>().at(Scalar(0))) end;
  /// The farther of the two supporting vertices along s.
  Vector3<Scalar> support(const Vector3<Scalar>& s) const {
    const Vector3<Scalar> a = start.support(s), b = end.support(s);
    return s.dot(b) > s.dot(a) ? b : a;
  }
  /// Midway between the two centres.
  Vector3<Scalar> center() const { return (start.center() + end.center()) * Scalar(0.5); }
};

/// The swept hull of a moving body over [t0, t1].
template <typename Moving>
SweptHull<Moving> sweptHull(const Moving& body, typename Moving::Scalar t0, typename Moving::Scalar t1) {
  return SweptHull<Moving>{body.at(t0), body.at(t1)};
}

/// The sweeping test (§1): do the swept hulls of P and Q over [t0, t1] intersect? Never
/// misses a collision of translating bodies; reports false alarms.
template <typename MovingP, typename MovingQ>
IntersectionResult<typename MovingP::Scalar> sweepingTest(const MovingP& P, const MovingQ& Q,
                                                          typename MovingP::Scalar t0, typename MovingP::Scalar t1,
                                                          const IntersectionSettings<typename MovingP::Scalar>& settings = {}) {
  return intersect(sweptHull(P, t0, t1), sweptHull(Q, t0, t1), settings);
}

}  // namespace gjkx
