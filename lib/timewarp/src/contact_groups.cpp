// Resting contact in the hybrid model (contact_solver.hpp): the contact part of a step. It
// finds the contacts at an interval's start, joins their bodies into groups, projects and
// solves each group (solveGroup: contact_solver.cpp) and flies its bodies on the solved
// velocities; and it puts groups to sleep, and wakes them, as one.
#include <gjkx/timewarp/contact_solver.hpp>

#include <gjkx/timewarp/contact.hpp>
#include <gjkx/timewarp/narrow_phase.hpp>
#include <gjkx/timewarp/sleep.hpp>

#include <algorithm>
#include <cmath>
#include <numeric>

namespace gjkx {

namespace {

/// The body pairs of the hybrid's contacts, found at t0 by the pieces' static tests.
template <typename S>
std::vector<Manifold> findContacts(StepContext& step, NarrowPhase<S>& narrow, double t0, double dt,
                                   std::vector<BodyState>& states) {
  std::vector<WorldBody>& bodies = step.bodies;
  const StepTuning& tuning = step.settings.tuning;
  const double tolerance = step.scene.collisionTolerance;
  const double band = step.band(tuning.contactBand);
  const double contactSpeed = step.contactSpeed();
  // Each body's own box at t0 (its support along each axis), grown by the band: two bodies
  // whose boxes keep apart have no pieces within the band. (The sphere about a rib's centre
  // of mass would hold a dozen neighbours, each pair then tested piece by piece.)
  std::vector<Bounds> boxes(bodies.size());
  for (std::size_t b = 0; b < bodies.size(); ++b) {
    boxes[b] = boundsAt(bodies[b].shape, states[b].worldFromBody, &bodies[b].boundsHints);
    boxes[b].inflate(band);
  }
  // A moving body that comes within the band of a sleeping one wakes its group (Box2D's
  // islands wake as a contact begins): to the solver a sleeping body is immovable, and a
  // domino leaning on one that sleeps would be held by a wall. Woken bodies touch others
  // that sleep, so this is repeated until nothing more wakes.
  for (bool woke = true; woke;) {
    woke = false;
    const auto near = overlappingPairs(boxes, [&](int i, int j) { return bodies[i].asleep == bodies[j].asleep; });
    for (const auto& [i, j] : near) {
      const int sleeper = bodies[i].asleep ? i : j, mover = sleeper == i ? j : i;
      if (bodies[mover].rigid.isStatic() || !bodies[sleeper].asleep) continue;
      std::vector<std::pair<PiecePair, GjkResult<double>>> touching;
      narrow.piecesWithin(step, i, j, t0, states[i], states[j], band, touching);
      if (touching.empty()) continue;
      wakeGroup(step, sleeper);
      woke = true;
    }
  }
  const auto pairs = overlappingPairs(boxes, [&](int i, int j) { return bodies[i].resting() && bodies[j].resting(); });
  std::vector<Manifold> manifolds;
  std::vector<std::pair<PiecePair, GjkResult<double>>> close;
  const auto speedOf = [&](int b) {
    const BodyState& s = states[b];
    return bodies[b].resting() ? 0.0 : s.velocity.norm() + s.angularVelocity.norm() * bodies[b].radius;
  };
  for (const auto& [i, j] : pairs) {
    close.clear();
    narrow.piecesWithin(step, i, j, t0, states[i], states[j], band, close);
    if (close.empty()) continue;
    const std::size_t first = manifolds.size();
    bool collides = false;
    // The features reach as deep as the pair can close over the interval, so that every
    // point that may touch before t1 is in the manifold (a tilted box's far edge).
    const double smaller = std::min(bodies[i].rigid.isStatic() ? 1e300 : bodies[i].radius,
                                    bodies[j].rigid.isStatic() ? 1e300 : bodies[j].radius);
    const double depth = std::min(band + (speedOf(i) + speedOf(j) + step.scene.gravity.norm() * dt) * dt, smaller);
    const auto [restitution, friction] =
        materialOf(step.scene, step.scene.bodies[std::size_t(i)], step.scene.bodies[std::size_t(j)]);
    (void)restitution;  // contacts have none
    for (const auto& [pieces, g] : close) {
      Hit hit;
      contactFromGjk(step, g, i, pieces.a, j, pieces.b, t0, states[i], states[j], hit);
      const double distance = g.status == GjkStatus::Overlapping ? 0.0 : g.distance;
      const Shape<double>& pieceI = bodies[i].pieces[pieces.a];
      const Shape<double>& pieceJ = bodies[j].pieces[pieces.b];
      const Pose<double>& poseI = states[i].worldFromBody;
      const Pose<double>& poseJ = states[j].worldFromBody;
      // Overlapping, or too near for the closest points to give a direction: the axis of
      // least overlap (contactNormal's fallback, the line of the centres, can be far off).
      if (!(distance > step.band(tuning.reliableNormal)))
        hit.normal = leastOverlapAxis(pieceI, poseI, pieceJ, poseJ, {hit.normal});
      // Faces give their normal exactly (GJK's is off by its tolerance over the distance).
      hit.normal = faceNormal(pieceI, poseI, pieceJ, poseJ, hit.normal, band + 0.01 * smaller);
      Manifold m;
      m.i = i;
      m.pi = pieces.a;
      m.j = j;
      m.pj = pieces.b;
      m.normal = hit.normal;
      m.friction = friction;
      m.points = contactManifold(bodies[i].pieces[pieces.a], states[i].worldFromBody, bodies[j].pieces[pieces.b],
                                 states[j].worldFromBody, hit.normal, depth, 0.5 * (hit.pointI + hit.pointJ),
                                 distance, tolerance);
      // Closing faster than the contact speed at any point: a collision, left to the ordering.
      for (const ManifoldPoint& p : m.points)
        if (hit.normal.dot(bodies[j].rigid.velocityAt(states[j], p.point) -
                           bodies[i].rigid.velocityAt(states[i], p.point)) < -contactSpeed)
          collides = true;
      if (collides) break;
      manifolds.push_back(std::move(m));
    }
    if (collides) manifolds.resize(first);
  }
  return manifolds;
}

/// Each point's anchors in its two bodies, and the impulses of the last solve's point at the
/// same place (warm start).
void warmStart(StepContext& step, std::vector<Manifold>& manifolds, const std::vector<BodyState>& states) {
  const double match = step.band(step.settings.tuning.contactMatch);
  for (Manifold& m : manifolds) {
    const Pose<double>& poseI = states[m.i].worldFromBody;
    const Pose<double>& poseJ = states[m.j].worldFromBody;
    const auto cached = step.contactCache.find(step.piecePairKey(m.i, m.pi, m.j, m.pj));
    for (ManifoldPoint& p : m.points) {
      p.anchorI = poseI.rotation.transpose() * (p.point - poseI.translation);
      p.anchorJ = poseJ.rotation.transpose() * (p.point - poseJ.translation);
      if (cached == step.contactCache.end() || cached->second.normal.dot(m.normal) < 0.9) continue;
      for (const ManifoldPoint& old : cached->second.points)
        if ((old.anchorI - p.anchorI).norm() <= match || (old.anchorJ - p.anchorJ).norm() <= match) {
          p.normalImpulse = old.normalImpulse;
          p.frictionImpulse = old.frictionImpulse;
          break;
        }
    }
  }
}

/// The groups: the moving bodies joined by contacts (union-find; resting bodies join none).
std::vector<std::vector<int>> groupsOf(const StepContext& step, const std::vector<Manifold>& manifolds) {
  const std::size_t n = step.bodies.size();
  std::vector<int> parent(n);
  std::iota(parent.begin(), parent.end(), 0);
  const auto root = [&](int b) {
    while (parent[b] != b) b = parent[b] = parent[parent[b]];
    return b;
  };
  std::vector<char> member(n, 0);
  for (const Manifold& m : manifolds) {
    const bool movesI = !step.bodies[m.i].resting(), movesJ = !step.bodies[m.j].resting();
    if (movesI) member[m.i] = 1;
    if (movesJ) member[m.j] = 1;
    if (movesI && movesJ) parent[root(m.i)] = root(m.j);
  }
  std::vector<std::vector<int>> groups;
  std::vector<int> groupOf(n, -1);
  for (std::size_t b = 0; b < n; ++b) {
    if (!member[b]) continue;
    const int r = root(int(b));
    if (groupOf[r] < 0) {
      groupOf[r] = int(groups.size());
      groups.emplace_back();
    }
    groups[groupOf[r]].push_back(int(b));
  }
  return groups;
}

/// Position projection (non-linear Gauss-Seidel on positions): each manifold's deepest
/// point nearer than rest moves its bodies apart along the normal, in proportion to their
/// inverse masses, or, where one rests on the other, the upper one alone (shock
/// propagation). Positions only: no velocity, so no kinetic energy, is added. A body moves
/// no farther than contactBand − restSeparation in one projection.
void project(StepContext& step, const std::vector<int>& group, std::vector<Manifold*>& manifolds,
             std::vector<BodyState>& states) {
  const double rest = step.band(step.settings.tuning.restSeparation);
  const double reach = step.band(step.settings.tuning.contactBand) - rest;
  std::vector<Eigen::Vector3d> moved(step.bodies.size(), Eigen::Vector3d::Zero());
  std::vector<char> inGroup(step.bodies.size(), 0);
  for (int b : group) inGroup[b] = 1;
  const auto weight = [&](int b) { return inGroup[b] ? step.bodies[b].rigid.inverseMass() : 0.0; };
  // From the bottom up, as the velocities (a stack is lifted off the floor in one pass), until
  // nothing is pushed or StepTuning::positionIterations passes.
  std::vector<Manifold*> order = manifolds;
  const Eigen::Vector3d up = step.scene.gravity.squaredNorm() > 0 ? Eigen::Vector3d(-step.scene.gravity.normalized())
                                                                  : Eigen::Vector3d::Zero();
  if (up.squaredNorm() > 0) {
    const auto height = [&](const Manifold* m) { return up.dot(m->points.front().point); };
    std::stable_sort(order.begin(), order.end(), [&](const Manifold* a, const Manifold* b) { return height(a) < height(b); });
  }
  bool any = false;
  for (int iteration = 0; iteration < step.settings.tuning.positionIterations; ++iteration) {
    bool pushed = false;
    for (Manifold* m : order) {
      double deepest = 1e300;
      for (const ManifoldPoint& p : m->points)
        deepest = std::min(deepest, p.separation + m->normal.dot(moved[m->j] - moved[m->i]));
      double wi = weight(m->i), wj = weight(m->j);
      if (deepest >= rest || wi + wj <= 0) continue;
      // Shock propagation (Guendelman, Bridson and Fedkiw 2003): where one body rests on the
      // other (the normal within 45 degrees of the vertical), only the upper one moves, so a
      // pass from the bottom up lifts a pyramid off its floor without pushing a lower row
      // back down.
      if (up.squaredNorm() > 0) {
        const double along = m->normal.dot(up);
        if (along > std::sqrt(0.5) && wj > 0) wi = 0;
        if (along < -std::sqrt(0.5) && wi > 0) wj = 0;
      }
      const Eigen::Vector3d push = (rest - deepest) / (wi + wj) * m->normal;
      const double before = m->normal.dot(moved[m->j] - moved[m->i]);
      moved[m->i] -= wi * push;
      moved[m->j] += wj * push;
      // No farther than `reach` in one projection: the move is checked by nothing, and the
      // pieces the solver does not hold lie beyond the contact band, so it brings none of
      // them nearer than the rest separation.
      for (int b : {m->i, m->j})
        if (const double length = moved[b].norm(); length > reach) moved[b] *= reach / length;
      if (m->normal.dot(moved[m->j] - moved[m->i]) > before) any = pushed = true;
    }
    if (!pushed) break;
  }
  if (!any) return;
  ++step.frame.report.counters.projections;
  for (int b : group) states[b].worldFromBody.translation += moved[b];
  for (Manifold* m : manifolds)
    for (ManifoldPoint& p : m->points) {
      p.separation += m->normal.dot(moved[m->j] - moved[m->i]);
      p.point += 0.5 * (moved[m->i] + moved[m->j]);
    }
}

}  // namespace

template <typename S>
bool solveContacts(StepContext& step, NarrowPhase<S>& narrow, double t0, double t1) {
  std::vector<WorldBody>& bodies = step.bodies;
  FrameState& frame = step.frame;
  const double dt = t1 - t0;
  std::vector<BodyState> states(bodies.size());
  std::vector<std::vector<int>> groups;
  std::vector<Manifold> manifolds;
  {
    PartTimer timer(frame.report.parts.contacts);
    for (std::size_t b = 0; b < bodies.size(); ++b) {
      bodies[b].contactFlight = false;
      states[b] = bodies[b].rigid.isStatic() ? bodies[b].path.start : renormalized(bodies[b].path.stateAt(t0));
      if (bodies[b].asleep) {
        states[b].velocity.setZero();
        states[b].angularVelocity.setZero();
      }
    }
    frame.contactPairs.clear();
    manifolds = findContacts(step, narrow, t0, dt, states);
    warmStart(step, manifolds, states);
    groups = groupsOf(step, manifolds);
    // Each group's manifolds (a manifold with a resting body belongs to its moving one's group).
    std::vector<int> groupOf(bodies.size(), -1);
    for (std::size_t g = 0; g < groups.size(); ++g)
      for (int b : groups[g]) groupOf[b] = int(g);
    std::vector<std::vector<Manifold*>> ofGroup(groups.size());
    for (Manifold& m : manifolds) ofGroup[std::max(groupOf[m.i], groupOf[m.j])].push_back(&m);
    FrameCounters& c = frame.report.counters;
    for (std::size_t g = 0; g < groups.size(); ++g) {
      project(step, groups[g], ofGroup[g], states);
      const GroupSolve solve = solveGroup(step, groups[g], ofGroup[g], states, dt, true);
      ++c.contactGroups;
      c.contactSweeps += solve.sweeps;
      if (solve.energyRose()) ++c.energyRises;
    }
    step.contactCache.clear();
    for (const Manifold& m : manifolds) {
      c.contactPoints += long(m.points.size());
      frame.contactPairs.emplace_back(m.i, m.j);
      touched(step, m.i, m.pi, m.j, m.pj);  // the instant pass carries a collision through contacts
      step.contactCache.emplace(step.piecePairKey(m.i, m.pi, m.j, m.pj), m);
    }
    std::sort(frame.contactPairs.begin(), frame.contactPairs.end());
    frame.contactPairs.erase(std::unique(frame.contactPairs.begin(), frame.contactPairs.end()), frame.contactPairs.end());
    frame.heldPairs.insert(frame.heldPairs.end(), frame.contactPairs.begin(), frame.contactPairs.end());
  }
  // Each group's bodies fly over the interval on the solved velocities, gravity off. Under
  // Timewarp a body spinning fast flies an eighth of a turn at a time, as a free body does
  // (ownStepEnd; where its step ends it flies on, on the same velocities): a path holds
  // less than half a turn, and a light body a collision spun up (a cartilage of a few grams
  // in the torso's crash) would otherwise make the whole frame run again.
  for (const std::vector<int>& group : groups)
    for (int b : group) {
      bodies[b].contactFlight = true;
      if (!flyFrom(step, b, states[b], t0, ownStepEnd(step, states[b], t0, t1))) return false;
    }
  frame.groups = std::move(groups);
  return true;
}

template bool solveContacts<float>(StepContext&, NarrowPhase<float>&, double, double);
template bool solveContacts<double>(StepContext&, NarrowPhase<double>&, double, double);

void wakeGroup(StepContext& step, int b) {
  WorldBody& body = step.bodies[b];
  const int group = body.sleepGroup;
  body.asleep = false;
  body.sleepGroup = -1;
  if (group < 0) return;
  for (WorldBody& other : step.bodies)
    if (other.sleepGroup == group) {
      other.asleep = false;
      other.sleepGroup = -1;
    }
}

void sleepGroups(StepContext& step, double T1) {
  std::vector<WorldBody>& bodies = step.bodies;
  const double g = step.scene.gravity.norm();
  const double frameLength = step.frameLength();
  std::vector<char> grouped(bodies.size(), 0);
  for (const std::vector<int>& group : step.frame.groups) {
    bool sleeps = g > 0;  // without weight nothing holds a body still: rest is not defined
    for (int b : group) {
      grouped[b] = 1;
      WorldBody& body = bodies[b];
      body.slowFor = isSlow(step, body, body.path.stateAt(T1)) ? body.slowFor + frameLength : 0.0;
      sleeps = sleeps && body.slowFor >= step.settings.tuning.settleSeconds;
    }
    if (!sleeps) continue;
    for (int b : group) {
      putToSleep(step, b, bodies[b].path.stateAt(T1), T1);
      bodies[b].sleepGroup = group.front();
    }
  }
  long sleeping = 0;
  for (std::size_t b = 0; b < bodies.size(); ++b) {
    if (!grouped[b] && !bodies[b].asleep) bodies[b].slowFor = 0;  // flying free: not at rest
    sleeping += bodies[b].asleep;
  }
  step.frame.report.counters.sleeping = sleeping;
}

}  // namespace gjkx
