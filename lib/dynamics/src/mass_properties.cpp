// Mass properties: closed forms and Mirtich's polyhedral algorithm (see the header).
#include <gjkx/dynamics/mass_properties.hpp>

#include <cmath>
#include <stdexcept>
#include <string>

namespace gjkx {
namespace {

constexpr double kPi = 3.14159265358979323846;

// Mirtich's algorithm, step by step (the names are the paper's).
//
// Volume integrals. With the divergence theorem, for a field F with div F = f,
//   \int_V f dV = \sum_faces \int_F (n . F) dA.
// Choosing F along one axis gives, for instance,
//   T0  = \int_V 1 dV      = \sum_F n_x \int_F x dA,
//   T1x = \int_V x dV      = 1/2 \sum_F n_x \int_F x^2 dA,
//   T2x = \int_V x^2 dV    = 1/3 \sum_F n_x \int_F x^3 dA,
//   TPx = \int_V x y dV    = 1/2 \sum_F n_x \int_F x^2 y dA   (TPy = \int yz, TPz = \int zx).
//
// Face integrals. A face lies in the plane n . x + w = 0. Name the coordinate along which
// |n| is largest gamma (C), and the two others alpha, beta (A, B) so that (alpha, beta,
// gamma) is a right-handed cycle. Project the face onto the alpha-beta plane (region Pi);
// on the face gamma = -(n_a alpha + n_b beta + w) / n_c and dA = d(alpha) d(beta) / |n_c|.
// So each face integral of a monomial is a combination of projection integrals
// \pi_{pq} = \int_Pi alpha^p beta^q d(alpha) d(beta), e.g.
//   F_gamma = \int_F gamma dA = -1/(n_c |n_c|) (n_a P_a + n_b P_b + w P_1).
// Mirtich keeps 1/n_c rather than 1/|n_c|: the sign is absorbed because the projected
// polygon's orientation flips with the sign of n_c, so the signed projection integrals
// below carry it.
//
// Projection integrals. By Green's theorem, \int_Pi alpha^p beta^q = \oint of a polynomial
// along the projected boundary, and along the edge from (a0, b0) to (a1, b1) each such line
// integral has a closed form in a0, a1, b0, b1 (Mirtich's eq. (37)-(40)); the sums are below.
struct ProjectionIntegrals {
  double P1 = 0, Pa = 0, Pb = 0, Paa = 0, Pab = 0, Pbb = 0, Paaa = 0, Paab = 0, Pabb = 0, Pbbb = 0;
};

ProjectionIntegrals projectionIntegrals(const std::array<Eigen::Vector3d, 3>& v, int A, int B) {
  ProjectionIntegrals p;
  for (int i = 0; i < 3; ++i) {
    const double a0 = v[i][A], b0 = v[i][B];
    const double a1 = v[(i + 1) % 3][A], b1 = v[(i + 1) % 3][B];
    const double da = a1 - a0, db = b1 - b0;
    const double a0_2 = a0 * a0, a0_3 = a0_2 * a0, a0_4 = a0_3 * a0;
    const double b0_2 = b0 * b0, b0_3 = b0_2 * b0, b0_4 = b0_3 * b0;
    const double a1_2 = a1 * a1, a1_3 = a1_2 * a1;
    const double b1_2 = b1 * b1, b1_3 = b1_2 * b1;

    const double C1 = a1 + a0;
    const double Ca = a1 * C1 + a0_2, Caa = a1 * Ca + a0_3, Caaa = a1 * Caa + a0_4;
    const double Cb = b1 * (b1 + b0) + b0_2, Cbb = b1 * Cb + b0_3, Cbbb = b1 * Cbb + b0_4;
    const double Cab = 3 * a1_2 + 2 * a1 * a0 + a0_2, Kab = a1_2 + 2 * a1 * a0 + 3 * a0_2;
    const double Caab = a0 * Cab + 4 * a1_3, Kaab = a1 * Kab + 4 * a0_3;
    const double Cabb = 4 * b1_3 + 3 * b1_2 * b0 + 2 * b1 * b0_2 + b0_3;
    const double Kabb = b1_3 + 2 * b1_2 * b0 + 3 * b1 * b0_2 + 4 * b0_3;

    p.P1 += db * C1;
    p.Pa += db * Ca;
    p.Paa += db * Caa;
    p.Paaa += db * Caaa;
    p.Pb += da * Cb;
    p.Pbb += da * Cbb;
    p.Pbbb += da * Cbbb;
    p.Pab += db * (b1 * Cab + b0 * Kab);
    p.Paab += db * (b1 * Caab + b0 * Kaab);
    p.Pabb += da * (a1 * Cabb + a0 * Kabb);
  }
  p.P1 /= 2.0;
  p.Pa /= 6.0;
  p.Paa /= 12.0;
  p.Paaa /= 20.0;
  p.Pb /= -6.0;
  p.Pbb /= -12.0;
  p.Pbbb /= -20.0;
  p.Pab /= 24.0;
  p.Paab /= 60.0;
  p.Pabb /= -60.0;
  return p;
}

MassProperties fromVolumeIntegrals(double T0, const Eigen::Vector3d& T1, const Eigen::Vector3d& T2,
                                   const Eigen::Vector3d& TP, double density) {
  MassProperties m;
  m.mass = density * T0;
  m.centerOfMass = T1 / T0;
  // Inertia about the reference origin: J_xx = \rho \int (y^2 + z^2), J_xy = -\rho \int xy, ...
  Eigen::Matrix3d J;
  J(0, 0) = density * (T2.y() + T2.z());
  J(1, 1) = density * (T2.z() + T2.x());
  J(2, 2) = density * (T2.x() + T2.y());
  J(0, 1) = J(1, 0) = -density * TP.x();
  J(1, 2) = J(2, 1) = -density * TP.y();
  J(2, 0) = J(0, 2) = -density * TP.z();
  // Parallel axis theorem: J_c = J_o - m (|c|^2 1 - c c^T).
  const Eigen::Vector3d& c = m.centerOfMass;
  m.inertia = J - m.mass * (c.squaredNorm() * Eigen::Matrix3d::Identity() - c * c.transpose());
  return m;
}

void requireDensity(double density) {
  if (!std::isfinite(density) || !(density > 0))
    failInput("density", "must be finite and positive, got " + std::to_string(density));
}

MassProperties boxProperties(const Box<double>& box, double density) {
  const Eigen::Vector3d& h = box.halfExtents;
  if (!(h.minCoeff() > 0)) failInput("shape", "a box with a zero half extent has no volume");
  MassProperties m;
  m.mass = density * 8 * h.x() * h.y() * h.z();
  // J_xx = \rho \int (y^2 + z^2) = m/3 (h_y^2 + h_z^2), since \int_{-h}^{h} y^2 dy / (2h) = h^2 / 3.
  const Eigen::Vector3d h2 = h.cwiseProduct(h);
  m.inertia = (m.mass / 3 * Eigen::Vector3d(h2.y() + h2.z(), h2.z() + h2.x(), h2.x() + h2.y())).asDiagonal();
  return m;
}

MassProperties sphereProperties(double r, double density) {
  if (!(r > 0)) failInput("shape", "a sphere of radius 0 has no volume");
  MassProperties m;
  m.mass = density * 4.0 / 3.0 * kPi * r * r * r;
  m.inertia = (0.4 * m.mass * r * r) * Eigen::Matrix3d::Identity();
  return m;
}

MassProperties cylinderProperties(const Cylinder<double>& cylinder, double density) {
  const double r = cylinder.radius, h = cylinder.halfLength;
  if (!(r > 0) || !(h > 0)) failInput("shape", "a cylinder of radius 0 or length 0 has no volume");
  // m = rho pi r^2 2h. About the axis, each ring of radius rho' adds rho' ^2 dm:
  // J_zz = rho 2h int_0^r rho'^2 2 pi rho' d rho' = m r^2 / 2. Across it, through the centre:
  // J_xx = rho int (y^2 + z^2) dV, where int y^2 over the disc is pi r^4 / 4 (half the polar
  // moment) and int z^2 over [-h, h] is 2h^3 / 3, so J_xx = m (r^2 / 4 + h^2 / 3).
  MassProperties m;
  m.mass = density * kPi * r * r * 2 * h;
  const double across = m.mass * (r * r / 4 + h * h / 3);
  m.inertia = Eigen::Vector3d(across, across, m.mass * r * r / 2).asDiagonal();
  return m;
}

MassProperties capsuleProperties(const Capsule<double>& capsule, double density) {
  const double r = capsule.radius;
  if (!(r > 0)) failInput("shape", "a capsule of radius 0 has no volume");
  const Eigen::Vector3d a = capsule.axis.a, b = capsule.axis.b;
  const double h = 0.5 * (b - a).norm();  // half the axis length
  if (h == 0) {
    MassProperties m = sphereProperties(r, density);
    m.centerOfMass = a;
    return m;
  }
  // A cylinder of radius r and length 2h, and two hemispheres (together one ball).
  const double mc = density * kPi * r * r * 2 * h;
  const double ms = density * 4.0 / 3.0 * kPi * r * r * r;
  // About the axis: cylinder m r^2 / 2, ball 2/5 m r^2.
  const double axial = mc * r * r / 2 + ms * 0.4 * r * r;
  // Across the axis, through the centre: the cylinder m (r^2/4 + (2h)^2/12); each hemisphere
  // (mass ms/2) has its centre of mass 3r/8 from its flat face and 83/320 m r^2 about it,
  // so by the parallel axis theorem the two give ms (83/320 r^2 + (h + 3r/8)^2)
  // = ms (2/5 r^2 + h^2 + 3/4 h r).
  const double across = mc * (r * r / 4 + h * h / 3) + ms * (0.4 * r * r + h * h + 0.75 * h * r);
  const Eigen::Vector3d d = (b - a).normalized();
  MassProperties m;
  m.mass = mc + ms;
  m.centerOfMass = 0.5 * (a + b);
  m.inertia = across * (Eigen::Matrix3d::Identity() - d * d.transpose()) + axial * d * d.transpose();
  return m;
}

}  // namespace

MassProperties polyhedronMassProperties(const std::vector<Eigen::Vector3d>& vertices,
                                        const std::vector<std::array<int, 3>>& triangles, double density) {
  requireDensity(density);
  if (vertices.empty() || triangles.empty()) failInput("mesh", "has no faces");
  // The integrals are taken about a reference point inside (the vertex centroid), not
  // about the body origin: a polytope far from its origin would otherwise lose digits to
  // cancellation in the third-order terms. The centre of mass is moved back at the end.
  Eigen::Vector3d reference = Eigen::Vector3d::Zero();
  for (const auto& v : vertices) reference += v;
  reference /= double(vertices.size());

  double T0 = 0;
  Eigen::Vector3d T1 = Eigen::Vector3d::Zero(), T2 = Eigen::Vector3d::Zero(), TP = Eigen::Vector3d::Zero();
  for (const auto& tri : triangles) {
    const std::array<Eigen::Vector3d, 3> v = {vertices[tri[0]] - reference, vertices[tri[1]] - reference,
                                              vertices[tri[2]] - reference};
    Eigen::Vector3d n = (v[1] - v[0]).cross(v[2] - v[0]);
    const double area2 = n.norm();
    if (!(area2 > 0)) continue;  // a sliver of zero area adds nothing
    n /= area2;
    const double w = -n.dot(v[0]);
    // gamma (C): the axis along which the normal is largest; (A, B, C) a right-handed cycle.
    const Eigen::Vector3d an = n.cwiseAbs();
    const int C = (an.x() > an.y() && an.x() > an.z()) ? 0 : (an.y() > an.z() ? 1 : 2);
    const int A = (C + 1) % 3, B = (A + 1) % 3;
    const ProjectionIntegrals p = projectionIntegrals(v, A, B);

    // Face integrals (Mirtich's eq. (26)-(35)) from the projection integrals.
    const double na = n[A], nb = n[B];
    const double k1 = 1 / n[C], k2 = k1 * k1, k3 = k2 * k1, k4 = k3 * k1;
    const double Fa = k1 * p.Pa, Fb = k1 * p.Pb;
    const double Fc = -k2 * (na * p.Pa + nb * p.Pb + w * p.P1);
    const double Faa = k1 * p.Paa, Fbb = k1 * p.Pbb;
    const double Fcc = k3 * (na * na * p.Paa + 2 * na * nb * p.Pab + nb * nb * p.Pbb +
                             w * (2 * (na * p.Pa + nb * p.Pb) + w * p.P1));
    const double Faaa = k1 * p.Paaa, Fbbb = k1 * p.Pbbb;
    const double Fccc = -k4 * (na * na * na * p.Paaa + 3 * na * na * nb * p.Paab + 3 * na * nb * nb * p.Pabb +
                               nb * nb * nb * p.Pbbb +
                               3 * w * (na * na * p.Paa + 2 * na * nb * p.Pab + nb * nb * p.Pbb) +
                               w * w * (3 * (na * p.Pa + nb * p.Pb) + w * p.P1));
    const double Faab = k1 * p.Paab;
    const double Fbbc = -k2 * (na * p.Pabb + nb * p.Pbbb + w * p.Pbb);
    const double Fcca = k3 * (na * na * p.Paaa + 2 * na * nb * p.Paab + nb * nb * p.Pabb +
                              w * (2 * (na * p.Paa + nb * p.Pab) + w * p.Pa));

    // Volume integrals (divergence theorem): sum the faces' contributions.
    T0 += n.x() * (A == 0 ? Fa : (B == 0 ? Fb : Fc));
    T1[A] += n[A] * Faa;
    T1[B] += n[B] * Fbb;
    T1[C] += n[C] * Fcc;
    T2[A] += n[A] * Faaa;
    T2[B] += n[B] * Fbbb;
    T2[C] += n[C] * Fccc;
    TP[A] += n[A] * Faab;
    TP[B] += n[B] * Fbbc;
    TP[C] += n[C] * Fcca;
  }
  T1 /= 2;
  T2 /= 3;
  TP /= 2;
  if (!(T0 > 0) || !std::isfinite(T0))
    failInput("mesh", "encloses no positive volume (faces must be counter-clockwise seen from outside)");
  MassProperties m = fromVolumeIntegrals(T0, T1, T2, TP, density);
  m.centerOfMass += reference;
  return m;
}

MassProperties massProperties(const Shape<double>& shape, double density) {
  requireDensity(density);
  return std::visit(
      [density](const auto& x) -> MassProperties {
        using X = std::decay_t<decltype(x)>;
        if constexpr (std::is_same_v<X, Box<double>>) {
          return boxProperties(x, density);
        } else if constexpr (std::is_same_v<X, Sphere<double>>) {
          return sphereProperties(x.radius, density);
        } else if constexpr (std::is_same_v<X, Capsule<double>>) {
          return capsuleProperties(x, density);
        } else if constexpr (std::is_same_v<X, Cylinder<double>>) {
          return cylinderProperties(x, density);
        } else if constexpr (std::is_same_v<X, Polytope<double>>) {
          if (x.planar()) failInput("shape", "a planar polytope (polygon) has no volume");
          return polyhedronMassProperties(x.vertices(), x.triangles(), density);
        } else {
          failInput("shape", "a point, segment or triangle has no volume, so no mass properties");
          return {};
        }
      },
      shape.variant());
}

}  // namespace gjkx
