/// @file
/// @brief What a frame of the world reports (§6, Fig. 6): its counters, its status, where its
/// wall time went, and the trace of what the orderings did.
///
/// A frame's report is the row of `frames.csv` that gjkx_simulate writes. Its counters are
/// listed once, in `frameColumns()`, with their CSV names: the writer goes through that
/// table, and the readers (gjkx_frame_ratios, chapters/08_torso/run_stats.hpp) look a
/// column up by its name in the file's header. A new counter is one member here, one line
/// in `operator+=` and one line at the end of that table.
#pragma once

#include <gjkx/verify/frame_verifier.hpp>

#include <string>
#include <vector>

namespace gjkx {

/// What happened in one frame (a row of frames.csv).
struct FrameCounters {
  long events = 0;              ///< events taken from the queue (stale ones included)
  long collisionChecks = 0;     ///< pair queries of the time-of-impact solver (or static tests)
  long collisions = 0;          ///< impulses applied (microcollisions included)
  long microcollisions = 0;     ///< of which microcollisions
  long caught = 0;              ///< bodies stopped as caught: Zeno's wedge, or too many collisions at one instant (response.hpp)
  long settled = 0;             ///< bodies put to sleep at the frame's end (sleep.hpp)
  long rollbacks = 0;           ///< collisions that rolled back bodies whose local time had run past t_c
  long bodiesRolledBack = 0;    ///< bodies rolled back (or, for the heap, advanced to the impact)
  long brentQueries = 0;        ///< queries whose first extrusion test failed, so that Brent ran (§5)
  long brentIterations = 0;     ///< Brent iterates of every query
  long brentMax = 0;            ///< the most of one query
  long photoFinishes = 0;       ///< queries that ended in a photo finish (§5)
  long completeTests = 0;       ///< complete extrusion tests (one per query plus restarts)
  long solverCaps = 0;          ///< queries that ran out of iterations (treated as collisions)
  long piecePairs = 0;          ///< convex piece pairs of mesh bodies that the 14-DOP hierarchy handed to the solver
  long kdopNodes = 0;           ///< nodes of the hierarchies' test trees visited (kdop)
  long sdEvaluations = 0;       ///< supporting distances evaluated by the time-of-impact queries (each a support pair)
  long impulseSteps = 0;        ///< steps of the impulse integration, accepted and rejected (ImpulseResult::integratorSteps)
  long impulseCaps = 0;         ///< impulses whose integration reached ImpulseSettings::maxSteps (the impulse so far applied)
  long spinRestarts = 0;        ///< times the frame was run again in shorter intervals (a body spun past a half turn per interval)
  long eventCaps = 0;           ///< intervals whose events reached StepTuning's cap (FrameStatus::EventCap)
  long projections = 0;         ///< fixed steps: overlapping pairs moved apart at a step's end (fixed_step.hpp); the hybrid: contact groups whose position projection moved a body (contact_solver.hpp)
  long contactPoints = 0;       ///< manifold points solved by the hybrid's contact solver (summed over intervals)
  long contactGroups = 0;       ///< contact groups solved (summed over intervals)
  long contactSweeps = 0;       ///< sweeps of the contact solver over its groups' points
  long energyRises = 0;         ///< group solves whose kinetic energy rose (must stay 0; contact_solver.hpp)
  long sleeping = 0;            ///< bodies asleep at the frame's end
  long landings = 0;            ///< hybrid: pairs that met slowly inside an interval, left to the next one's contact solve (narrow_phase.hpp)
  long staticChecks = 0;        ///< of collisionChecks, the time-of-impact queries of a piece against a static body's piece
  long contactImpulses = 0;     ///< hybrid: of collisions, impulses on a contact pair closing slower than the contact speed (no restitution; response.hpp)
  long cascadeImpulses = 0;     ///< of collisions, the instant pass's impulses after an event's own (on contacts its impulses set closing; response.hpp)
  long stepEnds = 0;            ///< Timewarp (either model of contact): own steps that ended before the interval's end (the body flies on; timewarp.hpp)
  long recheckedAfterCollisions = 0;  ///< Timewarp: body pairs checked again from t_c because a collision's impulses struck one of their bodies
  long recheckedAtStepEnds = 0;       ///< Timewarp: body pairs checked again at their bodies' step ends
  long checkedAtIntervalStarts = 0;   ///< Timewarp: body pairs checked at the starts of the frame's intervals (the broad phase's candidates)
  long intervals = 0;           ///< intervals the frame was run in (after any spin restart; world.cpp)
  double maxPenetration = 0;    ///< the deepest penetration at the frame's end (independent check)
  long tunnelled = 0;           ///< pairs that interpenetrated during the frame with no collision reported (verify)

  /// Adds another frame's counts (the maxima take the larger).
  FrameCounters& operator+=(const FrameCounters& o);
};

/// Wall time of a frame by part (seconds), as Fig. 6 of the paper splits it.
struct PartTimes {
  double integration = 0;         ///< free flight (odeint for turning bodies)
  double bounds = 0;              ///< swept bounds and the broad phase
  double collisionDetection = 0;  ///< the time-of-impact solver (or the static tests)
  double impulses = 0;            ///< contact points and Mirtich's impulses
  double ordering = 0;            ///< the event queue, rollbacks, bookkeeping
  double contacts = 0;            ///< the hybrid's contacts: manifolds, groups, the contact solver
  double checks = 0;              ///< the independent checks (not part of the method)

  /// Adds another frame's times.
  PartTimes& operator+=(const PartTimes& o);
};

/// How a frame ended.
enum class FrameStatus {
  Done,      ///< every event of the frame was resolved
  EventCap,  ///< an interval reached the event cap (StepTuning::eventCap): its remaining events were dropped
};

/// One frame's report.
struct FrameReport {
  int frame = 0;              ///< 1, 2, ...
  double time = 0;            ///< simulated time at the frame's end
  double wallSeconds = 0;     ///< wall time spent on the frame
  /// processor time the process spent on the frame (std::clock): unlike the wall time, it
  /// does not count the time other programs of a shared machine held the processor
  double cpuSeconds = 0;
  FrameStatus status = FrameStatus::Done;  ///< how it ended
  bool checked = false;       ///< the independent checks ran (else maxPenetration and tunnelled mean nothing)
  FrameCounters counters;     ///< what happened
  PartTimes parts;            ///< where the wall time went
  std::vector<Finding> findings;  ///< what the independent checks found wrong (when checked)
};

/// One column of frames.csv: its name and how a report gives its value.
struct FrameColumn {
  const char* name;                          ///< the header
  double (*value)(const FrameReport& r);     ///< the value of a frame
  bool integer;                              ///< a count, written as an integer (else as a real, 6 digits)
};

/// The columns of frames.csv, in the file's order (new columns go at the end). A run
/// without the independent checks writes -1 for `max_penetration` and `tunnelled`.
const std::vector<FrameColumn>& frameColumns();

/// The header line of frames.csv (no newline).
std::string frameHeader();

/// The row of frames.csv for a frame (no newline).
std::string frameRow(const FrameReport& report);

/// One collision of the run, as the world logs it (World::collisionLog(), gjkx_simulate --log).
struct CollisionRecord {
  double time = 0;             ///< the time of impact t_c
  int i = -1;                  ///< the first body
  int j = -1;                  ///< the second body
  int pieceI = 0;              ///< the convex piece of i
  int pieceJ = 0;              ///< the convex piece of j
  double approachSpeed = 0;    ///< the normal speed at which they closed (m/s, positive)
  double impulse = 0;          ///< the size of the impulse applied (N s)
  bool microcollision = false; ///< a microcollision (restitution 1, below the microcollision speed)
  /// Under the hybrid: struck as a contact, a pair the contact solver holds closing slower
  /// than the contact speed (restitution 0, no microcollision's bounce; response.hpp).
  bool contact = false;
  double separationSpeed = 0;  ///< the normal speed at which they leave after the impulse (m/s)
};

/// One record of the trace (WorldSettings::trace): what an ordering did to a body's local time.
struct TraceEvent {
  /// What happened.
  enum class Kind {
    Advance,    ///< the body flew from `from` to `to` (its local time now `to`)
    Collision,  ///< a collision at `to` between `body` and `other`
    Rollback,   ///< the body's local time went back from `from` to `to`
    Check,      ///< a pair check over [from, to] between `body` and `other`
  };
  Kind kind = Kind::Advance;  ///< what happened
  int body = -1;              ///< the body
  int other = -1;             ///< the other body of a pair, or -1
  double from = 0;            ///< time before / interval start
  double to = 0;              ///< time after / interval end
};

}  // namespace gjkx
