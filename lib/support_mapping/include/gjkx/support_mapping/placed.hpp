/// @file
/// @brief A shape placed at a pose, and a shape moving along a motion: P(t) and Q(t) (§2.1, §3).
#pragma once

#include <gjkx/motion/motion.hpp>
#include <gjkx/support_mapping/support.hpp>

#include <utility>

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
  /// A placed rounded shape is rounded, with the same radius (support.hpp, `IsRounded`).
  template <typename X = Shape, typename = std::enable_if_t<IsRounded<X>::value>>
  Scalar coreRadius() const {
    return shape.coreRadius();
  }
  /// The support of the placed core, $R\,S_C(R^Tec{s}) + p$.
  template <typename X = Shape, typename = std::enable_if_t<IsRounded<X>::value>>
  Vector3<Scalar> coreSupport(const Vector3<Scalar>& s, SupportHint& hint) const {
    return worldFromBody(shape.coreSupport(worldFromBody.toBodyDirection(s), hint));
  }
  /// The placed core's ends, when the core is a point or a segment (`HasSegmentCore`).
  template <typename X = Shape, typename = std::enable_if_t<HasSegmentCore<X>::value>>
  CoreEnds<Scalar> coreEnds() const {
    const CoreEnds<Scalar> c = shape.coreEnds();
    return {worldFromBody(c.a), worldFromBody(c.b)};
  }
};

/// `place(shape, pose)`: the shape at a pose (the pose is checked).
template <typename Shape>
Placed<Shape> place(const Shape& shape, const Pose<typename Shape::Scalar>& worldFromBody) {
  worldFromBody.validate("place.worldFromBody");
  return Placed<Shape>{shape, worldFromBody};
}

/// A shape moving along a rigid motion: X(t) = `Placed{shape, motion.pose(t)}`.
///
/// The stages after GJK (extrusion, Brent) see a moving body only through this door:
/// - `at(t)`: the body at time t, a static support mapping GJK runs on (the pose is
///   computed once, not once per support query);
/// - `support(s, t)`: \f$S_{X(t)}(\vec{s})\f$;
/// - `accelerationBound()`: how fast any point of the body can accelerate, for the
///   certified extrusion test (zero for linear motion).
/// Rigid motion, accelerated motion and per-vertex linear motion (DeformingSimplex) all fit.
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
  /// The same body seen from a frame whose origin sits at `-offset` (Motion::translated).
  Moving translated(const Vector3<Scalar>& offset) const { return Moving{shape, motion.translated(offset)}; }
  /// The same body on a clock that reads 0 at time `clock` (Motion::retimed).
  Moving retimed(Scalar clock) const& { return Moving{shape, motion.retimed(clock)}; }
  /// The same, reusing this body's shape (no copy of a polytope's vertices).
  Moving retimed(Scalar clock) && {
    motion = motion.retimed(clock);
    return std::move(*this);
  }
  /// The largest acceleration of a point of the body: \f$a + \alpha r + \omega^2 r\f$ with r the
  /// shape's bounding radius about its body origin (the centre of rotation).
  Scalar accelerationBound() const { return motion.bound().pointAcceleration(shape.boundingRadius()); }
};

/// `moving(shape, motion)`: a shape moving along a motion.
template <typename Shape>
Moving<Shape> moving(const Shape& shape, const Motion<typename Shape::Scalar>& motion) {
  return Moving<Shape>{shape, motion};
}

/// A shape at rest at `position`, not turned.
template <typename Shape>
Moving<Shape> fixedAt(const Shape& shape, const Vector3<typename Shape::Scalar>& position) {
  using S = typename Shape::Scalar;
  return moving(shape, Motion<S>::fixed(Pose<S>::translate(position)));
}

/// A shape at `start` at t = 0 moving at constant `velocity`, not turning: the linear
/// motion of §3.
template <typename Shape>
Moving<Shape> translating(const Shape& shape, const Vector3<typename Shape::Scalar>& start,
                          const Vector3<typename Shape::Scalar>& velocity) {
  using S = typename Shape::Scalar;
  return moving(shape, Motion<S>::constantVelocity(Pose<S>::translate(start), velocity));
}

}  // namespace gjkx
