// Swept bounds of a free-flight path (swept_bounds.hpp).
#include <gjkx/dynamics/swept_bounds.hpp>

#include <gjkx/support_mapping/placed.hpp>

namespace gjkx {

Bounds boundsAt(const Shape<double>& shape, const Pose<double>& pose, SweepHints* hints) {
  SweepHints own{};
  SweepHints& h = hints ? *hints : own;
  const Placed<Shape<double>> placed{shape, pose};
  Bounds box;
  for (int k = 0; k < 3; ++k) {
    Eigen::Vector3d e = Eigen::Vector3d::Zero();
    e[k] = 1;
    box.add(Eigen::Vector3d(placed.support(e, h[2 * k])));
    box.add(Eigen::Vector3d(placed.support(-e, h[2 * k + 1])));
  }
  return box;
}

Bounds sweptBounds(const Shape<double>& shape, double radius, bool isStatic, const FreeFlight& path, double t0,
                   double t1, const Eigen::Vector3d& gravity, SweepHints* hints) {
  const BodyState a = path.stateAt(t0), z = path.stateAt(t1);
  // A static body's box is tight (its support along each axis), with no bulge.
  if (isStatic) return boundsAt(shape, a.worldFromBody, hints);
  // The shape's own box at both ends of [t0, t1], grown by how far any of its points can
  // bulge off the chord between its two ends: a point p(t) whose acceleration stays below
  // a lies within a T^2 / 8 of the chord, and the chord lies in the two end boxes' union.
  // The path (free_flight.hpp) turns about a fixed axis at a constant rate w and falls
  // with g, so a point within `radius` of the centre of mass has a <= |g| + w^2 radius
  // (MotionBound::pointAcceleration).
  const double T = t1 - t0;
  Bounds box = boundsAt(shape, a.worldFromBody, hints);
  box.add(boundsAt(shape, z.worldFromBody, hints));
  box.inflate(path.motion.bound().pointAcceleration(radius) * T * T / 8);
  if (path.start.angularVelocity.squaredNorm() > 0) {
    // Turning far, the sphere about the centre of mass is the tighter box (each holds the
    // body, so their overlap does): its centre at both ends, with the ballistic bulge.
    Bounds sphere;
    sphere.add(a.worldFromBody.translation);
    sphere.add(z.worldFromBody.translation);
    sphere.inflate(radius + gravity.norm() * T * T / 8);
    box.lo = box.lo.cwiseMax(sphere.lo);
    box.hi = box.hi.cwiseMin(sphere.hi);
  }
  return box;
}

}  // namespace gjkx
