// One contact point's friction step (coulomb_friction.hpp).
#include <gjkx/timewarp/coulomb_friction.hpp>

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>

namespace gjkx {

TangentBlock TangentBlock::of(const Eigen::Matrix2d& K) {
  TangentBlock block;
  block.K = K;
  block.invertible = K.determinant() > 1e-300;
  if (!block.invertible) return block;
  block.inverse = K.inverse();
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eigen;
  eigen.computeDirect(K);
  block.axes = eigen.eigenvectors();
  block.stiffness = eigen.eigenvalues();
  return block;
}

// The friction step.
//
// An impulse change Δ = f − f0 in the tangent plane changes the slip s by KΔ, and the
// kinetic energy by φ(f) = s·Δ + ½ ΔᵀKΔ (K the plane's 2x2 block, symmetric, positive
// definite). Inside the disc the minimiser is where the slip stops, f_u = f0 − K⁻¹s: the
// point sticks. Outside, the minimiser lies on the circle, where ∇φ = K(f − f0) + s = −η f
// for some η > 0 (Lagrange): f(η) = (K + ηI)⁻¹ (K f0 − s), and |f(η)| = L fixes η. The
// slip left, −η f, is opposite to the friction: the point slides, and feels exactly L
// against its slip (Coulomb's maximal dissipation).
//
// In K's eigenbasis (eigenvalues k1, k2; c = Qᵀ(K f0 − s)), |f(η)|² = Σ c_m² / (k_m + η)²,
// which falls as η grows, and ψ(η) = 1/|f(η)| − 1/L is increasing and concave (as in Moré
// and Sorensen's trust region step, 1983): Newton's method from η = 0, where ψ < 0, climbs
// to the root from below without overshooting, in a few steps.
//
// Being the exact minimiser over a convex set that holds f0, the step never raises φ: a
// sweep of such steps only lowers the kinetic energy.
Eigen::Vector2d frictionInDisc(const TangentBlock& block, const Eigen::Vector2d& old, const Eigen::Vector2d& slip,
                               double limit) {
  if (!block.invertible)  // no response in the plane: nothing to solve, kept in the disc
    return old.norm() > limit ? Eigen::Vector2d(old * (limit / old.norm())) : old;
  const Eigen::Vector2d free = old - block.inverse * slip;
  if (free.norm() <= limit) return free;
  if (limit <= 0) return Eigen::Vector2d::Zero();
  const Eigen::Vector2d& k = block.stiffness;
  const Eigen::Vector2d c = block.axes.transpose() * (block.K * old - slip);
  double eta = 0;
  for (int iteration = 0; iteration < 30; ++iteration) {
    const double q0 = 1 / (k[0] + eta), q1 = 1 / (k[1] + eta);
    const double size = std::sqrt(c[0] * c[0] * q0 * q0 + c[1] * c[1] * q1 * q1);
    const double psi = 1 / size - 1 / limit;
    if (psi >= -1e-12 / limit) break;
    // dψ/dη = Σ c_m² / (k_m + η)³ / |f|³
    const double slope = (c[0] * c[0] * q0 * q0 * q0 + c[1] * c[1] * q1 * q1 * q1) / (size * size * size);
    if (!(slope > 0)) break;
    eta -= psi / slope;
  }
  const Eigen::Vector2d f = block.axes * Eigen::Vector2d(c[0] / (k[0] + eta), c[1] / (k[1] + eta));
  const double size = f.norm();
  return size > limit ? Eigen::Vector2d(f * (limit / size)) : f;  // on the circle (round-off)
}

}  // namespace gjkx
