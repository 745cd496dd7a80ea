// Look-at and perspective matrices, and the orbiting camera, of the 3D figures.
#include <gjkx/render/camera.hpp>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace gjkx::render {

Eigen::Matrix4d lookAt(const Eigen::Vector3d& eye, const Eigen::Vector3d& target, const Eigen::Vector3d& up) {
  if (!((target - eye).norm() > 0.0)) throw std::invalid_argument("lookAt: eye and target coincide");
  const Eigen::Vector3d f = (target - eye).normalized(), side = f.cross(up);
  if (!(up.norm() > 0.0) || !(side.norm() > 1e-12 * up.norm()))
    throw std::invalid_argument("lookAt: up is zero or parallel to the viewing direction");
  const Eigen::Vector3d s = side.normalized(), u = s.cross(f);
  Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
  m.block<1, 3>(0, 0) = s.transpose();
  m.block<1, 3>(1, 0) = u.transpose();
  m.block<1, 3>(2, 0) = -f.transpose();
  m.block<3, 1>(0, 3) = Eigen::Vector3d(-s.dot(eye), -u.dot(eye), f.dot(eye));
  return m;
}

Eigen::Matrix4d perspective(double fovyRadians, double aspect, double nearPlane, double farPlane) {
  if (!(fovyRadians > 0.0 && fovyRadians < M_PI)) throw std::invalid_argument("perspective: fovyRadians must be in (0, pi)");
  if (!(aspect > 0.0) || !std::isfinite(aspect)) throw std::invalid_argument("perspective: aspect must be positive");
  if (!(nearPlane > 0.0)) throw std::invalid_argument("perspective: nearPlane must be positive");
  if (!(farPlane > nearPlane)) throw std::invalid_argument("perspective: farPlane must exceed nearPlane");
  const double f = 1.0 / std::tan(fovyRadians / 2.0);
  Eigen::Matrix4d m = Eigen::Matrix4d::Zero();
  m(0, 0) = f / aspect;
  m(1, 1) = f;
  m(2, 2) = (farPlane + nearPlane) / (nearPlane - farPlane);
  m(2, 3) = 2.0 * farPlane * nearPlane / (nearPlane - farPlane);
  m(3, 2) = -1.0;
  return m;
}

Camera Camera::orbit(const Eigen::Vector3d& target, double radius, double azimuthRadians, double elevationRadians,
                     double fovyRadians, double aspect) {
  if (!(radius > 0.0)) throw std::invalid_argument("Camera::orbit: radius must be positive");
  if (!(std::abs(elevationRadians) < M_PI / 2.0)) throw std::invalid_argument("Camera::orbit: elevationRadians must be in (-pi/2, pi/2)");
  if (!(fovyRadians > 0.0 && fovyRadians < M_PI)) throw std::invalid_argument("Camera::orbit: fovyRadians must be in (0, pi)");
  if (!(aspect > 0.0)) throw std::invalid_argument("Camera::orbit: aspect must be positive");
  // The ball must fit the narrower of the two fields of view.
  const double halfFov = std::min(fovyRadians / 2.0, std::atan(std::tan(fovyRadians / 2.0) * aspect));
  const double distance = radius / std::sin(halfFov);
  const Eigen::Vector3d eye = target + distance * Eigen::Vector3d(std::cos(elevationRadians) * std::cos(azimuthRadians),
                                                                  std::cos(elevationRadians) * std::sin(azimuthRadians), std::sin(elevationRadians));
  return Camera{lookAt(eye, target, Eigen::Vector3d::UnitZ()),
                      perspective(fovyRadians, aspect, std::max(1e-3 * distance, distance - 2.0 * radius), distance + 2.0 * radius)};
}

Eigen::Vector3d Camera::eye() const { return -view.block<3, 3>(0, 0).transpose() * view.block<3, 1>(0, 3); }

}  // namespace gjkx::render
