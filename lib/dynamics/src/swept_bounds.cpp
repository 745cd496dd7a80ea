// Swept bounds of a free-flight path (swept_bounds.hpp).
#include <gjkx/dynamics/swept_bounds.hpp>

#include <gjkx/support_mapping/placed.hpp>

namespace gjkx {

Bounds sweptBounds(const Shape<double>& shape, double radius, bool isStatic, const FreeFlight& path, double t0,
                   double t1, const Eigen::Vector3d& gravity) {
  const BodyState a = path.stateAt(t0), z = path.stateAt(t1);
  if (isStatic) {  // a static body's box is tight (its support along each axis), with no bulge
    Bounds tight;
    const Placed<Shape<double>> placed{shape, a.worldFromBody};
    for (int k = 0; k < 3; ++k) {
      Eigen::Vector3d e = Eigen::Vector3d::Zero();
      e[k] = 1;
      tight.hi[k] = placed.support(e)[k];
      tight.lo[k] = placed.support(-e)[k];
    }
    return tight;
  }
  Bounds box;
  if (path.start.angularVelocity.squaredNorm() > 0) {
    // Turning: every orientation may occur, the sphere about the centre of mass.
    box.add(a.worldFromBody.translation);
    box.add(z.worldFromBody.translation);
    box.inflate(radius);
  } else {
    // Not turning: the shape's own box at both ends (the box moves with the centre of mass).
    for (const BodyState* s : {&a, &z}) {
      const Placed<Shape<double>> placed{shape, s->worldFromBody};
      for (int k = 0; k < 3; ++k) {
        Eigen::Vector3d e = Eigen::Vector3d::Zero();
        e[k] = 1;
        box.add(Eigen::Vector3d(placed.support(e)));
        box.add(Eigen::Vector3d(placed.support(-e)));
      }
    }
  }
  // The ballistic bulge of the path off its chord: |g| T^2 / 8.
  const double T = t1 - t0;
  box.inflate(gravity.norm() * T * T / 8);
  return box;
}

}  // namespace gjkx
