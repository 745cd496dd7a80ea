/// @file
/// @brief Support mappings of the simple shapes: point, segment, triangle, box, sphere, capsule, cylinder (§2.1).
///
/// Each shape is given in its own body frame; `Placed` puts it at a pose. The support
/// mapping of each is a one-line formula, derived above it. Ties (a face or an edge
/// facing s exactly) are broken the same way every time, so results are reproducible.
#pragma once

#include <gjkx/support_mapping/support.hpp>

#include <algorithm>
#include <cmath>

namespace gjkx {

/// A single point \f$\{a\}\f$: \f$S(\vec{s}) = a\f$ for every s.
template <typename S>
struct Point {
  /// The scalar type.
  using Scalar = S;
  /// The point, in the body frame.
  Vector3<S> a = Vector3<S>::Zero();
  /// A point at `a` (checked finite).
  explicit Point(const Vector3<S>& a_ = Vector3<S>::Zero()) : a(a_) { requireFinite(a, "point.a"); }
  /// \f$S(\vec{s}) = a\f$.
  Vector3<S> support(const Vector3<S>& /*s*/) const { return a; }
  /// The point itself.
  Vector3<S> center() const { return a; }
  /// The largest distance of a point of the shape from the body origin (§3, certified margin).
  S boundingRadius() const { return a.norm(); }
};

/// The segment \f$[a, b]\f$: the end farther along s, \f$S(\vec{s}) = \vec{s}\cdot a \ge \vec{s}\cdot b\ ?\ a : b\f$.
template <typename S>
struct Segment {
  /// The scalar type.
  using Scalar = S;
  /// First end.
  Vector3<S> a;
  /// Second end.
  Vector3<S> b;
  /// The segment from `a` to `b` (ends checked finite; a = b is allowed and is a point).
  Segment(const Vector3<S>& a_, const Vector3<S>& b_) : a(a_), b(b_) {
    requireFinite(a, "segment.a");
    requireFinite(b, "segment.b");
  }
  /// The end farther along s (a on a tie).
  Vector3<S> support(const Vector3<S>& s) const { return s.dot(b) > s.dot(a) ? b : a; }
  /// The midpoint.
  Vector3<S> center() const { return (a + b) * S(0.5); }
  /// The largest distance of a point of the shape from the body origin (§3, certified margin).
  S boundingRadius() const { return std::max(a.norm(), b.norm()); }
};

/// The triangle with vertices a, b, c: the vertex with the largest \f$\vec{s}\cdot x\f$.
template <typename S>
struct Triangle {
  /// The scalar type.
  using Scalar = S;
  /// First vertex.
  Vector3<S> a;
  /// Second vertex.
  Vector3<S> b;
  /// Third vertex.
  Vector3<S> c;
  /// The triangle abc (vertices checked finite; a degenerate triangle is allowed).
  Triangle(const Vector3<S>& a_, const Vector3<S>& b_, const Vector3<S>& c_) : a(a_), b(b_), c(c_) {
    requireFinite(a, "triangle.a");
    requireFinite(b, "triangle.b");
    requireFinite(c, "triangle.c");
  }
  /// The vertex farthest along s (the first on a tie).
  Vector3<S> support(const Vector3<S>& s) const {
    const S da = s.dot(a), db = s.dot(b), dc = s.dot(c);
    if (db > da) return dc > db ? c : b;
    return dc > da ? c : a;
  }
  /// The centroid.
  Vector3<S> center() const { return (a + b + c) / S(3); }
  /// The largest distance of a point of the shape from the body origin (§3, certified margin).
  S boundingRadius() const { return std::max({a.norm(), b.norm(), c.norm()}); }
};

/// The box \f$[-h_x,h_x]\times[-h_y,h_y]\times[-h_z,h_z]\f$ centred on the body origin:
/// each coordinate of the support is \f$\pm h\f$ by the sign of s, \f$S(\vec{s})_k = \operatorname{sign}(s_k)\,h_k\f$.
template <typename S>
struct Box {
  /// The scalar type.
  using Scalar = S;
  /// Half the side lengths.
  Vector3<S> halfExtents;
  /// A box with the given half extents (each finite and not negative).
  explicit Box(const Vector3<S>& halfExtents_) : halfExtents(halfExtents_) {
    for (int k = 0; k < 3; ++k) requireNonNegative(halfExtents[k], "box.halfExtents[" + std::to_string(k) + "]");
  }
  /// The corner in the octant of s (+h on a zero component).
  Vector3<S> support(const Vector3<S>& s) const {
    return Vector3<S>(s.x() < S(0) ? -halfExtents.x() : halfExtents.x(),
                      s.y() < S(0) ? -halfExtents.y() : halfExtents.y(),
                      s.z() < S(0) ? -halfExtents.z() : halfExtents.z());
  }
  /// The body origin.
  Vector3<S> center() const { return Vector3<S>::Zero(); }
  /// The largest distance of a point of the shape from the body origin (§3, certified margin).
  S boundingRadius() const { return halfExtents.norm(); }
};

/// The ball of radius r about the body origin: \f$S(\vec{s}) = r\,\vec{s}/\lVert\vec{s}\rVert\f$.
template <typename S>
struct Sphere {
  /// The scalar type.
  using Scalar = S;
  /// The radius.
  S radius;
  /// A sphere of radius r (finite, not negative).
  explicit Sphere(S r) : radius(r) { requireNonNegative(radius, "sphere.radius"); }
  /// The point of the sphere in the direction s (the centre for s = 0).
  Vector3<S> support(const Vector3<S>& s) const {
    const S n = s.norm();
    return n > S(0) ? Vector3<S>(s * (radius / n)) : Vector3<S>::Zero();
  }
  /// The body origin.
  Vector3<S> center() const { return Vector3<S>::Zero(); }
  /// The largest distance of a point of the shape from the body origin (§3, certified margin).
  S boundingRadius() const { return radius; }
  /// A sphere is rounded (support.hpp, `IsRounded`): the point at the origin swept by a ball of this radius.
  S coreRadius() const { return radius; }
  /// The support of the core: the centre, whatever the direction.
  Vector3<S> coreSupport(const Vector3<S>& /*s*/, SupportHint& /*hint*/) const { return Vector3<S>::Zero(); }
  /// The core as a degenerate segment: the centre twice (support.hpp, `HasSegmentCore`).
  CoreEnds<S> coreEnds() const { return {Vector3<S>::Zero(), Vector3<S>::Zero()}; }
};

/// The capsule: all points within r of the segment [a, b]. Its support is the
/// segment's support plus the sphere's, \f$S(\vec{s}) = S_{[a,b]}(\vec{s}) + r\,\vec{s}/\lVert\vec{s}\rVert\f$
/// (the support mapping of a Minkowski sum is the sum of the support mappings).
template <typename S>
struct Capsule {
  /// The scalar type.
  using Scalar = S;
  /// The axis segment.
  Segment<S> axis;
  /// The radius.
  S radius;
  /// A capsule about the segment [a, b] of radius r (finite, not negative).
  Capsule(const Vector3<S>& a, const Vector3<S>& b, S r) : axis(checked(a, "capsule.a"), checked(b, "capsule.b")), radius(r) {
    requireNonNegative(radius, "capsule.radius");
  }
  /// The axis support plus the ball's.
  Vector3<S> support(const Vector3<S>& s) const {
    const S n = s.norm();
    const Vector3<S> end = axis.support(s);
    return n > S(0) ? Vector3<S>(end + s * (radius / n)) : end;
  }
  /// The midpoint of the axis.
  Vector3<S> center() const { return axis.center(); }
  /// The largest distance of a point of the shape from the body origin (§3, certified margin).
  S boundingRadius() const { return axis.boundingRadius() + radius; }
  /// A capsule is rounded (support.hpp, `IsRounded`): its axis swept by a ball of this radius.
  S coreRadius() const { return radius; }
  /// The support of the core: the axis segment's.
  Vector3<S> coreSupport(const Vector3<S>& s, SupportHint& /*hint*/) const { return axis.support(s); }
  /// The core: the axis segment (support.hpp, `HasSegmentCore`).
  CoreEnds<S> coreEnds() const { return {axis.a, axis.b}; }

 private:
  static const Vector3<S>& checked(const Vector3<S>& end, const char* field) {
    requireFinite(end, field);
    return end;
  }
};

/// The cylinder of radius r about the body's z axis, from z = -h to z = h (§2.1).
///
/// Derivation. The cylinder is the Minkowski sum of the disc \f$D = \{(x, y, 0) : x^2 + y^2
/// \le r^2\}\f$ and the segment \f$[-h\hat{z}, h\hat{z}]\f$, so its support is the sum of
/// theirs (the support mapping of a Minkowski sum is the sum of the support mappings). The
/// disc's: \f$\vec{s}\cdot x = s_x x + s_y y\f$ over the disc is largest on its rim in the
/// direction of \f$\vec{s}_{xy} = (s_x, s_y, 0)\f$, at \f$r\,\vec{s}_{xy}/\lVert\vec{s}_{xy}\rVert\f$
/// (when \f$\vec{s}_{xy} = 0\f$ every point of the disc ties; we take its centre). The
/// segment's: the end on the side of \f$s_z\f$ (the top on a tie, as the box takes +h).
/// So \f$S(\vec{s}) = r\,\vec{s}_{xy}/\lVert\vec{s}_{xy}\rVert + \operatorname{sign}(s_z)\,h\,\hat{z}\f$:
/// a point of the top or bottom rim, or the centre of a cap when s is along the axis.
/// (Unlike the capsule, the cylinder is no core swept by a ball: its caps are flat and its
/// rims sharp, so GJK meets it as it meets any curved shape, support point by support point.)
template <typename S>
struct Cylinder {
  /// The scalar type.
  using Scalar = S;
  /// The radius r of its circular cross-section.
  S radius;
  /// Half its length along z, h.
  S halfLength;
  /// A cylinder of radius r and half length h about the body's z axis (each finite, not negative).
  Cylinder(S r, S h) : radius(r), halfLength(h) {
    requireNonNegative(radius, "cylinder.radius");
    requireNonNegative(halfLength, "cylinder.halfLength");
  }
  /// The disc's support plus the segment's: a rim point, or a cap's centre for s along z.
  Vector3<S> support(const Vector3<S>& s) const {
    const S across = std::hypot(s.x(), s.y());  // \f$\lVert\vec{s}_{xy}\rVert\f$, without overflow
    const S z = s.z() < S(0) ? -halfLength : halfLength;
    if (!(across > S(0))) return Vector3<S>(S(0), S(0), z);
    return Vector3<S>(s.x() * (radius / across), s.y() * (radius / across), z);
  }
  /// The body origin (the middle of the axis).
  Vector3<S> center() const { return Vector3<S>::Zero(); }
  /// The largest distance of a point of the shape from the body origin (§3, certified
  /// margin): a point of a rim, \f$\sqrt{r^2 + h^2}\f$.
  S boundingRadius() const { return std::hypot(radius, halfLength); }
};

}  // namespace gjkx
