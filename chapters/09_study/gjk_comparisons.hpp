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
// step to the next (ours: GjkCache; see gjkx/study/peers.hpp for the peers).
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
//
// Namespace gjkx::study::gjk_comparison: the GJK comparison's own workloads (static pairs
// at poses) and its own exact reference (`ref`), apart from the time-of-impact study's
// (gjkx::study::ref in workloads.hpp).
#pragma once

#include <gjkx/study/shape_description.hpp>

#include <gjkx/gjk/gjk.hpp>
#include <gjkx/reference/polytope_distance.hpp>
#include <gjkx/support_mapping/placed.hpp>
#include <gjkx/supporting_distance/intersection.hpp>

#include <algorithm>
#include <functional>
#include <limits>
#include <map>
#include <random>
#include <string>
#include <vector>

namespace gjkx::study::gjk_comparison {

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
// The closest points and the brute-force polytope distance are the reference library's
// (gjkx/reference: sliver-safe, long double); here only the study's shapes are mapped to it.
namespace ref {
using Real = reference::Real;
using RVec = reference::Vec;

/// A polytope at a pose, in world coordinates (long double) as the reference library takes it.
inline reference::WorldPolytope toWorld(const Polytope<double>& shape, const Pose<double>& pose) {
  const Eigen::Matrix<Real, 3, 3> R = pose.rotation.cast<Real>();
  const RVec t = pose.translation.cast<Real>();
  std::vector<RVec> vertices;
  for (const auto& v : shape.vertices()) vertices.push_back(R * v.cast<Real>() + t);
  return reference::WorldPolytope::fromTriangles(std::move(vertices), shape.triangles());
}

/// The exact distance (0 when overlapping) between two study shapes at their poses.
/// `boxHulls` holds a box's hull (its 8 corners) for the brute force.
inline Real distance(const ShapeDescription& P, const Pose<double>& poseP, const ShapeDescription& Q, const Pose<double>& poseQ) {
  const RVec cP = poseP.translation.cast<Real>(), cQ = poseQ.translation.cast<Real>();
  switch (P.kind) {
    case ShapeKind::Sphere: return std::max(Real(0), (cQ - cP).norm() - Real(P.radius) - Real(Q.radius));
    case ShapeKind::Capsule: {
      auto end = [](const ShapeDescription& d, const Pose<double>& pose, double sign) {
        return RVec(pose.rotation.cast<Real>() * RVec(0, 0, Real(sign * d.halfLength)) + pose.translation.cast<Real>());
      };
      const Real axes = reference::segmentSegmentDistance(end(P, poseP, -1), end(P, poseP, 1), end(Q, poseQ, -1), end(Q, poseQ, 1));
      return std::max(Real(0), axes - Real(P.radius) - Real(Q.radius));
    }
    default: {
      auto hull = [](const ShapeDescription& d) {
        if (d.kind == ShapeKind::Polytope) return *d.hull;
        std::vector<Vector3<double>> corners;
        for (int k = 0; k < 8; ++k)
          corners.emplace_back((k & 1 ? 1 : -1) * d.halfExtents.x(), (k & 2 ? 1 : -1) * d.halfExtents.y(), (k & 4 ? 1 : -1) * d.halfExtents.z());
        return Polytope<double>::hull(corners);
      };
      return reference::distance(toWorld(hull(P), poseP), toWorld(hull(Q), poseQ));
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
  std::vector<ShapeDescription> shapes;
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

// Boolean: reference distances in (0, band] are not judged. The band is above the
// largest collision tolerance of a method here (ours in float: sqrt(eps_float) = 3.5e-4),
// which calls a pair that close "intersecting" by design (§2.3).
constexpr double kBand = 5e-4;

/// Our shape of concrete type T (Box<S>, Sphere<S>, Capsule<S>, Polytope<S>) for a description.
template <typename T>
T ourShapeAs(const ShapeDescription& d) {
  return std::get<T>(ourShape<typename T::Scalar>(d));
}

}  // namespace detail

/// What profileOurs() counted.
struct GjkProfile {
  long long calls = 0;                    ///< queries answered (queries × passes)
  long long iterations = 0;               ///< GJK iterations over all calls
  std::map<std::string, long long> ends;  ///< calls by the status they ended in
};

/// Our GJK query on a workload, for gjk_profile: `intersect` (boolean) or `gjk` (distance)
/// on every query of the warm list (or the cold one), `passes` times in order, one GjkCache
/// carried along each trajectory (none when cold), in float or double, with callgrind's
/// counting on around each call alone (callgrind_markers.hpp). Compiled here once, with the
/// rest of ours on every shape type.
GjkProfile profileOurs(const GjkWorkload& w, bool boolean, bool cold, bool single, int passes);

/// Runs every comparison; one row per method × workload (distance/boolean × shape × cold/warm).
std::vector<GjkRow> runGjkComparisons(const GjkStudyOptions& options);

/// One line per row, for the tables and study_summary.
std::string formatGjkRow(const GjkRow& r);

/// The best peer (lowest median) of a workload, "" when it has none.
std::string gjkBestPeer(const std::vector<GjkRow>& rows, const std::string& workload);

/// `RATIO <workload> ours_vs_best_peer=<ours-double median / best peer median>`, one per
/// workload that has a peer, in the order of the rows.
std::vector<std::string> gjkRatioLines(const std::vector<GjkRow>& rows);

}  // namespace gjkx::study::gjk_comparison
