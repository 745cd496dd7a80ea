/// @file
/// @brief The pile: bodies of four kinds falling into an open box, the scene of
/// `timewarp_benchmark` and of the hybrid's pile tests (§6's "many bodies in contact").
#pragma once

#include <gjkx/timewarp/scene.hpp>

namespace gjkx {

/// A static box open at the top (a floor and four walls) and `count` moving bodies in a
/// loose grid above it, side × side × 2·side at 0.45 m, in turn a box, a sphere, a capsule
/// and a random polytope of ten points, each with a random orientation, sideways velocity
/// and spin drawn from `seed` (the same seed, the same scene). Runs `duration` seconds.
Scene fallingIntoABox(int count, double duration, unsigned seed);

}  // namespace gjkx
