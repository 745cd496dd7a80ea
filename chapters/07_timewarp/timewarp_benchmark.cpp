// The Timewarp benchmark (docs/07_timewarp.md): a few hundred convex bodies (boxes,
// spheres, capsules, small polytopes) dropped into a box, run under each ordering from
// the same scene with one model of resting contact (--contact, the hybrid by default), and
// Timewarp under the other model. Prints, per run: wall time per simulated second,
// collisions, rollbacks per frame, pair checks, and the split of the wall time by part; then
//   RATIO timewarp_vs_toi_heap=<heap wall / timewarp wall>
//   RATIO <other>_vs_<chosen>=<Timewarp's wall under the other model / under the chosen>
//   RATIO timewarp_<chosen>_wall_per_sim_s=<Timewarp's wall per simulated second>
// The independent checks are off (they are not part of the method); the collisions
// columns show whether the orderings resolved the same number of impacts.
// --write-scene FILE writes the pile as a scene file instead (and runs nothing), so that
// gjkx_simulate and the peers' runners of chapter 08 run the same bodies.
#include "../command_line.hpp"

#include <gjkx/timewarp/pile.hpp>
#include <gjkx/timewarp/scene.hpp>
#include <gjkx/timewarp/world.hpp>

#include <cstdio>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>

namespace {

/// The pile as a scene file (gjkx/timewarp/scene.hpp's keys), every number with all its
/// digits, so that the file is the same bodies.
std::string sceneJson(const gjkx::Scene& scene, const std::string& contact) {
  std::ostringstream out;
  out.precision(17);
  auto vec = [&](const Eigen::Vector3d& v) { out << '[' << v.x() << ", " << v.y() << ", " << v.z() << ']'; };
  out << "{\n  \"duration\": " << scene.duration << ",\n  \"contact\": \"" << contact << "\",\n  \"bodies\": [";
  for (std::size_t k = 0; k < scene.bodies.size(); ++k) {
    const gjkx::BodySpec& b = scene.bodies[k];
    out << (k ? ",\n" : "\n") << "    { \"name\": \"" << b.name << "\", \"shape\": {";
    switch (b.shape.kind) {
      case gjkx::ShapeSpec::Kind::Box: out << "\"box\": ", vec(b.shape.halfExtents); break;
      case gjkx::ShapeSpec::Kind::Sphere: out << "\"sphere\": " << b.shape.radius; break;
      case gjkx::ShapeSpec::Kind::Capsule:
        out << "\"capsule\": [" << b.shape.radius << ", " << b.shape.halfLength << ']';
        break;
      default:  // the pile's polytopes (it has no other shape)
        out << "\"polytope\": [";
        for (std::size_t v = 0; v < b.shape.points.size(); ++v) out << (v ? ", " : ""), vec(b.shape.points[v]);
        out << ']';
    }
    out << "}, \"position\": ", vec(b.position);
    if (b.isStatic) {
      out << ", \"static\": true }";
      continue;
    }
    const Eigen::Quaterniond& q = b.orientation;
    out << ", \"orientation\": [" << q.w() << ", " << q.x() << ", " << q.y() << ", " << q.z() << "], \"velocity\": ";
    vec(b.velocity);
    out << ", \"angular_velocity\": ";
    vec(b.angularVelocity);
    out << " }";
  }
  out << "\n  ]\n}\n";
  return out.str();
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Timewarp against the time-of-impact heap and fixed steps on bodies falling into a box.",
               "timewarp_benchmark"};
  int count = 200;
  double duration = 2.0;
  std::string scalar = "float", contact = "hybrid";
  bool fixedToo = true;
  app.add_option("--bodies", count, "moving bodies")->check(CLI::Range(1, 5000));
  app.add_option("--duration", duration, "simulated seconds")->check(CLI::PositiveNumber);
  app.add_option("--scalar", scalar, "collision detection in float or double")->check(CLI::IsMember({"float", "double"}));
  app.add_flag("!--no-fixed-step", fixedToo, "leave out the fixed-step ordering");
  app.add_option("--contact", contact, "the model of resting contact of the orderings' runs (Timewarp is also run under the other)")
      ->check(CLI::IsMember({"hybrid", "microcollisions"}))
      ->capture_default_str();
  std::string writeScene;
  app.add_option("--write-scene", writeScene, "write the pile as a scene file (with --contact) and run nothing");
  chapter::parseOrExit(app, argc, argv);

  if (!writeScene.empty()) {
    std::ofstream file(writeScene);
    if (!(file << sceneJson(gjkx::fallingIntoABox(count, duration, 2026), contact))) {
      std::fprintf(stderr, "timewarp_benchmark: cannot write %s\n", writeScene.c_str());
      return 1;
    }
    return 0;
  }
  std::printf("%d bodies into a box, %.2f s simulated, collision detection in %s, contact model %s\n", count, duration,
              scalar.c_str(), contact.c_str());
  std::printf("%-11s %10s %9s %9s %11s %10s %8s | %6s %6s %6s %6s %6s\n", "ordering", "wall/sim_s", "collisions",
              "rollbacks", "rollbk/frame", "checks", "brent", "integ", "bounds", "detect", "impuls", "order");
  const gjkx::ContactModel chosen =
      contact == "hybrid" ? gjkx::ContactModel::Hybrid : gjkx::ContactModel::Microcollisions;
  const gjkx::ContactModel other =
      chosen == gjkx::ContactModel::Hybrid ? gjkx::ContactModel::Microcollisions : gjkx::ContactModel::Hybrid;
  double wallTimewarp = 0, wallHeap = 0, wallOther = 0;
  // The three orderings under the chosen contact model, then Timewarp under the other.
  const std::vector<std::pair<gjkx::Ordering, gjkx::ContactModel>> runs = {
      {gjkx::Ordering::Timewarp, chosen}, {gjkx::Ordering::ToiHeap, chosen}, {gjkx::Ordering::FixedStep, chosen},
      {gjkx::Ordering::Timewarp, other}};
  for (const auto& [ordering, model] : runs) {
    if (ordering == gjkx::Ordering::FixedStep && !fixedToo) continue;
    gjkx::Scene scene = gjkx::fallingIntoABox(count, duration, 2026);
    scene.run.ordering = ordering;
    scene.run.contact = model;
    scene.run.scalar = scalar == "float" ? gjkx::CollisionScalar::Float : gjkx::CollisionScalar::Double;
    gjkx::WorldSettings settings;
    settings.checks = false;
    std::unique_ptr<gjkx::World> world;
    try {
      world = std::make_unique<gjkx::World>(scene, settings);
    } catch (const std::exception& e) {
      std::fprintf(stderr, "timewarp_benchmark: %s\n", e.what());
      return 1;
    }
    double wall = 0;
    gjkx::FrameCounters total;
    gjkx::PartTimes parts;
    while (!world->done()) {
      gjkx::FrameReport r;
      try {
        r = world->step();
      } catch (const std::exception& e) {
        std::fprintf(stderr, "timewarp_benchmark: %s: stopped at t = %g: %s\n", gjkx::orderingName(ordering),
                     world->time(), e.what());
        return 1;
      }
      wall += r.wallSeconds;
      total += r.counters;
      parts += r.parts;
    }
    auto share = [&](double part) { return 100 * part / wall; };
    const std::string name = std::string(gjkx::orderingName(ordering)) + (model == chosen ? "" : "*");
    std::printf("%-11s %10.3f %9ld %9ld %11.2f %10ld %8ld | %5.1f%% %5.1f%% %5.1f%% %5.1f%% %5.1f%%\n",
                name.c_str(), wall / world->time(), total.collisions, total.rollbacks,
                double(total.rollbacks) / world->frameCount(), total.collisionChecks, total.brentIterations,
                share(parts.integration), share(parts.bounds), share(parts.collisionDetection), share(parts.impulses),
                share(parts.ordering));
    std::fflush(stdout);
    if (ordering == gjkx::Ordering::Timewarp && model == chosen) wallTimewarp = wall;
    if (ordering == gjkx::Ordering::Timewarp && model != chosen) wallOther = wall;
    if (ordering == gjkx::Ordering::ToiHeap) wallHeap = wall;
  }
  std::printf("(* Timewarp under the %s model)\n", gjkx::contactModelName(other));
  std::printf("RATIO timewarp_vs_toi_heap=%.3f\n", wallHeap / wallTimewarp);
  std::printf("RATIO %s_vs_%s=%.3f\n", gjkx::contactModelName(other), gjkx::contactModelName(chosen),
              wallOther / wallTimewarp);
  std::printf("RATIO timewarp_%s_wall_per_sim_s=%.3f\n", gjkx::contactModelName(chosen), wallTimewarp / duration);
  return 0;
}
