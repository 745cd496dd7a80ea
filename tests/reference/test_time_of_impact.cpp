// The dense-sampling time-of-impact reference of gjkx::reference (time_of_impact.hpp):
// distance functions whose first contact is known in closed form, a dip narrower than the
// sampling (no tunnelling), and the uncertified first root.
#include <gjkx/reference/time_of_impact.hpp>

#include <catch2/catch.hpp>

#include <cmath>
#include <stdexcept>

using namespace gjkx::reference;

TEST_CASE("reference: first contact of a linear approach", "[reference][toi]") {
  // d(t) = 0.5 - t closes at rate 1: contact (threshold 0) at t = 0.5; within 0.1 at 0.4.
  int evaluations = 0;
  auto d = [&](Real t) {
    ++evaluations;
    return std::abs(Real(0.5) - t);
  };
  CHECK(std::abs(firstContact(d, 1, 0) - Real(0.5)) <= Real(1e-13));
  CHECK(std::abs(firstContact(d, 1, Real(0.1)) - Real(0.4)) <= Real(1e-13));
  CHECK(evaluations < 2000);
  // Starts within the threshold: t0. Never within it: -1.
  CHECK(firstContact(d, 1, Real(0.6)) == 0);
  CHECK(firstContact([](Real) { return Real(1); }, 0, Real(0.5)) == -1);
}

TEST_CASE("reference: a dip between two samples is found (no tunnelling)", "[reference][toi]") {
  // d(t) = 100 |t - 0.501| - 0.01 touches 0 only on [0.5009, 0.5011], between the samples
  // 32/64 and 33/64, where d is 0.09 and 1.46: the Lipschitz bound 100 proves the other gaps
  // free and sends the search into this one.
  auto d = [](Real t) { return std::max(Real(0), 100 * std::abs(t - Real(0.501)) - Real(0.01)); };
  CHECK(std::abs(firstContact(d, 100, 0) - Real(0.5009)) <= Real(1e-12));
  // On another interval, with fewer samples.
  ContactSearch search;
  search.t0 = Real(0.25);
  search.t1 = Real(2.25);
  search.samples = 3;
  CHECK(std::abs(firstContact(d, 100, 0, search) - Real(0.5009)) <= Real(1e-12));
  // A grazing approach that never touches: -1.
  auto graze = [](Real t) { return Real(1e-6) + std::abs(t - Real(0.3)); };
  CHECK(firstContact(graze, 1, 0) == -1);
}

TEST_CASE("reference: bad searches are refused", "[reference][toi]") {
  auto d = [](Real t) { return t; };
  ContactSearch backwards;
  backwards.t0 = 1;
  backwards.t1 = 0;
  CHECK_THROWS_AS(firstContact(d, 1, 0, backwards), std::invalid_argument);
  CHECK_THROWS_AS(firstContact(d, -1, 0), std::invalid_argument);
}

TEST_CASE("reference: the first root of a gap function", "[reference][toi]") {
  CHECK(firstRoot([](Real t) { return Real(0.7) - t; }) == Approx(0.7).epsilon(1e-15));
  CHECK(firstRoot([](Real t) { return Real(-1) + t; }) == 0);
  CHECK(std::isnan(firstRoot([](Real t) { return 1 + t; })));
  // The first of two roots.
  CHECK(firstRoot([](Real t) { return std::cos(Real(10) * t); }) == Approx(M_PI / 20).epsilon(1e-15));
}
