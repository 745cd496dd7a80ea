/// @file
/// @brief `Shape`: any of the shapes of §2.1 behind one support mapping, chosen at run time.
#pragma once

#include <gjkx/support_mapping/polytope.hpp>
#include <gjkx/support_mapping/primitives.hpp>

#include <variant>

namespace gjkx {

/// Any of the shapes of this stage. GJK is a template over support mappings, so a
/// scene that knows its shapes pays nothing; a scene that decides at run time uses
/// this, at the cost of one switch per support query.
template <typename S>
class Shape {
 public:
  /// The scalar type.
  using Scalar = S;
  /// The alternatives.
  using Variant = std::variant<Point<S>, Segment<S>, Triangle<S>, Box<S>, Sphere<S>, Capsule<S>, Polytope<S>, Cylinder<S>>;

  /// Any alternative converts to a Shape.
  template <typename X, typename = std::enable_if_t<std::is_constructible_v<Variant, X>>>
  Shape(X x) : shape_(std::move(x)) {}  // NOLINT: implicit on purpose

  /// \f$S_X(\vec{s})\f$.
  Vector3<S> support(const Vector3<S>& s) const {
    return std::visit([&](const auto& x) { return Vector3<S>(x.support(s)); }, shape_);
  }
  /// \f$S_X(\vec{s})\f$ with a warm-start hint (used by the polytope).
  Vector3<S> support(const Vector3<S>& s, SupportHint& hint) const {
    return std::visit([&](const auto& x) { return Vector3<S>(supportFrom(x, s, hint)); }, shape_);
  }
  /// A point inside.
  Vector3<S> center() const {
    return std::visit([](const auto& x) { return Vector3<S>(x.center()); }, shape_);
  }
  /// The largest distance of a point of the shape from the body origin.
  S boundingRadius() const {
    return std::visit([](const auto& x) { return S(x.boundingRadius()); }, shape_);
  }
  /// The radius of the alternative if it is rounded (sphere, capsule), else 0: a Shape is
  /// always "rounded" (support.hpp, `IsRounded`), with a radius known only at run time.
  S coreRadius() const {
    return std::visit([](const auto& x) { return S(coreRadiusOf(x)); }, shape_);
  }
  /// The support of the alternative's core (the alternative itself if it is not rounded).
  Vector3<S> coreSupport(const Vector3<S>& s, SupportHint& hint) const {
    return std::visit([&](const auto& x) { return Vector3<S>(coreSupportFrom(x, s, hint)); }, shape_);
  }
  /// The alternative held.
  const Variant& variant() const { return shape_; }

 private:
  Variant shape_;
};

/// A Shape seen through a pointer: the same support mapping, without a copy. A simulation
/// places each body's pieces thousands of times per frame (`Placed`, `Moving` and the
/// solver's poses hold their shape by value), and copying a polytope's Shape copies its
/// shared hull (an atomic count up and down). The Shape must outlive the reference.
template <typename S>
class ShapeRef {
 public:
  /// The scalar type.
  using Scalar = S;
  /// A reference to `shape`.
  ShapeRef(const Shape<S>& shape) : shape_(&shape) {}  // NOLINT: implicit on purpose

  /// \f$S_X(\vec{s})\f$.
  Vector3<S> support(const Vector3<S>& s) const { return shape_->support(s); }
  /// \f$S_X(\vec{s})\f$ with a warm-start hint (used by the polytope).
  Vector3<S> support(const Vector3<S>& s, SupportHint& hint) const { return shape_->support(s, hint); }
  /// A point inside.
  Vector3<S> center() const { return shape_->center(); }
  /// The largest distance of a point of the shape from the body origin.
  S boundingRadius() const { return shape_->boundingRadius(); }
  /// The radius of the alternative if it is rounded, else 0 (Shape::coreRadius).
  S coreRadius() const { return shape_->coreRadius(); }
  /// The support of the alternative's core (Shape::coreSupport).
  Vector3<S> coreSupport(const Vector3<S>& s, SupportHint& hint) const { return shape_->coreSupport(s, hint); }
  /// The Shape referred to.
  const Shape<S>& shape() const { return *shape_; }

 private:
  const Shape<S>* shape_;
};

}  // namespace gjkx
