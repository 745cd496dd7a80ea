// Convex decomposition through HACD (§6): the pieces cover the surface, each is a convex
// polytope with hill climbing, the report adds up, and the cache gives back the same
// pieces without running HACD again.
#include <gjkx/mesh/convex_decomposition.hpp>

#include <catch2/catch.hpp>

#include <optional>

#include <cstdlib>

#include <filesystem>
#include <random>

using namespace gjkx;

namespace {
const std::string kData = GJKX_MESH_TEST_DATA;

std::string freshCacheDir(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() / ("gjkx-mesh-cache-" + name);
  std::filesystem::remove_all(dir);
  return dir.string();
}

// Every mesh vertex lies in (or on) the hull of the piece of each of its triangles.
void checkCovers(const TriangleMesh& mesh, const ConvexDecomposition& d) {
  const auto pieces = d.polytopes<double>();
  REQUIRE(d.pieceOfTriangle.size() == mesh.triangles.size());
  for (size_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto& piece = pieces[d.pieceOfTriangle[t]];
    for (int v : mesh.triangles[t]) {
      // Inside a convex polytope: no direction s has s.v above the support value.
      for (const auto& tri : piece.triangles()) {
        const Eigen::Vector3d a = piece.vertex(tri[0]);
        const Eigen::Vector3d n = (piece.vertex(tri[1]) - a).cross(piece.vertex(tri[2]) - a).normalized();
        REQUIRE(n.dot(mesh.vertices[v] - a) <= 1e-9);
      }
    }
  }
}
}  // namespace

TEST_CASE("a convex mesh (the cube) is one piece, with no volume excess", "[mesh]") {
  const TriangleMesh cube = readMesh(kData + "/cube.off", {true});
  const auto d = decompose(cube, {}, "");
  CHECK(d.report.pieces == 1);
  CHECK(d.report.meshClosed);
  CHECK(d.report.meshVolume == Approx(1.0));
  CHECK(d.report.volumeExcess == Approx(0.0).margin(1e-12));
  CHECK(d.report.verticesPerPiece == std::vector<int>{8});
  CHECK(d.report.cacheFile.empty());
}

TEST_CASE("the L prism: pieces cover the surface, each a polytope whose hill climbing agrees with a scan", "[mesh]") {
  const TriangleMesh mesh = readMesh(kData + "/l_prism.off", {true});
  CHECK(enclosedVolume(mesh) == Approx(3.0));
  const auto d = decompose(mesh, {}, "");
  CHECK(d.report.pieces >= 1);
  CHECK(d.report.hullVolume >= d.report.meshVolume * (1 - 1e-9));  // hulls cover the body
  checkCovers(mesh, d);
  std::mt19937 rng(3);
  std::normal_distribution<double> g;
  for (const auto& piece : d.polytopes<float>())
    for (int k = 0; k < 50; ++k) {
      const Vector3<float> s(float(g(rng)), float(g(rng)), float(g(rng)));
      CHECK(s.dot(piece.support(s)) == Approx(s.dot(piece.vertex(piece.supportIndexLinearScan(s)))));
    }
}

TEST_CASE("the cache: a second run reads the same pieces, another setting is another key", "[mesh]") {
  const TriangleMesh mesh = readMesh(kData + "/l_prism.off", {true});
  const std::string dir = freshCacheDir("l-prism");
  const auto first = decompose(mesh, {}, dir);
  CHECK_FALSE(first.report.fromCache);
  CHECK(std::filesystem::exists(first.report.cacheFile));
  const auto second = decompose(mesh, {}, dir);
  CHECK(second.report.fromCache);
  CHECK(second.pieces == first.pieces);
  CHECK(second.pieceOfTriangle == first.pieceOfTriangle);
  DecompositionSettings other;
  other.concavity = 10;
  CHECK(decompositionKey(mesh, other) != decompositionKey(mesh, DecompositionSettings{}));
  TriangleMesh moved = mesh;
  moved.vertices[0].x() += 1e-9;
  CHECK(decompositionKey(moved, DecompositionSettings{}) != decompositionKey(mesh, DecompositionSettings{}));
  std::filesystem::remove_all(dir);
}

TEST_CASE("the cache goes where caches go: GJKX_MESH_CACHE, else XDG_CACHE_HOME/gjkx, else ~/.cache/gjkx", "[mesh]") {
  // Nothing compiled in: the default folder is read from the environment each time.
  const auto saved = [](const char* name) { const char* v = std::getenv(name); return v ? std::optional<std::string>(v) : std::nullopt; };
  const auto restore = [](const char* name, const std::optional<std::string>& v) {
    if (v) ::setenv(name, v->c_str(), 1);
    else ::unsetenv(name);
  };
  const auto chosen = saved("GJKX_MESH_CACHE"), xdg = saved("XDG_CACHE_HOME"), home = saved("HOME");
  ::setenv("GJKX_MESH_CACHE", "/tmp/chosen-cache", 1);
  CHECK(defaultDecompositionCacheDir() == "/tmp/chosen-cache");
  ::unsetenv("GJKX_MESH_CACHE");
  ::setenv("XDG_CACHE_HOME", "/tmp/xdg", 1);
  CHECK(defaultDecompositionCacheDir() == "/tmp/xdg/gjkx");
  ::unsetenv("XDG_CACHE_HOME");
  ::setenv("HOME", "/tmp/someone", 1);
  CHECK(defaultDecompositionCacheDir() == "/tmp/someone/.cache/gjkx");
  restore("GJKX_MESH_CACHE", chosen);
  restore("XDG_CACHE_HOME", xdg);
  restore("HOME", home);
  // A folder that cannot be made degrades to no cache: the pieces are computed all the same.
  const TriangleMesh mesh = readMesh(kData + "/l_prism.off", {true});
  const auto d = decompose(mesh, {}, "/proc/no-cache-here");
  CHECK(d.report.cacheFile.empty());
  CHECK(!d.pieces.empty());
}

TEST_CASE("bad settings and bad meshes are refused before HACD runs", "[mesh]") {
  const TriangleMesh mesh = readMesh(kData + "/cube.off");
  DecompositionSettings bad;
  bad.concavity = -1;
  CHECK_THROWS_WITH(decompose(mesh, bad, ""), Catch::Contains("decomposition.concavity"));
  bad = {};
  bad.minClusters = 0;
  CHECK_THROWS_WITH(decompose(mesh, bad, ""), Catch::Contains("decomposition.minClusters"));
  TriangleMesh broken = mesh;
  broken.source = "broken-cube";
  broken.vertices[2].y() = std::nan("");
  CHECK_THROWS_WITH(decompose(broken, {}, ""), Catch::Contains("broken-cube") && Catch::Contains("vertex 2"));
}

TEST_CASE("Wuson (assimp-testmodels): a nonconvex mesh cut into pieces that cover it, and the report", "[mesh]") {
  const std::string path = "/usr/share/assimp/models/STL/Wuson.stl";
  if (!std::filesystem::exists(path)) {
    WARN("skipped: " << path << " is absent (Debian package assimp-testmodels, cmake/install-deps.sh)");
    return;
  }
  const TriangleMesh mesh = readMesh(path);
  const auto d = decompose(mesh);  // the build tree's cache: HACD runs once per build
  CHECK(d.report.pieces > 5);
  CHECK_FALSE(d.report.meshClosed);
  CHECK(d.report.volumeExcess > 0);  // the hulls add volume to a nonconvex body ...
  CHECK(d.report.volumeExcess < 1);  // ... but less than the body's own
  int total = 0;
  for (int n : d.report.verticesPerPiece) {
    CHECK(n >= 4);
    total += n;
  }
  CHECK(total >= static_cast<int>(mesh.vertices.size()) / 4);
  checkCovers(mesh, d);
}
