/// @file
/// @brief Rigid poses `worldFromBody`: where a body stands at one instant (§3).
#pragma once

#include <gjkx/motion/round_off.hpp>
#include <gjkx/motion/vector.hpp>

namespace gjkx {

/// A rigid transform from a body's frame to the world frame, \f$x_w = R\,x_b + p\f$.
///
/// The paper's objects P(t) and Q(t) are a fixed shape placed at a pose that
/// changes with time (§3). The rotation is kept as a matrix, because a support
/// query needs \f$R^T\vec{s}\f$ and \f$R\,S(R^T\vec{s})\f$, two matrix products.
template <typename Scalar>
struct Pose {
  /// Rotation R (orthonormal, determinant +1).
  Matrix3<Scalar> rotation = Matrix3<Scalar>::Identity();
  /// Translation p: where the body origin lies in the world.
  Vector3<Scalar> translation = Vector3<Scalar>::Zero();

  /// The identity pose: body frame equals world frame.
  static Pose identity() { return Pose{}; }

  /// Bit for bit the same pose (every entry equal).
  bool operator==(const Pose& o) const { return rotation == o.rotation && translation == o.translation; }
  /// Not the same pose.
  bool operator!=(const Pose& o) const { return !(*this == o); }

  /// A pure translation.
  static Pose translate(const Vector3<Scalar>& p) {
    Pose pose;
    pose.translation = p;
    return pose;
  }

  /// A pose from a rotation and a translation; checks both (the message names the field).
  static Pose fromRotationTranslation(const Matrix3<Scalar>& rotation, const Vector3<Scalar>& translation) {
    Pose pose;
    pose.rotation = rotation;
    pose.translation = translation;
    pose.validate("pose");
    return pose;
  }

  /// A pose from a rotation of `angle` radians about `axis` (any length but zero) and a translation.
  static Pose fromAxisAngle(const Vector3<Scalar>& axis, Scalar angle, const Vector3<Scalar>& translation) {
    requireFinite(axis, "pose.axis");
    requireFinite(angle, "pose.angle");
    if (axis.norm() == Scalar(0)) failInput("pose.axis", "must be nonzero");
    Pose pose;
    pose.rotation = Eigen::AngleAxis<Scalar>(angle, axis.normalized()).toRotationMatrix();
    pose.translation = translation;
    pose.validate("pose");
    return pose;
  }

  /// Throws std::invalid_argument naming `field` if the pose is not finite or R is not a rotation.
  void validate(const std::string& field) const {
    if (!rotation.allFinite()) failInput(field + ".rotation", "must be finite");
    requireFinite(translation, field + ".translation");
    const bool orthonormal = (rotation.transpose() * rotation).isIdentity(rotationTolerance<Scalar>());
    if (!orthonormal || rotation.determinant() < Scalar(0))
      failInput(field + ".rotation", "must be orthonormal with determinant +1");
  }

  /// Maps a body-frame point to the world: \f$R\,x + p\f$.
  Vector3<Scalar> operator()(const Vector3<Scalar>& bodyPoint) const { return rotation * bodyPoint + translation; }

  /// Maps a world direction into the body frame: \f$R^T\vec{s}\f$ (directions do not translate).
  Vector3<Scalar> toBodyDirection(const Vector3<Scalar>& worldDirection) const {
    return rotation.transpose() * worldDirection;
  }

  /// Composition: `(a * b)(x) == a(b(x))`.
  friend Pose operator*(const Pose& a, const Pose& b) {
    Pose c;
    c.rotation = a.rotation * b.rotation;
    c.translation = a.rotation * b.translation + a.translation;
    return c;
  }

  /// The inverse transform (`bodyFromWorld`).
  Pose inverse() const {
    Pose inv;
    inv.rotation = rotation.transpose();
    inv.translation = -(inv.rotation * translation);
    return inv;
  }

  /// The same pose in another scalar type (e.g. double to float).
  template <typename Other>
  Pose<Other> cast() const {
    Pose<Other> other;
    other.rotation = rotation.template cast<Other>();
    other.translation = translation.template cast<Other>();
    return other;
  }
};

}  // namespace gjkx
