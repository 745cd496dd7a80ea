/// @file
/// @brief The simplex V_Z = V_Q - V_P and its closest feature to the origin, by signed volumes (§2.2).
///
/// §2.2: "calculate the feature of the Minkowski sum \f$V_Z = V_Q - V_P\f$ [...] which is
/// closest to the origin. Refine \f$V_Z\f$ to contain only this feature, and since it must
/// be either a vertex, edge, or triangle (in 3D), \f$V_P\f$ and \f$V_Q\f$ will always contain
/// three vertices or less."
///
/// This is GJK's *sub-algorithm*. We use the signed-volume method of Montanari,
/// Petrinic and Barbieri (ACM TOG 2017): instead of Johnson's Voronoi-region tests, it
/// writes the origin's projection in barycentric coordinates of the simplex, each
/// coordinate a ratio of signed volumes (lengths, areas, volumes) measured in the
/// axis-aligned projection where the simplex is largest. A coordinate whose sign
/// differs from the whole simplex's volume means the closest point lies on the facet
/// opposite that vertex, so only those facets are searched. When the simplex is
/// degenerate (collinear triangle, flat tetrahedron) its volume is zero, no sign
/// agrees, and every facet is searched: the method stays correct exactly where
/// Johnson's loses precision.
#pragma once

#include <gjkx/motion/vector.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace gjkx {

/// One vertex of the simplex: a point \f$w = q - p\f$ of \f$V_Z\f$ with the support
/// points it came from (\f$p \in V_P\f$, \f$q \in V_Q\f$) and the direction that found them.
template <typename S>
struct SimplexVertex {
  /// \f$S_P(\vec{s})\f$, a vertex of \f$V_P\f$.
  Vector3<S> p;
  /// \f$S_Q(-\vec{s})\f$, a vertex of \f$V_Q\f$.
  Vector3<S> q;
  /// \f$w = q - p\f$, a vertex of \f$V_Z = V_Q - V_P\f$.
  Vector3<S> w;
  /// The direction \f$\vec{s}\f$ that found p and q (a warm start asks it again).
  Vector3<S> s;
  /// Hill-climbing hint of P's search (the polytope vertex found).
  int hintP = 0;
  /// Hill-climbing hint of Q's search.
  int hintQ = 0;
};

/// The simplex \f$V_Z\f$ (1 to 4 vertices) and the barycentric coordinates of its
/// point closest to the origin, \f$z = \sum_k \lambda_k w_k\f$.
template <typename S>
struct Simplex {
  /// The vertices; only the first `size` are used.
  std::array<SimplexVertex<S>, 4> vertices;
  /// Barycentric coordinates of z (positive, summing to 1) for the first `size` vertices.
  std::array<S, 4> lambda{};
  /// Number of vertices in use (0 to 4).
  int size = 0;

  /// z, the point of the simplex closest to the origin.
  Vector3<S> closestPoint() const {
    Vector3<S> z = Vector3<S>::Zero();
    for (int k = 0; k < size; ++k) z += lambda[k] * vertices[k].w;
    return z;
  }
  /// The witness point on P, \f$\sum_k \lambda_k p_k\f$.
  Vector3<S> witnessP() const {
    Vector3<S> x = Vector3<S>::Zero();
    for (int k = 0; k < size; ++k) x += lambda[k] * vertices[k].p;
    return x;
  }
  /// The witness point on Q, \f$\sum_k \lambda_k q_k\f$.
  Vector3<S> witnessQ() const {
    Vector3<S> x = Vector3<S>::Zero();
    for (int k = 0; k < size; ++k) x += lambda[k] * vertices[k].q;
    return x;
  }
  /// Appends a vertex (the caller makes sure there is room).
  void push(const SimplexVertex<S>& v) { vertices[size++] = v; }
  /// Becomes a copy of `other` in everything that is used: its first `other.size`
  /// vertices and coordinates. (Speed: GJK saves and restores its simplex every
  /// iteration; a plain copy would also move the unused slots, four vertices in all.)
  void assignUsed(const Simplex& other) {
    for (int k = 0; k < other.size; ++k) {
      vertices[k] = other.vertices[k];
      lambda[k] = other.lambda[k];
    }
    size = other.size;
  }
};

namespace detail {

/// The closest feature found by a signed-volume test: which input vertices it keeps
/// (bit k set for vertex k) and their barycentric coordinates.
template <typename S>
struct Feature {
  unsigned keep = 0;
  std::array<S, 4> lambda{};
  S distanceSquared = std::numeric_limits<S>::infinity();
};

/// True when a and b are both strictly positive or both strictly negative.
/// A zero never agrees: that is what sends degenerate simplices to their facets.
template <typename S>
bool sameSign(S a, S b) {
  return (a > S(0) && b > S(0)) || (a < S(0) && b < S(0));
}

/// When may the signs be trusted? A volume within round-off of zero has signs that are
/// noise. Rounding
/// leaves a nearly collinear triangle or a nearly flat tetrahedron with a tiny volume
/// of either sign; the sub-volumes may then all "agree" by chance, and the interior
/// answer is a point of the simplex far from the closest one (needle tetrahedra 0.01
/// from the origin were reported as containing it). Each signed volume is good to
/// about \f$\epsilon\f$ times a product of lengths (triangle: its longest edge times its
/// farthest vertex from the origin; tetrahedron: the farthest vertex cubed), so the
/// barycentric coordinates are good to \f$\epsilon / r\f$, r the volume relative to that
/// product. Below \f$r = \epsilon^{1/4}\f$ (where they would be good only to
/// \f$\epsilon^{3/4}\f$, GJK's own tolerance) the signs are not trusted: every facet is
/// searched, and the interior answer, if any, is kept only when it is nearer. Every
/// candidate is a point of the simplex, so the nearest of them is never worse than any.
template <typename S>
S trustedVolumeRatio() {
  return std::pow(std::numeric_limits<S>::epsilon(), S(0.25));
}

template <typename S>
Feature<S> vertexFeature(const std::array<Vector3<S>, 4>& w, int a) {
  Feature<S> f;
  f.keep = 1u << a;
  f.lambda[a] = S(1);
  f.distanceSquared = w[a].squaredNorm();
  return f;
}

template <typename S>
S distanceSquaredOf(const std::array<Vector3<S>, 4>& w, const Feature<S>& f) {
  Vector3<S> z = Vector3<S>::Zero();
  for (int k = 0; k < 4; ++k)
    if (f.keep & (1u << k)) z += f.lambda[k] * w[k];
  return z.squaredNorm();
}

/// Segment [A, B] (Montanari's S1D). The origin projects onto the line at p0; measured
/// along the axis I where B - A is longest, \f$\lambda_A = (B_I - p0_I)/(B_I - A_I)\f$
/// and \f$\lambda_B = (p0_I - A_I)/(B_I - A_I)\f$. Both agree in sign with \f$B_I - A_I\f$
/// exactly when p0 lies inside the segment; otherwise the closest point is an end.
template <typename S>
Feature<S> segment(const std::array<Vector3<S>, 4>& w, int a, int b) {
  const Vector3<S> t = w[b] - w[a];
  const S tt = t.squaredNorm();
  if (!(tt > S(0))) return vertexFeature(w, a);  // coincident ends: a point
  const Vector3<S> p0 = w[a] - t * (w[a].dot(t) / tt);
  int I = 0;
  t.cwiseAbs().maxCoeff(&I);
  const S muMax = w[b][I] - w[a][I];
  const S cA = w[b][I] - p0[I];
  const S cB = p0[I] - w[a][I];
  if (sameSign(muMax, cA) && sameSign(muMax, cB)) {
    Feature<S> f;
    f.keep = (1u << a) | (1u << b);
    f.lambda[a] = cA / muMax;
    f.lambda[b] = cB / muMax;
    f.distanceSquared = distanceSquaredOf(w, f);
    return f;
  }
  // p0 is beyond one end: if it is before A (cB disagrees) the closest point is A.
  return sameSign(muMax, cB) ? vertexFeature(w, b) : vertexFeature(w, a);
}

/// Twice the signed area of the 2D triangle (p, q, r) in the coordinates (x, y).
template <typename S>
S area2(const Vector3<S>& p, const Vector3<S>& q, const Vector3<S>& r, int x, int y) {
  return (q[x] - p[x]) * (r[y] - p[y]) - (q[y] - p[y]) * (r[x] - p[x]);
}

/// Triangle ABC (Montanari's S2D). Project the origin onto the plane at p0, then drop
/// the coordinate I where the normal n is largest: the triangle's projected area is
/// \f$n_I\f$, and the area with vertex k replaced by p0 is \f$C_k\f$, so \f$\lambda_k = C_k / n_I\f$.
/// Where \f$C_k\f$ disagrees with \f$n_I\f$, search the edge opposite k.
template <typename S>
Feature<S> triangle(const std::array<Vector3<S>, 4>& w, int a, int b, int c) {
  const Vector3<S> n = (w[b] - w[a]).cross(w[c] - w[a]);
  const S nn = n.squaredNorm();
  // Is the area |n| well above its round-off, about epsilon * (longest edge) *
  // (farthest vertex from the origin)? If not, its signs are noise (trustedVolumeRatio).
  const S edge2 = std::max({(w[b] - w[a]).squaredNorm(), (w[c] - w[a]).squaredNorm(), (w[c] - w[b]).squaredNorm()});
  const S far2 = std::max({w[a].squaredNorm(), w[b].squaredNorm(), w[c].squaredNorm()});
  const S ratio = trustedVolumeRatio<S>();
  const bool noisy = !(nn > ratio * ratio * edge2 * far2);
  Feature<S> best;
  std::array<S, 3> C{S(0), S(0), S(0)};
  S muMax = S(0);
  if (nn > S(0)) {
    const Vector3<S> p0 = n * (w[a].dot(n) / nn);
    int I = 0;
    n.cwiseAbs().maxCoeff(&I);
    const int x = (I + 1) % 3, y = (I + 2) % 3;  // cyclic, so the projected area is +n_I
    muMax = n[I];
    C[0] = area2(p0, w[b], w[c], x, y);
    C[1] = area2(w[a], p0, w[c], x, y);
    C[2] = area2(w[a], w[b], p0, x, y);
    if (sameSign(muMax, C[0]) && sameSign(muMax, C[1]) && sameSign(muMax, C[2])) {
      Feature<S> f;
      f.keep = (1u << a) | (1u << b) | (1u << c);
      // Divide by the sum of the C_k (equal to n_I in exact arithmetic), so the lambda
      // sum to 1 even when round-off has spoilt the C_k: z stays in the triangle.
      const S sumC = C[0] + C[1] + C[2];
      f.lambda[a] = C[0] / sumC;
      f.lambda[b] = C[1] / sumC;
      f.lambda[c] = C[2] / sumC;
      f.distanceSquared = distanceSquaredOf(w, f);
      if (!noisy) return f;
      best = f;  // a noisy interior answer is only a candidate: an edge may be nearer
    }
  }
  // The closest point is on an edge: search the edges opposite the disagreeing vertices
  // (all three for a degenerate triangle, where muMax = 0, or a noisy one).
  const std::array<int, 3> ids{a, b, c};
  for (int k = 0; k < 3; ++k) {
    if (!noisy && sameSign(muMax, C[k])) continue;
    const Feature<S> f = segment(w, ids[(k + 1) % 3], ids[(k + 2) % 3]);
    if (f.distanceSquared < best.distanceSquared) best = f;
  }
  return best;
}

/// Signed volume (times 6) of the tetrahedron (p, q, r, u).
template <typename S>
S volume6(const Vector3<S>& p, const Vector3<S>& q, const Vector3<S>& r, const Vector3<S>& u) {
  return (q - p).dot((r - p).cross(u - p));
}

/// Tetrahedron ABCD (Montanari's S3D). \f$C_k\f$ is the signed volume with vertex k
/// replaced by the origin; their sum is the whole volume. All agree in sign: the origin
/// is inside (distance 0). Otherwise search the faces opposite the disagreeing vertices.
template <typename S>
Feature<S> tetrahedron(const std::array<Vector3<S>, 4>& w) {
  const Vector3<S> o = Vector3<S>::Zero();
  const std::array<S, 4> C{volume6(o, w[1], w[2], w[3]), volume6(w[0], o, w[2], w[3]),
                           volume6(w[0], w[1], o, w[3]), volume6(w[0], w[1], w[2], o)};
  const S detM = C[0] + C[1] + C[2] + C[3];
  // The C_k are triple products of the w_k, good to about epsilon * (farthest vertex)^3;
  // a volume not well above that is noise (trustedVolumeRatio).
  S far2 = S(0);
  for (int k = 0; k < 4; ++k) far2 = std::max(far2, w[k].squaredNorm());
  const bool noisy = !(std::abs(detM) > trustedVolumeRatio<S>() * far2 * std::sqrt(far2));
  Feature<S> best;
  if (sameSign(detM, C[0]) && sameSign(detM, C[1]) && sameSign(detM, C[2]) && sameSign(detM, C[3])) {
    Feature<S> f;
    f.keep = 0xFu;
    for (int k = 0; k < 4; ++k) f.lambda[k] = C[k] / detM;
    f.distanceSquared = S(0);
    if (!noisy) return f;
    f.distanceSquared = distanceSquaredOf(w, f);  // a noisy "inside" is only a candidate
    best = f;
  }
  for (int k = 0; k < 4; ++k) {
    if (!noisy && sameSign(detM, C[k])) continue;  // a noisy tetrahedron searches every face
    const Feature<S> f = triangle(w, (k + 1) % 4, (k + 2) % 4, (k + 3) % 4);
    if (f.distanceSquared < best.distanceSquared) best = f;
  }
  return best;
}

}  // namespace detail

/// Refines the simplex to its feature closest to the origin (§2.2), setting
/// `simplex.lambda` so that `simplex.closestPoint()` is that point z. Vertices not in
/// the feature are dropped; the order of those kept is preserved.
template <typename S>
void reduceToClosestFeature(Simplex<S>& simplex) {
  std::array<Vector3<S>, 4> w;
  for (int k = 0; k < simplex.size; ++k) w[k] = simplex.vertices[k].w;
  detail::Feature<S> f;
  switch (simplex.size) {
    case 1: f = detail::vertexFeature(w, 0); break;
    case 2: f = detail::segment(w, 0, 1); break;
    case 3: f = detail::triangle(w, 0, 1, 2); break;
    case 4: f = detail::tetrahedron(w); break;
    default: return;
  }
  int kept = 0;
  for (int k = 0; k < simplex.size; ++k) {
    if (!(f.keep & (1u << k))) continue;
    simplex.vertices[kept] = simplex.vertices[k];
    simplex.lambda[kept] = f.lambda[k];
    ++kept;
  }
  simplex.size = kept;
}

}  // namespace gjkx
