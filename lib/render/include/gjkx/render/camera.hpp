/// @file
/// @brief Cameras of the paper's 3D figures, built from Eigen matrices (no GLU).
#pragma once

#include <Eigen/Core>

namespace gjkx::render {

/// The view matrix looking from @p eye at @p target with @p up pointing up on
/// screen (the gluLookAt convention: the camera looks down its -z axis). Used
/// to aim at the polytopes of the 3D figures. Throws std::invalid_argument if
/// eye equals target or up is parallel to the viewing direction.
/// @param eye Position of the camera.
/// @param target Point the camera looks at.
/// @param up Direction that appears upwards.
/// @return The 4 x 4 view matrix.
Eigen::Matrix4d lookAt(const Eigen::Vector3d& eye, const Eigen::Vector3d& target, const Eigen::Vector3d& up);

/// A perspective projection (the gluPerspective convention, OpenGL clip space).
/// Throws std::invalid_argument naming the field if fovy is not in (0, pi),
/// aspect is not positive or not 0 < near < far.
/// @param fovyRadians Vertical field of view in radians.
/// @param aspect Width divided by height of the panel (see Canvas::plotAspect()).
/// @param nearPlane Distance of the near clipping plane (> 0).
/// @param farPlane Distance of the far clipping plane (> near).
/// @return The 4 x 4 projection matrix.
Eigen::Matrix4d perspective(double fovyRadians, double aspect, double nearPlane, double farPlane);

/// An orthographic projection of the box [left, right] x [bottom, top] x
/// [-near, -far] in eye coordinates (the glOrtho convention). Throws
/// std::invalid_argument naming the field if an interval is empty.
/// @param left Left edge of the view volume.
/// @param right Right edge of the view volume.
/// @param bottom Bottom edge of the view volume.
/// @param top Top edge of the view volume.
/// @param nearPlane Near clipping distance.
/// @param farPlane Far clipping distance.
/// @return The 4 x 4 projection matrix.
Eigen::Matrix4d orthographic(double left, double right, double bottom, double top, double nearPlane, double farPlane);

/// A camera of a 3D figure panel: a view matrix (world to eye) and a
/// projection matrix (eye to OpenGL clip space).
struct Camera {
  Eigen::Matrix4d view = Eigen::Matrix4d::Identity();        ///< World to eye coordinates.
  Eigen::Matrix4d projection = Eigen::Matrix4d::Identity();  ///< Eye to clip coordinates.

  /// A camera from a view and a projection matrix.
  /// @param viewMatrix World to eye coordinates, e.g. from lookAt().
  /// @param projectionMatrix Eye to clip coordinates, e.g. from perspective().
  /// @return The camera.
  static Camera fromMatrices(const Eigen::Matrix4d& viewMatrix, const Eigen::Matrix4d& projectionMatrix);

  /// A perspective camera on a sphere around @p target, the usual view of a
  /// polytope in the 3D figures: azimuth turns about the world z axis from the
  /// x axis, elevation lifts the eye towards +z, and the distance is chosen
  /// so that a ball of @p radius around the target fills the view.
  /// @param target Centre of the scene.
  /// @param radius Radius of the ball that must be visible (> 0).
  /// @param azimuthRadians Angle about +z, measured from +x.
  /// @param elevationRadians Angle above the xy plane, in (-pi/2, pi/2).
  /// @param fovyRadians Vertical field of view.
  /// @param aspect Width / height of the panel (see Canvas::plotAspect()).
  /// @return The camera.
  static Camera orbit(const Eigen::Vector3d& target, double radius, double azimuthRadians, double elevationRadians,
                      double fovyRadians, double aspect);

  /// The product projection * view (world to clip coordinates).
  /// @return The world-to-clip matrix.
  Eigen::Matrix4d viewProjection() const { return projection * view; }

  /// True if the projection is orthographic (no perspective division).
  /// @return Whether the projection is orthographic.
  bool isOrthographic() const { return projection(3, 2) == 0.0 && projection(3, 3) != 0.0; }

  /// Position of the eye in world coordinates (for perspective cameras).
  /// @return The eye position.
  Eigen::Vector3d eye() const;

  /// Projects @p world to normalised device coordinates (x, y in [-1, 1] on
  /// screen, z the depth in [-1, 1]); points behind the eye give meaningless
  /// results, the Canvas clips them before projecting.
  /// @param world A point of the scene.
  /// @return The point in normalised device coordinates.
  Eigen::Vector3d project(const Eigen::Vector3d& world) const;
};

}  // namespace gjkx::render
