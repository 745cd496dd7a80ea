/// @file
/// @brief How a world is run (§5–§6): the solver's switches and every tunable of a step, each
/// with its unit and the reason for its default, checked by name where it enters.
///
/// A scene (scene.hpp) says what is simulated: bodies, gravity, e, μ, the collision
/// tolerance, and the frame rate. These settings say how: which extrusion test, which warm
/// starts, whether the independent checks run, and the constants of the step. Most of those
/// constants are multiples of the scene's collision tolerance `tol` (§2.3: bodies closer
/// than `tol` touch), so a scene at another scale keeps the same behaviour.
#pragma once

#include <gjkx/brent/toi_result.hpp>
#include <gjkx/dynamics/impulse.hpp>
#include <gjkx/extrusion/extrusion.hpp>
#include <gjkx/mesh/convex_decomposition.hpp>

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace gjkx {

/// The constants of a step. The defaults are those every measurement in docs 07 and 08 was
/// made with; each says why it is what it is.
struct StepTuning {
  // --- The collision tolerance band (multiples of the scene's tolerance `tol`) ---

  /// The contact patch: the points of each touching piece within this many `tol` of its
  /// supporting plane (contact.hpp). 2: a box lying flat within the band touches with its
  /// face; tilted by more than two tolerances across it, with its lowest edge or corner.
  double patchDepth = 2;
  /// A time-of-impact restart that finds the pieces within this many `tol`, once the query
  /// has taken `acceptedAfter` Brent iterations, is a hit (`ToiSettings::acceptedDistance`):
  /// a grazing pass just above the tolerance ends there rather than being proven free of
  /// contact link by link. 1.5: a contact found within 1.5 tolerances is as good to the
  /// impulse as one found at exactly one (docs 08 measures the trade against penetration).
  double acceptedBand = 1.5;
  /// Brent iterations after which the accepted band applies (`ToiSettings::acceptedAfter`).
  /// 24: short queries end as §5 ends them; from the 24th iteration on, the torso's deepest
  /// penetration grew least (0.56 mm against 1.36 mm from the 16th).
  int acceptedAfter = 24;
  /// The time tolerance of a query is the time the pair needs to close this many `tol` at
  /// its fastest (at most a quarter of the interval). 0.5: the time of impact is needed to
  /// within the band, not to sqrt(eps) of the interval.
  double closingBand = 0.5;
  /// Closest points nearer than this many `tol` (or pieces overlapping) give no reliable
  /// normal: their direction is round-off, and the pair's last reliable normal is used
  /// instead (contact.hpp). 1e-2: a hundredth of the band is far above double's round-off
  /// and far below any distance the solver reports a hit at.
  double reliableNormal = 1e-2;
  /// Settling (sleep.hpp): a body is slow when its kinetic energy could not lift its centre
  /// of mass by this many `tol` against gravity (E_k < m |g| tol × settleEnergy). 1: such a
  /// body only rattles inside the band.
  double settleEnergy = 1;

  // --- Speeds and times ---

  /// Two bodies whose normal speed at the contact is above -approachSpeed (m/s) are at rest
  /// against each other, not approaching. 1e-9: two bodies at rest approach by round-off
  /// (4e-16 m/s), which no impulse can change.
  double approachSpeed = 1e-9;
  /// A contact that is leaving is looked at again once it can have left the band, but at
  /// least this fraction of a frame later (so a frame holds at most 1/x looks). 1e-4.
  double minLookAhead = 1e-4;
  /// ... and at most this fraction of a frame later. 1/16: a slow leave is looked at again
  /// within the frame, in case gravity turns it round.
  double maxLookAhead = 1.0 / 16;
  /// The time a look-ahead skips is checked with half the distance the pair has when it
  /// leaves, if that distance is more than this fraction of the query's band (nearer, a
  /// resting pair, it moves on unchecked: narrow_phase.cpp). 0.25.
  double windowBand = 0.25;
  /// A path shorter than this fraction of a frame is not kept (it may not exist in float):
  /// the body flies on from the time of impact for that long. 1e-3.
  double minPath = 1e-3;
  /// A body must stay slow for this long (simulated seconds) before it may settle. 0.5: a
  /// domino just starting to topple is slow too, and is fast by then.
  double settleSeconds = 0.5;

  // --- Zeno's wedge and the instant pass (response.hpp) ---

  /// A body struck by more than this many microcollisions in a frame along normals more than
  /// a right angle apart is caught (stopped where it stands). 32: a box sliding on a floor is
  /// struck along one normal only, a rib wedged between a stem and a leaf along two.
  int caughtAfter = 32;
  /// A body in more than this many collisions at the very same instant is caught. 8: a light
  /// rod on two corners alternates between them at one instant (2,600 times for a cartilage).
  int sameInstantAfter = 8;
  /// An instant pass ends after this many impulses, leaving what still closes to the pair
  /// checks. 256: well above the torso's longest chain at its crash.
  int instantImpulses = 256;

  // --- Resting contact in the hybrid model (contact_solver.hpp) ---

  /// Pieces within this many `tol` at an interval's start, not closing faster than the
  /// contact speed, are a contact. 2: the band of the patch (patchDepth), so a body the
  /// solver holds at restSeparation stays a contact.
  double contactBand = 2;
  /// Where the solver brings a contact to rest: this many `tol` apart. 0.5: inside the band
  /// (touching, §2.3), yet apart, so the independent checks see no overlap.
  double restSeparation = 0.5;
  /// The contact speed, in intervals of gravity: a pair closing faster than this × |g| Δt
  /// is a collision (an event, with restitution). 2: gravity alone closes a resting pair by
  /// |g| Δt over an interval; twice that is what only an impact gives.
  double contactSpeed = 2;
  /// Sweeps of sequential impulses in each of the three passes of a group's velocity solve,
  /// at most (a pass stops once no impulse changes a velocity by more than
  /// contactSettled). 512: a stack of ten boxes placed touching, cold, needs about 400 in its
  /// first pass; warm-started, hundreds per interval are still common (Gauss–Seidel shares a
  /// box's weight between its corners slowly).
  int contactIterations = 512;
  /// When a pass of the velocity solve has converged: no impulse of a sweep changed the
  /// velocity at its point by more than this fraction of restSeparation per interval. 0.1:
  /// a tenth of the rest separation is what such a change moves the point over the
  /// interval, far below the band; the stacks' and inclines' tests hold as with a hundredth,
  /// and the torso's crash frames, thousands of points on light bones, take fewer sweeps.
  double contactSettled = 0.1;
  /// A contact pair is still checked by the extrusion test, with this band (in `tol`): a
  /// collision only where the solver's path brings it nearer than that. 0.25: half the rest
  /// separation, which the solver's paths keep (a rotating body's corners follow arcs the
  /// solver's velocities at t0 do not see; the check catches what they miss).
  double contactCheckBand = 0.25;
  /// Under the hybrid and gravity, a frame of Timewarp or the heap is run in at least this
  /// many intervals, each starting with a contact solve: a pair that lands fast inside an
  /// interval is a collision, and what it strikes is held by the solver only from the next
  /// interval on (a slow landing is left to that solve: narrow_phase.hpp). 4: on the torso,
  /// half the collisions and 60% of the wall time of one interval per frame; with landings,
  /// 2 made the torso's crash frames slower (seeds 1 to 4), 8 its whole runs slower.
  int contactIntervals = 4;
  /// Under Timewarp with microcollisions, a frame is cut into intervals of an eighth of a
  /// turn of its fastest body among those that spin at most this many eighths of a turn a
  /// frame; a body spinning faster flies in steps of its own (world.cpp, ownStepEnd). 8 (one
  /// turn a frame, 150.8 rad/s at 24 frames a second): on the torso dropped in eight poses,
  /// microcollisions took 28 to 39% less processor time (two passes) than with every body
  /// cutting the frame (up to 47 intervals), and frames slower than three times real time
  /// went from 135-156 to 21-24 of 576; 16 and 32 took 30% and 21% less; the paper's
  /// Brent's method takes more iterations in longer intervals (docs 08).
  int spinIntervals = 8;
  /// Under the hybrid, a body struck by a collision flies on in a step of at most this much
  /// of a frame (timewarp.hpp's own steps), its pairs checked again over that step only;
  /// where the step ends it flies on. A body struck within the last interval starts the
  /// next one in such a step too (flyAll). 1/16: in a pile a struck body is struck again long
  /// before its interval ends, and checking its pairs over the whole rest of the interval
  /// was wasted beyond the next collision (and their swept bounds took in more pieces). On
  /// the torso a sixteenth took the run from 1.7 to 0.7 times real time, an eighth and a
  /// thirty-second between the two (one run each, gjkx_frame_ratios).
  double struckStep = 1.0 / 16;
  /// Passes of the position projection, at most (it stops when a pass pushes nothing). 32:
  /// a stack of ten boxes placed touching is lifted apart in a dozen.
  int positionIterations = 32;
  /// Sweeps of each level of a group's shock propagation, at most (contact_solver.cpp: after
  /// the velocity solve's passes, each level of a pile is solved on the one below, held).
  /// 4: a box on two others settles on them in one or two; on the 20-row pyramid kept awake
  /// 1 left it rocking, 2 held it, and 32 did no better than 4.
  int shockSweeps = 4;
  /// A manifold point takes the impulses of the last solve's point whose anchor in either
  /// body is within this many `tol` (warm start). 10.
  double contactMatch = 10;

  // --- Caps ---

  /// A frame's events are capped at eventCap + eventCapPerBody × bodies; past it the frame
  /// ends with the status EventCap (its remaining events dropped, counted in frames.csv).
  /// 200,000 + 1,000 per body: ten times the torso's busiest frame.
  long eventCap = 200000;
  /// See eventCap.
  long eventCapPerBody = 1000;
  /// A frame is run in intervals of at most an eighth of a turn of its fastest body; at the
  /// start of a frame at most this many (more come only from a spin overflow). 64.
  int maxIntervals = 64;
  /// A frame that would need more intervals than this for a body's spin stops the run with
  /// an error naming the body (raise the scene's frame rate). 4096.
  int maxSpinIntervals = 4096;

  /// Throws std::invalid_argument naming `field`.member for a value out of its range.
  void validate(const std::string& field) const;
};

/// The names of StepTuning's fields, in the order the struct declares them: what
/// `setTuning` accepts (gjkx_simulate's --tuning).
std::vector<std::string> tuningNames();

/// Sets the field `name` of `tuning` (its name in the struct, e.g. "contactSettled") from
/// the text `value`, so that what a constant buys can be measured on a scene without a
/// rebuild (gjkx_simulate --tuning contactSettled=0.25). Throws std::invalid_argument naming
/// "tuning.<name>" for an unknown name (the message lists the known ones), or for a value
/// that is not a number of the field's type (a whole number for a count) in full; whether
/// the number is in the field's range is StepTuning::validate's to say, when the world is
/// built.
void setTuning(StepTuning& tuning, const std::string& name, const std::string& value);

/// How a world is run: the solver's switches and the step's tunables (what a scene *is*
/// stays in scene.hpp).
struct WorldSettings {
  /// The time-of-impact solver: §5 exactly as the paper wrote it (`ToiSettings::paper()`:
  /// the paper's extrusion test whatever `variant` says, no warm starts, no coherence, no
  /// accepted band, no refinement of Brent's bracket) or this project's (the default,
  /// `ToiSettings::gjkx()`, with `variant`, `warmStarts`, `coherence` and the tuning's
  /// accepted band).
  ToiSolverMode solver = ToiSolverMode::Gjkx;
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
  /// Run the independent checks at each frame's end (gjkx/verify: penetration, tunnelling
  /// by dense sampling). Off by default: they are not part of the method, and on the torso
  /// they cost more than the method itself (docs 08).
  bool checks = false;
  /// Record what the orderings did, event by event (chapter 07 draws it).
  bool trace = false;
  /// The impulse integration's tolerances and step cap (gjkx/dynamics/impulse.hpp, §6); its
  /// microcollision speed is not taken from here but from the scene (its gravity and
  /// collision tolerance). Checked when the world is built ("settings.impulse...").
  ImpulseSettings impulse;
  /// The constants of a step ("settings.tuning...").
  StepTuning tuning;
  /// The folder of the mesh decomposition cache; unset: the default
  /// (gjkx::defaultDecompositionCacheDir()), empty: no cache.
  std::optional<std::string> meshCache;
  /// Seconds every mesh's decomposition may take, over each mesh's own `decomposition.budget_s`
  /// (gjkx_simulate's --decompose-budget); 0: each mesh's own (gjkx::MeshBuildOptions).
  double decompositionBudget = 0;
  /// Called about ten times a second while a mesh is decomposed, with its file (gjkx_simulate's
  /// progress bar); unset: nothing.
  std::function<void(const std::string& mesh, const DecompositionProgress& progress)> decompositionProgress;

  /// Throws std::invalid_argument naming `field`.member for a value out of its range.
  void validate(const std::string& field) const;
};

}  // namespace gjkx
