// What the support mapping's tests share: the tolerance for coordinates of size about 10
// in each scalar, and random directions.
#pragma once

#include <gjkx/support_mapping/primitives.hpp>

#include <random>
#include <type_traits>

namespace gjkx::test {

/// π, for the tests' angles.
constexpr double kPi = 3.14159265358979323846;

/// Tolerance for coordinates of size about 10: tight in double, looser in float.
template <typename S>
S tol() {
  return std::is_same_v<S, float> ? S(1e-5) : S(1e-12);
}

/// A random direction (not normalized), from a normal distribution per coordinate, never
/// shorter than 1e-3.
template <typename S>
Vector3<S> randomDirection(std::mt19937& rng) {
  std::normal_distribution<S> n(S(0), S(1));
  Vector3<S> s;
  do s = Vector3<S>(n(rng), n(rng), n(rng));
  while (s.norm() < S(1e-3));
  return s;
}

}  // namespace gjkx::test
