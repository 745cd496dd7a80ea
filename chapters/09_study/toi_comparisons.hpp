// The time-of-impact comparison of the study (chapter 09): every method on every workload
// of workloads.hpp, against the independent long-double reference there.
//
// Methods (each at the settings listed; "ours" are this library's):
// - static N: gjkx::staticSampling, the static test at N evenly spaced times (N = 2, 8,
//   32); the time of impact is the first sample found intersecting;
// - swept: gjkx::sweepingTest (the hulls of each body at t0 and t1): yes/no only, so its
//   error is not measured, only its misses and false alarms;
// - CA: conservative advancement (the paper's reference [8]), gjkx::conservativeAdvancement:
//   GJK's distance d at t (its proven lower bound), then t += d / L with L the bound on the
//   relative speed of any two points (|v| + |a| + |w| r per body), until d < tol (hit) or
//   t > 1 (no hit); its cap of 10000 steps and a numerical failure are taken as hits;
// - ours: gjkx::timeOfImpact (the paper's extrusion test + Brent) at collision tolerances
//   1e-2 ... 1e-9 in double and 1e-2 ... 1e-5 in float, time tolerance min(sqrt(eps), tol);
// - certified: the same with ExtrusionVariant::Certified (double 1e-7 and 1e-5; float 1e-5);
// - the peers of peers_toi.hpp: FCL naive (toc_err 1e-2, and 1e-3 in the full run), FCL
//   conservative advancement with FCL's default GJK (libccd, "FCL CA") and its own ("FCL CA
//   indep"), Bullet btContinuousConvexCollision; Box2D on the 2D set only
//   (FCL and Bullet on the 3D workloads only).
// Judging (per query): a miss is a reference hit the method does not report; a false
// alarm a reported hit on a clear miss of the reference (never within 0.02); the error is
// |t_method - t_ref| over the hits both report. Undecided answers of ours (iteration cap,
// numerical failure) count as hits, as a caller that must not miss would take them.
// Timing: each (method, query) is run once for its answer, then repeated for about
// `budget` seconds and timed as one batch (steady_clock): one time per query; the table
// gives the median and 99th percentile over the workload's queries.
//
// Also here: the CCD benchmark's sample queries (chapter 05's reader) at collision
// tolerances 1e-4 ... 1e-10 in double: false negatives, false positives, time per query.
#pragma once

#include <gjkx/study/our_settings.hpp>
#include <gjkx/study/workloads.hpp>

#include <cstdint>
#include <limits>
#include <string>
#include <vector>

namespace gjkx::study {

/// Options of the comparison.
struct ToiStudyOptions {
  /// A short run (for study_summary): fewer queries, shorter timing batches, fewer settings.
  bool quick = false;
  /// Seed of the workloads.
  std::uint64_t seed = 4;
  /// The CCD benchmark's sample queries (empty: the build's default, ../shared/data/ccd-queries).
  std::string ccdData;
  /// Progress lines on stderr.
  bool verbose = false;
};

/// One method at one setting on one workload.
struct ToiRow {
  std::string workload;
  std::string family;   ///< static N, swept, CA, ours, certified, FCL naive, FCL CA, Bullet, Box2D
  std::string setting;  ///< e.g. "tol=1e-7", "N=8", "toc_err=1e-2", "-"
  std::string scalar;   ///< double or float
  bool ours = false;
  bool detectionOnly = false;
  int queries = 0, refHits = 0, clearMisses = 0;
  int misses = 0, falseAlarms = 0, reported = 0;
  std::vector<double> errors;  ///< |t - t_ref| over the hits both report
  double errMedian = std::numeric_limits<double>::quiet_NaN(), errMax = std::numeric_limits<double>::quiet_NaN();
  double medianUs = 0, p99Us = 0;
  double meanUs = 0;  ///< the mean: a method with a heavy tail can lead on the median and trail on the mean
  double meanGjkRuns = 0;  ///< GJK runs per query (methods of ours)
  /// "family setting scalar" without the dashes, e.g. "ours tol=1e-7 double".
  std::string label() const {
    std::string s = family;
    if (setting != "-") s += " " + setting;
    return s + " " + scalar;
  }
};

/// The CCD sample queries at one tolerance.
struct CcdRow {
  double tolerance = 0;
  long long queries = 0, truthPositives = 0, positives = 0, fn = 0, fp = 0, capped = 0;
  double usPerQuery = 0;
};

/// Everything the comparison measured.
struct ToiStudyResults {
  std::vector<ToiWorkload> workloads;
  std::vector<ToiRow> rows;
  std::vector<CcdRow> ccd;
  std::string ccdNote;  ///< why the CCD part is missing, if it is
};

namespace detail {


/// A query in one scalar type: shapes, motions, and the relative speed bound L.
template <typename S>
struct Prepared {
  AnyShape<S> P, Q;
  Motion<S> mp, mq;
  S lipschitz;
  explicit Prepared(const ToiQuery& q)
      : P(ourShape<S>(q.P)), Q(ourShape<S>(q.Q)), mp(toMotion<S>(q.motionP)), mq(toMotion<S>(q.motionQ)),
        lipschitz(S(relativeSpeedBound(q))) {}
};

/// What a method said.
struct Outcome {
  bool hit = false;
  double time = 1;
  int gjkRuns = 0;  ///< GJK runs (ours, CA, static, swept; 0 for the peers)
};

/// Ours (double, gjkx::timeOfImpact over [0, 1]) on a prepared query, for toi_profile:
/// without a trace, `calls` calls with callgrind's counting on around them alone
/// (callgrind_markers.hpp); with one, a single traced call outside the counting. The last
/// call's result. Compiled here once, where the comparison instantiates the solver on every
/// shape pair already, rather than again in every program that runs ours.
ToiResult<double> runOurs(const Prepared<double>& p, const ToiSettings<double>& settings, int calls,
                          ToiTrace<double>* trace = nullptr);

/// The q-quantile of x (the smallest element with at least a fraction q at or below it); NaN if empty.
double quantile(std::vector<double> x, double q);
/// The median of x (the mean of the two middle elements for an even count); NaN if empty.
double median(std::vector<double> x);

}  // namespace detail

/// The CCD sample queries at collision tolerances 1e-4 ... 1e-10 (double).
std::vector<CcdRow> runCcdSweep(const std::string& folder, std::string& note);

/// Runs the whole comparison; see the file comment.
ToiStudyResults runToiComparisons(const ToiStudyOptions& options);

/// One table line per row.
std::string formatToiRow(const ToiRow& r);

/// The table's header line (the columns of formatToiRow).
const char* toiTableHeader();

/// The RATIO lines of the ToI comparison: ours (double, tol 1e-7) against the fastest peer
/// and against FCL's conservative advancement (default solver, libccd), per workload, by
/// median time; and, by mean time, against FCL's conservative advancement and Bullet (the
/// peers' times have heavy tails: the two statistics can rank the methods differently).
std::vector<std::string> toiRatioLines(const std::vector<ToiRow>& rows);

/// `MISSES method=<label> workload=<name> misses=N false_alarms=N queries=N`, one per row.
std::vector<std::string> toiMissLines(const std::vector<ToiRow>& rows);

}  // namespace gjkx::study
