/// @file
/// @brief A shape placed at a pose, and a shape moving along a motion: P(t) and Q(t) (§2.1, §3).
#pragma once

#include <gjkx/motion/motion.hpp>
#include <gjkx/support_mapping/support.hpp>

namespace gjkx {

/// A shape X placed in the world at the pose `worldFromBody` = (R, p).
///
/// A rigid motion maps support points to support points: the point of R X + p
/// farthest along s is R times the point of X farthest along \f$R^T\vec{s}\f$, plus p:
/// \f[ S_{RX+p}(\vec{s}) = R\,S_X(R^T\vec{s}) + p. \f]
template <typename Shape>
struct Placed {
  /// The scalar type.
  using Scalar = typename Shape::Scalar;
  /// The shape, in its body frame.
  Shape shape;
  /// Where it stands: `worldFromBody`.
  Pose<Scalar> worldFromBody;

  /// \f$S(\vec{s}) = R\,S_X(R^T\vec{s}) + p\f$.
  Vector3<Scalar> support(const Vector3<Scalar>& s) const {
    return worldFromBody(shape.support(worldFromBody.toBodyDirection(s)));
  }
  /// The same with a warm-start hint for shapes that use one.
  Vector3<Scalar> support(const Vector3<Scalar>& s, SupportHint& hint) const {
    return worldFromBody(supportFrom(shape, worldFromBody.toBodyDirection(s), hint));
  }
  /// The shape's centre, in the world.
  Vector3<Scalar> center() const { return worldFromBody(shape.center()); }
};

/// `place(shape, pose)`: the shape at a pose (the pose is checked).
template <typename Shape>
Placed<Shape> place(const Shape& shape, const Pose<typename Shape::Scalar>& worldFromBody) {
  worldFromBody.validate("place.worldFromBody");
  return Placed<Shape>{shape, worldFromBody};
}

/// A shape moving along a rigid motion: X(t) = `Placed{shape, motion.pose(t)}`.
///
/// The stages after GJK (extrusion, Brent) ask a moving body only for
/// `support(s, t)`, the supporting vertex of X(t): that one door fits every motion.
template <typename Shape>
struct Moving {
  /// The scalar type.
  using Scalar = typename Shape::Scalar;
  /// The shape, in its body frame.
  Shape shape;
  /// How it moves: `pose(t)` = `worldFromBody` at time t.
  Motion<Scalar> motion;

  /// The body at time t, a static support mapping GJK can run on.
  Placed<Shape> at(Scalar t) const { return Placed<Shape>{shape, motion.pose(t)}; }
  /// \f$S_{X(t)}(\vec{s})\f$.
  Vector3<Scalar> support(const Vector3<Scalar>& s, Scalar t) const { return at(t).support(s); }
};

}  // namespace gjkx
