#include <gjkx/dynamics/impulse.hpp>
#include <catch2/catch.hpp>
TEST_CASE("y"){}
