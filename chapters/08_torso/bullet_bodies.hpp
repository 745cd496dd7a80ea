// The bodies of a gjkx scene as Bullet holds them (gjkx_bullet_scene): our shapes, masses and
// body frames handed to Bullet, and Bullet's poses read back in our body frames.
#pragma once

#include "peer_run.hpp"

#include <gjkx/mesh/triangle_mesh.hpp>
#include <gjkx/timewarp/body.hpp>
#include <gjkx/timewarp/scene.hpp>

#include <BulletCollision/CollisionShapes/btBoxShape.h>
#include <BulletCollision/CollisionShapes/btBvhTriangleMeshShape.h>
#include <BulletCollision/CollisionShapes/btCapsuleShape.h>
#include <BulletCollision/CollisionShapes/btCompoundShape.h>
#include <BulletCollision/CollisionShapes/btConvexHullShape.h>
#include <BulletCollision/CollisionShapes/btCylinderShape.h>
#include <BulletCollision/CollisionShapes/btSphereShape.h>
#include <BulletCollision/CollisionShapes/btTriangleIndexVertexArray.h>
#include <LinearMath/btGeometryUtil.h>
#include <btBulletDynamicsCommon.h>

#include <cmath>
#include <limits>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace bullet_bodies {

/// A vector in Bullet's terms, and back.
inline btVector3 toBullet(const Eigen::Vector3d& v) { return btVector3(btScalar(v.x()), btScalar(v.y()), btScalar(v.z())); }
/// A vector in our terms.
inline Eigen::Vector3d fromBullet(const btVector3& v) { return Eigen::Vector3d(v.x(), v.y(), v.z()); }
inline btMatrix3x3 toBullet(const Eigen::Matrix3d& m) {
  return btMatrix3x3(btScalar(m(0, 0)), btScalar(m(0, 1)), btScalar(m(0, 2)), btScalar(m(1, 0)), btScalar(m(1, 1)),
                     btScalar(m(1, 2)), btScalar(m(2, 0)), btScalar(m(2, 1)), btScalar(m(2, 2)));
}
inline Eigen::Matrix3d fromBullet(const btMatrix3x3& m) {
  Eigen::Matrix3d out;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) out(r, c) = m[r][c];
  return out;
}

/// Bullet's largest collision margin, its default (0.04 world units).
constexpr double kBulletDefaultMargin = 0.04;

/// A convex hull for Bullet whose rounded shape (hull plus margin) is the given hull.
struct HullForBullet {
  std::vector<btVector3> points;  ///< the hull shrunk by `margin` (or the hull itself when margin is 0)
  double margin = 0;              ///< the margin Bullet adds back around it
  double thickness = 0;           ///< the hull's least width over its face normals
};

/// Bullet adds a convex hull's margin *outside* its points: a btConvexHullShape of the
/// given points is larger by its margin all round (the Bullet manual's "collision margin"
/// section; a box's margin, by contrast, lies inside its half extents). Bullet's
/// convex-decomposition demo therefore shrinks each hull's face planes by the margin
/// (btGeometryUtil) and lets the margin round the result back out; we do the same, so
/// that the shape Bullet collides is our piece with its edges rounded by the margin. The
/// margin is Bullet's default 0.04, but at most a tenth of the hull's thickness: a thin
/// piece would vanish under a 0.04 shrink. Bullet's GJK/EPA wants some margin (it finds
/// penetration depths on the shrunk core), so we keep one rather than set it to zero.
inline HullForBullet hullForBullet(const std::vector<Eigen::Vector3d>& vertices) {
  btAlignedObjectArray<btVector3> points, planes;
  for (const auto& v : vertices) points.push_back(toBullet(v));
  btGeometryUtil::getPlaneEquationsFromVertices(points, planes);
  HullForBullet out;
  double thickness = std::numeric_limits<double>::infinity();
  for (int p = 0; p < planes.size(); ++p) {
    double width = 0;  // Bullet's planes: n.x + d <= 0 inside
    for (int v = 0; v < points.size(); ++v) width = std::max(width, -double(planes[p].dot(points[v]) + planes[p][3]));
    thickness = std::min(thickness, width);
  }
  out.thickness = std::isfinite(thickness) ? thickness : 0;
  out.margin = std::min(kBulletDefaultMargin, 0.1 * out.thickness);
  if (out.margin > 0) {
    btAlignedObjectArray<btVector3> shifted, shrunk;
    for (int p = 0; p < planes.size(); ++p) {
      btVector3 plane = planes[p];
      plane[3] += btScalar(out.margin);
      shifted.push_back(plane);
    }
    btGeometryUtil::getVerticesFromPlaneEquations(shifted, shrunk);
    for (int v = 0; v < shrunk.size(); ++v) out.points.push_back(shrunk[v]);
  }
  if (out.points.size() < 4) {  // nothing left to shrink: the hull itself, without margin
    out.points.clear();
    for (int v = 0; v < points.size(); ++v) out.points.push_back(points[v]);
    out.margin = 0;
  }
  return out;
}

/// A body as Bullet holds it, with what it takes to go back to our body frame.
struct BulletBody {
  std::unique_ptr<btCollisionShape> shape;
  std::vector<std::unique_ptr<btCollisionShape>> children;  ///< a compound's pieces
  std::unique_ptr<btTriangleIndexVertexArray> triangles;     ///< a static mesh's triangles (Bullet keeps pointers)
  std::vector<int> indices;                                  ///< their storage
  std::vector<btScalar> vertices;
  std::unique_ptr<btRigidBody> rigid;
  /// Bullet's body frame is our body frame (origin at the centre of mass) turned onto the
  /// principal axes of inertia: bodyFromPrincipal, a rotation (identity when ours are).
  Eigen::Matrix3d bodyFromPrincipal = Eigen::Matrix3d::Identity();
  /// Half the body's least thickness (CCD's swept sphere and motion threshold).
  double halfThickness = 0;
};

using peer_run::principalAxes;
using peer_run::principalVertices;

/// A convex hull shape for Bullet from our piece (shrunk by its margin, see hullForBullet).
inline std::unique_ptr<btCollisionShape> hullShape(const std::vector<Eigen::Vector3d>& vertices, double& halfThickness) {
  const HullForBullet hull = hullForBullet(vertices);
  auto shape = std::make_unique<btConvexHullShape>();
  for (const auto& p : hull.points) shape->addPoint(p, false);
  shape->recalcLocalAabb();
  shape->setMargin(btScalar(hull.margin));
  halfThickness = 0.5 * hull.thickness;
  return shape;
}

/// The Bullet shape of body `index`: the same shape as ours, in Bullet's body frame.
inline void buildShape(const gjkx::Scene& scene, std::size_t index, const gjkx::WorldBody& body, BulletBody& out) {
  const gjkx::BodySpec& spec = scene.bodies[index];
  const Eigen::Matrix3d& P = out.bodyFromPrincipal;
  switch (spec.shape.kind) {
    case gjkx::ShapeSpec::Kind::Box: {
      // A box keeps its extents: Bullet puts a box's margin inside them. The default 0.04
      // is larger than a thin box's half thickness (a domino's is 0.02), so the margin is at
      // most a tenth of the smallest half extent.
      const Eigen::Vector3d h = spec.shape.halfExtents;
      auto box = std::make_unique<btBoxShape>(toBullet(h));
      box->setMargin(btScalar(std::min(kBulletDefaultMargin, 0.1 * h.minCoeff())));
      out.halfThickness = h.minCoeff();
      out.shape = std::move(box);
      return;
    }
    case gjkx::ShapeSpec::Kind::Sphere:  // a sphere's and a capsule's margin is their radius: nothing to set
      out.shape = std::make_unique<btSphereShape>(btScalar(spec.shape.radius));
      out.halfThickness = spec.shape.radius;
      return;
    case gjkx::ShapeSpec::Kind::Capsule:
      // Our capsule's axis is the body's z (scene.hpp); Bullet's "height" is the length of
      // the segment between the two hemispheres' centres.
      out.shape = std::make_unique<btCapsuleShapeZ>(btScalar(spec.shape.radius), btScalar(2 * spec.shape.halfLength));
      out.halfThickness = spec.shape.radius;
      return;
    case gjkx::ShapeSpec::Kind::Cylinder: {
      // Our cylinder's axis is the body's z (scene.hpp): Bullet's btCylinderShapeZ, whose
      // half extents are (r, r, h). Like a box's, its margin lies inside its extents; the
      // default 0.04 is at most a tenth of its smaller half size.
      const double r = spec.shape.radius, h = spec.shape.halfLength;
      auto cylinder = std::make_unique<btCylinderShapeZ>(toBullet(Eigen::Vector3d(r, r, h)));
      cylinder->setMargin(btScalar(std::min(kBulletDefaultMargin, 0.1 * std::min(r, h))));
      out.halfThickness = std::min(r, h);
      out.shape = std::move(cylinder);
      return;
    }
    case gjkx::ShapeSpec::Kind::Polytope:
      out.shape = hullShape(principalVertices(body.pieces[0], P), out.halfThickness);
      return;
    case gjkx::ShapeSpec::Kind::Mesh: break;
  }
  if (!spec.isStatic) {
    // A moving mesh: a compound of the very convex pieces our world uses (Bullet's advice
    // for a dynamic concave body is a compound of convex hulls).
    auto compound = std::make_unique<btCompoundShape>();
    out.halfThickness = std::numeric_limits<double>::infinity();
    for (const auto& piece : body.pieces) {
      double half = 0;
      out.children.push_back(hullShape(principalVertices(piece, P), half));
      out.halfThickness = std::min(out.halfThickness, half);
      btTransform identity;
      identity.setIdentity();
      compound->addChildShape(identity, out.children.back().get());
    }
    out.shape = std::move(compound);
    return;
  }
  // A static mesh: its triangles in a btBvhTriangleMeshShape, Bullet's usual static
  // environment (a static body's frame is the scene's: no centre of mass to move to).
  const std::string& given = spec.shape.meshPath;
  const std::string path = !given.empty() && given[0] == '/' ? given : scene.folder + "/" + given;
  const gjkx::TriangleMesh mesh = gjkx::readMesh(path);
  for (const auto& v : mesh.vertices)
    for (int k = 0; k < 3; ++k) out.vertices.push_back(btScalar(v[k]));
  for (const auto& t : mesh.triangles) out.indices.insert(out.indices.end(), t.begin(), t.end());
  out.triangles = std::make_unique<btTriangleIndexVertexArray>(int(mesh.triangles.size()), out.indices.data(),
                                                               int(3 * sizeof(int)), int(mesh.vertices.size()),
                                                               out.vertices.data(), int(3 * sizeof(btScalar)));
  out.shape = std::make_unique<btBvhTriangleMeshShape>(out.triangles.get(), true);
}

}  // namespace bullet_bodies
