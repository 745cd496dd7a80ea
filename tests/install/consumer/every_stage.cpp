// Every static stage of the installed package, so that every library the package finds
// again (Qhull, assimp, HACD, Boost.Odeint, nlohmann-json) is on the link line and used.
//
// A ball of radius 0.1 is dropped from rest with its centre at z = 0.5 onto a static floor
// whose top is z = 0 (gjkx::timewarp parses the scene with nlohmann-json; gjkx::dynamics
// integrates with Boost.Odeint). It first touches the floor after falling 0.4:
// t = sqrt(2 * 0.4 / 9.81) = 0.28558 s. And the hull of a unit cube's corners has volume 1
// (gjkx::mesh, whose object also holds the HACD decomposition, and Qhull).
#include <gjkx/mesh/convex_decomposition.hpp>
#include <gjkx/mesh/triangle_mesh.hpp>
#include <gjkx/timewarp/scene.hpp>
#include <gjkx/timewarp/world.hpp>

#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <vector>

int main() {
  bool ok = true;

  const gjkx::Scene scene = gjkx::parseScene(R"({
    "gravity": [0, 0, -9.81], "frame_rate": 24, "duration": 0.5, "scalar": "double",
    "bodies": [
      { "name": "floor", "shape": {"box": [1, 1, 0.1]}, "position": [0, 0, -0.1], "static": true },
      { "name": "ball", "shape": {"sphere": 0.1}, "position": [0, 0, 0.5] } ] })",
                                             "consumer");
  gjkx::World world(scene);
  while (!world.done()) world.step();
  const double expected = std::sqrt(2 * 0.4 / 9.81);
  if (world.collisionLog().empty()) {
    std::printf("first collision: none, expected at %.5f s\n", expected);
    ok = false;
  } else {
    const double first = world.collisionLog().front().time;
    std::printf("first collision at %.5f s, expected %.5f s\n", first, expected);
    ok = ok && std::abs(first - expected) < 1e-3;
  }

  std::vector<Eigen::Vector3d> corners;
  for (double x : {0.0, 1.0})
    for (double y : {0.0, 1.0})
      for (double z : {0.0, 1.0}) corners.emplace_back(x, y, z);
  const double volume = gjkx::hullVolume(corners);
  std::printf("hull volume %.12f, expected 1\n", volume);
  ok = ok && std::abs(volume - 1) < 1e-12;

  try {  // Assimp's reader is behind this (the file is checked first).
    gjkx::readMesh("/nonexistent/gjkx-consumer.obj");
    ok = false;
  } catch (const std::runtime_error& e) {
    std::printf("readMesh refused: %s\n", e.what());
  }

  std::printf("%s\n", ok ? "OK" : "WRONG");
  return ok ? 0 : 1;
}
