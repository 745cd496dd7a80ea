// The world's settings, checked by name (settings.hpp).
#include <gjkx/timewarp/settings.hpp>

#include <gjkx/motion/vector.hpp>

#include <cmath>

namespace gjkx {

namespace {

void positive(double value, const std::string& field) {
  if (!(value > 0 && std::isfinite(value))) failInput(field, "must be finite and positive");
}

void atLeast(long value, long least, const std::string& field) {
  if (value < least) failInput(field, "must be at least " + std::to_string(least));
}

}  // namespace

void StepTuning::validate(const std::string& field) const {
  positive(patchDepth, field + ".patchDepth");
  if (!(acceptedBand >= 1 && std::isfinite(acceptedBand)))
    failInput(field + ".acceptedBand", "must be finite and at least 1 (a hit within the tolerance is always accepted)");
  atLeast(acceptedAfter, 0, field + ".acceptedAfter");
  positive(closingBand, field + ".closingBand");
  if (!(reliableNormal > 0 && reliableNormal < 1)) failInput(field + ".reliableNormal", "must lie in (0, 1)");
  positive(settleEnergy, field + ".settleEnergy");
  positive(approachSpeed, field + ".approachSpeed");
  positive(minLookAhead, field + ".minLookAhead");
  if (!(maxLookAhead >= minLookAhead && maxLookAhead <= 1))
    failInput(field + ".maxLookAhead", "must lie in [minLookAhead, 1]");
  if (!(windowBand > 0 && windowBand <= 1)) failInput(field + ".windowBand", "must lie in (0, 1]");
  if (!(minPath > 0 && minPath < 1)) failInput(field + ".minPath", "must lie in (0, 1)");
  if (!(settleSeconds >= 0 && std::isfinite(settleSeconds))) failInput(field + ".settleSeconds", "must be finite and not negative");
  atLeast(caughtAfter, 1, field + ".caughtAfter");
  atLeast(sameInstantAfter, 1, field + ".sameInstantAfter");
  atLeast(instantImpulses, 1, field + ".instantImpulses");
  positive(contactBand, field + ".contactBand");
  if (!(restSeparation >= 0 && restSeparation < contactBand))
    failInput(field + ".restSeparation", "must lie in [0, contactBand)");
  if (!(contactSpeed >= 0 && std::isfinite(contactSpeed))) failInput(field + ".contactSpeed", "must be finite and not negative");
  atLeast(contactIterations, 1, field + ".contactIterations");
  positive(contactSettled, field + ".contactSettled");
  atLeast(contactIntervals, 1, field + ".contactIntervals");
  atLeast(spinIntervals, 1, field + ".spinIntervals");
  if (!(struckStep > 0 && struckStep <= 1)) failInput(field + ".struckStep", "must lie in (0, 1]");
  if (!(contactCheckBand > 0 && contactCheckBand <= restSeparation))
    failInput(field + ".contactCheckBand", "must lie in (0, restSeparation]");
  atLeast(positionIterations, 0, field + ".positionIterations");
  positive(contactMatch, field + ".contactMatch");
  atLeast(eventCap, 1, field + ".eventCap");
  atLeast(eventCapPerBody, 0, field + ".eventCapPerBody");
  atLeast(maxIntervals, 1, field + ".maxIntervals");
  atLeast(maxSpinIntervals, maxIntervals, field + ".maxSpinIntervals");
}

void WorldSettings::validate(const std::string& field) const {
  impulse.validate(field + ".impulse");
  tuning.validate(field + ".tuning");
}

}  // namespace gjkx
