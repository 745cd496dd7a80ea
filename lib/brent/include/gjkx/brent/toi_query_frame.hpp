/// @file
/// @brief The frame and the clock a time-of-impact query runs in, beyond the paper: the
/// origin at P's position at \f$t_0\f$ and time 0 at \f$t_0\f$, so that GJK's arithmetic sees
/// the bodies' small relative coordinates and Brent's bracket a clock relative to the
/// interval (`detail::queryOrigin`, `detail::localBody`).
///
/// Part of the solver of gjkx/brent/time_of_impact.hpp, the header to include; why and
/// what it buys: `timeOfImpact`.
#pragma once

#include <gjkx/support_mapping/deforming_simplex.hpp>
#include <gjkx/support_mapping/placed.hpp>

#include <type_traits>
#include <utility>

namespace gjkx {

namespace detail {

/// A point of P at \f$t_0\f$ to put the query's origin at: the body origin of a rigid body,
/// the first vertex of a deforming simplex.
template <typename Shape>
Vector3<typename Shape::Scalar> queryOrigin(const Moving<Shape>& P, typename Shape::Scalar t0) {
  return P.motion.pose(t0).translation;
}
/// The same for a deforming simplex.
template <typename S>
Vector3<S> queryOrigin(const DeformingSimplex<S>& P, S t0) {
  return P.at(t0).points[0];
}

/// True for a body type that can be seen from another frame (`translated(offset)`).
template <typename X, typename = void>
struct CanTranslate : std::false_type {};
/// True for a body type that can be seen from another frame (`translated(offset)`).
template <typename X>
struct CanTranslate<X, std::void_t<decltype(std::declval<const X&>().translated(
                           std::declval<const Vector3<typename X::Scalar>&>()))>> : std::true_type {};

/// True for a body type that can be put on another clock (`retimed(clock)`).
template <typename X, typename = void>
struct CanRetime : std::false_type {};
/// True for a body type that can be put on another clock (`retimed(clock)`).
template <typename X>
struct CanRetime<X, std::void_t<decltype(std::declval<const X&>().retimed(std::declval<typename X::Scalar>()))>>
    : std::true_type {};

/// A body seen from the query's frame (origin moved by `offset`) and on its clock (0 at `clock`).
template <typename X>
X localBody(const X& body, const Vector3<typename X::Scalar>& offset, typename X::Scalar clock) {
  if (clock == 0) return body.translated(offset);
  if (offset.squaredNorm() == 0) return body.retimed(clock);
  return body.translated(offset).retimed(clock);
}

}  // namespace detail

}  // namespace gjkx
