/// @file
/// @brief A motion in another scalar type: a body's path in the scalar of collision detection
/// (the paper ran in float, §6).
///
/// The dynamics integrates in double; collision detection runs in the scene's scalar type.
/// castMotion converts a motion alternative by alternative, rounding each number once (a
/// pose by Pose::cast).
#pragma once

#include <gjkx/motion/motion.hpp>

#include <cmath>
#include <limits>
#include <type_traits>

namespace gjkx {

/// The end of an interval rounded to To, kept after its rounded start: an interval shorter
/// than To's spacing there would otherwise round to nothing.
template <typename To, typename From>
To laterThan(To t0, From t1) {
  const To rounded = To(t1);
  return rounded > t0 ? rounded : std::nextafter(t0, std::numeric_limits<To>::infinity());
}

/// A motion in the scalar type To (the same alternative, its numbers rounded to To).
template <typename To, typename From>
Motion<To> castMotion(const Motion<From>& motion) {
  if constexpr (std::is_same_v<To, From>) {
    return motion;
  } else {
    return std::visit(
        [](const auto& m) -> Motion<To> {
          using M = std::decay_t<decltype(m)>;
          if constexpr (std::is_same_v<M, StaticMotion<From>>) {
            return Motion<To>::fixed(m.start.template cast<To>());
          } else if constexpr (std::is_same_v<M, ConstantVelocity<From>>) {
            return Motion<To>::constantVelocity(m.start.template cast<To>(), m.velocity.template cast<To>(), To(m.t0));
          } else if constexpr (std::is_same_v<M, ConstantAcceleration<From>>) {
            return Motion<To>::constantAcceleration(m.start.template cast<To>(), m.velocity.template cast<To>(),
                                                    m.acceleration.template cast<To>(), To(m.t0));
          } else if constexpr (std::is_same_v<M, ScrewMotion<From>>) {
            return Motion<To>::screw(m.start.template cast<To>(), m.velocity.template cast<To>(),
                                     m.angularVelocity.template cast<To>(), To(m.t0));
          } else if constexpr (std::is_same_v<M, PoseInterpolation<From>>) {
            return Motion<To>::interpolate(m.from.template cast<To>(), m.to.template cast<To>(), To(m.t0), laterThan(To(m.t0), m.t1));
          } else {
            static_assert(std::is_same_v<M, FreeFlightPath<From>>, "castMotion: a motion alternative is missing");
            return Motion<To>::freeFlight(m.start.template cast<To>(), m.velocity.template cast<To>(),
                                          m.acceleration.template cast<To>(), m.endRotation.template cast<To>(),
                                          To(m.t0), laterThan(To(m.t0), m.t1));
          }
        },
        motion.variant());
  }
}

}  // namespace gjkx
