/// @file
/// @brief Vector and matrix names shared by every stage (Eigen, templated on the scalar type).
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <cmath>
#include <stdexcept>
#include <string>
#include <string_view>

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

// (The checks below take the field's name as a view and build the message only when the
// input is bad: the time-of-impact solver and the hierarchies check their intervals at
// every query.)

/// Checks that a scalar input is finite; the message names the field.
template <typename Scalar>
void requireFinite(Scalar value, std::string_view field) {
  if (!std::isfinite(value)) failInput(std::string(field), "must be finite, got " + std::to_string(double(value)));
}

/// Checks that every component of a vector input is finite; the message names the field.
template <typename Scalar>
void requireFinite(const Vector3<Scalar>& v, std::string_view field) {
  if (!v.allFinite()) failInput(std::string(field), "must be finite (no NaN or infinity)");
}

/// Checks a time interval [t0, t1]: both finite and t1 >= t0 (the message names the field).
template <typename Scalar>
void requireInterval(Scalar t0, Scalar t1, std::string_view field) {
  if (std::isfinite(t0) && std::isfinite(t1) && t1 >= t0) return;
  requireFinite(t0, std::string(field) + ".t0");
  requireFinite(t1, std::string(field) + ".t1");
  if (t1 < t0) failInput(std::string(field) + ".t1", "must not be before t0");
}

}  // namespace gjkx
