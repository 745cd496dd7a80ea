/// @file
/// @brief The independent checks of a run: penetration and tunnelling measured without the solver.
///
/// A simulation's claims are checked against the reference library (gjkx::reference, long
/// double, brute force over features), which shares no code with GJK or the
/// time-of-impact solver: the signed distance of two bodies at a pose (negative: the depth
/// of their penetration), and, over a frame, whether a pair interpenetrated at any time,
/// found by dense sampling with a proof between samples (reference::firstContact).
#pragma once

#include <gjkx/motion/pose.hpp>
#include <gjkx/timewarp/world.hpp>

#include <functional>

namespace gjkx {

/// The signed distance of two bodies at the given poses, by the reference: their distance
/// when apart, minus their penetration depth when they overlap. Exact for spheres,
/// capsules, boxes and polytopes of up to 16 vertices (reference::signedDistance on point
/// clouds with radii). A polytope of more vertices is measured by GJK in double instead,
/// which is not independent and sees no penetration depth (0 when overlapping): the
/// reference's cost grows as n^3 m, too slow for every frame.
double referenceSignedDistance(const WorldBody& a, const Pose<double>& poseA, const WorldBody& b,
                               const Pose<double>& poseB);

/// True when d(t) falls to `threshold` or below somewhere in [t0, t1], given that d changes at
/// most `lipschitz` per unit time (reference::firstContact, 8 samples and bisection).
bool firstInterpenetration(const std::function<double(double)>& d, double lipschitz, double threshold, double t0,
                           double t1);

}  // namespace gjkx
