// Triangle meshes in (§6): each file format through Assimp, and each fault of point 1 of
// the stage's brief refused where it enters, with the file's name and what is wrong.
// Test data: tests/mesh/data (small meshes written for these tests) and Wuson from
// Debian's assimp-testmodels (BSD-3-Clause), skipped with a message if absent.
#include <gjkx/mesh/triangle_mesh.hpp>

#include <catch2/catch.hpp>

#include <filesystem>
#include <string>

using namespace gjkx;

namespace {
const std::string kData = GJKX_MESH_TEST_DATA;
std::string data(const std::string& name) { return kData + "/" + name; }
const std::string kWuson = "/usr/share/assimp/models";
}  // namespace

TEST_CASE("the unit cube from OFF and OBJ: quads triangulated, 8 vertices, 12 triangles, volume 1", "[mesh]") {
  for (const char* name : {"cube.off", "cube.obj"}) {
    const TriangleMesh mesh = readMesh(data(name), {true});
    INFO(name);
    CHECK(mesh.vertices.size() == 8);
    CHECK(mesh.triangles.size() == 12);
    CHECK(enclosedVolume(mesh) == Approx(1.0));
    CHECK(mesh.source == data(name));
  }
}

TEST_CASE("the corner tetrahedron from STL and PLY: STL's separate corners are welded, volume 1/6", "[mesh]") {
  for (const char* name : {"tetra.stl", "tetra.ply"}) {
    const TriangleMesh mesh = readMesh(data(name), {true});
    INFO(name);
    CHECK(mesh.vertices.size() == 4);
    CHECK(mesh.triangles.size() == 4);
    CHECK(enclosedVolume(mesh) == Approx(1.0 / 6.0));
  }
}

TEST_CASE("an empty file is refused, naming the file", "[mesh]") {
  CHECK_THROWS_AS(readMesh(data("empty.obj")), std::invalid_argument);
  CHECK_THROWS_WITH(readMesh(data("empty.obj")), Catch::Contains("empty.obj") && Catch::Contains("empty"));
}

TEST_CASE("a missing file is refused, naming the file", "[mesh]") {
  CHECK_THROWS_AS(readMesh(data("no-such-mesh.obj")), std::runtime_error);
  CHECK_THROWS_WITH(readMesh(data("no-such-mesh.obj")), Catch::Contains("no-such-mesh.obj"));
}

TEST_CASE("a NaN coordinate is refused, naming the file and the vertex", "[mesh]") {
  CHECK_THROWS_AS(readMesh(data("nan.off")), std::invalid_argument);
  CHECK_THROWS_WITH(readMesh(data("nan.off")), Catch::Contains("nan.off") && Catch::Contains("vertex 3") &&
                                                   Catch::Contains("not finite"));
}

TEST_CASE("a face index out of range is refused, in OBJ and in OFF (whose reader would clamp it)", "[mesh]") {
  for (const char* name : {"bad_index.obj", "bad_index.off"}) {
    INFO(name);
    CHECK_THROWS_AS(readMesh(data(name)), std::invalid_argument);
    CHECK_THROWS_WITH(readMesh(data(name)), Catch::Contains(name) && Catch::Contains("out of range"));
  }
}

TEST_CASE("an open box is refused where closure is required, naming an open edge, and accepted where it is not", "[mesh]") {
  CHECK_THROWS_WITH(readMesh(data("open_box.off"), {true}),
                    Catch::Contains("open_box.off") && Catch::Contains("not closed") && Catch::Contains("edge"));
  CHECK(readMesh(data("open_box.off"), {false}).triangles.size() == 10);
}

TEST_CASE("validateMesh: an index out of range and a repeated vertex in a mesh built in memory", "[mesh]") {
  TriangleMesh mesh;
  mesh.source = "in-memory";
  mesh.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  mesh.triangles = {{0, 1, 3}};
  CHECK_THROWS_WITH(validateMesh(mesh), Catch::Contains("in-memory") && Catch::Contains("triangle 0") &&
                                            Catch::Contains("out of range"));
  mesh.triangles = {{0, 1, 1}};
  CHECK_THROWS_WITH(validateMesh(mesh), Catch::Contains("repeats a vertex"));
  mesh.triangles.clear();
  CHECK_THROWS_WITH(validateMesh(mesh), Catch::Contains("no triangles"));
}

TEST_CASE("Wuson (assimp-testmodels) reads alike from OFF, PLY and STL", "[mesh]") {
  const std::string off = kWuson + "/OFF/Wuson.off", ply = kWuson + "/PLY/Wuson.ply", stl = kWuson + "/STL/Wuson.stl";
  if (!std::filesystem::exists(off) || !std::filesystem::exists(ply) || !std::filesystem::exists(stl)) {
    WARN("skipped: Wuson is absent from " << kWuson << " (Debian package assimp-testmodels, cmake/install-deps.sh)");
    return;
  }
  const TriangleMesh a = readMesh(off), b = readMesh(ply), c = readMesh(stl);
  CHECK(a.triangles.size() == 3732);
  CHECK(b.triangles.size() == a.triangles.size());
  CHECK(c.triangles.size() == a.triangles.size());
  CHECK(b.vertices.size() == a.vertices.size());
  CHECK(c.vertices.size() == a.vertices.size());
  // Wuson has holes: refused where closure is required.
  CHECK_THROWS_WITH(readMesh(stl, {true}), Catch::Contains("Wuson.stl") && Catch::Contains("not closed"));
  CHECK(std::abs(enclosedVolume(a)) == Approx(std::abs(enclosedVolume(c))).epsilon(1e-3));
}
