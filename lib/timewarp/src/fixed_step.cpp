// Fixed steps with discrete collision detection (fixed_step.hpp).
#include <gjkx/timewarp/fixed_step.hpp>

#include <gjkx/support_mapping/placed.hpp>
#include <gjkx/timewarp/broad_phase.hpp>
#include <gjkx/timewarp/contact.hpp>
#include <gjkx/timewarp/response.hpp>

#include <algorithm>
#include <optional>
#include <tuple>

namespace gjkx {

namespace {

// How far two overlapping pieces must move apart along the unit contact normal n (from i
// towards j) to touch: i reaches n . S_i(n) along n, j starts at n . S_j(-n), so the overlap
// along n is n . (S_i(n) - S_j(-n)), minus the supporting distance of §2.3 along n.
// Positive: they overlap by that much along n.
double overlapAlong(const Shape<double>& pieceI, const Pose<double>& poseI, const Shape<double>& pieceJ,
                    const Pose<double>& poseJ, const Eigen::Vector3d& n) {
  const Placed<Shape<double>> P{pieceI, poseI}, Q{pieceJ, poseJ};
  return n.dot(P.support(n) - Q.support(-n));
}

// The projection of a discrete engine: a pair found overlapping at a step's end is moved
// apart along its normal until it touches, each body by its share of the inverse mass
// (a static or sleeping body does not move). Only positions change: no velocity is added, so the
// correction adds no kinetic energy, where a velocity bias (Baumgarte) would. True if the
// pair was moved.
bool separate(StepContext& step, const Hit& hit, double t) {
  WorldBody& I = step.bodies[hit.i];
  WorldBody& J = step.bodies[hit.j];
  const BodyState si = I.path.stateAt(t), sj = J.path.stateAt(t);
  const double overlap = overlapAlong(I.pieces[hit.pieceI], si.worldFromBody, J.pieces[hit.pieceJ], sj.worldFromBody,
                                      hit.normal);
  // A resting body (static, or asleep: held where it stands, its pairs with other resting
  // bodies not looked at) is not moved: pushed into a floor, it would stay there.
  const double wi = I.resting() ? 0.0 : I.rigid.inverseMass(), wj = J.resting() ? 0.0 : J.rigid.inverseMass();
  if (!(overlap > 0) || !(wi + wj > 0)) return false;
  for (const auto& [b, state, share] : {std::tuple{hit.i, si, -wi / (wi + wj)}, std::tuple{hit.j, sj, wj / (wi + wj)}}) {
    if (share == 0) continue;
    BodyState moved = state;
    moved.worldFromBody.translation += share * overlap * hit.normal;
    if (!flyFrom(step, b, moved, t, std::max(step.bodies[b].path.t1, step.intervalEnd))) return false;
  }
  ++step.frame.report.counters.projections;
  step.frame.collidedPairs.emplace_back(hit.i, hit.j);  // found and answered: not unreported
  return true;
}

// Moving one pair apart can push a body into another (a domino pressed into the floor by
// the one lying on it), so the touching pairs of a step are projected again, in a few
// passes, as discrete engines iterate their position solver.
constexpr int kProjectionPasses = 4;

}  // namespace

template <typename S>
void runFixedStep(StepContext& step, NarrowPhase<S>& narrow, double T0, double T1) {
  const int steps = step.scene.run.fixedSubsteps;
  FrameCounters& c = step.frame.report.counters;
  for (int s = 0; s < steps; ++s) {
    const double ta = T0 + (T1 - T0) * s / steps, tb = s + 1 == steps ? T1 : T0 + (T1 - T0) * (s + 1) / steps;
    if (!flyAll(step, ta, tb)) return;
    step.intervalEnd = tb;  // a collision flies its bodies on to the step's end
    // Discrete collision detection: the pairs as they stand at the step's end.
    std::vector<Hit> touching;
    for (const auto& [i, j] : candidatePairs(step, tb, tb)) {
      const BodyState si = step.bodies[i].path.stateAt(tb), sj = step.bodies[j].path.stateAt(tb);
      Hit hit;
      if (!narrow.touchingAt(step, i, j, tb, si, sj, hit)) continue;
      // A contact pair of the hybrid model is held by its contact solver: only one that came
      // nearer than the contact check's band is the step's to resolve (contact_solver.hpp).
      if (step.frame.isContactPair(i, j) &&
          (hit.pointJ - hit.pointI).norm() > step.band(step.settings.tuning.contactCheckBand))
        continue;
      std::optional<ContactPatch> deepest;
      if (hit.pointI == hit.pointJ) {
        // Overlapping: GJK stops at the overlap and gives no closest points, nor a patch
        // (the patch of a box sunk into a floor is the floor's whole face, and an impulse at
        // its centre spun a domino up instead of stopping it). The impulse acts where a
        // discrete engine's penetration depth puts it: at the deepest feature of the smaller
        // body, halfway back to the other's surface along the normal.
        const double overlap = overlapAlong(step.bodies[i].pieces[hit.pieceI], si.worldFromBody,
                                            step.bodies[j].pieces[hit.pieceJ], sj.worldFromBody, hit.normal);
        // The smaller body's deepest feature (its points within the patch depth of its
        // deepest plane: a face lying flat, an edge, or a corner), moved halfway back.
        const bool jSmaller = step.bodies[j].radius <= step.bodies[i].radius;
        const Eigen::Vector3d back = (jSmaller ? 0.5 : -0.5) * overlap * hit.normal;
        deepest.emplace();
        deepest->points = jSmaller ? touchingFeature(step.bodies[j].pieces[hit.pieceJ], sj.worldFromBody, -hit.normal,
                                                     step.band(step.settings.tuning.patchDepth))
                                   : touchingFeature(step.bodies[i].pieces[hit.pieceI], si.worldFromBody, hit.normal,
                                                     step.band(step.settings.tuning.patchDepth));
        for (auto& p : deepest->points) {
          p += back;
          deepest->centre += p / double(deepest->points.size());
        }
      }
      const double vn = deepest ? approachOn(step, hit, *deepest, si, sj) : approachAt(step, hit, si, sj);
      if (vn < 0) {
        ++c.events;
        // One impulse per pair and step, as a discrete engine's single pass over its
        // contacts; no instant pass (the baseline stays the simple one).
        resolve(step, hit, false, deepest ? &*deepest : nullptr);  // flies both bodies on from tb
        if (step.abandoned()) return;
      }
      // What the step let the pair sink into each other is undone by moving them apart
      // (approaching or not: a pair that stopped overlapping would stay in).
      separate(step, hit, tb);
      if (step.abandoned()) return;
      touching.push_back(hit);
    }
    for (int pass = 1; pass < kProjectionPasses; ++pass) {
      bool moved = false;
      for (const Hit& hit : touching) {
        moved = separate(step, hit, tb) || moved;
        if (step.abandoned()) return;
      }
      if (!moved) break;
    }
  }
}

template void runFixedStep<float>(StepContext&, NarrowPhase<float>&, double, double);
template void runFixedStep<double>(StepContext&, NarrowPhase<double>&, double, double);

}  // namespace gjkx
