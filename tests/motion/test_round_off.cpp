// Tests of round_off.hpp: each named round-off constant is, to the last bit, the
// expression it replaced, in float, double and long double; and all are constexpr.
#include <gjkx/motion/round_off.hpp>

#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

using namespace gjkx;

// Usable where a constant expression is required (the simplex squares signSafety at compile time).
static_assert(machineEpsilon<double>() == 0x1p-52, "epsilon of double is 2^-52");
static_assert(sqrtEpsilon<double>() == 0x1p-26, "sqrt(eps) of double is 2^-26, exactly");
static_assert(epsilonToThreeQuarters<double>() == 0x1p-39, "eps^(3/4) of double is 2^-39, exactly");
static_assert(signSafety<float>() * signSafety<float>() > 0.0f, "squares at compile time without underflow");

TEMPLATE_TEST_CASE("round-off: the powers of epsilon are the correctly rounded std:: values", "[round_off]", float,
                   double, long double) {
  using S = TestType;
  const S eps = std::numeric_limits<S>::epsilon();
  CHECK(machineEpsilon<S>() == eps);
  CHECK(sqrtEpsilon<S>() == std::sqrt(eps));                       // IEEE sqrt is correctly rounded
  CHECK(epsilonToThreeQuarters<S>() == std::pow(eps, S(0.75)));    // as GjkSettings computed it before
  CHECK(std::abs(epsilonToThreeQuarters<S>() / std::sqrt(std::sqrt(eps * eps * eps)) - S(1)) <= eps);
}

TEMPLATE_TEST_CASE("round-off: the named allowances are the expressions they replaced", "[round_off]", float,
                   double) {
  using S = TestType;
  const S eps = std::numeric_limits<S>::epsilon();
  CHECK(defaultCollisionTolerance<S>() == std::sqrt(eps));  // §6: eps^(1/2) ~ 0.0003 in float
  CHECK(defaultTimeTolerance<S>() == std::sqrt(eps));
  CHECK(defaultGjkRelativeTolerance<S>() == std::pow(eps, S(0.75)));
  CHECK(defaultOverlapTolerance<S>() == S(16) * eps);
  CHECK(gjkTieAllowance<S>() == S(8) * eps);
  CHECK(signSafety<S>() == S(64) * eps);
  CHECK(rotationTolerance<S>() == S(1e3) * eps);
}

TEST_CASE("round-off: the paper's collision tolerance for 4-byte floats is about 0.0003 (§6)", "[round_off]") {
  CHECK(defaultCollisionTolerance<float>() == Approx(3.4527e-4).epsilon(1e-4));
  CHECK(defaultCollisionTolerance<double>() == Approx(1.4901e-8).epsilon(1e-4));
}
