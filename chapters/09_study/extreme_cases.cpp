// extreme_cases: the table of stiff and extreme cases of the study (chapter 09).
//
//   extreme_cases [--out DIR] [--watchdog SECONDS]
//
// Runs every time-of-impact method (ours: static sampling, swept test, conservative
// advancement, the paper's solver and the certified one in double and float; the peers:
// FCL continuousCollide naive and conservative advancement, Bullet
// btContinuousConvexCollision, Box2D b2TimeOfImpact on the cases with a 2D form) on the ten
// cases of gjkx/study/extreme_cases.hpp, and every GJK method (ours in double and float, libccd GJK and
// MPR, FCL's distance with both solvers, Bullet btGjkPairDetector) on the six static ones.
// Each cell runs in its own fork()ed process under a watchdog (default 5 s) and is judged
// right, wrong, NaN, hang, crash or cap against the independent reference (the rules are in
// gjkx/study/extreme_cases.hpp and in the legend of the output). Prints the tables and writes them as
// markdown to DIR/extreme-cases.md (default figures/study). Exits with 1 if the references
// disagree with one another (closed forms, brute force, 2D forms). Takes a few seconds.
// Regenerate the kept table with `build/chapters/09_study/extreme_cases --out figures/study`.
#include "../command_line.hpp"
#include "../formatting.hpp"

#include <gjkx/study/extreme_cases.hpp>
#include <gjkx/study/peers.hpp>
#include <gjkx/study/peers_toi.hpp>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

using namespace gjkx;
using namespace gjkx::study;

namespace {

struct Options {
  std::string out = "figures/study";
  double watchdog = kWatchdog;
};

Options parse(int argc, char** argv) {
  Options o;
  CLI::App app{"The table of stiff and extreme cases: tables on stdout, DIR/extreme-cases.md."};
  app.add_option("--out", o.out, "the folder for extreme-cases.md")->type_name("DIR")->capture_default_str();
  app.add_option("--watchdog", o.watchdog, "the time limit of one cell")
      ->type_name("SECONDS")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  chapter::parseOrExit(app, argc, argv);
  return o;
}

// ---------------------------------------------------------------------------------------
// The peers

std::vector<ToiMethod> peerToiMethods() {
  std::vector<ToiMethod> m;
#if GJKX_HAVE_FCL
  auto fcl = [](const ToiQuery& q, bool ca, double tocErr, fcl::GJKSolverType solver) {
    const peers::FclQuery f(q);
    const peers::PeerOutcome r = f.run(ca, tocErr, solver);
    ToiAnswer a;
    a.hit = r.hit;
    a.time = r.time;
    return a;
  };
  m.push_back({"FCL naive", false, false, false, [fcl](const ToiQuery& q) { return fcl(q, false, 1e-3, fcl::GST_LIBCCD); }});
  m.push_back({"FCL CA", false, false, false, [fcl](const ToiQuery& q) { return fcl(q, true, 1e-4, fcl::GST_LIBCCD); }});
  m.push_back({"FCL CA indep", false, false, false, [fcl](const ToiQuery& q) { return fcl(q, true, 1e-4, fcl::GST_INDEP); }});
#endif
#if GJKX_HAVE_BULLET
  m.push_back({"Bullet", false, false, false, [](const ToiQuery& q) {
                 const peers::BulletQuery b(q);
                 const peers::PeerOutcome r = b.run();
                 ToiAnswer a;
                 a.hit = r.hit;
                 a.time = r.time;
                 return a;
               }});
#endif
#if GJKX_HAVE_BOX2D
  m.push_back({"Box2D", false, true, false, [](const ToiQuery& q) {
                 const peers::Box2dQuery b(q);
                 b2TOIOutput output;
                 b2TimeOfImpact(&output, &b.input);
                 ToiAnswer a;
                 switch (output.state) {
                   case b2TOIOutput::e_touching: a.hit = true; a.time = output.t; setText(a.status, sizeof a.status, "e_touching"); break;
                   case b2TOIOutput::e_overlapped: a.hit = true; a.time = 0; setText(a.status, sizeof a.status, "e_overlapped"); break;
                   case b2TOIOutput::e_separated: setText(a.status, sizeof a.status, "e_separated"); break;
                   case b2TOIOutput::e_failed:  // Box2D's iteration limits ran out
                     a.kind = AnswerKind::Cap;
                     a.hit = true;
                     a.time = output.t;
                     setText(a.status, sizeof a.status, "e_failed");
                     break;
                   default: setText(a.status, sizeof a.status, "e_unknown"); break;
                 }
                 return a;
               }});
#endif
  return m;
}

std::vector<GjkMethod> peerGjkMethods() {
  std::vector<GjkMethod> m;
#if GJKX_HAVE_CCD
  for (const bool mpr : {false, true})
    m.push_back({mpr ? "libccd MPR" : "libccd GJK", false, [mpr](const StaticCase& c) {
                   const peers::CcdObject A{&c.P, c.poseP}, B{&c.Q, c.poseQ};
                   const ccd_t ccd = peers::ccdSettings();
                   GjkAnswer out;
                   out.boolean = true;
                   out.overlap = (mpr ? ccdMPRIntersect(&A, &B, &ccd) : ccdGJKIntersect(&A, &B, &ccd)) != 0;
                   return out;
                 }});
#endif
#if GJKX_HAVE_FCL
  for (const auto solver : {fcl::GST_LIBCCD, fcl::GST_INDEP})
    m.push_back({solver == fcl::GST_LIBCCD ? "FCL libccd" : "FCL indep", false, [solver](const StaticCase& c) {
                   const auto a = peers::fclShape(c.P), b = peers::fclShape(c.Q);
                   fcl::DistanceRequestd request;
                   request.gjk_solver_type = solver;
                   fcl::DistanceResultd result;
                   GjkAnswer out;
                   out.distance = fcl::distance(a.get(), peers::fclTransform(c.poseP), b.get(), peers::fclTransform(c.poseQ), request, result);
                   return out;
                 }});
#endif
#if GJKX_HAVE_BULLET
  m.push_back({"Bullet", false, [](const StaticCase& c) {
                 const auto a = peers::bulletShape(c.P), b = peers::bulletShape(c.Q);
                 peers::BulletPair pair(a.get(), b.get());
                 GjkAnswer out;
                 out.distance = pair.distance(peers::bulletTransform(c.poseP), peers::bulletTransform(c.poseQ));
                 if (std::isnan(out.distance)) setText(out.status, sizeof out.status, "no result");
                 return out;
               }});
#endif
  return m;
}

// ---------------------------------------------------------------------------------------
// Output

std::string expectText(const ToiCase& c) {
  switch (c.expect) {
    case Expect::Hit: return "hit";
    case Expect::NoHit: return "no hit";
    case Expect::Either: return "either";
  }
  return "?";
}

using chapter::formatOrDash;
using chapter::markdownTable;

// A plain-text table for the terminal: columns padded to their widest cell.
std::string textTable(const std::vector<std::string>& header, const std::vector<std::vector<std::string>>& rows) {
  std::vector<std::size_t> width(header.size(), 0);
  for (std::size_t k = 0; k < header.size(); ++k) width[k] = header[k].size();
  for (const auto& row : rows)
    for (std::size_t k = 0; k < row.size(); ++k) width[k] = std::max(width[k], row[k].size());
  std::ostringstream out;
  auto line = [&](const std::vector<std::string>& cells) {
    for (std::size_t k = 0; k < cells.size(); ++k) {
      out << cells[k] << std::string(width[k] - cells[k].size() + 2, ' ');
    }
    out << "\n";
  };
  line(header);
  for (const auto& row : rows) line(row);
  return out.str();
}

}  // namespace

int main(int argc, char** argv) {
  const Options options = parse(argc, argv);
  const auto start = std::chrono::steady_clock::now();

  const std::vector<ToiCase> cases = makeToiCases();
  const std::vector<StaticCase> statics = makeStaticCases();
  const std::vector<std::string> problems = referenceProblems(cases, statics);
  const double referenceSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  std::vector<ToiMethod> toiMethods = ourToiMethods();
  for (auto& m : peerToiMethods()) toiMethods.push_back(std::move(m));
  std::vector<GjkMethod> gjkMethods = ourGjkMethods();
  for (auto& m : peerGjkMethods()) gjkMethods.push_back(std::move(m));

  // Every cell, each in its own process under the watchdog.
  std::vector<std::vector<Cell>> toiCells, gjkCells;
  for (const ToiCase& c : cases) {
    toiCells.emplace_back();
    for (const ToiMethod& m : toiMethods) toiCells.back().push_back(runToiCell(c, m, options.watchdog));
  }
  for (const StaticCase& c : statics) {
    gjkCells.emplace_back();
    for (const GjkMethod& m : gjkMethods) gjkCells.back().push_back(runGjkCell(c, m, options.watchdog));
  }
  const double totalSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  // The tables.
  std::vector<std::string> toiHeader{"case"}, gjkHeader{"case"};
  for (const auto& m : toiMethods) toiHeader.push_back(m.name);
  for (const auto& m : gjkMethods) gjkHeader.push_back(m.name);
  std::vector<std::vector<std::string>> toiRows, gjkRows;
  for (std::size_t i = 0; i < cases.size(); ++i) {
    toiRows.push_back({cases[i].name});
    for (const Cell& cell : toiCells[i]) toiRows.back().push_back(cell.text());
  }
  for (std::size_t i = 0; i < statics.size(); ++i) {
    gjkRows.push_back({statics[i].name});
    for (const Cell& cell : gjkCells[i]) gjkRows.back().push_back(cell.text());
  }

  // Counts per column, for the summary lines.
  auto count = [](const std::vector<std::vector<Cell>>& cells, std::size_t column, Verdict v) {
    int n = 0;
    for (const auto& row : cells) n += row[column].verdict == v;
    return n;
  };

  // The peers of the time-of-impact table and libccd of the static one.
  const std::vector<peers::Peer> tablePeers{peers::Peer::FCL, peers::Peer::Bullet, peers::Peer::Box2D, peers::Peer::Libccd};
  const std::string peersFound = peers::found(tablePeers).empty() ? std::string("none") : peers::joined(peers::found(tablePeers));
  const std::string peersMissing = peers::joined(peers::missing(tablePeers));

  std::printf("Stiff and extreme cases (chapter 09): every method, each cell in its own process, watchdog %.0f s\n", options.watchdog);
  std::printf("peers: %s%s\n\n", peersFound.c_str(), peersMissing.empty() ? "" : ("; left out (not installed): " + peersMissing).c_str());
  std::printf("Time of impact (ours at collision tolerance %.0e; CA at %.0e; static N=32 and swept at the library's default tolerance)\n%s\n",
              kTolerance, kTolerance, textTable(toiHeader, toiRows).c_str());
  std::printf("Static pairs (distance or yes/no)\n%s\n", textTable(gjkHeader, gjkRows).c_str());
  for (std::size_t k = 0; k < toiMethods.size(); ++k)
    std::printf("EXTREME toi method=\"%s\" right=%d wrong=%d nan=%d hang=%d crash=%d cap=%d na=%d\n", toiMethods[k].name.c_str(),
                count(toiCells, k, Verdict::Right), count(toiCells, k, Verdict::Wrong), count(toiCells, k, Verdict::NaN),
                count(toiCells, k, Verdict::Hang), count(toiCells, k, Verdict::Crash), count(toiCells, k, Verdict::Cap),
                count(toiCells, k, Verdict::NotApplicable));
  for (std::size_t k = 0; k < gjkMethods.size(); ++k)
    std::printf("EXTREME static method=\"%s\" right=%d wrong=%d nan=%d hang=%d crash=%d cap=%d\n", gjkMethods[k].name.c_str(),
                count(gjkCells, k, Verdict::Right), count(gjkCells, k, Verdict::Wrong), count(gjkCells, k, Verdict::NaN),
                count(gjkCells, k, Verdict::Hang), count(gjkCells, k, Verdict::Crash), count(gjkCells, k, Verdict::Cap));
  for (const auto& p : problems) std::printf("REFERENCE DISAGREEMENT %s\n", p.c_str());

  // Details of every cell that is not right, on stdout and in the markdown.
  std::ostringstream details;
  std::vector<std::vector<std::string>> detailRows;
  auto detail = [&](const std::string& caseName, const std::string& method, const Cell& cell, bool always = false) {
    if (!always && (cell.verdict == Verdict::Right || cell.verdict == Verdict::NotApplicable)) return;
    details << "  " << caseName << " / " << method << ": " << cell.text() << " - " << cell.said << "\n";
    detailRows.push_back({caseName, method, cell.text(), cell.said});
  };
  for (std::size_t i = 0; i < cases.size(); ++i)
    for (std::size_t k = 0; k < toiMethods.size(); ++k) detail(cases[i].name, toiMethods[k].name, toiCells[i][k]);
  // What the frame of P buys (docs 09, origin independence): both float runs far from the
  // origin, right or not.
  for (std::size_t i = 0; i < cases.size(); ++i)
    for (std::size_t k = 0; k < toiMethods.size(); ++k)
      if (cases[i].name == "coordinates near 10^5" &&
          (toiMethods[k].name == "ours float" || toiMethods[k].name == "ours float, world frame"))
        detail(cases[i].name, toiMethods[k].name, toiCells[i][k], true);
  for (std::size_t i = 0; i < statics.size(); ++i)
    for (std::size_t k = 0; k < gjkMethods.size(); ++k) detail(statics[i].name + " (static)", gjkMethods[k].name, gjkCells[i][k]);
  std::printf("\nWhat the methods said where they were not right (and ours in float at 10^5, both frames):\n%s", details.str().c_str());
  // The slowest cells (each includes its fork and, for the peers, building their shapes).
  double slowest = 0;
  std::string slowestName;
  for (std::size_t i = 0; i < cases.size(); ++i)
    for (std::size_t k = 0; k < toiMethods.size(); ++k)
      if (toiCells[i][k].seconds > slowest) slowest = toiCells[i][k].seconds, slowestName = cases[i].name + " / " + toiMethods[k].name;
  for (std::size_t i = 0; i < statics.size(); ++i)
    for (std::size_t k = 0; k < gjkMethods.size(); ++k)
      if (gjkCells[i][k].seconds > slowest) slowest = gjkCells[i][k].seconds, slowestName = statics[i].name + " / " + gjkMethods[k].name;
  std::printf("\nreferences %.2f s, whole run %.2f s; slowest cell %.3f s (%s)\n", referenceSeconds, totalSeconds, slowest,
              slowestName.c_str());

  // The markdown. The docs page of the study includes it with Doxygen's \includedoc, which
  // joins a file into one paragraph: so it starts with a title, breaks the line before every
  // later title, and ends with its notes (command, date, rules), which read as a caption.
  std::ostringstream md;
  auto title = [&](bool first, const std::string& bold, const std::string& rest) {
    md << (first ? "" : "\n<br>") << "**" << bold << "**" << rest << "\n\n";
  };
  title(true, "Stiff and extreme cases, time of impact", ": each case against every method (the rules are under the tables).");
  md << markdownTable(toiHeader, toiRows);
  title(false, "Stiff and extreme cases, static pairs", ": GJK's distance (ours, FCL, Bullet) or yes/no (libccd).");
  md << markdownTable(gjkHeader, gjkRows);
  title(false, "The cases and their references", "");
  {
    std::vector<std::vector<std::string>> rows;
    for (const ToiCase& c : cases)
      rows.push_back({c.name, c.setup, expectText(c), c.query.refHit ? formatOrDash("%.9f", c.query.tRef) : "-", formatOrDash("%.9f", c.closedForm),
                      c.hasPlanarForm ? (c.planar.refHit ? formatOrDash("%.9f", c.planar.tRef) : "no hit") : "-",
                      c.expect == Expect::NoHit ? "-" : formatOrDash("%.0e", c.delta) + " (" + c.deltaWhy + ")", formatOrDash("%.3g", c.lipschitz)});
    md << markdownTable({"case", "setup", "expect", "t_ref, brute force", "t_ref, closed form", "t_ref, 2D form", "delta", "L"}, rows)
       << "\n";
  }
  {
    std::vector<std::vector<std::string>> rows;
    for (const StaticCase& c : statics)
      rows.push_back({c.name, c.setup, formatOrDash("%.9g", c.reference), formatOrDash("%.9g", c.closedForm), formatOrDash("%.1e", c.tau)});
    md << markdownTable({"static case", "setup", "d_ref, brute force", "d_ref, closed form", "tau"}, rows);
  }
  title(false, "What the methods said where they were not right (and both float runs of ours at 10^5, in P's frame and in the world's)", "");
  md << markdownTable({"case", "method", "cell", "what it said"}, detailRows);

  // The notes: provenance, rules, settings.
  md << "\n<br>Written by `extreme_cases --out " << options.out << "` on " << chapter::utcNow() << "; peers: " << peersFound
     << (peersMissing.empty() ? "" : "; left out (not installed): " + peersMissing) << ". "
     << "Each cell ran in its own `fork()`ed process under a watchdog of " << formatOrDash("%.0f", options.watchdog)
     << " s and is judged against an independent reference: the long-double brute force of `workloads.hpp` (feature pairs, a "
        "Lipschitz bound on d(t), bisection), checked against a closed form where the geometry gives one and against the 2D "
        "form's own reference.\n"
     << "<br>*Right*, time of impact: when the reference has contact, a hit at a time t with `d_ref(t) <= delta` (not early) and "
        "`t <= t_ref + delta / L` (not late: the bodies can have interpenetrated by at most delta; L bounds the rate of d(t)), "
        "delta stated per case; when it has none, no hit; when the gap stays under 1e-10 without closing (*either*), no hit or "
        "a hit that meets the hit rule. The swept test answers yes/no only and is judged on that. *Right*, static pairs: a "
        "distance within tau = 1e-6 times the case's scale (its largest coordinate, at least 1: 8 float ulps) of the "
        "reference, an overlap counting as 0; a yes/no method must say intersecting when the reference is 0 (touching counts) "
        "and disjoint when it exceeds tau. *Wrong*: otherwise, with why (miss, false alarm, late by t - t_ref, early at "
        "d_ref(t), error |d - d_ref|). *NaN*: a non-finite answer or a numerical-failure status. *Cap*: an iteration-cap "
        "status (ours: IterationCap; CA: 10000 steps; Box2D: e_failed; FCL and Bullet have none). *Hang*: killed by the "
        "watchdog. *Crash*: died of a signal, or threw on these valid inputs. *n/a*: Box2D on a case without a 2D form.\n"
     << "<br>Settings: ours (the paper's extrusion test and Brent, `gjkx::timeOfImpact`) and the certified variant at "
        "collision tolerance " << formatOrDash("%.0e", kTolerance) << " in double and in float (time tolerance the smaller of "
        "sqrt(eps) and the tolerance), each query run in the frame of P; *ours float, world frame*: the same in world "
        "coordinates (`ToiSettings::inFrameOfP = false`), to show what the frame buys; CA (conservative advancement on our GJK) at " << formatOrDash("%.0e", kTolerance)
     << "; static sampling at 32 times and the swept test at the library's default tolerance sqrt(eps), in double; FCL "
        "`continuousCollide` naive at toc_err 1e-3 (1000 static tests) and conservative advancement (libccd's GJK and FCL's "
        "own, toc_err 1e-4); Bullet `btContinuousConvexCollision` (single precision); Box2D `b2TimeOfImpact` on the 2D form "
        "(the cross-sections in z = 0), which aims at a gap of b2_linearSlop = 0.005 by design. Static: ours `gjkx::gjk` "
        "(default settings), libccd `ccdGJKIntersect` and `ccdMPRIntersect`, FCL `distance` with both solvers, Bullet "
        "`btGjkPairDetector` (margins 0).\n";
  // FCL and Bullet receive the start and end poses of each body (their APIs interpolate
  // between two transforms): a turn of more than half a revolution reaches them as the
  // shortest rotation between those poses.
  for (const ToiCase& c : cases)
    for (const auto* m : {&c.query.motionP, &c.query.motionQ})
      if (m->w.norm() > M_PI) {
        const Eigen::Matrix3d turn = m->poseAt(1).first * m->R0.transpose();
        md << "<br>Case " << c.name << ": " << (m == &c.query.motionP ? "P" : "Q") << " turns " << formatOrDash("%.3g", m->w.norm())
           << " rad over the interval; FCL and Bullet, given its start and end poses, see a turn of "
           << formatOrDash("%.3g", Eigen::AngleAxisd(turn).angle()) << " rad (the shortest rotation between them).\n";
      }
  for (const auto& p : problems) md << "<br>**The references disagree:** " << p << "\n";

  std::filesystem::create_directories(options.out);
  const std::string path = options.out + "/extreme-cases.md";
  std::ofstream(path) << md.str();
  std::printf("wrote %s\n", path.c_str());
  return problems.empty() ? 0 : 1;
}
