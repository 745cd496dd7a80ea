// gjkx_toi_refinements: what each refinement of the time-of-impact solver beyond §5 buys.
//
//   gjkx_toi_refinements [--queries N] [--ccd FOLDER] [--out FILE.md]
//
// Runs §5 exactly as the paper wrote it (`ToiSettings::paper()`), the paper with one
// refinement turned on, this project's solver (`ToiSettings::gjkx()`) and ours with one
// refinement turned off, on the study's workloads (gjkx/study/workloads.hpp: linear,
// ballistic and screw motions of boxes, capsules and polytopes of 12 to 1000 vertices,
// near misses, the 2D set that spins up to 3 rad) and on the CCD benchmark's sample
// queries where they are found (../shared/data/ccd-queries). Every run uses the paper's
// extrusion test, in double, at the torso's collision tolerance (sqrt of float's epsilon),
// so that the rows differ by their switches only.
//
// Each row gives the work in counts that do not depend on the machine: Brent iterations
// (the mean over the queries that ran Brent, and the worst), complete extrusion tests and
// supporting distances per query, the share of photo finishes among the queries that ran
// Brent, iteration caps, and the verdicts against the long-double reference (misses,
// false alarms on clear misses). Counts only, so that the file is the same on every
// machine (supportHints saves climbing steps, which no column counts; a profiler or the
// study's timings show it). With --out the tables are written as Markdown for the docs
// (figures/data/toi-refinements.md); they always go to standard output.
//
// Coherence between queries needs a sequence of queries of one pair: gjkx_simulate measures
// it (--no-coherence). The query's clock changes nothing here (every query starts at t = 0).
#include "../command_line.hpp"
#include "../formatting.hpp"

#include <gjkx/study/ccd_queries.hpp>
#include <gjkx/study/workloads.hpp>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

using namespace gjkx;
using namespace gjkx::study;
using chapter::format;

namespace {

// One configuration of the solver: its name and its settings.
struct Config {
  std::string name;
  ToiSettings<double> settings;
};

// The switches, by name, so that each can be turned on in the paper or off in ours.
struct Switch {
  const char* name;
  bool ToiSettings<double>::*member;
};
const Switch kSwitches[] = {
    {"warmStart", &ToiSettings<double>::warmStart},     {"supportHints", &ToiSettings<double>::supportHints},
    {"farEndReuse", &ToiSettings<double>::farEndReuse}, {"probe", &ToiSettings<double>::probe},
    {"leap", &ToiSettings<double>::leap},               {"separatingAtStart", &ToiSettings<double>::separatingAtStart},
    {"inFrameOfP", &ToiSettings<double>::inFrameOfP},
};

// What a configuration did over all queries.
struct Tally {
  long queries = 0, brentQueries = 0, brentIterations = 0, brentMax = 0, completeTests = 0, sdEvaluations = 0;
  long photoFinishes = 0, caps = 0, misses = 0, falseAlarms = 0;
  void add(const ToiResult<double>& r) {
    ++queries;
    completeTests += r.gjkRuns;
    sdEvaluations += r.sdEvaluations;
    if (r.status == ToiStatus::IterationCap) ++caps;
    if (r.brentIterations > 0) {
      ++brentQueries;
      brentIterations += r.brentIterations;
      brentMax = std::max(brentMax, long(r.brentIterations));
      if (r.status == ToiStatus::PhotoFinish) ++photoFinishes;
    }
  }
};

// A workload query prepared once: its bodies in double and its reference.
struct Prepared {
  AnyShape<double> P, Q;
  Motion<double> mp, mq;
  bool refHit, clearMiss;
};

ToiResult<double> solve(const Prepared& p, const ToiSettings<double>& settings) {
  return std::visit(
      [&](const auto& a, const auto& b) { return timeOfImpact(moving(a, p.mp), moving(b, p.mq), 0.0, 1.0, settings); },
      p.P, p.Q);
}

Tally run(const Config& c, const std::vector<Prepared>& queries, const std::vector<ccd::QueryFile>& ccdFiles) {
  Tally t;
  for (const Prepared& p : queries) {
    const ToiResult<double> r = solve(p, c.settings);
    t.add(r);
    if (p.refHit && !reportsCollision(r.status)) ++t.misses;
    if (p.clearMiss && reportsCollision(r.status)) ++t.falseAlarms;
  }
  for (const ccd::QueryFile& file : ccdFiles) {
    const ccd::FileRun<double> fr = ccd::runQueries(file, c.settings);
    for (const ToiResult<double>& r : fr.results) t.add(r);
    t.misses += fr.falseNegatives;
    t.falseAlarms += fr.falsePositives;
  }
  return t;
}

// One table: every configuration on one group of queries.
void table(std::ostream& md, const std::string& title, const std::vector<Config>& configs,
           const std::vector<Prepared>& queries, const std::vector<ccd::QueryFile>& ccdFiles) {
  md << "**" << title << "**\n\n";
  md << "| solver | Brent mean | Brent max | tests | SDs | photo finish | caps | misses | false alarms |\n";
  md << "| --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |\n";
  for (const Config& c : configs) {
    const Tally t = run(c, queries, ccdFiles);
    const double n = double(std::max(1L, t.queries)), nb = double(std::max(1L, t.brentQueries));
    md << "| " << c.name << " | " << format("%.2f", double(t.brentIterations) / nb) << " | " << t.brentMax << " | "
       << format("%.2f", double(t.completeTests) / n) << " | " << format("%.1f", double(t.sdEvaluations) / n) << " | "
       << format("%.0f%%", 100.0 * double(t.photoFinishes) / nb) << " | " << t.caps << " | " << t.misses << " | "
       << t.falseAlarms << " |\n";
    std::fprintf(stderr, "gjkx_toi_refinements: %s, %s\n", title.c_str(), c.name.c_str());
  }
  md << "\n";
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"What each refinement of the time-of-impact solver beyond §5 buys: the paper's solver, one "
               "refinement on, ours, one refinement off, on the study's workloads and the CCD sample queries.",
               "gjkx_toi_refinements"};
  int perWorkload = 64;
  std::string ccdFolder = GJKX_CCD_QUERIES_DIR, out;
  app.add_option("--queries", perWorkload, "queries per workload of the study")->check(CLI::Range(1, 100000))->capture_default_str();
  app.add_option("--ccd", ccdFolder, "the CCD benchmark's sample queries (skipped when absent)")->capture_default_str();
  app.add_option("--out", out, "also write the table as Markdown to this file");
  chapter::parseOrExit(app, argc, argv);

  WorkloadOptions options;
  options.queriesPerWorkload = perWorkload;
  std::vector<Prepared> all, spinning;
  std::vector<std::string> names;
  for (const ToiWorkload& w : makeWorkloads(options)) {
    names.push_back(w.name);
    const bool spins = w.name == "screw_w1.5" || w.name == "screw_w3.0" || w.name == "planar_2d";
    for (const ToiQuery& q : w.queries) {
      const Prepared p{ourShape<double>(q.P), ourShape<double>(q.Q), toMotion<double>(q.motionP),
                       toMotion<double>(q.motionQ), q.refHit, q.clearMiss};
      all.push_back(p);
      if (spins) spinning.push_back(p);
    }
  }
  std::vector<ccd::QueryFile> ccdFiles;
  if (std::filesystem::is_directory(ccdFolder)) ccdFiles = ccd::readQueryFolder(ccdFolder);
  long ccdQueries = 0;
  for (const ccd::QueryFile& f : ccdFiles) ccdQueries += long(f.queries.size());

  const double tolerance = double(defaultCollisionTolerance<float>());
  auto base = [&](ToiSettings<double> s) {
    s.collisionTolerance = tolerance;
    return s;
  };
  std::vector<Config> configs{{"paper", base(ToiSettings<double>::paper())}};
  for (const Switch& sw : kSwitches) {
    Config c{std::string("paper + ") + sw.name, base(ToiSettings<double>::paper())};
    c.settings.*sw.member = true;
    configs.push_back(c);
  }
  configs.push_back({"gjkx", base(ToiSettings<double>::gjkx())});
  for (const Switch& sw : kSwitches) {
    Config c{std::string("gjkx - ") + sw.name, base(ToiSettings<double>::gjkx())};
    c.settings.*sw.member = false;
    configs.push_back(c);
  }
  Config band{"gjkx + acceptedBand (1.5 tol after 24)", base(ToiSettings<double>::gjkx())};
  band.settings.acceptedDistance = 1.5 * tolerance;
  band.settings.acceptedAfter = 24;
  configs.push_back(band);

  std::ostringstream md;
  md << "<!-- Written by gjkx_toi_refinements --out (chapters/05_brent/toi_refinements.cpp); do not edit. -->\n\n";
  md << "The paper's extrusion test, double, collision tolerance " << format("%.4g", tolerance)
     << " (the torso's), time tolerance sqrt(eps) of the interval, at most 100 Brent iterations. "
        "Brent mean, max: iterations per query that ran Brent (the mean over those queries) and the worst; tests, "
        "SDs: complete extrusion tests and supporting distances per query; photo finish: the share of the queries that "
        "ran Brent; caps: iteration caps; misses, false alarms: against the long-double reference (the study's "
        "workloads; a false alarm is a hit reported on a clear miss) or the benchmark's ground truth (CCD). "
        "Counts only, the same on every machine: supportHints shortens hill climbs, which no column counts.\n\n";
  std::string list;
  for (std::size_t k = 0; k < names.size(); ++k) list += (k ? ", " : "") + names[k];
  table(md, "The study's workloads: " + std::to_string(all.size()) + " queries (" + std::to_string(perWorkload) +
                " each of " + list + ")", configs, all, {});
  table(md, "Spinning bodies: " + std::to_string(spinning.size()) + " queries (screw_w1.5, screw_w3.0, planar_2d)",
        configs, spinning, {});
  if (ccdQueries > 0)
    table(md, "The CCD benchmark's sample queries: " + std::to_string(ccdQueries) +
                  " (per-vertex linear motion of a vertex and a triangle or two edges)", configs, {}, ccdFiles);
  std::cout << md.str();
  if (!out.empty()) {
    std::ofstream file(out);
    file << md.str();
    if (!file) {
      std::cerr << "gjkx_toi_refinements: cannot write " << out << "\n";
      return 1;
    }
  }
  return 0;
}
