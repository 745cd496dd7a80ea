// The needle slab of GJK's stall (tests/gjk/test_gjk_stalled.cpp): a needle triangle, L
// long and h thick, touching a segment at a shared vertex, the origin. V_Q - V_P is then a
// slab h thick whose top face holds the origin as a corner; about a billion times longer
// than thick, GJK stalls on it. Shared by the GJK, static and extrusion tests.
#pragma once

#include <gjkx/support_mapping/primitives.hpp>

namespace gjkx::test {

/// The needle triangle, L long and h thick (its apex h above the segment's line).
inline Triangle<double> needle(double L, double h) {
  using V = Vector3<double>;
  return {V(0, 0, 0), V(-L, 0, -L), V(2.775 * h, h, 2.775 * h)};
}

/// The segment from (-f L, 0, 0) to the shared vertex, the origin.
inline Segment<double> segmentTo(double L, double f) {
  using V = Vector3<double>;
  return {V(-f * L, 0, 0), V(0, 0, 0)};
}

}  // namespace gjkx::test
