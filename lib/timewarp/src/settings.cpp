// The world's settings, checked by name (settings.hpp).
#include <gjkx/timewarp/settings.hpp>

#include <gjkx/motion/vector.hpp>

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <variant>

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
  atLeast(shockSweeps, 0, field + ".shockSweeps");
  positive(contactMatch, field + ".contactMatch");
  atLeast(eventCap, 1, field + ".eventCap");
  atLeast(eventCapPerBody, 0, field + ".eventCapPerBody");
  atLeast(maxIntervals, 1, field + ".maxIntervals");
  atLeast(maxSpinIntervals, maxIntervals, field + ".maxSpinIntervals");
}

namespace {

/// One field of StepTuning: its name and where it is in the struct (a double, or a count).
struct TuningField {
  const char* name;
  std::variant<double StepTuning::*, int StepTuning::*, long StepTuning::*> member;
};

/// Every field of StepTuning, in the struct's order (a field added there is added here).
// The struct's size is its 18 doubles, 2 longs and 11 ints with their padding (on the LP64
// systems the project builds on): a field added to it stops the build here until it has a
// name below (the tests check that each name reaches a field of its own).
static_assert(sizeof(long) != 8 || sizeof(StepTuning) == 216,
              "StepTuning changed: give its new field a name in kTuningFields, then update this size");
const TuningField kTuningFields[] = {
    {"patchDepth", &StepTuning::patchDepth},
    {"acceptedBand", &StepTuning::acceptedBand},
    {"acceptedAfter", &StepTuning::acceptedAfter},
    {"closingBand", &StepTuning::closingBand},
    {"reliableNormal", &StepTuning::reliableNormal},
    {"settleEnergy", &StepTuning::settleEnergy},
    {"approachSpeed", &StepTuning::approachSpeed},
    {"minLookAhead", &StepTuning::minLookAhead},
    {"maxLookAhead", &StepTuning::maxLookAhead},
    {"windowBand", &StepTuning::windowBand},
    {"minPath", &StepTuning::minPath},
    {"settleSeconds", &StepTuning::settleSeconds},
    {"caughtAfter", &StepTuning::caughtAfter},
    {"sameInstantAfter", &StepTuning::sameInstantAfter},
    {"instantImpulses", &StepTuning::instantImpulses},
    {"contactBand", &StepTuning::contactBand},
    {"restSeparation", &StepTuning::restSeparation},
    {"contactSpeed", &StepTuning::contactSpeed},
    {"contactIterations", &StepTuning::contactIterations},
    {"contactSettled", &StepTuning::contactSettled},
    {"contactCheckBand", &StepTuning::contactCheckBand},
    {"contactIntervals", &StepTuning::contactIntervals},
    {"spinIntervals", &StepTuning::spinIntervals},
    {"struckStep", &StepTuning::struckStep},
    {"positionIterations", &StepTuning::positionIterations},
    {"shockSweeps", &StepTuning::shockSweeps},
    {"contactMatch", &StepTuning::contactMatch},
    {"eventCap", &StepTuning::eventCap},
    {"eventCapPerBody", &StepTuning::eventCapPerBody},
    {"maxIntervals", &StepTuning::maxIntervals},
    {"maxSpinIntervals", &StepTuning::maxSpinIntervals},
};

}  // namespace

std::vector<std::string> tuningNames() {
  std::vector<std::string> names;
  for (const TuningField& f : kTuningFields) names.emplace_back(f.name);
  return names;
}

void setTuning(StepTuning& tuning, const std::string& name, const std::string& value) {
  const std::string field = "tuning." + name;
  for (const TuningField& f : kTuningFields) {
    if (name != f.name) continue;
    const char* text = value.c_str();
    char* end = nullptr;
    errno = 0;
    if (auto* d = std::get_if<double StepTuning::*>(&f.member)) {
      const double v = std::strtod(text, &end);
      if (value.empty() || *end != '\0' || errno == ERANGE || !std::isfinite(v))
        failInput(field, "must be a finite number, got '" + value + "'");
      tuning.*(*d) = v;
      return;
    }
    const long v = std::strtol(text, &end, 10);
    if (value.empty() || *end != '\0' || errno == ERANGE) failInput(field, "must be a whole number, got '" + value + "'");
    if (auto* i = std::get_if<int StepTuning::*>(&f.member)) {
      if (v < long(std::numeric_limits<int>::min()) || v > long(std::numeric_limits<int>::max()))
        failInput(field, "is out of an int's range, got '" + value + "'");
      tuning.*(*i) = int(v);
    } else {
      tuning.*(std::get<long StepTuning::*>(f.member)) = v;
    }
    return;
  }
  std::string known;
  for (const std::string& n : tuningNames()) known += (known.empty() ? "" : ", ") + n;
  failInput(field, "no such setting (known: " + known + ")");
}

void WorldSettings::validate(const std::string& field) const {
  impulse.validate(field + ".impulse");
  tuning.validate(field + ".tuning");
}

}  // namespace gjkx
