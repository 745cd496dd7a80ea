// The few surface builders the torso and the plant are made of (chapter 08). Every bone
// and every leaf is a closed, consistently oriented, outward-facing triangle mesh built
// from *rings*: rings of equal size joined by quads, the ends closed by a cap (a fan to
// one point) or joined into a loop. Three shapes use them:
//   - a sweep: a 2D profile carried along a path (ribs, cartilages, clavicles, the hip
//     bones, the sacrum, the plant's stalks);
//   - a loop sweep: the same around a closed path, a ring with a hole (a vertebra: its
//     body in front, its arch behind, the spinal canal through);
//   - a plate: an outline in the plane, thickened and bent (the sternum, the scapulae,
//     the plant's leaves, thin slabs: the paper's flat-object case).
// Nonconvex detail (a vertebra's processes) is made by pulling a patch of a ring grid out
// along one direction, which extrudes it as a finger.
#pragma once

#include <gjkx/mesh/triangle_mesh.hpp>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <map>
#include <random>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace torso {

/// A point or direction in metres.
using V3 = Eigen::Vector3d;
/// A point of a 2D profile or outline.
using V2 = Eigen::Vector2d;
/// Rings of vertices, ring k holding the same number of vertices as every other.
using Rings = std::vector<std::vector<V3>>;

/// Uniform numbers from std::mt19937 mapped by hand, so that a seed gives the same
/// numbers with every standard library (std::uniform_real_distribution does not).
class Random {
 public:
  /// A generator started from `seed`.
  explicit Random(std::uint32_t seed) : engine_(seed) {}
  /// A number in [a, b): 53 random bits from two 32-bit draws (taken in a fixed order).
  double uniform(double a, double b) {
    const double high = double(engine_() >> 5), low = double(engine_() >> 6);
    return a + (b - a) * (high * 67108864.0 + low) / 9007199254740992.0;
  }

 private:
  std::mt19937 engine_;
};

/// The value a fraction `t` of the way from `a` to `b`.
inline double lerp(double a, double b, double t) { return a + (b - a) * t; }

/// Checks that every vertex of `mesh` is finite and every edge is used once in each
/// direction (closed and consistently oriented); throws std::logic_error naming the mesh otherwise.
inline void requireClosedOriented(const gjkx::TriangleMesh& mesh) {
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i)
    if (!mesh.vertices[i].allFinite())
      throw std::logic_error(mesh.source + ": vertex " + std::to_string(i) + " is not finite");
  std::map<std::pair<int, int>, int> directed;
  for (const auto& t : mesh.triangles)
    for (int k = 0; k < 3; ++k) ++directed[{t[k], t[(k + 1) % 3]}];
  for (const auto& [edge, count] : directed) {
    const auto back = directed.find({edge.second, edge.first});
    if (count != 1 || back == directed.end() || back->second != 1)
      throw std::logic_error(mesh.source + ": edge " + std::to_string(edge.first) + "-" + std::to_string(edge.second) +
                             " is not shared by exactly two consistently oriented triangles");
  }
}

/// Appends `part` to `mesh` (a mesh of several closed components, such as the plant).
inline void append(gjkx::TriangleMesh& mesh, const gjkx::TriangleMesh& part) {
  const int offset = int(mesh.vertices.size());
  mesh.vertices.insert(mesh.vertices.end(), part.vertices.begin(), part.vertices.end());
  for (const auto& t : part.triangles) mesh.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
}

/// The closed surface through `rings`: consecutive rings joined by quads (two triangles
/// each), the last joined back to the first when `loop`, otherwise the first ring closed
/// by a fan to `startCap` and the last by a fan to `endCap`. The triangles are turned to
/// face outward (positive enclosed volume). `name` names the mesh in messages.
inline gjkx::TriangleMesh ringSurface(const Rings& rings, bool loop, const V3& startCap, const V3& endCap,
                                      const std::string& name) {
  if (rings.size() < 2 || rings[0].size() < 3) throw std::invalid_argument(name + ": needs 2 rings of 3 vertices");
  const int K = int(rings.size()), n = int(rings[0].size());
  gjkx::TriangleMesh mesh;
  mesh.source = name;
  for (const auto& ring : rings) {
    if (int(ring.size()) != n) throw std::invalid_argument(name + ": rings of different sizes");
    mesh.vertices.insert(mesh.vertices.end(), ring.begin(), ring.end());
  }
  auto at = [&](int k, int i) { return (k % K) * n + (i % n); };
  for (int k = 0; k + 1 < K + (loop ? 1 : 0); ++k)
    for (int i = 0; i < n; ++i) {
      mesh.triangles.push_back({at(k, i), at(k, i + 1), at(k + 1, i + 1)});
      mesh.triangles.push_back({at(k, i), at(k + 1, i + 1), at(k + 1, i)});
    }
  if (!loop) {
    const int s = int(mesh.vertices.size());
    mesh.vertices.push_back(startCap);
    mesh.vertices.push_back(endCap);
    for (int i = 0; i < n; ++i) {
      mesh.triangles.push_back({s, at(0, i + 1), at(0, i)});
      mesh.triangles.push_back({s + 1, at(K - 1, i), at(K - 1, i + 1)});
    }
  }
  if (gjkx::enclosedVolume(mesh) < 0)
    for (auto& t : mesh.triangles) std::swap(t[1], t[2]);
  requireClosedOriented(mesh);
  return mesh;
}

/// n points of an ellipse-like profile, point i at angle 2 pi i / n from the +x axis:
/// half sizes `plusX`/`minusX` on the two sides of x, `plusY`/`minusY` of y, and a
/// superellipse `exponent` (2: an ellipse; larger: flatter sides, like a vertebral body).
inline std::vector<V2> profile(int n, double plusX, double minusX, double plusY, double minusY, double exponent = 2) {
  std::vector<V2> points;
  for (int i = 0; i < n; ++i) {
    const double a = 2 * M_PI * i / n, c = std::cos(a), s = std::sin(a);
    auto power = [&](double x) { return std::copysign(std::pow(std::fabs(x), 2 / exponent), x); };
    points.emplace_back(power(c) * (c >= 0 ? plusX : minusX), power(s) * (s >= 0 ? plusY : minusY));
  }
  return points;
}

/// A frame along a path: the tangent, and two normals (`side`, `up`) with `up` the given
/// reference direction made perpendicular to the tangent.
struct Frame {
  V3 tangent;  ///< along the path
  V3 side;     ///< tangent x up
  V3 up;       ///< the reference direction, made perpendicular to the tangent
};

/// The frames of a path at its points (central differences; wrapping round when `loop`).
inline std::vector<Frame> frames(const std::vector<V3>& path, bool loop, const std::function<V3(int)>& reference) {
  const int K = int(path.size());
  std::vector<Frame> out(path.size());
  for (int k = 0; k < K; ++k) {
    const V3 before = loop ? path[(k + K - 1) % K] : path[std::max(k - 1, 0)];
    const V3 after = loop ? path[(k + 1) % K] : path[std::min(k + 1, K - 1)];
    Frame& f = out[k];
    f.tangent = (after - before).normalized();
    const V3 r = reference(k);
    f.up = (r - r.dot(f.tangent) * f.tangent).normalized();
    f.side = f.tangent.cross(f.up);
  }
  return out;
}

/// The rings of a sweep: profile k placed at path point k, its x along the frame's side
/// and its y along the frame's up.
inline Rings sweepRings(const std::vector<V3>& path, const std::vector<Frame>& frame,
                        const std::function<std::vector<V2>(int)>& profileAt) {
  Rings rings;
  for (std::size_t k = 0; k < path.size(); ++k) {
    std::vector<V3> ring;
    for (const V2& p : profileAt(int(k))) ring.push_back(path[k] + p.x() * frame[k].side + p.y() * frame[k].up);
    rings.push_back(ring);
  }
  return rings;
}

/// A closed tube along an open path: the rings of sweepRings, each end closed by a cone
/// reaching `capLength` beyond the end point along the path.
inline gjkx::TriangleMesh sweep(const std::vector<V3>& path, const std::function<V3(int)>& reference,
                                const std::function<std::vector<V2>(int)>& profileAt, double capLength,
                                const std::string& name) {
  const auto f = frames(path, false, reference);
  const Rings rings = sweepRings(path, f, profileAt);
  return ringSurface(rings, false, path.front() - capLength * f.front().tangent,
                     path.back() + capLength * f.back().tangent, name);
}

/// Pulls the patch of `rings` with ring index in [k0, k1] and vertex index in [i0, i1]
/// (both taken modulo the sizes, so a patch may wrap round) out by `offset`: the patch is
/// extruded as a finger whose sides are the quads around it.
inline void extrude(Rings& rings, int k0, int k1, int i0, int i1, const V3& offset) {
  const int K = int(rings.size()), n = int(rings[0].size());
  for (int k = k0; k <= k1; ++k)
    for (int i = i0; i <= i1; ++i) rings[((k % K) + K) % K][((i % n) + n) % n] += offset;
}

/// Points along a cubic Bezier curve, `count` of them from a to d.
inline std::vector<V3> bezier(const V3& a, const V3& b, const V3& c, const V3& d, int count) {
  std::vector<V3> points;
  for (int k = 0; k < count; ++k) {
    const double t = double(k) / (count - 1), u = 1 - t;
    points.push_back(u * u * u * a + 3 * u * u * t * b + 3 * u * t * t * c + t * t * t * d);
  }
  return points;
}

/// A closed outline resampled to `n` points evenly spaced along its length.
inline std::vector<V2> resample(const std::vector<V2>& outline, int n) {
  std::vector<double> length{0};
  for (std::size_t i = 0; i < outline.size(); ++i)
    length.push_back(length.back() + (outline[(i + 1) % outline.size()] - outline[i]).norm());
  std::vector<V2> out;
  std::size_t segment = 0;
  for (int k = 0; k < n; ++k) {
    const double s = length.back() * k / n;
    while (length[segment + 1] < s) ++segment;
    const double t = (s - length[segment]) / (length[segment + 1] - length[segment]);
    out.push_back(outline[segment] + t * (outline[(segment + 1) % outline.size()] - outline[segment]));
  }
  return out;
}

/// A plate: the outline (star-shaped about its centroid) filled in by shrinking copies
/// of it (`levels`, from 1 at the rim towards 0 at the centre), the upper face lifted by
/// `thickness(p, +1)` and the lower by `thickness(p, -1)` (p a point of the outline's
/// plane); the rim ring has no thickness. `place(p, h)` puts the point p of the plane at
/// height h above it in space (it may bend the plate). Closed by a point at the centre
/// of each face.
inline gjkx::TriangleMesh plate(const std::vector<V2>& outline, const std::vector<double>& levels,
                                const std::function<double(const V2&, int)>& thickness,
                                const std::function<V3(const V2&, double)>& place, const std::string& name) {
  V2 centre = V2::Zero();
  for (const V2& p : outline) centre += p;
  centre /= double(outline.size());
  auto ring = [&](double level, int face) {
    std::vector<V3> points;
    for (const V2& p : outline) {
      const V2 q = centre + level * (p - centre);
      points.push_back(place(q, level >= 1 ? 0.0 : face * thickness(q, face)));
    }
    return points;
  };
  // From the upper face's centre down to the rim, then in along the lower face.
  Rings rings;
  for (auto it = levels.rbegin(); it != levels.rend(); ++it)
    if (*it < 1) rings.push_back(ring(*it, +1));
  rings.push_back(ring(1, 0));
  for (double level : levels)
    if (level < 1) rings.push_back(ring(level, -1));
  return ringSurface(rings, false, place(centre, thickness(centre, +1)), place(centre, -thickness(centre, -1)), name);
}

}  // namespace torso
