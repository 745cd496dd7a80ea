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

/// Checks that a size (radius, half extent) is finite and not negative; the message names the field.
template <typename Scalar>
void requireNonNegative(Scalar value, const std::string& field) {
  requireFinite(value, field);
  if (value < Scalar(0)) failInput(field, "must not be negative, got " + std::to_string(double(value)));
}

}  // namespace gjkx
