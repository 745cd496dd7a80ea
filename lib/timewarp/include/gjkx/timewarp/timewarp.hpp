/// @file
/// @brief Mirtich's Timewarp (SIGGRAPH 2000), the ordering the paper's simulation uses (§5–§6):
/// every body runs ahead on its own, and a collision found late rolls back only what it touches.
///
/// §5: "The extrusion solver [...] returns either 'no collision' or the time of impact for a
/// whole interval [...] used in a rigid-body simulation with Mirtich's Timewarp algorithm."
///
/// - **Local times.** Each body keeps its own clock: at the start of an interval
///   [T0, T1] every moving body is flown to T1 on its own (free flight), its local time T1,
///   its path a motion the solver can query.
/// - **The event queue.** The broad phase keeps the pairs whose swept bounds meet, and the
///   narrow phase (the paper's extrusion + Brent solver) checks each over the interval; a
///   hit is a *collision event* in one queue ordered by time of impact.
/// - **Rollback.** The earliest event is taken. Its bodies' local times ran past its time
///   t_c, so they are *rolled back* to t_c (their histories cut there), the impulse is
///   applied (response.hpp), and they fly on to T1. Only the pairs that touch the struck
///   bodies are checked again, from t_c: every other event stays valid. The events that
///   used the rolled-back paths after t_c are stale: each event carries the *versions* of
///   its bodies' paths, and an event whose bodies have moved on is dropped when taken.
/// - **Own steps** (StepContext::ownSteps). A body spinning faster than its interval allows
///   flies an eighth of a turn at a time, and under the hybrid a body a collision struck a step
///   of StepTuning::struckStep at most: where its path ends before T1 is a *step end*, an
///   event at which it flies on and its pairs are checked again from there. A pair is
///   checked as far as both its bodies' paths reach.
/// - **The global virtual time** is the time of the earliest event still queued: no body's
///   history before it can change any more. The interval is final once the queue is empty:
///   the global virtual time has passed T1, and the history before it is discarded.
///
/// Compared with the time-of-impact heap (toi_heap.hpp), which moves every body to each
/// impact, a collision costs work only for the bodies it strikes.
#pragma once

#include <gjkx/timewarp/narrow_phase.hpp>
#include <gjkx/timewarp/step.hpp>

namespace gjkx {

/// Runs the interval [T0, T1] under Timewarp (see the file comment). Ends with the interval
/// simulated, or early with FrameStatus::EventCap (counted in FrameCounters::eventCaps; the
/// remaining events dropped) or with the frame abandoned (StepContext::abandoned, a spin
/// overflow: the frame is run again in shorter intervals).
template <typename S>
void runTimewarp(StepContext& step, NarrowPhase<S>& narrow, double T0, double T1);

/// The event cap of one interval of a world of `bodies` bodies (StepTuning::eventCap).
long eventCapOf(const StepContext& step);

/// Marks the frame as having reached the event cap (FrameStatus::EventCap, counted).
void reachEventCap(StepContext& step);

}  // namespace gjkx
