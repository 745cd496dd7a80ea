/// @file
/// @brief The step context: what every part of a step shares (§5–§6). The world's bodies, its
/// scene and settings, the frame being run, and free flight, the first part of a step.
///
/// A frame [T0, T1] is run by named parts (world.hpp draws the map): the bodies fly
/// (here), the broad phase keeps the pairs whose swept bounds meet (broad_phase.hpp), the
/// narrow phase asks the paper's solver when each pair collides (narrow_phase.hpp), an
/// ordering takes the collisions in time order (timewarp.hpp, toi_heap.hpp,
/// fixed_step.hpp), the response applies Mirtich's impulses (response.hpp), and slow
/// bodies settle (sleep.hpp). They share one `StepContext`, as Box2D's stages share its
/// step context: the parts are functions of it, and none keeps state of its own between
/// frames but the narrow phase (its caches).
#pragma once

#include <gjkx/dynamics/free_flight.hpp>
#include <gjkx/gjk/gjk.hpp>
#include <gjkx/dynamics/impulse.hpp>
#include <gjkx/dynamics/swept_bounds.hpp>
#include <gjkx/timewarp/body.hpp>
#include <gjkx/timewarp/contact_manifold.hpp>
#include <gjkx/timewarp/frame.hpp>
#include <gjkx/timewarp/scene.hpp>
#include <gjkx/timewarp/settings.hpp>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <map>
#include <string>
#include <tuple>
#include <unordered_map>
#include <vector>

namespace gjkx {

/// A collision found by a pair check: when, between which pieces of which bodies, and the
/// contact data (in double, whatever the scalar of collision detection). The versions say
/// which paths it was computed on: once a body's path changes, the event is stale
/// (Timewarp's "events that used them after t_c").
struct Hit {
  double time = 0;                 ///< the time of impact t_c
  int i = -1;                      ///< the first body
  int j = -1;                      ///< the second body (i < j)
  int pieceI = 0;                  ///< the convex piece of i that touches
  int pieceJ = 0;                  ///< the convex piece of j that touches
  int versionI = 0;                ///< i's path version the hit was found on
  int versionJ = 0;                ///< j's path version the hit was found on
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();   ///< unit, from i towards j
  Eigen::Vector3d pointI = Eigen::Vector3d::Zero();   ///< the closest point of i
  Eigen::Vector3d pointJ = Eigen::Vector3d::Zero();   ///< the closest point of j
  Eigen::Vector3d contact = Eigen::Vector3d::Zero();  ///< where the impulse acts (contact.hpp)
  /// The queue pops the earliest first; ties by the pair, so every run takes the same order.
  bool operator>(const Hit& o) const { return std::tie(time, i, j) > std::tie(o.time, o.i, o.j); }
};

/// What a frame keeps while it runs (the step's scratch, made fresh for each frame).
struct FrameState {
  FrameReport report;                              ///< what the frame reports
  std::vector<std::vector<PathPiece>> paths;       ///< per body, the paths of this frame in order
  std::vector<std::pair<int, int>> collidedPairs;  ///< pairs with a collision reported this frame
  /// Pairs the hybrid's contact solver held this frame, in any interval (i < j; may repeat):
  /// to the independent checks they are pairs in contact, as a peer's contact points are.
  std::vector<std::pair<int, int>> heldPairs;
  /// How a body was struck this frame (response.hpp: Zeno's wedge; sleep.hpp).
  struct Struck {
    int microcollisions = 0;              ///< its microcollisions
    std::vector<Eigen::Vector3d> sides;   ///< the outward normals it was struck along (up to 8, apart)
    double lastTime = -1;                 ///< the time of its last collision
    int atLastTime = 0;                   ///< its collisions at that very time
    std::vector<int> by;                  ///< the bodies that struck it (each once)
  };
  std::vector<Struck> struck;  ///< per body
  /// Two bodies' pieces that came within the tolerance this frame, or that the hybrid's
  /// contact solver held (response.hpp's instant pass).
  struct Touching {
    int i;   ///< the first body
    int pi;  ///< its piece
    int j;   ///< the second body
    int pj;  ///< its piece
    /// Same pieces.
    bool operator==(const Touching& o) const { return i == o.i && pi == o.pi && j == o.j && pj == o.pj; }
  };
  std::vector<std::vector<Touching>> touching;  ///< per body, the piece pairs it is in
  /// A body whose path would turn half a turn or more within one interval (flyChecked): the
  /// frame must be run again in shorter intervals. Once set, the orderings stop at once.
  struct SpinOverflow {
    bool happened = false;  ///< set by the first body that overflowed
    double angularSpeed = 0;  ///< its angular speed (rad/s)
    std::string what;       ///< which body, how far it turned
  } spinOverflow;           ///< (see the struct)
  /// The hybrid model's contact pairs of the interval (i < j, sorted): the ordering checks
  /// them with StepTuning::contactCheckBand, not the tolerance (contact_solver.hpp).
  std::vector<std::pair<int, int>> contactPairs;
  /// The hybrid model's contact groups of the last interval (contact_solver.hpp).
  std::vector<std::vector<int>> groups;
  /// Per piece pair (StepContext::piecePairKey), the simplex its last contact query ended on
  /// (contact.hpp's contactAt): the instant pass asks the same contacts again at every
  /// collision that reaches them, and GJK warm-started from there (§2.2's coherence) takes
  /// an iteration or two where a cold run climbs every piece from scratch.
  std::unordered_map<std::uint64_t, GjkCache<double>> contactCoherence;
  /// True if bodies i and j (any order) are a contact pair of the hybrid model.
  bool isContactPair(int i, int j) const {
    return std::binary_search(contactPairs.begin(), contactPairs.end(), std::make_pair(std::min(i, j), std::max(i, j)));
  }

  /// A fresh frame for `bodies` bodies.
  explicit FrameState(std::size_t bodies = 0);
};

/// The most a path of the world turns: an eighth of a turn (pi/4 rad). A free-flight path
/// holds less than half a turn (motion.hpp); a frame's intervals and a body's own steps keep
/// to a quarter of that, so that a collision spinning a body up within a path leaves room.
constexpr double eighthTurn = 0.25 * M_PI;

/// True if the scene's bodies fly in steps of their own (ownStepEnd): under Timewarp, where
/// every body runs on its own clock. A body that spins too fast for its interval flies an
/// eighth of a turn at a time instead of cutting every body's frame; which bodies still cut
/// the frame into intervals is the world's choice (world.cpp, StepTuning::spinIntervals).
/// The heap and fixed steps move all bodies together and cut the frame for the fastest.
bool ownStepsOf(const Scene& scene);

/// True if a body a collision struck flies a step of at most StepTuning::struckStep of a
/// frame (flyAll, resolve): under Timewarp with the hybrid contact model.
bool struckStepsOf(const Scene& scene);

/// What the parts of a step share: the world's lasting state, and the frame being run.
struct StepContext {
  const Scene& scene;                         ///< what is simulated
  const WorldSettings& settings;              ///< how
  const ImpulseSettings& impulse;             ///< settings.impulse with the scene's microcollision speed
  std::vector<WorldBody>& bodies;             ///< the bodies
  std::vector<TraceEvent>& trace;             ///< filled when settings.trace
  std::vector<CollisionRecord>& collisionLog;  ///< every collision of the run
  /// Per piece pair (i, pi, j, pj), the last reliable contact normal (contact.hpp), zero until one is seen.
  std::map<std::array<int, 4>, Eigen::Vector3d>& pairNormals;
  FrameState& frame;                          ///< the frame being run
  /// The hybrid's manifolds of the last solve, with their impulses (warm start).
  ContactCache& contactCache;
  double intervalEnd = 0;  ///< the end of the interval an ordering runs (a collision flies its bodies on to it)
  double intervalStart = 0;  ///< the start of that interval (the hybrid's contact solve is at it)

  /// The scene's collision tolerance times `multiple` (StepTuning's multiples).
  double band(double multiple) const { return multiple * scene.collisionTolerance; }
  /// A frame's length (s).
  double frameLength() const { return 1.0 / scene.frameRate; }
  /// The hybrid's contact speed over the current interval (m/s, contact_solver.hpp):
  /// StepTuning::contactSpeed intervals of gravity. A pair within the contact band that
  /// closes faster is a collision.
  double contactSpeed() const {
    return settings.tuning.contactSpeed * scene.gravity.norm() * (intervalEnd - intervalStart);
  }
  /// The last reliable normal of piece pi of body i against piece pj of body j.
  Eigen::Vector3d& knownNormal(int i, int pi, int j, int pj) {
    return pairNormals.try_emplace(std::array<int, 4>{i, pi, j, pj}, Eigen::Vector3d::Zero()).first->second;
  }
  /// A key of piece pi of body i and piece pj of body j, unique in the world.
  std::uint64_t piecePairKey(int i, int pi, int j, int pj) const {
    const std::uint64_t slot = std::uint64_t(i) * std::uint64_t(bodies.size()) + std::uint64_t(j);
    return (slot << 32) | std::uint64_t(std::uint32_t(pi) * std::uint32_t(bodies[j].pieces.size()) + std::uint32_t(pj));
  }
  /// True when the scene's resting contact is the hybrid model (contact_solver.hpp).
  bool hybrid() const { return scene.run.contact == ContactModel::Hybrid; }
  /// True when bodies fly in steps of their own (ownStepsOf, ownStepEnd).
  bool ownSteps() const { return ownStepsOf(scene); }
  /// True when struck bodies fly steps of StepTuning::struckStep (struckStepsOf).
  bool struckSteps() const { return struckStepsOf(scene); }
  /// True when §5 runs exactly as the paper wrote it (the world's or the scene's solver):
  /// none of this project's warm starts.
  bool paperSolver() const { return settings.solver == ToiSolverMode::Paper || scene.run.solver == ToiSolverMode::Paper; }
  /// True when queries may start from where the same piece pair's last one ended (§2.2):
  /// the world's warm starts on and the solver not the paper's.
  bool warmStarts() const { return settings.warmStarts && !paperSolver(); }
  /// Records a trace event when tracing.
  void record(TraceEvent::Kind kind, int body, int other, double from, double to) {
    if (settings.trace) trace.push_back({kind, body, other, from, to});
  }
  /// True once a part of the step found that the frame must be run again (a spin overflow):
  /// every ordering returns at once.
  bool abandoned() const { return frame.spinOverflow.happened; }
};

/// Adds the wall time of a scope to one part of the frame's split (Fig. 6).
class PartTimer {
 public:
  /// Starts timing into `part`.
  explicit PartTimer(double& part) : part_(part), start_(std::chrono::steady_clock::now()) {}
  /// Adds the time since construction.
  ~PartTimer() { part_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count(); }
  PartTimer(const PartTimer&) = delete;
  PartTimer& operator=(const PartTimer&) = delete;

 private:
  double& part_;
  std::chrono::steady_clock::time_point start_;
};

/// A state whose rotation is made orthonormal again: a body flown from state to state
/// thousands of times (fixed steps) would otherwise gather round-off in its rotation.
BodyState renormalized(BodyState state);

/// Flies body `b` from its state at `t0` to `t1` (free flight, dynamics' freeFlight),
/// cutting its frame path at t0 (a rollback) and bumping its version. A path that would
/// turn half a turn or more is not set: the frame is marked for a rerun
/// (FrameState::spinOverflow) and false returned. Throws std::runtime_error when the
/// integrator runs out of steps.
bool fly(StepContext& step, int b, double t0, double t1);
/// Flies `b` from `state` at t0 to t1 (see fly); its path is cut at t0.
bool flyFrom(StepContext& step, int b, const BodyState& state, double t0, double t1);
/// Remembers that pieces pi of body i and pj of body j came within the tolerance this
/// frame (response.hpp's instant pass looks at them again). Kept for the moving body or
/// bodies only: the pass never starts from a static one (the plant would gather every contact).
void touched(StepContext& step, int i, int pi, int j, int pj);
/// Where a path of the body in `state` that starts at t0 ends, towards t1: t1, or under
/// own steps (StepContext::ownSteps) an eighth of a turn at the body's angular speed
/// if that comes sooner (never shorter than StepTuning::minPath). A path holds less than
/// half a turn (motion.hpp): a body spinning faster than its interval allows (one the world
/// did not cut the frame for, or one a collision spun up) flies on in steps of its own
/// rather than making the frame run again in shorter intervals.
double ownStepEnd(const StepContext& step, const BodyState& state, double t0, double t1);
/// Flies body b on from its state at t0 in a path that ends at ownStepEnd towards t1 (see
/// fly); false on a spin overflow.
bool flyOwnStep(StepContext& step, int b, double t0, double t1);
/// The end of body b's current path that a check may use, at most t1 (a static body: t1).
double pathEnd(const StepContext& step, int b, double t1);
/// Flies every moving body from t0 to t1, or to its own step's end (ownStepEnd); those
/// already flown from t0 past t1 keep their path. False on a spin overflow.
bool flyAll(StepContext& step, double t0, double t1);

}  // namespace gjkx
