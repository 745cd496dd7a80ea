/// @file
/// @brief A body's path in the scalar type of collision detection (the paper ran in float, §6).
///
/// The dynamics integrates in double; collision detection runs in the scene's scalar type.
/// These convert a pose or a motion, alternative by alternative, rounding each number once.
#pragma once

#include <gjkx/motion/motion.hpp>

#include <cmath>
#include <limits>
#include <type_traits>

namespace gjkx {

/// A pose in the scalar type To.
template <typename To, typename From>
Pose<To> castPose(const Pose<From>& p) {
  Pose<To> q;
  q.rotation = p.rotation.template cast<To>();
  q.translation = p.translation.template cast<To>();
  return q;
}

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
            return Motion<To>::fixed(castPose<To>(m.start));
          } else if constexpr (std::is_same_v<M, ConstantVelocity<From>>) {
            return Motion<To>::constantVelocity(castPose<To>(m.start), m.velocity.template cast<To>(), To(m.t0));
          } else if constexpr (std::is_same_v<M, ConstantAcceleration<From>>) {
            return Motion<To>::constantAcceleration(castPose<To>(m.start), m.velocity.template cast<To>(),
                                                    m.acceleration.template cast<To>(), To(m.t0));
          } else if constexpr (std::is_same_v<M, ScrewMotion<From>>) {
            return Motion<To>::screw(castPose<To>(m.start), m.velocity.template cast<To>(),
                                     m.angularVelocity.template cast<To>(), To(m.t0));
          } else if constexpr (std::is_same_v<M, PoseInterpolation<From>>) {
            return Motion<To>::interpolate(castPose<To>(m.from), castPose<To>(m.to), To(m.t0), laterThan(To(m.t0), m.t1));
          } else {
            static_assert(std::is_same_v<M, FreeFlightPath<From>>, "castMotion: a motion alternative is missing");
            return Motion<To>::freeFlight(castPose<To>(m.start), m.velocity.template cast<To>(),
                                          m.acceleration.template cast<To>(), m.endRotation.template cast<To>(),
                                          To(m.t0), laterThan(To(m.t0), m.t1));
          }
        },
        motion.variant());
  }
}

}  // namespace gjkx
