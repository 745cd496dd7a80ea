/// @file
/// @brief Cameras of the paper's 3D figures, built from Eigen matrices (no GLU).
#pragma once

#include <Eigen/Core>

namespace gjkx::render {

/// The view matrix looking from @p eye at @p target with @p up pointing up on screen (the
/// gluLookAt convention: the camera looks down its -z axis). Throws std::invalid_argument
/// if eye equals target or up is zero or parallel to the viewing direction.
Eigen::Matrix4d lookAt(const Eigen::Vector3d& eye, const Eigen::Vector3d& target, const Eigen::Vector3d& up);

/// A perspective projection (the gluPerspective convention, OpenGL clip space) of vertical
/// field @p fovyRadians and width/height @p aspect (see Canvas::plotAspect()). Throws
/// std::invalid_argument naming the field unless fovy is in (0, pi), aspect > 0 and
/// 0 < nearPlane < farPlane.
Eigen::Matrix4d perspective(double fovyRadians, double aspect, double nearPlane, double farPlane);

/// A camera of a 3D figure panel: a view matrix (world to eye, e.g. lookAt()) and a
/// projection matrix (eye to OpenGL clip space, e.g. perspective()).
struct Camera {
  Eigen::Matrix4d view = Eigen::Matrix4d::Identity();        ///< World to eye coordinates.
  Eigen::Matrix4d projection = Eigen::Matrix4d::Identity();  ///< Eye to clip coordinates.

  /// A perspective camera on a sphere around @p target, the usual view of a body in the 3D
  /// figures: @p azimuthRadians turns about the world z axis from the x axis,
  /// @p elevationRadians (in (-pi/2, pi/2)) lifts the eye towards +z, and the distance is
  /// chosen so that the ball of @p radius (> 0) around the target fills the view.
  static Camera orbit(const Eigen::Vector3d& target, double radius, double azimuthRadians, double elevationRadians,
                      double fovyRadians, double aspect);

  /// Position of the eye in world coordinates.
  Eigen::Vector3d eye() const;
};

}  // namespace gjkx::render
