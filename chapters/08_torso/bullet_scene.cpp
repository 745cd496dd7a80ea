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
#include "bullet_bodies.hpp"

#include <gjkx/timewarp/body.hpp>
#include <gjkx/timewarp/scene.hpp>
#include <gjkx/verify/frame_verifier.hpp>

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

using namespace bullet_bodies;

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
