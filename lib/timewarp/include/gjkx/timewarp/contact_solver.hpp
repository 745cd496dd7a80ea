/// @file
/// @brief Resting contact in the hybrid model (§6's "future work"): contact manifolds, contact
/// groups, and the velocity-level solver that advances a group over an interval.
///
/// The paper models resting contact by microcollisions: a box on a floor is a train of tiny
/// bounces, each an event of the ordering. The hybrid keeps collisions as events, and takes
/// the pairs that *rest* against each other out of the event queue:
///
/// - At the start of each interval [t0, t1], every body pair whose pieces lie within
///   StepTuning::contactBand tolerances and do not close faster than the *contact speed*
///   (below) is a **contact**. Its **manifold** is the overlap of the two touching features
///   (contactManifold): up to four points, each with its separation.
/// - Contacts join the moving bodies they touch into **contact groups** (static and sleeping
///   bodies join none: to the solver they have infinite mass), as Mirtich's Timewarp joins
///   bodies in persistent contact.
/// - Each group is advanced by a **velocity-level solver**: gravity's impulse over the
///   interval is added to each body's velocity, then sequential impulses (projected
///   Gauss–Seidel, its sweeps going up the pile and down it in turn: symmetric Gauss–Seidel)
///   find the normal and friction impulses at every manifold point, warm-started
///   from the impulses the same points took in the last solve. The solved velocities are
///   the bodies' velocities over the whole interval (semi-implicit Euler), and each body's
///   path is the torque-free flight from them, gravity off: a motion of the `motion` stage
///   like any other, so the extrusion test checks it against every body it is not in contact
///   with, and nothing passes through anything.
///
/// **The contact speed.** A pair resting under gravity closes by at most what gravity adds
/// over an interval, |g| Δt; anything faster came from an impact and is a collision, its
/// restitution applied by Mirtich's impulse. The threshold is StepTuning::contactSpeed
/// intervals of gravity, 2 |g| Δt (0.2 m/s at 24 frames a second in four intervals), below
/// Box2D's restitution threshold (1 m/s).
///
/// **Keeping stacks from sinking without adding energy.** Two parts, each of which cannot
/// add kinetic energy:
/// - *Speculative contact* (Catto, GDC 2013): a point separated by s may close at most by
///   s − s* over the interval, where s* = StepTuning::restSeparation tolerances is where
///   bodies come to rest, inside the band and apart. The normal velocity target is never
///   positive, so a normal impulse only stops what closes too fast.
/// - *Position projection* (non-linear Gauss–Seidel on the positions, Box2D v2's position
///   solver): a point nearer than s* moves its bodies apart along the normal at t0, in
///   proportion to their inverse masses, before the velocities are solved. Positions move,
///   velocities do not: no energy is added (Baumgarte's velocity bias would add it).
///
/// References: B. Mirtich, "Timewarp rigid body simulation", SIGGRAPH 2000 (groups); E.
/// Catto, "Iterative dynamics with temporal coherence", GDC 2005 (sequential impulses, warm
/// start); E. Catto, "Physics for game programmers: continuous collision", GDC 2013
/// (speculative contact); E. Guendelman, R. Bridson, R. Fedkiw, "Nonconvex rigid bodies with
/// stacking", SIGGRAPH 2003 (the position correction kept apart from the velocities).
#pragma once

#include <gjkx/timewarp/contact_manifold.hpp>
#include <gjkx/timewarp/coulomb_friction.hpp>
#include <gjkx/timewarp/step.hpp>

#include <vector>

namespace gjkx {

template <typename S>
class NarrowPhase;

/// What one velocity solve of a group did (for the tests and the report).
struct GroupSolve {
  double kineticBefore = 0;  ///< the group's kinetic energy after gravity's impulse, before the contacts
  double kineticAfter = 0;   ///< after the contacts
  int sweeps = 0;            ///< sweeps of sequential impulses over the group's points
  /// True if the solve raised the kinetic energy by more than round-off (the column
  /// `energy_rises` counts such solves).
  bool energyRose() const;
};

/// Solves the velocities of the bodies `group` at states `states` (indexed by body) against
/// `manifolds` (those whose bodies are in the group, or static or sleeping) over an interval
/// of `dt`: sequential impulses, warm-started from each point's stored impulses, which are
/// updated. Gravity's impulse is added first when `gravity` is true.
GroupSolve solveGroup(const StepContext& step, const std::vector<int>& group, std::vector<Manifold*>& manifolds,
                      std::vector<BodyState>& states, double dt, bool gravity);

/// The hybrid's part of a step at the start of the interval [t0, t1]: finds the contacts,
/// forms the groups, projects and solves each, and flies its bodies over the interval on
/// the solved velocities (gravity off: WorldBody::contactFlight). The contact pairs
/// (FrameState::contactPairs) are checked by the ordering with StepTuning::contactCheckBand
/// over the interval. False on a spin overflow.
template <typename S>
bool solveContacts(StepContext& step, NarrowPhase<S>& narrow, double t0, double t1);

/// The hybrid's sleep at a frame's end: a contact group whose bodies have all been slow (the
/// energy test of sleep.hpp) for StepTuning::settleSeconds sleeps as one; a sleeping group
/// wakes as one (wakeGroup).
void sleepGroups(StepContext& step, double T1);

/// Wakes body b and every body that fell asleep in the same group.
void wakeGroup(StepContext& step, int b);


}  // namespace gjkx
