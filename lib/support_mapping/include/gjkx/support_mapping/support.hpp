/// @file
/// @brief The one door to a shape: its supporting vertex \f$S_X(\vec{s})\f$ (§2.1).
///
/// Every shape of this stage is a *support mapping*: a type `X` with
/// - `using Scalar = ...;` the scalar type (float or double),
/// - `Vector3<Scalar> support(const Vector3<Scalar>& s) const;` a point of X that is
///   farthest in the direction s, \f$\vec{s}\cdot S_X(\vec{s}) = \max_{x\in X}\vec{s}\cdot x\f$,
/// - `Vector3<Scalar> center() const;` a point inside X (GJK's first direction uses it).
///
/// A shape that can start its search from a vertex it found before (the polytope's hill
/// climbing) also has `support(s, hint)`, where `hint` is a vertex index read and
/// written by the search. `supportFrom()` calls whichever the shape has, so GJK can keep
/// a hint per shape and exploit temporal coherence without knowing the shape.
#pragma once

#include <gjkx/motion/vector.hpp>

#include <type_traits>
#include <utility>

namespace gjkx {

/// The warm-start hint of a support query: the index of the vertex found last time
/// (-1 for "none"). Shapes without vertices ignore it.
using SupportHint = int;

namespace detail {
template <typename X, typename = void>
struct HasHintedSupport : std::false_type {};
template <typename X>
struct HasHintedSupport<X, std::void_t<decltype(std::declval<const X&>().support(
                               std::declval<const Vector3<typename X::Scalar>&>(), std::declval<SupportHint&>()))>>
    : std::true_type {};
}  // namespace detail

/// \f$S_X(\vec{s})\f$ starting from `hint` where the shape can use one (§2.1, hill climbing).
template <typename X>
Vector3<typename X::Scalar> supportFrom(const X& x, const Vector3<typename X::Scalar>& s, SupportHint& hint) {
  if constexpr (detail::HasHintedSupport<X>::value) {
    return x.support(s, hint);
  } else {
    (void)hint;
    return x.support(s);
  }
}

/// A *rounded* shape is a core swept by a ball, \f$X = C \oplus B(r)\f$: a sphere is a
/// point swept by a ball, a capsule a segment. It says so with two more members,
/// - `Scalar coreRadius() const;` r, and
/// - `Vector3<Scalar> coreSupport(const Vector3<Scalar>& s, SupportHint& hint) const;`
///   \f$S_C(\vec{s})\f$, the support of the core.
///
/// The support of a Minkowski sum is the sum of the supports, so
/// \f$S_X(\vec{s}) = S_C(\vec{s}) + r\,\vec{s}/\lVert\vec{s}\rVert\f$, and the supporting distance
/// of two rounded shapes is that of their cores less the radii,
/// \f$SD(P, Q, \vec{s}) = SD(C_P, C_Q, \vec{s}) - r_P - r_Q\f$ (§2.3). GJK uses it to run on
/// the cores, which are polytopes and end in a few iterations, instead of the curved
/// surfaces, where it converges only linearly (see `gjk`).
template <typename X, typename = void>
struct IsRounded : std::false_type {};
/// A shape with `coreRadius()` is rounded.
template <typename X>
struct IsRounded<X, std::void_t<decltype(std::declval<const X&>().coreRadius())>> : std::true_type {};

/// The ends of a core that is a point or a segment: \f$C = [a, b]\f$ (a = b for a point).
template <typename S>
struct CoreEnds {
  /// First end.
  Vector3<S> a;
  /// Second end (equal to `a` when the core is a point).
  Vector3<S> b;
};

/// A rounded shape whose core is a point (the sphere) or a segment (the capsule) says so
/// with `CoreEnds<Scalar> coreEnds() const`. GJK on two such cores has a known answer,
/// the closest points of two segments, and skips the general machinery (`gjk`).
template <typename X, typename = void>
struct HasSegmentCore : std::false_type {};
/// A shape with `coreEnds()` has a point or segment for its core.
template <typename X>
struct HasSegmentCore<X, std::void_t<decltype(std::declval<const X&>().coreEnds())>> : std::true_type {};

/// The radius r of a rounded shape \f$C \oplus B(r)\f$; 0 for any other shape.
template <typename X>
typename X::Scalar coreRadiusOf(const X& x) {
  if constexpr (IsRounded<X>::value) {
    return x.coreRadius();
  } else {
    (void)x;
    return typename X::Scalar(0);
  }
}

/// The support of a shape's core: `coreSupport` for a rounded shape, the shape's own
/// support for any other (its core is itself).
template <typename X>
Vector3<typename X::Scalar> coreSupportFrom(const X& x, const Vector3<typename X::Scalar>& s, SupportHint& hint) {
  if constexpr (IsRounded<X>::value) {
    return x.coreSupport(s, hint);
  } else {
    return supportFrom(x, s, hint);
  }
}

/// Checks that a size (radius, half extent) is finite and not negative; the message names the field.
template <typename Scalar>
void requireNonNegative(Scalar value, std::string_view field) {
  requireFinite(value, field);
  if (value < Scalar(0)) failInput(std::string(field), "must not be negative, got " + std::to_string(double(value)));
}

}  // namespace gjkx
