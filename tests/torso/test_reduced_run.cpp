// The paper's experiment in small, as CI can afford it (docs/08_torso.md): the reduced
// torso scene of gjkx_generate_torso (a vertebra, two ribs, their cartilages and the
// sternum falling onto three leaves) run for its second under Timewarp with the
// independent checks on. Nothing tunnels, no pair penetrates deeper than the tolerance
// band allows, the mechanical energy never rises from frame to frame, and a second run
// ends in exactly the same state.
#include <catch2/catch.hpp>

#include <gjkx/timewarp/scene.hpp>
#include <gjkx/timewarp/world.hpp>

#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace {

fs::path generateReduced() {
  const fs::path dir = fs::temp_directory_path() / ("gjkx-torso-run-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  const std::string command =
      std::string("\"") + GJKX_GENERATE_TORSO + "\" --out \"" + dir.string() + "\" --reduced > /dev/null 2>&1";
  const int status = std::system(command.c_str());
  INFO(command);
  REQUIRE(WIFEXITED(status));
  REQUIRE(WEXITSTATUS(status) == 0);
  return dir;
}

// Kinetic energy plus the potential energy of gravity, m g.(-x), over the moving bodies.
double mechanicalEnergy(const gjkx::World& world) {
  double energy = 0;
  for (int b = 0; b < int(world.bodies().size()); ++b) {
    const gjkx::RigidBody& rigid = world.bodies()[b].rigid;
    if (rigid.isStatic()) continue;
    const gjkx::BodyState s = world.stateOf(b);
    energy += rigid.kineticEnergy(s) - world.scene().gravity.dot(s.worldFromBody.translation) / rigid.inverseMass();
  }
  return energy;
}

struct RunResult {
  long collisions = 0;
  int tunnelled = 0;
  double maxPenetration = 0;
  double worstRise = 0;  // the largest rise of the mechanical energy from one frame to the next (J)
  std::vector<gjkx::BodyState> end;
};

RunResult run(const gjkx::Scene& scene, bool checks) {
  gjkx::WorldSettings settings;
  settings.checks = checks;  // the checks only read the run: with or without them it is the same
  gjkx::World world(scene, settings);
  RunResult r;
  double energy = mechanicalEnergy(world);
  while (!world.done()) {
    const gjkx::FrameReport report = world.step();
    r.collisions += report.counters.collisions;
    r.tunnelled += report.counters.tunnelled;
    r.maxPenetration = std::max(r.maxPenetration, report.counters.maxPenetration);
    const double now = mechanicalEnergy(world);
    r.worstRise = std::max(r.worstRise, now - energy);
    energy = now;
  }
  for (int b = 0; b < int(world.bodies().size()); ++b) r.end.push_back(world.stateOf(b));
  return r;
}

}  // namespace

TEST_CASE("the reduced torso scene: no tunnelling, penetration within the tolerance band, no energy gain, the same every run") {
  const fs::path dir = generateReduced();
  const gjkx::Scene scene = gjkx::loadScene((dir / "scene.json").string());
  const RunResult first = run(scene, true);
  INFO("collisions " << first.collisions << ", deepest penetration " << first.maxPenetration << " m, worst energy rise "
                     << first.worstRise << " J");
  CHECK(first.collisions > 0);  // the bones do reach the leaves
  CHECK(first.tunnelled == 0);
  // Contacts are found within the tolerance; a pair may end a frame a little inside the
  // band's far side (the time tolerance is half a tolerance of closing).
  CHECK(first.maxPenetration <= 2 * scene.collisionTolerance);
  // Free flight conserves energy to the integrator's 1e-12; impulses only take it away.
  CHECK(first.worstRise <= 1e-9);
  const RunResult second = run(scene, false);
  REQUIRE(second.end.size() == first.end.size());
  CHECK(second.collisions == first.collisions);
  for (std::size_t b = 0; b < first.end.size(); ++b) {
    CHECK(second.end[b].worldFromBody.translation == first.end[b].worldFromBody.translation);
    CHECK(second.end[b].velocity == first.end[b].velocity);
  }
  fs::remove_all(dir);
}
