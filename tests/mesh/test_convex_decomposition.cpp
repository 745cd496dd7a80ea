// Convex decomposition through HACD (§6): the pieces cover the surface, each is a convex
// polytope with hill climbing, the report adds up, and the cache gives back the same
// pieces without running HACD again.
#include <gjkx/mesh/convex_decomposition.hpp>

#include <catch2/catch.hpp>

#include <optional>

#include <cstdlib>

#include <gjkx/support_mapping/convex_hull.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
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

namespace {
// A closed UV sphere of `rings` x `segments` quads (poles fanned): enough triangles that
// HACD's first phase alone (every triangle's ray against every other) takes a while.
TriangleMesh uvSphere(int rings, int segments) {
  TriangleMesh m;
  m.source = "uv-sphere";
  const double pi = 3.14159265358979323846;
  m.vertices.push_back({0, 0, 1});
  for (int r = 1; r < rings; ++r)
    for (int s = 0; s < segments; ++s) {
      const double theta = pi * r / rings, phi = 2 * pi * s / segments;
      m.vertices.push_back({std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)});
    }
  m.vertices.push_back({0, 0, -1});
  const int south = int(m.vertices.size()) - 1;
  const auto at = [&](int r, int s) { return 1 + (r - 1) * segments + (s % segments); };
  for (int s = 0; s < segments; ++s) m.triangles.push_back({0, at(1, s), at(1, s + 1)});
  for (int r = 1; r + 1 < rings; ++r)
    for (int s = 0; s < segments; ++s) {
      m.triangles.push_back({at(r, s), at(r + 1, s), at(r + 1, s + 1)});
      m.triangles.push_back({at(r, s), at(r + 1, s + 1), at(r, s + 1)});
    }
  for (int s = 0; s < segments; ++s) m.triangles.push_back({south, at(rings - 1, s + 1), at(rings - 1, s)});
  return m;
}
}  // namespace

TEST_CASE("a decomposition past its budget stops and falls back to the mesh's hull, and says how far it came", "[mesh]") {
  const TriangleMesh mesh = uvSphere(48, 64);  // 6,016 triangles: HACD needs seconds, the budget is 0.2 s
  REQUIRE_NOTHROW(validateMesh(mesh, MeshRequirements{true}));
  DecompositionSettings settings;
  settings.budgetSeconds = 0.2;
  int calls = 0;
  double lastSeconds = 0;
  const std::string cache = freshCacheDir("budget");
  const auto start = std::chrono::steady_clock::now();
  const ConvexDecomposition d = decompose(mesh, settings, cache, [&](const DecompositionProgress& p) {
    ++calls;
    lastSeconds = p.seconds;
    CHECK(p.budgetSeconds == 0.2);
    CHECK(p.fraction >= 0);
    CHECK(p.fraction <= 1);
  });
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  CHECK(d.report.fellBack);
  CHECK_THAT(d.report.fallbackReason, Catch::Contains("budget of 0.2 s"));
  // One piece, the hull of every vertex, and every triangle in it.
  REQUIRE(d.pieces.size() == 1);
  CHECK(d.report.pieces == 1);
  CHECK(d.pieces[0].size() == convexHull3d(mesh.vertices, "mesh").vertices.size());
  CHECK(std::abs(hullVolume(d.pieces[0]) - hullVolume(mesh.vertices)) < 1e-12);
  CHECK(std::count(d.pieceOfTriangle.begin(), d.pieceOfTriangle.end(), 0) == long(mesh.triangles.size()));
  // About the budget, not far more: at least the budget, and far less than HACD's seconds
  // (a generous bound, not a speed test: the machine may be loaded).
  CHECK(d.report.seconds >= 0.2);
  CHECK(wall < 10);
  CHECK(calls >= 1);
  CHECK(lastSeconds <= d.report.seconds);
  CHECK_THAT(describe(d.report, "uv-sphere"), Catch::Contains("not decomposed") && Catch::Contains("one piece"));

  // Remembered: the same budget falls back at once, from the cache; a larger one tries again.
  const ConvexDecomposition again = decompose(mesh, settings, cache);
  CHECK(again.report.fellBack);
  CHECK(again.report.fromCache);
  CHECK_THAT(describe(again.report, "uv-sphere"), Catch::Contains("(cached)"));
  settings.budgetSeconds = 0.3;
  const ConvexDecomposition larger = decompose(mesh, settings, cache);
  CHECK(larger.report.fellBack);
  CHECK_FALSE(larger.report.fromCache);
}

TEST_CASE("a decomposition within its budget is reported: pieces, vertices per piece, volume excess, time", "[mesh]") {
  const TriangleMesh mesh = readMesh(kData + "/l_prism.off");
  const ConvexDecomposition d = decompose(mesh, {}, "");
  CHECK_FALSE(d.report.fellBack);
  CHECK(d.report.fallbackReason.empty());
  const std::string line = describe(d.report, "l_prism.off");
  CHECK_THAT(line, Catch::StartsWith("l_prism.off: " + std::to_string(d.report.pieces) + " convex pieces") &&
                       Catch::Contains("vertices per piece") && Catch::Contains("volume excess") &&
                       Catch::EndsWith(" s"));
  DecompositionSettings bad;
  bad.budgetSeconds = 0;
  CHECK_THROWS_WITH(decompose(mesh, bad, ""), Catch::Contains("decomposition.budgetSeconds"));
}
