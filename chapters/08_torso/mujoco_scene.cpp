// gjkx_mujoco_scene: runs a scene file (gjkx/timewarp/scene.hpp) in MuJoCo, the simulator
// most used in research (Debian's libmujoco, 2.2), and measures the run with the same
// independent checks as gjkx_simulate --checks and gjkx_bullet_scene (peer_run.hpp).
//
//   gjkx_mujoco_scene SCENE.json [--out DIR] [--substeps N] [--duration S] [--max-contacts N] [--quiet]
//
// writes DIR/frames.csv, DIR/bodies.csv, DIR/checks.csv and the SUMMARY line exactly as
// gjkx_bullet_scene does (peer_run::measure), and DIR/model.xml, the MuJoCo model it ran.
// wall_s is MuJoCo's time alone (mj_step; the model's compilation and the checks are not in it).
// A scene with bad input exits 1 with a message naming the body and the field; a bad
// command line exits 2.
//
// The same bodies. The scene's bodies are built by gjkx::buildBodies as our world builds
// them, and the model is written from them as MJCF (MuJoCo's XML, the format its users
// write) and loaded with mj_loadXML:
// - a moving body is a <body> with a <freejoint/>, its frame at our centre of mass turned
//   onto the principal axes of our inertia (as for Bullet), and an explicit <inertial> with
//   our mass and principal moments (inertiafromgeom="false": MuJoCo computes none of its own);
// - a static body is a <body> without a joint (welded to the world) at its pose;
// - a box, sphere, capsule or cylinder is MuJoCo's geom of that type and size (a capsule's
//   and a cylinder's axis is z in both); a polytope, and each convex piece of a mesh (a
//   moving mesh's decomposition, a static mesh's one thin prism per triangle, the very pieces
//   our world collides), is a <mesh> asset of the piece's vertices: MuJoCo collides a mesh as
//   the convex hull of its vertices, which is our piece;
// - gravity is the scene's; friction is each geom's first friction coefficient, the
//   scene's mu (or the body's own; MuJoCo takes the larger of two geoms', where our world
//   takes the geometric mean, so only a scene with per-body friction differs).
// MuJoCo's contacts are soft (a spring-damper reference, solref, critically damped by
// default) and take no coefficient of restitution: the runner keeps MuJoCo's defaults, so a
// body does not bounce as the scene's restitution says. The rest is MuJoCo's defaults too:
// the semi-implicit Euler integrator, pyramidal friction cones, the Newton solver, no margin.
// --integrator implicit takes MuJoCo's implicit integrator instead (implicit in velocity,
// the gyroscopic terms included), for a scene where a body spins up: Euler integrates a
// free body's gyroscopic torque explicitly, and a light body with unequal principal moments
// spinning fast gains energy at every step until its accelerations blow up.
//
// The step. MuJoCo's default time step is 2 ms (its documentation's advice for stable
// contact), so the runner takes a whole number of steps per frame of at most 2 ms
// (21 a frame at 24 frames a second). MuJoCo has no continuous collision detection.
//
// MuJoCo resets a simulation whose accelerations blow up (mjWARN_BADQACC) to its start; the
// runner stops there with exit status 1 and says when, and which body, with its speed and
// spin before the step, rather than measure a run restarted.
//
// The contacts. MuJoCo 2.2 allocates its contact and constraint buffers once (the MJCF
// <size nconmax njmax>): the runner sizes them from the scene (--max-contacts, by default
// 10 per moving body and at least 500) and says on standard error if a step found more.
// A pair counts as in contact in a frame when any step's contact list held it; MuJoCo
// detects at the start of a step, so after a frame the runner also asks its collision
// detection where the bodies are now (mj_fwdPosition, which changes no state), untimed.
#include "../command_line.hpp"
#include "peer_run.hpp"

#include <mujoco/mujoco.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

/// MuJoCo's default time step (s), the longest the runner takes.
constexpr double kMuJoCoDefaultStep = 0.002;

/// How a scene body sits in the MuJoCo model.
struct MuJoCoBody {
  Eigen::Matrix3d bodyFromPrincipal = Eigen::Matrix3d::Identity();  ///< our body frame from MuJoCo's
  int qposAddress = -1;                                            ///< its free joint's place in qpos (-1: static)
  int dofAddress = -1;                                             ///< and in qvel
  gjkx::Pose<double> fixedPose;                                    ///< a static body's pose
};

/// Numbers as MJCF wants them, separated by spaces, with all the digits of a double.
std::string numbers(std::initializer_list<double> values) {
  std::ostringstream out;
  out.precision(17);
  bool first = true;
  for (double v : values) out << (first ? "" : " ") << v, first = false;
  return out.str();
}

/// A rotation as MJCF's quat attribute (w x y z).
std::string quatText(const Eigen::Matrix3d& rotation) {
  const Eigen::Quaterniond q(rotation);
  return numbers({q.w(), q.x(), q.y(), q.z()});
}

/// The <geom> elements (and <mesh> assets, appended to `assets`) of body `index`, in
/// MuJoCo's body frame (ours turned by bodyFromPrincipal), with friction `mu`.
std::string geomsOf(const gjkx::Scene& scene, std::size_t index, const gjkx::WorldBody& body,
                    const Eigen::Matrix3d& bodyFromPrincipal, double mu, std::string& assets) {
  const gjkx::ShapeSpec& shape = scene.bodies[index].shape;
  const std::string common =
      "friction=\"" + numbers({mu, 0.005, 0.0001}) + "\" quat=\"" + quatText(bodyFromPrincipal.transpose()) + "\"";
  switch (shape.kind) {
    case gjkx::ShapeSpec::Kind::Box:
      return "<geom type=\"box\" size=\"" + numbers({shape.halfExtents.x(), shape.halfExtents.y(), shape.halfExtents.z()}) +
             "\" " + common + "/>\n";
    case gjkx::ShapeSpec::Kind::Sphere:
      return "<geom type=\"sphere\" size=\"" + numbers({shape.radius}) + "\" " + common + "/>\n";
    case gjkx::ShapeSpec::Kind::Capsule:
      return "<geom type=\"capsule\" size=\"" + numbers({shape.radius, shape.halfLength}) + "\" " + common + "/>\n";
    case gjkx::ShapeSpec::Kind::Cylinder:
      return "<geom type=\"cylinder\" size=\"" + numbers({shape.radius, shape.halfLength}) + "\" " + common + "/>\n";
    case gjkx::ShapeSpec::Kind::Polytope:
    case gjkx::ShapeSpec::Kind::Mesh:
      break;
  }
  // Each convex piece a mesh asset of its vertices, already in MuJoCo's body frame. MuJoCo
  // moves a mesh to its own centre and axes and puts the geom there, so the piece stays
  // where its vertices say.
  std::string geoms;
  const std::string friction = "friction=\"" + numbers({mu, 0.005, 0.0001}) + "\"";
  for (std::size_t k = 0; k < body.pieces.size(); ++k) {
    const std::string name = "b" + std::to_string(index) + "_" + std::to_string(k);
    assets += "<mesh name=\"" + name + "\" vertex=\"";
    bool first = true;
    for (const Eigen::Vector3d& v : peer_run::principalVertices(body.pieces[k], bodyFromPrincipal))
      assets += (first ? "" : " ") + numbers({v.x(), v.y(), v.z()}), first = false;
    assets += "\"/>\n";
    geoms += "<geom type=\"mesh\" mesh=\"" + name + "\" " + friction + "/>\n";
  }
  return geoms;
}

/// The MJCF model of the scene (see the file's head), with `integrator` "euler" or
/// "implicit" (--integrator); fills `out` with each body's place.
std::string modelXml(const peer_run::PeerScene& loaded, double step, const std::string& integrator, int maxContacts,
                     std::vector<MuJoCoBody>& out) {
  const gjkx::Scene& scene = loaded.scene;
  std::string assets, world;
  out.assign(loaded.bodies.size(), MuJoCoBody{});
  for (std::size_t b = 0; b < loaded.bodies.size(); ++b) {
    const gjkx::WorldBody& body = loaded.bodies[b];
    const gjkx::BodySpec& spec = scene.bodies[b];
    MuJoCoBody& mb = out[b];
    Eigen::Vector3d principal = Eigen::Vector3d::Zero();
    if (!body.rigid.isStatic())
      std::tie(mb.bodyFromPrincipal, principal) = peer_run::principalAxes(body.rigid.massProperties().inertia);
    const gjkx::BodyState start = body.path.stateAt(0.0);
    mb.fixedPose = start.worldFromBody;
    const Eigen::Matrix3d rotation = start.worldFromBody.rotation * mb.bodyFromPrincipal;
    const Eigen::Vector3d& p = start.worldFromBody.translation;
    world += "<body name=\"body" + std::to_string(b) + "\" pos=\"" + numbers({p.x(), p.y(), p.z()}) + "\" quat=\"" +
             quatText(rotation) + "\">\n";
    if (!body.rigid.isStatic()) {
      world += "<freejoint/>\n<inertial pos=\"0 0 0\" mass=\"" + numbers({body.rigid.massProperties().mass}) +
               "\" diaginertia=\"" + numbers({principal.x(), principal.y(), principal.z()}) + "\"/>\n";
    }
    world += geomsOf(scene, b, body, mb.bodyFromPrincipal, spec.friction >= 0 ? spec.friction : scene.friction, assets);
    world += "</body>\n";
  }
  const Eigen::Vector3d& g = scene.gravity;
  // Four constraint rows a contact (a pyramidal cone of condim 3).
  const std::string mjcfIntegrator = integrator == "euler" ? "Euler" : "implicit";  // (MJCF's spelling)
  return "<mujoco model=\"gjkx scene\">\n<compiler angle=\"radian\" inertiafromgeom=\"false\"/>\n<option integrator=\"" +
         mjcfIntegrator + "\" timestep=\"" + numbers({step}) + "\" gravity=\"" + numbers({g.x(), g.y(), g.z()}) + "\"/>\n<size nconmax=\"" +
         std::to_string(maxContacts) + "\" njmax=\"" + std::to_string(4 * maxContacts) + "\"/>\n<asset>\n" + assets +
         "</asset>\n<worldbody>\n" + world + "</worldbody>\n</mujoco>\n";
}

/// The scene bodies of MuJoCo's contact list now (MuJoCo's body k + 1 is scene body k).
void contactPairs(const mjModel* m, const mjData* d, peer_run::ContactPairs& pairs) {
  for (int c = 0; c < d->ncon; ++c)
    peer_run::addPair(pairs, m->geom_bodyid[d->contact[c].geom1] - 1, m->geom_bodyid[d->contact[c].geom2] - 1);
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Runs a gjkx scene file in MuJoCo (free bodies, convex mesh geoms from the same pieces) and measures "
               "penetration and tunnelling with the same independent checks as gjkx_simulate.",
               "gjkx_mujoco_scene"};
  peer_run::CommandLine options;
  int maxContacts = 0;
  std::string integrator = "euler";
  options.addTo(app, "enough for steps of at most 2 ms");
  app.add_option("--integrator", integrator,
                 "MuJoCo's integrator: euler (semi-implicit, its default) or implicit (in velocity, the gyroscopic "
                 "terms included)")
      ->check(CLI::IsMember({"euler", "implicit"}));
  app.add_option("--max-contacts", maxContacts,
                 "MuJoCo's contact buffer (nconmax; default: 10 per moving body, at least 500)")
      ->check(CLI::Range(1, 1000000));
  chapter::parseOrExit(app, argc, argv);
  peer_run::PeerScene loaded;
  if (!options.load("gjkx_mujoco_scene", loaded)) return 1;
  int substeps = options.substeps;
  if (substeps == 0) substeps = std::max(1, int(std::ceil(loaded.frameDt / kMuJoCoDefaultStep - 1e-9)));
  if (maxContacts == 0) {
    int moving = 0;
    for (const auto& body : loaded.bodies) moving += body.rigid.isStatic() ? 0 : 1;
    maxContacts = std::max(500, 10 * moving);
  }
  std::vector<MuJoCoBody> place;
  const std::string xml = modelXml(loaded, loaded.frameDt / substeps, integrator, maxContacts, place);
  std::filesystem::create_directories(options.out);
  const std::string modelPath = options.out + "/model.xml";
  if (!(std::ofstream(modelPath) << xml)) {
    std::cerr << "gjkx_mujoco_scene: cannot write " << modelPath << "\n";
    return 1;
  }
  // MuJoCo reports a full buffer through its warning handler, which by default appends to
  // MUJOCO_LOG.TXT in the working folder: counted in mjData instead, and said once below.
  mju_user_warning = [](const char*) {};
  char error[1000] = "";
  std::unique_ptr<mjModel, void (*)(mjModel*)> model(mj_loadXML(modelPath.c_str(), nullptr, error, sizeof error),
                                                     mj_deleteModel);
  if (!model) {
    std::cerr << "gjkx_mujoco_scene: MuJoCo refused " << modelPath << ": " << error << "\n";
    return 1;
  }
  std::unique_ptr<mjData, void (*)(mjData*)> data(mj_makeData(model.get()), mj_deleteData);
  const mjModel* m = model.get();
  mjData* d = data.get();
  for (std::size_t b = 0; b < place.size(); ++b) {
    const int joint = m->body_jntadr[b + 1];
    if (joint < 0) continue;
    place[b].qposAddress = m->jnt_qposadr[joint];
    place[b].dofAddress = m->jnt_dofadr[joint];
  }

  peer_run::Peer peer;
  peer.state = [&](std::size_t b) {
    const MuJoCoBody& mb = place[b];
    gjkx::BodyState s;
    if (mb.qposAddress < 0) {
      s.worldFromBody = mb.fixedPose;
      return s;
    }
    const mjtNum* q = d->qpos + mb.qposAddress;
    const mjtNum* v = d->qvel + mb.dofAddress;
    const Eigen::Matrix3d rotation = Eigen::Quaterniond(q[3], q[4], q[5], q[6]).normalized().toRotationMatrix();
    s.worldFromBody.rotation = rotation * mb.bodyFromPrincipal.transpose();
    s.worldFromBody.translation = Eigen::Vector3d(q[0], q[1], q[2]);
    s.velocity = Eigen::Vector3d(v[0], v[1], v[2]);                       // the centre's, in the world frame
    s.angularVelocity = rotation * Eigen::Vector3d(v[3], v[4], v[5]);     // a free joint's spin is in the body frame
    return s;
  };
  // The scene's start velocities.
  for (std::size_t b = 0; b < place.size(); ++b) {
    if (place[b].qposAddress < 0) continue;
    const gjkx::BodyState start = loaded.bodies[b].path.stateAt(0.0);
    const mjtNum* q = d->qpos + place[b].qposAddress;
    const Eigen::Matrix3d rotation = Eigen::Quaterniond(q[3], q[4], q[5], q[6]).normalized().toRotationMatrix();
    const Eigen::Vector3d spin = rotation.transpose() * start.angularVelocity;
    mjtNum* v = d->qvel + place[b].dofAddress;
    for (int k = 0; k < 3; ++k) v[k] = start.velocity[k], v[3 + k] = spin[k];
  }
  // What the runner says when MuJoCo's accelerations blew up in the step from `time`: the
  // body of the degree of freedom MuJoCo names (its warning's info), with its mass and its
  // speed and spin before the step.
  std::vector<mjtNum> velocities;
  const auto blowUp = [&](double time) {
    std::string what;
    const int dof = d->warning[mjWARN_BADQACC].lastinfo;
    if (dof >= 0 && dof < m->nv && m->dof_bodyid[dof] >= 1) {
      const int b = m->dof_bodyid[dof] - 1;  // (MuJoCo's body k + 1 is scene body k)
      const mjtNum* v = velocities.data() + place[std::size_t(b)].dofAddress;
      char text[200];
      std::snprintf(text, sizeof text, " (%.3g kg; before the step %.3g m/s, spinning at %.3g rad/s)",
                    m->body_mass[b + 1], Eigen::Vector3d(v[0], v[1], v[2]).norm(),
                    Eigen::Vector3d(v[3], v[4], v[5]).norm());
      what = " in body '" + loaded.bodies[std::size_t(b)].name + "'" + text;
    }
    return "MuJoCo found its simulation unstable (bad accelerations, mjWARN_BADQACC)" + what + " at t = " +
           std::to_string(time) + " s and reset it to the start: the run stops here" +
           (integrator == "euler" ? " (--integrator implicit integrates a spin's gyroscopic terms implicitly)" : "");
  };
  peer_run::ContactPairs atEnd;
  bool atEndKnown = false;
  int mostContacts = 0, mostRows = 0;  // of a step: what the buffers had to hold
  peer.stepFrame = [&](peer_run::ContactPairs& pairs) {
    for (int s = 0; s < substeps; ++s) {
      const double before = d->time;
      velocities.assign(d->qvel, d->qvel + m->nv);  // (the reset below clears them)
      mj_step(m, d);
      // MuJoCo resets a simulation whose accelerations became NaN, infinite or huge (its
      // mjWARN_BADQACC) back to the model's start: what follows would be a new run.
      if (d->warning[mjWARN_BADQACC].number > 0) throw std::runtime_error(blowUp(before));
      contactPairs(m, d, pairs);  // the contacts the step found at its start and answered
      mostContacts = std::max(mostContacts, d->ncon);
      mostRows = std::max(mostRows, d->nefc);
    }
    atEndKnown = false;
  };
  peer.touchingAtEnd = [&](int i, int j) {
    if (!atEndKnown) {
      atEnd.clear();
      mj_fwdPosition(m, d);  // collision detection where the bodies are now; the next step redoes it
      contactPairs(m, d, atEnd);
      atEndKnown = true;
    }
    return atEnd.count({i, j}) > 0;
  };
  const int status = peer_run::measure("gjkx_mujoco_scene", loaded, peer, substeps, options.out, options.quiet);
  if (status == 0)
    std::cerr << "gjkx_mujoco_scene: at most " << mostContacts << " contacts (of " << m->nconmax << ") and " << mostRows
              << " constraint rows (of " << m->njmax << ") in a step\n";
  if (d->warning[mjWARN_CONTACTFULL].number > 0 || d->warning[mjWARN_CNSTRFULL].number > 0)
    std::cerr << "gjkx_mujoco_scene: MuJoCo's buffers were full in " << d->warning[mjWARN_CONTACTFULL].number
              << " steps (contacts) and " << d->warning[mjWARN_CNSTRFULL].number
              << " (constraints): contacts were dropped; run again with a larger --max-contacts\n";
  return status;
}
