// The scene file: every key read, every bad input rejected with the body and the field named.
#include <gjkx/timewarp/pile.hpp>
#include <gjkx/timewarp/scene.hpp>
#include <gjkx/timewarp/world.hpp>

#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

using namespace gjkx;

namespace {

/// A valid scene with one body whose fields are `body` (JSON members), and scene members `extra`.
std::string sceneWith(const std::string& body, const std::string& extra = "") {
  return R"({ "duration": 0.5, )" + extra + R"( "bodies": [ { "name": "floor", "shape": {"box": [5, 5, 0.5]},
      "position": [0, 0, -0.5], "static": true }, { "name": "ball", )" +
         body + R"( } ] })";
}

std::string errorOf(const std::string& text) {
  try {
    const Scene scene = parseScene(text, "test.json");
    World world(scene);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST_CASE("scene: every key is read") {
  const Scene scene = parseScene(R"({ "gravity": [0, -9.8, 0], "frame_rate": 30, "duration": 2,
      "collision_tolerance": 0.001, "restitution": 0.5, "friction": 0.25, "scalar": "double",
      "ordering": "toi_heap", "fixed_substeps": 4, "contact": "microcollisions",
      "bodies": [ { "name": "b", "shape": {"capsule": [0.1, 0.3]}, "position": [1, 2, 3],
                    "orientation": [0, 0, 0, 2], "velocity": [1, 0, 0], "angular_velocity": [0, 0, 1],
                    "density": 500, "static": false },
                  { "name": "p", "shape": {"polytope": [[0,0,0],[1,0,0],[0,1,0],[0,0,1]]}, "position": [5, 0, 0] } ] })");
  CHECK(scene.gravity == Eigen::Vector3d(0, -9.8, 0));
  CHECK(scene.frameRate == 30);
  CHECK(scene.duration == 2);
  CHECK(scene.collisionTolerance == 0.001);
  CHECK(scene.restitution == 0.5);
  CHECK(scene.friction == 0.25);
  CHECK(scene.run.scalar == CollisionScalar::Double);
  CHECK(scene.run.ordering == Ordering::ToiHeap);
  CHECK(scene.run.fixedSubsteps == 4);
  CHECK(scene.run.contact == ContactModel::Microcollisions);
  REQUIRE(scene.bodies.size() == 2);
  const BodySpec& b = scene.bodies[0];
  CHECK(b.shape.kind == ShapeSpec::Kind::Capsule);
  CHECK(b.shape.radius == 0.1);
  CHECK(b.shape.halfLength == 0.3);
  CHECK(b.position == Eigen::Vector3d(1, 2, 3));
  CHECK(b.orientation.z() == Approx(1.0));  // normalised
  CHECK(b.density == 500);
  CHECK(scene.bodies[1].shape.points.size() == 4);
  CHECK(scene.bodies[1].density == 1000);  // the default
}

TEST_CASE("scene: defaults are the paper's settings") {
  const Scene scene = parseScene(sceneWith(R"("shape": {"sphere": 0.1}, "position": [0, 0, 1])"));
  CHECK(scene.frameRate == 24);
  CHECK(scene.restitution == 0.7);
  CHECK(scene.friction == 0.4);
  CHECK(scene.run.scalar == CollisionScalar::Float);
  CHECK(scene.run.ordering == Ordering::Timewarp);
  CHECK(scene.run.contact == ContactModel::Hybrid);  // the hybrid unless the scene asks for the paper's model
  CHECK(scene.collisionTolerance == Approx(std::sqrt(double(std::numeric_limits<float>::epsilon()))).epsilon(1e-6));
}

TEST_CASE("scene: bad input names the body and the field") {
  struct Case {
    const char* what;
    std::string text;
    std::vector<std::string> mentions;
  };
  const std::vector<Case> cases = {
      {"a missing field", sceneWith(R"("shape": {"sphere": 0.1})"), {"body 'ball'", "'position'", "missing"}},
      {"a missing name", R"({ "duration": 1, "bodies": [ { "shape": {"sphere": 0.1}, "position": [0, 0, 1] } ] })",
       {"bodies[0]", "'name'", "missing"}},
      {"a negative radius", sceneWith(R"("shape": {"sphere": -0.1}, "position": [0, 0, 1])"),
       {"body 'ball'", "'shape.sphere'", "positive"}},
      {"a negative capsule radius", sceneWith(R"("shape": {"capsule": [-1, 1]}, "position": [0, 0, 1])"),
       {"body 'ball'", "shape.capsule[0]", "positive"}},
      {"an infinite coordinate (JSON has no infinity: the number overflows)",
       sceneWith(R"("shape": {"sphere": 0.1}, "position": [0, 1e999, 1])"), {"not valid JSON", "1e999"}},
      {"NaN (not JSON)", sceneWith(R"("shape": {"sphere": 0.1}, "position": [0, NaN, 1])"), {"not valid JSON"}},
      {"an unknown body key", sceneWith(R"("shape": {"sphere": 0.1}, "position": [0, 0, 1], "colour": 3)"),
       {"body 'ball'", "'colour'", "not a known key"}},
      {"an unknown scene key", sceneWith(R"("shape": {"sphere": 0.1}, "position": [0, 0, 1])", R"("gravityy": 1,)"),
       {"'gravityy'", "not a known key"}},
      {"an unknown shape", sceneWith(R"("shape": {"cone": 1}, "position": [0, 0, 1])"), {"body 'ball'", "shape.cone"}},
      {"a zero quaternion", sceneWith(R"("shape": {"sphere": 0.1}, "position": [0, 0, 1], "orientation": [0,0,0,0])"),
       {"body 'ball'", "'orientation'", "zero"}},
      {"a wrong type", sceneWith(R"("shape": {"sphere": 0.1}, "position": [0, 0, 1], "static": "yes")"),
       {"body 'ball'", "'static'"}},
      {"an unknown ordering", sceneWith(R"("shape": {"sphere": 0.1}, "position": [0, 0, 1])", R"("ordering": "fast",)"),
       {"'ordering'"}},
      {"an unknown contact model", sceneWith(R"("shape": {"sphere": 0.1}, "position": [0, 0, 1])", R"("contact": "glue",)"),
       {"'contact'", "\"microcollisions\" or \"hybrid\""}},
      {"a flat polytope", sceneWith(R"("shape": {"polytope": [[0,0,0],[1,0,0],[0,1,0],[1,1,0]]}, "position": [0, 0, 1])"),
       {"body 'ball'", "'shape'"}},
      {"two bodies overlapping at the start", sceneWith(R"("shape": {"sphere": 0.1}, "position": [0, 0, 0.05])"),
       {"body 'floor'", "body 'ball'", "overlapping"}},
      {"a velocity on a static body",
       sceneWith(R"("shape": {"sphere": 0.1}, "position": [0, 0, 1], "static": true, "velocity": [1, 0, 0])"),
       {"body 'ball'", "'velocity'", "static"}},
  };
  for (const Case& c : cases) {
    INFO(c.what << ": " << c.text);
    const std::string message = errorOf(c.text);
    INFO("message: " << message);
    REQUIRE_FALSE(message.empty());
    for (const std::string& m : c.mentions) CHECK(message.find(m) != std::string::npos);
  }
}

TEST_CASE("scene: a file that cannot be read is named") {
  try {
    (void)loadScene("/nonexistent/scene.json");
    FAIL("no error");
  } catch (const std::invalid_argument& e) {
    CHECK(std::string(e.what()).find("/nonexistent/scene.json") != std::string::npos);
  }
}

TEST_CASE("scene: a body's own mass, restitution and friction, and the rule for a pair") {
  const Scene scene = parseScene(R"({ "duration": 1, "restitution": 0.5, "friction": 0.4,
      "bodies": [ { "name": "floor", "shape": {"box": [2, 2, 0.5]}, "position": [0, 0, -0.5], "static": true },
                  { "name": "ball", "shape": {"sphere": 0.1}, "position": [0, 0, 1], "mass": 2, "restitution": 0.9, "friction": 0.1 },
                  { "name": "box", "shape": {"box": [0.1, 0.1, 0.1]}, "position": [1, 0, 1] } ] })");
  CHECK(scene.bodies[1].mass == 2);
  CHECK(scene.bodies[2].restitution < 0);  // the scene's
  const auto [e, mu] = materialOf(scene, scene.bodies[0], scene.bodies[1]);
  CHECK(e == 0.9);                                 // the larger
  CHECK(mu == Approx(std::sqrt(0.4 * 0.1)));       // the geometric mean
  const auto [e2, mu2] = materialOf(scene, scene.bodies[0], scene.bodies[2]);
  CHECK(e2 == 0.5);
  CHECK(mu2 == 0.4);
  CHECK_THROWS_WITH(parseScene(R"({ "duration": 1, "bodies": [ { "name": "b", "shape": {"sphere": 1}, "position": [0, 0, 0],
      "mass": 1, "density": 5 } ] })"), Catch::Contains("'mass'") && Catch::Contains("density"));
  CHECK_THROWS_WITH(parseScene(R"({ "duration": 1, "bodies": [ { "name": "b", "shape": {"sphere": 1}, "position": [0, 0, 0],
      "restitution": 1.5 } ] })"), Catch::Contains("'restitution'"));
  CHECK_THROWS_WITH(parseScene(R"({ "duration": 1, "bodies": [ { "name": "b", "shape": {"sphere": 1}, "position": [0, 0, 0],
      "mass": -1 } ] })"), Catch::Contains("'mass'"));
}

TEST_CASE("scene: a mesh's decomposition settings are read, and a bad one is named") {
  const auto shapeOf = [](const std::string& shape) {
    return parseScene(R"({ "duration": 1, "bodies": [ { "name": "m", "shape": )" + shape +
                          R"(, "position": [0, 0, 0] } ] })",
                      "test.json")
        .bodies[0]
        .shape;
  };
  const ShapeSpec plain = shapeOf(R"({"mesh": "a.off"})");
  CHECK(plain.decomposition.budgetSeconds == 30);
  const ShapeSpec s = shapeOf(R"({"mesh": "a.off", "decomposition": {"budget_s": 2.5, "concavity": 20, "min_pieces": 3,
      "compacity_weight": 0.2, "volume_weight": 0.5, "extra_points": false, "face_points": false}})");
  CHECK(s.decomposition.budgetSeconds == 2.5);
  CHECK(s.decomposition.concavity == 20);
  CHECK(s.decomposition.minClusters == 3);
  CHECK(s.decomposition.compacityWeight == 0.2);
  CHECK(s.decomposition.volumeWeight == 0.5);
  CHECK_FALSE(s.decomposition.addExtraDistPoints);
  CHECK_FALSE(s.decomposition.addFacesPoints);
  const std::vector<std::pair<std::string, std::string>> bad = {
      {R"({"budget_s": 0})", "shape.decomposition.budget_s"},
      {R"({"budget_s": "long"})", "shape.decomposition.budget_s"},
      {R"({"concavity": -1})", "shape.decomposition.concavity"},
      {R"({"min_pieces": 0})", "shape.decomposition.min_pieces"},
      {R"({"min_pieces": 2.5})", "shape.decomposition.min_pieces"},
      {R"({"volume_weight": -1})", "shape.decomposition.volume_weight"},
      {R"({"extra_points": 1})", "shape.decomposition.extra_points"},
      {R"({"pieces": 4})", "shape.decomposition.pieces"},
      {R"(30)", "shape.decomposition"},
  };
  for (const auto& [value, field] : bad) {
    INFO(value);
    CHECK_THROWS_WITH(shapeOf(R"({"mesh": "a.off", "decomposition": )" + value + "}"),
                      Catch::Contains("test.json") && Catch::Contains("body 'm'") && Catch::Contains("'" + field + "'"));
  }
}

TEST_CASE("scene: a decomposed mesh is reported once, and a budget given to buildBodies is the one it gets") {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "gjkx-scene-report";
  std::filesystem::create_directories(dir);
  {
    std::ofstream off(dir / "cube.off");
    off << "OFF\n8 12 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 1\n1 0 1\n1 1 1\n0 1 1\n"
        << "3 0 2 1\n3 0 3 2\n3 4 5 6\n3 4 6 7\n3 0 1 5\n3 0 5 4\n3 1 2 6\n3 1 6 5\n3 2 3 7\n3 2 7 6\n3 3 0 4\n3 3 4 7\n";
  }
  Scene scene = parseScene(R"({ "duration": 0.05, "gravity": [0, 0, 0], "bodies": [
      { "name": "a", "shape": {"mesh": "cube.off"}, "position": [0, 0, 0] },
      { "name": "b", "shape": {"mesh": "cube.off"}, "position": [3, 0, 0] } ] })",
                           "test.json");
  scene.folder = dir.string();
  std::vector<std::string> lines;
  MeshBuildOptions options;
  options.cache = "";
  options.report = [&](const std::string& line, const DecompositionReport& report) {
    lines.push_back(line);
    CHECK(report.pieces == 1);
  };
  const std::vector<WorldBody> bodies = buildBodies(scene, 0.05, options);
  REQUIRE(lines.size() == 1);  // two bodies, one mesh used one way: one decomposition, one report
  CHECK_THAT(lines[0], Catch::StartsWith("cube.off: 1 convex piece,") && Catch::Contains("volume excess"));
  CHECK(bodies[0].pieces.size() == 1);
  // A budget of its own overrides the mesh's, and a bad one is refused by name (0: each mesh's own).
  options.budgetSeconds = -1;
  CHECK_THROWS_WITH(buildBodies(scene, 0.05, options), Catch::Contains("budgetSeconds"));
  std::filesystem::remove_all(dir);
}

TEST_CASE("scene: a cylinder is [radius, half_length] along z, each positive") {
  const Scene scene = parseScene(sceneWith(R"("shape": {"cylinder": [0.1, 0.25]}, "position": [0, 0, 1])"), "test.json");
  const ShapeSpec& s = scene.bodies[1].shape;
  CHECK(s.kind == ShapeSpec::Kind::Cylinder);
  CHECK(s.radius == 0.1);
  CHECK(s.halfLength == 0.25);
  CHECK_THAT(errorOf(sceneWith(R"("shape": {"cylinder": [-0.1, 0.25]}, "position": [0, 0, 1])")),
             Catch::Contains("body 'ball'") && Catch::Contains("shape.cylinder[0] (radius)"));
  CHECK_THAT(errorOf(sceneWith(R"("shape": {"cylinder": [0.1, 0]}, "position": [0, 0, 1])")),
             Catch::Contains("shape.cylinder[1] (half_length)"));
  CHECK_THAT(errorOf(sceneWith(R"("shape": {"cylinder": 0.1}, "position": [0, 0, 1])")),
             Catch::Contains("shape.cylinder") && Catch::Contains("[radius, half_length]"));
}

TEST_CASE("scene: the key solver asks for §5 as the paper wrote it, and a bad value is named") {
  const std::string bodies = R"("bodies": [{ "name": "ball", "shape": {"sphere": 0.1}, "position": [0, 0, 1] }] })";
  CHECK(parseScene(R"({ "duration": 1, )" + bodies).run.solver == ToiSolverMode::Gjkx);
  CHECK(parseScene(R"({ "duration": 1, "solver": "paper", )" + bodies).run.solver == ToiSolverMode::Paper);
  CHECK(parseScene(R"({ "duration": 1, "solver": "gjkx", )" + bodies).run.solver == ToiSolverMode::Gjkx);
  CHECK_THROWS_WITH(parseScene(R"({ "duration": 1, "solver": "brent", )" + bodies), Catch::Contains("solver"));
}

TEST_CASE("scene: the pile is five static walls and the bodies asked for, the same for the same seed") {
  const Scene a = fallingIntoABox(24, 2, 2026), b = fallingIntoABox(24, 2, 2026), c = fallingIntoABox(24, 2, 7);
  REQUIRE(a.bodies.size() == 5 + 24);
  CHECK(a.duration == 2);
  int walls = 0;
  for (const BodySpec& body : a.bodies) walls += body.isStatic;
  CHECK(walls == 5);
  for (std::size_t k = 5; k < a.bodies.size(); ++k) {  // the same seed: the same bodies, bit for bit
    CHECK(a.bodies[k].position == b.bodies[k].position);
    CHECK(a.bodies[k].orientation.coeffs() == b.bodies[k].orientation.coeffs());
    CHECK(a.bodies[k].angularVelocity == b.bodies[k].angularVelocity);
  }
  CHECK(a.bodies[5].orientation.coeffs() != c.bodies[5].orientation.coeffs());  // another seed: other spins
  // Every moving body starts above the floor and inside the walls, and the scene runs.
  for (std::size_t k = 5; k < a.bodies.size(); ++k) {
    CHECK(a.bodies[k].position.z() > 0.3);
    CHECK(std::abs(a.bodies[k].position.x()) < a.bodies[2].position.x());
  }
  World world(a, WorldSettings{});
  CHECK(world.step().status == FrameStatus::Done);
}
