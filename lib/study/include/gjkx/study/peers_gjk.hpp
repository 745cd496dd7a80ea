// The GJK study's shapes and its adapters to the peers (chapter 07).
//
// One shape description (`ShapeDesc`: box, sphere, capsule or convex polytope from a
// point set) is turned into each library's own shape, so every method answers the same
// query on the same numbers:
// - ours: gjkx::Box / Sphere / Capsule / Polytope placed at a gjkx::Pose (double and float);
// - libccd 2.x (double build): ccdGJKIntersect, ccdMPRIntersect. libccd has no shapes of
//   its own, the user supplies support functions: ours below are the textbook ones, with
//   a linear scan over the vertices for a polytope (what FCL's libccd adapter does too).
//   Its GJK is boolean only (no distance query in this version); it has no warm start.
// - FCL 0.7: fcl::distance and fcl::collide on fcl::Boxd / Sphered / Capsuled / Convexd,
//   with both narrow-phase solvers (GST_LIBCCD, GST_INDEP). FCL answers some pairs with
//   closed forms, not GJK (sphere-sphere, capsule-capsule distance; box-box collide by
//   SAT); the tables say "what FCL does", whichever it is. Warm start: collide with
//   GST_INDEP takes `cached_gjk_guess` (enabled for the warm runs); distance has none.
// - Bullet (single precision build): btGjkPairDetector with btVoronoiSimplexSolver and
//   btGjkEpaPenetrationDepthSolver on btBoxShape, btSphereShape, btCapsuleShapeZ,
//   btConvexHullShape. Margins: box and hull margins are set to 0 (btBoxShape keeps its
//   outer extents when the margin changes); a sphere and a capsule *are* their margin in
//   Bullet (a point and a segment inflated by the radius), so theirs stay. Warm start:
//   one detector per pair kept across steps, which starts from its cached separating axis.
//   Bullet has no boolean GJK query of its own: its boolean rows ("bullet-gjk-dist") are the
//   distance call with "overlap" = distance <= 0 (EPA runs on every overlapping pair).
#pragma once

#include <gjkx/motion/pose.hpp>
#include <gjkx/support_mapping/placed.hpp>
#include <gjkx/support_mapping/polytope.hpp>
#include <gjkx/support_mapping/primitives.hpp>

#include <cmath>
#include <memory>
#include <random>
#include <string>
#include <vector>

#if GJKX_HAVE_CCD
#include <ccd/ccd.h>
#endif
#if GJKX_HAVE_FCL
#include <fcl/geometry/shape/box.h>
#include <fcl/geometry/shape/capsule.h>
#include <fcl/geometry/shape/convex.h>
#include <fcl/geometry/shape/sphere.h>
#include <fcl/narrowphase/collision.h>
#include <fcl/narrowphase/distance.h>
#endif
#if GJKX_HAVE_BULLET
#include <BulletCollision/CollisionShapes/btBoxShape.h>
#include <BulletCollision/CollisionShapes/btCapsuleShape.h>
#include <BulletCollision/CollisionShapes/btConvexHullShape.h>
#include <BulletCollision/CollisionShapes/btSphereShape.h>
#include <BulletCollision/NarrowPhaseCollision/btGjkEpaPenetrationDepthSolver.h>
#include <BulletCollision/NarrowPhaseCollision/btGjkPairDetector.h>
#include <BulletCollision/NarrowPhaseCollision/btPointCollector.h>
#include <BulletCollision/NarrowPhaseCollision/btVoronoiSimplexSolver.h>
#endif

namespace gjkx::study {

/// The kinds of shape in the GJK study.
enum class ShapeKind { Box, Sphere, Capsule, Polytope };

/// One shape, in its body frame, from which every library builds its own.
struct ShapeDesc {
  ShapeKind kind = ShapeKind::Box;
  Vector3<double> halfExtents = Vector3<double>::Ones();  ///< box
  double radius = 0.5;                                     ///< sphere, capsule
  double halfLength = 0.5;                                 ///< capsule: axis from (0,0,-h) to (0,0,h)
  std::shared_ptr<Polytope<double>> polytope;              ///< polytope (hull of the points)
  std::shared_ptr<Polytope<float>> polytopeF;              ///< the same hull in float
};

/// A random rotation (uniform, from a normalised Gaussian quaternion).
inline Matrix3<double> randomRotation(std::mt19937_64& rng) {
  std::normal_distribution<double> g(0.0, 1.0);
  Eigen::Quaterniond q(g(rng), g(rng), g(rng), g(rng));
  q.normalize();
  return q.toRotationMatrix();
}

/// A random unit vector.
inline Vector3<double> randomUnit(std::mt19937_64& rng) {
  std::normal_distribution<double> g(0.0, 1.0);
  Vector3<double> v(g(rng), g(rng), g(rng));
  return v.normalized();
}

/// A random shape of the kind; a polytope is the hull of `vertices` random points on an
/// ellipsoid with semi-axes in [0.5, 1.2] (the hull keeps them all: they are on a convex surface).
inline ShapeDesc randomShape(ShapeKind kind, int vertices, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  ShapeDesc d;
  d.kind = kind;
  switch (kind) {
    case ShapeKind::Box: d.halfExtents = Vector3<double>(0.3 + 0.7 * u(rng), 0.3 + 0.7 * u(rng), 0.3 + 0.7 * u(rng)); break;
    case ShapeKind::Sphere: d.radius = 0.3 + 0.7 * u(rng); break;
    case ShapeKind::Capsule:
      d.radius = 0.2 + 0.4 * u(rng);
      d.halfLength = 0.25 + 0.75 * u(rng);
      break;
    case ShapeKind::Polytope: {
      const Vector3<double> axes(0.5 + 0.7 * u(rng), 0.5 + 0.7 * u(rng), 0.5 + 0.7 * u(rng));
      std::vector<Vector3<double>> points;
      for (int k = 0; k < vertices; ++k) points.push_back(randomUnit(rng).cwiseProduct(axes));
      d.polytope = std::make_shared<Polytope<double>>(Polytope<double>::hull(points));
      std::vector<Vector3<float>> pointsF;  // the float hull from the double hull's vertices
      for (const auto& v : d.polytope->vertices()) pointsF.push_back(v.cast<float>());
      d.polytopeF = std::make_shared<Polytope<float>>(Polytope<float>::hull(pointsF));
      break;
    }
  }
  return d;
}

/// Calls `f(shape)` with our own shape for the description, in scalar S (once per
/// workload, outside the timed loops, so the timed code is a plain template instance).
template <typename S, typename F>
decltype(auto) withOurShape(const ShapeDesc& d, F&& f) {
  switch (d.kind) {
    case ShapeKind::Box: return f(Box<S>(d.halfExtents.cast<S>()));
    case ShapeKind::Sphere: return f(Sphere<S>(S(d.radius)));
    case ShapeKind::Capsule:
      return f(Capsule<S>(Vector3<S>(S(0), S(0), S(-d.halfLength)), Vector3<S>(S(0), S(0), S(d.halfLength)), S(d.radius)));
    case ShapeKind::Polytope:
    default:
      if constexpr (std::is_same_v<S, float>)
        return f(*d.polytopeF);
      else
        return f(*d.polytope);
  }
}

/// The support point in the world of a shape at a pose (double), with a linear scan over
/// a polytope's vertices: the support function we hand to libccd.
inline Vector3<double> scanSupport(const ShapeDesc& d, const Pose<double>& pose, const Vector3<double>& s) {
  const Vector3<double> b = pose.toBodyDirection(s);
  Vector3<double> x;
  switch (d.kind) {
    case ShapeKind::Box: x = Box<double>(d.halfExtents).support(b); break;
    case ShapeKind::Sphere: x = Sphere<double>(d.radius).support(b); break;
    case ShapeKind::Capsule:
      x = Capsule<double>(Vector3<double>(0, 0, -d.halfLength), Vector3<double>(0, 0, d.halfLength), d.radius).support(b);
      break;
    case ShapeKind::Polytope:
    default: x = d.polytope->vertex(d.polytope->supportIndexLinearScan(b)); break;
  }
  return pose(x);
}

// ---------------------------------------------------------------------------------------
// libccd
#if GJKX_HAVE_CCD
/// What libccd's void* points at: a shape and its pose.
struct CcdObject {
  const ShapeDesc* shape = nullptr;
  Pose<double> pose;
};

inline void ccdSupport(const void* obj, const ccd_vec3_t* dir, ccd_vec3_t* out) {
  const auto* o = static_cast<const CcdObject*>(obj);
  const Vector3<double> x = scanSupport(*o->shape, o->pose, Vector3<double>(dir->v[0], dir->v[1], dir->v[2]));
  ccdVec3Set(out, x.x(), x.y(), x.z());
}
inline void ccdCenter(const void* obj, ccd_vec3_t* out) {
  const auto* o = static_cast<const CcdObject*>(obj);
  const Vector3<double> c = o->pose.translation;  // every study shape is centred on its body origin
  ccdVec3Set(out, c.x(), c.y(), c.z());
}
/// libccd's settings for the study: our support functions, its default tolerances.
inline ccd_t ccdSettings() {
  ccd_t ccd;
  CCD_INIT(&ccd);
  ccd.support1 = ccdSupport;
  ccd.support2 = ccdSupport;
  ccd.center1 = ccdCenter;
  ccd.center2 = ccdCenter;
  ccd.max_iterations = 500;
  return ccd;
}
#endif

// ---------------------------------------------------------------------------------------
// FCL
#if GJKX_HAVE_FCL
/// FCL's shape for the description (a polytope becomes a Convexd with the hull's triangles).
inline std::shared_ptr<fcl::CollisionGeometryd> fclShape(const ShapeDesc& d) {
  switch (d.kind) {
    case ShapeKind::Box: return std::make_shared<fcl::Boxd>(2.0 * d.halfExtents);
    case ShapeKind::Sphere: return std::make_shared<fcl::Sphered>(d.radius);
    case ShapeKind::Capsule: return std::make_shared<fcl::Capsuled>(d.radius, 2.0 * d.halfLength);
    case ShapeKind::Polytope:
    default: {
      auto vertices = std::make_shared<std::vector<fcl::Vector3d>>(d.polytope->vertices().begin(), d.polytope->vertices().end());
      auto faces = std::make_shared<std::vector<int>>();
      for (const auto& t : d.polytope->triangles()) faces->insert(faces->end(), {3, t[0], t[1], t[2]});
      auto convex = std::make_shared<fcl::Convexd>(vertices, int(d.polytope->triangles().size()), faces);
      convex->computeLocalAABB();
      return convex;
    }
  }
}
inline fcl::Transform3d fclTransform(const Pose<double>& pose) {
  fcl::Transform3d tf = fcl::Transform3d::Identity();
  tf.linear() = pose.rotation;
  tf.translation() = pose.translation;
  return tf;
}
#endif

// ---------------------------------------------------------------------------------------
// Bullet
#if GJKX_HAVE_BULLET
/// Bullet's shape for the description (float), margins as said at the top of this file.
inline std::shared_ptr<btConvexShape> bulletShape(const ShapeDesc& d) {
  switch (d.kind) {
    case ShapeKind::Box: {
      auto box = std::make_shared<btBoxShape>(btVector3(btScalar(d.halfExtents.x()), btScalar(d.halfExtents.y()), btScalar(d.halfExtents.z())));
      box->setMargin(0);
      return box;
    }
    case ShapeKind::Sphere: return std::make_shared<btSphereShape>(btScalar(d.radius));
    case ShapeKind::Capsule: return std::make_shared<btCapsuleShapeZ>(btScalar(d.radius), btScalar(2.0 * d.halfLength));
    case ShapeKind::Polytope:
    default: {
      auto hull = std::make_shared<btConvexHullShape>();
      for (const auto& v : d.polytope->vertices()) hull->addPoint(btVector3(btScalar(v.x()), btScalar(v.y()), btScalar(v.z())), false);
      hull->recalcLocalAabb();
      hull->setMargin(0);
      return hull;
    }
  }
}
inline btTransform bulletTransform(const Pose<double>& pose) {
  const Matrix3<double>& R = pose.rotation;
  btMatrix3x3 basis(btScalar(R(0, 0)), btScalar(R(0, 1)), btScalar(R(0, 2)), btScalar(R(1, 0)), btScalar(R(1, 1)),
                    btScalar(R(1, 2)), btScalar(R(2, 0)), btScalar(R(2, 1)), btScalar(R(2, 2)));
  return btTransform(basis, btVector3(btScalar(pose.translation.x()), btScalar(pose.translation.y()), btScalar(pose.translation.z())));
}
/// One Bullet GJK pair: the detector and its solvers (kept across a warm sequence).
struct BulletPair {
  btVoronoiSimplexSolver simplexSolver;
  btGjkEpaPenetrationDepthSolver epa;
  btGjkPairDetector detector;
  BulletPair(const btConvexShape* a, const btConvexShape* b) : detector(a, b, &simplexSolver, &epa) {}
  /// The signed distance (negative: penetration depth by EPA), NaN when Bullet gave no result.
  double distance(const btTransform& ta, const btTransform& tb) {
    btGjkPairDetector::ClosestPointInput input;
    input.m_transformA = ta;
    input.m_transformB = tb;
    btPointCollector out;
    detector.getClosestPoints(input, out, nullptr);
    return out.m_hasResult ? double(out.m_distance) : std::nan("");
  }
};
#endif

/// Which peers this build has, for the tables' header.
inline std::string peersPresent() {
  std::string found, missing;
  auto add = [](std::string& list, const char* name) { list += (list.empty() ? "" : ", ") + std::string(name); };
#if GJKX_HAVE_CCD
  add(found, "libccd");
#else
  add(missing, "libccd");
#endif
#if GJKX_HAVE_FCL
  add(found, "FCL");
#else
  add(missing, "FCL");
#endif
#if GJKX_HAVE_BULLET
  add(found, "Bullet");
#else
  add(missing, "Bullet");
#endif
  return "peers: " + (found.empty() ? std::string("none") : found) + (missing.empty() ? "" : "; left out (not installed): " + missing);
}

}  // namespace gjkx::study
