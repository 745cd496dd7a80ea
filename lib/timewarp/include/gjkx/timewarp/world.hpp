/// @file
/// @brief The world: bodies in free flight, their collisions found by the paper's solver (§5)
/// and resolved in the right order by Mirtich's Timewarp, or by the two orderings it is compared with (§6).
///
/// §5: "The extrusion solver [...] returns either 'no collision' or the time of impact for a
/// whole interval [...] used in a rigid-body simulation with Mirtich's Timewarp algorithm."
/// Each frame [T0, T1] of 1/24 s (the paper's frames):
/// - every moving body is flown to T1 on its own (`freeFlight`): its *local time* runs
///   ahead to the frame's end, its path a motion the solver can query;
/// - the broad phase (broad_phase.hpp) keeps the pairs whose swept bounds overlap, and the
///   paper's extrusion + Brent solver checks each over the interval since it was last known
///   disjoint; a hit is a *collision event* in one queue ordered by time;
/// - **Timewarp** (Mirtich, SIGGRAPH 2000) takes the earliest event, *rolls back* only its
///   two bodies to the time of impact t_c (their histories cut at t_c), applies the impulse
///   (impulse.hpp), flies them on to T1, and re-checks only the pairs that touch them: every
///   other event stays valid, and the events that used the rolled-back paths after t_c
///   are dropped (their bodies' *versions* changed). The frame is final once the queue is
///   empty: the global virtual time has passed it, and the history before it is discarded;
/// - the **time-of-impact heap** (what a user would otherwise pick) advances *every* body to
///   the earliest impact, resolves it, and checks every pair again from there;
/// - **fixed steps** fly every body a fixed step and test the pairs statically at its end
///   (discrete collision detection, which can tunnel).
///
/// Contacts within the tolerance that are already moving apart are not collisions: the
/// pair's check starts again once they have had time to leave the tolerance band. Resting
/// contact is a train of *microcollisions* (impulse.hpp).
#pragma once

#include <gjkx/brent/time_of_impact.hpp>
#include <gjkx/dynamics/free_flight.hpp>
#include <gjkx/dynamics/impulse.hpp>
#include <gjkx/dynamics/rigid_body.hpp>
#include <gjkx/kdop/body_pair.hpp>
#include <gjkx/support_mapping/shape.hpp>
#include <gjkx/timewarp/broad_phase.hpp>
#include <gjkx/timewarp/contact.hpp>
#include <gjkx/timewarp/motion_cast.hpp>
#include <gjkx/timewarp/scene.hpp>

#include <array>
#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <type_traits>
#include <unordered_map>
#include <vector>

namespace gjkx {

class ReferenceBody;  // checks.hpp

/// Settings of the world that are not part of a scene (they choose how, not what).
struct WorldSettings {
  /// The extrusion test of the solver: the paper's or the certified one (never misses
  /// under rotation; gjkx/extrusion/certified_margin.hpp). The default is certified.
  ExtrusionVariant variant = ExtrusionVariant::Certified;
  /// Warm starts inside each time-of-impact query: every complete extrusion test after the
  /// first starts from the last one's simplex and support hints (`ToiSettings::warmStart`).
  bool warmStarts = true;
  /// Temporal coherence between queries (§2): each convex piece pair's query starts where
  /// the pair's last one ended (its separating vector, tried first, and GJK's simplex).
  /// Needs `warmStarts`.
  bool coherence = true;
  /// Keep each body pair's 14-DOP front between frames (generalized front tracking, kdop's
  /// `BodyPairQuery`); false traverses the hierarchies afresh at every query.
  bool frontTracking = true;
  /// Run the independent checks (penetration at each frame's end, tunnelling by dense sampling).
  bool checks = true;
  /// Record what the orderings did, event by event (chapter 07 draws it).
  bool trace = false;
  /// The impulse integration's tolerances and step cap (gjkx/dynamics/impulse.hpp, §6); its
  /// microcollision speed is not taken from here but from the scene (its gravity and
  /// collision tolerance). Checked when the world is built ("settings.impulse...").
  ImpulseSettings impulse;
};

/// What happened in one frame (a row of frames.csv).
struct FrameCounters {
  long events = 0;              ///< events taken from the queue (stale ones included)
  long collisionChecks = 0;     ///< pair queries of the time-of-impact solver (or static tests)
  long collisions = 0;          ///< impulses applied (microcollisions included)
  long microcollisions = 0;     ///< of which microcollisions
  long caught = 0;              ///< microcollisions that stopped a caught body (one struck more than 32 times in the frame: Zeno's wedge; World::resolve)
  long settled = 0;             ///< bodies put to sleep at the frame's end, their kinetic energy too small to leave the tolerance band (World::settle)
  long rollbacks = 0;           ///< collisions that rolled back bodies whose local time had run past t_c
  long bodiesRolledBack = 0;    ///< bodies rolled back (or, for the heap, advanced to the impact)
  long brentQueries = 0;        ///< queries whose first extrusion test failed, so that Brent ran (§5)
  long brentIterations = 0;     ///< Brent iterates of every query
  int brentMax = 0;             ///< the most of one query
  long photoFinishes = 0;       ///< queries that ended in a photo finish (§5)
  long completeTests = 0;       ///< complete extrusion tests (one per query plus restarts)
  long solverCaps = 0;          ///< queries that ran out of iterations (treated as collisions)
  long piecePairs = 0;          ///< convex piece pairs of mesh bodies that the 14-DOP hierarchy handed to the solver
  long kdopNodes = 0;           ///< nodes of the hierarchies' test trees visited (kdop)
  long sdEvaluations = 0;       ///< supporting distances evaluated by the time-of-impact queries (each a support pair)
  long impulseSteps = 0;        ///< steps of the impulse integration, accepted and rejected (ImpulseResult::integratorSteps)
  long impulseCaps = 0;         ///< impulses whose integration reached ImpulseSettings::maxSteps (ImpulseStatus::StepCap; the impulse so far applied)
  double maxPenetration = 0;    ///< the deepest penetration at the frame's end (independent check)
  int tunnelled = 0;            ///< pairs that interpenetrated during the frame with no collision reported (by more than twice the tolerance, or a tolerance deeper than they started the frame)
};

/// Wall time of a frame by part (seconds), as Fig. 6 of the paper splits it.
struct PartTimes {
  double integration = 0;         ///< free flight (odeint for turning bodies)
  double bounds = 0;              ///< swept bounds and the broad phase
  double collisionDetection = 0;  ///< the time-of-impact solver (or the static tests)
  double impulses = 0;            ///< contact points and Mirtich's impulses
  double ordering = 0;            ///< the event queue, rollbacks, bookkeeping
  double checks = 0;              ///< the independent checks (not part of the method)
};

/// One frame's report.
struct FrameReport {
  int frame = 0;              ///< 1, 2, ...
  double time = 0;            ///< simulated time at the frame's end
  double wallSeconds = 0;     ///< wall time spent on the frame
  FrameCounters counters;     ///< what happened
  PartTimes parts;            ///< where the wall time went
};

/// One record of the trace (WorldSettings::trace): what an ordering did to a body's local time.
struct TraceEvent {
  /// What happened.
  enum class Kind {
    Advance,    ///< the body flew from `from` to `to` (its local time now `to`)
    Collision,  ///< a collision at `to` between `body` and `other`
    Rollback,   ///< the body's local time went back from `from` to `to`
    Check,      ///< a pair check over [from, to] between `body` and `other`
  };
  Kind kind = Kind::Advance;  ///< what happened
  int body = -1;              ///< the body
  int other = -1;             ///< the other body of a pair, or -1
  double from = 0;            ///< time before / interval start
  double to = 0;              ///< time after / interval end
};

/// A body of the world: its shape about its centre of mass, its mass, its path.
///
/// Every body is a set of convex pieces (§6): a convex body is one piece, a mesh body the
/// pieces of its convex decomposition (gjkx/mesh), held in a 14-DOP hierarchy
/// (gjkx/kdop) that prunes the piece pairs of a body pair before the solver sees them.
struct WorldBody {
  std::string name;                 ///< its name in the scene
  Shape<double> shape = Sphere<double>(0);   ///< its shape (a mesh body: the hull of its pieces), body frame at the centre of mass
  Shape<float> shapeFloat = Sphere<float>(0);  ///< the same in float (collision detection in float)
  std::vector<Shape<double>> pieces;       ///< its convex pieces (a convex body: `shape` alone)
  std::vector<Shape<float>> piecesFloat;   ///< the same in float
  std::shared_ptr<const Bvh<double>> bvh;       ///< a mesh body's hierarchy of pieces (null for a convex body)
  std::shared_ptr<const Bvh<float>> bvhFloat;   ///< the same in float
  Eigen::Vector3d frameOrigin;      ///< the scene's shape frame origin, in the body frame (minus the centre of mass)
  RigidBody rigid = RigidBody::fixed();  ///< mass properties (or static)
  double radius = 0;                ///< bounding radius about the centre of mass
  FreeFlight path;                  ///< its path from its last event to its local time `path.t1` (set it with setPath)
  Motion<float> motionFloat;        ///< `path`'s motion in float, made once per path (collision detection in float reads it at every query)
  int version = 0;                  ///< bumped when its path changes: events that used the old one are stale
  /// Caught at rest against a static body (World::resolve), or settled at a frame's end
  /// with too little kinetic energy to leave the tolerance band (World::settle), and not
  /// struck since: it is held where it stands, gravity off, and its pairs with static and
  /// sleeping bodies are not looked at, until a collision with a moving body wakes it.
  bool asleep = false;
  /// How long (simulated s) it has been too slow to leave the tolerance band and struck by
  /// nothing but resting or slow bodies (World::settle); it settles after half a second.
  double slowFor = 0;
  /// The gravity its path feels: none while it sleeps.
  Eigen::Vector3d gravity(const Eigen::Vector3d& sceneGravity) const {
    return asleep ? Eigen::Vector3d::Zero() : sceneGravity;
  }
  /// A body that cannot move of its own accord: static, or asleep.
  bool resting() const { return asleep || rigid.isStatic(); }
  /// Sets its path, and the path's motion in float once for all the queries that read it
  /// (converting it at each query took a tenth of the torso's run).
  void setPath(FreeFlight next) {
    path = std::move(next);
    motionFloat = castMotion<float>(path.motion);
  }
  /// The path's motion in the scalar type S of collision detection.
  template <typename S>
  const Motion<S>& motionIn() const {
    if constexpr (std::is_same_v<S, float>) return motionFloat;
    else return path.motion;
  }
};

/// The world of a scene, run frame by frame.
class World {
 public:
  /// Builds the bodies of `scene` (mass properties, shapes about the centre of mass) and
  /// checks them: two bodies overlapping at the start (one of them not static) is an
  /// error naming both. Throws std::invalid_argument.
  explicit World(const Scene& scene, const WorldSettings& settings = {});

  /// Runs one frame and reports it.
  FrameReport step();
  /// True once the scene's duration is simulated.
  bool done() const { return frame_ >= frameCount_; }
  /// Frames in the scene's duration.
  int frameCount() const { return frameCount_; }
  /// Simulated time.
  double time() const { return double(frame_) / scene_.frameRate; }
  /// The bodies.
  const std::vector<WorldBody>& bodies() const { return bodies_; }
  /// A body's state now (at `time()`).
  BodyState stateOf(int body) const { return bodies_[body].path.stateAt(time()); }
  /// Where the origin of a body's scene frame is now (the position as the scene file gives it).
  Eigen::Vector3d positionOf(int body) const;
  /// The scene.
  const Scene& scene() const { return scene_; }
  /// The trace of every frame so far (empty unless WorldSettings::trace).
  const std::vector<TraceEvent>& trace() const { return trace_; }
  /// The collisions of every frame so far: (time, body, other).
  const std::vector<std::array<double, 3>>& collisionLog() const { return collisionLog_; }

 private:
  struct Hit;
  struct FrameState;
  void flyAll(double t0, double t1, FrameState& frame);
  void fly(int body, double t0, double t1, FrameState& frame);
  Bounds sweptBounds(int body, double t0, double t1) const;
  Bounds sweptBounds(int body, const FreeFlight& path, double t0, double t1) const;
  double approachAt(Hit& hit, const BodyState& si, const BodyState& sj, FrameState& frame) const;
  ContactPatch patchOf(const Hit& hit, const BodyState& si, const BodyState& sj) const;
  double approachOn(Hit& hit, const ContactPatch& patch, const BodyState& si, const BodyState& sj) const;
  std::vector<std::pair<int, int>> candidatePairs(double t0, double t1, FrameState& frame, int only = -1,
                                                  int also = -1);
  bool checkPair(int i, int j, double t0, double t1, FrameState& frame, Hit& hit);
  bool checkPieces(int i, int pi, int j, int pj, double t0, double t1, FrameState& frame, Hit& hit);
  template <typename S>
  std::vector<PiecePair> piecePairs(int i, int j, double t0, double t1, FrameState& frame);
  void applyImpulse(const Hit& hit, BodyState& si, BodyState& sj, FrameState& frame);
  bool contactFromGjk(const GjkResult<double>& g, int i, int pi, int j, int pj, double t, const BodyState& si,
                      const BodyState& sj, Hit& hit);
  bool contactAt(int i, int pi, int j, int pj, double t, const BodyState& si, const BodyState& sj, FrameState& frame,
                 Hit& hit);
  void touched(int i, int pi, int j, int pj, FrameState& frame);
  std::vector<int> resolve(const Hit& hit, FrameState& frame, bool instantPass = true);
  void runTimewarp(double T0, double T1, FrameState& frame);
  void runToiHeap(double T0, double T1, FrameState& frame);
  void runFixedStep(double T0, double T1, FrameState& frame);
  void runChecks(double T0, double T1, FrameState& frame);
  void settle(double T1, FrameState& frame);
  double relativeSpeedBound(int i, int j, double T0, double T1, const FrameState& frame) const;

  Scene scene_;
  WorldSettings settings_;
  std::vector<WorldBody> bodies_;
  /// The bodies as the independent checks measure them (checks.hpp), prepared once.
  std::vector<std::shared_ptr<const ReferenceBody>> referenceBodies_;
  ImpulseSettings impulse_;
  int frame_ = 0;
  int frameCount_ = 0;
  double intervalEnd_ = 0;  // the end of the interval an ordering is running (the frame's end, or a part of it)
  std::vector<TraceEvent> trace_;
  std::vector<std::array<double, 3>> collisionLog_;
  /// Per mesh body, its nodes' 14-DOPs at its recent poses, shared by all its body pairs
  /// (kdop's `BodyKdops`; created when a pair first needs it).
  std::vector<std::unique_ptr<BodyKdops<float>>> kdopsFloat_;
  /// The same in double.
  std::vector<std::unique_ptr<BodyKdops<double>>> kdopsDouble_;
  /// Per pair of mesh bodies, the body-pair query that keeps its front between frames (kdop).
  std::map<long long, std::unique_ptr<BodyPairQuery<float>>> frontsFloat_;
  /// The same in double.
  std::map<long long, std::unique_ptr<BodyPairQuery<double>>> frontsDouble_;
  /// Per convex piece pair, where its last time-of-impact query ended (WorldSettings::coherence).
  std::unordered_map<std::uint64_t, ExtrusionCache<float>> coherenceFloat_;
  /// The same in double.
  std::unordered_map<std::uint64_t, ExtrusionCache<double>> coherenceDouble_;
  /// The key of piece pi of body i and piece pj of body j in those maps.
  std::uint64_t piecePairKey(int i, int pi, int j, int pj) const {
    return (std::uint64_t(pairSlot(i, j)) << 32) | std::uint64_t(std::uint32_t(pi) * std::uint32_t(bodies_[j].pieces.size()) + std::uint32_t(pj));
  }
  /// Per piece pair, the last reliable contact normal (see checkPieces), zero until one is seen.
  std::map<std::array<int, 4>, Eigen::Vector3d> pairNormal_;
  Eigen::Vector3d& knownNormal(int i, int pi, int j, int pj) {
    return pairNormal_.try_emplace(std::array<int, 4>{i, pi, j, pj}, Eigen::Vector3d::Zero()).first->second;
  }
  long long pairSlot(int i, int j) const { return (long long)(i) * (long long)(bodies_.size()) + j; }
};

}  // namespace gjkx
