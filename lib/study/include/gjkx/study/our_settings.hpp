/// @file
/// @brief The settings the study gives the library's methods at one collision tolerance,
/// shared by the time-of-impact comparison and the table of extreme cases so that both
/// run the same method at the same setting.
///
/// Holds (namespace gjkx::study): `toiSettings` (the §5 solver), `caSettings` (conservative
/// advancement, ref. [8]).
#pragma once

#include <gjkx/brent/conservative_advancement.hpp>
#include <gjkx/brent/time_of_impact.hpp>

#include <algorithm>

namespace gjkx::study {

/// The settings of the paper's solver at a collision tolerance (the time tolerance no
/// larger than it), in the study's tables.
template <typename S>
ToiSettings<S> toiSettings(double tolerance, ExtrusionVariant variant) {
  ToiSettings<S> settings;
  settings.collisionTolerance = S(tolerance);
  settings.timeTolerance = std::min(settings.timeTolerance, S(tolerance));
  settings.variant = variant;
  return settings;
}

/// The settings of conservative advancement at a collision tolerance and relative speed bound L.
template <typename S>
ConservativeAdvancementSettings<S> caSettings(double tolerance, S L) {
  ConservativeAdvancementSettings<S> settings;
  settings.collisionTolerance = S(tolerance);
  settings.relativeSpeedBound = L;
  return settings;
}

}  // namespace gjkx::study
