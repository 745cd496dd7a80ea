/// @file
/// @brief Mass, centre of mass and inertia tensor of a shape of uniform density (§6's rigid bodies).
///
/// The paper's simulation (§6) moves rigid bodies; their response to gravity and to
/// collision impulses needs the mass m, the centre of mass c and the inertia tensor J
/// about c. Boxes, spheres, capsules and cylinders have closed forms. A convex polytope is handled
/// by Mirtich's algorithm, B. Mirtich, "Fast and Accurate Computation of Polyhedral Mass
/// Properties", Journal of Graphics Tools 1(2), 1996: each volume integral
/// \f$\int_V x^i y^j z^k\,dV\f$ is turned into a sum of surface integrals over the faces by the
/// divergence theorem, and each face integral into a line integral around the face's
/// projection onto a coordinate plane by Green's theorem (see src/mass_properties.cpp).
#pragma once

#include <gjkx/support_mapping/shape.hpp>

#include <Eigen/Core>

namespace gjkx {

/// Mass properties of a body of uniform density, in the body frame of its shape.
struct MassProperties {
  /// Mass m (density times volume).
  double mass = 0;
  /// Centre of mass c, in the body frame of the shape.
  Eigen::Vector3d centerOfMass = Eigen::Vector3d::Zero();
  /// Inertia tensor about the centre of mass, along the body axes:
  /// \f$J = \int_V \rho\,(\lVert r\rVert^2 \mathbf{1} - r\,r^T)\,dV\f$, \f$r = x - c\f$.
  Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();
};

/// The mass properties of `shape` filled with material of `density` (mass per volume).
///
/// Closed forms for the box (\f$m = 8\rho h_x h_y h_z\f$, \f$J_{xx} = \tfrac{m}{3}(h_y^2 + h_z^2)\f$),
/// the sphere (\f$J = \tfrac25 m r^2 \mathbf{1}\f$), the capsule (a cylinder and two
/// hemispheres) and the cylinder (\f$m = 2\pi\rho r^2 h\f$, \f$J_{zz} = \tfrac12 m r^2\f$,
/// \f$J_{xx} = J_{yy} = m(\tfrac14 r^2 + \tfrac13 h^2)\f$); Mirtich's polyhedral mass
/// properties for a polytope. Throws std::invalid_argument naming the field for a density
/// that is not finite and positive ("density"), for a shape without volume ("shape": a
/// point, segment, triangle, planar polytope, or a box, sphere, capsule or cylinder of zero size).
MassProperties massProperties(const Shape<double>& shape, double density);

/// Mirtich's volume integrals of a closed triangulated surface (counter-clockwise seen
/// from outside): mass properties of the solid it bounds at `density`. Used by
/// massProperties() for polytopes; exposed for tests and for meshes. Throws
/// std::invalid_argument ("mesh: ...") if the enclosed volume is not positive.
MassProperties polyhedronMassProperties(const std::vector<Eigen::Vector3d>& vertices,
                                        const std::vector<std::array<int, 3>>& triangles, double density);

}  // namespace gjkx
