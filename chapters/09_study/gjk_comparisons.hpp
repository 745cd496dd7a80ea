// The GJK comparison of the study (chapter 09): distance and boolean queries, ours
// against libccd, FCL and Bullet, cold and warm-started, with the disagreement against
// an exact reference. `runGjkComparisons(options)` returns one row per method and
// workload; `gjkRatioLines(rows)` the machine-readable RATIO lines.
//
// Workloads: pairs of boxes, spheres, capsules, and polytopes of 12, 100 and 1000
// vertices (random points on ellipsoids), at random poses. Cold: independent pairs with a
// supporting distance along a random direction of 1e-3, 1e-2, 0.05, 0.2, 0.5 (separated;
// the true distance is at least that) or -0.01, -0.1, -0.3 (mostly overlapping).
// Warm: trajectories of small pose changes (Q moves 0.004 and turns 0.01 rad per step, P
// turns 0.01 rad), as in a simulation; each method keeps whatever it carries from one
// step to the next (ours: GjkCache; see peers_gjk.hpp for the peers).
//
// Timing: each query set is run in batches of `batch` queries timed together with
// steady_clock (time / batch = one sample per query of the batch); the median and 99th
// percentile of those samples are reported. The answers of a first, untimed pass are
// compared with the reference:
// - distance: |answer - reference|, answers clamped at 0 (an overlap is distance 0);
// - boolean: the reference says overlap when the exact distance is 0, disjoint when it
//   exceeds a band of 5e-4 (pairs inside the band are not judged: the methods' collision
//   tolerances, up to sqrt(eps_float) = 3.5e-4, make them "touching" by design).
// The reference is our own, in long double, independent of every method: closed forms
// for spheres and capsules; for boxes and polytopes a brute force over feature pairs
// (vertex-triangle, edge-edge, edge crossing a triangle) plus a vertex-containment test.
#pragma once

#include <gjkx/study/peers_gjk.hpp>

#include <gjkx/gjk/gjk.hpp>
#include <gjkx/supporting_distance/intersection.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <limits>
#include <map>
#include <set>
#include <string>
#include <vector>

namespace gjkx::study {

/// Options of the GJK comparison.
struct GjkStudyOptions {
  /// A short run (for study_summary): fewer pairs and repetitions.
  bool quick = false;
  /// Seed of the shapes and poses.
  unsigned seed = 2026;
};

/// One method on one workload.
struct GjkRow {
  std::string workload;   ///< e.g. gjk_distance_polytope100_warm
  std::string method;     ///< e.g. ours-double, fcl-indep
  std::string warmStart;  ///< what the method carries between steps ("-" for a cold workload)
  bool ours = false;      ///< one of ours (the RATIO lines compare ours-double with the best peer)
  int queries = 0;        ///< queries answered (untimed pass)
  double medianNs = 0, p99Ns = 0;
  double errorMedian = 0, errorMax = 0;  ///< distance: |d - d_ref|
  int judged = 0;                        ///< boolean: queries outside the band
  int wrong = 0;                         ///< boolean: wrong answers
  int failures = 0;                      ///< no answer (iteration cap, NaN, no result)
  /// Ours only: how the `failures` split by status, counted in a separate untimed pass with
  /// the same calls (the peers report no status, only an answer or none).
  int iterationCap = 0, numericalFailure = 0, otherFailure = 0;
};

// ---------------------------------------------------------------------------------------
// The exact reference (long double)
namespace ref {
using Real = long double;
using RVec = Eigen::Matrix<Real, 3, 1>;

/// The closest point to x on the segment [a, b].
inline RVec closestOnSegment(const RVec& x, const RVec& a, const RVec& b) {
  const RVec ab = b - a;
  const Real t = ab.squaredNorm() > 0 ? std::clamp((x - a).dot(ab) / ab.squaredNorm(), Real(0), Real(1)) : Real(0);
  return a + t * ab;
}

/// Distance between segments [p1,q1] and [p2,q2] (Ericson, Real-Time Collision Detection §5.1.9).
inline Real segmentSegment(const RVec& p1, const RVec& q1, const RVec& p2, const RVec& q2) {
  const RVec d1 = q1 - p1, d2 = q2 - p2, r = p1 - p2;
  const Real a = d1.squaredNorm(), e = d2.squaredNorm(), f = d2.dot(r);
  Real s = 0, t = 0;
  if (a <= 0 && e <= 0) return r.norm();
  if (a <= 0) {
    t = std::clamp(f / e, Real(0), Real(1));
  } else {
    const Real c = d1.dot(r);
    if (e <= 0) {
      s = std::clamp(-c / a, Real(0), Real(1));
    } else {
      const Real b = d1.dot(d2), denom = a * e - b * b;
      s = denom > 0 ? std::clamp((b * f - c * e) / denom, Real(0), Real(1)) : Real(0);
      t = (b * s + f) / e;
      if (t < 0) {
        t = 0;
        s = std::clamp(-c / a, Real(0), Real(1));
      } else if (t > 1) {
        t = 1;
        s = std::clamp((b - c) / a, Real(0), Real(1));
      }
    }
  }
  return ((p1 + d1 * s) - (p2 + d2 * t)).norm();
}

/// Distance from x to the triangle abc (Ericson §5.1.5, by Voronoi regions).
inline Real pointTriangle(const RVec& p, const RVec& a, const RVec& b, const RVec& c) {
  const RVec ab = b - a, ac = c - a, ap = p - a;
  const Real d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0) return (p - a).norm();
  const RVec bp = p - b;
  const Real d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3) return (p - b).norm();
  const Real vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return (p - (a + ab * (d1 / (d1 - d3)))).norm();
  const RVec cp = p - c;
  const Real d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6) return (p - c).norm();
  const Real vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return (p - (a + ac * (d2 / (d2 - d6)))).norm();
  const Real va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) return (p - (b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6))))).norm();
  const Real denom = 1 / (va + vb + vc);
  return (p - (a + ab * (vb * denom) + ac * (vc * denom))).norm();
}

/// Does the segment [p, q] cross the triangle abc (strictly, by orientation signs)?
inline bool segmentCrossesTriangle(const RVec& p, const RVec& q, const RVec& a, const RVec& b, const RVec& c) {
  const RVec n = (b - a).cross(c - a);
  const Real sp = n.dot(p - a), sq = n.dot(q - a);
  if ((sp > 0 && sq > 0) || (sp < 0 && sq < 0) || sp == sq) return false;
  const RVec x = p + (q - p) * (sp / (sp - sq));
  const Real u = n.dot((b - a).cross(x - a)), v = n.dot((c - b).cross(x - b)), w = n.dot((a - c).cross(x - c));
  return (u >= 0 && v >= 0 && w >= 0) || (u <= 0 && v <= 0 && w <= 0);
}

/// A convex polytope in world coordinates.
struct WorldPolytope {
  std::vector<RVec> vertices;
  std::vector<std::array<int, 3>> triangles;
  std::vector<std::pair<int, int>> edges;
  std::vector<RVec> normals;  // unit outward face normals
  std::vector<Real> offsets;
  RVec lo, hi;
  bool contains(const RVec& x) const {
    for (size_t f = 0; f < normals.size(); ++f)
      if (normals[f].dot(x) > offsets[f]) return false;
    return true;
  }
};

inline WorldPolytope toWorld(const Polytope<double>& shape, const Pose<double>& pose) {
  WorldPolytope out;
  const Eigen::Matrix<Real, 3, 3> R = pose.rotation.cast<Real>();
  const RVec t = pose.translation.cast<Real>();
  RVec centroid = RVec::Zero();
  for (const auto& v : shape.vertices()) {
    out.vertices.push_back(R * v.cast<Real>() + t);
    centroid += out.vertices.back();
  }
  centroid /= Real(out.vertices.size());
  out.triangles = shape.triangles();
  std::set<std::pair<int, int>> edges;
  for (const auto& tri : out.triangles) {
    for (int k = 0; k < 3; ++k) edges.insert({std::min(tri[k], tri[(k + 1) % 3]), std::max(tri[k], tri[(k + 1) % 3])});
    const RVec& a = out.vertices[tri[0]];
    RVec n = (out.vertices[tri[1]] - a).cross(out.vertices[tri[2]] - a);
    if (!(n.norm() > 0)) continue;
    n.normalize();
    if (n.dot(a - centroid) < 0) n = -n;
    out.normals.push_back(n);
    out.offsets.push_back(n.dot(a));
  }
  out.edges.assign(edges.begin(), edges.end());
  out.lo = out.hi = out.vertices[0];
  for (const RVec& v : out.vertices) out.lo = out.lo.cwiseMin(v), out.hi = out.hi.cwiseMax(v);
  return out;
}

inline Real boxGap(const RVec& lo1, const RVec& hi1, const RVec& lo2, const RVec& hi2) {
  RVec gap;
  for (int k = 0; k < 3; ++k) gap[k] = std::max({Real(0), lo1[k] - hi2[k], lo2[k] - hi1[k]});
  return gap.norm();
}

/// The exact distance between two convex polytopes (0 when they overlap): brute force.
inline Real polytopeDistance(const WorldPolytope& A, const WorldPolytope& B) {
  for (const RVec& v : A.vertices)
    if (B.contains(v)) return 0;
  for (const RVec& v : B.vertices)
    if (A.contains(v)) return 0;
  // An upper bound: the nearest pair of vertices. A feature whose bounding box is farther
  // than that from the other polytope's box cannot hold the closest point.
  Real best = std::numeric_limits<Real>::infinity();
  for (const RVec& a : A.vertices)
    for (const RVec& b : B.vertices) best = std::min(best, (a - b).norm());
  auto near = [&](const RVec& lo, const RVec& hi, const WorldPolytope& other) { return boxGap(lo, hi, other.lo, other.hi) <= best; };
  auto relevantTriangles = [&](const WorldPolytope& X, const WorldPolytope& other) {
    std::vector<int> out;
    for (size_t k = 0; k < X.triangles.size(); ++k) {
      const auto& t = X.triangles[k];
      const RVec lo = X.vertices[t[0]].cwiseMin(X.vertices[t[1]]).cwiseMin(X.vertices[t[2]]);
      const RVec hi = X.vertices[t[0]].cwiseMax(X.vertices[t[1]]).cwiseMax(X.vertices[t[2]]);
      if (near(lo, hi, other)) out.push_back(int(k));
    }
    return out;
  };
  auto relevantEdges = [&](const WorldPolytope& X, const WorldPolytope& other) {
    std::vector<int> out;
    for (size_t k = 0; k < X.edges.size(); ++k) {
      const RVec& a = X.vertices[X.edges[k].first];
      const RVec& b = X.vertices[X.edges[k].second];
      if (near(a.cwiseMin(b), a.cwiseMax(b), other)) out.push_back(int(k));
    }
    return out;
  };
  auto relevantVertices = [&](const WorldPolytope& X, const WorldPolytope& other) {
    std::vector<int> out;
    for (size_t k = 0; k < X.vertices.size(); ++k)
      if (near(X.vertices[k], X.vertices[k], other)) out.push_back(int(k));
    return out;
  };
  const auto tA = relevantTriangles(A, B), tB = relevantTriangles(B, A);
  const auto eA = relevantEdges(A, B), eB = relevantEdges(B, A);
  const auto vA = relevantVertices(A, B), vB = relevantVertices(B, A);
  auto tri = [](const WorldPolytope& X, int k, int j) -> const RVec& { return X.vertices[X.triangles[k][j]]; };
  auto vertexTriangles = [&](const WorldPolytope& X, const std::vector<int>& vs, const WorldPolytope& Y, const std::vector<int>& ts) {
    for (int v : vs)
      for (int t : ts) best = std::min(best, pointTriangle(X.vertices[v], tri(Y, t, 0), tri(Y, t, 1), tri(Y, t, 2)));
  };
  vertexTriangles(A, vA, B, tB);
  vertexTriangles(B, vB, A, tA);
  for (int i : eA)
    for (int j : eB) {
      const RVec &a = A.vertices[A.edges[i].first], &b = A.vertices[A.edges[i].second];
      const RVec &c = B.vertices[B.edges[j].first], &d = B.vertices[B.edges[j].second];
      if (boxGap(a.cwiseMin(b), a.cwiseMax(b), c.cwiseMin(d), c.cwiseMax(d)) >= best) continue;
      best = std::min(best, segmentSegment(a, b, c, d));
    }
  // Boundaries that cross (no vertex inside the other): an edge pierces a triangle.
  auto crossing = [&](const WorldPolytope& X, const std::vector<int>& es, const WorldPolytope& Y, const std::vector<int>& ts) {
    for (int e : es)
      for (int t : ts)
        if (segmentCrossesTriangle(X.vertices[X.edges[e].first], X.vertices[X.edges[e].second], tri(Y, t, 0), tri(Y, t, 1), tri(Y, t, 2)))
          return true;
    return false;
  };
  if (crossing(A, eA, B, tB) || crossing(B, eB, A, tA)) return 0;
  return best;
}

/// The exact distance (0 when overlapping) between two study shapes at their poses.
/// `boxHulls` holds a box's hull (its 8 corners) for the brute force.
inline Real distance(const ShapeDesc& P, const Pose<double>& poseP, const ShapeDesc& Q, const Pose<double>& poseQ) {
  const RVec cP = poseP.translation.cast<Real>(), cQ = poseQ.translation.cast<Real>();
  switch (P.kind) {
    case ShapeKind::Sphere: return std::max(Real(0), (cQ - cP).norm() - Real(P.radius) - Real(Q.radius));
    case ShapeKind::Capsule: {
      auto end = [](const ShapeDesc& d, const Pose<double>& pose, double sign) {
        return RVec(pose.rotation.cast<Real>() * RVec(0, 0, Real(sign * d.halfLength)) + pose.translation.cast<Real>());
      };
      const Real axes = segmentSegment(end(P, poseP, -1), end(P, poseP, 1), end(Q, poseQ, -1), end(Q, poseQ, 1));
      return std::max(Real(0), axes - Real(P.radius) - Real(Q.radius));
    }
    default: {
      auto hull = [](const ShapeDesc& d) {
        if (d.kind == ShapeKind::Polytope) return *d.polytope;
        std::vector<Vector3<double>> corners;
        for (int k = 0; k < 8; ++k)
          corners.emplace_back((k & 1 ? 1 : -1) * d.halfExtents.x(), (k & 2 ? 1 : -1) * d.halfExtents.y(), (k & 4 ? 1 : -1) * d.halfExtents.z());
        return Polytope<double>::hull(corners);
      };
      return polytopeDistance(toWorld(hull(P), poseP), toWorld(hull(Q), poseQ));
    }
  }
}
}  // namespace ref

// ---------------------------------------------------------------------------------------
// Workloads
struct GjkQuery {
  int shapeP = 0, shapeQ = 0;
  Pose<double> poseP, poseQ;
  bool startsTrajectory = true;  ///< warm runs reset their caches here
  double reference = std::numeric_limits<double>::quiet_NaN();  ///< exact distance (NaN: not computed)
};

struct GjkWorkload {
  std::string name;  ///< box, sphere, capsule, polytope12, ...
  ShapeKind kind;
  std::vector<ShapeDesc> shapes;
  std::vector<GjkQuery> cold, warm;
};

namespace detail {

inline GjkQuery randomPair(const GjkWorkload& w, double gap, std::mt19937_64& rng) {
  GjkQuery q;
  q.shapeP = int(rng() % w.shapes.size());
  q.shapeQ = int(rng() % w.shapes.size());
  q.poseP.rotation = randomRotation(rng);
  q.poseQ.rotation = randomRotation(rng);
  const Vector3<double> u = randomUnit(rng);
  // SD(P, Q, u) = u.c + u.S_Q0(-u) - u.S_P(u) = gap, with Q's centre c on the line along u.
  const double hP = u.dot(scanSupport(w.shapes[q.shapeP], q.poseP, u));
  const double hQ = u.dot(scanSupport(w.shapes[q.shapeQ], q.poseQ, Vector3<double>(-u)));
  q.poseQ.translation = u * (gap + hP - hQ);
  return q;
}

inline GjkWorkload makeWorkload(const std::string& name, ShapeKind kind, int vertices, const GjkStudyOptions& o) {
  std::mt19937_64 rng(o.seed + std::hash<std::string>{}(name) % 1000);
  GjkWorkload w;
  w.name = name;
  w.kind = kind;
  for (int k = 0; k < 4; ++k) w.shapes.push_back(randomShape(kind, vertices, rng));
  const double gaps[] = {1e-3, 1e-2, 0.05, 0.2, 0.5, -0.01, -0.1, -0.3};
  const int pairs = o.quick ? 64 : 256;
  for (int k = 0; k < pairs; ++k) w.cold.push_back(randomPair(w, gaps[k % 8], rng));
  const int trajectories = o.quick ? 8 : 32, steps = o.quick ? 64 : 128;
  for (int t = 0; t < trajectories; ++t) {
    GjkQuery q = randomPair(w, gaps[t % 5] + 0.05, rng);  // starts separated, drifts
    const Vector3<double> velocity = 0.004 * randomUnit(rng);
    const Matrix3<double> turnP = Eigen::AngleAxisd(0.01, randomUnit(rng)).toRotationMatrix();
    const Matrix3<double> turnQ = Eigen::AngleAxisd(0.01, randomUnit(rng)).toRotationMatrix();
    for (int s = 0; s < steps; ++s) {
      q.startsTrajectory = s == 0;
      w.warm.push_back(q);
      q.poseP.rotation = turnP * q.poseP.rotation;
      q.poseQ.rotation = turnQ * q.poseQ.rotation;
      q.poseQ.translation += velocity;
    }
  }
  // The exact distances; for the 1000-vertex polytopes of the warm runs, every 8th step
  // (the brute force costs milliseconds there).
  const int stride = vertices >= 1000 ? 8 : 1;
  for (auto& q : w.cold) q.reference = double(ref::distance(w.shapes[q.shapeP], q.poseP, w.shapes[q.shapeQ], q.poseQ));
  for (size_t k = 0; k < w.warm.size(); k += stride) {
    auto& q = w.warm[k];
    q.reference = double(ref::distance(w.shapes[q.shapeP], q.poseP, w.shapes[q.shapeQ], q.poseQ));
  }
  return w;
}

/// Per-query times of a sequence of queries, timed in batches: `run(k)` answers query k.
template <typename Run>
std::pair<double, double> timeQueries(int n, int repeats, Run&& run) {
  constexpr int batch = 16;
  std::vector<double> samples;
  double sink = 0;
  for (int r = 0; r < repeats; ++r)
    for (int start = 0; start + batch <= n; start += batch) {
      const auto t0 = std::chrono::steady_clock::now();
      for (int k = start; k < start + batch; ++k) sink += run(k);
      const auto t1 = std::chrono::steady_clock::now();
      samples.push_back(std::chrono::duration<double, std::nano>(t1 - t0).count() / batch);
    }
  if (sink == 12345.678) std::printf(" ");  // keeps the answers alive
  std::sort(samples.begin(), samples.end());
  if (samples.empty()) return {0, 0};
  return {samples[samples.size() / 2], samples[std::min(samples.size() - 1, size_t(0.99 * double(samples.size())))]};
}

// Boolean: reference distances in (0, band] are not judged. The band is above the
// largest collision tolerance of a method here (ours in float: sqrt(eps_float) = 3.5e-4),
// which calls a pair that close "intersecting" by design (§2.3).
constexpr double kBand = 5e-4;

/// Runs one method on a query list: an untimed pass (answers → errors), then timed passes.
/// `answer(k)` returns the distance (distance query) or 1/0 for overlap/disjoint (boolean),
/// NaN for no answer; `reset()` clears the warm-start state.
template <typename Answer, typename Reset>
GjkRow measure(const std::string& workload, const std::string& method, const std::string& warmStart, bool ours,
               const std::vector<GjkQuery>& queries, bool boolean, int repeats, Answer&& answer, Reset&& reset) {
  GjkRow row;
  row.workload = workload;
  row.method = method;
  row.warmStart = warmStart;
  row.ours = ours;
  row.queries = int(queries.size());
  std::vector<double> errors;
  reset();
  for (int k = 0; k < int(queries.size()); ++k) {
    const double a = answer(k);
    const double r = queries[k].reference;
    if (std::isnan(a)) {
      ++row.failures;
      continue;
    }
    if (std::isnan(r)) continue;
    if (boolean) {
      if (r > 0 && r <= kBand) continue;
      ++row.judged;
      if ((a > 0.5) != (r == 0)) ++row.wrong;
    } else {
      errors.push_back(std::abs(std::max(a, 0.0) - r));
    }
  }
  if (!errors.empty()) {
    std::sort(errors.begin(), errors.end());
    row.errorMedian = errors[errors.size() / 2];
    row.errorMax = errors.back();
  }
  reset();
  const auto t = timeQueries(int(queries.size()), repeats, std::forward<Answer>(answer));
  row.medianNs = t.first;
  row.p99Ns = t.second;
  return row;
}

template <typename T>
T ourShape(const ShapeDesc& d) {
  using S = typename T::Scalar;
  if constexpr (std::is_same_v<T, Box<S>>) return Box<S>(d.halfExtents.cast<S>());
  else if constexpr (std::is_same_v<T, Sphere<S>>) return Sphere<S>(S(d.radius));
  else if constexpr (std::is_same_v<T, Capsule<S>>)
    return Capsule<S>(Vector3<S>(S(0), S(0), S(-d.halfLength)), Vector3<S>(S(0), S(0), S(d.halfLength)), S(d.radius));
  else if constexpr (std::is_same_v<S, float>) return *d.polytopeF;
  else return *d.polytope;
}

/// Ours (gjkx::gjk for distance, gjkx::intersect for boolean) in scalar S. With
/// `roundedCores` false, spheres and capsules run the paper's GJK on their curved surfaces
/// (the "ours-curved" rows) instead of on their cores.
template <typename T>
GjkRow measureOurs(const GjkWorkload& w, const std::string& workload, const char* method, bool warm, bool boolean, int repeats,
                   bool roundedCores = true) {
  using S = typename T::Scalar;
  const std::vector<GjkQuery>& queries = warm ? w.warm : w.cold;
  std::vector<Placed<T>> P, Q;
  for (const auto& q : queries) {
    P.push_back(Placed<T>{ourShape<T>(w.shapes[q.shapeP]), q.poseP.cast<S>()});
    Q.push_back(Placed<T>{ourShape<T>(w.shapes[q.shapeQ]), q.poseQ.cast<S>()});
  }
  GjkSettings<S> settings;
  settings.roundedCores = roundedCores;
  IntersectionSettings<S> intersection;
  intersection.gjk.roundedCores = roundedCores;
  GjkCache<S> cache;
  GjkCache<S>* cachePtr = warm ? &cache : nullptr;
  auto reset = [&] { cache = GjkCache<S>{}; };
  auto answer = [&](int k) -> double {
    if (warm && queries[k].startsTrajectory) cache.valid = false;
    if (boolean) {
      const auto r = intersect(P[k], Q[k], intersection, cachePtr);
      if (r.status == IntersectionStatus::Disjoint) return 0.0;
      if (r.status == IntersectionStatus::Intersecting) return 1.0;
      return std::nan("");
    }
    const auto r = gjk(P[k], Q[k], settings, cachePtr);
    if (r.status == GjkStatus::Separated || r.status == GjkStatus::Overlapping) return double(r.distance);
    return std::nan("");
  };
  GjkRow row = measure(workload, method, warm ? "GjkCache" : "-", true, queries, boolean, repeats, answer, reset);
  // The failure statuses, for the float-against-double table: the same calls once more,
  // untimed, in the same order (so the warm caches evolve as in the measured passes).
  reset();
  for (int k = 0; k < int(queries.size()); ++k) {
    if (warm && queries[k].startsTrajectory) cache.valid = false;
    bool cap = false, numerical = false, other = false;
    if (boolean) {
      const IntersectionStatus s = intersect(P[k], Q[k], intersection, cachePtr).status;
      cap = s == IntersectionStatus::IterationCap;
      numerical = s == IntersectionStatus::NumericalFailure;
      other = !cap && !numerical && s != IntersectionStatus::Disjoint && s != IntersectionStatus::Intersecting;
    } else {
      const GjkStatus s = gjk(P[k], Q[k], settings, cachePtr).status;
      cap = s == GjkStatus::IterationCap;
      numerical = s == GjkStatus::NumericalFailure;
      other = !cap && !numerical && s != GjkStatus::Separated && s != GjkStatus::Overlapping;
    }
    row.iterationCap += cap;
    row.numericalFailure += numerical;
    row.otherFailure += other;
  }
  return row;
}

template <template <typename> class Shape>
void measureOursBothScalars(const GjkWorkload& w, const std::string& workload, bool warm, bool boolean, int repeats,
                            std::vector<GjkRow>& rows) {
  rows.push_back(measureOurs<Shape<double>>(w, workload, "ours-double", warm, boolean, repeats));
  rows.push_back(measureOurs<Shape<float>>(w, workload, "ours-float", warm, boolean, repeats));
}

inline void measurePeers(const GjkWorkload& w, const std::string& workload, bool warm, bool boolean, int repeats,
                         std::vector<GjkRow>& rows) {
  const std::vector<GjkQuery>& queries = warm ? w.warm : w.cold;
  const int n = int(queries.size());
  (void)n;
  (void)rows;
  (void)repeats;
  (void)boolean;
  (void)workload;
#if GJKX_HAVE_CCD
  if (boolean) {
    std::vector<CcdObject> A(n), B(n);
    for (int k = 0; k < n; ++k) {
      A[k] = CcdObject{&w.shapes[queries[k].shapeP], queries[k].poseP};
      B[k] = CcdObject{&w.shapes[queries[k].shapeQ], queries[k].poseQ};
    }
    const ccd_t ccd = ccdSettings();
    const char* none = warm ? "none" : "-";
    rows.push_back(measure(workload, "ccd-gjk", none, false, queries, true, repeats,
                           [&](int k) { return double(ccdGJKIntersect(&A[k], &B[k], &ccd)); }, [] {}));
    rows.push_back(measure(workload, "ccd-mpr", none, false, queries, true, repeats,
                           [&](int k) { return double(ccdMPRIntersect(&A[k], &B[k], &ccd)); }, [] {}));
  }
#endif
#if GJKX_HAVE_FCL
  {
    std::vector<std::shared_ptr<fcl::CollisionGeometryd>> geometry;
    for (const auto& s : w.shapes) geometry.push_back(fclShape(s));
    std::vector<fcl::Transform3d> tP, tQ;
    for (const auto& q : queries) tP.push_back(fclTransform(q.poseP)), tQ.push_back(fclTransform(q.poseQ));
    for (const auto solver : {fcl::GST_LIBCCD, fcl::GST_INDEP}) {
      const char* name = solver == fcl::GST_LIBCCD ? "fcl-libccd" : "fcl-indep";
      if (boolean) {
        fcl::CollisionRequestd request;
        request.gjk_solver_type = solver;
        const bool guess = warm && solver == fcl::GST_INDEP;
        request.enable_cached_gjk_guess = guess;
        auto reset = [&] { request.cached_gjk_guess = fcl::Vector3d::UnitX(); };
        rows.push_back(measure(workload, name, !warm ? "-" : guess ? "cached_gjk_guess" : "none", false, queries, true, repeats,
                               [&](int k) {
                                 if (queries[k].startsTrajectory) request.cached_gjk_guess = fcl::Vector3d::UnitX();
                                 fcl::CollisionResultd result;
                                 const bool hit = fcl::collide(geometry[queries[k].shapeP].get(), tP[k], geometry[queries[k].shapeQ].get(), tQ[k],
                                                               request, result) > 0;
                                 if (guess) request.cached_gjk_guess = result.cached_gjk_guess;
                                 return hit ? 1.0 : 0.0;
                               },
                               reset));
      } else {
        fcl::DistanceRequestd request;
        request.gjk_solver_type = solver;
        rows.push_back(measure(workload, name, warm ? "none" : "-", false, queries, false, repeats,
                               [&](int k) {
                                 fcl::DistanceResultd result;
                                 const double d = fcl::distance(geometry[queries[k].shapeP].get(), tP[k], geometry[queries[k].shapeQ].get(), tQ[k],
                                                                request, result);
                                 return std::isfinite(d) ? d : std::nan("");
                               },
                               [] {}));
      }
    }
  }
#endif
#if GJKX_HAVE_BULLET
  {
    std::vector<std::shared_ptr<btConvexShape>> shapes;
    for (const auto& s : w.shapes) shapes.push_back(bulletShape(s));
    std::vector<btTransform> tP, tQ;
    for (const auto& q : queries) tP.push_back(bulletTransform(q.poseP)), tQ.push_back(bulletTransform(q.poseQ));
    std::unique_ptr<BulletPair> pair;
    auto answer = [&](int k) {
      // Cold: a fresh detector per query. Warm: one per trajectory, starting from its cached axis.
      if (!warm || queries[k].startsTrajectory || !pair)
        pair = std::make_unique<BulletPair>(shapes[queries[k].shapeP].get(), shapes[queries[k].shapeQ].get());
      const double d = pair->distance(tP[k], tQ[k]);
      if (std::isnan(d)) return d;
      return boolean ? (d <= 0 ? 1.0 : 0.0) : d;
    };
    rows.push_back(measure(workload, boolean ? "bullet-gjk-dist" : "bullet-gjk", warm ? "cached-axis" : "-", false, queries, boolean,
                           repeats, answer, [&] { pair.reset(); }));
  }
#endif
}

}  // namespace detail

/// Runs every comparison; one row per method × workload (distance/boolean × shape × cold/warm).
inline std::vector<GjkRow> runGjkComparisons(const GjkStudyOptions& options) {
  struct Kind {
    const char* name;
    ShapeKind kind;
    int vertices;
  };
  const Kind kinds[] = {{"box", ShapeKind::Box, 8},           {"sphere", ShapeKind::Sphere, 0},
                        {"capsule", ShapeKind::Capsule, 0},   {"polytope12", ShapeKind::Polytope, 12},
                        {"polytope100", ShapeKind::Polytope, 100}, {"polytope1000", ShapeKind::Polytope, 1000}};
  std::vector<GjkRow> rows;
  for (const Kind& kind : kinds) {
    const GjkWorkload w = detail::makeWorkload(kind.name, kind.kind, kind.vertices, options);
    const int heavy = kind.vertices >= 1000 ? 4 : 1;
    for (const bool boolean : {false, true})
      for (const bool warm : {false, true}) {
        const std::string workload = std::string("gjk_") + (boolean ? "boolean_" : "distance_") + kind.name + (warm ? "_warm" : "");
        const int n = int((warm ? w.warm : w.cold).size());
        const int repeats = std::max(1, (options.quick ? 2048 : 16384) / heavy / n);
        switch (kind.kind) {
          case ShapeKind::Box: detail::measureOursBothScalars<Box>(w, workload, warm, boolean, repeats, rows); break;
          case ShapeKind::Sphere:
            detail::measureOursBothScalars<Sphere>(w, workload, warm, boolean, repeats, rows);
            rows.push_back(detail::measureOurs<Sphere<double>>(w, workload, "ours-curved", warm, boolean, repeats, false));
            break;
          case ShapeKind::Capsule:
            detail::measureOursBothScalars<Capsule>(w, workload, warm, boolean, repeats, rows);
            rows.push_back(detail::measureOurs<Capsule<double>>(w, workload, "ours-curved", warm, boolean, repeats, false));
            break;
          case ShapeKind::Polytope: detail::measureOursBothScalars<Polytope>(w, workload, warm, boolean, repeats, rows); break;
        }
        detail::measurePeers(w, workload, warm, boolean, repeats, rows);
      }
  }
  return rows;
}

/// One line per row, for the tables and study_summary.
inline std::string formatGjkRow(const GjkRow& r) {
  char line[512];
  const bool boolean = r.workload.find("boolean") != std::string::npos;
  if (boolean)
    std::snprintf(line, sizeof line, "%-32s %-20s %-17s median %9.1f ns  p99 %9.1f ns  wrong %3d/%-4d  failures %d", r.workload.c_str(),
                  r.method.c_str(), r.warmStart.c_str(), r.medianNs, r.p99Ns, r.wrong, r.judged, r.failures);
  else
    std::snprintf(line, sizeof line, "%-32s %-20s %-17s median %9.1f ns  p99 %9.1f ns  error median %8.1e max %8.1e  failures %d",
                  r.workload.c_str(), r.method.c_str(), r.warmStart.c_str(), r.medianNs, r.p99Ns, r.errorMedian, r.errorMax, r.failures);
  return line;
}

/// The best peer (lowest median) of a workload, "" when it has none.
inline std::string gjkBestPeer(const std::vector<GjkRow>& rows, const std::string& workload) {
  const GjkRow* best = nullptr;
  for (const auto& r : rows)
    if (r.workload == workload && !r.ours && (!best || r.medianNs < best->medianNs)) best = &r;
  return best ? best->method : "";
}

/// `RATIO <workload> ours_vs_best_peer=<ours-double median / best peer median>`, one per
/// workload that has a peer, in the order of the rows.
inline std::vector<std::string> gjkRatioLines(const std::vector<GjkRow>& rows) {
  std::vector<std::string> order;
  std::map<std::string, double> ours, best;
  for (const auto& r : rows) {
    if (std::find(order.begin(), order.end(), r.workload) == order.end()) order.push_back(r.workload);
    if (r.method == "ours-double") ours[r.workload] = r.medianNs;
    if (!r.ours && (!best.count(r.workload) || r.medianNs < best[r.workload])) {
      best[r.workload] = r.medianNs;
    }
  }
  std::vector<std::string> lines;
  for (const auto& w : order) {
    if (!best.count(w) || !ours.count(w)) continue;
    char line[256];
    std::snprintf(line, sizeof line, "RATIO %s ours_vs_best_peer=%.2f", w.c_str(), ours[w] / best[w]);
    lines.push_back(line);
  }
  return lines;
}

}  // namespace gjkx::study
