// The response to a collision (response.hpp): the impulse, Zeno's wedge, the instant pass.
#include <gjkx/timewarp/response.hpp>

#include <gjkx/timewarp/contact.hpp>
#include <gjkx/timewarp/contact_solver.hpp>

#include <algorithm>
#include <deque>
#include <optional>
#include <tuple>
#include <unordered_map>

namespace gjkx {

namespace {

/// The restitution and friction of bodies i and j (each its own or the scene's; the pair's
/// by materialOf's rule).
CollisionMaterial material(const StepContext& step, int i, int j) {
  const auto [restitution, friction] =
      materialOf(step.scene, step.scene.bodies[std::size_t(i)], step.scene.bodies[std::size_t(j)]);
  return CollisionMaterial{restitution, friction};
}

/// Coulomb friction about the normal of a contact struck over a patch (twist friction, as
/// Bullet's spinning friction and MuJoCo's torsional friction). Mirtich's impulse acts at
/// the patch's centre, where a box spinning flat on a floor does not slip: its corners do.
/// With the normal impulse \f$\lambda_n\f$ shared by the patch's K points (the corners
/// of a face, as the contact solver's manifold shares a group's weight), each point r_k from
/// the centre slipping at \f$\omega\,|r_k|\f$ feels \f$\mu\lambda_n / K\f$ against its
/// slip: an angular impulse about the normal of at most
/// \f$\mu\lambda_n \bar r\f$, \f$\bar r\f$ the points' mean distance from the centre.
/// The angular impulse \f$\tau\f$ that stops the relative spin \f$w = n\cdot(\omega_j -
/// \omega_i)\f$ is \f$-w / k\f$, \f$k = n\cdot(I_i^{-1} + I_j^{-1})\,n\f$; it is cut to
/// the limit. Between 0 and the stopping impulse, the kinetic energy only falls (its change
/// is \f$\tau w + \tfrac12 k \tau^2 \le 0\f$).
void twistFriction(const RigidBody& A, BodyState& a, const RigidBody& B, BodyState& b, const ContactPatch& patch,
                   const Eigen::Vector3d& n, double tangentLimit) {
  if (patch.points.size() < 2) return;  // a point: no lever about the normal
  double lever = 0;
  for (const Eigen::Vector3d& p : patch.points) {
    const Eigen::Vector3d r = p - patch.centre;
    lever += (r - n * n.dot(r)).norm();
  }
  lever /= double(patch.points.size());
  const Eigen::Vector3d spinA = A.inverseInertiaWorld(a.worldFromBody.rotation) * n;
  const Eigen::Vector3d spinB = B.inverseInertiaWorld(b.worldFromBody.rotation) * n;
  const double k = n.dot(spinA) + n.dot(spinB);
  if (!(k > 0)) return;
  const double limit = tangentLimit * lever;  // mu lambda_n at the mean lever
  const double tau = std::clamp(-n.dot(b.angularVelocity - a.angularVelocity) / k, -limit, limit);
  a.angularVelocity -= tau * spinA;
  b.angularVelocity += tau * spinB;
}

}  // namespace

void applyImpulse(StepContext& step, const Hit& hit, BodyState& si, BodyState& sj, const ContactPatch& patch) {
  std::vector<WorldBody>& bodies = step.bodies;
  const StepTuning& tuning = step.settings.tuning;
  FrameCounters& c = step.frame.report.counters;
  ImpulseResult result;
  bool contact = false;
  {
    PartTimer timer(step.frame.report.parts.impulses);
    CollisionMaterial material = gjkx::material(step, hit.i, hit.j);
    ImpulseSettings settings = step.impulse;
    // Under the hybrid, a pair its contact solver holds this interval that closes slower than
    // the contact speed is no collision but a contact (it met before, and no impact drives
    // it): it takes no restitution, and no microcollision's bounce either (the paper's model
    // of resting contact, which the solver replaces). With restitution, such impulses at the
    // start of an interval would run on through the instant pass as microcollisions, and a
    // pile that should settle would keep bouncing.
    if (step.hybrid() && step.frame.isContactPair(hit.i, hit.j) &&
        hit.normal.dot(bodies[hit.i].rigid.velocityAt(si, hit.contact) - bodies[hit.j].rigid.velocityAt(sj, hit.contact)) <
            step.contactSpeed()) {
      material.restitution = 0;
      settings.microcollisionSpeed = 0;
      contact = true;
      ++c.contactImpulses;
    }
    result = resolveCollision(bodies[hit.i].rigid, si, bodies[hit.j].rigid, sj, Contact{hit.contact, hit.normal},
                              material, settings);
    if (contact && result.status != ImpulseStatus::Separating)
      twistFriction(bodies[hit.i].rigid, si, bodies[hit.j].rigid, sj, patch, hit.normal,
                    material.friction * std::abs(hit.normal.dot(result.impulse)));
  }
  ++c.collisions;
  c.impulseSteps += result.integratorSteps;
  if (result.status == ImpulseStatus::StepCap) ++c.impulseCaps;
  if (result.status == ImpulseStatus::Microcollision) ++c.microcollisions;
  step.collisionLog.push_back({hit.time, hit.i, hit.j, hit.pieceI, hit.pieceJ, result.approachSpeed,
                               result.impulse.norm(), result.status == ImpulseStatus::Microcollision, contact,
                               result.separationSpeed});
  step.record(TraceEvent::Kind::Collision, hit.i, hit.j, hit.time, hit.time);
  // Zeno's wedge (response.hpp): caught after too many microcollisions from opposite
  // sides (a box sliding on a floor is struck along one normal only), or after too many
  // collisions at one instant (a light rod lying on two corners, each impulse at one
  // corner setting the other closing). Caught, a body is stopped where it stands, and
  // gravity starts it again, so it settles in a few drops of one tolerance per frame.
  for (const auto& [b, state, outward] : {std::tuple<int, BodyState*, Eigen::Vector3d>{hit.i, &si, hit.normal},
                                          std::tuple<int, BodyState*, Eigen::Vector3d>{hit.j, &sj, -hit.normal}}) {
    if (bodies[b].rigid.isStatic()) continue;
    bodies[b].lastStruck = hit.time;
    FrameState::Struck& struck = step.frame.struck[b];
    struck.atLastTime = struck.lastTime == hit.time ? struck.atLastTime + 1 : 1;
    struck.lastTime = hit.time;
    bool wedged = false;
    // (The hybrid model holds resting bodies with its contact solver: no wedge to stop.)
    if (result.status == ImpulseStatus::Microcollision && !step.hybrid()) {
      bool seen = false;
      for (const auto& side : struck.sides) {
        wedged = wedged || side.dot(outward) < 0;
        seen = seen || side.dot(outward) > 0.9;
      }
      if (!seen && struck.sides.size() < 8) struck.sides.push_back(outward);
      wedged = ++struck.microcollisions > tuning.caughtAfter && wedged;
    }
    const int other = b == hit.i ? hit.j : hit.i;
    if (std::find(struck.by.begin(), struck.by.end(), other) == struck.by.end()) struck.by.push_back(other);
    if (wedged || struck.atLastTime > tuning.sameInstantAfter) {  // caught: stopped where it stands
      state->velocity.setZero();
      state->angularVelocity.setZero();
      ++c.caught;
      // Caught against a static body, it would fall again under gravity and be caught again,
      // a few times per frame, each fall taking it deeper: a flat domino on the floor sank
      // half a millimetre per frame, 20 tolerances in 1.5 s. It sleeps instead: held where
      // it stands until a moving body strikes it (what engines call sleeping).
      // (The hybrid model's bodies sleep only as contact groups: contact_solver.hpp.)
      if (bodies[other].rigid.isStatic() && !step.hybrid()) bodies[b].asleep = true;
    } else if (!bodies[other].resting()) {
      // Struck by a moving body: awake (in the hybrid, with the group it slept with).
      if (step.hybrid()) wakeGroup(step, b);
      else bodies[b].asleep = false;
    }
  }
}

std::vector<int> resolve(StepContext& step, const Hit& hit, bool instantPass, const ContactPatch* patch) {
  std::vector<WorldBody>& bodies = step.bodies;
  const StepTuning& tuning = step.settings.tuning;
  // Roll back: the bodies' states at the time of impact t_c.
  const double tc = hit.time;
  struct Body {
    int index;                  // in bodies
    BodyState state;            // at t_c
    bool changed = false;       // by an impulse of this pass
  };
  std::deque<Body> seen;        // the bodies the pass has looked at (a deque: references stay valid)
  const auto inPass = [&](int b) -> Body& {
    for (Body& s : seen)
      if (s.index == b) return s;
    seen.push_back({b, renormalized(bodies[b].path.stateAt(tc))});
    return seen.back();
  };
  // The instant pass (response.hpp). Each impulse is the one the event loop would apply
  // (the scene's restitution, or a microcollision's), so each takes energy away or keeps
  // it; a pass ends after `instantImpulses`, leaving what still closes to the checks.
  // (Restitution 0 for a contact struck again within a pass, as engines treat resting
  // contact, was tried and left out: on the torso dropped in three other poses, its piles
  // sank 1.6 to 3.8 mm deep, against 0.05 to 0.66 mm with the scene's restitution.)
  //
  // The poses stay where they are through the pass, so each contact's geometry (is it
  // within the tolerance, its normal, its patch) is found once; only its closing speed
  // is read again after each impulse.
  struct Link {
    Hit hit;
    bool inContact = false;
    std::optional<ContactPatch> patch;  // found when first needed
    bool queued = false;
  };
  std::vector<Link> links;
  std::unordered_map<std::uint64_t, std::size_t> linkIndex;  // piecePairKey to links
  const auto linkOf = [&](int i, int pi, int j, int pj) {
    const auto [where, isNew] = linkIndex.try_emplace(step.piecePairKey(i, pi, j, pj), links.size());
    if (!isNew) return where->second;
    Link link;
    link.inContact = contactAt(step, i, pi, j, pj, tc, inPass(i).state, inPass(j).state, link.hit);
    links.push_back(std::move(link));
    return links.size() - 1;
  };
  // The normal speed at a contact with the velocities its bodies have now (approachOn).
  const auto closingSpeed = [&](Link& link) {
    const BodyState& si = inPass(link.hit.i).state;
    const BodyState& sj = inPass(link.hit.j).state;
    PartTimer timer(step.frame.report.parts.impulses);
    if (!link.patch) link.patch = patchOf(step, link.hit, si, sj);
    return approachOn(step, link.hit, *link.patch, si, sj);
  };
  // The hit itself is the first contact (remembered as touching here too: a fixed step's
  // check does not remember contacts).
  inPass(hit.i);
  inPass(hit.j);  // (in this order: the bodies fly on in the order seen)
  touched(step, hit.i, hit.pieceI, hit.j, hit.pieceJ);
  links.push_back({hit, true, patch ? std::optional<ContactPatch>(*patch) : std::nullopt, true});
  linkIndex.emplace(step.piecePairKey(hit.i, hit.pieceI, hit.j, hit.pieceJ), 0);
  // A contact the pass reaches closes when it approaches at all; under the hybrid, only when
  // it would close its rest separation within a frame: slower than that its contact solver
  // holds it (a resting pyramid approaches by round-off at every contact, and the pass
  // otherwise ran through all of it at every collision).
  const double linkSpeed = step.hybrid() ? std::max(tuning.approachSpeed, step.band(tuning.restSeparation) * step.scene.frameRate)
                                         : tuning.approachSpeed;
  std::deque<std::size_t> closing{0};
  for (int impulses = 0; !closing.empty() && impulses < tuning.instantImpulses;) {
    const std::size_t k = closing.front();
    closing.pop_front();
    links[k].queued = false;
    // Each contact is looked at with the states of this pass, the hit's too (its check
    // chose its point on states not renormalized), and one queued by an earlier link with
    // the velocities that link left.
    if (closingSpeed(links[k]) >= -(k == 0 ? tuning.approachSpeed : linkSpeed)) continue;
    ++impulses;
    const Hit struck = links[k].hit;  // (a copy: `links` grows below)
    step.frame.collidedPairs.emplace_back(struck.i, struck.j);
    Body& bi = inPass(struck.i);
    Body& bj = inPass(struck.j);
    applyImpulse(step, struck, bi.state, bj.state, *links[k].patch);  // (closingSpeed found it)
    if (k != 0) ++step.frame.report.counters.cascadeImpulses;
    bi.changed = bj.changed = true;
    for (int b : {struck.i, struck.j}) {
      if (!instantPass || bodies[b].rigid.isStatic()) continue;
      for (const FrameState::Touching& t : step.frame.touching[b]) {
        const std::size_t n = linkOf(t.i, t.pi, t.j, t.pj);
        if (!links[n].inContact || links[n].queued) continue;
        if (closingSpeed(links[n]) < -linkSpeed) {
          links[n].queued = true;
          closing.push_back(n);
        }
      }
    }
  }
  // On from t_c with the new velocities, to the end of the current path (the interval's
  // end, or a little on when the impact is at the very end).
  FrameCounters& c = step.frame.report.counters;
  const double minPath = tuning.minPath / step.scene.frameRate;
  std::vector<int> flown;
  for (const Body& s : seen) {
    const int b = s.index;
    WorldBody& body = bodies[b];
    if (body.rigid.isStatic() || !s.changed) continue;
    flown.push_back(b);
    // (Under the hybrid, a step of its own: StepTuning::struckStep.)
    double end = ownStepEnd(step, s.state, tc, std::max(body.path.t1, step.intervalEnd));
    if (step.struckSteps()) end = std::min(end, tc + tuning.struckStep / step.scene.frameRate);
    if (body.path.t1 > tc) {
      ++c.bodiesRolledBack;
      step.record(TraceEvent::Kind::Rollback, b, -1, body.path.t1, tc);
    }
    // A path shorter than `minPath` is not worth keeping (and may not exist in float).
    const double t1 = end - tc > minPath ? end : tc + minPath;
    if (!flyFrom(step, b, s.state, tc, t1)) return {};
  }
  return flown;
}

}  // namespace gjkx
