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

#include <gjkx/motion/round_off.hpp>
#include <gjkx/motion/vector.hpp>

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>
#include <cmath>
#include <initializer_list>
#include <limits>
#include <type_traits>

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

/// The simplex \f$V_Z\f$ (1 to 4 vertices), its point z closest to the origin and the
/// barycentric coordinates of z, \f$z = \sum_k \lambda_k w_k\f$.
template <typename S>
struct Simplex {
  /// The vertices; only the first `size` are used.
  std::array<SimplexVertex<S>, 4> vertices;
  /// Barycentric coordinates of z (positive, summing to 1) for the first `size` vertices.
  std::array<S, 4> lambda{};
  /// z, the point of the simplex closest to the origin, as `reduceToClosestFeature` found it.
  Vector3<S> z = Vector3<S>::Zero();
  /// Number of vertices in use (0 to 4).
  int size = 0;

  /// z, the point of the simplex closest to the origin (set by `reduceToClosestFeature`).
  /// It is computed directly as the projection of the origin onto the closest feature,
  /// not as \f$\sum_k \lambda_k w_k\f$: on a sliver feature far from the origin that sum
  /// cancels to a point whose *direction* is off by far more than its length (see
  /// `detail::triangle`), and GJK's next direction is this z.
  const Vector3<S>& closestPoint() const { return z; }
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
  /// vertices and coordinates, and z. (Speed: GJK saves and restores its simplex every
  /// iteration; a plain copy would also move the unused slots, four vertices in all.)
  void assignUsed(const Simplex& other) {
    for (int k = 0; k < other.size; ++k) {
      vertices[k] = other.vertices[k];
      lambda[k] = other.lambda[k];
    }
    z = other.z;
    size = other.size;
  }
};

namespace detail {

/// The vertices the sub-algorithm works on.
template <typename S>
using Vertices = std::array<SimplexVertex<S>, 4>;

/// The closest feature found by a signed-volume test: which input vertices it keeps
/// (bit k set for vertex k), their barycentric coordinates, and the closest point z.
template <typename S>
struct Feature {
  unsigned keep = 0;
  std::array<S, 4> lambda{};
  Vector3<S> z = Vector3<S>::Zero();
  S distanceSquared = std::numeric_limits<S>::infinity();
};

/// True when a and b are both strictly positive or both strictly negative.
/// A zero never agrees: that is what sends degenerate simplices to their facets.
template <typename S>
bool sameSign(S a, S b) {
  return (a > S(0) && b > S(0)) || (a < S(0) && b < S(0));
}

// When may a sign be trusted? Each signed volume below is computed with a known
// round-off: about epsilon times the lengths it multiplies. A value within a few
// times that bound of zero has a sign that is noise: rounding can make a nearly
// collinear triangle or a nearly flat tetrahedron "contain" the origin by chance, and
// the interior answer is then a point of the simplex far from the closest one (needle
// tetrahedra 0.01 from the origin were reported as containing it). A feature whose sign
// is not trusted is searched as if it disagreed, and the interior answer, if any, is
// kept only when it is nearer: every candidate is a point of the simplex, so the
// nearest of them is never worse than any. The safety factor on the bound is
// signSafety() (64 epsilon, round_off.hpp).

/// The edge \f$w_b - w_a\f$, computed from the support points as \f$(q_b - q_a) - (p_b - p_a)\f$.
/// Each \f$w = q - p\f$ is rounded by \f$\epsilon\lVert w\rVert\f$; when P is large and far
/// (a long rod) and two vertices share their p, \f$w_b - w_a\f$ would carry that rounding
/// into an edge much shorter than \f$\lVert w\rVert\f$, while \f$q_b - q_a\f$ is exact.
template <typename S>
Vector3<S> edge(const Vertices<S>& v, int a, int b) {
  return (v[b].q - v[a].q) - (v[b].p - v[a].p);
}

/// \f$2^{-e}\f$ for \f$x \in [2^e, 2^{e+1})\f$: the power of two that brings x into [1, 2),
/// or 1 for zero, subnormal, infinite and NaN x. Read from the exponent bits of a float or
/// double (speed: `std::ldexp(1, -std::ilogb(x))` costs two library calls, about 3% of a
/// cold GJK distance query on 100-vertex polytopes, and this runs at every sub-algorithm call).
template <typename S>
S unitsFor(S x) {
  if constexpr (std::is_same_v<S, double> || std::is_same_v<S, float>) {
    using Bits = std::conditional_t<std::is_same_v<S, double>, std::uint64_t, std::uint32_t>;
    constexpr int mantissa = std::numeric_limits<S>::digits - 1;           // 52 or 23
    constexpr Bits exponentMask = (Bits(1) << (sizeof(S) * 8 - 1 - mantissa)) - 1;  // 0x7FF or 0xFF
    Bits bits;
    std::memcpy(&bits, &x, sizeof bits);
    const Bits biased = (bits >> mantissa) & exponentMask;
    if (biased == 0 || biased == exponentMask) return S(1);  // zero, subnormal, inf, NaN
    // x = 2^(biased - bias) * 1.m, bias = mask / 2; 2^-(biased - bias) has biased
    // exponent 2 bias - biased = mask - 1 - biased, in [1, mask - 1] for normal x.
    const Bits inverse = (exponentMask - 1 - biased) << mantissa;
    S out;
    std::memcpy(&out, &inverse, sizeof out);
    return inverse == 0 ? S(1) : out;
  } else {
    if (!(x > S(0)) || !(x < std::numeric_limits<S>::infinity())) return S(1);
    return std::ldexp(S(1), -std::ilogb(x));
  }
}

/// What the sub-algorithm measures once per call and reads many times (speed: a
/// tetrahedron's faces share their edges): each vertex's w and \f$\lVert w\rVert^2\f$, and
/// every edge (`edge`, from the support points) with its squared length, all in units
/// where the largest coordinate of a w is in [1, 2).
///
/// Why the units. The signs below are trusted by comparing products of up to six lengths
/// (a squared height against squared edges times a squared length); in float, on shapes
/// 1e-8 across, those are 1e-48 and underflow to zero, and a tetrahedron 1.7e-3 (relative)
/// around the origin was taken for flat and the origin left outside (a fuzz finding; its
/// twin overflows on coordinates of 1e7). Scaling by a power of two is exact, so the
/// answers at ordinary scales do not change; z is scaled back by `reduceToClosestFeature`.
template <typename S>
struct Geometry {
  /// The vertices (their p and q give the edges).
  const Vertices<S>& v;
  /// The units: each w here is the vertex's w times `scale`, a power of two.
  S scale = S(1);
  /// \f$w_k\f$, in these units.
  std::array<Vector3<S>, 4> w;
  /// \f$\lVert w_k\rVert^2\f$.
  std::array<S, 4> w2{};
  /// \f$w_b - w_a\f$ for a < b, at `pair(a, b)`.
  std::array<Vector3<S>, 6> edges;
  /// Their squared lengths.
  std::array<S, 6> edges2{};
  /// Measures the first `size` vertices.
  Geometry(const Vertices<S>& vertices, int size) : v(vertices) {
    S largest = S(0);
    for (int k = 0; k < size; ++k) largest = std::max(largest, v[k].w.cwiseAbs().maxCoeff());
    scale = unitsFor(largest);
    for (int k = 0; k < size; ++k) {
      w[k] = v[k].w * scale;
      w2[k] = w[k].squaredNorm();
    }
    for (int a = 0; a < size; ++a)
      for (int b = a + 1; b < size; ++b) {
        edges[pair(a, b)] = detail::edge(v, a, b) * scale;
        edges2[pair(a, b)] = edges[pair(a, b)].squaredNorm();
      }
  }
  /// The slot of edge (a, b), a < b: (0,1) (0,2) (0,3) (1,2) (1,3) (2,3).
  static int pair(int a, int b) { return a == 0 ? b - 1 : (a == 1 ? b + 1 : 5); }
  /// \f$w_b - w_a\f$.
  Vector3<S> edge(int a, int b) const { return a < b ? edges[pair(a, b)] : Vector3<S>(-edges[pair(b, a)]); }
  /// \f$\lVert w_b - w_a\rVert^2\f$.
  S edge2(int a, int b) const { return a < b ? edges2[pair(a, b)] : edges2[pair(b, a)]; }
};

template <typename S>
Feature<S> vertexFeature(const Geometry<S>& g, int a) {
  Feature<S> f;
  f.keep = 1u << a;
  f.lambda[a] = S(1);
  f.z = g.w[a];
  f.distanceSquared = g.w2[a];
  return f;
}

/// Segment [A, B] (Montanari's S1D). The origin projects onto the line at
/// \f$p_0 = t \times (w_o \times t) / (t\cdot t)\f$, t = B - A, w_o the end nearer the origin
/// (its rounding is the smaller): the part of \f$w_o\f$ across t. The textbook
/// \f$w_o - t\,(w_o\cdot t)/(t\cdot t)\f$ is the same point, but along a long t it subtracts
/// two numbers of the size of \f$w_o\f$ and keeps only \f$\epsilon\lVert w_o\rVert\f$ of
/// the component along t; the triple product gets every component to its own relative
/// precision. That component matters: on a rod 2e5 long and 1.5e-5 from the origin, the
/// true p0 has 1e-14 along the rod, and the supporting distance along p0 multiplies it by
/// 1e5 (an error of 1e-11 there turned SD from 1.5e-5 into -3.7e-5). Measured along the axis I where t is longest,
/// \f$\lambda_A = (B_I - p0_I)/t_I\f$ and \f$\lambda_B = (p0_I - A_I)/t_I\f$. Both agree in sign
/// with \f$t_I\f$ exactly when p0 lies inside the segment; otherwise the closest point is an end.
template <typename S>
Feature<S> segment(const Geometry<S>& g, int a, int b) {
  const Vector3<S> t = g.edge(a, b);
  const S tt = g.edge2(a, b);
  if (!(tt > S(0))) return vertexFeature(g, a);  // coincident ends: a point
  const Vector3<S>& wo = g.w2[a] <= g.w2[b] ? g.w[a] : g.w[b];
  const Vector3<S> p0 = t.cross(wo.cross(t)) / tt;
  int I = 0;
  t.cwiseAbs().maxCoeff(&I);
  const S muMax = t[I];
  const S cA = g.w[b][I] - p0[I];
  const S cB = p0[I] - g.w[a][I];
  if (sameSign(muMax, cA) && sameSign(muMax, cB)) {
    Feature<S> f;
    f.keep = (1u << a) | (1u << b);
    f.lambda[a] = cA / (cA + cB);
    f.lambda[b] = cB / (cA + cB);
    f.z = p0;
    f.distanceSquared = p0.squaredNorm();
    return f;
  }
  // p0 is beyond one end: if it is before A (cB disagrees) the closest point is A.
  return sameSign(muMax, cB) ? vertexFeature(g, b) : vertexFeature(g, a);
}

/// Twice the signed area of the 2D parallelogram (u, v) in the coordinates (x, y).
template <typename S>
S cross2(const Vector3<S>& u, const Vector3<S>& v, int x, int y) {
  return u[x] * v[y] - u[y] * v[x];
}

/// The normal \f$(B - A) \times (C - A)\f$ of a triangle, and the squared product of the
/// two edge lengths it was computed from (the scale of its round-off, squared).
template <typename S>
struct TriangleNormal {
  Vector3<S> n;
  S scale2;
};

/// The normal of triangle ABC from the two edges at its largest angle (opposite its
/// longest edge): on a needle every other pair is nearly parallel and their cross
/// product is mostly round-off. All three choices are \f$(B - A) \times (C - A)\f$ exactly.
template <typename S>
TriangleNormal<S> normalOf(const Geometry<S>& g, int a, int b, int c) {
  const Vector3<S> eab = g.edge(a, b), eac = g.edge(a, c), ebc = g.edge(b, c);
  const S lab = g.edge2(a, b), lac = g.edge2(a, c), lbc = g.edge2(b, c);
  if (lbc >= lab && lbc >= lac) return {eab.cross(eac), lab * lac};
  if (lac >= lab) return {eab.cross(ebc), lab * lbc};
  return {eac.cross(ebc), lac * lbc};
}

/// The vertex of the list nearest the origin (its w has the smallest rounding).
template <typename S>
int nearestOf(const Geometry<S>& g, std::initializer_list<int> ids) {
  int best = *ids.begin();
  for (int k : ids)
    if (g.w2[k] < g.w2[best]) best = k;
  return best;
}

/// Triangle ABC (Montanari's S2D). Project the origin onto the plane at p0, then drop
/// the coordinate I where the normal n is largest: the triangle's projected area is
/// \f$n_I\f$, and the area with vertex k replaced by p0 is \f$C_k\f$, so \f$\lambda_k = C_k / n_I\f$.
/// Where \f$C_k\f$ disagrees with \f$n_I\f$ (or its sign is not trusted, `signSafety`),
/// search the edge opposite k.
///
/// Accuracy on slivers. GJK's next direction is z, and the supporting distance along it
/// is measured across the whole of \f$V_Q - V_P\f$: a direction error \f$\delta\f$ costs up to
/// \f$\delta\,\mathrm{diam}(V_Q - V_P)\f$ there, and GJK stalls when that exceeds the gap
/// it is closing. A rod 3464 long through a box 2e-4 wide makes triangles of exactly
/// that kind; three choices keep their z accurate:
/// - the edges come from the support points (`edge`), not from the rounded w;
/// - n comes from the two edges at the largest angle (`normalOf`);
/// - z is the projection p0 itself, from the vertex nearest the origin. Rebuilt as
///   \f$\sum_k \lambda_k w_k\f$ it would carry the \f$\lambda_k\f$'s round-off times
///   \f$\lVert w_k\rVert\f$, 1732 on that rod against a distance of 6e-6: its length
///   stayed right, its direction was off by 3%.
/// Each \f$C_k\f$ is the opposite edge crossed with p0 minus that edge's start, so it too
/// multiplies one accurate edge by one rounded vector.
template <typename S>
Feature<S> triangle(const Geometry<S>& g, int a, int b, int c, const TriangleNormal<S>* known = nullptr) {
  const TriangleNormal<S> tn = known ? *known : normalOf(g, a, b, c);  // a tetrahedron passes its face's
  const Vector3<S>& n = tn.n;
  Feature<S> best;
  std::array<S, 3> C{S(0), S(0), S(0)};
  std::array<bool, 3> trusted{false, false, false};
  S muMax = S(0);
  int I = 0;
  n.cwiseAbs().maxCoeff(&I);
  constexpr S safety2 = signSafety<S>() * signSafety<S>();
  if (n[I] * n[I] > safety2 * tn.scale2) {  // else degenerate: search every edge
    const Vector3<S>& wo = g.w[nearestOf(g, {a, b, c})];
    // The projection along n in n's own units (a power of two, exact): a triangle tiny
    // against its distance from the origin has a tiny n, and in float \f$n\cdot n\f$ fell
    // into the subnormals and lost its digits (a fuzz finding: a triangle 5e-5 across at
    // 7.5e5 was put 31% nearer the origin than it is). Bit for bit the same otherwise.
    const Vector3<S> m = n * unitsFor(n.cwiseAbs().maxCoeff());
    const Vector3<S> p0 = m * (wo.dot(m) / m.squaredNorm());
    const int x = (I + 1) % 3, y = (I + 2) % 3;  // cyclic, so the projected area is +n_I
    muMax = n[I];
    const std::array<int, 3> ids{a, b, c};
    for (int k = 0; k < 3; ++k) {
      const int from = ids[(k + 1) % 3], to = ids[(k + 2) % 3];
      const Vector3<S> e = g.edge(from, to), d = p0 - g.w[from];
      C[k] = cross2(e, d, x, y);  // area (from, to, p0): vertex k replaced by p0
      // |C_k| above its round-off, eps |e| (|p0| + |w_from|) (compared squared, with
      // (a + b)^2 <= 2 (a^2 + b^2), to save the square roots).
      trusted[k] = C[k] * C[k] > safety2 * g.edge2(from, to) * S(2) * (p0.squaredNorm() + g.w2[from]);
    }
    if (sameSign(muMax, C[0]) && sameSign(muMax, C[1]) && sameSign(muMax, C[2])) {
      Feature<S> f;
      f.keep = (1u << a) | (1u << b) | (1u << c);
      // Divide by the sum of the C_k (equal to n_I in exact arithmetic), so the lambda
      // sum to 1 even when round-off has spoilt the C_k: the witnesses stay in the triangle.
      const S sumC = C[0] + C[1] + C[2];
      f.lambda[a] = C[0] / sumC;
      f.lambda[b] = C[1] / sumC;
      f.lambda[c] = C[2] / sumC;
      f.z = p0;
      f.distanceSquared = p0.squaredNorm();
      if (trusted[0] && trusted[1] && trusted[2]) return f;
      best = f;  // an untrusted interior answer is only a candidate: an edge may be nearer
    }
  }
  // The closest point is on an edge: search the edges opposite the disagreeing vertices
  // and those whose sign is not trusted (all three for a degenerate triangle).
  const std::array<int, 3> ids{a, b, c};
  for (int k = 0; k < 3; ++k) {
    if (trusted[k] && sameSign(muMax, C[k])) continue;
    const Feature<S> f = segment(g, ids[(k + 1) % 3], ids[(k + 2) % 3]);
    if (f.distanceSquared < best.distanceSquared) best = f;
  }
  return best;
}

/// Tetrahedron ABCD (Montanari's S3D). The barycentric coordinate of the origin for
/// vertex k is its height over the opposite face divided by vertex k's height over it:
/// \f$\lambda_k = n_k\cdot(0 - w_o) / n_k\cdot(w_k - w_o)\f$, \f$n_k\f$ that face's normal and
/// \f$w_o\f$ its vertex nearest the origin (the ratio of signed volumes of Montanari et al.,
/// each computed from its own face, so that a sliver tetrahedron keeps the accuracy the
/// triangle test has). All positive: the origin is inside (distance 0). Otherwise search
/// the faces whose coordinate is negative or not trusted.
template <typename S>
Feature<S> tetrahedron(const Geometry<S>& g) {
  constexpr S safety2 = signSafety<S>() * signSafety<S>();
  std::array<S, 4> C{}, D{};
  std::array<bool, 4> trusted{};
  std::array<TriangleNormal<S>, 4> normals;
  bool flat = false;  // a vertex within round-off of its opposite face: no sign is trusted
  for (int k = 0; k < 4; ++k) {
    const int f0 = (k + 1) % 4, f1 = (k + 2) % 4, f2 = (k + 3) % 4;
    const TriangleNormal<S>& tn = normals[k] = normalOf(g, f0, f1, f2);
    const int o = nearestOf(g, {f0, f1, f2});
    const Vector3<S> h = g.edge(o, k);
    C[k] = -tn.n.dot(g.w[o]);  // the origin's height over face k, times |n_k|
    D[k] = tn.n.dot(h);        // vertex k's height over face k, times |n_k|
    // Each above its round-off, eps |n_k| times the other factor's length (compared squared).
    trusted[k] = C[k] * C[k] > safety2 * tn.scale2 * g.w2[o];
    if (!(D[k] * D[k] > safety2 * tn.scale2 * g.edge2(o, k))) flat = true;
  }
  Feature<S> best;
  bool inside = !flat;
  for (int k = 0; k < 4; ++k) inside = inside && sameSign(C[k], D[k]);
  if (inside) {
    Feature<S> f;
    f.keep = 0xFu;
    S sum = S(0);
    for (int k = 0; k < 4; ++k) sum += f.lambda[k] = C[k] / D[k];
    for (int k = 0; k < 4; ++k) f.lambda[k] /= sum;
    f.distanceSquared = S(0);  // the origin is inside: z = 0
    if (trusted[0] && trusted[1] && trusted[2] && trusted[3]) return f;
    // An untrusted "inside" is only a candidate, at the point its coordinates give.
    for (int k = 0; k < 4; ++k) f.z += f.lambda[k] * g.w[k];
    f.distanceSquared = f.z.squaredNorm();
    best = f;
  }
  for (int k = 0; k < 4; ++k) {
    if (!flat && trusted[k] && sameSign(C[k], D[k])) continue;  // the origin is on k's side of face k
    const Feature<S> f = triangle(g, (k + 1) % 4, (k + 2) % 4, (k + 3) % 4, &normals[k]);
    if (f.distanceSquared < best.distanceSquared) best = f;
  }
  return best;
}

}  // namespace detail

/// Refines the simplex to its feature closest to the origin (§2.2), setting
/// `simplex.lambda` and `simplex.z` (the closest point). Vertices not in the feature are
/// dropped; the order of those kept is preserved.
template <typename S>
void reduceToClosestFeature(Simplex<S>& simplex) {
  if (simplex.size < 1 || simplex.size > 4) return;
  const detail::Geometry<S> g(simplex.vertices, simplex.size);
  detail::Feature<S> f;
  switch (simplex.size) {
    case 1: f = detail::vertexFeature(g, 0); break;
    case 2: f = detail::segment(g, 0, 1); break;
    case 3: f = detail::triangle(g, 0, 1, 2); break;
    default: f = detail::tetrahedron(g); break;
  }
  int kept = 0;
  for (int k = 0; k < simplex.size; ++k) {
    if (!(f.keep & (1u << k))) continue;
    if (kept != k) simplex.vertices[kept] = simplex.vertices[k];
    simplex.lambda[kept] = f.lambda[k];
    ++kept;
  }
  simplex.size = kept;
  simplex.z = f.z / g.scale;  // back from the sub-algorithm's units (exact: a power of two)
}

}  // namespace gjkx
