// gjkx_generate_torso as a user runs it (chapter 08, docs/08_torso.md): its meshes are
// closed, the torso has exactly 80 bones in the named groups, the triangle totals are
// the paper's within 2%, the same seed writes the same bytes, the convex decompositions
// cover every mesh, and the scenes load into the world (which refuses bodies that
// overlap at the start).
#include <catch2/catch.hpp>

#include "../run_program.hpp"

#include <gjkx/mesh/convex_decomposition.hpp>
#include <gjkx/mesh/triangle_mesh.hpp>
#include <gjkx/support_mapping/convex_hull.hpp>
#include <gjkx/timewarp/scene.hpp>
#include <gjkx/timewarp/world.hpp>

#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>

namespace fs = std::filesystem;

namespace {

// Runs gjkx_generate_torso (its path passed in by tests/CMakeLists.txt) into a fresh folder.
fs::path generate(const std::string& name, const std::string& arguments = "") {
  const fs::path dir = fs::temp_directory_path() / ("gjkx-torso-" + name + "-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  const std::string command =
      std::string("\"") + GJKX_GENERATE_TORSO + "\" --out \"" + dir.string() + "\" " + arguments + " > /dev/null 2>&1";
  const int status = std::system(command.c_str());
  INFO(command);
  REQUIRE(WIFEXITED(status));
  REQUIRE(WEXITSTATUS(status) == 0);
  return dir;
}

std::string contents(const fs::path& file) { return test::readText(file); }

// The group of a bone from its name: "rib_left_3" -> "rib".
std::string groupOf(const std::string& name) { return name.substr(0, name.find('_')); }

// The planes of a convex piece's hull, outward normals: (n, offset) with n.p <= offset inside.
std::vector<std::pair<Eigen::Vector3d, double>> hullPlanes(const std::vector<Eigen::Vector3d>& piece) {
  const gjkx::ConvexHull hull = gjkx::convexHull3d(piece, "piece");
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  for (const auto& v : hull.vertices) centre += v;
  centre /= double(hull.vertices.size());
  std::vector<std::pair<Eigen::Vector3d, double>> planes;
  for (const auto& t : hull.triangles) {
    const Eigen::Vector3d a = hull.vertices[t[0]];
    Eigen::Vector3d n = (hull.vertices[t[1]] - a).cross(hull.vertices[t[2]] - a).normalized();
    if (n.dot(centre - a) > 0) n = -n;
    planes.emplace_back(n, n.dot(a));
  }
  return planes;
}

// True if p lies in the hull given by `planes` or within `tolerance` of it.
bool inHull(const Eigen::Vector3d& p, const std::vector<std::pair<Eigen::Vector3d, double>>& planes, double tolerance) {
  for (const auto& [n, offset] : planes)
    if (n.dot(p) > offset + tolerance) return false;
  return true;
}

}  // namespace

TEST_CASE("the torso has exactly 80 bones in the named groups, every mesh closed", "[torso]") {
  const fs::path dir = generate("count");
  const gjkx::Scene scene = gjkx::loadScene((dir / "scene.json").string());
  std::map<std::string, int> groups;
  long boneTriangles = 0;
  for (const auto& body : scene.bodies) {
    if (body.name == "floor" || body.name == "plant") {
      CHECK(body.isStatic);
      continue;
    }
    CHECK_FALSE(body.isStatic);
    REQUIRE(body.shape.kind == gjkx::ShapeSpec::Kind::Mesh);
    ++groups[groupOf(body.name)];
    INFO(body.name);
    // Closed (every edge on two triangles): readMesh validates it, and nothing was welded away.
    const gjkx::TriangleMesh mesh = gjkx::readMesh((dir / body.shape.meshPath).string(), gjkx::MeshRequirements{true});
    CHECK(mesh.droppedTriangles == 0);
    CHECK(gjkx::enclosedVolume(mesh) > 0);  // faces outward
    boneTriangles += long(mesh.triangles.size());
  }
  CHECK(groups == std::map<std::string, int>{{"vertebra", 24}, {"rib", 24},     {"cartilage", 22},
                                             {"sternum", 2},   {"clavicle", 2}, {"scapula", 2},
                                             {"hip", 2},       {"sacrum", 1},   {"coccyx", 1}});
  // The paper: 24,790 triangles for the torso, 8,640 for the plant.
  CHECK(std::abs(boneTriangles - 24790) <= 0.02 * 24790);
  const gjkx::TriangleMesh plant = gjkx::readMesh((dir / "plant.off").string(), gjkx::MeshRequirements{true});
  CHECK(std::abs(long(plant.triangles.size()) - 8640) <= 0.02 * 8640);
  fs::remove_all(dir);
}

TEST_CASE("the same seed writes the same bytes, another seed another drop", "[torso]") {
  const fs::path a = generate("same-a", "--seed 7"), b = generate("same-b", "--seed 7"), c = generate("other", "--seed 8");
  std::vector<fs::path> files{"scene.json", "plant.off"};
  for (const auto& entry : fs::directory_iterator(a / "meshes")) files.push_back(fs::path("meshes") / entry.path().filename());
  CHECK(files.size() == 82);
  for (const auto& file : files) {
    INFO(file);
    CHECK(contents(a / file) == contents(b / file));
  }
  CHECK(contents(a / "scene.json") != contents(c / "scene.json"));    // the drop differs
  CHECK(contents(a / "plant.off") == contents(c / "plant.off"));      // the plant is fixed
  for (const auto& dir : {a, b, c}) fs::remove_all(dir);
}

TEST_CASE("the convex pieces of every mesh cover it", "[torso]") {
  const fs::path dir = generate("cover");
  std::vector<fs::path> meshes{dir / "plant.off"};
  for (const auto& entry : fs::directory_iterator(dir / "meshes")) meshes.push_back(entry.path());
  int pieces = 0;
  for (const auto& file : meshes) {
    INFO(file.filename());
    const gjkx::TriangleMesh mesh = gjkx::readMesh(file.string());
    const gjkx::ConvexDecomposition d = gjkx::decompose(mesh);  // cached in the build tree
    REQUIRE(d.report.pieces >= 1);
    CHECK(d.report.meshClosed);
    pieces += d.report.pieces;
    if (file.filename() == "plant.off")
      std::printf("plant: %d convex pieces, hulls %.0f%% over the mesh's volume\n", d.report.pieces,
                  100 * d.report.volumeExcess);
    std::vector<std::vector<std::pair<Eigen::Vector3d, double>>> hulls;
    for (const auto& piece : d.pieces) hulls.push_back(hullPlanes(piece));
    for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
      bool covered = false;
      for (std::size_t p = 0; p < hulls.size() && !covered; ++p) covered = inHull(mesh.vertices[v], hulls[p], 1e-7);
      INFO("vertex " << v);
      REQUIRE(covered);
    }
  }
  std::printf("torso and plant: %zu meshes, %d convex pieces\n", meshes.size(), pieces);
  fs::remove_all(dir);
}

TEST_CASE("the full and the reduced scene load into the world: no two bones overlap at the start", "[torso]") {
  for (const std::string arguments : {"--reduced", ""}) {
    const fs::path dir = generate(arguments.empty() ? "full" : "reduced", arguments);
    INFO("gjkx_generate_torso " << arguments);
    const gjkx::Scene scene = gjkx::loadScene((dir / "scene.json").string());
    CHECK(scene.bodies.size() == (arguments.empty() ? 82u : 8u));
    CHECK(scene.frameRate == 24);
    CHECK(scene.restitution == 0.7);
    CHECK(scene.friction == 0.4);
    CHECK(scene.run.scalar == gjkx::CollisionScalar::Float);
    CHECK(scene.run.ordering == gjkx::Ordering::Timewarp);
    gjkx::WorldSettings settings;
    settings.checks = false;
    const gjkx::World world(scene, settings);  // throws if two bodies overlap at the start
    CHECK(world.bodies().size() == scene.bodies.size());
    fs::remove_all(dir);
  }
}
