#include <gjkx/dynamics/free_flight.hpp>
#include <catch2/catch.hpp>
TEST_CASE("x"){}
