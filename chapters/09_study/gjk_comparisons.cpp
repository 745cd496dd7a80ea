// The GJK comparison of the study (see gjk_comparisons.hpp): the measurements of ours and
// the peers, compiled once for every study program that reports it.
#include "gjk_comparisons.hpp"

#include "callgrind_markers.hpp"

#include <gjkx/study/peers.hpp>

#include <chrono>
#include <cstdio>
#include <map>
#include <set>

namespace gjkx::study::gjk_comparison {
namespace detail {

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

/// Ours on one query list of a workload (the warm trajectories or the cold pairs), shapes
/// of type T: the shapes placed as the queries place them, the settings, and one GjkCache
/// carried along each warm trajectory (none for the cold list). A query is begun
/// (beginQuery: a new trajectory starts cold), then answered by intersectOn or gjkOn.
template <typename T>
struct OursOnQueries {
  using S = typename T::Scalar;
  const std::vector<GjkQuery>& queries;
  bool warm;
  std::vector<Placed<T>> P, Q;
  GjkSettings<S> settings;
  IntersectionSettings<S> intersection;
  GjkCache<S> cache;

  /// With `roundedCores` false, spheres and capsules run the paper's GJK on their curved
  /// surfaces instead of on their cores.
  OursOnQueries(const GjkWorkload& w, bool warmList, bool roundedCores = true)
      : queries(warmList ? w.warm : w.cold), warm(warmList) {
    for (const auto& q : queries) {
      P.push_back(Placed<T>{ourShapeAs<T>(w.shapes[q.shapeP]), q.poseP.cast<S>()});
      Q.push_back(Placed<T>{ourShapeAs<T>(w.shapes[q.shapeQ]), q.poseQ.cast<S>()});
    }
    settings.roundedCores = roundedCores;
    intersection.gjk.roundedCores = roundedCores;
  }
  /// Forgets every warm start (before a pass over the list).
  void reset() { cache = GjkCache<S>{}; }
  /// Query k begins: the cache is dropped where a trajectory starts.
  void beginQuery(int k) {
    if (warm && queries[k].startsTrajectory) cache.valid = false;
  }
  /// gjkx::intersect on query k.
  auto intersectOn(int k) { return intersect(P[k], Q[k], intersection, warm ? &cache : nullptr); }
  /// gjkx::gjk on query k.
  auto gjkOn(int k) { return gjk(P[k], Q[k], settings, warm ? &cache : nullptr); }
};

/// Ours (gjkx::gjk for distance, gjkx::intersect for boolean) in scalar S. With
/// `roundedCores` false, spheres and capsules run the paper's GJK on their curved surfaces
/// (the "ours-curved" rows) instead of on their cores.
template <typename T>
GjkRow measureOurs(const GjkWorkload& w, const std::string& workload, const char* method, bool warm, bool boolean, int repeats,
                   bool roundedCores = true) {
  OursOnQueries<T> ours(w, warm, roundedCores);
  const std::vector<GjkQuery>& queries = ours.queries;
  auto reset = [&] { ours.reset(); };
  auto answer = [&](int k) -> double {
    ours.beginQuery(k);
    if (boolean) {
      const auto r = ours.intersectOn(k);
      if (r.status == IntersectionStatus::Disjoint) return 0.0;
      if (r.status == IntersectionStatus::Intersecting) return 1.0;
      return std::nan("");
    }
    const auto r = ours.gjkOn(k);
    if (r.status == GjkStatus::Separated || r.status == GjkStatus::Overlapping) return double(r.distance);
    return std::nan("");
  };
  GjkRow row = measure(workload, method, warm ? "GjkCache" : "-", true, queries, boolean, repeats, answer, reset);
  // The failure statuses, for the float-against-double table: the same calls once more,
  // untimed, in the same order (so the warm caches evolve as in the measured passes).
  reset();
  for (int k = 0; k < int(queries.size()); ++k) {
    ours.beginQuery(k);
    bool cap = false, numerical = false, other = false;
    if (boolean) {
      const IntersectionStatus s = ours.intersectOn(k).status;
      cap = s == IntersectionStatus::IterationCap;
      numerical = s == IntersectionStatus::NumericalFailure;
      other = !cap && !numerical && s != IntersectionStatus::Disjoint && s != IntersectionStatus::Intersecting;
    } else {
      const GjkStatus s = ours.gjkOn(k).status;
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

/// profileOurs() with shapes of type T.
template <typename T>
GjkProfile profileOursAs(const GjkWorkload& w, bool boolean, bool cold, int passes) {
  OursOnQueries<T> ours(w, !cold);
  GjkProfile profile;
  for (int pass = 0; pass < passes; ++pass) {
    for (int k = 0; k < int(ours.queries.size()); ++k) {
      ours.beginQuery(k);
      GJKX_PROFILE_START();
      if (boolean) {
        const auto result = ours.intersectOn(k);
        GJKX_PROFILE_STOP();
        ++profile.ends[toString(result.status)];
        profile.iterations += result.iterations;
      } else {
        const auto result = ours.gjkOn(k);
        GJKX_PROFILE_STOP();
        ++profile.ends[toString(result.status)];
        profile.iterations += result.iterations;
      }
      ++profile.calls;
    }
  }
  return profile;
}

template <template <typename> class Shape>
GjkProfile profileOursScalar(const GjkWorkload& w, bool boolean, bool cold, bool single, int passes) {
  return single ? profileOursAs<Shape<float>>(w, boolean, cold, passes) : profileOursAs<Shape<double>>(w, boolean, cold, passes);
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
    std::vector<peers::CcdObject> A(n), B(n);
    for (int k = 0; k < n; ++k) {
      A[k] = peers::CcdObject{&w.shapes[queries[k].shapeP], queries[k].poseP};
      B[k] = peers::CcdObject{&w.shapes[queries[k].shapeQ], queries[k].poseQ};
    }
    const ccd_t ccd = peers::ccdSettings();
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
    for (const auto& s : w.shapes) geometry.push_back(peers::fclShape(s));
    std::vector<fcl::Transform3d> tP, tQ;
    for (const auto& q : queries) tP.push_back(peers::fclTransform(q.poseP)), tQ.push_back(peers::fclTransform(q.poseQ));
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
    for (const auto& s : w.shapes) shapes.push_back(peers::bulletShape(s));
    std::vector<btTransform> tP, tQ;
    for (const auto& q : queries) tP.push_back(peers::bulletTransform(q.poseP)), tQ.push_back(peers::bulletTransform(q.poseQ));
    std::unique_ptr<peers::BulletPair> pair;
    auto answer = [&](int k) {
      // Cold: a fresh detector per query. Warm: one per trajectory, starting from its cached axis.
      if (!warm || queries[k].startsTrajectory || !pair)
        pair = std::make_unique<peers::BulletPair>(shapes[queries[k].shapeP].get(), shapes[queries[k].shapeQ].get());
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

GjkProfile profileOurs(const GjkWorkload& w, bool boolean, bool cold, bool single, int passes) {
  switch (w.kind) {
    case ShapeKind::Box: return detail::profileOursScalar<Box>(w, boolean, cold, single, passes);
    case ShapeKind::Sphere: return detail::profileOursScalar<Sphere>(w, boolean, cold, single, passes);
    case ShapeKind::Capsule: return detail::profileOursScalar<Capsule>(w, boolean, cold, single, passes);
    default: return detail::profileOursScalar<Polytope>(w, boolean, cold, single, passes);
  }
}

/// Runs every comparison; one row per method × workload (distance/boolean × shape × cold/warm).
std::vector<GjkRow> runGjkComparisons(const GjkStudyOptions& options) {
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
          case ShapeKind::Polygon:
          case ShapeKind::Disk: break;  // the 2D set is the time-of-impact study's
        }
        detail::measurePeers(w, workload, warm, boolean, repeats, rows);
      }
  }
  return rows;
}

/// One line per row, for the tables and study_summary.
std::string formatGjkRow(const GjkRow& r) {
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
std::string gjkBestPeer(const std::vector<GjkRow>& rows, const std::string& workload) {
  const GjkRow* best = nullptr;
  for (const auto& r : rows)
    if (r.workload == workload && !r.ours && (!best || r.medianNs < best->medianNs)) best = &r;
  return best ? best->method : "";
}

/// `RATIO <workload> ours_vs_best_peer=<ours-double median / best peer median>`, one per
/// workload that has a peer, in the order of the rows.
std::vector<std::string> gjkRatioLines(const std::vector<GjkRow>& rows) {
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

}  // namespace gjkx::study::gjk_comparison
