/// @file
/// @brief Beyond the paper: the margin that makes the extrusion test certain under rotation and acceleration.
///
/// §3 admits that with nonlinear motion "the separating space at \f$t_0\f$ may vanish
/// undetected, and a subset of which could reappear at \f$t_1\f$", errors "of second order
/// motion". This header bounds them, so that a test that asks for the bound as a margin
/// never misses a collision of a motion within its bounds.
///
/// **Derivation.** Fix a unit direction s and an interval \f$[t_a, t_b]\f$, \f$\Delta = t_b - t_a\f$.
/// For one body point x(t), the function \f$f(t) = \vec{s}\cdot x(t)\f$ differs from its chord
/// \f$L(t)\f$ (the straight line through its values at \f$t_a\f$ and \f$t_b\f$) by at most
/// \f[ \lvert f(t) - L(t)\rvert \le \tfrac{(t - t_a)(t_b - t)}{2}\max\lvert f''\rvert \le \tfrac{\Delta^2}{8}\,\max\lVert\ddot x\rVert. \f]
/// The support function \f$h(t) = \max_x f_x(t)\f$ is then at most the chord of h plus the
/// same amount, because every \f$L_x\f$ lies below the chord of h. A rigid body point at
/// distance r from the centre of rotation accelerates at most \f$D = a + \alpha r + \omega^2 r\f$
/// (`Moving::accelerationBound()`). The supporting distance, \f$-h_Q(-\vec{s},t) - h_P(\vec{s},t)\f$,
/// is therefore at least the smaller of its two end values minus
/// \f[ m(\Delta) = \tfrac{\Delta^2}{8}\,(D_P + D_Q) \f]
/// anywhere in the interval. A vector whose supporting distance exceeds the collision
/// tolerance plus \f$m(\Delta)\f$ at both ends separates P and Q over the whole interval.
/// For linear motion, and for per-vertex linear motion, \f$D = 0\f$ and the margin vanishes:
/// the certified test is then the paper's test.
#pragma once

#include <algorithm>

namespace gjkx {

/// Which extrusion test to run.
enum class ExtrusionVariant {
  Paper,      ///< §3 as stated: SD > tolerance at both ends (exact for linear motion only)
  Certified,  ///< beyond the paper: SD > tolerance + \f$\frac{\Delta^2}{8}(D_P + D_Q)\f$ at both ends (exact for bounded motion)
};

/// The name of a variant, for tables.
inline const char* toString(ExtrusionVariant variant) {
  return variant == ExtrusionVariant::Paper ? "paper" : "certified";
}

/// \f$m(\Delta) = \frac{\Delta^2}{8}(D_P + D_Q)\f$: how far a supporting distance can dip between
/// the ends of an interval of length `duration` (see the file comment); 0 for the paper's variant.
template <typename S>
S extrusionMargin(ExtrusionVariant variant, S duration, S accelerationBoundP, S accelerationBoundQ) {
  if (variant == ExtrusionVariant::Paper) return S(0);
  return duration * duration / S(8) * (accelerationBoundP + accelerationBoundQ);
}

/// The least value the supporting distance along a fixed vector can take over an interval,
/// given its end values `sd0` and `sd1` (see the file comment; 0 margin for the paper's variant).
///
/// **Derivation.** With \f$\tau = (t - t_a)/\Delta\f$ and \f$c = \tfrac{\Delta^2}{2}(D_P + D_Q)\f$,
/// the bound of the file comment, kept as a function of t rather than its worst case, is
/// \f$g(\tau) = sd_0 + (sd_1 - sd_0)\,\tau - c\,\tau(1 - \tau)\f$, a parabola opening upwards.
/// Its least value on [0, 1] is at \f$\tau^* = \frac{c - (sd_1 - sd_0)}{2c}\f$ when that lies
/// inside, else at an end. Near an end the margin vanishes with its distance to it, so
/// bodies that start a hair apart and move apart faster than c are proven apart, where the
/// flat bound \f$\min(sd_0, sd_1) - m(\Delta)\f$ (m = c/4) would not.
template <typename S>
S lowestSupportingDistance(ExtrusionVariant variant, S sd0, S sd1, S duration, S accelerationBoundP,
                           S accelerationBoundQ) {
  const S c = S(4) * extrusionMargin(variant, duration, accelerationBoundP, accelerationBoundQ);
  if (!(c > S(0))) return std::min(sd0, sd1);  // no margin: the chord's lower end
  const S rise = sd1 - sd0;
  const S tau = std::clamp((c - rise) / (S(2) * c), S(0), S(1));
  return sd0 + rise * tau - c * tau * (S(1) - tau);
}

}  // namespace gjkx
