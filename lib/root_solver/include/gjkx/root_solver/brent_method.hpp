/// @file
/// @brief Brent's method: the root solver of §5 that combines bisection, the secant method
/// and inverse quadratic interpolation (the paper's reference [9]). No geometry here.
///
/// The one concept of the stage `root_solver`, which depends on `motion` only (for the
/// round-off constants): the time-of-impact solver of §5 (`brent`) and the impulse
/// integration of `dynamics`, which locates an impulse's phase changes with it, both link it
/// without either linking the other.
///
/// "Our implementation uses Brent's method, which is a root solver that cleverly
/// combines bisection, the secant method, and inverse quadratic interpolation to
/// guarantee superlinear convergence." (§5)
///
/// Brent keeps three abscissae: b, the best estimate so far (smallest |f|); a, the
/// previous b; and c, chosen so that f(b) and f(c) have opposite signs, so the root
/// always lies between b and c. Each step proposes an interpolation — inverse
/// quadratic through (a, b, c) when they are distinct, secant through (a, b) otherwise —
/// and accepts it only if it falls well inside the bracket and shrinks the step
/// faster than the step before last did (Brent's acceptance rules, which bound the
/// worst case by bisection). Otherwise it bisects. It stops when the bracket is below
/// \f$2\cdot(2\epsilon\lvert b\rvert + \mathrm{tol}/2)\f$ or f(b) = 0.
///
/// The time-of-impact solver of §5 changes its function between steps (its set of
/// separating vectors grows), so the method is written as a stepper the caller drives:
/// `next()` says where to evaluate, `update(f)` takes the value. `findRoot()` drives
/// it for a plain function.
#pragma once

#include <gjkx/motion/round_off.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace gjkx {

/// Which rule produced a Brent iterate.
enum class BrentStepKind {
  Bisection,               ///< the midpoint of the bracket
  Secant,                  ///< linear interpolation through a and b
  InverseQuadratic,        ///< inverse quadratic interpolation through a, b and c
  MinimalStep,             ///< the interpolated step was below the tolerance: step by the tolerance
  Leap,                    ///< not Brent's own: the time-of-impact solver's leap past a creeping restart (gjkx/brent/time_of_impact.hpp)
  DistanceSecant,          ///< not Brent's own: the time-of-impact solver's probe where the exact distances extrapolate to the tolerance (gjkx/brent/time_of_impact.hpp)
};

/// The name of a step kind, for traces.
inline const char* toString(BrentStepKind kind) {
  switch (kind) {
    case BrentStepKind::Bisection: return "bisection";
    case BrentStepKind::Secant: return "secant";
    case BrentStepKind::InverseQuadratic: return "inverse-quadratic";
    case BrentStepKind::MinimalStep: return "minimal-step";
    case BrentStepKind::Leap: return "leap";
    case BrentStepKind::DistanceSecant: return "distance-secant";
  }
  return "?";
}

/// Brent's method as a stepper (reverse communication): see the file comment.
template <typename S>
class BrentStepper {
 public:
  /// Starts on the bracket [a, b] with f(a) = fa and f(b) = fb of opposite signs (or one
  /// zero), stopping when the bracket is within `tolerance` (plus round-off). Throws
  /// std::invalid_argument naming the field for a non-finite input or a non-bracket.
  BrentStepper(S a, S fa, S b, S fb, S tolerance) : a_(a), b_(b), fa_(fa), fb_(fb), tol_(tolerance) {
    if (!std::isfinite(a) || !std::isfinite(b)) throw std::invalid_argument("brent.bracket: ends must be finite");
    if (!std::isfinite(fa) || !std::isfinite(fb)) throw std::invalid_argument("brent.f: values at the ends must be finite");
    if (!(tolerance >= S(0))) throw std::invalid_argument("brent.tolerance: must be a non-negative number");
    if ((fa > S(0) && fb > S(0)) || (fa < S(0) && fb < S(0)))
      throw std::invalid_argument("brent.bracket: f(a) and f(b) must have opposite signs");
    c_ = a_;
    fc_ = fa_;
    d_ = e_ = b_ - a_;
    advance();
  }

  /// True when the root is located within the tolerance (then `root()` is the answer).
  bool converged() const { return converged_; }
  /// The abscissa to evaluate next (meaningful while not converged).
  S next() const { return next_; }
  /// The rule that produced `next()`.
  BrentStepKind nextKind() const { return kind_; }
  /// Takes f(next()) and prepares the following step. A non-finite value throws
  /// std::invalid_argument ("brent.f: ...").
  void update(S fNext) {
    if (!std::isfinite(fNext)) throw std::invalid_argument("brent.f: the function returned a non-finite value");
    a_ = b_;
    fa_ = fb_;
    b_ = next_;
    fb_ = fNext;
    advance();
  }
  /// The best estimate of the root: the end of the bracket with the smaller |f|.
  S root() const { return b_; }
  /// f at `root()`.
  S fRoot() const { return fb_; }
  /// The end of the current bracket opposite `root()` (the root lies between the two).
  S counterpart() const { return c_; }

 private:
  // One pass of Brent's loop up to the choice of the next abscissa.
  void advance() {
    if ((fb_ > S(0) && fc_ > S(0)) || (fb_ < S(0) && fc_ < S(0))) {
      c_ = a_;  // keep the root between b and c
      fc_ = fa_;
      d_ = e_ = b_ - a_;
    }
    if (std::abs(fc_) < std::abs(fb_)) {  // b is the best estimate
      a_ = b_;
      b_ = c_;
      c_ = a_;
      fa_ = fb_;
      fb_ = fc_;
      fc_ = fa_;
    }
    const S tol1 = S(2) * machineEpsilon<S>() * std::abs(b_) + S(0.5) * tol_;  // Brent's 2 eps |b| + tol / 2
    const S xm = S(0.5) * (c_ - b_);
    if (std::abs(xm) <= tol1 || fb_ == S(0)) {
      converged_ = true;
      next_ = b_;
      return;
    }
    kind_ = BrentStepKind::Bisection;
    if (std::abs(e_) >= tol1 && std::abs(fa_) > std::abs(fb_)) {
      S p, q;
      const S s = fb_ / fa_;
      if (a_ == c_) {  // two points: secant
        p = S(2) * xm * s;
        q = S(1) - s;
        kind_ = BrentStepKind::Secant;
      } else {  // three points: inverse quadratic interpolation
        const S qa = fa_ / fc_, r = fb_ / fc_;
        p = s * (S(2) * xm * qa * (qa - r) - (b_ - a_) * (r - S(1)));
        q = (qa - S(1)) * (r - S(1)) * (s - S(1));
        kind_ = BrentStepKind::InverseQuadratic;
      }
      if (p > S(0)) q = -q;
      p = std::abs(p);
      // Brent's acceptance: inside the bracket (3/4 of the way at most) and shrinking
      // faster than half the step before last; otherwise bisect.
      const S min1 = S(3) * xm * q - std::abs(tol1 * q);
      const S min2 = std::abs(e_ * q);
      if (S(2) * p < std::min(min1, min2)) {
        e_ = d_;
        d_ = p / q;
      } else {
        d_ = xm;
        e_ = d_;
        kind_ = BrentStepKind::Bisection;
      }
    } else {
      d_ = xm;
      e_ = d_;
    }
    if (std::abs(d_) > tol1) {
      next_ = b_ + d_;
    } else {
      next_ = b_ + (xm > S(0) ? tol1 : -tol1);
      kind_ = BrentStepKind::MinimalStep;
    }
  }

  S a_, b_, c_ = S(0), fa_, fb_, fc_ = S(0), d_ = S(0), e_ = S(0), tol_;
  S next_ = S(0);
  BrentStepKind kind_ = BrentStepKind::Bisection;
  bool converged_ = false;
};

/// How a root search ended.
enum class RootStatus {
  Converged,     ///< the root is bracketed within the tolerance
  IterationCap,  ///< the iteration cap ran out; `root` is the best estimate
};

/// One evaluation of a root search.
template <typename S>
struct RootIterate {
  /// The abscissa evaluated.
  S x;
  /// f(x).
  S fx;
  /// The rule that chose x.
  BrentStepKind kind;
};

/// What `findRoot` found.
template <typename S>
struct RootResult {
  /// How the search ended.
  RootStatus status = RootStatus::IterationCap;
  /// The best estimate of the root.
  S root = S(0);
  /// f(root).
  S fRoot = S(0);
  /// Function evaluations after the two at the ends.
  int iterations = 0;
  /// Every evaluation, in order.
  std::vector<RootIterate<S>> iterates;
};

/// A root of f in [a, b], where f(a) and f(b) have opposite signs, by Brent's method.
/// Throws std::invalid_argument naming the field if [a, b] does not bracket a root or
/// f returns a non-finite value.
template <typename S, typename F>
RootResult<S> findRoot(F&& f, S a, S b, S tolerance, int maxIterations = 100) {
  BrentStepper<S> brent(a, f(a), b, f(b), tolerance);
  RootResult<S> result;
  while (!brent.converged() && result.iterations < maxIterations) {
    const S x = brent.next();
    const S fx = f(x);
    result.iterates.push_back({x, fx, brent.nextKind()});
    ++result.iterations;
    brent.update(fx);
  }
  result.status = brent.converged() ? RootStatus::Converged : RootStatus::IterationCap;
  result.root = brent.root();
  result.fRoot = brent.fRoot();
  return result;
}

}  // namespace gjkx
