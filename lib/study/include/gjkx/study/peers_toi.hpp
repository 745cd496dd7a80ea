// The time-of-impact methods of the peers, on the study's queries (workloads.hpp):
// - FCL 0.7 `fcl::continuousCollide` on fcl::Boxd / Sphered / Capsuled / Convexd with
//   fcl::Transform3d start and end poses, the naive solver (CCDC_NAIVE: static tests at
//   ceil(1 / toc_err) evenly spaced times) and conservative advancement
//   (CCDC_CONSERVATIVE_ADVANCEMENT), GJK solver GST_LIBCCD (FCL's default; conservative
//   advancement also with GST_INDEP, FCL's own GJK, which misses less here). Motion model:
//   CCDM_TRANS (translation between the poses) when the query does not rotate, CCDM_LINEAR
//   (constant linear and angular velocity about the body origin, which is our screw motion)
//   when it does (built by hand: see FclQuery::run). A ballistic query becomes the chord between its end poses: FCL has no
//   accelerated motion, so its error there includes the difference between the parabola and
//   the chord.
// - Bullet `btContinuousConvexCollision` (btVoronoiSimplexSolver, btGjkEpaPenetrationDepthSolver)
//   on btBoxShape / btSphereShape / btCapsuleShapeZ / btConvexHullShape, margins set to 0
//   (a sphere's and a capsule's radius is their margin in Bullet and stays). Bullet
//   interpolates the two transforms with constant linear and angular velocity (our screw
//   motion); ballistic queries become the chord as for FCL. Single precision (Debian's build).
// - Box2D 2.4 `b2TimeOfImpact` on the 2D set: b2DistanceProxy (polygon vertices with radius 0,
//   a disk as one vertex with its radius) and b2Sweep (centre and angle at t = 0 and 1).
//   Box2D aims at a separation of b2_linearSlop (0.005) between the cores, within
//   0.25 b2_linearSlop, by design (its solver wants a small gap, not contact).
// Every peer-dependent line is inside #if GJKX_HAVE_FCL / _BULLET / _BOX2D.
#pragma once

#include <gjkx/study/workloads.hpp>

#include <memory>
#include <string>
#include <vector>

#if GJKX_HAVE_FCL
#include <fcl/geometry/shape/box.h>
#include <fcl/geometry/shape/capsule.h>
#include <fcl/geometry/shape/convex.h>
#include <fcl/geometry/shape/sphere.h>
#include <fcl/math/motion/interp_motion.h>
#include <fcl/math/motion/translation_motion.h>
#include <fcl/narrowphase/continuous_collision.h>
#endif
#if GJKX_HAVE_BULLET
#include <BulletCollision/CollisionShapes/btBoxShape.h>
#include <BulletCollision/CollisionShapes/btCapsuleShape.h>
#include <BulletCollision/CollisionShapes/btConvexHullShape.h>
#include <BulletCollision/CollisionShapes/btSphereShape.h>
#include <BulletCollision/NarrowPhaseCollision/btContinuousConvexCollision.h>
#include <BulletCollision/NarrowPhaseCollision/btGjkEpaPenetrationDepthSolver.h>
#include <BulletCollision/NarrowPhaseCollision/btVoronoiSimplexSolver.h>
#endif
#if GJKX_HAVE_BOX2D
#include <box2d/b2_time_of_impact.h>
#endif

namespace gjkx::toistudy::peers {

/// What a peer said about one query.
struct PeerOutcome {
  bool hit = false;
  double time = 1;
};

/// The peers this build has and has not, for the tables.
inline std::vector<std::string> found() {
  std::vector<std::string> out;
#if GJKX_HAVE_FCL
  out.push_back("FCL");
#endif
#if GJKX_HAVE_BULLET
  out.push_back("Bullet");
#endif
#if GJKX_HAVE_BOX2D
  out.push_back("Box2D");
#endif
  return out;
}
inline std::vector<std::string> missing() {
  std::vector<std::string> out;
#if !GJKX_HAVE_FCL
  out.push_back("FCL");
#endif
#if !GJKX_HAVE_BULLET
  out.push_back("Bullet");
#endif
#if !GJKX_HAVE_BOX2D
  out.push_back("Box2D");
#endif
  return out;
}

#if GJKX_HAVE_FCL
/// FCL's geometry for a shape.
inline std::shared_ptr<fcl::CollisionGeometryd> fclShape(const ShapeSpec& s) {
  switch (s.kind) {
    case ShapeKind::Box: return std::make_shared<fcl::Boxd>(2 * s.halfExtents.x(), 2 * s.halfExtents.y(), 2 * s.halfExtents.z());
    case ShapeKind::Sphere:
    case ShapeKind::Disk: return std::make_shared<fcl::Sphered>(s.radius);
    case ShapeKind::Capsule: return std::make_shared<fcl::Capsuled>(s.radius, 2 * s.halfLength);
    case ShapeKind::Polytope:
    case ShapeKind::Polygon: {
      auto vertices = std::make_shared<std::vector<fcl::Vector3d>>();
      for (const auto& v : s.hull->vertices()) vertices->push_back(v);
      auto faces = std::make_shared<std::vector<int>>();
      for (const auto& t : s.hull->triangles()) faces->insert(faces->end(), {3, t[0], t[1], t[2]});
      return std::make_shared<fcl::Convexd>(vertices, int(s.hull->triangles().size()), faces);
    }
  }
  return nullptr;
}

inline fcl::Transform3d fclPose(const MotionSpec& m, double t) {
  const auto [R, p] = m.poseAt(t);
  fcl::Transform3d tf = fcl::Transform3d::Identity();
  tf.linear() = R;
  tf.translation() = p;
  return tf;
}

/// One query set up for FCL.
struct FclQuery {
  std::shared_ptr<fcl::CollisionGeometryd> P, Q;
  fcl::Transform3d p0, p1, q0, q1;
  fcl::CCDMotionType motion = fcl::CCDM_TRANS;
  explicit FclQuery(const ToiQuery& q)
      : P(fclShape(q.P)), Q(fclShape(q.Q)), p0(fclPose(q.motionP, 0)), p1(fclPose(q.motionP, 1)), q0(fclPose(q.motionQ, 0)),
        q1(fclPose(q.motionQ, 1)) {
    if (q.motionP.rotates() || q.motionQ.rotates()) motion = fcl::CCDM_LINEAR;
  }
  /// continuousCollide with the naive solver (tocErr: 1 / number of samples) or conservative advancement.
  // The motions are built here, not by FCL from the two transforms: FCL 0.7's
  // InterpMotion(tf1, tf2), which continuousCollide uses for CCDM_LINEAR, leaves its
  // reference point (the centre of rotation) uninitialised, and the answers then change
  // from run to run (seen here on the screw workloads). The constructor taking
  // (R1, T1, R2, T2, O) sets it; O = 0 is the body origin, as in our screw motion.
  // Motions carry state (integrate), so each call gets fresh ones.
  PeerOutcome run(bool conservativeAdvancement, double tocErr, fcl::GJKSolverType solver = fcl::GST_LIBCCD) const {
    fcl::ContinuousCollisionRequestd request;
    request.ccd_motion_type = motion;
    request.ccd_solver_type = conservativeAdvancement ? fcl::CCDC_CONSERVATIVE_ADVANCEMENT : fcl::CCDC_NAIVE;
    request.gjk_solver_type = solver;
    request.toc_err = tocErr;
    request.num_max_iterations = 100000;
    fcl::ContinuousCollisionResultd result;
    if (motion == fcl::CCDM_LINEAR) {
      fcl::InterpMotion<double> mp(p0.linear(), p0.translation(), p1.linear(), p1.translation(), fcl::Vector3d::Zero());
      fcl::InterpMotion<double> mq(q0.linear(), q0.translation(), q1.linear(), q1.translation(), fcl::Vector3d::Zero());
      fcl::continuousCollide(P.get(), &mp, Q.get(), &mq, request, result);
    } else {
      fcl::TranslationMotion<double> mp(p0, p1), mq(q0, q1);
      fcl::continuousCollide(P.get(), &mp, Q.get(), &mq, request, result);
    }
    return {result.is_collide, result.time_of_contact};
  }
};
#endif

#if GJKX_HAVE_BULLET
inline std::unique_ptr<btConvexShape> bulletShape(const ShapeSpec& s) {
  switch (s.kind) {
    case ShapeKind::Box: {
      auto box = std::make_unique<btBoxShape>(btVector3(btScalar(s.halfExtents.x()), btScalar(s.halfExtents.y()), btScalar(s.halfExtents.z())));
      box->setMargin(0);
      return box;
    }
    case ShapeKind::Sphere:
    case ShapeKind::Disk: return std::make_unique<btSphereShape>(btScalar(s.radius));
    case ShapeKind::Capsule: return std::make_unique<btCapsuleShapeZ>(btScalar(s.radius), btScalar(2 * s.halfLength));
    case ShapeKind::Polytope:
    case ShapeKind::Polygon: {
      auto hull = std::make_unique<btConvexHullShape>();
      for (const auto& v : s.hull->vertices()) hull->addPoint(btVector3(btScalar(v.x()), btScalar(v.y()), btScalar(v.z())), false);
      hull->recalcLocalAabb();
      hull->setMargin(0);
      return hull;
    }
  }
  return nullptr;
}

inline btTransform bulletPose(const MotionSpec& m, double t) {
  const auto [R, p] = m.poseAt(t);
  return btTransform(btMatrix3x3(btScalar(R(0, 0)), btScalar(R(0, 1)), btScalar(R(0, 2)), btScalar(R(1, 0)), btScalar(R(1, 1)),
                                 btScalar(R(1, 2)), btScalar(R(2, 0)), btScalar(R(2, 1)), btScalar(R(2, 2))),
                     btVector3(btScalar(p.x()), btScalar(p.y()), btScalar(p.z())));
}

/// One query set up for Bullet.
struct BulletQuery {
  std::unique_ptr<btConvexShape> P, Q;
  btTransform p0, p1, q0, q1;
  explicit BulletQuery(const ToiQuery& q)
      : P(bulletShape(q.P)), Q(bulletShape(q.Q)), p0(bulletPose(q.motionP, 0)), p1(bulletPose(q.motionP, 1)),
        q0(bulletPose(q.motionQ, 0)), q1(bulletPose(q.motionQ, 1)) {}
  PeerOutcome run() const {
    btVoronoiSimplexSolver simplex;
    btGjkEpaPenetrationDepthSolver epa;
    btContinuousConvexCollision ccd(P.get(), Q.get(), &simplex, &epa);
    btConvexCast::CastResult result;
    const bool hit = ccd.calcTimeOfImpact(p0, p1, q0, q1, result);
    return {hit, hit ? double(result.m_fraction) : 1.0};
  }
};
#endif

#if GJKX_HAVE_BOX2D
/// One 2D query set up for Box2D.
struct Box2dQuery {
  std::vector<b2Vec2> verticesP, verticesQ;
  b2TOIInput input;
  static void proxy(const ShapeSpec& s, std::vector<b2Vec2>& vertices, b2DistanceProxy& out) {
    if (s.kind == ShapeKind::Disk) {
      vertices = {b2Vec2(0, 0)};
      out.Set(vertices.data(), 1, float(s.radius));
      return;
    }
    for (const auto& v : s.hull->vertices()) vertices.emplace_back(float(v.x()), float(v.y()));
    out.Set(vertices.data(), int32(vertices.size()), 0.0f);
  }
  static b2Sweep sweep(const MotionSpec& m) {
    b2Sweep s;
    s.localCenter.SetZero();
    const double a0 = std::atan2(m.R0(1, 0), m.R0(0, 0));
    const auto [R1, p1] = m.poseAt(1);
    (void)R1;
    s.c0.Set(float(m.p0.x()), float(m.p0.y()));
    s.c.Set(float(p1.x()), float(p1.y()));
    s.a0 = float(a0);
    s.a = float(a0 + m.w.z());
    s.alpha0 = 0;
    return s;
  }
  explicit Box2dQuery(const ToiQuery& q) {
    verticesP.reserve(8);
    verticesQ.reserve(8);
    proxy(q.P, verticesP, input.proxyA);
    proxy(q.Q, verticesQ, input.proxyB);
    input.sweepA = sweep(q.motionP);
    input.sweepB = sweep(q.motionQ);
    input.tMax = 1;
  }
  Box2dQuery(const Box2dQuery&) = delete;
  Box2dQuery& operator=(const Box2dQuery&) = delete;
  PeerOutcome run() const {
    b2TOIOutput output;
    b2TimeOfImpact(&output, &input);
    switch (output.state) {
      case b2TOIOutput::e_touching:
      case b2TOIOutput::e_failed: return {true, double(output.t)};
      case b2TOIOutput::e_overlapped: return {true, 0.0};
      default: return {false, 1.0};
    }
  }
};
#endif

}  // namespace gjkx::toistudy::peers
