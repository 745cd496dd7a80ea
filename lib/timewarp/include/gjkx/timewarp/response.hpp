/// @file
/// @brief The response to a collision (§6): Mirtich's impulse at the time of impact, the
/// impulses it sets off at the same instant (the instant pass), and Zeno's wedge.
///
/// A collision at t_c rolls its bodies back to t_c, applies the impulse of Mirtich's
/// integration (gjkx/dynamics/impulse.hpp) at the contact (contact.hpp), and flies them on.
/// A resting body is a train of microcollisions (impulse.hpp). Two rules keep the trains
/// finite:
/// - **Zeno's wedge.** A body caught between two contacts (a rib wedged between a stem and
///   a leaf) bounces from one to the other ever faster, the impulses ever smaller: 86,000
///   microcollisions in a frame for one rib. A body struck by more than
///   StepTuning::caughtAfter microcollisions within a frame along normals more than a right
///   angle apart, or in more than StepTuning::sameInstantAfter collisions at one instant, is
///   *caught*: stopped where it stands (which only takes energy away); caught against a
///   static body it sleeps, held until a moving body strikes it.
/// - **The instant pass.** A body lying on others passes each impulse on: a rib pressed
///   between two vertebrae, struck by one, closes on the other, which closes on the next.
///   Found by the pair checks, each link of such a chain would cost a rollback and a check
///   of every pair of its two bodies over the rest of the frame; the pass applies them at
///   the same instant, one GJK per contact of the struck bodies (the piece pairs that came
///   within the tolerance this frame), and each struck body is checked once, after the last link.
///   Under the hybrid a contact is what its solver holds: pieces within StepTuning::contactBand
///   tolerances, not one. A light body pinned between two others, a band's width from each
///   (a rib between the plant and a vertebra at the torso's crash), is then struck on both
///   sides at one instant, where with the tolerance alone it would rattle between them, each
///   bounce an event of its own with every pair of the rib checked again. The price: an
///   impulse on a link up to a band apart acts at most one tolerance of closing early.
#pragma once

#include <gjkx/timewarp/contact.hpp>
#include <gjkx/timewarp/step.hpp>

#include <vector>

namespace gjkx {

/// The impulse of one collision at `hit.contact`, applied to the states si and sj at the
/// time of impact, counted, logged and traced; then Zeno's wedge (a body may be caught).
/// Under the hybrid, a contact struck inside an interval also takes the Coulomb friction of
/// its `patch` about the normal (twist friction: response.cpp).
void applyImpulse(StepContext& step, const Hit& hit, BodyState& si, BodyState& sj, const ContactPatch& patch);

/// A collision at t_c: its impulse, then (with `instantPass`) the impulses it sets off at
/// the same instant; the bodies struck fly on from t_c to the interval's end. Returns the
/// bodies flown on (empty, with the frame abandoned, on a spin overflow). `patch`, when
/// given, is where the hit's impulse acts, instead of the patch of its closest points
/// (fixed steps give it for a pair found overlapping, whose closest points say nothing).
std::vector<int> resolve(StepContext& step, const Hit& hit, bool instantPass = true,
                         const ContactPatch* patch = nullptr);

}  // namespace gjkx
