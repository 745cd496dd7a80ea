// Chapter 04: the extrusion test (§1, §3), Figs. 1 and 4 of the paper.
//
// §1 sorts the intersection tests of two bodies over a time interval [t_0, t_1] into
// three kinds: static, sweeping and extrusion. §3 builds the extrusion test on GJK:
// "we determine whether the separating space ever vanishes in the interim by testing
// whether the spaces at t_0 and t_1 are disjoint". The bodies are polygons in the plane
// z = 0 moving over [0, 1]. Every verdict drawn is the library's (staticTest,
// sweepingTest, extrusionTest and the §5 solver timeOfImpact); a verdict is marked
// right or wrong against staticTest at 4001 instants, dense enough for these motions.
//
// Why this chapter calls §5's solver before chapter 05 introduces it: Fig. 4 of the paper
// ("extrusion tests robustly give correct results") is the §3 test *with §5 behind it*.
// Alone, the test only proves "no collision" or says "undecided" (§3: "we must further
// investigate [...] as described in section 5"); panel (c) is a §5 photo finish and (b),
// (d) are §5 hits, so their right verdicts, like the extrusion column of Fig. 1, need it.
//
// Options put a reader's pair (two boxes, their start poses, velocities and spins) in place
// of Fig. 4's four, and --trace prints every pair's extrusion test and solver run
// (trace.hpp, docs/traces.md).
#include "../chapter.hpp"
#include "moving_pair.hpp"
#include "photo_finish_chain.hpp"
#include "separating_directions.hpp"
#include "space_time.hpp"
#include "trace.hpp"
#include "verdicts.hpp"

#include <gjkx/brent/time_of_impact.hpp>
#include <gjkx/extrusion/extrusion.hpp>
#include <gjkx/extrusion/static_sampling.hpp>
#include <gjkx/extrusion/sweeping.hpp>
#include <gjkx/render/canvas.hpp>
#include <gjkx/support_mapping/polytope.hpp>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

using namespace extrusion_figures;

namespace {

// ---- Fig. 1: "Examples of intersection tests over time" ----------------------------
// "Static intersection tests check for intersection at specific instances in time [...]
// they may have actually passed straight through each other" (row A, left). "Sweeping
// intersection tests [...] conservatively report false alarms that never actually occur,
// because they do not account for the displacement of objects as they move" (row B,
// middle). "Extrusion intersection tests take a four-dimensional approach to detect
// spacio-temporal intersection directly, without misses or false alarms" (right column).
void figure1(const std::string& out, const Pair& passThrough, const Pair& crossing, const TestSettings& settings,
             bool trace) {
  // Row A is taller: under its bodies, an inset of x against t (drawSpaceTime).
  const int W = 430, heights[] = {470, 350}, tops[] = {0, heights[0]};
  const double insetBottom = passThrough.ymin + 0.3, insetTop = insetBottom + 2.2;
  Canvas c(3 * W, heights[0] + heights[1]);
  std::string summary = "Fig. 1:";
  const std::pair<const Pair*, std::string> rows[] = {{&passThrough, "(A) pass-through"}, {&crossing, "(B) crossing paths"}};
  for (int row = 0; row < 2; ++row) {
    const Pair& pair = *rows[row].first;
    const int H = heights[row], top = tops[row];
    const bool inset = row == 0;
    const bool truth = collides(pair);
    if (trace) printPairTrace("fig01-intersection-tests " + rows[row].second, pair, settings);
    // Static: the bodies at t_0 and t_1 only.
    panelAt(c, 0, top, W, H, 30, rows[row].second + ": static test at t_0 and t_1");
    drawPair(c, pair, 1);
    if (inset) drawSpaceTime(c, pair, SpaceTime::Static, insetBottom, insetTop, nullptr);
    const bool atEnds = staticTest(pair.P, pair.Q, t0, t1, 2);
    verdict(c, "static: " + said(atEnds) + judged(atEnds, truth), atEnds == truth, 30);
    // Sweeping: the swept hulls conv(X(t_0) \cup X(t_1)).
    panelAt(c, W, top, W, H, 30, rows[row].second + ": sweeping test");
    c.setWorldWindow(pair.xmin, pair.xmax, pair.ymin, pair.ymax);
    c.setClip(c.plotArea());
    for (const Body* b : {&pair.P, &pair.Q}) {
      std::vector<V> corners;
      for (double t : {t0, t1})
        for (const V& v : b->shape.vertices()) corners.push_back(b->at(t).worldFromBody(v));
      const bool isP = b == &pair.P;
      c.polygon(xy(Polytope<double>::polygon(corners).vertices()),
                ShapeStyle{isP ? palette::bodyPFill : palette::bodyQFill,
                           Stroke{isP ? palette::bodyPStroke : palette::bodyQStroke, 1.0, style::dashed}});
    }
    drawPair(c, pair, 1);
    if (inset) drawSpaceTime(c, pair, SpaceTime::Sweeping, insetBottom, insetTop, nullptr);
    const bool swept = sweepingTest(pair.P, pair.Q, t0, t1).status != IntersectionStatus::Disjoint;
    verdict(c, "sweeping: " + said(swept) + judged(swept, truth), swept == truth, 30);
    // Extrusion: the §3 test, then the §5 solver when it is undecided.
    panelAt(c, 2 * W, top, W, H, 30, rows[row].second + ": extrusion test");
    drawPair(c, pair, 8, !inset);  // with the inset, its t axis is the key of the poses' colours
    const auto test = extrusionTest(pair.P, pair.Q, t0, t1, settings.extrusion);
    const auto toi = timeOfImpact(pair.P, pair.Q, t0, t1, settings.toi);
    if (inset) drawSpaceTime(c, pair, SpaceTime::Extrusion, insetBottom, insetTop, &toi);
    drawFound(c, pair, test, toi);
    const bool extruded = reportsCollision(toi.status);
    verdict(c, solverVerdict(test, toi) + judged(extruded, truth), extruded == truth, 30);
    summary += std::string(" ") + "AB"[row] + ": reference " + said(truth) + ", static " + said(atEnds) + ", sweeping " +
               said(swept) + ", extrusion " + statuses(test, toi) + (row == 0 ? ";" : "");
  }
  chapter::save(c, out, "fig01-intersection-tests");
  std::printf("%s\n", summary.c_str());
}

// ---- Fig. 4: "Extrusion tests robustly give correct results" -----------------------
// "this extrusion test combines the complementary merits of both static and sweeping
// tests, and performs better for a broad scope of rigid body motion (Fig. 4)". Four
// motions, each decided by the extrusion test followed by the §5 solver: (a) a stack of
// blocks in free fall ("even over miniscule time intervals their swept volumes intersect,
// although the blocks themselves never come into contact"), (b) a head-on collision,
// (c) a glancing near miss, (d) one body overtaking another.
void figure4(const std::string& out, const std::vector<std::pair<Pair, std::string>>& panels,
             const TestSettings& settings, bool trace) {
  const int W = 520, H = 400;
  Canvas c(std::min<int>(2, int(panels.size())) * W, int(panels.size() + 1) / 2 * H);
  std::string summary = "Fig. 4:";
  for (std::size_t k = 0; k < panels.size(); ++k) {
    const Pair& pair = panels[k].first;
    if (trace) printPairTrace("fig04-extrusion-correct " + panels[k].second, pair, settings);
    panel(c, int(k % 2), int(k / 2), W, H, 50, panels[k].second);
    const auto test = extrusionTest(pair.P, pair.Q, t0, t1, settings.extrusion);
    ToiTrace<double> toiTrace;
    const auto toi = timeOfImpact(pair.P, pair.Q, t0, t1, settings.toi, &toiTrace);
    if (toi.status == ToiStatus::PhotoFinish) {  // the chain's poses instead of evenly spaced ones
      drawPair(c, pair, 1);
      drawChain(c, pair, toiTrace, chainOf(pair, toiTrace));
    } else {
      drawPair(c, pair, 6);
    }
    drawFound(c, pair, test, toi);
    const bool truth = collides(pair), extruded = reportsCollision(toi.status);
    std::string text = solverVerdict(test, toi);  // a photo finish: a chain of restarts + 1 intervals
    if (toi.status == ToiStatus::PhotoFinish) text += ", " + std::to_string(toi.restarts + 1) + " intervals";
    const bool atEnds = staticTest(pair.P, pair.Q, t0, t1, 2);
    const bool swept = sweepingTest(pair.P, pair.Q, t0, t1).status != IntersectionStatus::Disjoint;
    verdict(c, text + judged(extruded, truth), extruded == truth, 50,
            "for comparison: static " + said(atEnds) + judged(atEnds, truth) + ",  sweeping " + said(swept) +
                judged(swept, truth));
    summary += std::string(" (") + "abcd"[k] + ") " + statuses(test, toi) + ", reference " + said(truth) +
               (k + 1 < panels.size() ? ";" : "");
  }
  chapter::save(c, out, "fig04-extrusion-correct");
  std::printf("%s\n", summary.c_str());
}

// ---- The separating space at t_0 and t_1 (§3) --------------------------------------
// "Consider the space defined by all separating vectors between P(t_0) and Q(t_0). [...]
// if P and Q intersect at t_0, this space is null, otherwise it is an open pyramid
// extending away from the origin. [...] we determine whether the separating space ever
// vanishes in the interim by testing whether the spaces at t_0 and t_1 are disjoint."
// In the plane the pyramid is a wedge of directions: the arc of the unit circle where
// SD > 0. GJK's s_i at t_0 are tried in turn; one in both arcs proves no collision.


// Top: a pair that misses, whose spaces at t_0 and t_1 overlap; bottom: one that collides,
// whose spaces are disjoint (for it the §5 solver finds the time of impact).
void separatingSpace(const std::string& out, const Pair& apart, const Pair& hitting, TestSettings settings, bool trace) {
  const int W = 460, H = 430;
  Canvas c(2 * W, 2 * H);
  std::string summary = "separating space:";
  const std::pair<const Pair*, std::string> rows[] = {{&apart, "no collision"}, {&hitting, "collision"}};
  settings.extrusion.gjk.initialDirection = V(0, 1, 0);  // s_0: "an arbitrary nonzero vector" (a poor one, to show a few s_i)
  for (int row = 0; row < 2; ++row) {
    const Pair& pair = *rows[row].first;
    if (trace) printPairTrace("separating-space " + rows[row].second, pair, settings);
    ExtrusionTrace<double> steps;
    const auto test = extrusionTest(pair.P, pair.Q, t0, t1, settings.extrusion, nullptr, steps);
    panel(c, 0, row, W, H, 30, "(" + std::string(1, "ac"[row]) + ") " + rows[row].second + ": P and Q at t_0 and t_1");
    drawPair(c, pair, 1);
    const auto toi = timeOfImpact(pair.P, pair.Q, t0, t1, settings.toi);
    drawFound(c, pair, test, toi);
    const bool truth = collides(pair), extruded = reportsCollision(toi.status);
    verdict(c, solverVerdict(test, toi) + judged(extruded, truth), extruded == truth, 30);
    panel(c, 1, row, W, H, 30, "(" + std::string(1, "bd"[row]) + ") separating directions s at t_0 and t_1");
    summary += std::string(row ? "; " : " ") + rows[row].second + ": " + drawSpace(c, pair, steps) + ", " +
               std::to_string(steps.steps.size()) + " s_i, " + statuses(test, toi);
  }
  chapter::save(c, out, "separating-space");
  std::printf("%s\n", summary.c_str());
}

// A reader's box of w x h from its start pose, velocity and spin over [t_0, t_1].
Body movingBox(const std::string& size, const std::string& start, const std::string& velocity, double spin) {
  const std::vector<double> wh = chapter::numberList(size), v = chapter::numberList(velocity);
  return body(box(wh[0], wh[1]),
              Motion<double>::screw(chapter::planarPose(chapter::numberList(start)), V(v[0], v[1], 0), V(0, 0, spin)));
}

// A window around both bodies' paths over [t_0, t_1], with a margin.
Pair framed(const Body& P, const Body& Q) {
  V lo = V::Constant(1e300), hi = V::Constant(-1e300);
  for (int k = 0; k <= 50; ++k)
    for (const Body* b : {&P, &Q})
      for (const V& v : b->shape.vertices()) {
        const V x = b->at(k / 50.0).worldFromBody(v);
        lo = lo.cwiseMin(x), hi = hi.cwiseMax(x);
      }
  return Pair{P, Q, V(0, -1, 0), V(0, 1, 0), lo.x() - 1, hi.x() + 1, lo.y() - 1.2, hi.y() + 1};
}

}  // namespace

int main(int argc, char** argv) {
  std::string out = ".", pSize = "1,1", qSize = "1,1", pStart = "-3,0", qStart = "3,0.3", pVelocity = "5,0",
              qVelocity = "-5,0";
  double pSpin = 0, qSpin = 0, tolerance = 0;
  bool trace = false;
  CLI::App app{"Draws Figs. 1 and 4 of the paper and the separating space in DIR. The --p-*, --q-* and --tolerance "
               "options put a pair of boxes of your own in place of Fig. 4's four; --trace prints every pair's "
               "extrusion test and time-of-impact run (docs/traces.md)."};
  chapter::addFigureOptions(app, out);
  chapter::addTraceOption(app, trace);
  std::vector<CLI::Option*> query;
  for (auto [name, text, what] : {std::tuple{"--p-size", &pSize, "P's width and height"},
                                  std::tuple{"--q-size", &qSize, "Q's width and height"}})
    query.push_back(app.add_option(name, *text, what)->check(chapter::numbers(2, 2, "W,H"))->capture_default_str());
  for (auto [name, text, what] : {std::tuple{"--p-start", &pStart, "P's pose at t_0: its centre and angle (radians)"},
                                  std::tuple{"--q-start", &qStart, "Q's pose at t_0"}})
    query.push_back(chapter::addPoseOption(app, name, *text, what));
  for (auto [name, text, what] : {std::tuple{"--p-velocity", &pVelocity, "P's velocity over [t_0, t_1] = [0, 1]"},
                                  std::tuple{"--q-velocity", &qVelocity, "Q's velocity"}})
    query.push_back(app.add_option(name, *text, what)->check(chapter::numbers(2, 2, "VX,VY"))->capture_default_str());
  for (auto [name, spin, what] : {std::tuple{"--p-spin", &pSpin, "P's angular velocity about z (radians over [0, 1])"},
                                  std::tuple{"--q-spin", &qSpin, "Q's angular velocity"}})
    query.push_back(app.add_option(name, *spin, what)->check(CLI::Range(-1000.0, 1000.0))->capture_default_str());
  auto* toleranceOption =
      app.add_option("--tolerance", tolerance, "the collision tolerance (§2.3); default: the library's, sqrt(eps)")
          ->check(CLI::PositiveNumber);
  query.push_back(toleranceOption);
  chapter::parseOrExit(app, argc, argv);
  for (auto [name, text] : {std::pair{"--p-size", &pSize}, std::pair{"--q-size", &qSize}}) {
    const std::vector<double> wh = chapter::numberList(*text);
    if (wh[0] <= 0 || wh[1] <= 0) chapter::badOption(app, name, "W and H must be positive, got '" + *text + "'");
  }
  std::filesystem::create_directories(out);
  TestSettings settings;
  if (toleranceOption->count()) settings.extrusion.collisionTolerance = settings.toi.collisionTolerance = tolerance;
  const bool custom = std::any_of(query.begin(), query.end(), [](const CLI::Option* o) { return o->count() > 0; });

  // Fig. 1 (A): a small fast square passes straight through a thin fixed plate.
  const Pair passThrough{body(box(0.5, 0.5), glide(V(-3, 0.2, 0), V(6, -0.4, 0))),
                         body(box(0.2, 3.2), Motion<double>::fixed(Pose<double>::identity())),
                         V(0, 1, 0), V(0, 1, 0), -4, 4, -5.2, 2.4};
  // Fig. 1 (B): paths that cross, the crossing passed at different times.
  const Pair crossing{body(box(0.6, 0.6), glide(V(-3.5, 0, 0), V(6, 0, 0))),
                      body(box(0.6, 0.6), glide(V(0.8, -1.2, 0), V(3, 3, 0))), V(0, -1, 0), V(-1, 1, 0), -4.2, 4.6, -2.4, 2.4,
                      true};
  figure1(out, passThrough, crossing, settings, trace);

  // Fig. 4: (a) a stack of two blocks in free fall, (b) head on, (c) near miss, (d) overtaking.
  const auto fall = [](double y) {
    return Motion<double>::constantAcceleration(Pose<double>::translate(V(-2, y, 0)), V(4, 0, 0), V(0, -6, 0));
  };
  const std::vector<V> triangle{V(-0.6, -0.5, 0), V(0.7, 0, 0), V(-0.6, 0.5, 0)};
  const std::vector<V> wedge{V(-0.7, 0, 0), V(0.5, -0.6, 0), V(0.6, 0.5, 0)};
  const std::vector<std::pair<Pair, std::string>> panels{
      {Pair{body(box(1.6, 0.7), fall(0.5)), body(box(1.6, 0.7), fall(1.35)), V(-1, -1, 0), V(1, 1, 0), -3.5, 3.5, -3.2, 2.2},
       "(a) falling together, never touching"},
      {Pair{body(triangle, glide(V(-3, -0.3, 0), V(5, 0.3, 0))), body(wedge, glide(V(3, 0.3, 0), V(-4, -0.2, 0))),
            V(0, -1, 0), V(0, 1, 0), -4.2, 4.2, -1.6, 1.6},
       "(b) head-on collision"},
      {Pair{body(triangle, glide(V(-3, -0.55, 0), V(6, 0, 0))), body(wedge, glide(V(3, 0.62, 0), V(-6, 0, 0))), V(0, -1, 0),
            V(0, 1, 0), -4.2, 4.2, -2.6, 1.6},
       "(c) glancing near miss: a photo finish"},
      {Pair{body(triangle, glide(V(-3.6, 0, 0), V(7, 0.2, 0))), body(box(0.9, 0.9), glide(V(-1.2, 0.1, 0), V(3, 0, 0))),
            V(0, -1, 0), V(0, 1, 0), -4.5, 4.5, -1.6, 1.6},
       "(d) overtaking"}};
  if (custom)
    figure4(out,
            {{framed(movingBox(pSize, pStart, pVelocity, pSpin), movingBox(qSize, qStart, qVelocity, qSpin)),
              "your query"}},
            settings, trace);
  else
    figure4(out, panels, settings, trace);

  // The separating space: a pair that misses (arcs overlap) and one that collides (arcs disjoint).
  const std::vector<V> kite{V(-0.8, -0.3, 0), V(0.4, -0.6, 0), V(0.8, 0.4, 0), V(-0.2, 0.7, 0)};
  const Pair apart{body(kite, glide(V(-2.5, -0.5, 0), V(2, 0.5, 0))), body(triangle, glide(V(1.5, -1, 0), V(0, 3, 0))),
                   V(0, -1, 0), V(1, 0, 0), -3.6, 3.6, -2.4, 2.8};
  const Pair hitting{body(kite, glide(V(-2.5, -0.5, 0), V(5, 1, 0))), body(triangle, glide(V(1.5, -1, 0), V(-1, 1.5, 0))),
                     V(0, -1, 0), V(1, 0, 0), -3.6, 3.6, -2.4, 2.8};
  separatingSpace(out, apart, hitting, settings, trace);
  return 0;
}
