/// @file
/// @brief The scene file: a JSON description of a simulation that anyone can write (§6).
///
/// A scene gives the world's settings (gravity, frame rate, duration, the collision
/// tolerance of §2.3, the restitution and friction of the collision response, the scalar
/// type of collision detection and the ordering of collisions) and its bodies. The keys, in
/// the file as in docs/07_timewarp.md:
///
/// ```json
/// { "gravity": [0, 0, -9.81], "frame_rate": 24, "duration": 2.0,
///   "collision_tolerance": 0.000345, "restitution": 0.7, "friction": 0.4,
///   "scalar": "float", "ordering": "timewarp",
///   "bodies": [
///     { "name": "floor", "shape": {"box": [5, 5, 0.5]}, "position": [0, 0, -0.5], "static": true },
///     { "name": "ball", "shape": {"sphere": 0.1}, "position": [0, 0, 1],
///       "orientation": [1, 0, 0, 0], "velocity": [0, 0, 0], "angular_velocity": [0, 0, 0],
///       "density": 1000 } ] }
/// ```
///
/// Every key but `duration`, `bodies` and a body's `name`, `shape` and `position` has a
/// default (those of the paper's experiment where it has one: e = 0.7, mu = 0.4, float,
/// tolerance sqrt(eps) of float). The optional `fixed_substeps` sets the steps per frame of
/// the `fixed_step` ordering, and `contact` the model of resting contact (`"hybrid"`, the
/// default, or the paper's `"microcollisions"`). A shape is one of `{"box": [hx, hy, hz]}` (half extents),
/// `{"sphere": r}`, `{"capsule": [r, half_length]}` (axis along the body's z),
/// `{"cylinder": [r, half_length]}` (axis along the body's z, flat caps at ±half_length),
/// `{"polytope": [[x, y, z], ...]}` (the convex hull of the points, in the body's frame),
/// `{"mesh": "path"}` (or `{"mesh": "path", "scale": s, "collision": "decompose" | "hull",
/// "decomposition": {"budget_s": 30, ...}}`). Bad input is rejected where it enters, with a message that names
/// the body and the field: a missing field, an unknown key, a wrong type, NaN or
/// infinity, a negative radius or extent, a zero quaternion.
#pragma once

#include <gjkx/brent/toi_result.hpp>
#include <gjkx/mesh/convex_decomposition.hpp>
#include <gjkx/motion/vector.hpp>

#include <Eigen/Geometry>

#include <string>
#include <vector>

namespace gjkx {

/// How the world orders collisions (issue of the Timewarp stage; §5-§6).
enum class Ordering {
  Timewarp,   ///< Mirtich's Timewarp: bodies advance on their own, a late-found collision rolls back only its bodies
  ToiHeap,    ///< a global time-of-impact heap: every body is advanced to the earliest impact
  FixedStep,  ///< fixed steps with discrete (static) tests at the end of each step
};

/// The scalar type collision detection runs in (the paper: 4-byte float).
enum class CollisionScalar {
  Float,   ///< float, as the paper
  Double,  ///< double
};

/// The name of an ordering as the scene file writes it.
const char* orderingName(Ordering ordering);

/// How bodies at rest against each other are modelled (the scene file's `contact`; §6's
/// "future work", docs 07 *Resting contact*).
enum class ContactModel {
  /// The paper's model: every contact is a train of microcollisions, each an event of the
  /// ordering resolved by Mirtich's impulse.
  Microcollisions,
  /// Collisions stay events, but pairs resting within the tolerance band are contacts: their
  /// bodies form contact groups advanced by a velocity-level contact solver (contact_solver.hpp).
  Hybrid,
};

/// The name of a contact model as the scene file writes it.
const char* contactModelName(ContactModel model);

/// A body's shape as the scene file gives it, in the body's frame.
struct ShapeSpec {
  /// Which shape.
  enum class Kind {
    Box,       ///< `{"box": [hx, hy, hz]}`
    Sphere,    ///< `{"sphere": r}`
    Capsule,   ///< `{"capsule": [r, half_length]}`, axis along z
    Cylinder,  ///< `{"cylinder": [r, half_length]}`, axis along z
    Polytope,  ///< `{"polytope": [[x, y, z], ...]}`
    Mesh,      ///< `{"mesh": "path"}`
  };
  /// Which shape.
  Kind kind = Kind::Sphere;
  /// Half extents of a box.
  Eigen::Vector3d halfExtents = Eigen::Vector3d::Zero();
  /// Radius of a sphere, capsule or cylinder.
  double radius = 0;
  /// Half the length of a capsule's or a cylinder's axis.
  double halfLength = 0;
  /// The points of a polytope.
  std::vector<Eigen::Vector3d> points;
  /// The path of a mesh, relative to the scene file's folder unless absolute.
  std::string meshPath;
  /// A mesh's scale (`"scale"`: a number, or one per axis), applied to its vertices after
  /// the file's own node transforms; the scene's units stay metres.
  Eigen::Vector3d meshScale = Eigen::Vector3d::Ones();
  /// How a mesh collides (`"collision"`).
  enum class MeshCollision {
    Decompose,  ///< `"decompose"` (the default): convex pieces by HACD; a moving mesh must be closed
    Hull,       ///< `"hull"`: its convex hull, one piece; any mesh, open or closed, or a point cloud
  };
  /// How a mesh collides.
  MeshCollision meshCollision = MeshCollision::Decompose;
  /// How a moving mesh is decomposed (`"decomposition"`: `budget_s`, `concavity`,
  /// `min_pieces`, `compacity_weight`, `volume_weight`, `extra_points`, `face_points`; HACD's
  /// defaults and a budget of 30 s where it gives none).
  DecompositionSettings decomposition;
};

/// One body of a scene.
struct BodySpec {
  /// Its name (unique in the scene).
  std::string name;
  /// Its shape.
  ShapeSpec shape;
  /// Where the origin of its shape's frame is in the world at time 0.
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  /// Its orientation at time 0 (`[w, x, y, z]` in the file, normalised on entry).
  Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();
  /// Velocity of the centre of mass at time 0.
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();
  /// Angular velocity at time 0, world frame, radians per second.
  Eigen::Vector3d angularVelocity = Eigen::Vector3d::Zero();
  /// Density (mass per unit volume).
  double density = 1000;
  /// Its mass, if the file gives `mass` instead of `density` (exactly one of the two; the
  /// density is then mass / volume). 0: the density is used.
  double mass = 0;
  /// Its coefficient of restitution (`restitution`; -1: the scene's). A pair's is the larger
  /// of its two bodies' (materialOf).
  double restitution = -1;
  /// Its coefficient of friction (`friction`; -1: the scene's). A pair's is the geometric
  /// mean of its two bodies' (materialOf).
  double friction = -1;
  /// A static body never moves and is never integrated.
  bool isStatic = false;
};

/// How a scene asks to be run (the file's keys `scalar`, `ordering`, `fixed_substeps`, `contact` and `solver`),
/// kept apart from what the scene is; gjkx_simulate's options override them, and the
/// world's own settings (settings.hpp) say the rest.
struct SceneRun {
  /// The scalar type of collision detection.
  CollisionScalar scalar = CollisionScalar::Float;
  /// How collisions are ordered.
  Ordering ordering = Ordering::Timewarp;
  /// Steps per frame of the fixed-step ordering.
  int fixedSubsteps = 8;
  /// How resting contact is modelled (the key `contact`; the hybrid when it is absent).
  ContactModel contact = ContactModel::Hybrid;
  /// The time-of-impact solver (the key `solver`: `"gjkx"`, this project's, when it is absent,
  /// or `"paper"`, §5 exactly as the paper wrote it, `ToiSettings::paper()`); a world runs the
  /// paper's when its scene or its settings (`WorldSettings::solver`) ask for it.
  ToiSolverMode solver = ToiSolverMode::Gjkx;
};

/// A whole scene: what is simulated (its world's constants and its bodies), and how it asks to be run.
struct Scene {
  /// Gravity, world units per second squared.
  Eigen::Vector3d gravity = Eigen::Vector3d(0, 0, -9.81);
  /// Frames per second (the paper: 24).
  double frameRate = 24;
  /// Simulated seconds.
  double duration = 1;
  /// Bodies closer than this collide (§2.3; the paper: sqrt of float's epsilon).
  double collisionTolerance = 3.4526698e-4;
  /// Coefficient of restitution e (the paper: 0.7).
  double restitution = 0.7;
  /// Coefficient of dynamic friction mu (the paper: 0.4).
  double friction = 0.4;
  /// How it is run (the keys `scalar`, `ordering`, `fixed_substeps`).
  SceneRun run;
  /// The bodies.
  std::vector<BodySpec> bodies;
  /// The folder mesh paths are relative to.
  std::string folder = ".";
  /// Where the scene was read from (the file's path, or parseScene's `source`): every
  /// error found after parsing names it too.
  std::string source = "scene";
};

/// The restitution and friction of a collision between bodies a and b: each body's own, or
/// the scene's where it gives none; the pair's restitution is the larger of the two, its
/// friction the geometric mean, sqrt(mu_a mu_b) (Box2D's and Jolt's mixing rules: a bouncy
/// ball bounces off anything, and a frictionless body slides on anything). A body that
/// must bounce less than the scene's default needs the floor's restitution lowered too.
std::pair<double, double> materialOf(const Scene& scene, const BodySpec& a, const BodySpec& b);

/// The frames of the scene's duration (at least one). Throws std::invalid_argument naming
/// the scene and the field when duration × frame_rate is more than 10^8 frames (a count
/// that would not fit, or a run of years).
int frameCount(const Scene& scene);

/// Parses a scene from JSON text; `source` names it in messages. Throws
/// std::invalid_argument naming the body and the field on bad input.
Scene parseScene(const std::string& text, const std::string& source = "scene");

/// Reads and parses a scene file (see parseScene); a file that cannot be read is an error naming it.
Scene loadScene(const std::string& path);

}  // namespace gjkx
