// gjkx_bullet_scene: runs a scene file (gjkx/timewarp/scene.hpp) in Bullet, the rigid-body
// library most people would reach for, and measures the run with the same independent
// checks as gjkx_simulate --checks (gjkx/verify/frame_verifier.hpp), so that the two can be compared.
//
//   gjkx_bullet_scene SCENE.json [--out DIR] [--substeps N] [--duration S] [--no-ccd] [--quiet]
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
// (gjkx::FrameVerifier, through peer_run.hpp, which every peer's runner shares): the signed
// distance of every pair whose bounds meet, at the frame's end, by the reference (its
// negative is the penetration), and, for a pair Bullet had no contact point for during the
// frame, whether the pair interpenetrated (came closer than minus twice the collision
// tolerance) at any time of the frame, on the free-flight path fitted to Bullet's poses at
// the frame's ends (peer_run.hpp). Each finding is named on standard error and in
// DIR/checks.csv.
#include "../command_line.hpp"
#include "bullet_bodies.hpp"
#include "peer_run.hpp"

#include <gjkx/timewarp/body.hpp>
#include <gjkx/timewarp/scene.hpp>
#include <gjkx/verify/frame_verifier.hpp>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <memory>
#include <vector>

namespace {

using namespace bullet_bodies;

/// btDiscreteDynamicsWorld with its predictive (CCD) manifolds readable: Bullet keeps the
/// contacts that continuous collision detection creates apart from the dispatcher's.
class BulletWorld : public btDiscreteDynamicsWorld {
 public:
  using btDiscreteDynamicsWorld::btDiscreteDynamicsWorld;
  /// The manifolds of the last step's continuous collision detection.
  const btAlignedObjectArray<btPersistentManifold*>& predictiveManifolds() const { return m_predictiveManifolds; }
};

void recordManifold(const btPersistentManifold* m, peer_run::ContactPairs& log) {
  if (m->getNumContacts() == 0) return;
  peer_run::addPair(log, m->getBody0()->getUserIndex(), m->getBody1()->getUserIndex());
}

/// Called by Bullet after each internal step: every pair with a contact point in it (into
/// the world's user info, the frame's peer_run::ContactPairs).
void afterStep(btDynamicsWorld* world, btScalar) {
  auto* log = static_cast<peer_run::ContactPairs*>(world->getWorldUserInfo());
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

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Runs a gjkx scene file in Bullet (btDiscreteDynamicsWorld, CCD on every moving body) and measures "
               "penetration and tunnelling with the same independent checks as gjkx_simulate.",
               "gjkx_bullet_scene"};
  peer_run::CommandLine options;
  bool noCcd = false;
  options.addTo(app, "enough for steps of at most 1/240 s");
  app.add_flag("--no-ccd", noCcd, "leave Bullet's continuous collision detection off");
  chapter::parseOrExit(app, argc, argv);
  peer_run::PeerScene loaded;
  if (!options.load("gjkx_bullet_scene", loaded)) return 1;
  int substeps = options.substeps;
  const gjkx::Scene& scene = loaded.scene;
  const std::vector<gjkx::WorldBody>& bodies = loaded.bodies;
  const double frameDt = loaded.frameDt;
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
  world.setInternalTickCallback(afterStep, nullptr);  // its log: the frame's pairs, set by stepFrame below

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
      // With a body's own material (the scene file's per-body keys), the products are the
      // geometric means: ours for friction; ours for restitution is the larger of the two,
      // which Bullet's product cannot give, so such a scene differs there.
      const gjkx::BodySpec& spec = scene.bodies[b];
      info.m_restitution = btScalar(std::sqrt(spec.restitution >= 0 ? spec.restitution : scene.restitution));
      info.m_friction = btScalar(std::sqrt(spec.friction >= 0 ? spec.friction : scene.friction));
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

  peer_run::Peer peer;
  peer.stepFrame = [&](peer_run::ContactPairs& pairs) {
    world.setWorldUserInfo(&pairs);
    // One internal step per call: a time step equal to the fixed step is exactly one
    // step, with no time left over for Bullet to interpolate.
    for (int s = 0; s < substeps; ++s) world.stepSimulation(btScalar(step), 1, btScalar(step));
  };
  peer.state = [&](std::size_t b) {
    gjkx::BodyState s;
    s.worldFromBody = ourPose(*bullet[b].rigid, bullet[b]);
    s.velocity = fromBullet(bullet[b].rigid->getLinearVelocity());
    s.angularVelocity = fromBullet(bullet[b].rigid->getAngularVelocity());
    return s;
  };
  peer.touchingAtEnd = [&](int i, int j) {
    return touchesAtEnd(world, *bullet[std::size_t(i)].rigid, *bullet[std::size_t(j)].rigid);
  };
  const int status = peer_run::measure("gjkx_bullet_scene", loaded, peer, substeps, options.out, options.quiet);
  for (auto& bb : bullet) world.removeRigidBody(bb.rigid.get());
  return status;
}
