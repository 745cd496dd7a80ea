// The narrow phase (narrow_phase.hpp): the paper's solver on the piece pairs of a body pair.
#include <gjkx/timewarp/narrow_phase.hpp>

#include <gjkx/gjk/gjk.hpp>
#include <gjkx/timewarp/contact.hpp>
#include <gjkx/motion/motion_cast.hpp>

#include <algorithm>
#include <stdexcept>
#include <type_traits>

namespace gjkx {

namespace {

/// How fast any point of a body can move over its path: |v| + |w| r at either end of it,
/// with the change gravity can make within the path (a bound for the time tolerance only).
double speedBound(const WorldBody& body) {
  if (body.rigid.isStatic()) return 0;
  const FreeFlight& path = body.path;
  double bound = 0;
  for (const BodyState* s : {&path.start, &path.end})
    bound = std::max(bound, s->velocity.norm() + s->angularVelocity.norm() * body.radius);
  return bound;
}

}  // namespace

template <typename S>
NarrowPhase<S>::NarrowPhase(const std::vector<WorldBody>& bodies) {
  bvh_.resize(bodies.size());
  kdops_.resize(bodies.size());
  if constexpr (std::is_same_v<S, float>) {
    motions_.resize(bodies.size(), {-1, Motion<S>{}});
    for (const WorldBody& body : bodies) pieces_.push_back(gjkx::piecesOf<S>(body.source));
  }
  for (std::size_t b = 0; b < bodies.size(); ++b) {
    if (!bodies[b].source.isMesh()) continue;
    std::vector<Polytope<S>> polytopes;
    for (const Shape<S>& piece : piecesOf(bodies, int(b))) polytopes.push_back(std::get<Polytope<S>>(piece.variant()));
    // A static body's 14-DOPs are needed at one pose: its inner nodes need no hull (bvh.hpp).
    bvh_[b] = std::make_shared<const Bvh<S>>(std::move(polytopes),
                                             bodies[b].rigid.isStatic() ? InnerHulls::none : InnerHulls::every);
  }
}

template <typename S>
const std::vector<Shape<S>>& NarrowPhase<S>::piecesOf(const std::vector<WorldBody>& bodies, int b) const {
  if constexpr (std::is_same_v<S, float>) return pieces_[std::size_t(b)];
  else return bodies[std::size_t(b)].pieces;
}

template <typename S>
const Motion<S>& NarrowPhase<S>::motionOf(const WorldBody& body, int b) {
  if constexpr (std::is_same_v<S, float>) {
    auto& [serial, motion] = motions_[std::size_t(b)];
    if (serial != body.pathSerial) {  // rounded once per path (converting at each query took a tenth of the torso's run)
      motion = castMotion<float>(body.path.motion);
      serial = body.pathSerial;
    }
    return motion;
  } else {
    (void)b;
    return body.path.motion;
  }
}

/// The time-of-impact query of piece pi of body i and piece pj of body j over [t0, t1].
template <typename S>
ToiResult<double> NarrowPhase<S>::query(StepContext& step, int i, int pi, int j, int pj, double t0, double t1,
                                        double tolerance) {
  const WorldBody& P = step.bodies[i];
  const WorldBody& Q = step.bodies[j];
  const StepTuning& tuning = step.settings.tuning;
  const Moving<ShapeRef<S>> movingP{piecesOf(step.bodies, i)[pi], motionOf(P, i)};
  const Moving<ShapeRef<S>> movingQ{piecesOf(step.bodies, j)[pj], motionOf(Q, j)};
  // The paper's solver (asked for by the scene or the world's settings) runs the paper's
  // test with every refinement off; ours takes the world's variant and warm starts.
  const bool paper = step.paperSolver();
  ToiSettings<S> settings = paper ? ToiSettings<S>::paper() : ToiSettings<S>::gjkx();
  settings.collisionTolerance = S(tolerance);
  if (!paper) settings.variant = step.settings.variant;
  settings.warmStart = settings.warmStart && step.settings.warmStarts;
  settings.coherence = settings.coherence && step.settings.coherence;
  // The time of impact is needed to within the tolerance band, not to the solver's default
  // of sqrt(eps) of the interval (6e-10 s of a frame in double): a contact found where the
  // bodies are within 1.5 tolerances is as good to the impulse as one found at exactly one.
  // So the time tolerance is the time the pair needs to close half a tolerance at its
  // fastest (StepTuning::closingBand). (Under rotation the solver's restarts halve the gap
  // to the contact one at a time, time_of_impact.hpp: this ends them some twenty restarts
  // sooner.) For the same reason a restart that finds the bodies within the accepted band,
  // once the query has taken `acceptedAfter` Brent iterations, is a hit: a grazing pass just
  // above the tolerance ends there rather than being proven free of contact link by link
  // (StepTuning::acceptedBand says what it costs in penetration).
  settings.acceptedDistance = S(tuning.acceptedBand * tolerance);
  settings.acceptedAfter = tuning.acceptedAfter;
  // That time is also a bound the solver must keep: when Brent's bracket converges it
  // reports the hit at the bracket's start, where the pieces may be as far apart as they
  // close in one time tolerance. The solver's default (sqrt(eps) of the interval) is finer
  // for slow pairs, where the band's time is used instead, but coarser for fast ones: in
  // float a ball thrown at 10^6 m/s moves 14 m in it, and a pass 2 mm above a box was
  // reported as a hit there, its impulse spinning the box at 10^5 rad/s. So the band's
  // time is used whatever it is (closingBand tolerances at the pair's fastest).
  const double closing = speedBound(P) + speedBound(Q);
  if (closing > 0)
    settings.timeTolerance = S(std::min(0.25, tuning.closingBand * tolerance / (closing * (t1 - t0))));
  ExtrusionCache<S>* coherence = nullptr;
  if (settings.coherence && settings.warmStart) coherence = &coherence_[step.piecePairKey(i, pi, j, pj)];
  const ToiResult<S> r = timeOfImpact(movingP, movingQ, S(t0), S(t1), settings, nullptr, coherence);
  ToiResult<double> out;
  out.status = r.status;
  out.time = std::clamp(double(r.time), t0, t1);
  out.distance = double(r.distance);
  out.normal = r.normal.template cast<double>();
  out.witnessP = r.witnessP.template cast<double>();
  out.witnessQ = r.witnessQ.template cast<double>();
  out.brentIterations = r.brentIterations;
  out.gjkRuns = r.gjkRuns;
  out.sdEvaluations = r.sdEvaluations;
  out.restarts = r.restarts;
  return out;
}

/// The piece pairs of bodies i and j that may come within `tolerance` over [t0, t1]: the one
/// pair of two convex bodies; for mesh bodies, the pairs the 14-DOP hierarchies cannot prove
/// apart (kdop's body-pair query, its front kept between frames for the pair); a mesh against a
/// convex body that is not a polytope: every piece.
template <typename S>
std::vector<PiecePair> NarrowPhase<S>::piecePairs(StepContext& step, int i, int j, double t0, double t1,
                                                  double tolerance) {
  const std::size_t piecesI = step.bodies[i].pieces.size(), piecesJ = step.bodies[j].pieces.size();
  if (piecesI == 1 && piecesJ == 1) return {PiecePair{0, 0}};
  std::vector<PiecePair> pairs;
  if (bvh_[i] && bvh_[j]) {
    PartTimer timer(step.frame.report.parts.bounds);
    auto& query = fronts_[(long long)(i) * (long long)(step.bodies.size()) + j];
    if (!query) {
      BodyPairSettings<S> settings;
      settings.tolerance = S(step.scene.collisionTolerance);
      settings.frontTracking = step.settings.frontTracking;
      // Each body's 14-DOPs at a pose are shared by all its pairs: after a collision every
      // pair of the struck body is queried at the same two poses, and its nodes' slab
      // ends are computed once for all of them (body_kdops.hpp).
      for (int b : {i, j})
        if (!kdops_[b]) kdops_[b] = std::make_unique<BodyKdops<S>>(*bvh_[b]);
      query = std::make_unique<BodyPairQuery<S>>(*kdops_[i], *kdops_[j], settings);
    }
    BodyPairOutput<S> out =
        query->query(motionOf(step.bodies[i], i), motionOf(step.bodies[j], j), S(t0), S(t1), S(tolerance));
    step.frame.report.counters.kdopNodes += out.counters.nodesVisited;
    pairs = std::move(out.pairs);
  } else {
    for (int a = 0; a < int(piecesI); ++a)
      for (int b = 0; b < int(piecesJ); ++b) pairs.push_back(PiecePair{a, b});
  }
  step.frame.report.counters.piecePairs += long(pairs.size());
  return pairs;
}

template <typename S>
bool NarrowPhase<S>::checkPair(StepContext& step, int i, int j, double t0, double t1, Hit& hit) {
  // The pair's collision is the earliest of its pieces'.
  bool found = false;
  Hit piece;
  const double tolerance = step.frame.isContactPair(i, j) ? step.band(step.settings.tuning.contactCheckBand)
                                                          : step.scene.collisionTolerance;
  // Once one piece pair has a collision, the others are checked only until it: one of
  // theirs that comes later is not the pair's (and were it needed, the collision's impulse
  // changes a body of the pair, whose pairs are all checked again from there).
  for (const PiecePair& p : piecePairs(step, i, j, t0, t1, step.scene.collisionTolerance)) {
    const double until = found ? hit.time : t1;
    if (until <= t0 || !checkPieces(step, i, p.a, j, p.b, t0, until, t1, tolerance, piece)) continue;
    if (!found || piece.time < hit.time) hit = piece;
    found = true;
  }
  return found;
}

template <typename S>
bool NarrowPhase<S>::checkPieces(StepContext& step, int i, int pi, int j, int pj, double t0, double t1,
                                 double pathsEnd, double tolerance, Hit& hit) {
  FrameCounters& c = step.frame.report.counters;
  const StepTuning& tuning = step.settings.tuning;
  const double frameLength = step.frameLength();
  // A contact within the tolerance that is already moving apart is no collision: look again
  // once the bodies can have left the tolerance band, until the interval is covered (each
  // look moves on by at least minLookAhead of a frame; the rest of an interval is never
  // left unchecked).
  //
  // The time skipped is checked too. Its closest points leave, but a spinning body closes
  // elsewhere meanwhile (a box turning at 16 rad/s put another corner 3.9 mm into the
  // floor within one look-ahead). So the skipped window [t_c, t_c + look] is asked once
  // more, with half the distance the pair has at t_c as its band: no contact nearer than
  // that, or the first one; a contact found there that still leaves moves on by its own
  // look-ahead, within the window. A pair nearer than StepTuning::windowBand at t_c
  // (resting) moves on as before: halving its distance would find it again and again.
  bool inWindow = false;    // the next query checks a skipped window
  double band = tolerance;  // the band of the next query: the tolerance, or a window's
  double windowEnd = t1;    // the end of the next query: t1, or the window's
  const auto leaveWindow = [&] {
    inWindow = false;
    band = tolerance;
    windowEnd = t1;
  };
  while (t0 < t1) {
    ToiResult<double> r;
    {
      PartTimer timer(step.frame.report.parts.collisionDetection);
      r = query(step, i, pi, j, pj, t0, windowEnd, band);
    }
    ++c.collisionChecks;
    if (step.bodies[i].rigid.isStatic() || step.bodies[j].rigid.isStatic()) ++c.staticChecks;
    c.brentIterations += r.brentIterations;
    c.brentMax = std::max(c.brentMax, long(r.brentIterations));
    c.completeTests += r.gjkRuns;
    c.sdEvaluations += r.sdEvaluations;
    step.record(TraceEvent::Kind::Check, i, j, t0, windowEnd);
    if (r.status == ToiStatus::Hit || r.status == ToiStatus::PhotoFinish ||
        (r.status == ToiStatus::IterationCap && r.brentIterations > 0))
      ++c.brentQueries;
    bool clear = false;  // [t0, windowEnd] is proven free of contact
    switch (r.status) {
      case ToiStatus::NoCollision: clear = true; break;
      case ToiStatus::Separating: touched(step, i, pi, j, pj); clear = true; break;  // in contact, leaving
      case ToiStatus::PhotoFinish: ++c.photoFinishes; clear = true; break;
      case ToiStatus::NumericalFailure:
        throw std::runtime_error("bodies '" + step.bodies[i].name + "' and '" + step.bodies[j].name +
                                 "': the time-of-impact solver met a non-finite support point near t = " +
                                 std::to_string(t0));
      case ToiStatus::IterationCap: ++c.solverCaps; [[fallthrough]];  // undecided: treated as a collision
      case ToiStatus::Hit:
      case ToiStatus::StartsPenetrating: break;
    }
    if (clear) {
      if (windowEnd >= t1) return false;
      t0 = windowEnd;  // the window is clear: on with the tolerance to t1
      leaveWindow();
      continue;
    }
    hit.time = r.time;
    hit.i = i;
    hit.j = j;
    hit.pieceI = pi;
    hit.pieceJ = pj;
    hit.versionI = step.bodies[i].version;
    hit.versionJ = step.bodies[j].version;
    hit.pointI = r.witnessP;
    hit.pointJ = r.witnessQ;
    hit.normal = r.normal;
    const BodyState si = step.bodies[i].path.stateAt(hit.time), sj = step.bodies[j].path.stateAt(hit.time);
    if constexpr (std::is_same_v<S, float>) {
      // Float decides when; the impulse needs where, better than float's witnesses give
      // it: at a distance of one tolerance (3.45e-4) their round-off (~1e-7 of the
      // coordinates) tilts the normal by 1e-3, enough to make a 6 m floor touch at a far
      // corner. So the contact data are taken again in double at the time found.
      PartTimer timer(step.frame.report.parts.collisionDetection);
      const GjkResult<double> g = gjk(Placed<ShapeRef<double>>{step.bodies[i].pieces[pi], si.worldFromBody},
                                      Placed<ShapeRef<double>>{step.bodies[j].pieces[pj], sj.worldFromBody});
      if (g.status != GjkStatus::Overlapping) {
        r.distance = g.distance;
        hit.pointI = g.witnessP;
        hit.pointJ = g.witnessQ;
        const Eigen::Vector3d z = g.witnessQ - g.witnessP;
        hit.normal = z.norm() > 0 ? Eigen::Vector3d(z.normalized()) : Eigen::Vector3d::Zero();
      }
    }
    contactNormal(step, hit, r.distance, si, sj);
    touched(step, i, pi, j, pj);
    const double vn = approachAt(step, hit, si, sj);
    // Approaching: a collision. Two bodies at rest against each other (a caught body, see
    // response.hpp) approach by round-off (4e-16 m/s), and an impulse cannot change that:
    // they are taken as at rest, and looked at again once gravity has moved them.
    if (vn < -tuning.approachSpeed) {
      if (!landsAsContact(step, i, pi, j, pj, hit.time, pathsEnd, vn)) return true;
      ++c.landings;  // nearer than the tolerance but never than s*: the next contact solve's
      return false;
    }
    const double leave = step.scene.collisionTolerance / std::max(vn, 1e-12);
    const double look = std::clamp(leave, tuning.minLookAhead * frameLength, tuning.maxLookAhead * frameLength);
    if (inWindow) {  // within a window: on by the look-ahead, to the window's end at most
      t0 = std::min(windowEnd, hit.time + look);
      if (t0 >= windowEnd) leaveWindow();  // the window is covered
    } else if (r.distance > tuning.windowBand * tolerance) {  // the window, asked with half the distance
      // (A pair the query found within its band may be farther apart in double, where the
      // distance is taken: the window's band is never wider than the query's.)
      inWindow = true;
      band = std::min(0.5 * r.distance, tolerance);
      windowEnd = std::min(t1, hit.time + look);
      t0 = hit.time;
    } else if (step.hybrid()) {  // nearer than that (resting): on by the look-ahead, unchecked ...
      // ... but under the hybrid no longer than its fastest points take to move one tolerance.
      // A contact struck with no restitution (response.cpp) rests here, where a
      // microcollision's bounce would send it apart, and a box turning on a capsule could
      // sink several tolerances into it within one unchecked sixteenth of a frame.
      const double drift = speedBound(step.bodies[i]) + speedBound(step.bodies[j]);
      t0 = hit.time + std::max(tuning.minLookAhead * frameLength,
                               drift > 0 ? std::min(look, step.scene.collisionTolerance / drift) : look);
    } else {  // nearer than that (resting): on by the look-ahead
      t0 = hit.time + look;
    }
  }
  return false;
}

template <typename S>
bool NarrowPhase<S>::landsAsContact(StepContext& step, int i, int pi, int j, int pj, double tc, double t1,
                                    double vn) {
  const StepTuning& tuning = step.settings.tuning;
  // Only a pair the solver does not hold yet (a contact pair is checked with a narrower band),
  // on paths that reach the interval's end (the next solve's start).
  if (!step.hybrid() || step.frame.isContactPair(i, j) || t1 < step.intervalEnd) return false;
  // Faster than the contact speed the next solve would take it for a collision all the same.
  if (step.intervalEnd <= step.intervalStart || vn < -step.contactSpeed()) return false;
  if (tc >= step.intervalEnd) return true;  // met at the very end: the next solve's start
  // The rest of the interval, asked with the rest separation as the band: proven clear, the
  // pair ends the interval no nearer than where the solver brings contacts to rest.
  ToiResult<double> r;
  {
    PartTimer timer(step.frame.report.parts.collisionDetection);
    r = query(step, i, pi, j, pj, tc, t1, step.band(tuning.restSeparation));
  }
  ++step.frame.report.counters.collisionChecks;
  return r.status == ToiStatus::NoCollision || r.status == ToiStatus::Separating || r.status == ToiStatus::PhotoFinish;
}

template <typename S>
bool NarrowPhase<S>::touchingAt(StepContext& step, int i, int j, double t, const BodyState& si, const BodyState& sj,
                                Hit& hit) {
  const std::vector<PiecePair> pairs = piecePairs(step, i, j, t, t, step.scene.collisionTolerance);
  bool found = false;
  for (const PiecePair& p : pairs) {
    ++step.frame.report.counters.collisionChecks;
    GjkResult<double> g;
    {
      PartTimer timer(step.frame.report.parts.collisionDetection);
      const auto r = gjk(Placed<ShapeRef<S>>{piecesOf(step.bodies, i)[p.a], si.worldFromBody.template cast<S>()},
                         Placed<ShapeRef<S>>{piecesOf(step.bodies, j)[p.b], sj.worldFromBody.template cast<S>()});
      g.status = r.status;
      g.distance = double(r.distance);
      g.witnessP = r.witnessP.template cast<double>();
      g.witnessQ = r.witnessQ.template cast<double>();
    }
    const bool touching = g.status == GjkStatus::Overlapping || g.distance <= step.scene.collisionTolerance;
    if (!touching) {
      // Apart: the direction of the closest points is the pair's reliable normal.
      const Eigen::Vector3d z = g.witnessQ - g.witnessP;
      if (z.norm() > step.band(step.settings.tuning.reliableNormal)) step.knownNormal(i, p.a, j, p.b) = z.normalized();
      continue;
    }
    // The first touching piece pair found speaks for the body pair.
    if (found) continue;
    found = true;
    contactFromGjk(step, g, i, p.a, j, p.b, t, si, sj, hit);
  }
  return found;
}

template <typename S>
void NarrowPhase<S>::piecesWithin(StepContext& step, int i, int j, double t, const BodyState& si,
                                  const BodyState& sj, double distance,
                                  std::vector<std::pair<PiecePair, GjkResult<double>>>& out) {
  // (The hierarchies keep only pieces within `distance`: the contact band is wider than the
  // collisions' tolerance the body pair's other queries use.)
  for (const PiecePair& p : piecePairs(step, i, j, t, t, distance)) {
    ++step.frame.report.counters.collisionChecks;
    GjkCache<double>* cache =
        step.settings.warmStarts ? &staticCoherence_[step.piecePairKey(i, p.a, j, p.b)] : nullptr;
    // A pair farther apart than `distance` is left as soon as a direction proves it (§2.3's
    // boolean query; warm, most often the first): its run ends with a distance above
    // `distance` (an upper bound).
    GjkSettings<double> settings;
    settings.separationThreshold = distance;
    const GjkResult<double> g = gjk(Placed<ShapeRef<double>>{step.bodies[i].pieces[p.a], si.worldFromBody},
                                    Placed<ShapeRef<double>>{step.bodies[j].pieces[p.b], sj.worldFromBody}, settings, cache);
    if (g.status == GjkStatus::Overlapping || g.distance <= distance) out.emplace_back(p, g);
  }
}

template class NarrowPhase<float>;
template class NarrowPhase<double>;

}  // namespace gjkx
