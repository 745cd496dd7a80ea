/// @file
/// @brief The time-of-impact heap: the ordering a user would otherwise pick, that Timewarp is
/// compared with (§6).
///
/// Every pair is checked from the current time; the earliest impact of all is taken, every
/// body is advanced to it (its path cut there and flown on), the impulse applied, and every
/// pair checked again from there. Simple and exact, but each collision costs a check of
/// every pair, where Timewarp (timewarp.hpp) checks only the pairs of the bodies it struck.
#pragma once

#include <gjkx/timewarp/narrow_phase.hpp>
#include <gjkx/timewarp/step.hpp>

namespace gjkx {

/// Runs the interval [T0, T1] with a global time-of-impact heap. Ends as runTimewarp does
/// (the interval simulated, the event cap, or the frame abandoned).
template <typename S>
void runToiHeap(StepContext& step, NarrowPhase<S>& narrow, double T0, double T1);

}  // namespace gjkx
