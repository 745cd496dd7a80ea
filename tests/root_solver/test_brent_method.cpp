// Brent's method on plain functions (§5, the paper's reference [9]): no geometry here.
//
// The time-of-impact solver drives a BrentStepper with a function that changes between
// steps; before trusting it there, these tests check the stepper on functions whose
// roots are known: where it converges, how many evaluations it needs, that every
// iterate stays inside the current bracket, and, step by step, that the first iterates
// on x^2 - 2 are exactly the secant and inverse quadratic steps derived by hand below.
#include <gjkx/root_solver/brent_method.hpp>

#include <catch2/catch.hpp>

#include <cmath>
#include <functional>
#include <iostream>
#include <limits>
#include <stdexcept>
#include <string>

using namespace gjkx;

namespace {

// Drives the stepper by hand and checks, before every evaluation, that the iterate lies
// inside the current bracket [min(root, counterpart), max(root, counterpart)] and that
// f changes sign over the bracket. Returns the number of evaluations.
int driveInsideBracket(const std::function<double(double)>& f, double a, double b, double tol, double& root) {
  BrentStepper<double> brent(a, f(a), b, f(b), tol);
  int iterations = 0;
  while (!brent.converged()) {
    const double lo = std::min(brent.root(), brent.counterpart());
    const double hi = std::max(brent.root(), brent.counterpart());
    const double fb = f(brent.root()), fc = f(brent.counterpart());
    REQUIRE(!((fb > 0 && fc > 0) || (fb < 0 && fc < 0)));  // still a bracket
    const double x = brent.next();
    INFO("iteration " << iterations << ": x = " << x << " in [" << lo << ", " << hi << "]");
    REQUIRE(x >= lo);
    REQUIRE(x <= hi);
    brent.update(f(x));
    REQUIRE(++iterations <= 200);
  }
  root = brent.root();
  return iterations;
}

// The message of the std::invalid_argument thrown by `call`, or "" if none.
std::string invalidArgumentMessage(const std::function<void()>& call) {
  try {
    call();
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

}  // namespace

// x^2 - 2 on [0, 2]: the root is sqrt(2); Brent must land within the tolerance and use
// far fewer evaluations than bisection (which needs log2(2 / 1e-12) = 41).
TEST_CASE("Brent finds sqrt(2) as the root of x^2 - 2 on [0, 2]", "[brent][root]") {
  const auto r = findRoot([](double x) { return x * x - 2.0; }, 0.0, 2.0, 1e-12);
  std::cout << "BRENT x^2-2 on [0,2]: iterations=" << r.iterations << "\n";
  REQUIRE(r.status == RootStatus::Converged);
  CHECK(std::abs(r.root - std::sqrt(2.0)) <= 1e-12);
  CHECK(r.iterations <= 12);
  CHECK(r.iterations == static_cast<int>(r.iterates.size()));
}

// cos(x) - x on [0, 1]: the Dottie number 0.739085133215160641655...
TEST_CASE("Brent finds the fixed point of cos", "[brent][root]") {
  const auto r = findRoot([](double x) { return std::cos(x) - x; }, 0.0, 1.0, 1e-13);
  std::cout << "BRENT cos(x)-x on [0,1]: iterations=" << r.iterations << "\n";
  REQUIRE(r.status == RootStatus::Converged);
  CHECK(std::abs(r.root - 0.7390851332151607) <= 1e-13);
  CHECK(r.iterations <= 10);
}

// (x - 1)^3 on [-1, 4]: the function is flat around its root, so interpolation creeps
// (each step shrinks the bracket by little) and Brent's acceptance rule must fall back
// to bisection; it still converges, with a bounded number of evaluations.
TEST_CASE("Brent falls back to bisection on the flat cubic (x - 1)^3", "[brent][root]") {
  const auto f = [](double x) { return (x - 1) * (x - 1) * (x - 1); };
  const auto r = findRoot(f, -1.0, 4.0, 1e-10);
  int bisections = 0;
  for (const auto& it : r.iterates) bisections += it.kind == BrentStepKind::Bisection;
  std::cout << "BRENT (x-1)^3 on [-1,4]: iterations=" << r.iterations << " bisections=" << bisections << "\n";
  REQUIRE(r.status == RootStatus::Converged);
  CHECK(std::abs(r.root - 1.0) <= 1e-10);
  CHECK(bisections >= 1);
  // Bisection alone needs log2(5 / 1e-10) = 36 halvings; Brent is at worst a few times that.
  CHECK(r.iterations <= 3 * 36);
  double root = 0;
  driveInsideBracket(f, -1.0, 4.0, 1e-10, root);
  CHECK(std::abs(root - 1.0) <= 1e-10);
}

// tanh(100 (x - 0.3)) on [0, 1]: nearly a step; the interpolants overshoot far from the
// root, so Brent must bisect until the steep part is bracketed.
TEST_CASE("Brent on the step-like tanh(100 (x - 0.3))", "[brent][root]") {
  const auto f = [](double x) { return std::tanh(100 * (x - 0.3)); };
  const auto r = findRoot(f, 0.0, 1.0, 1e-12);
  int bisections = 0;
  for (const auto& it : r.iterates) bisections += it.kind == BrentStepKind::Bisection;
  std::cout << "BRENT tanh(100(x-0.3)) on [0,1]: iterations=" << r.iterations << " bisections=" << bisections
            << "\n";
  REQUIRE(r.status == RootStatus::Converged);
  CHECK(std::abs(r.root - 0.3) <= 1e-12);
  CHECK(bisections >= 1);
  CHECK(r.iterations <= 50);
  double root = 0;
  driveInsideBracket(f, 0.0, 1.0, 1e-12, root);
  CHECK(std::abs(root - 0.3) <= 1e-12);
}

// Every iterate of every function above stays inside the current bracket (checked at
// each step by driveInsideBracket), including the functions not tried above.
TEST_CASE("Brent's iterates never leave the bracket", "[brent][root]") {
  struct Case {
    const char* name;
    std::function<double(double)> f;
    double a, b, root;
  };
  const Case cases[] = {
      {"x^2-2", [](double x) { return x * x - 2; }, 0.0, 2.0, std::sqrt(2.0)},
      {"cos(x)-x", [](double x) { return std::cos(x) - x; }, 0.0, 1.0, 0.7390851332151607},
      {"x^9 (odd, very flat)", [](double x) { return std::pow(x, 9); }, -1.0, 3.0, 0.0},
      {"exp(x)-10", [](double x) { return std::exp(x) - 10; }, -5.0, 5.0, std::log(10.0)},
      {"1/(x+0.5)-1 (pole outside)", [](double x) { return 1 / (x + 0.5) - 1; }, 0.0, 4.0, 0.5},
  };
  for (const Case& c : cases) {
    INFO(c.name);
    double root = 0;
    const int n = driveInsideBracket(c.f, c.a, c.b, 1e-11, root);
    std::cout << "BRENT " << c.name << ": iterations=" << n << "\n";
    // x^9 is so flat that |f| < 1e-300 far from 0: the bracket, not f, decides there.
    CHECK(std::abs(root - c.root) <= 1e-11 + 1e-10 * std::abs(c.root));
  }
}

// A root at an end of the bracket needs no evaluation at all.
TEST_CASE("a root at an end of the bracket is returned at once", "[brent][root]") {
  // f(a) = 0: the constructor swaps a into b (|f(a)| < |f(b)|) and stops on f(b) == 0.
  const auto left = findRoot([](double x) { return x; }, 0.0, 1.0, 1e-12);
  REQUIRE(left.status == RootStatus::Converged);
  CHECK(left.root == 0.0);
  CHECK(left.fRoot == 0.0);
  CHECK(left.iterations == 0);
  // f(b) = 0.
  const auto right = findRoot([](double x) { return x - 1; }, 0.0, 1.0, 1e-12);
  REQUIRE(right.status == RootStatus::Converged);
  CHECK(right.root == 1.0);
  CHECK(right.iterations == 0);
}

// On a linear function the secant step is exact, so Brent converges in one evaluation.
// f(x) = x - 1 on [0, 3]: f(0) = -1, f(3) = 2. Since |f(0)| < |f(3)|, b = 0 is the best
// estimate, a = c = 3. xm = (c - b)/2 = 1.5, s = f(b)/f(a) = -1/2, p = 2 xm s = -1.5,
// q = 1 - s = 1.5; p < 0 so q keeps its sign and p = 1.5: the step d = p/q = 1 is
// accepted (2p = 3 < min(3 xm q, |e q|) = min(6.75, 4.5)), x1 = b + d = 1 exactly,
// where f = 0: done. Every number here is a dyadic rational, so the check is exact.
TEST_CASE("Brent on a linear function: one exact secant step", "[brent][root][hand]") {
  const auto r = findRoot([](double x) { return x - 1.0; }, 0.0, 3.0, 1e-12);
  REQUIRE(r.status == RootStatus::Converged);
  REQUIRE(r.iterations == 1);
  CHECK(r.iterates[0].kind == BrentStepKind::Secant);
  CHECK(r.iterates[0].x == 1.0);
  CHECK(r.iterates[0].fx == 0.0);
  CHECK(r.root == 1.0);
  // Also in float: the same dyadic numbers.
  const auto rf = findRoot([](float x) { return x - 1.0f; }, 0.0f, 3.0f, 1e-6f);
  REQUIRE(rf.iterations == 1);
  CHECK(rf.root == 1.0f);
}

// BrentStepper on f(x) = x^2 - 2 over [1, 2], step by step.
//
// Start: a = 1, f(a) = -1; b = 2, f(b) = 2; c = a = 1, d = e = b - a = 1.
// |f(c)| = 1 < |f(b)| = 2, so the a/b/c swap makes b = 1 the best estimate:
//   b = 1 (f = -1), a = c = 2 (f = 2).
// Iterate 1: a == c, so a secant through (a, f(a)) and (b, f(b)):
//   x1 = b - f(b) (b - a) / (f(b) - f(a)) = 1 - (-1)(1 - 2)/(-1 - 2) = 1 + 1/3 = 4/3.
//   (Brent's form: xm = 1/2, s = f(b)/f(a) = -1/2, p = 2 xm s = -1/2, q = 1 - s = 3/2,
//    d = |p|/q = 1/3, accepted since 2|p| = 1 < min(3 xm q, |e q|) = min(9/4, 3/2).)
// f(4/3) = 16/9 - 2 = -2/9. Now a = 1 (f = -1), b = 4/3 (f = -2/9), c = 2 (f = 2): three
// distinct points, and f(b), f(c) still differ in sign, so no reset.
// Iterate 2: inverse quadratic interpolation, x as a quadratic in y through the three
// points, evaluated at y = 0 (Lagrange):
//   x2 = 1 * (2/9)(-2)/((-7/9)(-3)) + 4/3 * (1)(-2)/((7/9)(-20/9)) + 2 * (1)(2/9)/((3)(20/9))
//      = -4/21 + 54/35 + 1/15 = 149/105 = 1.41904761...
//   (Brent's form: p = 1/9, q = 35/27, d = p/q = 3/35, x2 = 4/3 + 3/35.)
// f(149/105) = 22201/11025 - 2 = 151/11025 > 0: now f(b) and f(c) = f(2) have the same
// sign, so c becomes the previous b, 4/3 (f = -2/9), and a == c again.
// Iterate 3: a secant through (4/3, -2/9) and (149/105, 151/11025):
//   x3 = 149/105 - (151/11025)(9/105) / (151/11025 + 2450/11025) = 149/105 - 453/91035
//      = 8582/6069 = 1.41407150...   (sqrt(2) = 1.41421356...)
TEST_CASE("Brent's method, step by step: the first iterates of BrentStepper on x^2 - 2 over [1, 2]", "[brent][root][hand][steps]") {
  const auto f = [](double x) { return x * x - 2.0; };
  BrentStepper<double> brent(1.0, f(1.0), 2.0, f(2.0), 1e-12);
  REQUIRE(!brent.converged());
  // After the swap, b = 1 is the best estimate and c = 2 its counterpart.
  CHECK(brent.root() == 1.0);
  CHECK(brent.counterpart() == 2.0);

  REQUIRE(brent.nextKind() == BrentStepKind::Secant);
  CHECK(brent.next() == Approx(4.0 / 3.0).epsilon(1e-15));
  brent.update(f(brent.next()));
  CHECK(brent.root() == Approx(4.0 / 3.0).epsilon(1e-15));
  CHECK(brent.counterpart() == 2.0);

  REQUIRE(brent.nextKind() == BrentStepKind::InverseQuadratic);
  CHECK(brent.next() == Approx(149.0 / 105.0).epsilon(1e-14));
  brent.update(f(brent.next()));
  CHECK(brent.root() == Approx(149.0 / 105.0).epsilon(1e-14));
  CHECK(brent.counterpart() == Approx(4.0 / 3.0).epsilon(1e-15));  // the sign change moved c

  REQUIRE(brent.nextKind() == BrentStepKind::Secant);
  CHECK(brent.next() == Approx(8582.0 / 6069.0).epsilon(1e-13));

  // And then on to convergence.
  int more = 0;
  while (!brent.converged() && more < 20) {
    brent.update(f(brent.next()));
    ++more;
  }
  REQUIRE(brent.converged());
  CHECK(std::abs(brent.root() - std::sqrt(2.0)) <= 1e-12);
  std::cout << "BRENT x^2-2 on [1,2]: iterations=" << 2 + more << "\n";
}

// The iteration cap: findRoot reports IterationCap with its best estimate so far.
TEST_CASE("findRoot stops at the iteration cap with the best estimate", "[brent][root]") {
  const auto r = findRoot([](double x) { return std::tanh(100 * (x - 0.3)); }, 0.0, 1.0, 1e-14, 3);
  CHECK(r.status == RootStatus::IterationCap);
  CHECK(r.iterations == 3);
  CHECK(r.root >= 0.0);
  CHECK(r.root <= 1.0);
}

// Bad input is refused, naming the field: no sign change, a NaN at an end or during the
// search, a non-finite bracket, a negative tolerance.
TEST_CASE("Brent refuses bad input, naming the field", "[brent][root][input]") {
  const auto noSignChange = invalidArgumentMessage([] { findRoot([](double x) { return x * x + 1; }, -1.0, 1.0, 1e-9); });
  CHECK(noSignChange.rfind("brent.bracket", 0) == 0);

  const double nan = std::numeric_limits<double>::quiet_NaN();
  const auto nanAtEnd = invalidArgumentMessage([&] { findRoot([&](double x) { return x > 0.5 ? nan : -1.0; }, 0.0, 1.0, 1e-9); });
  CHECK(nanAtEnd.rfind("brent.f", 0) == 0);

  // NaN in the middle of the search: f is fine at the ends, NaN inside.
  const auto nanInside = invalidArgumentMessage(
      [&] { findRoot([&](double x) { return (x > 0 && x < 1) ? nan : x - 0.5; }, 0.0, 1.0, 1e-9); });
  CHECK(nanInside.rfind("brent.f", 0) == 0);

  const double inf = std::numeric_limits<double>::infinity();
  const auto infiniteEnd = invalidArgumentMessage([&] { BrentStepper<double>(0.0, -1.0, inf, 1.0, 1e-9); });
  CHECK(infiniteEnd.rfind("brent.bracket", 0) == 0);

  const auto negativeTolerance = invalidArgumentMessage([] { BrentStepper<double>(0.0, -1.0, 1.0, 1.0, -1.0); });
  CHECK(negativeTolerance.rfind("brent.tolerance", 0) == 0);

  BrentStepper<double> brent(0.0, -1.0, 1.0, 1.0, 1e-9);
  const auto nanUpdate = invalidArgumentMessage([&] { brent.update(nan); });
  CHECK(nanUpdate.rfind("brent.f", 0) == 0);
}
