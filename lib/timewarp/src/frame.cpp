// The frame's report and its columns in frames.csv (frame.hpp).
#include <gjkx/timewarp/frame.hpp>

#include <algorithm>
#include <sstream>

namespace gjkx {

FrameCounters& FrameCounters::operator+=(const FrameCounters& o) {
  events += o.events;
  collisionChecks += o.collisionChecks;
  collisions += o.collisions;
  microcollisions += o.microcollisions;
  caught += o.caught;
  settled += o.settled;
  rollbacks += o.rollbacks;
  bodiesRolledBack += o.bodiesRolledBack;
  brentQueries += o.brentQueries;
  brentIterations += o.brentIterations;
  brentMax = std::max(brentMax, o.brentMax);
  photoFinishes += o.photoFinishes;
  completeTests += o.completeTests;
  solverCaps += o.solverCaps;
  piecePairs += o.piecePairs;
  kdopNodes += o.kdopNodes;
  sdEvaluations += o.sdEvaluations;
  impulseSteps += o.impulseSteps;
  impulseCaps += o.impulseCaps;
  spinRestarts += o.spinRestarts;
  eventCaps += o.eventCaps;
  projections += o.projections;
  contactPoints += o.contactPoints;
  contactGroups += o.contactGroups;
  energyRises += o.energyRises;
  contactSweeps += o.contactSweeps;
  landings += o.landings;
  staticChecks += o.staticChecks;
  contactImpulses += o.contactImpulses;
  cascadeImpulses += o.cascadeImpulses;
  stepEnds += o.stepEnds;
  recheckedAfterCollisions += o.recheckedAfterCollisions;
  recheckedAtStepEnds += o.recheckedAtStepEnds;
  checkedAtIntervalStarts += o.checkedAtIntervalStarts;
  intervals += o.intervals;
  sleeping = o.sleeping;  // a state at the frame's end: the later one
  maxPenetration = std::max(maxPenetration, o.maxPenetration);
  tunnelled += o.tunnelled;
  return *this;
}

PartTimes& PartTimes::operator+=(const PartTimes& o) {
  integration += o.integration;
  bounds += o.bounds;
  collisionDetection += o.collisionDetection;
  impulses += o.impulses;
  ordering += o.ordering;
  checks += o.checks;
  contacts += o.contacts;
  return *this;
}

const std::vector<FrameColumn>& frameColumns() {
  // The order of the file: the paper's columns first, then each as it was added.
  static const std::vector<FrameColumn> columns = {
      {"frame", [](const FrameReport& r) { return double(r.frame); }, true},
      {"time", [](const FrameReport& r) { return r.time; }, false},
      {"wall_s", [](const FrameReport& r) { return r.wallSeconds; }, false},
      {"collision_checks", [](const FrameReport& r) { return double(r.counters.collisionChecks); }, true},
      {"collisions", [](const FrameReport& r) { return double(r.counters.collisions); }, true},
      {"rollbacks", [](const FrameReport& r) { return double(r.counters.rollbacks); }, true},
      {"brent_iterations", [](const FrameReport& r) { return double(r.counters.brentIterations); }, true},
      {"photo_finishes", [](const FrameReport& r) { return double(r.counters.photoFinishes); }, true},
      {"max_penetration", [](const FrameReport& r) { return r.checked ? r.counters.maxPenetration : -1.0; }, false},
      {"events", [](const FrameReport& r) { return double(r.counters.events); }, true},
      {"microcollisions", [](const FrameReport& r) { return double(r.counters.microcollisions); }, true},
      {"bodies_rolled_back", [](const FrameReport& r) { return double(r.counters.bodiesRolledBack); }, true},
      {"brent_max", [](const FrameReport& r) { return double(r.counters.brentMax); }, true},
      {"complete_tests", [](const FrameReport& r) { return double(r.counters.completeTests); }, true},
      {"solver_caps", [](const FrameReport& r) { return double(r.counters.solverCaps); }, true},
      {"tunnelled", [](const FrameReport& r) { return r.checked ? double(r.counters.tunnelled) : -1.0; }, true},
      {"integration_s", [](const FrameReport& r) { return r.parts.integration; }, false},
      {"bounds_s", [](const FrameReport& r) { return r.parts.bounds; }, false},
      {"collision_detection_s", [](const FrameReport& r) { return r.parts.collisionDetection; }, false},
      {"impulses_s", [](const FrameReport& r) { return r.parts.impulses; }, false},
      {"ordering_s", [](const FrameReport& r) { return r.parts.ordering; }, false},
      {"checks_s", [](const FrameReport& r) { return r.parts.checks; }, false},
      {"brent_queries", [](const FrameReport& r) { return double(r.counters.brentQueries); }, true},
      {"caught", [](const FrameReport& r) { return double(r.counters.caught); }, true},
      {"spin_restarts", [](const FrameReport& r) { return double(r.counters.spinRestarts); }, true},
      {"event_caps", [](const FrameReport& r) { return double(r.counters.eventCaps); }, true},
      {"projections", [](const FrameReport& r) { return double(r.counters.projections); }, true},
      {"contact_points", [](const FrameReport& r) { return double(r.counters.contactPoints); }, true},
      {"contact_groups", [](const FrameReport& r) { return double(r.counters.contactGroups); }, true},
      {"contact_sweeps", [](const FrameReport& r) { return double(r.counters.contactSweeps); }, true},
      {"energy_rises", [](const FrameReport& r) { return double(r.counters.energyRises); }, true},
      {"sleeping", [](const FrameReport& r) { return double(r.counters.sleeping); }, true},
      {"contacts_s", [](const FrameReport& r) { return r.parts.contacts; }, false},
      {"cpu_s", [](const FrameReport& r) { return r.cpuSeconds; }, false},
      {"landings", [](const FrameReport& r) { return double(r.counters.landings); }, true},
      {"static_checks", [](const FrameReport& r) { return double(r.counters.staticChecks); }, true},
      {"contact_impulses", [](const FrameReport& r) { return double(r.counters.contactImpulses); }, true},
      {"cascade_impulses", [](const FrameReport& r) { return double(r.counters.cascadeImpulses); }, true},
      {"step_ends", [](const FrameReport& r) { return double(r.counters.stepEnds); }, true},
      {"rechecked_after_collisions", [](const FrameReport& r) { return double(r.counters.recheckedAfterCollisions); }, true},
      {"rechecked_at_step_ends", [](const FrameReport& r) { return double(r.counters.recheckedAtStepEnds); }, true},
      {"checked_at_interval_starts", [](const FrameReport& r) { return double(r.counters.checkedAtIntervalStarts); }, true},
      {"intervals", [](const FrameReport& r) { return double(r.counters.intervals); }, true},
  };
  return columns;
}

std::string frameHeader() {
  std::string header;
  for (const FrameColumn& column : frameColumns()) header += (header.empty() ? "" : ",") + std::string(column.name);
  return header;
}

std::string frameRow(const FrameReport& report) {
  std::ostringstream row;
  bool first = true;
  for (const FrameColumn& column : frameColumns()) {
    if (!first) row << ',';
    first = false;
    const double value = column.value(report);
    if (column.integer) row << static_cast<long long>(value);
    else row << value;
  }
  return row.str();
}

}  // namespace gjkx
