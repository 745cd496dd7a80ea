// gjkx_bullet_scene: runs a scene file (gjkx/timewarp/scene.hpp) in Bullet, the rigid-body
// library most people would reach for, and measures the run with the same independent
// checks as gjkx_simulate --checks (gjkx/verify/frame_verifier.hpp), so that the two can be compared.
//
//   gjkx_bullet_scene SCENE.json [--out DIR] [--substeps N] [--no-ccd] [--quiet]
//
// writes DIR/frames.csv (per frame: frame, time, wall seconds of Bullet, deepest
// penetration, kinetic energy, pairs Bullet had in contact, pairs that tunnelled, seconds
// of the checks), DIR/bodies.csv (per frame and body, the columns of gjkx_simulate's, so
// the same renderer draws both runs), and ends with one line a script can read:
//
//   SUMMARY frames=N sim_s=... wall_s=... steps=N max_penetration=... tunnelled=N
//           kinetic_start=... kinetic_end=... kinetic_max=...
//
// wall_s is Bullet's time alone (the checks are timed apart, as gjkx_simulate's checks_s).
// A scene with bad input exits 1 with a message naming the body and the field; a bad
// command line exits 2.
//
// The same bodies. The scene is read by the library's parser and its bodies built by
// gjkx::buildBodies, as our world builds them: our mass, inertia and centre of mass from the same shape
// and density, the same convex pieces of a mesh (gjkx::decompose, cached on disk). Bullet
// is handed those, so both simulators move the same bodies and the checks measure both
// on the same shapes.
//
// The same checks. After every frame, the same observer our world attaches
// (gjkx::FrameVerifier): the signed distance of every pair whose bounds meet, at the
// frame's end, by the reference (its negative is the penetration), and, for a pair Bullet
// had no contact point for during the frame, whether the pair interpenetrated (came closer
// than minus twice the collision tolerance) at any time of the frame. Each finding is
// named on standard error and in DIR/checks.csv. Between frames our world moves a body on a free-flight path: a
// parabola under gravity for its centre of mass and a rotation turning at a constant rate
// along the shortest arc (gjkx::FreeFlightPath). Bullet gives only the poses at the
// frame's ends, and a free-flight path is fitted to them: the same rotation, and the one
// parabola under the scene's gravity that joins the two centres (velocity
// (p1 - p0)/dt - g dt/2 at the start). For a body in free flight this is the path it
// flew; for one that collided within the frame the pair is exempt anyway, as in our run.
// Like ours, the fit cannot represent a body turning half a turn or more within a frame.
#include "../command_line.hpp"

#include <gjkx/mesh/triangle_mesh.hpp>
#include <gjkx/timewarp/body.hpp>
#include <gjkx/timewarp/scene.hpp>
#include <gjkx/verify/frame_verifier.hpp>

#include <BulletCollision/CollisionShapes/btBoxShape.h>
#include <BulletCollision/CollisionShapes/btBvhTriangleMeshShape.h>
#include <BulletCollision/CollisionShapes/btCapsuleShape.h>
#include <BulletCollision/CollisionShapes/btCompoundShape.h>
#include <BulletCollision/CollisionShapes/btConvexHullShape.h>
#include <BulletCollision/CollisionShapes/btSphereShape.h>
#include <BulletCollision/CollisionShapes/btTriangleIndexVertexArray.h>
#include <LinearMath/btGeometryUtil.h>
#include <btBulletDynamicsCommon.h>

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <set>
#include <utility>
#include <vector>

namespace {

using Clock = std::chrono::steady_clock;

btVector3 toBullet(const Eigen::Vector3d& v) { return btVector3(btScalar(v.x()), btScalar(v.y()), btScalar(v.z())); }
Eigen::Vector3d fromBullet(const btVector3& v) { return Eigen::Vector3d(v.x(), v.y(), v.z()); }
btMatrix3x3 toBullet(const Eigen::Matrix3d& m) {
  return btMatrix3x3(btScalar(m(0, 0)), btScalar(m(0, 1)), btScalar(m(0, 2)), btScalar(m(1, 0)), btScalar(m(1, 1)),
                     btScalar(m(1, 2)), btScalar(m(2, 0)), btScalar(m(2, 1)), btScalar(m(2, 2)));
}
Eigen::Matrix3d fromBullet(const btMatrix3x3& m) {
  Eigen::Matrix3d out;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) out(r, c) = m[r][c];
  return out;
}

/// Bullet's largest collision margin, its default (0.04 world units).
constexpr double kBulletDefaultMargin = 0.04;

/// A convex hull for Bullet whose rounded shape (hull plus margin) is the given hull.
struct HullForBullet {
  std::vector<btVector3> points;  ///< the hull shrunk by `margin` (or the hull itself when margin is 0)
  double margin = 0;              ///< the margin Bullet adds back around it
  double thickness = 0;           ///< the hull's least width over its face normals
};

/// Bullet adds a convex hull's margin *outside* its points: a btConvexHullShape of the
/// given points is larger by its margin all round (the Bullet manual's "collision margin"
/// section; a box's margin, by contrast, lies inside its half extents). Bullet's
/// convex-decomposition demo therefore shrinks each hull's face planes by the margin
/// (btGeometryUtil) and lets the margin round the result back out; we do the same, so
/// that the shape Bullet collides is our piece with its edges rounded by the margin. The
/// margin is Bullet's default 0.04, but at most a tenth of the hull's thickness: a thin
/// piece would vanish under a 0.04 shrink. Bullet's GJK/EPA wants some margin (it finds
/// penetration depths on the shrunk core), so we keep one rather than set it to zero.
HullForBullet hullForBullet(const std::vector<Eigen::Vector3d>& vertices) {
  btAlignedObjectArray<btVector3> points, planes;
  for (const auto& v : vertices) points.push_back(toBullet(v));
  btGeometryUtil::getPlaneEquationsFromVertices(points, planes);
  HullForBullet out;
  double thickness = std::numeric_limits<double>::infinity();
  for (int p = 0; p < planes.size(); ++p) {
    double width = 0;  // Bullet's planes: n.x + d <= 0 inside
    for (int v = 0; v < points.size(); ++v) width = std::max(width, -double(planes[p].dot(points[v]) + planes[p][3]));
    thickness = std::min(thickness, width);
  }
  out.thickness = std::isfinite(thickness) ? thickness : 0;
  out.margin = std::min(kBulletDefaultMargin, 0.1 * out.thickness);
  if (out.margin > 0) {
    btAlignedObjectArray<btVector3> shifted, shrunk;
    for (int p = 0; p < planes.size(); ++p) {
      btVector3 plane = planes[p];
      plane[3] += btScalar(out.margin);
      shifted.push_back(plane);
    }
    btGeometryUtil::getVerticesFromPlaneEquations(shifted, shrunk);
    for (int v = 0; v < shrunk.size(); ++v) out.points.push_back(shrunk[v]);
  }
  if (out.points.size() < 4) {  // nothing left to shrink: the hull itself, without margin
    out.points.clear();
    for (int v = 0; v < points.size(); ++v) out.points.push_back(points[v]);
    out.margin = 0;
  }
  return out;
}

/// A body as Bullet holds it, with what it takes to go back to our body frame.
struct BulletBody {
  std::unique_ptr<btCollisionShape> shape;
  std::vector<std::unique_ptr<btCollisionShape>> children;  ///< a compound's pieces
  std::unique_ptr<btTriangleIndexVertexArray> triangles;     ///< a static mesh's triangles (Bullet keeps pointers)
  std::vector<int> indices;                                  ///< their storage
  std::vector<btScalar> vertices;
  std::unique_ptr<btRigidBody> rigid;
  /// Bullet's body frame is our body frame (origin at the centre of mass) turned onto the
  /// principal axes of inertia: bodyFromPrincipal, a rotation (identity when ours are).
  Eigen::Matrix3d bodyFromPrincipal = Eigen::Matrix3d::Identity();
  /// Half the body's least thickness (CCD's swept sphere and motion threshold).
  double halfThickness = 0;
};

/// Our inertia in Bullet's terms: Bullet takes a diagonal inertia in the body's own axes.
/// Our body frame is at the centre of mass but along the shape's axes, where a polytope or
/// a mesh has products of inertia; their principal axes (the eigenvectors, turned to a
/// right-handed frame) become Bullet's body axes. A diagonal inertia keeps our axes.
std::pair<Eigen::Matrix3d, Eigen::Vector3d> principalAxes(const Eigen::Matrix3d& inertia) {
  const Eigen::Matrix3d off = inertia - Eigen::Matrix3d(inertia.diagonal().asDiagonal());
  if (off.cwiseAbs().maxCoeff() <= 1e-12 * inertia.trace()) return {Eigen::Matrix3d::Identity(), inertia.diagonal()};
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(inertia);
  Eigen::Matrix3d axes = solver.eigenvectors();
  if (axes.determinant() < 0) axes.col(2) = -axes.col(2);
  return {axes, solver.eigenvalues()};
}

/// The vertices of a convex piece, in Bullet's body frame.
std::vector<Eigen::Vector3d> principalVertices(const gjkx::Shape<double>& piece, const Eigen::Matrix3d& bodyFromPrincipal) {
  const auto& polytope = std::get<gjkx::Polytope<double>>(piece.variant());
  std::vector<Eigen::Vector3d> out;
  for (int v = 0; v < polytope.vertexCount(); ++v) out.push_back(bodyFromPrincipal.transpose() * polytope.vertex(v));
  return out;
}

/// A convex hull shape for Bullet from our piece (shrunk by its margin, see hullForBullet).
std::unique_ptr<btCollisionShape> hullShape(const std::vector<Eigen::Vector3d>& vertices, double& halfThickness) {
  const HullForBullet hull = hullForBullet(vertices);
  auto shape = std::make_unique<btConvexHullShape>();
  for (const auto& p : hull.points) shape->addPoint(p, false);
  shape->recalcLocalAabb();
  shape->setMargin(btScalar(hull.margin));
  halfThickness = 0.5 * hull.thickness;
  return shape;
}

/// The Bullet shape of body `index`: the same shape as ours, in Bullet's body frame.
void buildShape(const gjkx::Scene& scene, std::size_t index, const gjkx::WorldBody& body, BulletBody& out) {
  const gjkx::BodySpec& spec = scene.bodies[index];
  const Eigen::Matrix3d& P = out.bodyFromPrincipal;
  switch (spec.shape.kind) {
    case gjkx::ShapeSpec::Kind::Box: {
      // A box keeps its extents: Bullet puts a box's margin inside them. The default 0.04
      // is larger than a thin box's half thickness (a domino's is 0.02), so the margin is at
      // most a tenth of the smallest half extent.
      const Eigen::Vector3d h = spec.shape.halfExtents;
      auto box = std::make_unique<btBoxShape>(toBullet(h));
      box->setMargin(btScalar(std::min(kBulletDefaultMargin, 0.1 * h.minCoeff())));
      out.halfThickness = h.minCoeff();
      out.shape = std::move(box);
      return;
    }
    case gjkx::ShapeSpec::Kind::Sphere:  // a sphere's and a capsule's margin is their radius: nothing to set
      out.shape = std::make_unique<btSphereShape>(btScalar(spec.shape.radius));
      out.halfThickness = spec.shape.radius;
      return;
    case gjkx::ShapeSpec::Kind::Capsule:
      // Our capsule's axis is the body's z (scene.hpp); Bullet's "height" is the length of
      // the segment between the two hemispheres' centres.
      out.shape = std::make_unique<btCapsuleShapeZ>(btScalar(spec.shape.radius), btScalar(2 * spec.shape.halfLength));
      out.halfThickness = spec.shape.radius;
      return;
    case gjkx::ShapeSpec::Kind::Polytope:
      out.shape = hullShape(principalVertices(body.pieces[0], P), out.halfThickness);
      return;
    case gjkx::ShapeSpec::Kind::Mesh: break;
  }
  if (!spec.isStatic) {
    // A moving mesh: a compound of the very convex pieces our world uses (Bullet's advice
    // for a dynamic concave body is a compound of convex hulls).
    auto compound = std::make_unique<btCompoundShape>();
    out.halfThickness = std::numeric_limits<double>::infinity();
    for (const auto& piece : body.pieces) {
      double half = 0;
      out.children.push_back(hullShape(principalVertices(piece, P), half));
      out.halfThickness = std::min(out.halfThickness, half);
      btTransform identity;
      identity.setIdentity();
      compound->addChildShape(identity, out.children.back().get());
    }
    out.shape = std::move(compound);
    return;
  }
  // A static mesh: its triangles in a btBvhTriangleMeshShape, Bullet's usual static
  // environment (a static body's frame is the scene's: no centre of mass to move to).
  const std::string& given = spec.shape.meshPath;
  const std::string path = !given.empty() && given[0] == '/' ? given : scene.folder + "/" + given;
  const gjkx::TriangleMesh mesh = gjkx::readMesh(path);
  for (const auto& v : mesh.vertices)
    for (int k = 0; k < 3; ++k) out.vertices.push_back(btScalar(v[k]));
  for (const auto& t : mesh.triangles) out.indices.insert(out.indices.end(), t.begin(), t.end());
  out.triangles = std::make_unique<btTriangleIndexVertexArray>(int(mesh.triangles.size()), out.indices.data(),
                                                               int(3 * sizeof(int)), int(mesh.vertices.size()),
                                                               out.vertices.data(), int(3 * sizeof(btScalar)));
  out.shape = std::make_unique<btBvhTriangleMeshShape>(out.triangles.get(), true);
}

/// btDiscreteDynamicsWorld with its predictive (CCD) manifolds readable: Bullet keeps the
/// contacts that continuous collision detection creates apart from the dispatcher's.
class BulletWorld : public btDiscreteDynamicsWorld {
 public:
  using btDiscreteDynamicsWorld::btDiscreteDynamicsWorld;
  /// The manifolds of the last step's continuous collision detection.
  const btAlignedObjectArray<btPersistentManifold*>& predictiveManifolds() const { return m_predictiveManifolds; }
};

/// What the internal-step callback gathers: the body pairs Bullet had a contact point for.
struct ContactLog {
  std::set<std::pair<int, int>> pairs;
};

void recordManifold(const btPersistentManifold* m, ContactLog& log) {
  if (m->getNumContacts() == 0) return;
  const int a = m->getBody0()->getUserIndex(), b = m->getBody1()->getUserIndex();
  if (a >= 0 && b >= 0 && a != b) log.pairs.insert({std::min(a, b), std::max(a, b)});
}

/// Called by Bullet after each internal step: every pair with a contact point in it.
void afterStep(btDynamicsWorld* world, btScalar) {
  auto* log = static_cast<ContactLog*>(world->getWorldUserInfo());
  btDispatcher* dispatcher = world->getDispatcher();
  for (int k = 0; k < dispatcher->getNumManifolds(); ++k) recordManifold(dispatcher->getManifoldByIndexInternal(k), *log);
  const auto& predictive = static_cast<BulletWorld*>(world)->predictiveManifolds();
  for (int k = 0; k < predictive.size(); ++k) recordManifold(predictive[k], *log);
}

/// Whether Bullet's narrow phase finds a contact point between two bodies where they are
/// now. Bullet detects collisions at the start of a step, before it moves the bodies: a
/// contact that arises in a frame's last step is found (and answered) at the start of the
/// next frame's first. The query (btCollisionWorld::contactPairTest) leaves the world's
/// manifolds untouched, so it does not change Bullet's run.
bool touchesAtEnd(btCollisionWorld& world, btCollisionObject& a, btCollisionObject& b) {
  struct Found : btCollisionWorld::ContactResultCallback {
    bool any = false;
    btScalar addSingleResult(btManifoldPoint&, const btCollisionObjectWrapper*, int, int, const btCollisionObjectWrapper*,
                             int, int) override {
      any = true;
      return 0;
    }
  } found;
  world.contactPairTest(&a, &b, found);
  return found.any;
}

/// A body's pose in our body frame, from Bullet's.
gjkx::Pose<double> ourPose(const btRigidBody& rigid, const BulletBody& body) {
  const btTransform& t = rigid.getWorldTransform();
  gjkx::Pose<double> pose;
  pose.rotation = fromBullet(t.getBasis()) * body.bodyFromPrincipal.transpose();
  // Bullet works in float: make the rotation orthonormal again for the checks.
  pose.rotation = Eigen::Quaterniond(pose.rotation).normalized().toRotationMatrix();
  pose.translation = fromBullet(t.getOrigin());
  return pose;
}

/// The free-flight path that joins two poses over [t0, t1] (see the file's head).
gjkx::Motion<double> fittedPath(const gjkx::Pose<double>& from, const gjkx::Pose<double>& to, const Eigen::Vector3d& gravity,
                                double t0, double t1) {
  const double dt = t1 - t0;
  const Eigen::Vector3d velocity = (to.translation - from.translation) / dt - 0.5 * gravity * dt;
  return gjkx::Motion<double>::freeFlight(from, velocity, gravity, to.rotation, t0, t1);
}

/// A body's path over the frame as the checks take it: the fitted free-flight path, its
/// centre's velocity at both ends (a parabola's: v0 and v0 + g dt) and the slerp's constant
/// turning rate as its spin at both ends.
gjkx::PathPiece checkedPath(const gjkx::Motion<double>& motion, const gjkx::Pose<double>& from,
                            const gjkx::Pose<double>& to, double t0, double t1) {
  gjkx::FreeFlight path;
  path.t0 = t0;
  path.t1 = t1;
  path.motion = motion;
  path.start.worldFromBody = from;
  path.end.worldFromBody = to;
  if (const auto* f = std::get_if<gjkx::FreeFlightPath<double>>(&motion.variant())) {
    path.start.velocity = f->velocity;
    path.end.velocity = f->velocity + f->acceleration * (t1 - t0);
    const double spin = motion.bound().angularSpeed;
    path.start.angularVelocity = path.end.angularVelocity = Eigen::Vector3d(spin, 0, 0);
  }
  return {path, t1};
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Runs a gjkx scene file in Bullet (btDiscreteDynamicsWorld, CCD on every moving body) and measures "
               "penetration and tunnelling with the same independent checks as gjkx_simulate.",
               "gjkx_bullet_scene"};
  std::string scenePath, out = ".";
  int substeps = 0;
  bool noCcd = false, quiet = false;
  app.add_option("scene", scenePath, "the scene file (JSON)")->required();
  app.add_option("--out", out, "folder for frames.csv and bodies.csv (created)");
  app.add_option("--substeps", substeps,
                 "Bullet's internal steps per frame (default: enough for steps of at most 1/240 s)")
      ->check(CLI::Range(1, 100000));
  app.add_flag("--no-ccd", noCcd, "leave Bullet's continuous collision detection off");
  app.add_flag("--quiet", quiet, "no progress bar");
  chapter::parseOrExit(app, argc, argv);

  gjkx::Scene scene;
  std::vector<gjkx::WorldBody> bodies;
  std::unique_ptr<gjkx::FrameVerifier> verifier;
  try {
    scene = gjkx::loadScene(scenePath);
    bodies = gjkx::buildBodies(scene, gjkx::frameCount(scene) / scene.frameRate);
    // The checks' view of the bodies, prepared once (the plant's tree of 8,640 pieces); 5%
    // spare on the speed bound, for Bullet's float poses.
    verifier = std::make_unique<gjkx::FrameVerifier>(gjkx::verifiedBodies(bodies), scene.collisionTolerance,
                                                     scene.gravity, 1.05);
  } catch (const std::exception& e) {
    std::cerr << "gjkx_bullet_scene: " << e.what() << "\n";
    return 1;
  }
  const int frames = gjkx::frameCount(scene);
  const double frameDt = 1.0 / scene.frameRate;
  // Bullet's step: its manual's default internal step is 1/60 s, which its users are told to
  // shorten for accuracy; PyBullet, Bullet's own front end, steps 1/240 s by default. So:
  // at most 1/240 s, a whole number of steps per frame.
  if (substeps == 0) substeps = std::max(1, int(std::ceil(240.0 / scene.frameRate - 1e-9)));
  const double step = frameDt / substeps;

  // The world as Bullet's "hello world" builds it.
  btDefaultCollisionConfiguration configuration;
  btCollisionDispatcher dispatcher(&configuration);
  btDbvtBroadphase broadphase;
  btSequentialImpulseConstraintSolver solver;
  BulletWorld world(&dispatcher, &broadphase, &solver, &configuration);
  world.setGravity(toBullet(scene.gravity));
  ContactLog contacts;
  world.setInternalTickCallback(afterStep, &contacts);

  std::vector<BulletBody> bullet(bodies.size());
  try {
    for (std::size_t b = 0; b < bodies.size(); ++b) {
      const gjkx::WorldBody& body = bodies[b];
      BulletBody& bb = bullet[b];
      Eigen::Vector3d principal = Eigen::Vector3d::Zero();
      double mass = 0;
      if (!body.rigid.isStatic()) {
        // Our mass properties, about our centre of mass, on the principal axes.
        mass = body.rigid.massProperties().mass;
        std::tie(bb.bodyFromPrincipal, principal) = principalAxes(body.rigid.massProperties().inertia);
      }
      buildShape(scene, b, body, bb);
      const gjkx::BodyState start = body.path.stateAt(0.0);
      btTransform transform(toBullet(Eigen::Matrix3d(start.worldFromBody.rotation * bb.bodyFromPrincipal)),
                            toBullet(start.worldFromBody.translation));
      btRigidBody::btRigidBodyConstructionInfo info(btScalar(mass), nullptr, bb.shape.get(), toBullet(principal));
      info.m_startWorldTransform = transform;
      // Bullet combines two bodies' coefficients by multiplying them
      // (btManifoldResult::calculateCombinedRestitution and ...Friction): each body gets the
      // square root of the scene's, so that every pair has the scene's e and mu.
      info.m_restitution = btScalar(std::sqrt(scene.restitution));
      info.m_friction = btScalar(std::sqrt(scene.friction));
      bb.rigid = std::make_unique<btRigidBody>(info);
      bb.rigid->setUserIndex(int(b));
      if (!body.rigid.isStatic()) {
        bb.rigid->setLinearVelocity(toBullet(start.velocity));
        bb.rigid->setAngularVelocity(toBullet(start.angularVelocity));
        if (!noCcd) {
          // CCD as Bullet's CCD demo sets it up: it acts when a body moves farther in one
          // step than its motion threshold, sweeping a sphere that must lie inside the body
          // (the demo: threshold the half extent, sphere 0.9 of it). Ours: half the body's
          // least thickness (a mesh: its thinnest piece's), and 0.9 of that.
          bb.rigid->setCcdMotionThreshold(btScalar(bb.halfThickness));
          bb.rigid->setCcdSweptSphereRadius(btScalar(0.9 * bb.halfThickness));
        }
      }
      world.addRigidBody(bb.rigid.get());
    }
  } catch (const std::exception& e) {
    std::cerr << "gjkx_bullet_scene: " << e.what() << "\n";
    return 1;
  }

  std::filesystem::create_directories(out);
  std::ofstream framesCsv(out + "/frames.csv"), bodiesCsv(out + "/bodies.csv"), checksCsv(out + "/checks.csv");
  if (!framesCsv || !bodiesCsv || !checksCsv) {
    std::cerr << "gjkx_bullet_scene: cannot write to " << out << "\n";
    return 1;
  }
  framesCsv << "frame,time,wall_s,max_penetration,kinetic_energy,contact_pairs,tunnelled,checks_s\n";
  bodiesCsv << "frame,time,name,x,y,z,qw,qx,qy,qz,vx,vy,vz,wx,wy,wz,kinetic_energy\n";
  checksCsv << "frame,time,kind,body,other,depth\n";

  auto stateOf = [&](std::size_t b) {
    gjkx::BodyState s;
    s.worldFromBody = ourPose(*bullet[b].rigid, bullet[b]);
    s.velocity = fromBullet(bullet[b].rigid->getLinearVelocity());
    s.angularVelocity = fromBullet(bullet[b].rigid->getAngularVelocity());
    return s;
  };
  auto kineticEnergy = [&]() {
    double sum = 0;
    for (std::size_t b = 0; b < bodies.size(); ++b) sum += bodies[b].rigid.kineticEnergy(stateOf(b));
    return sum;
  };
  const double kineticStart = kineticEnergy();
  double kineticEnd = kineticStart, kineticMax = kineticStart, maxPenetration = 0, wall = 0;
  int tunnelled = 0;
  std::vector<gjkx::Pose<double>> before(bodies.size());
  for (std::size_t b = 0; b < bodies.size(); ++b) before[b] = ourPose(*bullet[b].rigid, bullet[b]);
  const bool bar = !quiet && isatty(fileno(stderr));

  try {
    for (int frame = 1; frame <= frames; ++frame) {
      const double T0 = double(frame - 1) * frameDt, T1 = double(frame) * frameDt;
      contacts.pairs.clear();
      const auto start = Clock::now();
      // One internal step per call: a time step equal to the fixed step is exactly one
      // step, with no time left over for Bullet to interpolate.
      for (int s = 0; s < substeps; ++s) world.stepSimulation(btScalar(step), 1, btScalar(step));
      const double frameWall = std::chrono::duration<double>(Clock::now() - start).count();
      wall += frameWall;

      // The checks (not timed as Bullet's work).
      const auto checksStart = Clock::now();
      std::vector<std::vector<gjkx::PathPiece>> paths(bodies.size());
      for (std::size_t b = 0; b < bodies.size(); ++b) {
        const gjkx::Pose<double> after = ourPose(*bullet[b].rigid, bullet[b]);
        const gjkx::Motion<double> motion = bodies[b].rigid.isStatic()
                                                ? gjkx::Motion<double>::fixed(after)
                                                : fittedPath(before[b], after, scene.gravity, T0, T1);
        paths[b].push_back(checkedPath(motion, before[b], after, T0, T1));
        before[b] = after;
      }
      const gjkx::FrameVerdict verdict = verifier->check(frame, T0, T1, paths, [&](int i, int j) {
        return contacts.pairs.count({i, j}) > 0 || touchesAtEnd(world, *bullet[i].rigid, *bullet[j].rigid);
      });
      for (const gjkx::Finding& f : verdict.findings) {
        const std::string& a = bodies[std::size_t(f.i)].name;
        const std::string& b = bodies[std::size_t(f.j)].name;
        checksCsv << f.frame << ',' << f.time << ',' << gjkx::findingName(f.kind) << ',' << a << ',' << b << ','
                  << f.depth << '\n';
        if (f.kind == gjkx::Finding::Kind::Tunnelling)
          std::cerr << "gjkx_bullet_scene: frame " << f.frame << ", t = " << f.time << ": '" << a << "' and '" << b
                    << "' interpenetrated with no contact\n";
      }
      const double penetration = verdict.maxPenetration;
      const int tunnelledNow = int(verdict.tunnelled);
      const double checks = std::chrono::duration<double>(Clock::now() - checksStart).count();
      maxPenetration = std::max(maxPenetration, penetration);
      tunnelled += tunnelledNow;
      kineticEnd = kineticEnergy();
      kineticMax = std::max(kineticMax, kineticEnd);
      framesCsv << frame << ',' << T1 << ',' << frameWall << ',' << penetration << ',' << kineticEnd << ','
                << contacts.pairs.size() << ',' << tunnelledNow << ',' << checks << '\n';
      for (std::size_t b = 0; b < bodies.size(); ++b) {
        const gjkx::BodyState s = stateOf(b);
        const Eigen::Vector3d x = s.worldFromBody(bodies[b].frameOrigin);  // the scene frame's origin
        const Eigen::Quaterniond q(s.worldFromBody.rotation);
        bodiesCsv << frame << ',' << T1 << ',' << bodies[b].name << ',' << x.x() << ',' << x.y() << ',' << x.z() << ','
                  << q.w() << ',' << q.x() << ',' << q.y() << ',' << q.z() << ',' << s.velocity.x() << ','
                  << s.velocity.y() << ',' << s.velocity.z() << ',' << s.angularVelocity.x() << ','
                  << s.angularVelocity.y() << ',' << s.angularVelocity.z() << ','
                  << bodies[b].rigid.kineticEnergy(s) << '\n';
      }
      if (bar) chapter::progress(frame, frames, wall);
    }
  } catch (const std::exception& e) {
    if (bar) std::fprintf(stderr, "\n");
    std::cerr << "gjkx_bullet_scene: " << e.what() << "\n";
    return 1;
  }
  if (bar) std::fprintf(stderr, "\n");
  for (auto& bb : bullet) world.removeRigidBody(bb.rigid.get());
  std::printf("SUMMARY frames=%d sim_s=%.6g wall_s=%.6g steps=%d max_penetration=%.6g tunnelled=%d "
              "kinetic_start=%.6g kinetic_end=%.6g kinetic_max=%.6g\n",
              frames, double(frames) * frameDt, wall, frames * substeps, maxPenetration, tunnelled, kineticStart,
              kineticEnd, kineticMax);
  return 0;
}
