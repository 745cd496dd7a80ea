/// @file
/// @brief Fixed steps with discrete collision detection: the baseline Timewarp is compared with (§6).
///
/// Every body flies a fixed step (SceneRun::fixedSubsteps per frame); at the step's end each
/// pair is tested statically (GJK at that instant), and a pair found within the tolerance
/// and approaching gets one impulse, as a discrete engine's single pass over its contacts;
/// a pair found overlapping is then moved apart along its normal until it touches (the
/// position projection of a discrete engine: positions only, so it adds no kinetic
/// energy). Without it a box resting on a floor would sink a little at every step that
/// found it late, and nothing would lift it back.
/// What happens between the ends of a step is never looked at: a fast body can pass
/// through a thin one (tunnel), which the paper's extrusion test over the interval cannot.
#pragma once

#include <gjkx/timewarp/narrow_phase.hpp>
#include <gjkx/timewarp/step.hpp>

namespace gjkx {

/// Runs the interval [T0, T1] in Scene::fixedSubsteps fixed steps. Ends with the interval
/// simulated or the frame abandoned (a spin overflow).
template <typename S>
void runFixedStep(StepContext& step, NarrowPhase<S>& narrow, double T0, double T1);

}  // namespace gjkx
