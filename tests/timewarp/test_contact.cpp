// Resting contact under the hybrid model (contact_solver.hpp), against physics nobody here
// wrote: stacks and pyramids that stand within one collision tolerance (one of them kept
// awake), a heavy box on a
// light one, Coulomb friction that holds a box below its friction angle and lets it slide
// at g (sin θ − μ cos θ) above it, a ball that rolls at (5/7) g sin θ, a pushed box that
// stops after v² / (2 μ g), no energy from any contact solve, no bounce from a contact
// struck inside an interval, and the same run twice. (The manifold of overlapping pieces and
// the friction step, one at a time: test_contact_parts.cpp.)
//
// The hybrid advances contact groups by semi-implicit Euler (the solved velocity over the
// whole interval, as Box2D, Bullet and MuJoCo do), whose position under a constant
// acceleration a after n intervals is ½ a t² (1 + 1/n): the tests that compare a distance
// with ½ a t² within 2% run at 120 frames a second for 1 to 2 s (an error of 1/n, under 1%).
#include <gjkx/timewarp/contact_manifold.hpp>
#include <gjkx/timewarp/pile.hpp>
#include <gjkx/timewarp/scene.hpp>
#include <gjkx/timewarp/world.hpp>

#include <catch2/catch.hpp>

#include <cmath>
#include <string>
#include <tuple>

using namespace gjkx;

namespace {

const double tol = 3.4526698e-4;  // the scene's default collision tolerance
const double g = 9.81;

std::string box(const std::string& name, Eigen::Vector3d half, Eigen::Vector3d at, const std::string& extra = "") {
  char text[512];
  std::snprintf(text, sizeof text, R"({ "name": "%s", "shape": {"box": [%.9g, %.9g, %.9g]}, "position": [%.9g, %.9g, %.9g]%s })",
                name.c_str(), half.x(), half.y(), half.z(), at.x(), at.y(), at.z(), extra.c_str());
  return text;
}

const std::string floorBody = R"({ "name": "floor", "shape": {"box": [20, 20, 0.5]}, "position": [0, 0, -0.5], "static": true })";

/// The floor and a pyramid of unit boxes, one box deep: `rows` on the floor, one fewer on
/// each row above, `spacing` apart along x (centre to centre), the bottom row's centres at
/// `bottom` and each row 1.0001 above the last (a tenth of a millimetre apart).
std::vector<std::string> pyramid(int rows, double spacing, double bottom) {
  std::vector<std::string> bodies{floorBody};
  for (int row = 0; row < rows; ++row)
    for (int k = 0; k < rows - row; ++k)
      bodies.push_back(box("p" + std::to_string(row) + "_" + std::to_string(k), {0.5, 0.5, 0.5},
                           {(k - (rows - 1 - row) / 2.0) * spacing, 0, bottom + row * 1.0001}));
  return bodies;
}

Scene sceneOf(const std::string& settings, const std::vector<std::string>& bodies) {
  std::string list;
  for (const auto& b : bodies) list += (list.empty() ? "" : ", ") + b;
  return parseScene("{ " + settings + R"(, "bodies": [)" + list + "] }", "test");
}

/// What a run of a resting scene did: the deepest overlap of any two bodies at any frame's
/// end (or at the last only: RestRun) by the independent reference library, how far any
/// body moved after the first second (bodies placed touching or a little apart are first brought to the rest
/// separation, half a tolerance per contact: 0.7 mm up a stack of ten), and the world's counters.
struct Rest {
  double deepest = 0;
  double drift = 0;
  long collisions = 0, energyRises = 0, contactPoints = 0;
  bool asleep = false;  // every moving body asleep at the end
  long mostAsleep = 0;  // the most bodies asleep at any frame's end
};

/// How a scene is run by `rest`: the world's settings, and whether overlaps are read at
/// every frame's end or at the last only (the reference library over a pile of hundreds of
/// boxes at every frame would take most of a test's time).
struct RestRun {
  WorldSettings settings{};
  bool overlapsEveryFrame = true;
};

Rest rest(const Scene& scene, const RestRun& run = RestRun{}) {
  World world(scene, run.settings);
  const FrameVerifier verifier(verifiedBodies(world.bodies()), scene.collisionTolerance, scene.gravity);
  const int n = int(world.bodies().size());
  std::vector<Eigen::Vector3d> first;
  Rest out;
  const auto readOverlaps = [&] {
    for (int i = 0; i < n; ++i)
      for (int j = i + 1; j < n; ++j) {
        if ((world.positionOf(i) - world.positionOf(j)).norm() > world.bodies()[i].radius + world.bodies()[j].radius + 0.01)
          continue;
        const double d = verifier.signedDistance(i, world.stateOf(i).worldFromBody, j, world.stateOf(j).worldFromBody);
        out.deepest = std::max(out.deepest, -d);
      }
  };
  while (!world.done()) {
    const FrameReport r = world.step();
    out.collisions += r.counters.collisions;
    out.energyRises += r.counters.energyRises;
    out.contactPoints += r.counters.contactPoints;
    out.mostAsleep = std::max(out.mostAsleep, long(r.counters.sleeping));
    if (first.empty() && world.time() >= 1.0 - 1e-9)
      for (int b = 0; b < n; ++b) first.push_back(world.positionOf(b));
    for (std::size_t b = 0; b < first.size(); ++b)
      out.drift = std::max(out.drift, (world.positionOf(int(b)) - first[b]).norm());
    if (run.overlapsEveryFrame) readOverlaps();
  }
  if (!run.overlapsEveryFrame) readOverlaps();
  out.asleep = true;
  for (const WorldBody& b : world.bodies()) out.asleep = out.asleep && (b.rigid.isStatic() || b.asleep);
  return out;
}

/// A rotation about y by θ: the x axis goes down the slope, (cos θ, 0, −sin θ).
std::string tilted(double theta) {
  char text[128];
  std::snprintf(text, sizeof text, R"(, "orientation": [%.12g, 0, %.12g, 0])", std::cos(theta / 2), std::sin(theta / 2));
  return text;
}

/// How far body 1 has gone down a ramp tilted by θ (body 0), from where it started.
struct Slide {
  double distance = 0;
  double end = 0;
};

Slide slide(const Scene& scene, double theta, double until) {
  World world(scene, WorldSettings{});
  const Eigen::Vector3d down(std::cos(theta), 0, -std::sin(theta));
  const Eigen::Vector3d start = world.positionOf(1);
  Slide out;
  while (!world.done() && world.time() < until - 1e-9) world.step();
  out.distance = (world.positionOf(1) - start).dot(down);
  out.end = world.time();
  return out;
}

/// A ramp (static box 4 m long, its top face through the origin) tilted by θ, and a body on
/// it `lift` above its top face (along its normal), `along` down the slope from its middle.
std::vector<std::string> onRamp(double theta, const std::string& shape, double lift, const std::string& extra) {
  const Eigen::Vector3d normal(std::sin(theta), 0, std::cos(theta));
  const Eigen::Vector3d rampCentre = -0.5 * normal;
  const Eigen::Vector3d at = lift * normal;
  char text[512];
  std::snprintf(text, sizeof text, R"({ "name": "body", "shape": %s, "position": [%.12g, %.12g, %.12g]%s })", shape.c_str(),
                at.x(), at.y(), at.z(), extra.c_str());
  return {box("ramp", {4, 1, 0.5}, rampCentre, tilted(theta) + R"(, "static": true)"), text};
}

}  // namespace

TEST_CASE("hybrid: a stack of 10 boxes rests 10 s within one tolerance, then sleeps") {
  std::vector<std::string> bodies{floorBody};
  for (int k = 0; k < 10; ++k) bodies.push_back(box("box" + std::to_string(k), {0.5, 0.5, 0.5}, {0, 0, 0.5 + k * 1.0001}));
  const Rest r = rest(sceneOf(R"("duration": 10, "restitution": 0.5, "friction": 0.5)", bodies));
  INFO("deepest " << r.deepest << " m, drift " << r.drift << " m, " << r.collisions << " collisions");
  CHECK(r.deepest <= tol);
  CHECK(r.drift <= tol);
  CHECK(r.energyRises == 0);
  CHECK(r.contactPoints > 0);
  CHECK(r.asleep);
}

TEST_CASE("hybrid: a pyramid of 15 boxes rests within one tolerance") {
  const Rest r = rest(sceneOf(R"("duration": 5, "restitution": 0.5, "friction": 0.5)", pyramid(5, 1.05, 0.5)));
  INFO("deepest " << r.deepest << " m, drift " << r.drift << " m, " << r.collisions << " collisions");
  CHECK(r.deepest <= tol);
  CHECK(r.drift <= tol);
  CHECK(r.energyRises == 0);
}

TEST_CASE("hybrid: a pyramid of 20 rows kept awake stands still, within one tolerance") {
  // A wall one box deep, 20 boxes high: kept from sleeping, each of its solves must hold it
  // still again. Without shock propagation (contact_solver.cpp) what each level's solve left
  // closing added up the pile, and the whole wall rocked front to back, by millimetres
  // (StepTuning::shockSweeps = 0: a drift of 12 mm).
  // (Its overlaps are read at the end only: RestRun.)
  RestRun awake;
  awake.settings.tuning.settleSeconds = 1000;
  awake.overlapsEveryFrame = false;
  const Rest r = rest(sceneOf(R"("duration": 2, "restitution": 0.5, "friction": 0.5)", pyramid(20, 1.001, 0.5001)), awake);
  INFO("deepest at the end " << r.deepest << " m, drift after the first second " << r.drift << " m");
  CHECK(r.mostAsleep == 0);
  CHECK(r.deepest <= tol);
  CHECK(r.drift <= tol);
  CHECK(r.energyRises == 0);
}

TEST_CASE("hybrid: a box resting 8.5 m from the origin on a wide floor runs its frames (the look-ahead's window)") {
  // The box of gjkx_generate_pyramid's 20-row pyramid that stalled the narrow phase: brought
  // to the rest separation (half a tolerance), it is within the contact pair's band
  // (a quarter) by the float query and half a tolerance apart in double. The window that
  // checks a look-ahead's skipped time, asked with half that distance, was no narrower than
  // the query's own band and took the pair as a new contact at the same instant, for ever.
  const Scene scene = sceneOf(R"("duration": 0.25, "restitution": 0.5, "friction": 0.5)",
                              {R"({ "name": "floor", "shape": {"box": [60, 60, 0.5]}, "position": [0, 0, -0.5], "static": true })",
                               box("p0_1", {0.5, 0.5, 0.5}, {-8.5085, 0, 0.5001})});
  World world(scene, WorldSettings{});
  long checks = 0;
  while (!world.done()) {
    const FrameReport r = world.step();
    CHECK(r.status == FrameStatus::Done);
    checks += r.counters.collisionChecks;
  }
  CHECK(checks < 1000);
  CHECK(std::abs(world.positionOf(1).z() - 0.5) < tol);
}

TEST_CASE("hybrid: a box that lands slowly inside an interval is left to the next contact solve, no impulse") {
  // Released 2.5 tolerances above the floor (outside the contact band of 2), it falls into the
  // tolerance band at the end of the first interval at about 0.1 m/s, below the contact speed
  // (2 g dt, 0.2 m/s at 24 frames and 4 intervals a second): a landing, not a collision.
  const Scene scene = sceneOf(R"("duration": 1, "restitution": 0.5, "friction": 0.5)",
                              {floorBody, box("box", {0.5, 0.5, 0.5}, {0, 0, 0.5 + 2.5 * tol})});
  World world(scene, WorldSettings{});
  const FrameVerifier verifier(verifiedBodies(world.bodies()), scene.collisionTolerance, scene.gravity);
  long landings = 0, collisions = 0;
  double deepest = 0;
  while (!world.done()) {
    const FrameReport r = world.step();
    landings += r.counters.landings;
    collisions += r.counters.collisions;
    deepest = std::max(deepest, -verifier.signedDistance(0, world.stateOf(0).worldFromBody, 1, world.stateOf(1).worldFromBody));
  }
  INFO("landings " << landings << ", collisions " << collisions << ", deepest " << deepest << " m");
  CHECK(landings >= 1);
  CHECK(collisions == 0);
  CHECK(deepest <= 0);  // never nearer than touching
  CHECK(std::abs(world.positionOf(1).z() - (0.5 + 0.5 * tol)) < tol);  // held at the rest separation
  // The paper's model strikes it: a train of microcollisions.
  const Scene paper = sceneOf(R"("duration": 1, "restitution": 0.5, "friction": 0.5, "contact": "microcollisions")",
                              {floorBody, box("box", {0.5, 0.5, 0.5}, {0, 0, 0.5 + 2.5 * tol})});
  World struck(paper, WorldSettings{});
  long paperCollisions = 0, paperLandings = 0;
  while (!struck.done()) {
    const FrameReport r = struck.step();
    paperCollisions += r.counters.collisions;
    paperLandings += r.counters.landings;
  }
  CHECK(paperCollisions > 0);
  CHECK(paperLandings == 0);
}

TEST_CASE("hybrid: a bar spinning at 400 rad/s flies in steps of its own and strikes the floor where kinematics says") {
  // A bar 1 m long turning end over end about y (a stable principal axis: torque-free, ω stays)
  // while it falls: 2.65 turns a frame, far more than a path can hold. Under both models it
  // flies an eighth of a turn at a time (its own steps: under microcollisions it spins faster
  // than StepTuning::spinIntervals eighths of a turn a frame); neither may restart a frame, and
  // both must strike the floor when its lowest corner first comes within the tolerance, by
  // the kinematics below.
  const double omega = 400, z0 = 0.6;
  const auto lowest = [&](double t) {  // the lowest corner's height at t
    const double theta = omega * t;
    return z0 - 0.5 * g * t * t - (0.5 * std::abs(std::sin(theta)) + 0.05 * std::abs(std::cos(theta)));
  };
  double first = -1;  // the first time it is within the tolerance, by sampling at 0.1 µs
  for (double t = 0; t < 0.5 && first < 0; t += 1e-7)
    if (lowest(t) <= tol) first = t;
  REQUIRE(first > 0);
  for (const char* model : {"hybrid", "microcollisions"}) {
    const Scene scene = sceneOf(R"("duration": 0.5, "restitution": 0.5, "friction": 0.5, "contact": ")" + std::string(model) + "\"",
                                {floorBody, box("bar", {0.5, 0.05, 0.05}, {0, 0, z0}, R"(, "angular_velocity": [0, 400, 0])")});
    World world(scene, WorldSettings{});
    long restarts = 0;
    while (!world.done() && world.collisionLog().empty()) restarts += world.step().counters.spinRestarts;
    INFO(model << ": first collision at " << (world.collisionLog().empty() ? -1.0 : world.collisionLog().front().time)
               << " s, kinematics " << first << " s");
    REQUIRE(!world.collisionLog().empty());
    const double tc = world.collisionLog().front().time;
    CHECK(restarts == 0);
    CHECK(lowest(tc) >= -1e-6);       // not through the floor
    CHECK(lowest(tc) <= 1.5 * tol);   // within the band when struck
    CHECK(tc <= first + 1e-6);        // and not after it first came within it
  }
}

TEST_CASE("hybrid: a heavy box (100 times the mass) on a light one rests within one tolerance") {
  const Rest r = rest(sceneOf(R"("duration": 5, "friction": 0.5)",
                              {floorBody, box("light", {0.5, 0.5, 0.5}, {0, 0, 0.5001}, R"(, "density": 100)"),
                               box("heavy", {0.5, 0.5, 0.5}, {0, 0, 1.5002}, R"(, "density": 10000)")}));
  INFO("deepest " << r.deepest << " m, drift " << r.drift << " m");
  CHECK(r.deepest <= tol);
  CHECK(r.drift <= tol);
  CHECK(r.energyRises == 0);
}

TEST_CASE("hybrid: a box on an incline below its friction angle stays, above it slides at g (sin θ − μ cos θ)") {
  SECTION("below: 20 degrees, mu = 0.5 (friction angle 26.6 degrees): within 1 mm after 5 s") {
    const double theta = 20 * M_PI / 180;
    const Scene scene = sceneOf(R"("duration": 5, "friction": 0.5, "restitution": 0.3)",
                                onRamp(theta, R"({"box": [0.25, 0.25, 0.25]})", 0.2502, tilted(theta)));
    const Slide s = slide(scene, theta, 5);
    INFO("moved " << s.distance << " m down the slope in " << s.end << " s");
    CHECK(std::abs(s.distance) <= 1e-3);
  }
  SECTION("above: 35 degrees, mu = 0.3: 1/2 g (sin θ − μ cos θ) t^2 within 2% after 1.5 s") {
    const double theta = 35 * M_PI / 180, mu = 0.3, t = 1.5;
    const Scene scene = sceneOf(R"("duration": 1.5, "frame_rate": 120, "friction": 0.3, "restitution": 0.3)",
                                onRamp(theta, R"({"box": [0.25, 0.25, 0.25]})", 0.2502, tilted(theta)));
    const Slide s = slide(scene, theta, t);
    const double expected = 0.5 * g * (std::sin(theta) - mu * std::cos(theta)) * s.end * s.end;
    INFO("slid " << s.distance << " m in " << s.end << " s, expected " << expected);
    CHECK(s.distance == Approx(expected).epsilon(0.02));
  }
}

TEST_CASE("hybrid: a ball rolls down an incline without slipping at (5/7) g sin θ") {
  const double theta = 20 * M_PI / 180, t = 1.5;
  const Scene scene = sceneOf(R"("duration": 1.5, "frame_rate": 120, "friction": 0.5, "restitution": 0.3)",
                              onRamp(theta, R"({"sphere": 0.1})", 0.1002, ""));
  const Slide s = slide(scene, theta, t);
  const double expected = 0.5 * (5.0 / 7.0) * g * std::sin(theta) * s.end * s.end;
  INFO("rolled " << s.distance << " m in " << s.end << " s, expected " << expected);
  CHECK(s.distance == Approx(expected).epsilon(0.02));
}

TEST_CASE("hybrid: a box pushed along the floor stops after v^2 / (2 mu g)") {
  const double v = 2.0, mu = 0.4;
  const Scene scene = sceneOf(R"("duration": 1.0, "frame_rate": 240, "friction": 0.4)",
                              {floorBody, box("box", {0.2, 0.2, 0.05}, {-1, 0, 0.0502}, R"(, "velocity": [2, 0, 0])")});
  World world(scene, WorldSettings{});
  long rises = 0;
  while (!world.done()) rises += world.step().counters.energyRises;
  const double travelled = world.positionOf(1).x() + 1;
  INFO("travelled " << travelled << " m");
  CHECK(travelled == Approx(v * v / (2 * mu * g)).epsilon(0.02));
  CHECK(world.stateOf(1).velocity.norm() < 1e-6);
  CHECK(rises == 0);
}

TEST_CASE("hybrid: a second run ends in the same state, bit for bit") {
  std::vector<std::string> bodies{floorBody};
  for (int row = 0; row < 3; ++row)
    for (int k = 0; k < 3 - row; ++k)
      bodies.push_back(box("p" + std::to_string(row) + std::to_string(k), {0.5, 0.5, 0.5},
                           {(k - (2 - row) / 2.0) * 1.05, 0.01 * k, 0.8 + row * 1.2}));
  const Scene scene = sceneOf(R"("duration": 2, "friction": 0.5)", bodies);
  World a(scene, WorldSettings{}), b(scene, WorldSettings{});
  while (!a.done()) a.step();
  while (!b.done()) b.step();
  for (std::size_t k = 0; k < a.bodies().size(); ++k) {
    CHECK(a.positionOf(int(k)) == b.positionOf(int(k)));
    CHECK(a.stateOf(int(k)).velocity == b.stateOf(int(k)).velocity);
  }
}

TEST_CASE("hybrid: the manifold of a box on a floor is its four corners, of a box half over an edge the overlap") {
  const Shape<double> floor = Box<double>(Eigen::Vector3d(2, 2, 0.5));
  const Shape<double> cube = Box<double>(Eigen::Vector3d(0.5, 0.5, 0.5));
  Pose<double> floorPose;
  floorPose.translation = Eigen::Vector3d(0, 0, -0.5);
  Pose<double> cubePose;
  cubePose.translation = Eigen::Vector3d(0, 0, 0.5001);
  const Eigen::Vector3d up = Eigen::Vector3d::UnitZ();
  auto points = contactManifold(floor, floorPose, cube, cubePose, up, 2 * tol, Eigen::Vector3d::Zero(), 1e-4, tol);
  REQUIRE(points.size() == 4);
  for (const ManifoldPoint& p : points) {
    CHECK(std::abs(std::abs(p.point.x()) - 0.5) < 1e-12);
    CHECK(std::abs(std::abs(p.point.y()) - 0.5) < 1e-12);
    CHECK(p.separation == Approx(1e-4).margin(1e-12));
  }
  // The cube moved half off the floor's edge at x = 2: the overlap is x in [1.5, 2].
  cubePose.translation.x() = 2.0;
  points = contactManifold(floor, floorPose, cube, cubePose, up, 2 * tol, Eigen::Vector3d::Zero(), 1e-4, tol);
  REQUIRE(points.size() == 4);
  for (const ManifoldPoint& p : points) CHECK((std::abs(p.point.x() - 1.5) < 1e-9 || std::abs(p.point.x() - 2.0) < 1e-9));
  // A face normal is exact where GJK's is off by a milliradian.
  const Eigen::Vector3d tiltedUp = Eigen::Vector3d(1e-3, 0, 1).normalized();
  CHECK((faceNormal(floor, floorPose, cube, cubePose, tiltedUp, 0.01) - up).norm() < 1e-12);
}

TEST_CASE("hybrid: in a pile, a pair the solver holds that closes slower than the contact speed is struck with no bounce") {
  // Twenty-four bodies of four kinds falling into a box (timewarp_benchmark's pile): as they
  // come to rest, bodies turning on a body the contact solver holds close on it inside an
  // interval, slower than the contact speed (2 g Δt: 0.2 m/s at 24 frames a second in four
  // intervals, less in more). Such an impulse is a contact's (response.hpp): restitution 0
  // and no microcollision's bounce, so the pair leaves at zero normal speed. The pile's
  // collisions keep the scene's restitution (0.7: they leave at about two thirds of their
  // approach), and under the paper's microcollisions no impulse is a contact.
  const double contactSpeed = 2 * g / (24 * 4);
  for (const ContactModel model : {ContactModel::Hybrid, ContactModel::Microcollisions}) {
    Scene scene = fallingIntoABox(24, 2, 2026);
    scene.run.contact = model;
    World world(scene, WorldSettings{});
    while (!world.done()) world.step();
    long contacts = 0, restituted = 0;
    double fastestContact = 0, fastestLeaving = 0;
    for (const CollisionRecord& c : world.collisionLog()) {
      if (c.contact) {
        ++contacts;
        fastestContact = std::max(fastestContact, c.approachSpeed);
        fastestLeaving = std::max(fastestLeaving, std::abs(c.separationSpeed));
      } else if (!c.microcollision && c.separationSpeed > 0.5 * c.approachSpeed) {
        ++restituted;
      }
    }
    const bool hybrid = model == ContactModel::Hybrid;
    INFO((hybrid ? "hybrid" : "microcollisions") << ": " << world.collisionLog().size() << " collisions, " << contacts
                                                  << " struck as contacts (fastest approach " << fastestContact
                                                  << " m/s, fastest leaving " << fastestLeaving << " m/s), " << restituted
                                                  << " leaving at more than half their approach");
    CHECK(restituted > 0);
    if (!hybrid) {
      CHECK(contacts == 0);
      continue;
    }
    CHECK(contacts > 0);
    CHECK(fastestContact < contactSpeed);
    CHECK(fastestLeaving <= 1e-9);
  }
}

TEST_CASE("the counters of a step's anatomy: cascades within collisions, struck steps only under the hybrid, pairs checked again") {
  // The pile of the test above, both models. What a frame's time goes to at a crash
  // (frames.csv): the instant pass's impulses after each event's own, the hybrid's own steps of
  // struck bodies, and the body pairs Timewarp checks again after a collision and at a step's
  // end. In a box every body has a pair (the box), so each resolved event and each step end
  // checks at least one pair again.
  for (const ContactModel model : {ContactModel::Hybrid, ContactModel::Microcollisions}) {
    Scene scene = fallingIntoABox(24, 2, 2026);
    scene.run.contact = model;
    World world(scene, WorldSettings{});
    FrameCounters sum;
    while (!world.done()) sum += world.step().counters;
    const bool hybrid = model == ContactModel::Hybrid;
    INFO((hybrid ? "hybrid" : "microcollisions") << ": " << sum.collisions << " collisions, " << sum.cascadeImpulses
                                                  << " of them cascaded, " << sum.rollbacks << " rollbacks, "
                                                  << sum.stepEnds << " step ends, " << sum.recheckedAfterCollisions
                                                  << " pairs checked again after collisions, " << sum.recheckedAtStepEnds
                                                  << " at step ends, " << sum.checkedAtIntervalStarts << " at the starts of "
                                                  << sum.intervals << " intervals");
    CHECK(sum.cascadeImpulses > 0);
    CHECK(sum.cascadeImpulses < sum.collisions);
    CHECK(sum.recheckedAfterCollisions >= sum.rollbacks);
    CHECK(sum.rollbacks > 0);
    // Two seconds at 24 frames a second, one interval a frame at least (four under the hybrid),
    // each checking the broad phase's candidates at its start.
    CHECK(sum.intervals >= (hybrid ? 4 : 1) * 48);
    CHECK(sum.checkedAtIntervalStarts > 0);
    CHECK(sum.recheckedAtStepEnds >= sum.stepEnds);
    if (hybrid) {
      // Struck bodies fly steps of StepTuning::struckStep: a step end for most collisions.
      CHECK(sum.stepEnds * 10 > sum.collisions);
    } else {
      // No struck steps: a body flies a step of its own only when a collision spins it past
      // what its interval allows, which happens to a handful of these boxes at most.
      CHECK(sum.stepEnds * 100 <= sum.collisions);
    }
  }
}

TEST_CASE("hybrid: a box spinning at 400 rad/s on the floor, held by the contact solver, flies in eighths of a turn, and no frame runs again") {
  // A flat box resting on the floor and turning about the vertical at 400 rad/s: 4.2 rad
  // in one of a frame's four intervals at 24 frames a second, more than a path can hold.
  // The contact solver holds it from the first interval on; its bodies fly an eighth of a turn
  // at a time (ownStepEnd), so the frame is never run again in shorter intervals, and the
  // box stays on the floor, never through it.
  const double h = 0.02;
  const Scene scene = sceneOf(R"("duration": 0.25, "restitution": 0.5, "friction": 0.5)",
                              {floorBody, box("puck", {0.1, 0.05, h}, {0, 0, h + 0.5 * tol}, R"(, "angular_velocity": [0, 0, 400])")});
  World world(scene, WorldSettings{});
  const FrameVerifier verifier(verifiedBodies(world.bodies()), scene.collisionTolerance, scene.gravity);
  long restarts = 0, groups = 0;
  double deepest = 0, highest = 0;
  while (!world.done()) {
    const FrameReport r = world.step();
    restarts += r.counters.spinRestarts;
    groups += r.counters.contactGroups;
    deepest = std::max(deepest, -verifier.signedDistance(0, world.stateOf(0).worldFromBody, 1, world.stateOf(1).worldFromBody));
    highest = std::max(highest, world.positionOf(1).z() - h);
  }
  INFO("restarts " << restarts << ", contact groups " << groups << ", deepest " << deepest << " m, highest " << highest
                   << " m, spin at the end " << world.stateOf(1).angularVelocity.z() << " rad/s");
  CHECK(restarts == 0);
  CHECK(groups > 0);  // held by the contact solver
  CHECK(deepest <= tol);
  CHECK(highest <= 2 * tol);  // on the floor, not thrown off it
  CHECK(world.stateOf(1).angularVelocity.z() > 300);  // still spinning (friction slows it over seconds)
}

TEST_CASE("hybrid: a box spinning flat on the floor slows at the rate of Coulomb friction at its four corners") {
  // A box of half extents a x b x h resting on its face and turning about the vertical at
  // w0. Held at its four corners (the manifold), each carrying a quarter of its weight and
  // slipping at w r, r = sqrt(a^2 + b^2), each feels mu m g / 4 against its slip: the
  // torque mu m g r against I = m (a^2 + b^2) / 3, a constant deceleration
  // 3 mu g / sqrt(a^2 + b^2), until it stops. The contacts struck inside an interval carry
  // a share of its weight too, at the patch's centre, where the box does not slip: without
  // their twist friction (response.cpp) that share would not slow the spin at all.
  const double a = 0.1, b = 0.05, h = 0.02, mu = 0.5, w0 = 100;
  const double alpha = 3 * mu * g / std::hypot(a, b);  // 131.6 rad/s^2: stops at 0.76 s
  const Scene scene = sceneOf(R"("duration": 1.2, "restitution": 0.5, "friction": 0.5)",
                              {floorBody, box("puck", {a, b, h}, {0, 0, h + 0.5 * tol}, R"(, "angular_velocity": [0, 0, 100])")});
  World world(scene, WorldSettings{});
  double early = -1, late = -1, tEarly = 0, tLate = 0, slowest = w0;
  while (!world.done()) {
    world.step();
    const double t = world.time(), w = world.stateOf(1).angularVelocity.z();
    if (early < 0 && t >= 0.1) std::tie(early, tEarly) = std::make_tuple(w, t);
    if (late < 0 && t >= 0.5) std::tie(late, tLate) = std::make_tuple(w, t);
    slowest = std::min(slowest, w);
  }
  const double measured = (early - late) / (tLate - tEarly);
  INFO("spin " << early << " rad/s at " << tEarly << " s, " << late << " at " << tLate << " s: " << measured
               << " rad/s^2, Coulomb " << alpha << "; at the end " << world.stateOf(1).angularVelocity.z() << " rad/s");
  CHECK(measured == Approx(alpha).epsilon(0.02));
  CHECK(std::abs(world.stateOf(1).angularVelocity.z()) <= 1e-3);  // stopped by 1.2 s (w0 / alpha = 0.76 s)
  CHECK(slowest >= -1e-3);                                        // and not turned back
}
