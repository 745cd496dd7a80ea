/// @file
/// @brief The bodies of a world, built from a scene (§6): each a set of convex pieces about its
/// centre of mass, its mass properties and its path.
///
/// Every body is a set of convex pieces (§6): a convex body is one piece, a mesh body the
/// pieces of its convex decomposition (gjkx/mesh), a static mesh one thin prism per
/// triangle ("collision detection at the polygonal level"). The body frame is put at the
/// centre of mass, since free flight turns a body about it. The pieces are kept here in
/// double, what the contact data, the mass and the independent checks need; the narrow
/// phase (narrow_phase.hpp) makes them again in the scalar of collision detection from the
/// points kept beside them (`PieceSource`), so a float scene's float hulls are the hulls of
/// the rounded points, not rounded hulls.
///
/// buildBodies is the one way a runner gets bodies from a scene: the world calls it, and so
/// does the Bullet runner of chapter 08, which gives Bullet the same masses and shapes.
#pragma once

#include <gjkx/dynamics/free_flight.hpp>
#include <gjkx/dynamics/rigid_body.hpp>
#include <gjkx/dynamics/swept_bounds.hpp>
#include <gjkx/mesh/convex_decomposition.hpp>
#include <gjkx/motion/motion.hpp>
#include <gjkx/support_mapping/shape.hpp>
#include <gjkx/timewarp/scene.hpp>
#include <gjkx/verify/frame_verifier.hpp>

#include <functional>
#include <limits>
#include <string>
#include <vector>

namespace gjkx {

/// What a body's convex pieces are made from, in the body frame (centre of mass at the
/// origin), so that they can be made in either scalar type.
struct PieceSource {
  /// A convex body: its spec, a polytope's points moved to the body frame.
  ShapeSpec convex;
  /// A mesh body: each piece's points (the hull of each is the piece). Empty for a convex body.
  std::vector<std::vector<Eigen::Vector3d>> meshPieces;
  /// True if each mesh piece is a triangle and its copy moved off its plane (a static mesh
  /// met at the polygonal level): its hull is known (Polytope::prism), no Qhull call.
  bool meshPrisms = false;
  /// True for a mesh body (its pieces are held in a 14-DOP hierarchy by the narrow phase).
  bool isMesh() const { return !meshPieces.empty(); }
};

/// A convex shape of a scene in scalar type S, at the given points (a polytope's, already in
/// the body frame; ignored for the other shapes). Throws std::invalid_argument for a mesh.
template <typename S>
Shape<S> convexShapeOf(const ShapeSpec& spec, const std::vector<Eigen::Vector3d>& points);

/// A body's convex pieces in scalar type S (PieceSource).
template <typename S>
std::vector<Shape<S>> piecesOf(const PieceSource& source);

/// A body of the world: its shape about its centre of mass, its mass, its path.
struct WorldBody {
  std::string name;                           ///< its name in the scene
  Shape<double> shape = Sphere<double>(0);    ///< its shape (a mesh body: the hull of its pieces), body frame at the centre of mass
  std::vector<Shape<double>> pieces;          ///< its convex pieces (a convex body: `shape` alone)
  PieceSource source;                         ///< what the pieces are made from (for the other scalar)
  Eigen::Vector3d frameOrigin = Eigen::Vector3d::Zero();  ///< the scene's shape frame origin, in the body frame (minus the centre of mass)
  RigidBody rigid = RigidBody::fixed();       ///< mass properties (or static)
  double radius = 0;                          ///< bounding radius about the centre of mass
  FreeFlight path;                            ///< its path from its last event to its local time `path.t1` (set it with setPath)
  int version = 0;                            ///< bumped when its path changes: events that used the old one are stale
  /// Counts every path it is given (setPath), never reset: what a cache of the path keys on.
  long pathSerial = 0;
  /// Where the support climbs of its last swept bounds ended (broad_phase.hpp): its next
  /// box starts there. A cache for speed; the boxes are the same without it.
  mutable SweepHints boundsHints{};
  /// Caught at rest against a static body (response.hpp), or settled at a frame's end
  /// with too little kinetic energy to leave the tolerance band (sleep.hpp), and not
  /// struck since: it is held where it stands, gravity off, and its pairs with static and
  /// sleeping bodies are not looked at, until a collision with a moving body wakes it.
  bool asleep = false;
  /// How long (simulated s) it has been too slow to leave the tolerance band and struck by
  /// nothing but resting or slow bodies (sleep.hpp); it settles after StepTuning::settleSeconds.
  double slowFor = 0;
  /// Its path over the current interval is the contact solver's (the hybrid model,
  /// contact_solver.hpp): gravity's impulse is already in its velocity, and it flies with
  /// gravity off to the interval's end, after a collision too.
  bool contactFlight = false;
  /// When an impulse last struck it (simulated s; -inf: never). Under the hybrid a body
  /// struck within the last interval starts the next one in a struck body's step (flyAll).
  double lastStruck = -std::numeric_limits<double>::infinity();
  /// The contact group it fell asleep with (the hybrid model; -1: none): the group wakes as one.
  int sleepGroup = -1;
  /// The gravity its path feels: none while it sleeps, or flies on the contact solver's path.
  Eigen::Vector3d gravity(const Eigen::Vector3d& sceneGravity) const {
    return asleep || contactFlight ? Eigen::Vector3d::Zero() : sceneGravity;
  }
  /// A body that cannot move of its own accord: static, or asleep.
  bool resting() const { return asleep || rigid.isStatic(); }
  /// Sets its path.
  void setPath(FreeFlight next) {
    path = std::move(next);
    ++pathSerial;
  }
};

/// What buildBodies does with a mesh to decompose beyond what the scene says: where the
/// decompositions are cached, a budget over the scene's, and what the terminal is told.
struct MeshBuildOptions {
  /// The decomposition cache's folder (empty: no cache; gjkx/mesh/convex_decomposition.hpp).
  std::string cache = defaultDecompositionCacheDir();
  /// Seconds every decomposition may take, over each mesh's own (its scene key
  /// `decomposition.budget_s`; gjkx_simulate's --decompose-budget); 0: each mesh's own.
  double budgetSeconds = 0;
  /// Called about ten times a second while a mesh is decomposed, with the mesh's file (a
  /// progress bar); unset: nothing.
  std::function<void(const std::string& mesh, const DecompositionProgress&)> progress;
  /// Where the report of each decomposed mesh goes, once per mesh: its line (gjkx::describe:
  /// pieces, vertices per piece, volume excess, time or "cached") and its numbers; unset:
  /// the line on standard error.
  std::function<void(const std::string& line, const DecompositionReport& report)> report;
};

/// The bodies of `scene`: each shape read (a mesh through Assimp, decomposed once however
/// many bodies use it), its mass properties, its frame moved to the centre of mass, and its
/// start state flown for no time (a static body: over the whole `duration`, since it is
/// never integrated again). A moving mesh to decompose is decomposed with its scene's
/// settings (ShapeSpec::decomposition) within its budget (else its hull, said on standard
/// error) and reported once (MeshBuildOptions). Throws std::invalid_argument naming the
/// scene's file, the body and the field.
std::vector<WorldBody> buildBodies(const Scene& scene, double duration, const MeshBuildOptions& meshes);

/// buildBodies with the decompositions cached in `meshCache` (empty: no cache) and reported
/// on standard error.
std::vector<WorldBody> buildBodies(const Scene& scene, double duration,
                                   const std::string& meshCache = defaultDecompositionCacheDir());

/// The bodies as the independent checks see them (gjkx/verify): names, pieces, hulls.
std::vector<VerifiedBody> verifiedBodies(const std::vector<WorldBody>& bodies);

}  // namespace gjkx
