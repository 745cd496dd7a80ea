// The contact patch of two bodies (contact.hpp).
#include <gjkx/timewarp/contact.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <type_traits>

namespace gjkx {

std::vector<Eigen::Vector3d> touchingFeature(const Shape<double>& shape, const Pose<double>& pose,
                                             const Eigen::Vector3d& direction, double depth) {
  std::vector<Eigen::Vector3d> candidates;
  double radius = 0;
  std::visit(
      [&](const auto& x) {
        using X = std::decay_t<decltype(x)>;
        if constexpr (std::is_same_v<X, Box<double>>) {
          for (int k = 0; k < 8; ++k)
            candidates.push_back(Eigen::Vector3d((k & 1) ? x.halfExtents.x() : -x.halfExtents.x(),
                                                 (k & 2) ? x.halfExtents.y() : -x.halfExtents.y(),
                                                 (k & 4) ? x.halfExtents.z() : -x.halfExtents.z()));
        } else if constexpr (std::is_same_v<X, Polytope<double>>) {
          for (int v = 0; v < x.vertexCount(); ++v) candidates.push_back(x.vertex(v));
        } else if constexpr (std::is_same_v<X, Capsule<double>>) {
          candidates = {x.axis.a, x.axis.b};
          radius = x.radius;
        } else if constexpr (std::is_same_v<X, Sphere<double>>) {
          candidates = {Eigen::Vector3d::Zero()};
          radius = x.radius;
        } else if constexpr (std::is_same_v<X, Cylinder<double>>) {
          // Its two rims, sampled at the same angles (a cap flat on a floor touches with its
          // whole rim, a side with a segment from rim to rim), the samples starting at the
          // angle of its support point, so that the highest point is exactly among them and
          // a side's segment has both its ends (one end alone would move the patch's centre).
          const Eigen::Vector3d s = pose.toBodyDirection(direction);
          const double start = s.x() != 0 || s.y() != 0 ? std::atan2(s.y(), s.x()) : 0.0;
          constexpr int kRimPoints = 16;
          for (int k = 0; k < kRimPoints; ++k) {
            const double angle = start + 2 * M_PI * k / kRimPoints;
            const Eigen::Vector2d rim = x.radius * Eigen::Vector2d(std::cos(angle), std::sin(angle));
            for (const double z : {-x.halfLength, x.halfLength}) candidates.emplace_back(rim.x(), rim.y(), z);
          }
        } else {
          candidates = {x.support(pose.toBodyDirection(direction))};
        }
      },
      shape.variant());
  double highest = -std::numeric_limits<double>::infinity();
  for (auto& p : candidates) {
    p = pose(p);
    highest = std::max(highest, direction.dot(p));
  }
  std::vector<Eigen::Vector3d> feature;
  for (const auto& p : candidates)
    if (direction.dot(p) >= highest - depth) feature.push_back(p + radius * direction);
  return feature;
}

namespace {

double diameter(const std::vector<Eigen::Vector3d>& points) {
  double d = 0;
  for (const auto& p : points)
    for (const auto& q : points) d = std::max(d, (p - q).norm());
  return d;
}

Eigen::Vector3d centroid(const std::vector<Eigen::Vector3d>& points) {
  Eigen::Vector3d c = Eigen::Vector3d::Zero();
  for (const auto& p : points) c += p;
  return c / double(points.size());
}

}  // namespace

ContactPatch contactPatch(const Shape<double>& shapeA, const Pose<double>& poseA, const Shape<double>& shapeB,
                          const Pose<double>& poseB, const Eigen::Vector3d& pointA, const Eigen::Vector3d& pointB,
                          const Eigen::Vector3d& normal, double depth) {
  const Eigen::Vector3d middle = 0.5 * (pointA + pointB);
  const auto featureA = touchingFeature(shapeA, poseA, normal, depth);
  const auto featureB = touchingFeature(shapeB, poseB, -normal, depth);
  // The closest points lie on the touching features, so a feature that does not reach
  // them is no contact: a corner of a floor 6 m wide is within `depth` of its top plane
  // along a normal tilted by 1e-4 (float's noise), but it touches nothing.
  const auto reaches = [&](const std::vector<Eigen::Vector3d>& feature) {
    double nearest = std::numeric_limits<double>::infinity();
    for (const auto& p : feature) nearest = std::min(nearest, ((p - middle) - normal * normal.dot(p - middle)).norm());
    return nearest <= diameter(feature) + 2 * depth;
  };
  const bool a = reaches(featureA), b = reaches(featureB);
  static const std::vector<Eigen::Vector3d> none;
  const auto& patch = a && b ? (diameter(featureA) <= diameter(featureB) ? featureA : featureB)
                             : a ? featureA : b ? featureB : none;
  ContactPatch out;
  if (patch.empty()) {
    out.centre = middle;
    out.points = {middle};
    return out;
  }
  // Onto the plane midway between the closest points.
  for (const auto& p : patch) out.points.push_back(p + normal * normal.dot(middle - p));
  out.centre = centroid(out.points);
  return out;
}


// ---------------------------------------------------------------------------------------
// The contact of a hit

ContactPatch patchOf(const StepContext& step, const Hit& hit, const BodyState& si, const BodyState& sj) {
  return contactPatch(step.bodies[hit.i].pieces[hit.pieceI], si.worldFromBody, step.bodies[hit.j].pieces[hit.pieceJ],
                      sj.worldFromBody, hit.pointI, hit.pointJ, hit.normal, step.band(step.settings.tuning.patchDepth));
}

double approachOn(const StepContext& step, Hit& hit, const ContactPatch& patch, const BodyState& si,
                  const BodyState& sj) {
  const auto approach = [&](const Eigen::Vector3d& p) {
    return hit.normal.dot(step.bodies[hit.j].rigid.velocityAt(sj, p) - step.bodies[hit.i].rigid.velocityAt(si, p));
  };
  hit.contact = patch.centre;
  double vn = approach(patch.centre);
  // A patch that leaves at its centre may still close at a corner: a tilted body rocking
  // onto its other edge, an L resting on both legs after an impulse at one. The impulse
  // then acts at the corner that closes fastest (Mirtich's microcollisions at each
  // touching corner in turn), or the body would sink there unseen.
  if (vn >= 0)
    for (const Eigen::Vector3d& p : patch.points)
      if (const double v = approach(p); v < vn) {
        vn = v;
        hit.contact = p;
      }
  return vn;
}

double approachAt(StepContext& step, Hit& hit, const BodyState& si, const BodyState& sj) {
  PartTimer timer(step.frame.report.parts.impulses);
  return approachOn(step, hit, patchOf(step, hit, si, sj), si, sj);
}

namespace {

/// The unit direction from i's centre of mass to j's (up, +z, when they coincide): the
/// normal of a first contact whose closest points coincide.
Eigen::Vector3d centreToCentre(const BodyState& si, const BodyState& sj) {
  const Eigen::Vector3d d = sj.worldFromBody.translation - si.worldFromBody.translation;
  return d.norm() > 0 ? Eigen::Vector3d(d.normalized()) : Eigen::Vector3d::UnitZ();
}

}  // namespace

bool contactNormal(StepContext& step, Hit& hit, double distance, const BodyState& si, const BodyState& sj) {
  Eigen::Vector3d& known = step.knownNormal(hit.i, hit.pieceI, hit.j, hit.pieceJ);
  if (distance > step.band(step.settings.tuning.reliableNormal) && hit.normal.squaredNorm() > 0.5) {
    known = hit.normal;
    return true;
  }
  hit.normal = known.squaredNorm() > 0.5 ? known : centreToCentre(si, sj);
  return false;
}

bool contactFromGjk(StepContext& step, const GjkResult<double>& g, int i, int pi, int j, int pj, double t,
                    const BodyState& si, const BodyState& sj, Hit& hit) {
  hit.time = t;
  hit.i = i;
  hit.j = j;
  hit.pieceI = pi;
  hit.pieceJ = pj;
  const Eigen::Vector3d z = g.witnessQ - g.witnessP;
  const double distance = g.status == GjkStatus::Overlapping ? 0.0 : z.norm();
  hit.normal = distance > 0 ? Eigen::Vector3d(z / distance) : Eigen::Vector3d::Zero();
  if (contactNormal(step, hit, distance, si, sj)) {
    hit.pointI = g.witnessP;
    hit.pointJ = g.witnessQ;
    return true;
  }
  hit.pointI = hit.pointJ = 0.5 * (si.worldFromBody.translation + sj.worldFromBody.translation);
  return false;
}

bool contactAt(StepContext& step, int i, int pi, int j, int pj, double t, const BodyState& si, const BodyState& sj,
               Hit& hit) {
  // In contact: within the tolerance (§2.3), or under the hybrid within its contact band,
  // where its solver takes pieces as in contact (contact_solver.hpp, response.hpp).
  const double band = step.hybrid() ? step.band(step.settings.tuning.contactBand) : step.scene.collisionTolerance;
  GjkResult<double> g;
  {
    PartTimer timer(step.frame.report.parts.collisionDetection);
    GjkCache<double>* cache =
        step.warmStarts() ? &step.frame.contactCoherence[step.piecePairKey(i, pi, j, pj)] : nullptr;
    // Only "within the band or not" is asked of a pair that is apart (§2.3's boolean
    // query): most pairs the instant pass looks at touched earlier in the frame and have
    // parted since, and the direction that last separated them, warm from the cache, says
    // so with two supports (the run then ends with a distance above the band, an upper
    // bound, and the pair is not in contact).
    GjkSettings<double> settings;
    settings.separationThreshold = band;
    g = gjk(Placed<ShapeRef<double>>{step.bodies[i].pieces[pi], si.worldFromBody},
            Placed<ShapeRef<double>>{step.bodies[j].pieces[pj], sj.worldFromBody}, settings, cache);
  }
  if (g.status != GjkStatus::Overlapping && g.distance > band) return false;
  contactFromGjk(step, g, i, pi, j, pj, t, si, sj, hit);
  return true;
}

}  // namespace gjkx
