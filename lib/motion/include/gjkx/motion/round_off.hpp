/// @file
/// @brief The round-off constants of every stage, named once (as pbrt-v4's `float.h`
/// names `MachineEpsilon` and `gamma(n)`): the machine epsilon and the allowances built on it.
///
/// Every tolerance of the library that is a multiple or a power of the machine epsilon
/// \f$\epsilon\f$ of the scalar type is defined here, with the reason for its size, so a
/// reader can compare them side by side and a change is made in one place. All are
/// `constexpr` and exact: the powers \f$\epsilon^{1/2}\f$ and \f$\epsilon^{3/4}\f$ are built
/// from powers of two, and equal `std::sqrt` and `std::pow` of \f$\epsilon\f$ to the last bit
/// (tests/motion/test_round_off.cpp checks it for float, double and long double).
#pragma once

#include <limits>

namespace gjkx {

/// The machine epsilon \f$\epsilon\f$ of S: the gap between 1 and the next number of S,
/// \f$2^{-p}\f$ with p the bits of the fraction (\f$2^{-23}\f$ for float, \f$2^{-52}\f$ for
/// double). One rounded operation errs by at most \f$\epsilon/2\f$ of its result.
template <typename S>
constexpr S machineEpsilon() {
  return std::numeric_limits<S>::epsilon();
}

namespace detail {

/// \f$2^e\f$, exact in S (for e within S's exponent range).
template <typename S>
constexpr S powerOfTwo(int e) {
  S r = S(1);
  for (; e > 0; --e) r *= S(2);
  for (; e < 0; ++e) r /= S(2);
  return r;
}

/// \f$\epsilon^{k/4} = 2^{-kp/4}\f$: a power of two times \f$2^{j/4}\f$ (j = 0..3) rounded
/// once to S, which is the correctly rounded value, as `std::sqrt` gives for k = 2.
template <typename S>
constexpr S epsilonToQuarters(int k) {
  constexpr long double twoToQuarter[4] = {1.0L, 1.189207115002721066717499970560475915L,
                                           1.414213562373095048801688724209698079L,
                                           1.681792830507429086062250952466429790L};
  const int q = k * (std::numeric_limits<S>::digits - 1);  // eps^(k/4) = 2^(-q/4)
  const int whole = (q + 3) / 4;                           // 2^(-q/4) = 2^(-whole) * 2^(j/4)
  return powerOfTwo<S>(-whole) * S(twoToQuarter[4 * whole - q]);
}

}  // namespace detail

/// \f$\sqrt{\epsilon}\f$: half the digits of S. A quantity that is computed to \f$\epsilon\f$
/// but enters quadratically (a distance near a touching contact, a minimum in time) can be
/// located only to about \f$\sqrt{\epsilon}\f$. The paper's collision tolerance (§6).
template <typename S>
constexpr S sqrtEpsilon() {
  return detail::epsilonToQuarters<S>(2);
}

/// \f$\epsilon^{3/4}\f$: between \f$\epsilon\f$ and \f$\sqrt{\epsilon}\f$ (the default of
/// gjkx::GjkSettings::relativeTolerance).
template <typename S>
constexpr S epsilonToThreeQuarters() {
  return detail::epsilonToQuarters<S>(3);
}

/// The paper's collision tolerance, \f$\sqrt{\epsilon}\f$ of the scalar type (§2.3, §6:
/// "\f$\epsilon^{1/2} \approx 0.0003\f$, where \f$\epsilon\f$ is the 4-byte floating point
/// epsilon"). Bodies closer than this collide: GJK's round-off near a contact is about
/// \f$\epsilon\f$ of the shapes' size, far below it, so a separation it reports is real.
template <typename S>
constexpr S defaultCollisionTolerance() {
  return sqrtEpsilon<S>();
}

/// The time-of-impact solver's default time tolerance, \f$\sqrt{\epsilon}\f$ as a fraction of
/// the interval (§5; the paper gives no value): a time of impact is then resolved as finely,
/// relative to the interval, as the collision tolerance resolves a distance, and a grazing
/// contact, where the distance is quadratic in time, cannot be located more finely anyway.
template <typename S>
constexpr S defaultTimeTolerance() {
  return sqrtEpsilon<S>();
}

/// GJK's default relative convergence tolerance, \f$\epsilon^{3/4}\f$ (§2.2): stop when
/// \f$MD - SD \le \tau\,MD\f$. The gap \f$MD - SD\f$ is computed to about \f$\epsilon\f$ of the
/// shapes' size, so \f$\tau\f$ must stay well above \f$\epsilon\f$ (a factor
/// \f$\epsilon^{-1/4}\f$: 54 in float, 8192 in double) or the loop runs on round-off; and well
/// below the collision tolerance \f$\sqrt{\epsilon}\f$, so the distance it returns decides a
/// contact with digits to spare.
template <typename S>
constexpr S defaultGjkRelativeTolerance() {
  return epsilonToThreeQuarters<S>();
}

/// GJK's default overlap tolerance, \f$16\epsilon\f$ (§2.2): the origin counts as reached
/// when \f$\lVert z\rVert \le 16\epsilon\max_k\lVert w_k\rVert\f$. z is a combination of the
/// simplex's vertices \f$w_k\f$, each rounded by \f$\epsilon\lVert w_k\rVert\f$, and the
/// sub-algorithm adds a few roundings more; 16 covers them with room.
template <typename S>
constexpr S defaultOverlapTolerance() {
  return S(16) * machineEpsilon<S>();
}

/// GJK's tie allowance, \f$8\epsilon\f$ (§2.2): a new Minkowski distance no more than
/// \f$8\epsilon\max_k\lVert w_k\rVert\f$ above the old is a tie (no decrease within round-off),
/// not a step back. The round-off of \f$\lVert z\rVert\f$ scales with the simplex's size, not
/// with \f$\lVert z\rVert\f$: z is computed from the w.
template <typename S>
constexpr S gjkTieAllowance() {
  return S(8) * machineEpsilon<S>();
}

/// The safety factor of the signed-volume sub-algorithm, \f$64\epsilon\f$ (§2.2): a signed
/// length, area or volume whose size is within \f$64\epsilon\f$ times the lengths it
/// multiplies has a sign that is noise and is not trusted (see simplex.hpp). Each such
/// measure is a sum of a few rounded products, so its round-off is a small multiple of
/// \f$\epsilon\f$; 64 leaves room for the projection and the edges it is built from.
template <typename S>
constexpr S signSafety() {
  return S(64) * machineEpsilon<S>();
}

/// How far from orthonormal a pose's rotation may be, \f$1000\epsilon\f$ per entry of
/// \f$R^T R - I\f$ (§3): a rotation built from an angle and an axis, or composed from a few
/// others, is off by a few \f$\epsilon\f$ per product; a matrix that is not a rotation is
/// off by far more.
template <typename S>
constexpr S rotationTolerance() {
  return S(1000) * machineEpsilon<S>();
}

// The allowances of the checks (tests/fuzz): how far a result may be from the exact
// long-double reference (lib/reference) before a check blames the library.

/// Round-offs of the bodies' extent a checked result may be off by, 1000: a GJK run on
/// coordinates of size R rounds each support point by \f$\epsilon R\f$, and a few hundred
/// rounded operations lie between the input and a distance or a time.
constexpr int checkSlackRoundOffs = 1000;

/// Multiples of GJK's relative tolerance a checked distance on polytopes may be off by, 16:
/// GJK stops when its upper and lower bounds are within the relative tolerance of each
/// other, and the bound it returns is itself rounded.
constexpr int checkRelativeAllowance = 16;

/// How far the closest point z of GJK's final simplex may be from the true one, per unit
/// of the simplex's largest \f$\lVert w_k\rVert\f$ and of its thinness (16ε: the same
/// round-off that `defaultOverlapTolerance` allows z near the origin).
template <typename S>
constexpr S closestPointRoundOff() {
  return defaultOverlapTolerance<S>();
}

/// The relative allowance of a checked distance between rounded shapes, \f$\sqrt{\epsilon}\f$:
/// GJK converges slowly on curved surfaces and stops when the distance no longer decreases
/// in round-off, with the gap between its bounds still open.
template <typename S>
constexpr S roundedShapeAllowance() {
  return sqrtEpsilon<S>();
}

}  // namespace gjkx
