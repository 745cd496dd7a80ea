// The world and its three orderings (world.hpp). Read runTimewarp first: it is the
// paper's ordering; runToiHeap and runFixedStep are what it is compared with.
#include <gjkx/timewarp/world.hpp>

#include <gjkx/dynamics/mass_properties.hpp>
#include <gjkx/gjk/gjk.hpp>
#include <gjkx/mesh/convex_decomposition.hpp>
#include <gjkx/mesh/triangle_mesh.hpp>
#include <gjkx/timewarp/checks.hpp>
#include <gjkx/timewarp/contact.hpp>
#include <gjkx/timewarp/motion_cast.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <deque>
#include <optional>
#include <queue>
#include <tuple>
#include <stdexcept>

namespace gjkx {

// ---------------------------------------------------------------------------------------
// What a frame keeps while it runs

/// A collision found by a pair check: when, between which bodies, and the contact data.
/// The versions say which paths it was computed on: once a body's path changes, the
/// event is stale (Timewarp's "events that used them after t_c").
struct World::Hit {
  double time = 0;
  int i = -1, j = -1;
  int pieceI = 0, pieceJ = 0;  // the convex pieces that touch
  int versionI = 0, versionJ = 0;
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();  // unit, from i towards j
  Eigen::Vector3d pointI = Eigen::Vector3d::Zero(), pointJ = Eigen::Vector3d::Zero();
  Eigen::Vector3d contact = Eigen::Vector3d::Zero();  // where the impulse acts (contact.hpp)
  /// The queue pops the earliest first; ties by the pair, so every run takes the same order.
  bool operator>(const Hit& o) const { return std::tie(time, i, j) > std::tie(o.time, o.i, o.j); }
};

/// A piece of a body's path within the frame: `path` flown from path.t0, used until `end`.
struct Piece {
  FreeFlight path;
  double end;
};

struct World::FrameState {
  FrameReport report;
  std::vector<std::vector<Piece>> pieces;           // per body, the paths of this frame in order
  std::vector<std::pair<int, int>> collidedPairs;   // pairs with a collision reported this frame
  std::vector<Bounds> boxes;                         // Timewarp: each body's swept bounds to the frame's end
  /// How a body was struck this frame (resolve: Zeno's wedge).
  struct Struck {
    int microcollisions = 0;              // its microcollisions
    std::vector<Eigen::Vector3d> sides;   // the outward normals it was struck along (up to 8, apart)
    double lastTime = -1;                 // the time of its last collision
    int atLastTime = 0;                   // its collisions at that very time
    std::vector<int> by;                  // the bodies that struck it (each once)
  };
  std::vector<Struck> struck;                        // per body
  /// Two bodies' pieces that came within the tolerance this frame (resolve's instant pass).
  struct Touching {
    int i, pi, j, pj;
    bool operator==(const Touching& o) const { return i == o.i && pi == o.pi && j == o.j && pj == o.pj; }
  };
  std::vector<std::vector<Touching>> touching;       // per body, the pairs it is in
};

namespace {

using Clock = std::chrono::steady_clock;

/// Adds the wall time of a scope to one part of the frame's split (Fig. 6).
class PartTimer {
 public:
  explicit PartTimer(double& part) : part_(part), start_(Clock::now()) {}
  ~PartTimer() { part_ += std::chrono::duration<double>(Clock::now() - start_).count(); }
  PartTimer(const PartTimer&) = delete;
  PartTimer& operator=(const PartTimer&) = delete;

 private:
  double& part_;
  Clock::time_point start_;
};

/// The shape of a body spec, in its scene frame (before moving the origin to the centre of mass).
Shape<double> shapeOf(const ShapeSpec& spec, const std::vector<Eigen::Vector3d>& shiftedPoints) {
  switch (spec.kind) {
    case ShapeSpec::Kind::Box: return Box<double>(spec.halfExtents);
    case ShapeSpec::Kind::Sphere: return Sphere<double>(spec.radius);
    case ShapeSpec::Kind::Capsule:
      return Capsule<double>(Eigen::Vector3d(0, 0, -spec.halfLength), Eigen::Vector3d(0, 0, spec.halfLength),
                             spec.radius);
    case ShapeSpec::Kind::Polytope: return Polytope<double>::hull(shiftedPoints);
    case ShapeSpec::Kind::Mesh: break;
  }
  throw std::invalid_argument("mesh shapes are not supported by this world yet");
}

Shape<float> floatShapeOf(const ShapeSpec& spec, const std::vector<Eigen::Vector3d>& shiftedPoints) {
  switch (spec.kind) {
    case ShapeSpec::Kind::Box: return Box<float>(spec.halfExtents.cast<float>());
    case ShapeSpec::Kind::Sphere: return Sphere<float>(float(spec.radius));
    case ShapeSpec::Kind::Capsule:
      return Capsule<float>(Eigen::Vector3f(0, 0, -float(spec.halfLength)), Eigen::Vector3f(0, 0, float(spec.halfLength)),
                            float(spec.radius));
    case ShapeSpec::Kind::Polytope: {
      std::vector<Eigen::Vector3f> points;
      for (const auto& p : shiftedPoints) points.push_back(p.cast<float>());
      return Polytope<float>::hull(points);
    }
    case ShapeSpec::Kind::Mesh: break;
  }
  throw std::invalid_argument("mesh shapes are not supported by this world yet");
}

/// Mirtich's microcollisions: a resting body is a train of tiny bounces. A contact that
/// approaches slower than a body gains falling through the collision tolerance band,
/// sqrt(2 |g| tol), bounces out of it at that speed (to a height of one tolerance), so it
/// neither sinks into the other body nor collides endlessly. Without gravity: none.
double microcollisionSpeed(double gravity, double tolerance) { return std::sqrt(2 * gravity * tolerance); }

/// A state whose rotation is made orthonormal again: a body flown from state to state
/// thousands of times (fixed steps) would otherwise gather round-off in its rotation.
BodyState renormalized(BodyState state) {
  state.worldFromBody.rotation = Eigen::Quaterniond(state.worldFromBody.rotation).normalized().toRotationMatrix();
  return state;
}

/// The unit direction from i's centre of mass to j's (up, +z, when they coincide): the
/// normal of a first contact whose closest points coincide.
Eigen::Vector3d centreToCentre(const BodyState& si, const BodyState& sj) {
  const Eigen::Vector3d d = sj.worldFromBody.translation - si.worldFromBody.translation;
  return d.norm() > 0 ? Eigen::Vector3d(d.normalized()) : Eigen::Vector3d::UnitZ();
}

/// Free flight over [t0, t1], refused with a clear message when the path cannot hold it:
/// a free-flight path turns along the shortest arc between its end orientations
/// (motion.hpp, FreeFlightPath), so a body turning half a turn or more within one step
/// would be drawn turning the other way.
/// A path that would turn half a turn or more (see flyChecked): the frame is run again in
/// shorter intervals (World::step).
struct SpinOverflow : std::runtime_error {
  SpinOverflow(const std::string& what, double angularSpeed) : std::runtime_error(what), angularSpeed(angularSpeed) {}
  double angularSpeed;  ///< the body's angular speed (rad/s)
};

FreeFlight flyChecked(const WorldBody& body, const BodyState& state, double t0, double t1, const Eigen::Vector3d& gravity) {
  FreeFlight path = freeFlight(body.rigid, state, t0, t1, gravity);
  if (std::holds_alternative<FreeFlightPath<double>>(path.motion.variant()) && path.turnedAngle >= 0.95 * M_PI)
    throw SpinOverflow("body '" + body.name + "' turns " + std::to_string(path.turnedAngle) + " rad within " +
                           std::to_string(t1 - t0) + " s (angular speed " +
                           std::to_string(state.angularVelocity.norm()) +
                           " rad/s): more than the half turn a path can hold",
                       state.angularVelocity.norm());
  if (path.status == FreeFlightStatus::StepCap)
    throw std::runtime_error("body '" + body.name + "': the free-flight integrator ran out of steps");
  return path;
}

/// A static mesh met at the polygonal level, as the paper's plant is ("collision detection at
/// the polygonal level", §6): one convex piece per triangle, a thin prism under it (the
/// triangle and its copy moved back along its normal by a thousandth of the mesh's size),
/// so that a hull of neighbouring pieces has volume. A static body needs no volume of its
/// own, and a decomposition into hulls fills the space between thin leaves (the plant's
/// hulls by HACD came to 9 times its volume), where bodies would bounce off empty air.
ConvexDecomposition polygonPieces(const TriangleMesh& mesh) {
  Eigen::Vector3d lo = mesh.vertices.front(), hi = lo;
  for (const auto& v : mesh.vertices) {
    lo = lo.cwiseMin(v);
    hi = hi.cwiseMax(v);
  }
  const double depth = 1e-3 * (hi - lo).norm();
  ConvexDecomposition out;
  for (const auto& t : mesh.triangles) {
    const Eigen::Vector3d &a = mesh.vertices[t[0]], &b = mesh.vertices[t[1]], &c = mesh.vertices[t[2]];
    const Eigen::Vector3d n = (b - a).cross(c - a);
    if (!(n.norm() > 0)) continue;  // no area: no piece
    const Eigen::Vector3d back = -depth * n.normalized();
    out.pieces.push_back({a, b, c, a + back, b + back, c + back});
  }
  return out;
}

std::string bodyField(const BodySpec& body, std::size_t index, const std::string& field) {
  return "body '" + body.name + "' (bodies[" + std::to_string(index) + "]): field '" + field + "'";
}

}  // namespace

// ---------------------------------------------------------------------------------------
// Building the world

World::World(const Scene& scene, const WorldSettings& settings) : scene_(scene), settings_(settings) {
  frameCount_ = std::max(1, int(std::ceil(scene.duration * scene.frameRate - 1e-9)));
  // The impulse integration's settings enter here, so a bad one is named before the run
  // rather than at its first collision.
  settings.impulse.validate("settings.impulse");
  impulse_ = settings.impulse;
  impulse_.microcollisionSpeed = microcollisionSpeed(scene.gravity.norm(), scene.collisionTolerance);
  // A mesh is read and decomposed once however many bodies use it (the decomposition is
  // also cached on disk, gjkx/mesh/convex_decomposition.hpp).
  std::map<std::string, std::pair<TriangleMesh, ConvexDecomposition>> meshes;
  for (std::size_t index = 0; index < scene.bodies.size(); ++index) {
    const BodySpec& spec = scene.bodies[index];
    WorldBody body;
    body.name = spec.name;
    // The body frame is put at the centre of mass: free flight turns a body about it.
    Eigen::Vector3d centerOfMass = Eigen::Vector3d::Zero();
    MassProperties mass{};
    if (spec.shape.kind == ShapeSpec::Kind::Mesh) {
      const std::string& given = spec.shape.meshPath;
      const std::string path = !given.empty() && given[0] == '/' ? given : scene.folder + "/" + given;
      try {
        auto found = meshes.find(path);
        if (found == meshes.end()) {
          TriangleMesh mesh = readMesh(path);
          ConvexDecomposition pieces =
              spec.isStatic ? polygonPieces(mesh) : decompose(mesh);
          found = meshes.emplace(path, std::make_pair(std::move(mesh), std::move(pieces))).first;
        }
        const TriangleMesh& mesh = found->second.first;
        if (!spec.isStatic) {  // a moving mesh needs a volume: it must be closed
          validateMesh(mesh, MeshRequirements{true});
          mass = polyhedronMassProperties(mesh.vertices, mesh.triangles, spec.density);
          centerOfMass = mass.centerOfMass;
          mass.centerOfMass = Eigen::Vector3d::Zero();
        }
        std::vector<Polytope<double>> pieces;
        std::vector<Polytope<float>> piecesFloat;
        std::vector<Eigen::Vector3d> all;
        for (const auto& piece : found->second.second.pieces) {
          std::vector<Eigen::Vector3d> points;
          std::vector<Eigen::Vector3f> pointsFloat;
          for (const auto& p : piece) {
            points.push_back(p - centerOfMass);
            pointsFloat.push_back((p - centerOfMass).cast<float>());
          }
          all.insert(all.end(), points.begin(), points.end());
          pieces.push_back(Polytope<double>::hull(points));
          piecesFloat.push_back(Polytope<float>::hull(pointsFloat));
        }
        for (const auto& piece : pieces) body.pieces.push_back(piece);
        for (const auto& piece : piecesFloat) body.piecesFloat.push_back(piece);
        body.bvh = std::make_shared<const Bvh<double>>(std::move(pieces));
        body.bvhFloat = std::make_shared<const Bvh<float>>(std::move(piecesFloat));
        body.shape = Polytope<double>::hull(all);
        std::vector<Eigen::Vector3f> allFloat;
        for (const auto& p : all) allFloat.push_back(p.cast<float>());
        body.shapeFloat = Polytope<float>::hull(allFloat);
      } catch (const std::exception& e) {
        throw std::invalid_argument(bodyField(spec, index, "shape.mesh") + ": " + e.what());
      }
    } else {
      std::vector<Eigen::Vector3d> points = spec.shape.points;
      try {
        const Shape<double> sceneShape = shapeOf(spec.shape, points);
        if (!spec.isStatic) {
          mass = massProperties(sceneShape, spec.density);
          centerOfMass = mass.centerOfMass;
          mass.centerOfMass = Eigen::Vector3d::Zero();
        }
      } catch (const std::invalid_argument& e) {
        throw std::invalid_argument(bodyField(spec, index, "shape") + ": " + e.what());
      }
      for (auto& p : points) p -= centerOfMass;
      body.shape = shapeOf(spec.shape, points);
      body.shapeFloat = floatShapeOf(spec.shape, points);
      body.pieces = {body.shape};
      body.piecesFloat = {body.shapeFloat};
    }
    body.frameOrigin = -centerOfMass;
    body.rigid = spec.isStatic ? RigidBody::fixed() : RigidBody::dynamic(mass);
    body.radius = body.shape.boundingRadius();
    BodyState start;
    start.worldFromBody.rotation = spec.orientation.toRotationMatrix();
    start.worldFromBody.translation = spec.position + start.worldFromBody.rotation * centerOfMass;
    start.velocity = spec.velocity;
    start.angularVelocity = spec.angularVelocity;
    // A static body is flown once, over the whole run: it is never integrated again.
    const double end = spec.isStatic ? double(frameCount_) / scene.frameRate : 0.0;
    body.setPath(freeFlight(body.rigid, start, 0.0, end, scene.gravity));
    bodies_.push_back(std::move(body));
  }
  // The checks' own view of every body: piece clouds and a sphere tree, made once rather
  // than on each of the many distances a frame's checks take.
  for (const WorldBody& body : bodies_) referenceBodies_.push_back(std::make_shared<const ReferenceBody>(body));
  // Two bodies overlapping at the start are an error (static ones may meet: walls of a box).
  std::vector<Bounds> boxes;
  for (std::size_t i = 0; i < bodies_.size(); ++i) {
    Bounds b;
    b.add(bodies_[i].path.start.worldFromBody.translation);
    b.inflate(bodies_[i].radius + scene.collisionTolerance);
    boxes.push_back(b);
  }
  const auto pairs = overlappingPairs(boxes, [&](int i, int j) { return bodies_[i].rigid.isStatic() && bodies_[j].rigid.isStatic(); });
  for (const auto& [i, j] : pairs) {
    const double d = referenceSignedDistance(*referenceBodies_[i], bodies_[i].path.start.worldFromBody,
                                             *referenceBodies_[j], bodies_[j].path.start.worldFromBody);
    if (d < -scene.collisionTolerance)
      throw std::invalid_argument(scene.bodies[i].name.empty() ? "" :
                                  "body '" + bodies_[i].name + "' (bodies[" + std::to_string(i) + "]) and body '" +
                                      bodies_[j].name + "' (bodies[" + std::to_string(j) +
                                      "]): field 'position' puts them overlapping at the start (by " +
                                      std::to_string(-d) + ")");
  }
}

Eigen::Vector3d World::positionOf(int body) const {
  const Pose<double> pose = stateOf(body).worldFromBody;
  return pose(bodies_[body].frameOrigin);
}

// ---------------------------------------------------------------------------------------
// Free flight and the broad phase

void World::fly(int b, double t0, double t1, FrameState& frame) {
  WorldBody& body = bodies_[b];
  const BodyState state = renormalized(body.path.stateAt(t0));
  {
    PartTimer timer(frame.report.parts.integration);
    body.setPath(flyChecked(body, state, t0, t1, body.gravity(scene_.gravity)));
  }
  ++body.version;
  auto& pieces = frame.pieces[b];
  if (!pieces.empty() && pieces.back().end > t0) pieces.back().end = t0;  // cut at t0 (a rollback)
  pieces.push_back({body.path, t1});
  if (settings_.trace) trace_.push_back({TraceEvent::Kind::Advance, b, -1, t0, t1});
}

void World::flyAll(double t0, double t1, FrameState& frame) {
  for (std::size_t b = 0; b < bodies_.size(); ++b) {
    if (bodies_[b].rigid.isStatic()) continue;  // never integrated
    const FreeFlight& path = bodies_[b].path;
    if (path.t0 == t0 && path.t1 >= t1) {        // already flown from here (after an impulse at t0)
      if (frame.pieces[b].empty()) frame.pieces[b].push_back({path, t1});
      continue;
    }
    fly(int(b), t0, t1, frame);
  }
}

Bounds World::sweptBounds(int b, double t0, double t1) const { return sweptBounds(b, bodies_[b].path, t0, t1); }

Bounds World::sweptBounds(int b, const FreeFlight& path, double t0, double t1) const {
  const WorldBody& body = bodies_[b];
  Bounds box;
  const BodyState a = path.stateAt(t0), z = path.stateAt(t1);
  const bool turning = path.start.angularVelocity.squaredNorm() > 0;
  if (turning || body.rigid.isStatic()) {
    // Every orientation may occur: the sphere about the centre of mass.
    box.add(a.worldFromBody.translation);
    box.add(z.worldFromBody.translation);
    if (body.rigid.isStatic()) {
      // A static body's box is tight: its support along each axis.
      Bounds tight;
      const Placed<Shape<double>> placed{body.shape, a.worldFromBody};
      for (int k = 0; k < 3; ++k) {
        Eigen::Vector3d e = Eigen::Vector3d::Zero();
        e[k] = 1;
        tight.hi[k] = placed.support(e)[k];
        tight.lo[k] = placed.support(-e)[k];
      }
      return tight;
    }
    box.inflate(body.radius);
  } else {
    // Not turning: the shape's own box at both ends (the box moves with the centre of mass).
    for (const BodyState* s : {&a, &z}) {
      const Placed<Shape<double>> placed{body.shape, s->worldFromBody};
      for (int k = 0; k < 3; ++k) {
        Eigen::Vector3d e = Eigen::Vector3d::Zero();
        e[k] = 1;
        box.add(Eigen::Vector3d(placed.support(e)));
        box.add(Eigen::Vector3d(placed.support(-e)));
      }
    }
  }
  // The ballistic bulge of the path off its chord: |g| T^2 / 8.
  const double T = t1 - t0;
  box.inflate(scene_.gravity.norm() * T * T / 8);
  return box;
}

std::vector<std::pair<int, int>> World::candidatePairs(double t0, double t1, FrameState& frame, int only, int also) {
  PartTimer timer(frame.report.parts.bounds);
  std::vector<Bounds> boxes(bodies_.size());
  for (std::size_t b = 0; b < bodies_.size(); ++b) {
    boxes[b] = sweptBounds(int(b), t0, t1);
    boxes[b].inflate(scene_.collisionTolerance);
  }
  return overlappingPairs(boxes, [&](int i, int j) {
    if (bodies_[i].resting() && bodies_[j].resting()) return true;  // neither can move: no collision
    if (only < 0) return false;
    return !(i == only || j == only || i == also || j == also);
  });
}

// ---------------------------------------------------------------------------------------
// One pair check: the paper's solver (§5) over [t0, t1]

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

/// The time-of-impact query of piece pi of body P and piece pj of body Q in the scalar type S.
template <typename S>
ToiResult<double> query(const WorldBody& P, int pi, const WorldBody& Q, int pj, double t0, double t1,
                        double tolerance, const WorldSettings& world, ExtrusionCache<S>* coherence) {
  const Shape<S>* shapeP;
  const Shape<S>* shapeQ;
  if constexpr (std::is_same_v<S, float>) {
    shapeP = &P.piecesFloat[pi];
    shapeQ = &Q.piecesFloat[pj];
  } else {
    shapeP = &P.pieces[pi];
    shapeQ = &Q.pieces[pj];
  }
  const Moving<Shape<S>> movingP{*shapeP, P.motionIn<S>()};
  const Moving<Shape<S>> movingQ{*shapeQ, Q.motionIn<S>()};
  ToiSettings<S> settings;
  settings.collisionTolerance = S(tolerance);
  settings.variant = world.variant;
  settings.warmStart = world.warmStarts;
  // The time of impact is needed to within the tolerance band, not to the solver's default
  // of sqrt(eps) of the interval (6e-10 s of a frame in double): a contact found where the
  // bodies are within 1.5 tolerances is as good to the impulse as one found at exactly one.
  // So the time tolerance is the time the pair needs to close half a tolerance at its
  // fastest. (Under rotation the solver's restarts halve the gap to the contact one at a
  // time, time_of_impact.hpp: this ends them some twenty restarts sooner.)
  // For the same reason a restart that finds the bodies within 1.5 tolerances, once the
  // query has taken 24 Brent iterations, is a hit (`acceptedDistance`, `acceptedAfter`): a
  // grazing pass just above the tolerance ends there rather than being proven free of
  // contact link by link (the torso's worst query took the cap, 100 iterations). Short
  // queries are left as §5 ends them. The band is a trade: a hit in it that is not
  // approaching is looked at again only after checkPieces' skip, and the torso's deepest
  // penetration (float, checks on, one run each) grew as the band came sooner: 0.44 mm
  // without it, 0.56 mm from the 24th iteration on, 1.36 and 1.44 mm from the 16th and
  // 12th; from the first restart on it made 30% more collisions. From the 24th on
  // its worst query was 41 (paper: 43).
  settings.acceptedDistance = S(1.5 * tolerance);
  settings.acceptedAfter = 24;
  const double closing = speedBound(P) + speedBound(Q);
  if (closing > 0)
    settings.timeTolerance = std::max(settings.timeTolerance,
                                      S(std::min(0.25, 0.5 * tolerance / (closing * (t1 - t0)))));
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

}  // namespace

/// The contact patch of a hit (contact.hpp): the touching feature, the points within two
/// tolerances of the supporting plane. A box lying flat touches with its face (the impulse
/// acts at its centre); tilted by more than that, with its lowest edge or corner, where
/// the impulse rights it (Mirtich's microcollisions at the touching corners).
ContactPatch World::patchOf(const Hit& hit, const BodyState& si, const BodyState& sj) const {
  return contactPatch(bodies_[hit.i].pieces[hit.pieceI], si.worldFromBody, bodies_[hit.j].pieces[hit.pieceJ],
                      sj.worldFromBody, hit.pointI, hit.pointJ, hit.normal, 2 * scene_.collisionTolerance);
}

/// The normal speed of j relative to i at the point of `patch` where the impulse acts
/// (negative: approaching), which it writes to `hit.contact`. The impulse acts at the same
/// point, so a hit that is approaching here is never found "separating" by the impulse.
double World::approachOn(Hit& hit, const ContactPatch& patch, const BodyState& si, const BodyState& sj) const {
  const auto approach = [&](const Eigen::Vector3d& p) {
    return hit.normal.dot(bodies_[hit.j].rigid.velocityAt(sj, p) - bodies_[hit.i].rigid.velocityAt(si, p));
  };
  hit.contact = patch.centre;
  double vn = approach(patch.centre);
  // A patch that leaves at its centre may still close at a corner: a tilted body rocking
  // onto its other edge, an L resting on both legs after an impulse at one. The impulse
  // then acts at the corner that closes fastest (Mirtich's microcollisions at each
  // touching corner in turn), or the body would sink there unseen.
  if (vn >= 0)
    for (const Eigen::Vector3d& p : patch.points)
      if (const double v = approach(p); v < vn) {
        vn = v;
        hit.contact = p;
      }
  return vn;
}

/// approachOn at the hit's own patch.
double World::approachAt(Hit& hit, const BodyState& si, const BodyState& sj, FrameState& frame) const {
  PartTimer timer(frame.report.parts.impulses);
  return approachOn(hit, patchOf(hit, si, sj), si, sj);
}

/// The piece pairs of bodies i and j that may touch over [t0, t1]: the one pair of two
/// convex bodies; for mesh bodies, the pairs the 14-DOP hierarchies cannot prove apart
/// (kdop's body-pair query, its front kept between frames for the pair); a mesh against a
/// convex body that is not a polytope: every piece.
template <typename S>
std::vector<PiecePair> World::piecePairs(int i, int j, double t0, double t1, FrameState& frame) {
  const WorldBody& A = bodies_[i];
  const WorldBody& B = bodies_[j];
  if (A.pieces.size() == 1 && B.pieces.size() == 1) return {PiecePair{0, 0}};
  std::vector<PiecePair> pairs;
  if (A.bvh && B.bvh) {
    PartTimer timer(frame.report.parts.bounds);
    auto& fronts = [&]() -> auto& {
      if constexpr (std::is_same_v<S, float>) return frontsFloat_;
      else return frontsDouble_;
    }();
    auto& query = fronts[pairSlot(i, j)];
    if (!query) {
      BodyPairSettings<S> settings;
      settings.tolerance = S(scene_.collisionTolerance);
      settings.frontTracking = settings_.frontTracking;
      // Each body's 14-DOPs at a pose are shared by all its pairs: after a collision every
      // pair of the struck body is queried at the same two poses, and its nodes' slab
      // ends are computed once for all of them (body_kdops.hpp).
      auto& kdops = [&]() -> auto& {
        if constexpr (std::is_same_v<S, float>) return kdopsFloat_;
        else return kdopsDouble_;
      }();
      kdops.resize(bodies_.size());
      for (int b : {i, j})
        if (!kdops[b]) {
          if constexpr (std::is_same_v<S, float>) kdops[b] = std::make_unique<BodyKdops<S>>(*bodies_[b].bvhFloat);
          else kdops[b] = std::make_unique<BodyKdops<S>>(*bodies_[b].bvh);
        }
      query = std::make_unique<BodyPairQuery<S>>(*kdops[i], *kdops[j], settings);
    }
    BodyPairOutput<S> out = query->query(A.template motionIn<S>(), B.template motionIn<S>(), S(t0), S(t1));
    frame.report.counters.kdopNodes += out.counters.nodesVisited;
    pairs = std::move(out.pairs);
  } else {
    for (int a = 0; a < int(A.pieces.size()); ++a)
      for (int b = 0; b < int(B.pieces.size()); ++b) pairs.push_back(PiecePair{a, b});
  }
  if (A.pieces.size() > 1 || B.pieces.size() > 1) frame.report.counters.piecePairs += long(pairs.size());
  return pairs;
}

bool World::checkPair(int i, int j, double t0, double t1, FrameState& frame, Hit& hit) {
  const std::vector<PiecePair> pairs = scene_.scalar == CollisionScalar::Float ? piecePairs<float>(i, j, t0, t1, frame)
                                                                               : piecePairs<double>(i, j, t0, t1, frame);
  // The pair's collision is the earliest of its pieces'.
  bool found = false;
  Hit piece;
  for (const PiecePair& p : pairs) {
    if (!checkPieces(i, p.a, j, p.b, t0, t1, frame, piece)) continue;
    if (!found || piece.time < hit.time) hit = piece;
    found = true;
  }
  return found;
}

bool World::checkPieces(int i, int pi, int j, int pj, double t0, double t1, FrameState& frame, Hit& hit) {
  FrameCounters& c = frame.report.counters;
  const double frameLength = 1.0 / scene_.frameRate;
  // A contact within the tolerance that is already moving apart is no collision: look again
  // once the bodies can have left the tolerance band, until the interval is covered (each
  // look moves on by at least 1e-4 of a frame, so a frame holds at most 10^4 of them; the
  // rest of an interval is never left unchecked).
  while (t0 < t1) {
    ToiResult<double> r;
    {
      PartTimer timer(frame.report.parts.collisionDetection);
      const bool coherent = settings_.coherence && settings_.warmStarts;
      const std::uint64_t key = piecePairKey(i, pi, j, pj);
      r = scene_.scalar == CollisionScalar::Float
              ? query<float>(bodies_[i], pi, bodies_[j], pj, t0, t1, scene_.collisionTolerance, settings_,
                             coherent ? &coherenceFloat_[key] : nullptr)
              : query<double>(bodies_[i], pi, bodies_[j], pj, t0, t1, scene_.collisionTolerance, settings_,
                              coherent ? &coherenceDouble_[key] : nullptr);
    }
    ++c.collisionChecks;
    c.brentIterations += r.brentIterations;
    c.brentMax = std::max(c.brentMax, r.brentIterations);
    c.completeTests += r.gjkRuns;
    c.sdEvaluations += r.sdEvaluations;
    if (settings_.trace) trace_.push_back({TraceEvent::Kind::Check, i, j, t0, t1});
    if (r.status == ToiStatus::Hit || r.status == ToiStatus::PhotoFinish ||
        (r.status == ToiStatus::IterationCap && r.brentIterations > 0))
      ++c.brentQueries;
    switch (r.status) {
      case ToiStatus::NoCollision: return false;
      case ToiStatus::Separating: touched(i, pi, j, pj, frame); return false;  // in contact, leaving
      case ToiStatus::PhotoFinish: ++c.photoFinishes; return false;
      case ToiStatus::NumericalFailure:
        throw std::runtime_error("bodies '" + bodies_[i].name + "' and '" + bodies_[j].name +
                                 "': the time-of-impact solver met a non-finite support point near t = " +
                                 std::to_string(t0));
      case ToiStatus::IterationCap: ++c.solverCaps; [[fallthrough]];  // undecided: treated as a collision
      case ToiStatus::Hit:
      case ToiStatus::StartsPenetrating: break;
    }
    hit.time = r.time;
    hit.i = i;
    hit.j = j;
    hit.pieceI = pi;
    hit.pieceJ = pj;
    hit.versionI = bodies_[i].version;
    hit.versionJ = bodies_[j].version;
    hit.pointI = r.witnessP;
    hit.pointJ = r.witnessQ;
    hit.normal = r.normal;
    const BodyState si = bodies_[i].path.stateAt(hit.time), sj = bodies_[j].path.stateAt(hit.time);
    if (scene_.scalar == CollisionScalar::Float) {
      // Float decides when; the impulse needs where, better than float's witnesses give
      // it: at a distance of one tolerance (3.45e-4) their round-off (~1e-7 of the
      // coordinates) tilts the normal by 1e-3, enough to make a 6 m floor touch at a far
      // corner. So the contact data are taken again in double at the time found.
      PartTimer timer(frame.report.parts.collisionDetection);
      const GjkResult<double> g = gjk(Placed<Shape<double>>{bodies_[i].pieces[pi], si.worldFromBody},
                                      Placed<Shape<double>>{bodies_[j].pieces[pj], sj.worldFromBody});
      if (g.status != GjkStatus::Overlapping) {
        r.distance = g.distance;
        hit.pointI = g.witnessP;
        hit.pointJ = g.witnessQ;
        const Eigen::Vector3d z = g.witnessQ - g.witnessP;
        hit.normal = z.norm() > 0 ? Eigen::Vector3d(z.normalized()) : Eigen::Vector3d::Zero();
      }
    }
    // The normal is the direction between the closest points; when they (nearly) coincide,
    // the bodies touch or overlap and that direction is round-off: the pair's last
    // reliable normal is used instead, or, for a first contact, centre to centre.
    Eigen::Vector3d& known = knownNormal(i, pi, j, pj);
    if (r.distance > 1e-2 * scene_.collisionTolerance && hit.normal.squaredNorm() > 0.5) {
      known = hit.normal;
    } else {
      hit.normal = known.squaredNorm() > 0.5 ? known : centreToCentre(si, sj);
    }
    touched(i, pi, j, pj, frame);
    const double vn = approachAt(hit, si, sj, frame);
    // Approaching: a collision. Two bodies at rest against each other (a caught body, see
    // resolve) approach by round-off (4e-16 m/s), and an impulse cannot change that: they
    // are taken as at rest, and looked at again once gravity has moved them.
    if (vn < -1e-9) return true;
    const double leave = scene_.collisionTolerance / std::max(vn, 1e-12);
    t0 = hit.time + std::clamp(leave, 1e-4 * frameLength, frameLength / 16);
  }
  return false;
}

// ---------------------------------------------------------------------------------------
// A collision: back to t_c, the impulse, on to the frame's end

namespace {

// Zeno's wedge (applyImpulse): a body caught after more than `kCaughtAfter` microcollisions
// in a frame along normals more than a right angle apart, or after more than
// `kSameInstantAfter` collisions at the very same time.
constexpr int kCaughtAfter = 32, kSameInstantAfter = 8;

}  // namespace

/// The impulse of one collision at `hit.contact`, applied to the states si and sj at the
/// time of impact, and Zeno's wedge (a body may be caught: stopped where it stands).
void World::applyImpulse(const Hit& hit, BodyState& si, BodyState& sj, FrameState& frame) {
  ImpulseResult result;
  {
    PartTimer timer(frame.report.parts.impulses);
    result = resolveCollision(bodies_[hit.i].rigid, si, bodies_[hit.j].rigid, sj, Contact{hit.contact, hit.normal},
                              CollisionMaterial{scene_.restitution, scene_.friction}, impulse_);
  }
  FrameCounters& c = frame.report.counters;
  ++c.collisions;
  c.impulseSteps += result.integratorSteps;
  if (result.status == ImpulseStatus::StepCap) ++c.impulseCaps;
  if (result.status == ImpulseStatus::Microcollision) ++c.microcollisions;
  collisionLog_.push_back({hit.time, double(hit.i), double(hit.j)});
  if (settings_.trace) trace_.push_back({TraceEvent::Kind::Collision, hit.i, hit.j, hit.time, hit.time});
  // Zeno's wedge: a body caught between two contacts (a rib wedged between a stem and a
  // leaf) bounces from one to the other ever faster, the impulses ever smaller: 86,000
  // microcollisions in a frame for one rib. Impulses alone never end that. A body struck
  // by more than `kCaughtAfter` microcollisions within a frame, along normals more than a
  // right angle apart (a wedge; a box sliding on a floor is struck along one normal only),
  // is *caught*: it is stopped where it stands (its velocity and spin set to zero, which
  // only takes energy away), and gravity starts it again, so it settles in a few drops
  // of one tolerance per frame.
  //
  // The same at one instant: a light rod lying on two corners, each impulse at one corner
  // setting the other closing (2,600 collisions at one time for a cartilage on the floor).
  // A body in more than `kSameInstantAfter` collisions at the very same time is caught too.
  for (const auto& [b, state, outward] : {std::tuple<int, BodyState*, Eigen::Vector3d>{hit.i, &si, hit.normal},
                                          std::tuple<int, BodyState*, Eigen::Vector3d>{hit.j, &sj, -hit.normal}}) {
    if (bodies_[b].rigid.isStatic()) continue;
    FrameState::Struck& struck = frame.struck[b];
    struck.atLastTime = struck.lastTime == hit.time ? struck.atLastTime + 1 : 1;
    struck.lastTime = hit.time;
    bool wedged = false;
    if (result.status == ImpulseStatus::Microcollision) {
      bool seen = false;
      for (const auto& side : struck.sides) {
        wedged = wedged || side.dot(outward) < 0;
        seen = seen || side.dot(outward) > 0.9;
      }
      if (!seen && struck.sides.size() < 8) struck.sides.push_back(outward);
      wedged = ++struck.microcollisions > kCaughtAfter && wedged;
    }
    const int other = b == hit.i ? hit.j : hit.i;
    if (std::find(struck.by.begin(), struck.by.end(), other) == struck.by.end()) struck.by.push_back(other);
    if (wedged || struck.atLastTime > kSameInstantAfter) {  // caught: stopped where it stands
      state->velocity.setZero();
      state->angularVelocity.setZero();
      ++c.caught;
      // Caught against a static body, it would fall again under gravity and be caught again,
      // a few times per frame, each fall taking it deeper: a flat domino on the floor sank
      // half a millimetre per frame, 20 tolerances in 1.5 s. It sleeps instead: held where
      // it stands until a moving body strikes it (what engines call sleeping).
      if (bodies_[other].rigid.isStatic()) bodies_[b].asleep = true;
    } else if (!bodies_[other].resting()) {
      bodies_[b].asleep = false;  // struck by a moving body: awake
    }
  }
}

/// The contact data of pieces pi of body i and pj of body j at time t from a static GJK
/// `g` of the two at states si and sj, written to `hit`. The normal is the direction
/// between the closest points; where they (nearly) coincide or the pieces overlap, that
/// direction is round-off, and the pair's last reliable normal is used instead (for a
/// first contact, centre to centre). True if the closest points gave the normal.
bool World::contactFromGjk(const GjkResult<double>& g, int i, int pi, int j, int pj, double t, const BodyState& si,
                           const BodyState& sj, Hit& hit) {
  hit.time = t;
  hit.i = i;
  hit.j = j;
  hit.pieceI = pi;
  hit.pieceJ = pj;
  const Eigen::Vector3d z = g.witnessQ - g.witnessP;
  if (g.status != GjkStatus::Overlapping && z.norm() > 1e-2 * scene_.collisionTolerance) {
    hit.normal = z.normalized();
    hit.pointI = g.witnessP;
    hit.pointJ = g.witnessQ;
    return true;
  }
  const Eigen::Vector3d& known = knownNormal(i, pi, j, pj);
  hit.normal = known.squaredNorm() > 0.5 ? known : centreToCentre(si, sj);
  hit.pointI = hit.pointJ = 0.5 * (si.worldFromBody.translation + sj.worldFromBody.translation);
  return false;
}

/// The contact of pieces pi of body i and pj of body j at time t, the bodies at states si
/// and sj: true, with the contact data in `hit` (contactFromGjk, by a double GJK), if they
/// are within the collision tolerance.
bool World::contactAt(int i, int pi, int j, int pj, double t, const BodyState& si, const BodyState& sj,
                      FrameState& frame, Hit& hit) {
  GjkResult<double> g;
  {
    PartTimer timer(frame.report.parts.collisionDetection);
    g = gjk(Placed<Shape<double>>{bodies_[i].pieces[pi], si.worldFromBody},
            Placed<Shape<double>>{bodies_[j].pieces[pj], sj.worldFromBody});
  }
  if (g.status != GjkStatus::Overlapping && g.distance > scene_.collisionTolerance) return false;
  if (contactFromGjk(g, i, pi, j, pj, t, si, sj, hit)) knownNormal(i, pi, j, pj) = hit.normal;
  return true;
}

/// Remembers that pieces pi of body i and pj of body j came within the tolerance this
/// frame (resolve's instant pass looks at them again). Kept for the moving body or bodies
/// only: the pass never starts from a static one (the plant would gather every contact).
void World::touched(int i, int pi, int j, int pj, FrameState& frame) {
  const FrameState::Touching pair{i, pi, j, pj};
  for (int b : {i, j}) {
    if (bodies_[b].rigid.isStatic()) continue;
    auto& list = frame.touching[b];
    if (std::find(list.begin(), list.end(), pair) == list.end()) list.push_back(pair);
  }
}

/// A collision at t_c: its impulse, then (with `instantPass`) the impulses it sets off at
/// the same instant; the bodies struck fly on from t_c. Returns the bodies struck.
std::vector<int> World::resolve(const Hit& hit, FrameState& frame, bool instantPass) {
  // Roll back: the bodies' states at the time of impact t_c.
  const double tc = hit.time;
  struct Body {
    int index;                  // in bodies_
    BodyState state;            // at t_c
    bool changed = false;       // by an impulse of this pass
  };
  std::deque<Body> seen;        // the bodies the pass has looked at (a deque: references stay valid)
  const auto inPass = [&](int b) -> Body& {
    for (Body& s : seen)
      if (s.index == b) return s;
    seen.push_back({b, renormalized(bodies_[b].path.stateAt(tc))});
    return seen.back();
  };
  // The impulse at the hit; then every contact of the struck bodies that the impulses set
  // closing at this same instant, before any body flies on (the *instant pass*). A body
  // lying on others passes each impulse on: a rib pressed between two vertebrae, struck by
  // one, closes on the other, which closes on the next, as a pile's impulses travel through
  // it. Found by the pair checks, each link of such a chain cost a roll back and a check of
  // every pair of its two bodies over the rest of the frame: at the torso's crash, 86% of
  // the collisions of its busiest pairs came at the very instant of the one before. Here a
  // link costs one GJK per contact of its two bodies (the piece pairs that came within the
  // tolerance this frame, `touched`), and each struck body is checked over the rest of the
  // frame once, after the last link. A contact this pass does not know is found by that
  // check, as before.
  //
  // Each impulse is the one the event loop would apply (the scene's restitution, or a
  // microcollision's), so each takes energy away or keeps it. The caught rule
  // (applyImpulse) still stops a body struck more than `kSameInstantAfter` times at one
  // instant, and a pass ends after `kInstantImpulses`, leaving what still closes to the
  // checks. (Restitution 0 for a contact struck again within a pass, as engines treat
  // resting contact, was tried and left out: on the torso dropped in three other poses,
  // its piles sank 1.6 to 3.8 mm deep, against 0.05 to 0.66 mm with the scene's
  // restitution. It leaves bodies at rest within the band, with no hop to lift them back.)
  constexpr int kInstantImpulses = 256;
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
    const auto [where, isNew] = linkIndex.try_emplace(piecePairKey(i, pi, j, pj), links.size());
    if (!isNew) return where->second;
    Link link;
    link.inContact = contactAt(i, pi, j, pj, tc, inPass(i).state, inPass(j).state, frame, link.hit);
    links.push_back(std::move(link));
    return links.size() - 1;
  };
  // The normal speed at a contact with the velocities its bodies have now (approachOn).
  const auto closingSpeed = [&](Link& link) {
    const BodyState& si = inPass(link.hit.i).state;
    const BodyState& sj = inPass(link.hit.j).state;
    PartTimer timer(frame.report.parts.impulses);
    if (!link.patch) link.patch = patchOf(link.hit, si, sj);
    return approachOn(link.hit, *link.patch, si, sj);
  };
  // The hit itself is the first contact (remembered as touching here too: a fixed step's
  // check does not remember contacts).
  inPass(hit.i);
  inPass(hit.j);  // (in this order: the bodies fly on in the order seen)
  touched(hit.i, hit.pieceI, hit.j, hit.pieceJ, frame);
  links.push_back({hit, true, std::nullopt, true});
  linkIndex.emplace(piecePairKey(hit.i, hit.pieceI, hit.j, hit.pieceJ), 0);
  std::deque<std::size_t> closing{0};
  for (int impulses = 0; !closing.empty() && impulses < kInstantImpulses;) {
    const std::size_t k = closing.front();
    closing.pop_front();
    links[k].queued = false;
    // Each contact is looked at with the states of this pass, the hit's too (its check
    // chose its point on states not renormalized), and one queued by an earlier link with
    // the velocities that link left.
    if (closingSpeed(links[k]) >= -1e-9) continue;
    ++impulses;
    const Hit struck = links[k].hit;  // (a copy: `links` grows below)
    frame.collidedPairs.emplace_back(struck.i, struck.j);
    Body& bi = inPass(struck.i);
    Body& bj = inPass(struck.j);
    applyImpulse(struck, bi.state, bj.state, frame);
    bi.changed = bj.changed = true;
    for (int b : {struck.i, struck.j}) {
      if (!instantPass || bodies_[b].rigid.isStatic()) continue;
      for (const FrameState::Touching& t : frame.touching[b]) {
        const std::size_t n = linkOf(t.i, t.pi, t.j, t.pj);
        if (!links[n].inContact || links[n].queued) continue;
        if (closingSpeed(links[n]) < -1e-9) {
          links[n].queued = true;
          closing.push_back(n);
        }
      }
    }
  }
  // On from t_c with the new velocities, to the end of the current path (the frame's end,
  // or one frame on when the impact is at the very end).
  FrameCounters& c = frame.report.counters;
  const double frameEnd = intervalEnd_;
  std::vector<int> flown;
  for (const Body& s : seen) {
    const int b = s.index;
    WorldBody& body = bodies_[b];
    if (body.rigid.isStatic() || !s.changed) continue;
    flown.push_back(b);
    const double end = std::max(body.path.t1, frameEnd);
    if (body.path.t1 > tc) {
      ++c.bodiesRolledBack;
      if (settings_.trace) trace_.push_back({TraceEvent::Kind::Rollback, b, -1, body.path.t1, tc});
    }
    // A path shorter than a thousandth of a frame is not worth keeping (and may not exist
    // in float): the next interval flies on from there.
    const double t1 = end - tc > 1e-3 / scene_.frameRate ? end : tc + 1e-3 / scene_.frameRate;
    {
      PartTimer timer(frame.report.parts.integration);
      body.setPath(flyChecked(body, s.state, tc, t1, body.gravity(scene_.gravity)));
    }
    ++body.version;
    auto& pieces = frame.pieces[b];
    if (!pieces.empty() && pieces.back().end > tc) pieces.back().end = tc;
    pieces.push_back({body.path, t1});
    if (settings_.trace) trace_.push_back({TraceEvent::Kind::Advance, b, -1, tc, t1});
  }
  return flown;
}

// ---------------------------------------------------------------------------------------
// The orderings

void World::runTimewarp(double T0, double T1, FrameState& frame) {
  // Every body runs ahead to the frame's end on its own: its local time is T1.
  flyAll(T0, T1, frame);
  std::priority_queue<Hit, std::vector<Hit>, std::greater<Hit>> queue;
  {
    Hit hit;
    for (const auto& [i, j] : candidatePairs(T0, T1, frame))
      if (checkPair(i, j, T0, T1, frame, hit)) queue.push(hit);
  }
  // The swept bounds stay valid for every body a collision leaves alone: only the bodies
  // its impulses struck (its two, and those the instant pass reached) get new ones (from
  // t_c), and only their pairs are looked at.
  {
    PartTimer timer(frame.report.parts.bounds);
    frame.boxes.resize(bodies_.size());
    for (std::size_t b = 0; b < bodies_.size(); ++b) {
      frame.boxes[b] = sweptBounds(int(b), T0, T1);
      frame.boxes[b].inflate(scene_.collisionTolerance);
    }
  }
  auto pairsOf = [&](const std::vector<int>& struck, double tc) {
    PartTimer timer(frame.report.parts.bounds);
    for (int b : struck) {
      frame.boxes[b] = sweptBounds(b, tc, T1);
      frame.boxes[b].inflate(scene_.collisionTolerance);
    }
    std::vector<std::pair<int, int>> pairs;
    for (int b : struck)
      for (int k = 0; k < int(bodies_.size()); ++k)
        if (k != b && !(bodies_[b].resting() && bodies_[k].resting()) && frame.boxes[b].overlaps(frame.boxes[k]))
          pairs.emplace_back(std::min(b, k), std::max(b, k));  // (two resting bodies: no collision, as in candidatePairs)
    std::sort(pairs.begin(), pairs.end());
    pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
    return pairs;
  };
  FrameCounters& c = frame.report.counters;
  const long cap = 200000 + 1000 * long(bodies_.size());
  while (!queue.empty()) {
    Hit hit;
    {
      PartTimer timer(frame.report.parts.ordering);
      hit = queue.top();
      queue.pop();
    }
    if (++c.events > cap)
      throw std::runtime_error("frame " + std::to_string(frame_ + 1) + ": more than " + std::to_string(cap) +
                               " events; the scene does not settle");
    // Stale: computed on a path that a later-processed, earlier collision replaced.
    if (hit.versionI != bodies_[hit.i].version || hit.versionJ != bodies_[hit.j].version) continue;
    // The collision rolls back only the bodies it strikes (their local time was T1): its
    // two, and any that its impulses reach at the same instant (resolve) ...
    if (std::max(bodies_[hit.i].path.t1, bodies_[hit.j].path.t1) > hit.time) ++c.rollbacks;
    const std::vector<int> struck = resolve(hit, frame);
    // ... and re-checks only the pairs that touch the bodies it struck, from t_c on.
    Hit next;
    for (const auto& [i, j] : pairsOf(struck, hit.time))
      if (checkPair(i, j, hit.time, T1, frame, next)) queue.push(next);
  }
}

void World::runToiHeap(double T0, double T1, FrameState& frame) {
  flyAll(T0, T1, frame);
  FrameCounters& c = frame.report.counters;
  const long cap = 200000 + 1000 * long(bodies_.size());
  double t = T0;
  for (;;) {
    // Every pair, from the current time: the earliest impact of all.
    Hit earliest, hit;
    bool found = false;
    for (const auto& [i, j] : candidatePairs(t, T1, frame))
      if (checkPair(i, j, t, T1, frame, hit) && (!found || earliest > hit)) {
        earliest = hit;
        found = true;
      }
    if (!found) break;
    if (++c.events > cap)
      throw std::runtime_error("frame " + std::to_string(frame_ + 1) + ": more than " + std::to_string(cap) +
                               " events; the scene does not settle");
    // Every body is advanced to the impact: its path is cut there and flown on.
    t = earliest.time;
    for (std::size_t b = 0; b < bodies_.size(); ++b) {
      if (bodies_[b].rigid.isStatic() || int(b) == earliest.i || int(b) == earliest.j) continue;
      if (t < T1 && t > bodies_[b].path.t0) {  // an impact at the frame's very end cuts nothing
        fly(int(b), t, T1, frame);
        ++c.bodiesRolledBack;
      }
    }
    resolve(earliest, frame);
  }
}

void World::runFixedStep(double T0, double T1, FrameState& frame) {
  const int steps = scene_.fixedSubsteps;
  FrameCounters& c = frame.report.counters;
  for (int s = 0; s < steps; ++s) {
    const double ta = T0 + (T1 - T0) * s / steps, tb = s + 1 == steps ? T1 : T0 + (T1 - T0) * (s + 1) / steps;
    flyAll(ta, tb, frame);
    intervalEnd_ = tb;  // a collision flies its bodies on to the step's end
    // Discrete collision detection: the pairs as they stand at the step's end.
    for (const auto& [i, j] : candidatePairs(tb, tb, frame)) {
      const BodyState si = bodies_[i].path.stateAt(tb), sj = bodies_[j].path.stateAt(tb);
      const std::vector<PiecePair> pairs = scene_.scalar == CollisionScalar::Float
                                               ? piecePairs<float>(i, j, tb, tb, frame)
                                               : piecePairs<double>(i, j, tb, tb, frame);
      bool found = false;
      Hit hit;
      for (const PiecePair& p : pairs) {
        ++c.collisionChecks;
        GjkResult<double> g;
        {
          PartTimer timer(frame.report.parts.collisionDetection);
          if (scene_.scalar == CollisionScalar::Float) {
            const auto r = gjk(Placed<Shape<float>>{bodies_[i].piecesFloat[p.a], castPose<float>(si.worldFromBody)},
                               Placed<Shape<float>>{bodies_[j].piecesFloat[p.b], castPose<float>(sj.worldFromBody)});
            g.status = r.status;
            g.distance = r.distance;
            g.witnessP = r.witnessP.cast<double>();
            g.witnessQ = r.witnessQ.cast<double>();
          } else {
            g = gjk(Placed<Shape<double>>{bodies_[i].pieces[p.a], si.worldFromBody},
                    Placed<Shape<double>>{bodies_[j].pieces[p.b], sj.worldFromBody});
          }
        }
        Eigen::Vector3d& known = knownNormal(i, p.a, j, p.b);
        const Eigen::Vector3d z = g.witnessQ - g.witnessP;
        const bool touching = g.status == GjkStatus::Overlapping || g.distance <= scene_.collisionTolerance;
        if (!touching) {
          if (z.norm() > 1e-2 * scene_.collisionTolerance) known = z.normalized();
          continue;
        }
        // The deepest-looking touching piece pair speaks for the body pair (the first found).
        if (found) continue;
        found = true;
        contactFromGjk(g, i, p.a, j, p.b, tb, si, sj, hit);
      }
      if (!found || approachAt(hit, si, sj, frame) >= 0) continue;
      ++c.events;
      // One impulse per pair and step, as a discrete engine's single pass over its
      // contacts; no instant pass (the baseline stays the simple one).
      resolve(hit, frame, false);  // flies both bodies on from tb
    }
  }
}

// ---------------------------------------------------------------------------------------
// A frame

FrameReport World::step() {
  if (done()) throw std::logic_error("World::step: the scene's duration is already simulated");
  const auto start = Clock::now();
  const double T0 = double(frame_) / scene_.frameRate, T1 = double(frame_ + 1) / scene_.frameRate;
  const auto freshFrame = [&] {
    FrameState fresh;
    fresh.pieces.resize(bodies_.size());
    fresh.struck.resize(bodies_.size());
    fresh.touching.resize(bodies_.size());
    fresh.report.frame = frame_ + 1;
    fresh.report.time = T1;
    return fresh;
  };
  FrameState frame = freshFrame();
  // A free-flight path holds less than half a turn (motion.hpp, FreeFlightPath): when a
  // body spins fast (a ball rolling at speed), the frame is run as several intervals,
  // each a quarter turn of the fastest body at most (collisions can spin a body up within
  // an interval; flyChecked refuses what still does not fit).
  // A collision can spin a light body up past that within an interval (a cartilage of a
  // few grams struck at the crash: 370 rad/s); then the frame is run again from its start
  // in intervals short enough for the new spin (each body's path, version, sleep and the pairs'
  // normals as they were at T0).
  double fastest = 0;
  for (std::size_t b = 0; b < bodies_.size(); ++b)
    if (!bodies_[b].rigid.isStatic()) fastest = std::max(fastest, bodies_[b].path.end.angularVelocity.norm());
  const auto quarterTurns = [&](double speed) { return int(std::ceil(std::min(speed * (T1 - T0) / (0.25 * M_PI), 1e6))); };
  int intervals = std::clamp(quarterTurns(fastest), 1, 64);
  std::vector<FreeFlight> paths;
  std::vector<int> versions;
  std::vector<char> asleep;
  for (const WorldBody& body : bodies_) {
    paths.push_back(body.path);
    versions.push_back(body.version);
    asleep.push_back(body.asleep);
  }
  const auto normals = pairNormal_;
  const std::size_t traced = trace_.size(), logged = collisionLog_.size();
  for (;;) {
    try {
      for (int k = 0; k < intervals; ++k) {
        const double ta = k == 0 ? T0 : T0 + (T1 - T0) * k / intervals;
        const double tb = k + 1 == intervals ? T1 : T0 + (T1 - T0) * (k + 1) / intervals;
        intervalEnd_ = tb;
        switch (scene_.ordering) {
          case Ordering::Timewarp: runTimewarp(ta, tb, frame); break;
          case Ordering::ToiHeap: runToiHeap(ta, tb, frame); break;
          case Ordering::FixedStep: runFixedStep(ta, tb, frame); break;
        }
      }
      break;
    } catch (const SpinOverflow& spin) {
      const int needed = std::max(2 * intervals, quarterTurns(spin.angularSpeed));
      if (needed > 4096)
        throw std::runtime_error(std::string(spin.what()) + " even in " + std::to_string(intervals) +
                                 " intervals of a frame; raise frame_rate");
      for (std::size_t b = 0; b < bodies_.size(); ++b) {
        bodies_[b].setPath(paths[b]);
        bodies_[b].version = versions[b] + 1;  // events computed on the abandoned run are stale
        bodies_[b].asleep = asleep[b];
      }
      pairNormal_ = normals;
      trace_.resize(traced);
      collisionLog_.resize(logged);
      intervals = needed;
      const PartTimes parts = frame.report.parts;  // the abandoned run's wall time still counts
      frame = freshFrame();
      frame.report.parts = parts;
    }
  }
  // The frame is final: the global virtual time has passed T1, its history is discarded.
  settle(T1, frame);
  if (settings_.checks) {
    PartTimer timer(frame.report.parts.checks);
    runChecks(T0, T1, frame);
  }
  ++frame_;
  frame.report.wallSeconds = std::chrono::duration<double>(Clock::now() - start).count();
  PartTimes& parts = frame.report.parts;
  parts.ordering = std::max(0.0, frame.report.wallSeconds - parts.integration - parts.bounds -
                                     parts.collisionDetection - parts.impulses - parts.checks);
  return frame.report;
}

// ---------------------------------------------------------------------------------------
// Settling

// A body whose kinetic energy could not lift its centre of mass by one collision tolerance
// against gravity (E_k < m |g| tol) cannot leave the tolerance band of what supports it by
// its own motion: rocking on the floor, it only rattles inside the band, in
// microcollisions that keep its energy (restitution 1) and never lift it back to the
// band's edge, and it sinks a little with every one that is found late (docs 08:
// cartilages rocking at 1 rad/s sank 0.02 mm a frame, 5 mm in 6 s). Such a body is *slow*.
// Slow is not at rest: a domino just starting to topple is slow too, and gravity is about
// to speed it up. So a body must stay slow for `kSettleSeconds` (a toppling domino is
// fast by then) before it may settle; then, at a frame's end, it is put to sleep: held
// where it stands (velocity and spin set to zero, which only takes energy away) until a
// moving body strikes it. It must also rest on something, which grows from what cannot
// move, as engines grow their sleeping islands: a slow body struck in the frame by a
// static or sleeping body settles, then one struck by a body that settles, and so on. A
// body struck by one that is neither slow nor resting starts its wait again. A body in
// the air is struck by nothing, so it never settles there; a body sliding slowly on a
// floor stops as under static friction.
void World::settle(double T1, FrameState& frame) {
  constexpr double kSettleSeconds = 0.5;
  const double g = scene_.gravity.norm();
  if (!(g > 0)) return;  // no weight: nothing holds a body down, rest is not defined
  const std::size_t n = bodies_.size();
  std::vector<char> slow(n, 0), settles(n, 0);
  std::vector<BodyState> end(n);
  for (std::size_t b = 0; b < n; ++b) {
    const WorldBody& body = bodies_[b];
    if (body.rigid.isStatic() || body.asleep) continue;
    end[b] = body.path.stateAt(T1);
    slow[b] = body.rigid.kineticEnergy(end[b]) * body.rigid.inverseMass() / g < scene_.collisionTolerance;
  }
  // How long each body has been slow and struck by nothing but resting or slow bodies;
  // one that has been so long enough, and was struck in this frame, may settle.
  std::vector<char> waited(n, 0);
  std::vector<int> ready;
  for (std::size_t b = 0; b < n; ++b) {
    WorldBody& body = bodies_[b];
    if (body.rigid.isStatic() || body.asleep) continue;
    bool quiet = slow[b], supported = false;
    for (const int other : frame.struck[b].by) {
      quiet = quiet && (bodies_[other].resting() || slow[other]);
      supported = supported || bodies_[other].resting();
    }
    body.slowFor = quiet ? body.slowFor + 1.0 / scene_.frameRate : 0.0;
    waited[b] = quiet && body.slowFor >= kSettleSeconds && !frame.struck[b].by.empty();
    if (waited[b] && supported) {
      settles[b] = 1;
      ready.push_back(int(b));
    }
  }
  // The bodies that may settle on b once b settles: those it struck (striking is mutual).
  std::vector<std::vector<int>> next(n);
  for (std::size_t b = 0; b < n; ++b)
    if (waited[b])
      for (const int other : frame.struck[b].by)
        if (waited[other]) next[other].push_back(int(b));
  while (!ready.empty()) {
    const int b = ready.back();
    ready.pop_back();
    for (const int c : next[b])
      if (!settles[c]) {
        settles[c] = 1;
        ready.push_back(c);
      }
  }
  for (std::size_t b = 0; b < n; ++b) {
    if (!settles[b]) continue;
    WorldBody& body = bodies_[b];
    BodyState state = end[b];
    state.velocity.setZero();
    state.angularVelocity.setZero();
    body.asleep = true;
    body.slowFor = 0;
    body.setPath(flyChecked(body, state, T1, T1, body.gravity(scene_.gravity)));
    ++body.version;
    ++frame.report.counters.settled;
  }
}

// ---------------------------------------------------------------------------------------
// The independent checks (checks.hpp)

// How fast the distance of bodies i and j can change over a frame (the Lipschitz bound of
// the tunnelling check). A point of body b at x moves at v_b + w_b x (x - c_b), so the
// distance changes at most as fast as the largest relative speed of two points,
//   |d'(t)| <= |v_j(t) - v_i(t)| + |w_i| r_i + |w_j| r_j.
// The linear part. Over a piece of its path a body flies freely, so its velocity is linear
// in t (v(s) + g (t - s) awake, constant asleep or static) and is the line through the
// piece's end velocities. Over the time two pieces share, v_j - v_i is then linear too and
// its size, convex, is largest at an end of the shared time. The bound is the largest over
// the pieces that share time. Two bodies falling side by side (the paper's sweeping false
// alarm) get a bound near 0, since their gravity cancels, where the sum of their speeds,
// growing as g t, made the check crawl.
// The spin part. Over a piece the spin's size is bounded by its ends' largest (torque-free:
// |L| is fixed, but |w| within its ends' range is not guaranteed), so spare 10%.
double World::relativeSpeedBound(int i, int j, double T0, double T1, const FrameState& frame) const {
  // A body's pieces this frame (the frame's path, held in `unstruck`, when it was not struck).
  auto piecesOf = [&](int b, std::vector<Piece>& unstruck) -> const std::vector<Piece>& {
    if (!frame.pieces[b].empty()) return frame.pieces[b];
    unstruck = {Piece{bodies_[b].path, T1}};
    return unstruck;
  };
  std::vector<Piece> unstruckI, unstruckJ;
  const std::vector<Piece>& piecesI = piecesOf(i, unstruckI);
  const std::vector<Piece>& piecesJ = piecesOf(j, unstruckJ);
  double spin = 0;
  for (const auto& [b, pieces] : {std::pair{i, &piecesI}, std::pair{j, &piecesJ}}) {
    double w = 0;
    for (const Piece& piece : *pieces)
      w = std::max({w, piece.path.start.angularVelocity.norm(), piece.path.end.angularVelocity.norm()});
    if (w > 0) spin += 1.1 * w * bodies_[b].radius;
  }
  // The velocity of a piece's path at t: the line through its end velocities.
  auto velocity = [](const Piece& piece, double t) -> Eigen::Vector3d {
    const FreeFlight& path = piece.path;
    if (!(path.t1 > path.t0)) return path.start.velocity;
    return path.start.velocity + (path.end.velocity - path.start.velocity) * ((t - path.t0) / (path.t1 - path.t0));
  };
  double linear = 0;
  for (const Piece& a : piecesI)
    for (const Piece& b : piecesJ) {
      const double lo = std::max({T0, a.path.t0, b.path.t0}), hi = std::min({T1, a.end, b.end});
      if (lo > hi) continue;  // never at the same time
      for (double t : {lo, hi}) linear = std::max(linear, (velocity(b, t) - velocity(a, t)).norm());
    }
  return linear + spin;
}

void World::runChecks(double T0, double T1, FrameState& frame) {
  FrameCounters& c = frame.report.counters;
  auto poseAt = [&](int b, double t) -> Pose<double> {
    if (bodies_[b].rigid.isStatic() || frame.pieces[b].empty()) return bodies_[b].path.motion.pose(t);
    for (const Piece& piece : frame.pieces[b])
      if (t <= piece.end) return piece.path.motion.pose(std::max(t, piece.path.t0));
    return frame.pieces[b].back().path.motion.pose(t);
  };
  // The deepest penetration at the frame's end.
  std::vector<Bounds> boxes(bodies_.size());
  for (std::size_t b = 0; b < bodies_.size(); ++b) {
    if (bodies_[b].rigid.isStatic() || frame.pieces[b].empty()) {
      boxes[b] = sweptBounds(int(b), T0, T1);
    } else {
      for (const Piece& piece : frame.pieces[b])
        if (piece.end > piece.path.t0) boxes[b].add(sweptBounds(int(b), piece.path, piece.path.t0, piece.end));
    }
    boxes[b].inflate(scene_.collisionTolerance);
  }
  const auto pairs = overlappingPairs(boxes, [&](int i, int j) { return bodies_[i].rigid.isStatic() && bodies_[j].rigid.isStatic(); });
  for (const auto& [i, j] : pairs) {
    const double d = referenceSignedDistance(*referenceBodies_[i], poseAt(i, T1), *referenceBodies_[j], poseAt(j, T1));
    c.maxPenetration = std::max(c.maxPenetration, -d);
    // Tunnelling: a pair with no collision reported this frame that came closer than
    // minus twice the tolerance (interpenetrated) at some time of the frame (checks.hpp,
    // tunnellingThreshold).
    const bool reported = std::find(frame.collidedPairs.begin(), frame.collidedPairs.end(), std::make_pair(i, j)) !=
                          frame.collidedPairs.end();
    if (reported) continue;
    const double lipschitz = relativeSpeedBound(i, j, T0, T1, frame);
    const int a = i, b = j;  // a lambda may not capture structured bindings in C++17
    const ReferenceBody &ra = *referenceBodies_[a], &rb = *referenceBodies_[b];
    const auto distanceAt = [&](double t) { return referenceSignedDistance(ra, poseAt(a, t), rb, poseAt(b, t)); };
    const double threshold = tunnellingThreshold(distanceAt(T0), scene_.collisionTolerance);
    if (firstInterpenetration(distanceAt, lipschitz, threshold, T0, T1)) ++c.tunnelled;
  }
}

}  // namespace gjkx
