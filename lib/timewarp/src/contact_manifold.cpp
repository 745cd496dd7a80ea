// The contact manifold of two convex pieces (contact_manifold.hpp).
#include <gjkx/timewarp/contact_manifold.hpp>

#include <gjkx/timewarp/contact.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace gjkx {

namespace {

using Vec2 = Eigen::Vector2d;

double cross(const Vec2& a, const Vec2& b) { return a.x() * b.y() - a.y() * b.x(); }

/// A touching feature seen on the contact plane: each point's place on the plane and its
/// height along the normal, its convex hull counter-clockwise (one point, a segment, or a polygon).
struct Feature {
  std::vector<Vec2> hull;
  std::vector<double> height;  // per hull vertex
  std::vector<Vec2> points;    // every point of the feature (a curved one's lowest lie inside its hull)
  std::vector<double> pointHeight;

  /// The feature's height at a point of the plane inside it: the plane through its largest
  /// triangle (a face), the line of its segment (an edge), or its one point's.
  double heightAt(const Vec2& p) const {
    if (hull.size() == 1) return height[0];
    if (hull.size() == 2) {
      const Vec2 d = hull[1] - hull[0];
      const double s = std::clamp(d.dot(p - hull[0]) / std::max(d.squaredNorm(), 1e-300), 0.0, 1.0);
      return height[0] + s * (height[1] - height[0]);
    }
    // The plane h = h0 + g . (p - p0) through three hull vertices far apart.
    std::size_t a = 0, b = 1, c = 2;
    double best = -1;
    for (std::size_t k = 1; k < hull.size(); ++k)
      for (std::size_t l = k + 1; l < hull.size(); ++l)
        if (const double area = std::abs(cross(hull[k] - hull[0], hull[l] - hull[0])); area > best) {
          best = area;
          b = k;
          c = l;
        }
    const Vec2 u = hull[b] - hull[a], v = hull[c] - hull[a];
    const double det = cross(u, v);
    if (std::abs(det) < 1e-300) return height[a];
    const double hu = height[b] - height[a], hv = height[c] - height[a];
    // g . u = hu, g . v = hv  (Cramer's rule)
    const Vec2 g((hu * v.y() - hv * u.y()) / det, (u.x() * hv - v.x() * hu) / det);
    return height[a] + g.dot(p - hull[a]);
  }

  /// Is p inside the feature, or within eps of it?
  bool contains(const Vec2& p, double eps) const {
    if (hull.size() == 1) return (p - hull[0]).norm() <= eps;
    if (hull.size() == 2) {
      const Vec2 d = hull[1] - hull[0];
      const double s = std::clamp(d.dot(p - hull[0]) / std::max(d.squaredNorm(), 1e-300), 0.0, 1.0);
      return (hull[0] + s * d - p).norm() <= eps;
    }
    for (std::size_t k = 0; k < hull.size(); ++k) {
      const Vec2 e = hull[(k + 1) % hull.size()] - hull[k];
      if (cross(e, p - hull[k]) < -eps * e.norm()) return false;
    }
    return true;
  }
};

/// The feature of `points` on the plane spanned by u and v, heights along n: Andrew's
/// monotone chain for the hull, points closer than eps merged.
Feature featureOf(const std::vector<Eigen::Vector3d>& points, const Eigen::Vector3d& u, const Eigen::Vector3d& v,
                  const Eigen::Vector3d& n, double eps) {
  struct P {
    Vec2 at;
    double h;
  };
  std::vector<P> ps;
  for (const auto& p : points) ps.push_back({Vec2(u.dot(p), v.dot(p)), n.dot(p)});
  std::sort(ps.begin(), ps.end(), [](const P& a, const P& b) {
    return a.at.x() < b.at.x() || (a.at.x() == b.at.x() && a.at.y() < b.at.y());
  });
  std::vector<P> hull;
  const auto turnsLeft = [&](const P& a, const P& b, const P& c) { return cross(b.at - a.at, c.at - a.at) > eps * eps; };
  for (int pass = 0; pass < 2; ++pass) {
    const std::size_t base = hull.size();
    for (const P& p : ps) {
      while (hull.size() >= base + 2 && !turnsLeft(hull[hull.size() - 2], hull.back(), p)) hull.pop_back();
      hull.push_back(p);
    }
    hull.pop_back();  // the last point starts the other chain
    std::reverse(ps.begin(), ps.end());
  }
  Feature f;
  for (const P& p : ps) {
    f.points.push_back(p.at);
    f.pointHeight.push_back(p.h);
  }
  for (const P& p : hull)
    if (f.hull.empty() || (p.at - f.hull.back()).norm() > eps) {
      f.hull.push_back(p.at);
      f.height.push_back(p.h);
    }
  while (f.hull.size() > 1 && (f.hull.back() - f.hull.front()).norm() <= eps) {
    f.hull.pop_back();
    f.height.pop_back();
  }
  if (f.hull.empty() && !ps.empty()) {  // all points within eps of one another
    f.hull.push_back(ps.front().at);
    f.height.push_back(ps.front().h);
  }
  return f;
}

/// The edges of a feature (a segment is one edge; a point none).
std::vector<std::pair<std::size_t, std::size_t>> edgesOf(const Feature& f) {
  std::vector<std::pair<std::size_t, std::size_t>> edges;
  if (f.hull.size() == 2) edges.emplace_back(0, 1);
  if (f.hull.size() >= 3)
    for (std::size_t k = 0; k < f.hull.size(); ++k) edges.emplace_back(k, (k + 1) % f.hull.size());
  return edges;
}

/// Up to four of `points` that keep the largest area (Box2D's and Bullet's reduction): the
/// deepest, the farthest from it, the farthest from their line, and the one that adds most
/// area on the other side.
std::vector<std::pair<Vec2, double>> reduced(const std::vector<std::pair<Vec2, double>>& points) {
  if (points.size() <= 4) return points;
  std::size_t a = 0;
  for (std::size_t k = 1; k < points.size(); ++k)
    if (points[k].second < points[a].second) a = k;
  std::size_t b = a;
  double far = -1;
  for (std::size_t k = 0; k < points.size(); ++k)
    if (const double d = (points[k].first - points[a].first).squaredNorm(); d > far) {
      far = d;
      b = k;
    }
  const Vec2 ab = points[b].first - points[a].first;
  std::size_t c = a, d = a;
  double most = 0, least = 0;
  for (std::size_t k = 0; k < points.size(); ++k) {
    const double s = cross(ab, points[k].first - points[a].first);
    if (s > most) {
      most = s;
      c = k;
    }
    if (s < least) {
      least = s;
      d = k;
    }
  }
  std::vector<std::pair<Vec2, double>> out{points[a], points[b]};
  if (c != a) out.push_back(points[c]);
  if (d != a) out.push_back(points[d]);
  return out;
}

}  // namespace

namespace {

/// The unit normal of the plane of `points`, from their largest triangle, on n's side; zero
/// when they span no area (a vertex or an edge).
Eigen::Vector3d planeNormal(const std::vector<Eigen::Vector3d>& points, const Eigen::Vector3d& n, double tolerance) {
  Eigen::Vector3d best = Eigen::Vector3d::Zero();
  for (std::size_t a = 0; a < points.size(); ++a)
    for (std::size_t b = a + 1; b < points.size(); ++b)
      for (std::size_t c = b + 1; c < points.size(); ++c) {
        const Eigen::Vector3d m = (points[b] - points[a]).cross(points[c] - points[a]);
        if (m.norm() > best.norm()) best = m;
      }
  if (best.norm() <= tolerance * tolerance) return Eigen::Vector3d::Zero();
  best.normalize();
  return best.dot(n) < 0 ? Eigen::Vector3d(-best) : best;
}

}  // namespace

Eigen::Vector3d leastOverlapAxis(const Shape<double>& shapeA, const Pose<double>& poseA, const Shape<double>& shapeB,
                                 const Pose<double>& poseB, const std::vector<Eigen::Vector3d>& hints) {
  // Overlap along d: how far A reaches past B's nearest point, max_A d.x - min_B d.x.
  const auto overlap = [&](const Eigen::Vector3d& d) {
    const Eigen::Vector3d a = poseA(shapeA.support(poseA.toBodyDirection(d)));
    const Eigen::Vector3d b = poseB(shapeB.support(poseB.toBodyDirection(Eigen::Vector3d(-d))));
    return d.dot(a) - d.dot(b);
  };
  std::vector<Eigen::Vector3d> candidates;
  for (const Pose<double>* pose : {&poseA, &poseB})
    for (int k = 0; k < 3; ++k) candidates.push_back(pose->rotation.col(k));
  for (const auto& h : hints)
    if (h.squaredNorm() > 0.5) candidates.push_back(h.normalized());
  Eigen::Vector3d best = Eigen::Vector3d::UnitZ();
  double least = 1e300;
  for (const auto& c : candidates)
    for (const Eigen::Vector3d& d : {c, Eigen::Vector3d(-c)})
      if (const double o = overlap(d); o < least) {
        least = o;
        best = d;
      }
  return best;
}

Eigen::Vector3d faceNormal(const Shape<double>& shapeA, const Pose<double>& poseA, const Shape<double>& shapeB,
                           const Pose<double>& poseB, const Eigen::Vector3d& normal, double depth) {
  const Eigen::Vector3d a = planeNormal(touchingFeature(shapeA, poseA, normal, depth), normal, depth);
  const Eigen::Vector3d b = planeNormal(touchingFeature(shapeB, poseB, -normal, depth), normal, depth);
  const double cosLimit = std::cos(10.0 * M_PI / 180.0);
  const double da = a.dot(normal), db = b.dot(normal);
  if (std::max(da, db) < cosLimit) return normal;
  return da >= db ? a : b;
}

std::vector<ManifoldPoint> contactManifold(const Shape<double>& shapeA, const Pose<double>& poseA,
                                           const Shape<double>& shapeB, const Pose<double>& poseB,
                                           const Eigen::Vector3d& normal, double depth,
                                           const Eigen::Vector3d& fallback, double distance, double tolerance) {
  const Eigen::Vector3d& n = normal;
  const Eigen::Vector3d u = n.unitOrthogonal(), v = n.cross(u);
  const double eps = tolerance;
  const Feature A = featureOf(touchingFeature(shapeA, poseA, n, depth), u, v, n, eps);
  const Feature B = featureOf(touchingFeature(shapeB, poseB, -n, depth), u, v, n, eps);
  // Where the two features overlap on the plane: the vertices of each inside the other,
  // and the crossings of their edges; at each, the separation is B's height minus A's.
  std::vector<std::pair<Vec2, double>> found;  // place on the plane, separation
  std::vector<double> middle;                  // the height midway between the surfaces there
  const auto add = [&](const Vec2& p, double hA, double hB) {
    for (const auto& q : found)
      if ((q.first - p).norm() <= eps) return;
    found.emplace_back(p, hB - hA);
    middle.push_back(0.5 * (hA + hB));
  };
  for (std::size_t k = 0; k < A.points.size(); ++k)
    if (B.contains(A.points[k], eps)) add(A.points[k], A.pointHeight[k], B.heightAt(A.points[k]));
  for (std::size_t k = 0; k < B.points.size(); ++k)
    if (A.contains(B.points[k], eps)) add(B.points[k], A.heightAt(B.points[k]), B.pointHeight[k]);
  for (const auto& [a0, a1] : edgesOf(A))
    for (const auto& [b0, b1] : edgesOf(B)) {
      // a0 + s (a1 - a0) = b0 + r (b1 - b0), both in [0, 1]
      const Vec2 d = A.hull[a1] - A.hull[a0], e = B.hull[b1] - B.hull[b0], w = B.hull[b0] - A.hull[a0];
      const double det = cross(d, e);
      if (std::abs(det) <= 1e-12 * d.norm() * e.norm()) continue;  // parallel: their ends are found above
      const double s = cross(w, e) / det, r = cross(w, d) / det;
      if (s < 0 || s > 1 || r < 0 || r > 1) continue;
      add(A.hull[a0] + s * d, A.height[a0] + s * (A.height[a1] - A.height[a0]),
          B.height[b0] + r * (B.height[b1] - B.height[b0]));
    }
  // How far overlapping pieces (distance 0) overlap along the normal: B's lowest point less
  // A's highest (their supports). Never less deep than the overlap, so the projection parts
  // them (read as 0 or as a gap, it would hold them where they are, inside each other).
  const auto overlapAlongNormal = [&] {
    return std::min(0.0, *std::min_element(B.pointHeight.begin(), B.pointHeight.end()) -
                             *std::max_element(A.pointHeight.begin(), A.pointHeight.end()));
  };
  std::vector<ManifoldPoint> out;
  if (found.empty()) {  // features that do not overlap by round-off: the closest points
    ManifoldPoint p;
    p.point = fallback;
    // Overlapping pieces whose features miss each other on the plane (the normal of an
    // overlap is the axis of least overlap, not a closest points' direction): the overlap.
    p.separation = distance <= 0 ? overlapAlongNormal() : distance;
    out.push_back(p);
    return out;
  }
  // Overlapping pieces whose features overlap on the plane but read a gap there: a feature
  // as deep as the solver's (the band and the pair's motion over the interval, several
  // tolerances) spans several faces of a curved piece, and its hull's plane, a chord, lies
  // off the surface by up to that depth. An overlap is never read as a gap: the nearest
  // point takes the overlap along the normal.
  if (distance <= 0) {
    const auto nearest = std::min_element(found.begin(), found.end(),
                                          [](const auto& a, const auto& b) { return a.second < b.second; });
    if (nearest->second >= 0) nearest->second = overlapAlongNormal();
  }
  // The points that touch (within two tolerances of the deepest) first, reduced to four;
  // places left go to the deepest of the rest (a curved piece's points farther up).
  double deepest = 1e300;
  for (const auto& f : found) deepest = std::min(deepest, f.second);
  std::vector<std::pair<Vec2, double>> touching, rest;
  for (const auto& f : found) (f.second <= deepest + 2 * eps ? touching : rest).push_back(f);
  std::vector<std::pair<Vec2, double>> kept = reduced(touching);
  std::sort(rest.begin(), rest.end(), [](const auto& a, const auto& b) { return a.second < b.second; });
  for (std::size_t k = 0; kept.size() < 4 && k < rest.size(); ++k) kept.push_back(rest[k]);
  for (const auto& [at, separation] : kept) {
    ManifoldPoint p;
    // Midway between the two surfaces at that place.
    double mid = 0;
    for (std::size_t k = 0; k < found.size(); ++k)
      if (found[k].first == at) mid = middle[k];
    p.point = u * at.x() + v * at.y() + n * mid;
    p.separation = separation;
    out.push_back(p);
  }
  return out;
}

}  // namespace gjkx
