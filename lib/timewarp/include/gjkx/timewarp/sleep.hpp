/// @file
/// @brief Settling: slow bodies resting on what cannot move are put to sleep at a frame's end (§6).
///
/// A body whose kinetic energy could not lift its centre of mass by one collision tolerance
/// against gravity (E_k < m |g| tol) cannot leave the tolerance band of what supports it by
/// its own motion: rocking on the floor, it only rattles inside the band, in microcollisions
/// that keep its energy and never lift it back to the band's edge, and it sinks a little
/// with every one found late (docs 08: cartilages rocking at 1 rad/s sank 0.02 mm a frame).
/// Such a body is *slow*. Slow is not at rest: a domino just starting to topple is slow too,
/// and gravity is about to speed it up. So a body must stay slow for
/// StepTuning::settleSeconds before it may settle; then, at a frame's end, it is put to
/// sleep: held where it stands (velocity and spin set to zero, which only takes energy
/// away) until a moving body strikes it. It must also rest on something, which grows from
/// what cannot move, as engines grow their sleeping islands: a slow body struck in the
/// frame by a static or sleeping body settles, then one struck by a body that settles, and
/// so on. A body in the air is struck by nothing, so it never settles there.
#pragma once

#include <gjkx/timewarp/step.hpp>

namespace gjkx {

/// True if `body` at `state` is slow (see the file comment): its kinetic energy could not lift
/// its centre of mass by StepTuning::settleEnergy tolerances against gravity. False without gravity.
bool isSlow(const StepContext& step, const WorldBody& body, const BodyState& state);

/// Puts body b to sleep at T1 where `state` has it: velocity and spin zero, gravity off, its
/// path flown for no time; counted in FrameCounters::settled.
void putToSleep(StepContext& step, int b, BodyState state, double T1);

/// Puts to sleep, at the frame's end T1, the bodies that have settled (see the file
/// comment), and counts them (FrameCounters::settled). Without gravity, nothing settles.
void settle(StepContext& step, double T1);

}  // namespace gjkx
