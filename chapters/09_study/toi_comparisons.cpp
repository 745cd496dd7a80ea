// The time-of-impact comparison of the study (see toi_comparisons.hpp): its methods and
// the runs, compiled once for every study program that reports it.
#include "toi_comparisons.hpp"

#include "callgrind_markers.hpp"

#include <gjkx/study/ccd_queries.hpp>
#include <gjkx/study/peers_toi.hpp>

#include <gjkx/brent/conservative_advancement.hpp>
#include <gjkx/brent/time_of_impact.hpp>
#include <gjkx/extrusion/static_sampling.hpp>
#include <gjkx/extrusion/sweeping.hpp>
#include <gjkx/support_mapping/placed.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <map>
#include <numeric>
#include <variant>

#ifndef GJKX_CCD_QUERIES_DIR
#define GJKX_CCD_QUERIES_DIR ""
#endif

namespace gjkx::study {
namespace detail {

/// Runs `call` once for its answer, then in three batches of about `budget` / 3 seconds
/// each (at least one call each); returns the median batch's seconds per call (a batch
/// preempted by another process does not count).
template <typename F>
double timeCalls(double budget, Outcome& out, F&& call) {
  using Clock = std::chrono::steady_clock;
  auto start = Clock::now();
  out = call();
  const double first = std::chrono::duration<double>(Clock::now() - start).count();
  // A slow first call (cold caches, or preempted) does not decide the time: three batches do.
  const int reps = first >= budget / 3 ? 1 : int(std::min(100000.0, budget / 3 / std::max(first, 1e-9)));
  double sink = 0;
  double batch[3];
  for (double& b : batch) {
    start = Clock::now();
    for (int k = 0; k < reps; ++k) sink += call().time;
    b = std::chrono::duration<double>(Clock::now() - start).count() / reps;
  }
  if (sink == -1) std::fprintf(stderr, " ");  // keeps the calls
  std::sort(batch, batch + 3);
  return batch[1];
}

/// Runs a method of ours (a generic callable on two Moving bodies and L) with concrete shape types.
template <typename S, typename F>
double timeOurs(const Prepared<S>& p, double budget, Outcome& out, F&& method) {
  return std::visit(
      [&](const auto& a, const auto& b) {
        const auto P = moving(a, p.mp);
        const auto Q = moving(b, p.mq);
        return timeCalls(budget, out, [&] { return method(P, Q, p.lipschitz); });
      },
      p.P, p.Q);
}

// The methods of ours, as generic callables (P, Q, L) -> Outcome: each calls the library.
struct StaticSampling {
  int samples;
  template <typename MP, typename MQ, typename S>
  Outcome operator()(const MP& P, const MQ& Q, S /*L*/) const {
    const StaticSamplingResult<S> r = staticSampling(P, Q, S(0), S(1), samples);
    const bool hit = reportsCollision(r.status);
    return {hit, hit ? double(r.time) : 1.0, r.samplesRun};
  }
};
struct Swept {
  template <typename MP, typename MQ, typename S>
  Outcome operator()(const MP& P, const MQ& Q, S /*L*/) const {
    return {sweepingTest(P, Q, S(0), S(1)).status != IntersectionStatus::Disjoint, 0.0, 1};
  }
};
struct ConservativeAdvancement {
  double tolerance;
  template <typename MP, typename MQ, typename S>
  Outcome operator()(const MP& P, const MQ& Q, S L) const {
    const ConservativeAdvancementResult<S> r = conservativeAdvancement(P, Q, S(0), S(1), caSettings(tolerance, L));
    const bool hit = reportsCollision(r.status);  // the cap and a numerical failure: undecided, taken as hits
    return {hit, hit ? double(r.time) : 1.0, r.steps};
  }
};
struct Ours {
  double tolerance;
  ExtrusionVariant variant;
  template <typename MP, typename MQ, typename S>
  Outcome operator()(const MP& P, const MQ& Q, S /*L*/) const {
    const ToiResult<S> r = timeOfImpact(P, Q, S(0), S(1), toiSettings<S>(tolerance, variant));
    return {reportsCollision(r.status), double(r.time), r.gjkRuns};
  }
};

ToiResult<double> runOurs(const Prepared<double>& p, const ToiSettings<double>& settings, int calls,
                          ToiTrace<double>* trace) {
  return std::visit(
      [&](const auto& a, const auto& b) {
        const auto P = moving(a, p.mp);
        const auto Q = moving(b, p.mq);
        if (trace) return timeOfImpact(P, Q, 0.0, 1.0, settings, trace);
        ToiResult<double> r{};
        GJKX_PROFILE_START();
        for (int k = 0; k < calls; ++k) r = timeOfImpact(P, Q, 0.0, 1.0, settings);
        GJKX_PROFILE_STOP();
        return r;
      },
      p.P, p.Q);
}

/// One query, prepared for every method.
struct QueryContext {
  const ToiQuery& query;
  Prepared<double> d;
  Prepared<float> f;
#if GJKX_HAVE_FCL
  std::unique_ptr<peers::FclQuery> fcl;
#endif
#if GJKX_HAVE_BULLET
  std::unique_ptr<peers::BulletQuery> bullet;
#endif
#if GJKX_HAVE_BOX2D
  std::unique_ptr<peers::Box2dQuery> box2d;
#endif
  explicit QueryContext(const ToiQuery& q) : query(q), d(q), f(q) {
#if GJKX_HAVE_FCL
    if (!q.planar) fcl = std::make_unique<peers::FclQuery>(q);
#endif
#if GJKX_HAVE_BULLET
    if (!q.planar) bullet = std::make_unique<peers::BulletQuery>(q);
#endif
#if GJKX_HAVE_BOX2D
    if (q.planar) box2d = std::make_unique<peers::Box2dQuery>(q);
#endif
  }
};

/// A method at one setting: runs on one query (answer in `out`), returns seconds per call.
struct Method {
  std::string family, setting, scalar;
  bool ours = true, detectionOnly = false;
  bool planar = true, spatial = true;  ///< runs on the 2D set / on the 3D workloads
  std::function<double(const QueryContext&, double, Outcome&)> run;
};

inline std::string tolText(double tol) {
  char s[32];
  std::snprintf(s, sizeof s, "tol=1e%d", int(std::lround(std::log10(tol))));
  return s;
}

template <typename F>
void addOurs(std::vector<Method>& methods, const std::string& family, const std::string& setting, bool useFloat, F callable,
             bool detectionOnly = false) {
  Method m;
  m.family = family;
  m.setting = setting;
  m.scalar = useFloat ? "float" : "double";
  m.detectionOnly = detectionOnly;
  if (useFloat)
    m.run = [callable](const QueryContext& c, double budget, Outcome& out) { return timeOurs(c.f, budget, out, callable); };
  else
    m.run = [callable](const QueryContext& c, double budget, Outcome& out) { return timeOurs(c.d, budget, out, callable); };
  methods.push_back(std::move(m));
}

/// Adds a peer's method: `call(context)` gives its peers::PeerOutcome, timed as ours are.
template <typename Call>
void addPeer(std::vector<Method>& methods, Method m, Call call) {
  m.run = [call](const QueryContext& c, double budget, Outcome& out) {
    return timeCalls(budget, out, [&] {
      const peers::PeerOutcome r = call(c);
      return Outcome{r.hit, r.time};
    });
  };
  methods.push_back(std::move(m));
}

inline std::vector<Method> methods(bool quick) {
  std::vector<Method> out;
  for (int n : {2, 8, 32}) addOurs(out, "static", "N=" + std::to_string(n), false, StaticSampling{n});
  addOurs(out, "static", "N=8", true, StaticSampling{8});
  addOurs(out, "swept", "-", false, Swept{}, true);
  addOurs(out, "swept", "-", true, Swept{}, true);
  for (double tol : {1e-3, 1e-5, 1e-7}) addOurs(out, "CA", tolText(tol), false, ConservativeAdvancement{tol});
  for (double tol : {1e-3, 1e-5}) addOurs(out, "CA", tolText(tol), true, ConservativeAdvancement{tol});
  for (double tol : {1e-2, 1e-3, 1e-5, 1e-7, 1e-9}) addOurs(out, "ours", tolText(tol), false, Ours{tol, ExtrusionVariant::Paper});
  for (double tol : {1e-2, 1e-3, 1e-5}) addOurs(out, "ours", tolText(tol), true, Ours{tol, ExtrusionVariant::Paper});
  addOurs(out, "certified", tolText(1e-7), false, Ours{1e-7, ExtrusionVariant::Certified});
  addOurs(out, "certified", tolText(1e-5), false, Ours{1e-5, ExtrusionVariant::Certified});
  addOurs(out, "certified", tolText(1e-5), true, Ours{1e-5, ExtrusionVariant::Certified});
#if GJKX_HAVE_FCL
  for (double tocErr : quick ? std::vector<double>{1e-2} : std::vector<double>{1e-2, 1e-3})
    addPeer(out, {"FCL naive", tocErr > 5e-3 ? "toc_err=1e-2" : "toc_err=1e-3", "double", false, false, false, true, {}},
            [tocErr](const QueryContext& c) { return c.fcl->run(false, tocErr); });
  for (const bool indep : {false, true})
    addPeer(out, {indep ? "FCL CA indep" : "FCL CA", "-", "double", false, false, false, true, {}},
            [indep](const QueryContext& c) { return c.fcl->run(true, 1e-4, indep ? fcl::GST_INDEP : fcl::GST_LIBCCD); });
#endif
#if GJKX_HAVE_BULLET
  addPeer(out, {"Bullet", "-", "float", false, false, false, true, {}}, [](const QueryContext& c) { return c.bullet->run(); });
#endif
#if GJKX_HAVE_BOX2D
  addPeer(out, {"Box2D", "-", "float", false, false, true, false, {}}, [](const QueryContext& c) { return c.box2d->run(); });
#endif
  (void)quick;
  return out;
}

double quantile(std::vector<double> x, double q) {
  if (x.empty()) return std::numeric_limits<double>::quiet_NaN();
  std::sort(x.begin(), x.end());
  const std::size_t k = std::min(x.size() - 1, std::size_t(std::ceil(q * double(x.size()))) - (q > 0 ? 1 : 0));
  return x[k];
}
double median(std::vector<double> x) {
  if (x.empty()) return std::numeric_limits<double>::quiet_NaN();
  std::sort(x.begin(), x.end());
  const std::size_t n = x.size();
  return n % 2 ? x[n / 2] : 0.5 * (x[n / 2 - 1] + x[n / 2]);
}

}  // namespace detail

/// The CCD sample queries at collision tolerances 1e-4 ... 1e-10 (double).
std::vector<CcdRow> runCcdSweep(const std::string& folder, std::string& note) {
  std::vector<CcdRow> rows;
  std::string dir = folder.empty() ? std::string(GJKX_CCD_QUERIES_DIR) : folder;
  if (dir.empty() || !std::filesystem::is_directory(dir)) {
    note = "CCD sample queries not found (looked for '" + dir + "'); pass --ccd-data DIR";
    return rows;
  }
  const std::vector<ccd::QueryFile> files = ccd::readQueryFolder(dir);
  for (double tol : {1e-4, 1e-6, 1e-8, 1e-10}) {
    ToiSettings<double> settings;
    settings.collisionTolerance = tol;
    CcdRow row;
    row.tolerance = tol;
    double seconds = 0;
    for (const auto& file : files) {
      const ccd::FileRun<double> run = ccd::runQueries(file, settings);
      row.queries += (long long)file.queries.size();
      for (const auto& q : file.queries) row.truthPositives += q.truth;
      row.positives += run.positives;
      row.fn += run.falseNegatives;
      row.fp += run.falsePositives;
      row.capped += run.capped;
      seconds += run.seconds;
    }
    row.usPerQuery = row.queries ? 1e6 * seconds / double(row.queries) : 0;
    rows.push_back(row);
  }
  return rows;
}

/// Runs the whole comparison; see the file comment.
ToiStudyResults runToiComparisons(const ToiStudyOptions& options) {
  ToiStudyResults results;
  WorkloadOptions wo;
  wo.queriesPerWorkload = options.quick ? 40 : 120;
  wo.seed = options.seed;
  const auto start = std::chrono::steady_clock::now();
  results.workloads = makeWorkloads(wo);
  if (options.verbose)
    std::fprintf(stderr, "toi: workloads and references in %.1f s\n",
                 std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  const double budget = options.quick ? 2e-4 : 1e-3;
  const std::vector<detail::Method> methods = detail::methods(options.quick);
  for (const ToiWorkload& w : results.workloads) {
    std::vector<std::unique_ptr<detail::QueryContext>> contexts;
    for (const auto& q : w.queries) contexts.push_back(std::make_unique<detail::QueryContext>(q));
    for (const detail::Method& m : methods) {
      if (w.planar ? !m.planar : !m.spatial) continue;
      ToiRow row;
      row.workload = w.name;
      row.family = m.family;
      row.setting = m.setting;
      row.scalar = m.scalar;
      row.ours = m.ours;
      row.detectionOnly = m.detectionOnly;
      std::vector<double> times;
      for (const auto& c : contexts) {
        detail::Outcome out;
        const double seconds = m.run(*c, budget, out);
        times.push_back(1e6 * seconds);
        const ToiQuery& q = c->query;
        ++row.queries;
        row.refHits += q.refHit;
        row.clearMisses += q.clearMiss;
        row.reported += out.hit;
        if (q.refHit && !out.hit) ++row.misses;
        if (q.clearMiss && out.hit) ++row.falseAlarms;
        if (q.refHit && out.hit && !m.detectionOnly) row.errors.push_back(std::abs(out.time - q.tRef));
        row.meanGjkRuns += out.gjkRuns;
      }
      row.meanGjkRuns /= std::max(1, row.queries);
      row.medianUs = detail::median(times);
      row.p99Us = detail::quantile(times, 0.99);
      row.meanUs = std::accumulate(times.begin(), times.end(), 0.0) / double(std::max<std::size_t>(1, times.size()));
      if (!row.errors.empty()) {
        row.errMedian = detail::median(row.errors);
        row.errMax = *std::max_element(row.errors.begin(), row.errors.end());
      }
      results.rows.push_back(std::move(row));
    }
    if (options.verbose)
      std::fprintf(stderr, "toi: %s done at %.1f s\n", w.name.c_str(),
                   std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
  results.ccd = runCcdSweep(options.ccdData, results.ccdNote);
  return results;
}

/// One table line per row.
std::string formatToiRow(const ToiRow& r) {
  char line[512];
  auto err = [](double e) {
    char s[32];
    if (std::isnan(e)) return std::string("       -");
    std::snprintf(s, sizeof s, "%8.1e", e);
    return std::string(s);
  };
  char gjk[16] = "    -";
  if (r.ours) std::snprintf(gjk, sizeof gjk, "%5.1f", r.meanGjkRuns);
  std::snprintf(line, sizeof line, "%-11s %-10s %-13s %-6s %9.2f %9.2f %5d/%-3d %4d/%-3d %s %s %s", r.workload.c_str(), r.family.c_str(),
                r.setting.c_str(), r.scalar.c_str(), r.medianUs, r.p99Us, r.misses, r.refHits, r.falseAlarms, r.clearMisses,
                err(r.errMedian).c_str(), err(r.errMax).c_str(), gjk);
  return line;
}
const char* toiTableHeader() {
  return "workload    method     setting       scalar  med_us    p99_us  misses    f.alarms err_med  err_max   gjk/q";
}

/// The RATIO lines of the ToI comparison: ours (double, tol 1e-7) against the fastest peer
/// and against FCL's conservative advancement (default solver, libccd), per workload, by
/// median time; and, by mean time, against FCL's conservative advancement and Bullet (the
/// peers' times have heavy tails: the two statistics can rank the methods differently).
std::vector<std::string> toiRatioLines(const std::vector<ToiRow>& rows) {
  std::vector<std::string> order;
  std::map<std::string, double> ours, best, fclCa, oursMean, fclCaMean, bulletMean;
  std::map<std::string, std::string> bestName;
  for (const auto& r : rows) {
    if (std::find(order.begin(), order.end(), r.workload) == order.end()) order.push_back(r.workload);
    if (r.family == "ours" && r.setting == "tol=1e-7" && r.scalar == "double") {
      ours[r.workload] = r.medianUs;
      oursMean[r.workload] = r.meanUs;
    }
    if (!r.ours && (!best.count(r.workload) || r.medianUs < best[r.workload])) {
      best[r.workload] = r.medianUs;
      bestName[r.workload] = r.family + (r.setting == "-" ? "" : " " + r.setting);
    }
    if (r.family == "FCL CA") fclCa[r.workload] = r.medianUs, fclCaMean[r.workload] = r.meanUs;
    if (r.family == "Bullet") bulletMean[r.workload] = r.meanUs;
  }
  std::vector<std::string> lines;
  for (const auto& w : order) {
    if (!ours.count(w)) continue;
    char line[256];
    if (best.count(w)) {
      std::snprintf(line, sizeof line, "RATIO toi_%s ours_vs_best_peer=%.2f best_peer=%s", w.c_str(), ours[w] / best[w],
                    bestName[w].c_str());
      lines.push_back(line);
    }
    if (fclCa.count(w)) {
      std::snprintf(line, sizeof line, "RATIO toi_%s ours_vs_fcl_ca=%.2f", w.c_str(), ours[w] / fclCa[w]);
      lines.push_back(line);
      std::snprintf(line, sizeof line, "RATIO toi_%s ours_vs_fcl_ca_mean=%.2f", w.c_str(), oursMean[w] / fclCaMean[w]);
      lines.push_back(line);
    }
    if (bulletMean.count(w)) {
      std::snprintf(line, sizeof line, "RATIO toi_%s ours_vs_bullet_mean=%.2f", w.c_str(), oursMean[w] / bulletMean[w]);
      lines.push_back(line);
    }
  }
  return lines;
}

/// `MISSES method=<label> workload=<name> misses=N false_alarms=N queries=N`, one per row.
std::vector<std::string> toiMissLines(const std::vector<ToiRow>& rows) {
  std::vector<std::string> lines;
  for (const auto& r : rows) {
    std::string name;  // the label, spaces as '_', '=' dropped: "ours_tol1e-7_double"
    for (char c : r.label())
      if (c != '=') name += c == ' ' ? '_' : c;
    char line[256];
    std::snprintf(line, sizeof line, "MISSES method=%s workload=%s misses=%d false_alarms=%d queries=%d", name.c_str(), r.workload.c_str(),
                  r.misses, r.falseAlarms, r.queries);
    lines.push_back(line);
  }
  return lines;
}

}  // namespace gjkx::study
