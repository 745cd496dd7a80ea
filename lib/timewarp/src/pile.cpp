// The pile (pile.hpp).
#include <gjkx/timewarp/pile.hpp>

#include <cmath>
#include <random>
#include <string>

namespace gjkx {

Scene fallingIntoABox(int count, double duration, unsigned seed) {
  Scene scene;
  scene.duration = duration;
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> unit(-1, 1);
  const int side = int(std::ceil(std::cbrt(double(count) / 2)));  // a grid side x side x 2*side
  const double spacing = 0.45, half = 0.5 * spacing * side + 0.3;
  auto wall = [&](const char* name, Eigen::Vector3d h, Eigen::Vector3d p) {
    BodySpec b;
    b.name = name;
    b.shape.kind = ShapeSpec::Kind::Box;
    b.shape.halfExtents = h;
    b.position = p;
    b.isStatic = true;
    scene.bodies.push_back(b);
  };
  wall("floor", {half + 0.2, half + 0.2, 0.1}, {0, 0, -0.1});
  wall("wall_xm", {0.1, half + 0.2, 2}, {-half - 0.1, 0, 2});
  wall("wall_xp", {0.1, half + 0.2, 2}, {half + 0.1, 0, 2});
  wall("wall_ym", {half, 0.1, 2}, {0, -half - 0.1, 2});
  wall("wall_yp", {half, 0.1, 2}, {0, half + 0.1, 2});
  for (int k = 0; k < count; ++k) {
    BodySpec b;
    b.name = "body" + std::to_string(k);
    const int ix = k % side, iy = (k / side) % side, iz = k / (side * side);
    b.position = Eigen::Vector3d((ix - 0.5 * (side - 1)) * spacing, (iy - 0.5 * (side - 1)) * spacing, 0.4 + iz * spacing);
    b.orientation = Eigen::Quaterniond(Eigen::Vector4d(unit(random), unit(random), unit(random), unit(random)).normalized());
    b.velocity = Eigen::Vector3d(unit(random), unit(random), 0);
    b.angularVelocity = Eigen::Vector3d(unit(random), unit(random), unit(random)) * 3;
    switch (k % 4) {
      case 0:
        b.shape.kind = ShapeSpec::Kind::Box;
        b.shape.halfExtents = Eigen::Vector3d(0.12, 0.08, 0.06);
        break;
      case 1:
        b.shape.kind = ShapeSpec::Kind::Sphere;
        b.shape.radius = 0.1;
        break;
      case 2:
        b.shape.kind = ShapeSpec::Kind::Capsule;
        b.shape.radius = 0.06;
        b.shape.halfLength = 0.08;
        break;
      default:
        b.shape.kind = ShapeSpec::Kind::Polytope;
        for (int v = 0; v < 10; ++v)
          b.shape.points.push_back(Eigen::Vector3d(unit(random), unit(random), unit(random)).normalized() * 0.12);
        break;
    }
    scene.bodies.push_back(b);
  }
  return scene;
}

}  // namespace gjkx
