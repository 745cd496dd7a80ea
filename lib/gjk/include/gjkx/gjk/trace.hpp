/// @file
/// @brief What one GJK iteration did, the visitor that sees it, and the trace that keeps it (§2.2, Fig. 2).
#pragma once

#include <gjkx/gjk/simplex.hpp>

#include <vector>

namespace gjkx {

/// How an iteration ended.
enum class GjkStep {
  Continue,            ///< the simplex was refined and the Minkowski distance decreased: go on
  Converged,           ///< the new support point brought no progress: z is the closest point
  Overlap,             ///< the origin lies in the simplex (or within round-off of it)
  SeparatingVector,    ///< \f$SD(\vec{s}_i)\f$ exceeded the separation threshold (boolean query)
  Stalled,             ///< no progress, but the gap \f$MD - SD\f$ is still open: the distance is only bracketed
};

/// The name of a step, for messages and trace tables.
inline const char* toString(GjkStep step) {
  switch (step) {
    case GjkStep::Continue: return "continue";
    case GjkStep::Converged: return "converged";
    case GjkStep::Overlap: return "overlap";
    case GjkStep::SeparatingVector: return "separating-vector";
    case GjkStep::Stalled: return "stalled";
  }
  return "?";
}

/// One iteration i of GJK, as Fig. 2 draws it.
template <typename S>
struct GjkIteration {
  /// The iteration number i, from 0.
  int i = 0;
  /// \f$\vec{s}_i\f$, the search direction.
  Vector3<S> s;
  /// \f$S_P(\vec{s}_i)\f$, appended to \f$V_P\f$.
  Vector3<S> supportP;
  /// \f$S_Q(-\vec{s}_i)\f$, appended to \f$V_Q\f$.
  Vector3<S> supportQ;
  /// \f$SD(P, Q, \vec{s}_i)\f$, the supporting distance along \f$\vec{s}_i\f$ (§2.3); positive: \f$\vec{s}_i\f$ is a separating vector.
  S supportingDistance = S(0);
  /// The simplex \f$V_Z\f$ kept after this iteration (its closest feature to the origin).
  Simplex<S> simplex;
  /// z, the point of the kept simplex closest to the origin (\f$\vec{s}_{i+1} = z\f$).
  Vector3<S> z;
  /// The Minkowski distance \f$\lVert z\rVert\f$.
  S minkowskiDistance = S(0);
  /// How the iteration ended.
  GjkStep step = GjkStep::Continue;
};

/// The default visitor: sees nothing, costs nothing (the call is compiled out).
struct NoGjkVisitor {
  /// Always continue.
  template <typename Iteration>
  bool operator()(const Iteration&) const { return true; }
};

/// A visitor that keeps every iteration, for the figures and the step-by-step tests.
template <typename S>
struct GjkTrace {
  /// The iterations, in order.
  std::vector<GjkIteration<S>> iterations;
  /// Keeps the iteration; never stops the run.
  bool operator()(const GjkIteration<S>& iteration) {
    iterations.push_back(iteration);
    return true;
  }
};

}  // namespace gjkx
