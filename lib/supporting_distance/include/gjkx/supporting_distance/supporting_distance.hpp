/// @file
/// @brief The supporting distance \f$SD(P, Q, \vec{s})\f$ and its maximum over directions (§2.3, §4, Fig. 3).
#pragma once

#include <gjkx/support_mapping/support.hpp>

#include <limits>
#include <vector>

namespace gjkx {

/// \f$SD(P, Q, \vec{s}) = \vec{s}\cdot S_Q(-\vec{s}) - \vec{s}\cdot S_P(\vec{s})\f$ for the unit
/// vector along s (§2.3): "the *signed* distance between the supporting planes of P and Q
/// in opposing directions of \f$\vec{s}\f$". Positive: the plane through \f$S_P(\vec{s})\f$
/// normal to s separates P and Q, and \f$\vec{s}\f$ is a *separating vector* (Q lies
/// beyond P along s). Negative: along s the two sets overlap by that much.
/// A zero s separates nothing: the result is \f$-\infty\f$.
template <typename ShapeP, typename ShapeQ>
typename ShapeP::Scalar supportingDistance(const ShapeP& P, const ShapeQ& Q,
                                           const Vector3<typename ShapeP::Scalar>& s) {
  using S = typename ShapeP::Scalar;
  const S n = s.norm();
  if (!(n > S(0))) return -std::numeric_limits<S>::infinity();
  return (s.dot(Q.support(Vector3<S>(-s))) - s.dot(P.support(s))) / n;
}

/// The same, starting each support search at a hill-climbing hint (§2.1), read and written
/// as `supportFrom` does: `hintP` for \f$S_P(\vec{s})\f$, `hintQ` for \f$S_Q(-\vec{s})\f$.
/// The value is the one above; only the work differs. The time-of-impact solver
/// evaluates SD along each stored separating vector at many times (§5): kept per vector,
/// the hints start each polytope's climb at the vertex it ended on last time, a few
/// steps from the answer, where a climb from vertex 0 crosses the polytope.
template <typename ShapeP, typename ShapeQ>
typename ShapeP::Scalar supportingDistance(const ShapeP& P, const ShapeQ& Q, const Vector3<typename ShapeP::Scalar>& s,
                                           SupportHint& hintP, SupportHint& hintQ) {
  using S = typename ShapeP::Scalar;
  const S n = s.norm();
  if (!(n > S(0))) return -std::numeric_limits<S>::infinity();
  return (s.dot(supportFrom(Q, Vector3<S>(-s), hintQ)) - s.dot(supportFrom(P, s, hintP))) / n;
}

/// The largest supporting distance over the given directions, and the direction giving it.
template <typename S>
struct MaximumSupportingDistance {
  /// \f$\max_k SD(P, Q, \vec{s}_k)\f$.
  S value = -std::numeric_limits<S>::infinity();
  /// The unit direction that gave it.
  Vector3<S> direction = Vector3<S>::Zero();
};

/// \f$\max_{\vec{s}} SD(P,Q,\vec{s})\f$ over a set of directions, by exhaustive search (§4).
///
/// Over all unit vectors, the maximum supporting distance is the closest distance when
/// P and Q are disjoint and minus the penetration depth when they intersect (Fig. 3).
/// GJK finds it efficiently in the first case; in the second "an exhaustive search may
/// be required", which is what this is: the figures sample the unit circle densely.
template <typename ShapeP, typename ShapeQ>
MaximumSupportingDistance<typename ShapeP::Scalar> maximumSupportingDistance(
    const ShapeP& P, const ShapeQ& Q, const std::vector<Vector3<typename ShapeP::Scalar>>& directions) {
  MaximumSupportingDistance<typename ShapeP::Scalar> best;
  for (const auto& s : directions) {
    const auto sd = supportingDistance(P, Q, s);
    if (sd > best.value) {
      best.value = sd;
      best.direction = s.normalized();
    }
  }
  return best;
}

}  // namespace gjkx
