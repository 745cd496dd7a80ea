// gjkx_ode_scene: runs a scene file (gjkx/timewarp/scene.hpp) in ODE, the Open Dynamics
// Engine (Debian's libode, 0.16, double precision), and measures the run with the same
// independent checks as gjkx_simulate --checks and gjkx_bullet_scene (peer_run.hpp).
//
//   gjkx_ode_scene SCENE.json [--out DIR] [--substeps N] [--duration S] [--quiet]
//
// writes DIR/frames.csv, DIR/bodies.csv, DIR/checks.csv and the SUMMARY line exactly as
// gjkx_bullet_scene does (peer_run::measure). wall_s is ODE's time alone (collision
// detection and the step); a scene with bad input exits 1 with a message naming the body
// and the field, a bad command line 2.
//
// The same bodies, built by gjkx::buildBodies as our world builds them. ODE takes a full
// inertia tensor about the centre of mass (dMassSetParameters), so its body frame is ours
// (no turn onto principal axes, unlike Bullet and MuJoCo). A box, sphere, capsule or
// cylinder is ODE's geom of that kind (a capsule's and a cylinder's axis is z in both; ODE's
// length is the distance between the caps' centres, twice our half length); a polytope and
// each convex piece of a mesh (a moving mesh's decomposition, a static mesh's thin prism per
// triangle, the pieces our world collides) is a dConvex of its hull's triangles. A static
// body's geoms have no ODE body; static geoms are not tested against each other (category
// bits).
//
// The step as ODE's users step it: every step, dSpaceCollide over a hash space makes a
// contact joint for each contact point (at most 8 per geom pair), dWorldQuickStep (its
// iterative solver, 20 iterations, for many bodies) steps the world, and the contacts are
// dropped. Contacts take the pair's mu as our world combines the bodies' (the geometric
// mean; a friction pyramid, dContactApprox1) and its restitution e (the larger;
// dContactBounce, above 1 cm/s); ERP and CFM are ODE's defaults (0.2 and 1e-5). The step
// is that of gjkx_bullet_scene, at most 1/240 s, a whole number a frame. ODE has no
// continuous collision detection. A pair counts as in contact in a frame when any step
// made a contact joint for it, or when ODE's collision detection finds it touching where
// the bodies are at the frame's end (untimed).
#include "../command_line.hpp"
#include "peer_run.hpp"

#include <gjkx/support_mapping/convex_hull.hpp>

#include <ode/ode.h>

#include <algorithm>
#include <cstdint>
#include <cmath>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

namespace {

/// Contact points asked of one geom pair.
constexpr int kMaxContacts = 8;

/// A dConvex's arrays, which ODE keeps pointers to (they must outlive the geom).
struct ConvexData {
  std::vector<dReal> planes, points;
  std::vector<unsigned> polygons;
};

/// What the collision callback needs.
struct Stepper {
  dWorldID world = nullptr;
  dJointGroupID contacts = nullptr;
  peer_run::ContactPairs* pairs = nullptr;  ///< where the pairs in contact go
  bool makeJoints = true;                   ///< false: only find the pairs (the check at a frame's end)
  std::vector<double> friction, restitution;  ///< each scene body's (its own, or the scene's)
};

/// The scene body a geom belongs to (its data: index + 1).
int bodyOf(dGeomID g) { return int(reinterpret_cast<std::intptr_t>(dGeomGetData(g))) - 1; }

/// dSpaceCollide's callback: contact joints for every contact point of a pair.
void nearCallback(void* data, dGeomID a, dGeomID b) {
  auto* s = static_cast<Stepper*>(data);
  dContact contact[kMaxContacts];
  const int n = dCollide(a, b, kMaxContacts, &contact[0].geom, sizeof(dContact));
  if (n == 0) return;
  peer_run::addPair(*s->pairs, bodyOf(a), bodyOf(b));
  if (!s->makeJoints) return;
  // A pair's coefficients as our world combines them: the geometric mean of the two
  // frictions, the larger restitution.
  const auto i = std::size_t(bodyOf(a)), j = std::size_t(bodyOf(b));
  for (int k = 0; k < n; ++k) {
    contact[k].surface.mode = dContactBounce | dContactApprox1;
    contact[k].surface.mu = std::sqrt(s->friction[i] * s->friction[j]);
    contact[k].surface.bounce = std::max(s->restitution[i], s->restitution[j]);
    contact[k].surface.bounce_vel = 0.01;
    dJointAttach(dJointCreateContact(s->world, s->contacts, &contact[k]), dGeomGetBody(a), dGeomGetBody(b));
  }
}

/// A dConvex of a convex piece (its vertices in the body frame): its hull's triangles,
/// each a face with its outward plane.
dGeomID convexGeom(dSpaceID space, const gjkx::Shape<double>& piece, ConvexData& data) {
  std::vector<Eigen::Vector3d> vertices = peer_run::principalVertices(piece, Eigen::Matrix3d::Identity());
  const gjkx::ConvexHull hull = gjkx::convexHull3d(vertices, "piece");
  for (const Eigen::Vector3d& v : hull.vertices) data.points.insert(data.points.end(), {v.x(), v.y(), v.z()});
  for (const auto& t : hull.triangles) {
    const Eigen::Vector3d& p = hull.vertices[std::size_t(t[0])];
    const Eigen::Vector3d n =
        (hull.vertices[std::size_t(t[1])] - p).cross(hull.vertices[std::size_t(t[2])] - p).normalized();
    data.planes.insert(data.planes.end(), {n.x(), n.y(), n.z(), n.dot(p)});
    data.polygons.insert(data.polygons.end(), {3u, unsigned(t[0]), unsigned(t[1]), unsigned(t[2])});
  }
  return dCreateConvex(space, data.planes.data(), unsigned(data.planes.size() / 4), data.points.data(),
                       unsigned(data.points.size() / 3), data.polygons.data());
}

/// ODE's rotation matrix (3 rows of 4) of ours.
void toOde(const Eigen::Matrix3d& r, dMatrix3 out) {
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) out[4 * i + j] = r(i, j);
    out[4 * i + 3] = 0;
  }
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Runs a gjkx scene file in ODE (dWorldQuickStep, convex geoms from the same pieces) and measures "
               "penetration and tunnelling with the same independent checks as gjkx_simulate.",
               "gjkx_ode_scene"};
  peer_run::CommandLine options;
  options.addTo(app, "enough for steps of at most 1/240 s");
  chapter::parseOrExit(app, argc, argv);
  peer_run::PeerScene loaded;
  if (!options.load("gjkx_ode_scene", loaded)) return 1;
  int substeps = options.substeps;
  const gjkx::Scene& scene = loaded.scene;
  if (substeps == 0) substeps = std::max(1, int(std::ceil(240.0 / scene.frameRate - 1e-9)));
  const double step = loaded.frameDt / substeps;

  dInitODE2(0);
  Stepper stepper;
  stepper.world = dWorldCreate();
  dWorldSetGravity(stepper.world, scene.gravity.x(), scene.gravity.y(), scene.gravity.z());
  dSpaceID space = dHashSpaceCreate(nullptr);
  stepper.contacts = dJointGroupCreate(0);
  for (const gjkx::BodySpec& spec : scene.bodies) {
    stepper.friction.push_back(spec.friction >= 0 ? spec.friction : scene.friction);
    stepper.restitution.push_back(spec.restitution >= 0 ? spec.restitution : scene.restitution);
  }
  std::vector<dBodyID> ode(loaded.bodies.size(), nullptr);
  std::vector<std::unique_ptr<ConvexData>> convexData;
  try {
    for (std::size_t b = 0; b < loaded.bodies.size(); ++b) {
      const gjkx::WorldBody& body = loaded.bodies[b];
      const gjkx::ShapeSpec& shape = scene.bodies[b].shape;
      const gjkx::BodyState start = body.path.stateAt(0.0);
      dMatrix3 rotation;
      toOde(start.worldFromBody.rotation, rotation);
      const Eigen::Vector3d& p = start.worldFromBody.translation;
      if (!body.rigid.isStatic()) {
        ode[b] = dBodyCreate(stepper.world);
        const Eigen::Matrix3d& I = body.rigid.massProperties().inertia;
        dMass mass;
        dMassSetParameters(&mass, body.rigid.massProperties().mass, 0, 0, 0, I(0, 0), I(1, 1), I(2, 2), I(0, 1),
                           I(0, 2), I(1, 2));
        dBodySetMass(ode[b], &mass);
        dBodySetPosition(ode[b], p.x(), p.y(), p.z());
        dBodySetRotation(ode[b], rotation);
        dBodySetLinearVel(ode[b], start.velocity.x(), start.velocity.y(), start.velocity.z());
        dBodySetAngularVel(ode[b], start.angularVelocity.x(), start.angularVelocity.y(), start.angularVelocity.z());
      }
      std::vector<dGeomID> geoms;
      switch (shape.kind) {
        case gjkx::ShapeSpec::Kind::Box:
          geoms.push_back(dCreateBox(space, 2 * shape.halfExtents.x(), 2 * shape.halfExtents.y(), 2 * shape.halfExtents.z()));
          break;
        case gjkx::ShapeSpec::Kind::Sphere: geoms.push_back(dCreateSphere(space, shape.radius)); break;
        case gjkx::ShapeSpec::Kind::Capsule:
          geoms.push_back(dCreateCapsule(space, shape.radius, 2 * shape.halfLength));
          break;
        case gjkx::ShapeSpec::Kind::Cylinder:
          geoms.push_back(dCreateCylinder(space, shape.radius, 2 * shape.halfLength));
          break;
        case gjkx::ShapeSpec::Kind::Polytope:
        case gjkx::ShapeSpec::Kind::Mesh:
          for (const auto& piece : body.pieces) {
            convexData.push_back(std::make_unique<ConvexData>());
            geoms.push_back(convexGeom(space, piece, *convexData.back()));
          }
          break;
      }
      for (dGeomID g : geoms) {
        dGeomSetData(g, reinterpret_cast<void*>(std::intptr_t(b + 1)));
        // Static geoms (category 1) meet only moving ones (category 2).
        dGeomSetCategoryBits(g, body.rigid.isStatic() ? 1 : 2);
        dGeomSetCollideBits(g, body.rigid.isStatic() ? 2 : 3);
        if (ode[b]) {
          dGeomSetBody(g, ode[b]);
        } else {
          dGeomSetPosition(g, p.x(), p.y(), p.z());
          dGeomSetRotation(g, rotation);
        }
      }
    }
  } catch (const std::exception& e) {
    std::cerr << "gjkx_ode_scene: " << e.what() << "\n";
    return 1;
  }

  peer_run::Peer peer;
  peer.state = [&](std::size_t b) {
    if (!ode[b]) return loaded.bodies[b].path.stateAt(0.0);
    gjkx::BodyState s;
    const dReal* x = dBodyGetPosition(ode[b]);
    const dReal* q = dBodyGetQuaternion(ode[b]);  // w, x, y, z
    const dReal* v = dBodyGetLinearVel(ode[b]);
    const dReal* w = dBodyGetAngularVel(ode[b]);
    s.worldFromBody.rotation = Eigen::Quaterniond(q[0], q[1], q[2], q[3]).normalized().toRotationMatrix();
    s.worldFromBody.translation = Eigen::Vector3d(x[0], x[1], x[2]);
    s.velocity = Eigen::Vector3d(v[0], v[1], v[2]);
    s.angularVelocity = Eigen::Vector3d(w[0], w[1], w[2]);
    return s;
  };
  peer_run::ContactPairs atEnd;
  bool atEndKnown = false;
  peer.stepFrame = [&](peer_run::ContactPairs& pairs) {
    stepper.pairs = &pairs;
    stepper.makeJoints = true;
    for (int s = 0; s < substeps; ++s) {
      dSpaceCollide(space, &stepper, nearCallback);
      dWorldQuickStep(stepper.world, step);
      dJointGroupEmpty(stepper.contacts);
    }
    atEndKnown = false;
  };
  peer.touchingAtEnd = [&](int i, int j) {
    if (!atEndKnown) {  // once a frame: collision detection where the bodies are now, no joints made
      atEnd.clear();
      stepper.pairs = &atEnd;
      stepper.makeJoints = false;
      dSpaceCollide(space, &stepper, nearCallback);
      atEndKnown = true;
    }
    return atEnd.count({i, j}) > 0;
  };
  const int status = peer_run::measure("gjkx_ode_scene", loaded, peer, substeps, options.out, options.quiet);
  dJointGroupDestroy(stepper.contacts);
  dSpaceDestroy(space);
  dWorldDestroy(stepper.world);
  dCloseODE();
  return status;
}
