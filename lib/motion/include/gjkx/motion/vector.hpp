/// @file
/// @brief Vector and matrix names shared by every stage (Eigen, templated on the scalar type).
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <cmath>
#include <stdexcept>
#include <string>

namespace gjkx {

/// A column vector of R^3: points, directions \f$\vec{s}\f$ and support points (§2.1).
template <typename Scalar>
using Vector3 = Eigen::Matrix<Scalar, 3, 1>;

/// A 3x3 matrix: the rotation part of a pose (§3, rigid motion).
template <typename Scalar>
using Matrix3 = Eigen::Matrix<Scalar, 3, 3>;

/// Throws std::invalid_argument "<field>: <what>" where bad input enters the library.
inline void failInput(const std::string& field, const std::string& what) {
  throw std::invalid_argument(field + ": " + what);
}

/// Checks that a scalar input is finite; the message names the field.
template <typename Scalar>
void requireFinite(Scalar value, const std::string& field) {
  if (!std::isfinite(value)) failInput(field, "must be finite, got " + std::to_string(double(value)));
}

/// Checks that every component of a vector input is finite; the message names the field.
template <typename Scalar>
void requireFinite(const Vector3<Scalar>& v, const std::string& field) {
  if (!v.allFinite()) failInput(field, "must be finite (no NaN or infinity)");
}

/// Checks a time interval [t0, t1]: both finite and t1 >= t0 (the message names the field).
template <typename Scalar>
void requireInterval(Scalar t0, Scalar t1, const std::string& field) {
  requireFinite(t0, field + ".t0");
  requireFinite(t1, field + ".t1");
  if (t1 < t0) failInput(field + ".t1", "must not be before t0");
}

}  // namespace gjkx
