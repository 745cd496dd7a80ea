/// @file
/// @brief One contact point's friction step in the hybrid's velocity solve (§6's future work,
/// contact_solver.hpp): the impulse on Coulomb's disc that lowers the kinetic energy most.
///
/// A sweep of sequential impulses takes the points one at a time. At a point, the friction
/// impulse f lies in the disc \f$|f| \le \mu\lambda_n\f$; the step is the exact minimiser of
/// the kinetic energy over the disc with every other impulse held, so that no step of a
/// sweep can raise the energy. Inside the disc the point sticks; on its edge it slides,
/// friction opposite to the slip that remains (Coulomb's maximal dissipation).
#pragma once

#include <Eigen/Core>

namespace gjkx {

/// The tangent plane's 2x2 response block of a contact point in the velocity solve (§6's
/// future work, the hybrid): how the point's slip answers a friction impulse, made once per
/// solve with what each friction step needs of it.
struct TangentBlock {
  Eigen::Matrix2d K = Eigen::Matrix2d::Zero();         ///< the block (symmetric, positive semi-definite)
  Eigen::Matrix2d inverse = Eigen::Matrix2d::Zero();   ///< K⁻¹, zero where K has none
  Eigen::Matrix2d axes = Eigen::Matrix2d::Identity();  ///< K's eigenvectors, as columns
  Eigen::Vector2d stiffness = Eigen::Vector2d::Zero();  ///< K's eigenvalues
  bool invertible = false;                              ///< true where K has an inverse
  /// The block K with its inverse and eigen decomposition.
  static TangentBlock of(const Eigen::Matrix2d& K);
};

/// One point's friction step in the velocity solve (§6's future work, the hybrid): the
/// friction impulse f in Coulomb's disc \f$|f| \le L\f$ (L = \f$\mu\lambda_n\f$) that lowers
/// the kinetic energy most with every other impulse held, from the current impulse `old`, the
/// point's slip `slip` (its tangent velocity) and the tangent plane's response `block`.
/// Inside the disc the point sticks (the slip stops); outside it slides, f on the circle
/// opposite to the slip that remains. The exact minimiser over a convex set that holds
/// `old`: the step never raises the energy. The derivation is above the code.
Eigen::Vector2d frictionInDisc(const TangentBlock& block, const Eigen::Vector2d& old, const Eigen::Vector2d& slip,
                               double limit);

}  // namespace gjkx
