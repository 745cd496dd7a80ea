/// @file
/// @brief The study's one shape description: a box, sphere, capsule, convex polytope,
/// polygon or disk by its kind and numbers, from which our library, the reference and
/// every peer (peers.hpp) build their own shape, so all answer the same query on the same
/// numbers.
///
/// Holds (namespace gjkx::study): `ShapeKind`, `ShapeDescription` (kind, parameters, the
/// hull's vertices), its builders (`boxDescription`, `sphereDescription`,
/// `capsuleDescription`, `diskDescription`, `polytopeDescription`, `polygonDescription`,
/// `hullDescription`,
/// `randomShape`), our shape for a description (`ourShape`, `withOurShape`) and the
/// support point by a linear scan (`scanSupport`, what the study hands to libccd).
/// Every shape is centred on its body origin; a capsule's axis is the body's z axis.
#pragma once

#include <gjkx/motion/pose.hpp>
#include <gjkx/support_mapping/polytope.hpp>
#include <gjkx/support_mapping/primitives.hpp>

#include <Eigen/Geometry>

#include <memory>
#include <random>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <variant>
#include <vector>

namespace gjkx::study {

/// The kinds of shape in the study (a polygon and a disk lie in the plane z = 0: the 2D set).
enum class ShapeKind { Box, Sphere, Capsule, Polytope, Polygon, Disk };

/// One shape in its body frame (centred on the body origin), from which every library
/// builds its own.
struct ShapeDescription {
  /// What it is.
  ShapeKind kind = ShapeKind::Box;
  /// Box: half extents along the body axes.
  Eigen::Vector3d halfExtents = Eigen::Vector3d::Ones();
  /// Sphere, capsule, disk: the radius.
  double radius = 0;
  /// Capsule: its axis runs from (0, 0, -halfLength) to (0, 0, halfLength).
  double halfLength = 0;
  /// Box (its 8 corners), polytope, polygon: the convex hull, in double.
  std::shared_ptr<const Polytope<double>> hull;
  /// The same hull in float (the hull of the double hull's vertices), built once.
  std::shared_ptr<const Polytope<float>> hullF;

  /// A short name for tables ("box", "capsule", "poly100", "polygon6", "disk").
  std::string name() const {
    switch (kind) {
      case ShapeKind::Box: return "box";
      case ShapeKind::Sphere: return "sphere";
      case ShapeKind::Capsule: return "capsule";
      case ShapeKind::Polytope: return "poly" + std::to_string(hull->vertexCount());
      case ShapeKind::Polygon: return "polygon" + std::to_string(hull->vertexCount());
      case ShapeKind::Disk: return "disk";
    }
    return "?";
  }
  /// Largest distance of a point of the shape from the body origin.
  double boundingRadius() const {
    switch (kind) {
      case ShapeKind::Box: return halfExtents.norm();
      case ShapeKind::Sphere:
      case ShapeKind::Disk: return radius;
      case ShapeKind::Capsule: return halfLength + radius;
      case ShapeKind::Polytope:
      case ShapeKind::Polygon: return hull->boundingRadius();
    }
    return 0;
  }
  /// The vertex count for polytopes and polygons (8 for a box, 0 otherwise).
  int vertexCount() const { return hull ? hull->vertexCount() : 0; }
};

/// A box of half extents `h` (its hull, the 8 corners, built for the reference and the peers).
inline ShapeDescription boxDescription(const Eigen::Vector3d& h) {
  ShapeDescription s;
  s.kind = ShapeKind::Box;
  s.halfExtents = h;
  std::vector<Vector3<double>> corners;
  for (int k = 0; k < 8; ++k) corners.emplace_back((k & 1) ? h.x() : -h.x(), (k & 2) ? h.y() : -h.y(), (k & 4) ? h.z() : -h.z());
  s.hull = std::make_shared<const Polytope<double>>(Polytope<double>::hull(corners));
  return s;
}
/// A sphere of radius r.
inline ShapeDescription sphereDescription(double r) {
  ShapeDescription s;
  s.kind = ShapeKind::Sphere;
  s.radius = r;
  return s;
}
/// A capsule: the segment from (0, 0, -halfLength) to (0, 0, halfLength) inflated by r.
inline ShapeDescription capsuleDescription(double halfLength, double r) {
  ShapeDescription s;
  s.kind = ShapeKind::Capsule;
  s.halfLength = halfLength;
  s.radius = r;
  return s;
}
/// A disk of radius r in the plane z = 0 (a sphere to the 3D libraries, a rounded point to Box2D).
inline ShapeDescription diskDescription(double r) {
  ShapeDescription s;
  s.kind = ShapeKind::Disk;
  s.radius = r;
  return s;
}

/// The float hull from a double hull's vertices (the same hull when the cast keeps them apart).
inline std::shared_ptr<const Polytope<float>> floatHull(const Polytope<double>& hull, bool planar) {
  std::vector<Vector3<float>> points;
  for (const auto& v : hull.vertices()) points.push_back(v.cast<float>());
  return std::make_shared<const Polytope<float>>(planar ? Polytope<float>::polygon(points) : Polytope<float>::hull(points));
}

/// The convex polytope (kind Polytope) or polygon in z = 0 (kind Polygon) spanned by
/// `points`: their hull, in double and in float.
inline ShapeDescription hullDescription(ShapeKind kind, const std::vector<Vector3<double>>& points) {
  if (kind != ShapeKind::Polytope && kind != ShapeKind::Polygon) failInput("hullDescription.kind", "must be Polytope or Polygon");
  const bool planar = kind == ShapeKind::Polygon;
  ShapeDescription s;
  s.kind = kind;
  s.hull = std::make_shared<const Polytope<double>>(planar ? Polytope<double>::polygon(points) : Polytope<double>::hull(points));
  s.hullF = floatHull(*s.hull, planar);
  return s;
}
/// The convex polytope spanned by `points`.
inline ShapeDescription polytopeDescription(const std::vector<Vector3<double>>& points) {
  return hullDescription(ShapeKind::Polytope, points);
}
/// The convex polygon spanned by `points` in the plane z = 0.
inline ShapeDescription polygonDescription(const std::vector<Vector3<double>>& points) {
  return hullDescription(ShapeKind::Polygon, points);
}

/// A random unit vector (a normalised Gaussian vector).
inline Vector3<double> randomUnit(std::mt19937_64& rng) {
  std::normal_distribution<double> g(0.0, 1.0);
  Vector3<double> v(g(rng), g(rng), g(rng));
  return v.normalized();
}

/// A random rotation (uniform, from a normalised Gaussian quaternion).
inline Matrix3<double> randomRotation(std::mt19937_64& rng) {
  std::normal_distribution<double> g(0.0, 1.0);
  Eigen::Quaterniond q(g(rng), g(rng), g(rng), g(rng));
  q.normalize();
  return q.toRotationMatrix();
}

/// A random 3D shape of the kind (the GJK comparison's): box half extents in [0.3, 1],
/// sphere radius in [0.3, 1], capsule radius in [0.2, 0.6] and half length in [0.25, 1];
/// a polytope is the hull of `vertices` random points on an ellipsoid with semi-axes in
/// [0.5, 1.2] (the hull keeps them all: they are on a convex surface).
inline ShapeDescription randomShape(ShapeKind kind, int vertices, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  switch (kind) {
    // The draws stand inside one constructor call, as they always have: the order the
    // compiler evaluates them in decides which draw is which axis, and so the workloads.
    case ShapeKind::Box: return boxDescription(Vector3<double>(0.3 + 0.7 * u(rng), 0.3 + 0.7 * u(rng), 0.3 + 0.7 * u(rng)));
    case ShapeKind::Sphere: return sphereDescription(0.3 + 0.7 * u(rng));
    case ShapeKind::Capsule: {
      const double r = 0.2 + 0.4 * u(rng);
      return capsuleDescription(0.25 + 0.75 * u(rng), r);
    }
    case ShapeKind::Polytope: {
      const Vector3<double> axes(0.5 + 0.7 * u(rng), 0.5 + 0.7 * u(rng), 0.5 + 0.7 * u(rng));
      std::vector<Vector3<double>> points;
      for (int k = 0; k < vertices; ++k) points.push_back(randomUnit(rng).cwiseProduct(axes));
      return polytopeDescription(points);
    }
    default: throw std::invalid_argument("randomShape.kind: a 3D kind (box, sphere, capsule, polytope)");
  }
}

/// Our shape for a study shape, in scalar S (a disk is a sphere in the plane z = 0).
template <typename S>
using AnyShape = std::variant<Box<S>, Sphere<S>, Capsule<S>, Polytope<S>>;

/// The hull of a description in scalar S (double: `hull`; float: `hullF`, or built from `hull`).
template <typename S>
Polytope<S> hullIn(const ShapeDescription& s) {
  if constexpr (std::is_same_v<S, double>) {
    return *s.hull;
  } else {
    if (s.hullF) return *s.hullF;
    return *floatHull(*s.hull, s.kind == ShapeKind::Polygon);
  }
}

/// The library's shape for a description, in scalar S.
template <typename S>
AnyShape<S> ourShape(const ShapeDescription& s) {
  switch (s.kind) {
    case ShapeKind::Box: return Box<S>(s.halfExtents.cast<S>());
    case ShapeKind::Sphere:
    case ShapeKind::Disk: return Sphere<S>(S(s.radius));
    case ShapeKind::Capsule: return Capsule<S>(Vector3<S>(S(0), S(0), S(-s.halfLength)), Vector3<S>(S(0), S(0), S(s.halfLength)), S(s.radius));
    case ShapeKind::Polytope:
    case ShapeKind::Polygon: return hullIn<S>(s);
  }
  throw std::logic_error("study: unknown shape kind");
}

/// Calls `f(shape)` with our own shape for the description, in scalar S, as its concrete
/// type (done once per workload, outside the timed loops, so the timed code is a plain
/// template instance).
template <typename S, typename F>
decltype(auto) withOurShape(const ShapeDescription& d, F&& f) {
  return std::visit(std::forward<F>(f), ourShape<S>(d));
}

/// The support point in the world of a shape at a pose (double), with a linear scan over
/// a polytope's vertices: the support function the study hands to libccd.
inline Vector3<double> scanSupport(const ShapeDescription& d, const Pose<double>& pose, const Vector3<double>& s) {
  const Vector3<double> b = pose.toBodyDirection(s);
  Vector3<double> x = Vector3<double>::Zero();
  switch (d.kind) {
    case ShapeKind::Box: x = Box<double>(d.halfExtents).support(b); break;
    case ShapeKind::Sphere:
    case ShapeKind::Disk: x = Sphere<double>(d.radius).support(b); break;
    case ShapeKind::Capsule:
      x = Capsule<double>(Vector3<double>(0, 0, -d.halfLength), Vector3<double>(0, 0, d.halfLength), d.radius).support(b);
      break;
    case ShapeKind::Polytope:
    case ShapeKind::Polygon: x = d.hull->vertex(d.hull->supportIndexLinearScan(b)); break;
  }
  return pose(x);
}

}  // namespace gjkx::study
