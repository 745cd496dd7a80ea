// Exact closest points of small features, in long double: the ground truth that the
// tests, the fuzz targets and the study hold GJK (§2.2) and the time-of-impact solver
// (§5) to. Nothing here shares code with the library's stages (this library links Eigen
// only), so an error in the sub-algorithm cannot hide in its own reference.
//
// Slivers. The fuzz findings `reference_sliver_triangle` (a point 2.1e-8 from a triangle
// 47000 long and 1e-7 wide) and `reference_needle_face_normal` (a needle with edges 2.7e5
// and 1e-4) showed that Ericson's region tests (Real-Time Collision Detection, §5.1.5 and
// §5.1.9), which subtract products of dot products, lose every digit on such features.
// The versions here never subtract two products of lengths of the feature's long size:
// a triangle's normal is the cross product of the two edges at its largest angle, a
// point's side of an edge is a signed area (a cross product from a vertex), and a
// segment pair takes the distance from a point of one to the other, whose error does not
// grow as the segments turn parallel (see closestSegmentSegment).
#pragma once

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <vector>

namespace gjkx::reference {

/// The scalar of every reference: long double (64-bit mantissa on x86, eps = 1.1e-19),
/// so a reference carries about 11 more bits than the double computation it checks.
using Real = long double;
/// A point or direction in long double.
using Vec = Eigen::Matrix<Real, 3, 1>;

/// The closest point to x on the segment [a, b] (a if the segment is a point).
///
/// Accuracy: the parameter u = (x - a).(b - a) / |b - a|^2 is off by a few eps relative,
/// which moves the point along the segment by eps |b - a|; the distance |x - point|
/// changes by that only to second order, so the distance is right within
/// a few eps (|x| + |a| + |b|).
inline Vec closestOnSegment(const Vec& x, const Vec& a, const Vec& b) {
  const Vec ab = b - a;
  const Real len2 = ab.squaredNorm();
  if (!(len2 > 0)) return a;
  const Real u = std::clamp((x - a).dot(ab) / len2, Real(0), Real(1));
  return a + u * ab;
}

/// The distance from x to the segment [a, b]; accuracy as closestOnSegment.
inline Real pointSegmentDistance(const Vec& x, const Vec& a, const Vec& b) {
  return (closestOnSegment(x, a, b) - x).norm();
}

namespace detail {

/// The exact product a b as the sum hi + lo of two long doubles (Dekker's TwoProduct with
/// Veltkamp's split into 32-bit halves; exact for the 64-bit mantissa of long double, short
/// of overflow). Done without std::fma, which long double has only in software (300 ns).
inline void twoProduct(Real a, Real b, Real& hi, Real& lo) {
  constexpr Real split = Real(4294967297.0L);  // 2^32 + 1
  hi = a * b;
  const Real ca = split * a, cb = split * b;
  const Real aHi = ca - (ca - a), aLo = a - aHi;
  const Real bHi = cb - (cb - b), bLo = b - bHi;
  lo = ((aHi * bHi - hi) + aHi * bLo + aLo * bHi) + aLo * bLo;
}

/// a b - c d within a few ulps of the result, however much the two products cancel: both
/// are formed exactly (twoProduct), their leading parts subtracted (exactly, by Sterbenz's
/// lemma, when they cancel) and the rounding errors added back.
inline Real differenceOfProducts(Real a, Real b, Real c, Real d) {
  Real ab, abError, cd, cdError;
  twoProduct(a, b, ab, abError);
  twoProduct(c, d, cd, cdError);
  return (ab - cd) + (abError - cdError);
}

/// u x v with every component within a few ulps, however nearly parallel u and v are: the
/// exact cross product of the given vectors, rounded. When u and v are at least 14 degrees
/// apart (|u x v| >= |u| |v| / 4) the plain cross product is already that good (its
/// relative error is about eps / sin(angle)) and is returned.
inline Vec accurateCross(const Vec& u, const Vec& v) {
  const Vec plain = u.cross(v);
  if (16 * plain.squaredNorm() >= u.squaredNorm() * v.squaredNorm()) return plain;
  return Vec(differenceOfProducts(u.y(), v.z(), u.z(), v.y()), differenceOfProducts(u.z(), v.x(), u.x(), v.z()),
             differenceOfProducts(u.x(), v.y(), u.y(), v.x()));
}

}  // namespace detail

/// The normal (b - a) x (c - a) of triangle abc (not normalised; zero when degenerate),
/// taken from the two edges at the triangle's largest angle, with an accurate cross product.
///
/// Accuracy: the three pairs of edges give the same vector in exact arithmetic. A plain
/// cross product of two long edges cancels: on a needle (two edges 2.7e5 long, one 1e-4)
/// it came out 3e-10 off in direction (fuzz finding `reference_needle_face_normal`), on a
/// flat sliver 47000 x 1e-7 (every angle near 0 or 180 degrees) 2.5e-8 off, enough to move
/// the projection of a point 20000 along by 5e-4. Here each component is the cross product
/// of the edges as computed, right to a few ulps (detail::accurateCross); the edges
/// carry a round-off of eps |edge|, which is the exact normal of the triangle with its
/// vertices moved by that much, and a distance to a triangle moves by no more than its
/// vertices do. The shortest edges (those at the largest angle) keep that move smallest.
inline Vec triangleNormal(const Vec& a, const Vec& b, const Vec& c) {
  const Real ab = (b - a).squaredNorm(), bc = (c - b).squaredNorm(), ca = (a - c).squaredNorm();
  if (bc >= ab && bc >= ca) return detail::accurateCross(b - a, c - a);  // largest angle at a
  if (ca >= ab) return detail::accurateCross(c - b, a - b);              // at b
  return detail::accurateCross(a - c, b - c);                            // at c
}

namespace detail {

/// Where the projection of x onto the plane of triangle abc falls: the projection p and
/// its three signed areas against the normal (u opposite a: edge bc, v opposite b: edge ca,
/// w opposite c: edge ab), all >= 0 inside. `valid` is false for a degenerate triangle.
struct PlaneProjection {
  Vec p = Vec::Zero();
  Real u = 0, v = 0, w = 0;
  bool valid = false;
};

inline PlaneProjection projectOntoTriangle(const Vec& x, const Vec& a, const Vec& b, const Vec& c) {
  PlaneProjection out;
  const Vec n = triangleNormal(a, b, c);
  const Real nn = n.squaredNorm();
  if (!(nn > 0)) return out;
  out.p = x - n * (n.dot(x - a) / nn);
  out.u = n.dot((c - b).cross(out.p - b));
  out.v = n.dot((a - c).cross(out.p - c));
  out.w = n.dot((b - a).cross(out.p - a));
  out.valid = true;
  return out;
}

}  // namespace detail

/// The projection of x onto the plane of triangle abc when it lies in the triangle (its
/// closest point is then interior); std::nullopt when it lies outside (the closest point
/// is then on an edge) or the triangle is degenerate.
///
/// Accuracy: the projection uses the normal of triangleNormal; inside is decided by the
/// three signed areas n.((c - b) x (p - b)) etc., each a cross product of two vectors from
/// one vertex, so on a sliver 47000 long and 1e-7 wide every term keeps its relative
/// precision (Ericson's region tests subtract dot products 1.6e15 apart by less than their
/// round-off there and took an interior point for one on an edge: fuzz finding
/// `reference_sliver_triangle`). A point within round-off of an edge may be called
/// outside; the edge's closest point is then the same within that round-off.
inline std::optional<Vec> projectionInsideTriangle(const Vec& x, const Vec& a, const Vec& b, const Vec& c) {
  const detail::PlaneProjection q = detail::projectOntoTriangle(x, a, b, c);
  if (q.valid && q.u >= 0 && q.v >= 0 && q.w >= 0) return q.p;
  return std::nullopt;
}

/// The closest point to x of the triangle abc (solid): the interior projection when it
/// lies inside (projectionInsideTriangle), else the nearest closest point of the edges
/// whose signed area is negative (the edges whose lines separate the projection from the
/// triangle: the closest point lies on one of them). Degenerate triangles (a segment or a
/// point) are handled by all three edges.
///
/// Accuracy: the distance is right within a few eps times the size of the coordinates,
/// whatever the triangle's shape (see projectionInsideTriangle and closestOnSegment); an
/// area whose sign is wrong by round-off belongs to a projection within round-off of that
/// edge's line, where the edges kept give the same point within that round-off.
inline Vec closestOnTriangle(const Vec& x, const Vec& a, const Vec& b, const Vec& c) {
  const detail::PlaneProjection q = detail::projectOntoTriangle(x, a, b, c);
  if (q.valid && q.u >= 0 && q.v >= 0 && q.w >= 0) return q.p;
  Vec best = Vec::Zero();
  Real bestDistance2 = std::numeric_limits<Real>::infinity();
  auto tryEdge = [&](bool outside, const Vec& e0, const Vec& e1) {
    if (q.valid && !outside) return;
    const Vec y = closestOnSegment(x, e0, e1);
    const Real d2 = (y - x).squaredNorm();
    if (d2 < bestDistance2) best = y, bestDistance2 = d2;
  };
  tryEdge(q.w < 0, a, b);
  tryEdge(q.u < 0, b, c);
  tryEdge(q.v < 0, c, a);
  return best;
}

/// The distance from x to the triangle abc; accuracy as closestOnTriangle.
inline Real pointTriangleDistance(const Vec& x, const Vec& a, const Vec& b, const Vec& c) {
  return (closestOnTriangle(x, a, b, c) - x).norm();
}

/// The closest pair of points of two segments and their distance.
struct SegmentPair {
  Vec onFirst = Vec::Zero();   ///< the point of [p1, q1]
  Vec onSecond = Vec::Zero();  ///< the point of [p2, q2]
  Real distance = std::numeric_limits<Real>::infinity();  ///< |onSecond - onFirst|
};

/// The closest points of the segments [p1, q1] and [p2, q2].
///
/// The minimum over the two segments is either at an end of one (four point-segment
/// candidates) or at interior points of both, where it is the distance of the two lines.
/// The interior candidate takes the first line's parameter
///     s = ((p2 - p1) x d2) . n / |n|^2,   n = d1 x d2,
/// clamps it to [0, 1] and then the closest point of the second segment to that point;
/// the nearest of the five candidates is returned.
///
/// One other copy is kept on purpose: GJK's closed form for two spheres or capsules
/// (`detail::closestParametersOfSegments` in gjkx/gjk/gjk.hpp), in the stage's scalar and
/// with Ericson's parameters, fast. This one is its independent check
/// (tests/gjk/test_gjk_rounded.cpp holds the first to it), so the two share no code.
///
/// Accuracy: every candidate is a pair of points on the segments (within round-off), so
/// its distance is an upper bound, and the best one is the minimum within a few eps times
/// the size of the coordinates, however parallel the segments are. As they turn parallel
/// (angle theta) the parameter s becomes ill-conditioned, off by eps / theta, but moving
/// along the first segment by delta changes the distance to the second by only
/// theta * delta: the error eps |d1| does not grow. Ericson's version (§5.1.9) divides by
/// |d1|^2 |d2|^2 - (d1.d2)^2, which cancels to noise for two edges 2.7e5 long a few 1e-9
/// rad apart, and then picks a wrong pair of points.
inline SegmentPair closestSegmentSegment(const Vec& p1, const Vec& q1, const Vec& p2, const Vec& q2) {
  SegmentPair best;
  auto consider = [&](const Vec& x, const Vec& y) {
    const Real d = (y - x).norm();
    if (d < best.distance) best = SegmentPair{x, y, d};
  };
  consider(p1, closestOnSegment(p1, p2, q2));
  consider(q1, closestOnSegment(q1, p2, q2));
  consider(closestOnSegment(p2, p1, q1), p2);
  consider(closestOnSegment(q2, p1, q1), q2);
  const Vec d1 = q1 - p1, d2 = q2 - p2;
  const Vec n = d1.cross(d2);
  const Real nn = n.squaredNorm();
  if (nn > 0) {
    const Real s = std::clamp(((p2 - p1).cross(d2)).dot(n) / nn, Real(0), Real(1));
    const Vec x = p1 + s * d1;
    consider(x, closestOnSegment(x, p2, q2));
  }
  return best;
}

/// The distance between the segments [p1, q1] and [p2, q2]; accuracy as closestSegmentSegment.
inline Real segmentSegmentDistance(const Vec& p1, const Vec& q1, const Vec& p2, const Vec& q2) {
  return closestSegmentSegment(p1, q1, p2, q2).distance;
}

/// The distance from x to the axis-aligned box [-h, h] (0 inside); exact up to the
/// round-off of one norm.
inline Real pointBoxDistance(const Vec& x, const Vec& h) {
  Vec out;
  for (int k = 0; k < 3; ++k) out[k] = std::max(Real(0), std::abs(x[k]) - h[k]);
  return out.norm();
}

/// The distance from the segment [a, b] to the axis-aligned box [-h, h] (0 if they meet).
///
/// Accuracy: the distance of a + u (b - a) to a convex set is convex in u, so a ternary
/// search finds its minimum; 200 steps shrink the bracket by (2/3)^200 = 1e-35, far below
/// eps, leaving the round-off of pointBoxDistance.
inline Real segmentBoxDistance(const Vec& a, const Vec& b, const Vec& h) {
  Real lo = 0, hi = 1;
  for (int it = 0; it < 200; ++it) {
    const Real m1 = lo + (hi - lo) / 3, m2 = hi - (hi - lo) / 3;
    if (pointBoxDistance(a + m1 * (b - a), h) < pointBoxDistance(a + m2 * (b - a), h))
      hi = m2;
    else
      lo = m1;
  }
  return pointBoxDistance(a + (lo + hi) / 2 * (b - a), h);
}

/// The point of conv{w_0 .. w_{n-1}} (n <= 4) closest to the origin, with its barycentric
/// coordinates over the n input points: the answer GJK's simplex sub-algorithm (§2.2)
/// must give.
struct HullPoint {
  Vec point = Vec::Zero();                                 ///< the closest point
  Real distance = std::numeric_limits<Real>::infinity();  ///< |point|
  std::array<Real, 4> lambda{};                            ///< its barycentric coordinates
};

namespace detail {

/// Projection of the origin onto the affine hull of the points ids[0..K]: minimise
/// |w0 + A mu| with A = [w_j - w0], lambda = (1 - sum mu, mu); kept in `best` when every
/// lambda >= 0 and it is nearer. The point is rebuilt from lambda, so it lies in the hull.
template <int K>
void tryHullFeature(const std::array<Vec, 4>& w, const std::array<int, K + 1>& ids, HullPoint& best) {
  Eigen::Matrix<Real, 3, K> A;
  for (int j = 0; j < K; ++j) A.col(j) = w[ids[j + 1]] - w[ids[0]];
  const Eigen::Matrix<Real, K, 1> mu = A.colPivHouseholderQr().solve(Vec(-w[ids[0]]));
  if (!mu.allFinite()) return;
  std::array<Real, 4> lambda{};
  lambda[ids[0]] = Real(1) - mu.sum();
  for (int j = 0; j < K; ++j) lambda[ids[j + 1]] = mu[j];
  for (int k = 0; k < K + 1; ++k)
    if (lambda[ids[k]] < Real(0)) return;
  Vec p = Vec::Zero();
  for (int k = 0; k < K + 1; ++k) p += lambda[ids[k]] * w[ids[k]];
  const Real d = p.norm();
  if (d < best.distance) {
    best.distance = d;
    best.point = p;
    best.lambda = lambda;
  }
}

}  // namespace detail

/// The point of conv{w_0 .. w_{n-1}} (n <= 4) closest to the origin, by brute force over
/// every sub-simplex (vertex, edge, triangle, tetrahedron): the origin is projected onto
/// each one's affine hull by a least-squares solve and the nearest projection with all
/// barycentric coordinates >= 0 is kept.
///
/// Accuracy: the solve is a column-pivoted Householder QR, so a sliver costs its
/// condition number (not its square, as the normal equations would): the point is right
/// within about eps * cond * max |w_k| in long double, where GJK in double has eps(double)
/// * cond, 2^11 times more.
inline HullPoint closestToOrigin(const std::array<Vec, 4>& w, int n) {
  HullPoint best;
  for (int a = 0; a < n; ++a) {  // vertices: always feasible
    const Real d = w[a].norm();
    if (d < best.distance) {
      best = HullPoint{};
      best.distance = d;
      best.point = w[a];
      best.lambda[a] = Real(1);
    }
  }
  for (int a = 0; a < n; ++a)
    for (int b = a + 1; b < n; ++b) {
      detail::tryHullFeature<1>(w, {a, b}, best);
      for (int c = b + 1; c < n; ++c) {
        detail::tryHullFeature<2>(w, {a, b, c}, best);
        for (int d = c + 1; d < n; ++d) detail::tryHullFeature<3>(w, {a, b, c, d}, best);
      }
    }
  return best;
}

}  // namespace gjkx::reference
