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

}  // namespace gjkx
