/// @file
/// @brief The study's adapters to its peers, each written once: libccd's support
/// functions, FCL's and Bullet's shapes and poses, Box2D's proxies, all from the one
/// shape description (shape_description.hpp); used by the GJK and the time-of-impact
/// comparisons alike (their continuous queries: peers_toi.hpp).
///
/// Holds (namespace gjkx::study::peers, every peer-dependent line inside
/// `#if GJKX_HAVE_CCD / _FCL / _BULLET / _BOX2D`, set by cmake/peers.cmake):
/// - which peers this build has (`Peer`, `have`, `found`, `missing`, `presentText`);
/// - libccd 2.x (double build): `CcdObject`, `ccdSupport`, `ccdCenter`, `ccdSettings`.
///   libccd has no shapes of its own, the user supplies support functions: ours are the
///   textbook ones, with a linear scan over a polytope's vertices (what FCL's libccd
///   adapter does too). Its GJK is boolean only (no distance query in this version); it
///   has no warm start.
/// - FCL 0.7: `fclShape` (fcl::Boxd / Sphered / Capsuled / Convexd with the hull's
///   triangles; a disk is a sphere) and `fclTransform`. FCL answers some pairs with closed
///   forms, not GJK (sphere-sphere, capsule-capsule distance; box-box collide by SAT); the
///   tables say "what FCL does", whichever it is.
/// - Bullet (single precision build): `bulletShape` (btBoxShape, btSphereShape,
///   btCapsuleShapeZ, btConvexHullShape), `bulletTransform`, and `BulletPair`, one
///   btGjkPairDetector with btVoronoiSimplexSolver and btGjkEpaPenetrationDepthSolver.
///   Margins: box and hull margins are set to 0 (btBoxShape keeps its outer extents when
///   the margin changes); a sphere and a capsule *are* their margin in Bullet (a point and
///   a segment inflated by the radius), so theirs stay.
/// - Box2D 2.4: `box2dProxy`, a b2DistanceProxy for a polygon (its vertices, radius 0) or a
///   disk (one vertex with its radius).
#pragma once

#include <gjkx/study/shape_description.hpp>

#include <gjkx/motion/pose.hpp>

#include <cmath>
#include <memory>
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
#if GJKX_HAVE_BOX2D
#include <box2d/b2_distance.h>
#endif

namespace gjkx::study::peers {

// ---------------------------------------------------------------------------------------
// Which peers this build has

/// The peers of the study.
enum class Peer { Libccd, FCL, Bullet, Box2D };

/// The peers of the GJK comparison.
inline const std::vector<Peer> kGjkPeers{Peer::Libccd, Peer::FCL, Peer::Bullet};
/// The peers of the time-of-impact comparison and the extreme cases.
inline const std::vector<Peer> kToiPeers{Peer::FCL, Peer::Bullet, Peer::Box2D};

/// A peer's name for the tables.
inline const char* name(Peer peer) {
  switch (peer) {
    case Peer::Libccd: return "libccd";
    case Peer::FCL: return "FCL";
    case Peer::Bullet: return "Bullet";
    case Peer::Box2D: return "Box2D";
  }
  return "?";
}

/// Whether this build has the peer (cmake/peers.cmake found it).
inline bool have(Peer peer) {
#if GJKX_HAVE_CCD
  if (peer == Peer::Libccd) return true;
#endif
#if GJKX_HAVE_FCL
  if (peer == Peer::FCL) return true;
#endif
#if GJKX_HAVE_BULLET
  if (peer == Peer::Bullet) return true;
#endif
#if GJKX_HAVE_BOX2D
  if (peer == Peer::Box2D) return true;
#endif
  (void)peer;
  return false;
}

/// The names of the peers of `of` that this build has.
inline std::vector<std::string> found(const std::vector<Peer>& of) {
  std::vector<std::string> out;
  for (const Peer p : of)
    if (have(p)) out.push_back(name(p));
  return out;
}

/// The names of the peers of `of` that this build left out (not installed).
inline std::vector<std::string> missing(const std::vector<Peer>& of) {
  std::vector<std::string> out;
  for (const Peer p : of)
    if (!have(p)) out.push_back(name(p));
  return out;
}

/// Names joined by ", ".
inline std::string joined(const std::vector<std::string>& names) {
  std::string out;
  for (const auto& n : names) out += (out.empty() ? "" : ", ") + n;
  return out;
}

/// "peers: libccd, FCL, Bullet" (and "; left out (not installed): ..." when some are missing).
inline std::string presentText(const std::vector<Peer>& of) {
  const std::string yes = joined(found(of)), no = joined(missing(of));
  return "peers: " + (yes.empty() ? std::string("none") : yes) + (no.empty() ? "" : "; left out (not installed): " + no);
}

// ---------------------------------------------------------------------------------------
// libccd
#if GJKX_HAVE_CCD
/// What libccd's void* points at: a shape and its pose.
struct CcdObject {
  /// The shape.
  const ShapeDescription* shape = nullptr;
  /// Its pose in the world.
  Pose<double> pose;
};

/// libccd's support function: our linear-scan support of the object in direction `dir`.
inline void ccdSupport(const void* obj, const ccd_vec3_t* dir, ccd_vec3_t* out) {
  const auto* o = static_cast<const CcdObject*>(obj);
  const Vector3<double> x = scanSupport(*o->shape, o->pose, Vector3<double>(dir->v[0], dir->v[1], dir->v[2]));
  ccdVec3Set(out, x.x(), x.y(), x.z());
}
/// libccd's centre function (for MPR): the body origin, on which every study shape is centred.
inline void ccdCenter(const void* obj, ccd_vec3_t* out) {
  const auto* o = static_cast<const CcdObject*>(obj);
  const Vector3<double> c = o->pose.translation;
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
/// FCL's shape for the description (a polytope or polygon becomes a Convexd with the hull's triangles).
inline std::shared_ptr<fcl::CollisionGeometryd> fclShape(const ShapeDescription& d) {
  switch (d.kind) {
    case ShapeKind::Box: return std::make_shared<fcl::Boxd>(2.0 * d.halfExtents);
    case ShapeKind::Sphere:
    case ShapeKind::Disk: return std::make_shared<fcl::Sphered>(d.radius);
    case ShapeKind::Capsule: return std::make_shared<fcl::Capsuled>(d.radius, 2.0 * d.halfLength);
    case ShapeKind::Polytope:
    case ShapeKind::Polygon: {
      auto vertices = std::make_shared<std::vector<fcl::Vector3d>>(d.hull->vertices().begin(), d.hull->vertices().end());
      auto faces = std::make_shared<std::vector<int>>();
      for (const auto& t : d.hull->triangles()) faces->insert(faces->end(), {3, t[0], t[1], t[2]});
      auto convex = std::make_shared<fcl::Convexd>(vertices, int(d.hull->triangles().size()), faces);
      convex->computeLocalAABB();
      return convex;
    }
  }
  return nullptr;
}
/// FCL's transform for a pose.
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
inline std::unique_ptr<btConvexShape> bulletShape(const ShapeDescription& d) {
  switch (d.kind) {
    case ShapeKind::Box: {
      auto box = std::make_unique<btBoxShape>(btVector3(btScalar(d.halfExtents.x()), btScalar(d.halfExtents.y()), btScalar(d.halfExtents.z())));
      box->setMargin(0);
      return box;
    }
    case ShapeKind::Sphere:
    case ShapeKind::Disk: return std::make_unique<btSphereShape>(btScalar(d.radius));
    case ShapeKind::Capsule: return std::make_unique<btCapsuleShapeZ>(btScalar(d.radius), btScalar(2.0 * d.halfLength));
    case ShapeKind::Polytope:
    case ShapeKind::Polygon: {
      auto hull = std::make_unique<btConvexHullShape>();
      for (const auto& v : d.hull->vertices()) hull->addPoint(btVector3(btScalar(v.x()), btScalar(v.y()), btScalar(v.z())), false);
      hull->recalcLocalAabb();
      hull->setMargin(0);
      return hull;
    }
  }
  return nullptr;
}
/// Bullet's transform for a pose (float).
inline btTransform bulletTransform(const Pose<double>& pose) {
  const Matrix3<double>& R = pose.rotation;
  btMatrix3x3 basis(btScalar(R(0, 0)), btScalar(R(0, 1)), btScalar(R(0, 2)), btScalar(R(1, 0)), btScalar(R(1, 1)),
                    btScalar(R(1, 2)), btScalar(R(2, 0)), btScalar(R(2, 1)), btScalar(R(2, 2)));
  return btTransform(basis, btVector3(btScalar(pose.translation.x()), btScalar(pose.translation.y()), btScalar(pose.translation.z())));
}
/// One Bullet GJK pair: the detector and its solvers (kept across a warm sequence, where
/// the detector starts from its cached separating axis).
struct BulletPair {
  /// Bullet's simplex solver.
  btVoronoiSimplexSolver simplexSolver;
  /// EPA, for overlapping pairs.
  btGjkEpaPenetrationDepthSolver epa;
  /// The detector.
  btGjkPairDetector detector;
  /// A pair of the two shapes (which must outlive it).
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

// ---------------------------------------------------------------------------------------
// Box2D
#if GJKX_HAVE_BOX2D
/// Box2D's proxy for a 2D description: a polygon's vertices (x, y) with radius 0, or a
/// disk as one vertex with its radius. `vertices` holds the points the proxy refers to
/// (it must outlive the proxy and not reallocate).
inline void box2dProxy(const ShapeDescription& s, std::vector<b2Vec2>& vertices, b2DistanceProxy& out) {
  if (s.kind == ShapeKind::Disk) {
    vertices = {b2Vec2(0, 0)};
    out.Set(vertices.data(), 1, float(s.radius));
    return;
  }
  for (const auto& v : s.hull->vertices()) vertices.emplace_back(float(v.x()), float(v.y()));
  out.Set(vertices.data(), int32(vertices.size()), 0.0f);
}
#endif

}  // namespace gjkx::study::peers
