/// @file
/// @brief The time-of-impact methods of the peers on the study's queries (workloads.hpp),
/// built with the one set of shape adapters (peers.hpp).
///
/// Holds (namespace gjkx::study::peers): `PeerOutcome`, `FclQuery`, `BulletQuery`, `Box2dQuery`.
///
/// - FCL 0.7 `fcl::continuousCollide` on fcl::Boxd / Sphered / Capsuled / Convexd with
///   fcl::Transform3d start and end poses, the naive solver (CCDC_NAIVE: static tests at
///   ceil(1 / toc_err) evenly spaced times) and conservative advancement
///   (CCDC_CONSERVATIVE_ADVANCEMENT), GJK solver GST_LIBCCD (FCL's default; conservative
///   advancement also with GST_INDEP, FCL's own GJK, which misses less here). Motion model:
///   CCDM_TRANS (translation between the poses) when the query does not rotate, CCDM_LINEAR
///   (constant linear and angular velocity about the body origin, which is our screw motion)
///   when it does (built by hand: see FclQuery::run). A ballistic query becomes the chord between its end poses: FCL has no
///   accelerated motion, so its error there includes the difference between the parabola and
///   the chord.
/// - Bullet `btContinuousConvexCollision` (btVoronoiSimplexSolver, btGjkEpaPenetrationDepthSolver)
///   on btBoxShape / btSphereShape / btCapsuleShapeZ / btConvexHullShape, margins set to 0
///   (a sphere's and a capsule's radius is their margin in Bullet and stays). Bullet
///   interpolates the two transforms with constant linear and angular velocity (our screw
///   motion); ballistic queries become the chord as for FCL. Single precision (Debian's build).
/// - Box2D 2.4 `b2TimeOfImpact` on the 2D set: b2DistanceProxy (polygon vertices with radius 0,
///   a disk as one vertex with its radius) and b2Sweep (centre and angle at t = 0 and 1).
///   Box2D aims at a separation of b2_linearSlop (0.005) between the cores, within
///   0.25 b2_linearSlop, by design (its solver wants a small gap, not contact).
/// Every peer-dependent line is inside `#if GJKX_HAVE_FCL / _BULLET / _BOX2D`.
#pragma once

#include <gjkx/study/peers.hpp>
#include <gjkx/study/workloads.hpp>

#include <cmath>
#include <memory>
#include <string>
#include <vector>

#if GJKX_HAVE_FCL
#include <fcl/math/motion/interp_motion.h>
#include <fcl/math/motion/translation_motion.h>
#include <fcl/narrowphase/continuous_collision.h>
#endif
#if GJKX_HAVE_BULLET
#include <BulletCollision/NarrowPhaseCollision/btContinuousConvexCollision.h>  // the solvers: peers.hpp
#endif
#if GJKX_HAVE_BOX2D
#include <box2d/b2_time_of_impact.h>
#endif

namespace gjkx::study::peers {

/// What a peer said about one query.
struct PeerOutcome {
  bool hit = false;  ///< the peer reports a collision
  double time = 1;   ///< its time of impact (1 when none)
};

#if GJKX_HAVE_FCL

/// One query set up for FCL.
struct FclQuery {
  std::shared_ptr<fcl::CollisionGeometryd> P;  ///< P's shape
  std::shared_ptr<fcl::CollisionGeometryd> Q;  ///< Q's shape
  fcl::Transform3d p0;                         ///< P at t = 0
  fcl::Transform3d p1;                         ///< P at t = 1
  fcl::Transform3d q0;                         ///< Q at t = 0
  fcl::Transform3d q1;                         ///< Q at t = 1
  fcl::CCDMotionType motion = fcl::CCDM_TRANS;  ///< translation, or screw when a body turns
  /// The query's shapes and end poses.
  explicit FclQuery(const ToiQuery& q)
      : P(fclShape(q.P)), Q(fclShape(q.Q)), p0(fclTransform(q.motionP.pose(0))), p1(fclTransform(q.motionP.pose(1))), q0(fclTransform(q.motionQ.pose(0))),
        q1(fclTransform(q.motionQ.pose(1))) {
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
/// One query set up for Bullet.
struct BulletQuery {
  std::unique_ptr<btConvexShape> P;  ///< P's shape
  std::unique_ptr<btConvexShape> Q;  ///< Q's shape
  btTransform p0;                    ///< P at t = 0
  btTransform p1;                    ///< P at t = 1
  btTransform q0;                    ///< Q at t = 0
  btTransform q1;                    ///< Q at t = 1
  /// The query's shapes and end poses.
  explicit BulletQuery(const ToiQuery& q)
      : P(bulletShape(q.P)), Q(bulletShape(q.Q)), p0(bulletTransform(q.motionP.pose(0))), p1(bulletTransform(q.motionP.pose(1))),
        q0(bulletTransform(q.motionQ.pose(0))), q1(bulletTransform(q.motionQ.pose(1))) {}
  /// btContinuousConvexCollision::calcTimeOfImpact.
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
  std::vector<b2Vec2> verticesP;  ///< P's proxy's points
  std::vector<b2Vec2> verticesQ;  ///< Q's proxy's points
  b2TOIInput input;               ///< Box2D's input
  /// Box2D's sweep of a planar motion: centre and angle at t = 0 and 1.
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
  /// The query's proxies and sweeps over [0, 1].
  explicit Box2dQuery(const ToiQuery& q) {
    verticesP.reserve(8);
    verticesQ.reserve(8);
    box2dProxy(q.P, verticesP, input.proxyA);
    box2dProxy(q.Q, verticesQ, input.proxyB);
    input.sweepA = sweep(q.motionP);
    input.sweepB = sweep(q.motionQ);
    input.tMax = 1;
  }
  Box2dQuery(const Box2dQuery&) = delete;             ///< the proxies point into the vectors
  Box2dQuery& operator=(const Box2dQuery&) = delete;  ///< the proxies point into the vectors
  /// b2TimeOfImpact; its failure (iteration limits) is taken as a hit at its last t.
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

}  // namespace gjkx::study::peers
