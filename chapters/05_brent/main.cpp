// Chapter 05: the maximum supporting distance over time (§4) and Brent's method (§5).
//
// §4: "If we represent the maximum supporting distance between P(t) and Q(t) as a
// continuous scalar function of time, we can identify collisions by checking whether or
// not this function drops below zero, and then determine their exact TOI with a root
// solver." §5 approximates that function by "the maximum value of SD(P(t_1), Q(t_1), s_i)
// among those we calculated before the GJK query halted" and solves it with Brent's
// method, "a root solver that cleverly combines bisection, the secant method, and inverse
// quadratic interpolation". Three figures, drawn from the library's own runs
// (timeOfImpact with a ToiTrace, findRoot), for polygons in the plane z = 0 over [0, 1]:
//   brent-time-of-impact.png  a box turning as it moves onto a fixed polygon: the true
//       maximum SD, the approximation of every complete extrusion test, Brent's iterates
//       t_x, the restarts and the time of impact, and the bodies at those times;
//   brent-photo-finish.png    a bar turning as it passes the corner of a block: "the
//       extrusion test fails for the complete time interval t_0 to t_1 but succeeds when
//       performed on the sequence of intervals t_0 to t_x1, t_x1 to t_x2, ... t_xn to t_1";
//   brent-root-finder.png     Brent's method alone, on his own example x^3 - 2x - 5.
// The collision tolerance is 0.05 (the library's default is sqrt(eps)), so that its band
// can be seen.
#include "../chapter.hpp"

#include <gjkx/root_solver/brent_method.hpp>
#include <gjkx/brent/time_of_impact.hpp>
#include <gjkx/gjk/gjk.hpp>
#include <gjkx/render/canvas.hpp>
#include <gjkx/support_mapping/placed.hpp>
#include <gjkx/support_mapping/polytope.hpp>
#include <gjkx/supporting_distance/supporting_distance.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

using namespace gjkx;
using namespace gjkx::render;
using V = Vector3<double>;
using P2 = Eigen::Vector2d;
using Body = Moving<Polytope<double>>;
using Rows = std::vector<std::vector<std::string>>;
using chapter::xy;

namespace {

constexpr double kTol = 0.05;     // the collision tolerance of both solver runs
constexpr int kDirections = 720;  // unit directions for the penetration depth, half a degree apart
constexpr int kSamples = 801;     // instants at which a curve is drawn
const TextStyle kSmall{Font::Sans, 12.5, palette::ink, 2.0};
// One colour per complete extrusion test (interval), one per Brent step kind.
Color intervalColor(std::size_t k) {
  static const Color colors[] = {Color::hex(0x0072B2), Color::hex(0x2E8540), Color::hex(0x7B4EA3),
                                 Color::hex(0x009E9E), Color::hex(0xB8860B)};
  return colors[k % 5];
}
Color kindColor(BrentStepKind kind) {  // in the order of BrentStepKind
  static const Color colors[] = {Color::hex(0x9E9E9E), palette::ink, palette::highlight, Color::hex(0xCC79A7),
                                 Color::hex(0x009E73), Color::hex(0xD55E00)};
  return colors[static_cast<int>(kind)];
}

using chapter::format;

std::vector<V> unitDirections(int count) {
  std::vector<V> dirs;
  for (int k = 0; k < count; ++k) dirs.push_back(V(std::cos(2 * M_PI * k / count), std::sin(2 * M_PI * k / count), 0));
  return dirs;
}

// ---- the solver's runs and the functions they approximate -------------------------------

struct Run {
  ToiResult<double> result;
  ToiTrace<double> trace;
};

// The solver the figures run (--solver): this project's by default, or §5 as the paper wrote it.
ToiSolverMode solverMode = ToiSolverMode::Gjkx;

Run solve(const Body& P, const Body& Q) {
  ToiSettings<double> settings = ToiSettings<double>::of(solverMode);
  settings.collisionTolerance = kTol;
  Run run;
  run.result = timeOfImpact(P, Q, 0.0, 1.0, settings, &run.trace);
  std::printf("status %s", toString(run.result.status));
  if (reportsCollision(run.result.status))
    std::printf(", time of impact %.6f (distance %.6f)", run.result.time, run.result.distance);
  std::printf(", Brent iterations %d, GJK runs %d, restarts %d\n", run.result.brentIterations, run.result.gjkRuns,
              run.result.restarts);
  return run;
}

// The true maximum supporting distance at t (§4): "equivalent to the closest distance when
// P and Q are disjoint" (GJK), and "the penetration distance when they intersect", where
// "an exhaustive search may be required" (here over kDirections unit directions).
double trueMaximumSd(const Body& P, const Body& Q, double t) {
  static const std::vector<V> dirs = unitDirections(kDirections);
  const auto Pt = P.at(t);
  const auto Qt = Q.at(t);
  const GjkResult<double> run = gjk(Pt, Qt);
  return run.status == GjkStatus::Overlapping ? maximumSupportingDistance(Pt, Qt, dirs).value : run.distance;
}

// The approximation of one complete test: the maximum of SD(P(t), Q(t), s_k) over the
// separating vectors s_k it stored at its start (§5).
double approximateMaximumSd(const Body& P, const Body& Q, const ToiInterval<double>& test, double t) {
  double value = -1e300;
  for (int k = 0; k < test.separating.count; ++k)
    value = std::max(value, supportingDistanceAt(P, Q, test.separating.vectors[k], t));
  return value;
}

// ---- a plot of values over time ----------------------------------------------------------

// setWorldWindow scales x and y alike, so t in [ta, tb] is stretched to `width` value
// units (as chapter 03 stretches the angle of s); `below` (a fraction of hi - lo) is kept
// free under the t axis. Curves are clipped to the box [ta, tb] x [lo, hi].
struct Plot {
  double ta, tb, lo, hi, width;
  P2 at(double t, double v) const { return P2((t - ta) / (tb - ta) * width, v); }
};

Plot plotAxes(Canvas& canvas, double ta, double tb, double lo, double hi, double tStep, double vStep,
              const std::string& tName, const std::string& vName, double below = 0) {
  const PixelRect area = canvas.plotArea();
  const double span = hi - lo, tick = 4;
  const Plot plot{ta, tb, lo, hi, double(area.width) / area.height * (1.2 + below) * span / 1.14};
  canvas.setWorldWindow(-0.1 * plot.width, 1.04 * plot.width, lo - (0.12 + below) * span, hi + 0.08 * span);
  canvas.line(plot.at(ta, lo), plot.at(tb, lo), style::axisStroke);
  canvas.line(plot.at(ta, lo), plot.at(ta, hi), style::axisStroke);
  for (double t = std::ceil(ta / tStep - 1e-9) * tStep; t <= tb + 1e-9 * tStep; t += tStep) {
    canvas.line(plot.at(t, lo), plot.at(t, lo) - P2(0, tick / canvas.pixelsPerUnit()), style::axisStroke);
    canvas.text(plot.at(t, lo), format("%g", std::abs(t) < 1e-12 ? 0 : t), smallText, Anchor::Below, P2(0, -2));
  }
  for (double v = std::ceil(lo / vStep - 1e-9) * vStep; v <= hi + 1e-9 * vStep; v += vStep) {
    canvas.line(plot.at(ta, v), plot.at(ta, v) - P2(tick / canvas.pixelsPerUnit(), 0), style::axisStroke);
    canvas.text(plot.at(ta, v), format("%g", std::abs(v) < 1e-12 ? 0 : v), smallText, Anchor::Left, P2(-4, 0));
  }
  canvas.text(plot.at(tb, lo), tName, mathLabel, Anchor::Below, P2(0, -16));
  canvas.text(plot.at(ta, hi), vName, mathLabel, Anchor::AboveRight, P2(4, 0));
  const P2 a = canvas.toPixel(plot.at(ta, hi)), b = canvas.toPixel(plot.at(tb, lo));
  canvas.setClip({int(a.x()), int(a.y()), int(b.x() - a.x()) + 1, int(b.y() - a.y()) + 1});
  if (lo < 0 && hi > 0) canvas.line(plot.at(ta, 0), plot.at(tb, 0), Stroke{palette::axis, 1.0, style::dashed});
  return plot;
}

// A polyline of f(t) over [from, to] within the plot.
template <typename F>
void curve(Canvas& canvas, const Plot& plot, double from, double to, F&& f, const Stroke& stroke) {
  from = std::max(from, plot.ta), to = std::min(to, plot.tb);
  const double far = 10 * (plot.hi - plot.lo);
  std::vector<P2> points;
  for (int k = 0; k < kSamples && to > from; ++k) {
    const double t = from + (to - from) * k / (kSamples - 1);
    points.push_back(plot.at(t, std::clamp(f(t), plot.lo - far, plot.hi + far)));
  }
  if (!points.empty()) canvas.polyline(points, stroke);
}

// A numbered marker per iterate (t, value), coloured by its step kind; labels of iterates
// that fall on top of each other are stacked upwards.
struct Mark {
  double t, value;
  BrentStepKind kind;
};
void numberedMarkers(Canvas& canvas, const Plot& plot, const std::vector<Mark>& marks) {
  std::vector<P2> placed;
  for (std::size_t i = 0; i < marks.size(); ++i) {
    const auto [t, value, kind] = marks[i];
    if (t < plot.ta || t > plot.tb || value < plot.lo || value > plot.hi) continue;
    const P2 p = plot.at(t, value);
    P2 label = canvas.toPixel(p) + P2(6, -12);
    for (bool moved = true; moved;) {
      moved = false;
      for (const P2& q : placed)
        if ((q - label).norm() < 13) label.y() -= 14, moved = true;
    }
    placed.push_back(label);
    const Color color = kindColor(kind);
    canvas.point(p, color, 5, Stroke{palette::background, 1.5});
    canvas.textAtPixel(label.x(), label.y(), std::to_string(i + 1), TextStyle{Font::SansBold, 13, color, 2.5},
                       Anchor::Right);
  }
}

// Legend lines from pixel (x, y) down: a coloured sample (a dot, or a short line) and its text.
void legend(Canvas& canvas, double x, double y, const std::vector<std::pair<Color, std::string>>& items, bool dots) {
  for (const auto& [color, text] : items) {
    canvas.textAtPixel(x, y, dots ? "\u25cf" : "\u2014\u2014", TextStyle{Font::SansBold, 13, color}, Anchor::Right);
    canvas.textAtPixel(x + 26, y, text, kSmall, Anchor::Right);
    y += 17;
  }
}
// The step kinds' colours; the solver's own steps (its leap, its probe at the distance secant:
// not Brent's rules) only where `run` took one.
void kindLegend(Canvas& canvas, double x, double y, const Run* run = nullptr) {
  std::vector<std::pair<Color, std::string>> items{
      {kindColor(BrentStepKind::Bisection), "bisection"}, {kindColor(BrentStepKind::Secant), "secant"},
      {kindColor(BrentStepKind::InverseQuadratic), "inverse quadratic"},
      {kindColor(BrentStepKind::MinimalStep), "minimal step (tolerance)"}};
  if (run && std::any_of(run->trace.steps.begin(), run->trace.steps.end(),
                         [](const ToiStep<double>& step) { return step.kind == BrentStepKind::Leap; }))
    items.push_back({kindColor(BrentStepKind::Leap), "leap (the solver's own)"});
  if (run && std::any_of(run->trace.steps.begin(), run->trace.steps.end(),
                         [](const ToiStep<double>& step) { return step.kind == BrentStepKind::DistanceSecant; }))
    items.push_back({kindColor(BrentStepKind::DistanceSecant), "probe (the solver's own)"});
  legend(canvas, x, y, items, true);
}
void lineLegend(Canvas& canvas, double x, double y) {
  legend(canvas, x, y,
         {{palette::ink.withAlpha(0.3), "true max SD (GJK; exhaustive when intersecting)"},
          {intervalColor(0), "approximation: max over the stored s_k (thick)"},
          {intervalColor(0).withAlpha(0.6), "SD(t, s_k) of each stored vector (thin)"},
          {intervalColor(1), "next complete test (dashed: its start, a restart)"}},
         false);
}

// The §5 picture over [ta, tb]: the reported TOI, the tolerance band, the true maximum SD
// (a wide gray band beneath), for every complete test the lines SD(t, s_k) of its stored
// vectors (thin) and their maximum (thick) from its start to t_1, its start dashed (a
// restart), and the iterates.
Plot solverPlot(Canvas& canvas, const Body& P, const Body& Q, const Run& run, double ta, double tb, double lo,
                double hi, double tStep, double vStep, double below = 0) {
  const Plot plot = plotAxes(canvas, ta, tb, lo, hi, tStep, vStep, "t", "max SD", below);
  if (reportsCollision(run.result.status)) {
    canvas.line(plot.at(run.result.time, lo), plot.at(run.result.time, hi), Stroke{palette::penetration, 1.5});
    canvas.text(plot.at(run.result.time, hi), "TOI", TextStyle{Font::Sans, 13, palette::penetration, 2},
                Anchor::BelowLeft, P2(-2, 0));
  }
  canvas.polygon({plot.at(ta, 0), plot.at(tb, 0), plot.at(tb, kTol), plot.at(ta, kTol)},
                 ShapeStyle{palette::penetration.withAlpha(0.16), style::noStroke});
  canvas.text(plot.at(tb, kTol), "tol", TextStyle{Font::Math, 14, palette::penetration, 2}, Anchor::AboveLeft);
  const Stroke wideGray{palette::ink.withAlpha(0.22), 7};
  curve(canvas, plot, ta, tb, [&](double t) { return trueMaximumSd(P, Q, t); }, wideGray);
  const auto& tests = run.trace.intervals;
  for (std::size_t k = 0; k < tests.size(); ++k) {
    const Color color = intervalColor(k);
    for (int j = 0; j < tests[k].separating.count; ++j) {
      const V s = tests[k].separating.vectors[j];
      curve(canvas, plot, tests[k].start, 1.0, [&](double t) { return supportingDistanceAt(P, Q, s, t); },
            Stroke{color.withAlpha(0.5), 1.0});
    }
    if (tests[k].separating.count > 0)
      curve(canvas, plot, tests[k].start, 1.0, [&](double t) { return approximateMaximumSd(P, Q, tests[k], t); },
            Stroke{color, 2.5});
    if (k > 0) canvas.line(plot.at(tests[k].start, lo), plot.at(tests[k].start, hi), Stroke{color, 1.2, style::dashed});
  }
  std::vector<Mark> marks;
  for (const auto& step : run.trace.steps) marks.push_back({step.t, step.approximateMaxSd, step.kind});
  numberedMarkers(canvas, plot, marks);
  return plot;
}

// ---- bodies and tables ---------------------------------------------------------------------

std::vector<P2> outline(const Body& body, double t) {
  const auto placed = body.at(t);
  std::vector<P2> points;
  for (const V& v : body.shape.vertices()) points.push_back(xy(placed.worldFromBody(v)));
  return points;
}

// The world window (x0, x1) x (y0, y1); P, and the dotted path of Q's centre.
void bodiesPanel(Canvas& canvas, const Body& P, const Body& Q, double x0, double x1, double y0, double y1) {
  canvas.setWorldWindow(x0, x1, y0, y1);
  canvas.setClip(canvas.plotArea());
  std::vector<P2> path;
  for (int k = 0; k <= 100; ++k) path.push_back(xy(Q.at(k / 100.0).center()));
  canvas.polyline(path, Stroke{palette::trajectory, 1.0, style::dotted});
  canvas.polygon(outline(P, 0), style::bodyP);
  canvas.text(xy(P.at(0).center()), "P", TextStyle{Font::Math, 22, palette::bodyPStroke});
}

// Rows of text in columns from pixel (x, y) down, the first row bold; with `swatches`, a
// square in the colour of interval r - 1 before row r.
void table(Canvas& canvas, double x, double y, const std::vector<double>& columns, const Rows& rows,
           bool swatches = false) {
  for (std::size_t r = 0; r < rows.size(); ++r) {
    for (std::size_t c = 0; c < rows[r].size(); ++c)
      canvas.textAtPixel(x + columns[c], y + 18 * r, rows[r][c], r == 0 ? TextStyle{Font::SansBold, 12.5} : kSmall,
                         Anchor::Right);
    if (swatches && r > 0)
      canvas.textAtPixel(x - 16, y + 18 * r, "\u25a0", TextStyle{Font::Sans, 13, intervalColor(r - 1)}, Anchor::Right);
  }
}

// The trace as two tables from pixel (x, y): one row per iterate (t_x, its kind, the
// approximate maximum SD, what followed), then one per complete extrusion test.
void traceTables(Canvas& canvas, double x, double y, const Run& run) {
  Rows steps = {{"#", "t_x", "kind", "\u2248 max SD", "then"}};
  Rows tests = {{"complete test on", "verdict", "distance at start", "stored s_k"}};
  for (std::size_t i = 0; i < run.trace.steps.size(); ++i) {
    const auto& step = run.trace.steps[i];
    std::string then = "< tol: Brent goes on";
    for (const auto& test : run.trace.intervals)
      if (test.start == step.t && test.start > 0)
        then = step.kind == BrentStepKind::DistanceSecant
                   ? "probe: test \u2192 " + std::string(toString(test.status)) +
                         (step.completeTest ? ", proven" : ", far end")
                   : (step.completeTest ? "\u2265 tol: complete test \u2192 " : "converged: test at t_b \u2192 ") +
                         std::string(toString(test.status));
    steps.push_back({std::to_string(i + 1), format("%.6f", step.t), toString(step.kind),
                     format("%.4f", step.approximateMaxSd), then});
  }
  for (const auto& test : run.trace.intervals)
    tests.push_back({"[" + format("%.6f", test.start) + ", 1]", toString(test.status),
                     format("%.4f", test.distanceAtStart), std::to_string(test.separating.count)});
  table(canvas, x, y, {0, 16, 84, 202, 276}, steps);
  table(canvas, x, y + 18 * steps.size() + 14, {0, 140, 280, 400}, tests, true);
}

}  // namespace

int main(int argc, char** argv) {
  std::string out = ".", solver = "gjkx";
  {
    CLI::App app{"Draws chapter 05's figures in DIR: the time of impact, the photo finish and Brent's method."};
    chapter::addFigureOptions(app, out);
    app.add_option("--solver", solver,
                   "the time-of-impact solver of the figures: this project's (gjkx) or §5 exactly as the paper "
                   "wrote it (paper: ToiSettings::paper())")
        ->check(CLI::IsMember({"paper", "gjkx"}))
        ->capture_default_str();
    chapter::parseOrExit(app, argc, argv);
    std::filesystem::create_directories(out);
    solverMode = solver == "paper" ? ToiSolverMode::Paper : ToiSolverMode::Gjkx;
  }
  auto polygon = [](const std::vector<V>& corners) { return Polytope<double>::polygon(corners); };
  const Motion<double> atRest = Motion<double>::fixed(Pose<double>::identity());

  // ---- Figure 1: a time of impact. Q, a 2 x 1.2 box, moves by (-5, -1) and turns by -0.8
  // rad over [0, 1] onto the fixed P, so SD along a fixed direction is not linear in t.
  const Body P1 = moving(polygon({V(0, -1.5, 0), V(2, 0.5, 0), V(0.3, 1.8, 0), V(-1.2, 0.4, 0)}), atRest);
  const Body Q1 = moving(polygon({V(-1, -0.6, 0), V(1, -0.6, 0), V(1, 0.6, 0), V(-1, 0.6, 0)}),
                         Motion<double>::screw(Pose<double>::fromAxisAngle(V::UnitZ(), 0.3, V(6, 0, 0)), V(-5, -1, 0),
                                               V(0, 0, -0.8)));
  std::printf("figure 1, time of impact: ");
  const Run hit = solve(P1, Q1);
  if (hit.result.status != ToiStatus::Hit || hit.result.restarts < 1) {
    std::fprintf(stderr, "figure 1: expected a hit after a restart\n");
    return 1;
  }
  {
    const double toi = hit.result.time;
    Canvas canvas(1320, 820);
    canvas.setPanel({0, 0, 880, 410});
    canvas.title("(a) max SD(P(t), Q(t), s) and §5's approximations: a hit at TOI = " + format("%.4f", toi));
    solverPlot(canvas, P1, Q1, hit, 0, 1, -1.5, 3.0, 0.1, 0.5);
    kindLegend(canvas, 680, 60, &hit);
    lineLegend(canvas, 100, 300);

    canvas.setPanel({880, 0, 440, 410});
    canvas.title("(b) Q at t_0, t_1, the iterates (faint) and the TOI");
    bodiesPanel(canvas, P1, Q1, -1.8, 7.6, -2.5, 2.4);
    for (const auto& step : hit.trace.steps)
      canvas.polygon(outline(Q1, step.t), ShapeStyle{palette::none, Stroke{palette::bodyQStroke.withAlpha(0.35), 1}});
    canvas.polygon(outline(Q1, 0), style::bodyQ);
    canvas.polygon(outline(Q1, 1), ShapeStyle{palette::none, Stroke{palette::bodyQStroke, 1.0, style::dashed}});
    canvas.polygon(outline(Q1, toi), ShapeStyle{palette::highlight.withAlpha(0.25), style::highlightStroke});
    canvas.line(xy(hit.result.witnessP), xy(hit.result.witnessQ), Stroke{palette::ink, 2});
    canvas.text(xy(Q1.at(0).center()), "Q(t_0)", mathLabel);
    canvas.text(xy(Q1.at(1).center()), "Q(t_1)", mathLabel, Anchor::Below, P2(0, -40));
    canvas.text(xy(Q1.at(toi).center()), "Q(TOI)", mathLabel, Anchor::Below, P2(10, -26));

    canvas.setPanel({0, 410, 700, 410});
    canvas.title("(c) close to the TOI: the tolerance band, iterates 2 to " + std::to_string(hit.trace.steps.size()));
    solverPlot(canvas, P1, Q1, hit, 0.694, 0.701, 0.0, 0.08, 0.001, 0.01);

    canvas.setPanel({700, 410, 620, 410});
    canvas.title("(d) the solver's trace");
    traceTables(canvas, canvas.plotArea().x + 20, canvas.plotArea().y + 10, hit);
    chapter::save(canvas, out, "brent-time-of-impact");
  }

  // ---- Figure 2: a photo finish. A 3.2 x 0.6 bar moves by (-8, 1) over the corner of the
  // block P and turns by -2 rad: no single direction separates them at both t_0 and t_1.
  const Body P2b = moving(polygon({V(-1.5, -1.5, 0), V(1.5, -1.5, 0), V(1.5, 1, 0), V(0.5, 1.5, 0), V(-1.5, 1.5, 0)}),
                          atRest);
  const Body Q2 = moving(polygon({V(-1.6, -0.3, 0), V(1.6, -0.3, 0), V(1.6, 0.3, 0), V(-1.6, 0.3, 0)}),
                         Motion<double>::screw(Pose<double>::fromAxisAngle(V::UnitZ(), 1.0, V(4, 2.3, 0)), V(-8, 1, 0),
                                               V(0, 0, -2)));
  std::printf("figure 2, photo finish: ");
  const Run finish = solve(P2b, Q2);
  if (finish.result.status != ToiStatus::PhotoFinish) {
    std::fprintf(stderr, "figure 2: expected a photo finish\n");
    return 1;
  }
  {
    double common = -1e300, closest = 1e300;  // the best single direction for t_0 and t_1; the true minimum
    for (const V& s : unitDirections(3600))
      common = std::max(common, std::min(supportingDistanceAt(P2b, Q2, s, 0.0), supportingDistanceAt(P2b, Q2, s, 1.0)));
    for (int k = 0; k < kSamples; ++k) closest = std::min(closest, trueMaximumSd(P2b, Q2, double(k) / (kSamples - 1)));
    std::printf("  best single direction: min(SD(t_0, s), SD(t_1, s)) = %.4f; true max SD >= %.4f on [0, 1]\n",
                common, closest);
    // The chain [c_0, c_1], [c_1, c_2], ... [c_n, 1]: the complete tests' starts, and per
    // link the stored vector that separates best at both its ends (its proof).
    const auto& tests = finish.trace.intervals;
    std::vector<double> chain;
    std::vector<V> proof;
    for (const auto& test : tests) chain.push_back(test.start);
    chain.push_back(1.0);
    for (std::size_t k = 0; k < tests.size(); ++k) {
      auto both = [&](const V& s) {
        return std::min(supportingDistanceAt(P2b, Q2, s, chain[k]), supportingDistanceAt(P2b, Q2, s, chain[k + 1]));
      };
      const auto first = tests[k].separating.vectors.begin(), last = first + tests[k].separating.count;
      proof.push_back(*std::max_element(first, last, [&](const V& a, const V& b) { return both(a) < both(b); }));
    }
    auto name = [&](std::size_t k) {
      return k == 0 ? "t_0" : k + 1 == chain.size() ? "t_1" : "t_{x" + std::to_string(k) + "}";
    };

    Canvas canvas(1320, 460 + 80 + 18 * int(finish.trace.steps.size() + tests.size() + 2));
    canvas.setPanel({0, 0, 880, 460});
    canvas.title("(a) the first test fails, yet max SD stays above tol: a photo finish in " +
                 std::to_string(tests.size()) + " intervals");
    const Plot plot = solverPlot(canvas, P2b, Q2, finish, 0, 1, -1.5, 3.0, 0.1, 0.5, 0.22);
    canvas.setClip(canvas.plotArea());
    const double pixel = 1 / canvas.pixelsPerUnit();
    for (std::size_t k = 0; k + 1 < chain.size(); ++k) {  // the chain, as brackets under the t axis
      const Stroke stroke{intervalColor(k), 2.5};
      const double y = -1.5 - (40 + 12 * (k % 2)) * pixel;
      canvas.line(plot.at(chain[k], y), plot.at(chain[k + 1], y), stroke);
      for (double t : {chain[k], chain[k + 1]}) canvas.line(plot.at(t, y), plot.at(t, y + 6 * pixel), stroke);
      if (k > 0) canvas.text(plot.at(chain[k], 3), name(k), TextStyle{Font::Math, 15, stroke.color, 2}, Anchor::Above);
    }
    canvas.text(plot.at(0.5, -1.5 - 62 * pixel), "the chain: the extrusion test succeeds on each interval", kSmall);
    kindLegend(canvas, 680, 60, &finish);

    canvas.setPanel({880, 0, 440, 460});
    canvas.title("(b) Q at the chain's times, each link's separating line");
    bodiesPanel(canvas, P2b, Q2, -5.6, 5.6, -2.4, 5.2);
    canvas.polygon(outline(Q2, 0), style::bodyQ);
    canvas.polygon(outline(Q2, 1), ShapeStyle{palette::none, Stroke{palette::bodyQStroke, 1.0, style::dashed}});
    for (std::size_t k = 0; k < chain.size(); ++k) {
      if (k > 0 && k + 1 < chain.size())
        canvas.polygon(outline(Q2, chain[k]), ShapeStyle{palette::none, Stroke{intervalColor(k), 1.5}});
      canvas.text(xy(Q2.at(chain[k]).center()), name(k), TextStyle{Font::Math, 15, palette::ink, 2});
    }
    for (std::size_t k = 0; k < proof.size(); ++k) {  // normal to s, between P and Q at both ends of link k
      const V& s = proof[k];
      const V onP = P2b.at(0).support(s);
      const double hQ = std::min(s.dot(Q2.at(chain[k]).support(-s)), s.dot(Q2.at(chain[k + 1]).support(-s)));
      const P2 middle = xy(V(onP + 0.5 * (hQ - s.dot(onP)) * s)), along(-s.y(), s.x());
      canvas.line(middle - 3.5 * along, middle + 3.5 * along, Stroke{intervalColor(k), 1.5, style::dashed});
    }
    canvas.text(P2(0, -2.6), "best single s for t_0 and t_1: SD \u2264 " + format("%.2f", common), kSmall);

    canvas.setPanel({0, 460, 1320, canvas.height() - 460});
    canvas.title("(c) the solver's trace: Brent's iterates, and the complete extrusion tests (the chain)");
    traceTables(canvas, 130, 460 + 46, finish);
    lineLegend(canvas, 780, 460 + 46);
    chapter::save(canvas, out, "brent-photo-finish");
  }

  // ---- Figure 3: Brent's method alone, on his example x^3 - 2x - 5 over [1, 3].
  auto f = [](double x) { return x * x * x - 2 * x - 5; };
  const RootResult<double> root = findRoot(f, 1.0, 3.0, 1e-10);
  std::printf("figure 3, root finder: x^3 - 2x - 5 = 0 at x = %.12f (f = %.2e) after %d iterations, %s\n", root.root,
              root.fRoot, root.iterations, root.status == RootStatus::Converged ? "converged" : "iteration cap");
  {
    // The bracket after each iterate: the root stays between the two ends where f has
    // opposite signs, and each iterate replaces the end whose sign it shares.
    std::vector<std::pair<double, double>> brackets = {{1.0, 3.0}};
    for (const auto& it : root.iterates) {
      auto [a, b] = brackets.back();
      ((it.fx < 0) == (f(a) < 0) ? a : b) = it.x;
      brackets.push_back({a, b});
    }
    Canvas canvas(1320, 560);
    canvas.setPanel({0, 0, 840, 560});
    canvas.title("(a) f(x) = x^3 - 2x - 5: Brent's iterates, and the bracket after each (below)");
    const Plot plot = plotAxes(canvas, 1, 3, -6, 16, 0.25, 2, "x", "f(x)", 0.45);
    curve(canvas, plot, 1, 3, f, Stroke{palette::ink, 2});
    std::vector<Mark> marks;
    for (const auto& it : root.iterates) marks.push_back({it.x, it.fx, it.kind});
    for (double x : {1.0, 3.0}) canvas.point(plot.at(x, f(x)), palette::ink, 4);
    numberedMarkers(canvas, plot, marks);
    canvas.setClip(canvas.plotArea());
    for (std::size_t k = 0; k < brackets.size(); ++k) {
      const double y = -6 - (42 + 13 * k) / canvas.pixelsPerUnit();
      const Color color = k == 0 ? palette::ink : kindColor(root.iterates[k - 1].kind);
      canvas.line(plot.at(brackets[k].first, y), plot.at(brackets[k].second, y), Stroke{color, 5});
      canvas.text(plot.at(1, y), k == 0 ? "[a, b]" : std::to_string(k), TextStyle{Font::SansBold, 12, color},
                  Anchor::Left, P2(-6, 0));
    }
    canvas.text(plot.at(1, -6), "a", mathLabel, Anchor::AboveRight);
    canvas.text(plot.at(3, 16), "b", mathLabel, Anchor::BelowRight);
    kindLegend(canvas, 110, 60);

    canvas.setPanel({840, 0, 480, 560});
    canvas.title("(b) findRoot(f, 1, 3, 10^{-10}).iterates");
    Rows rows = {{"#", "x", "f(x)", "kind", "bracket"}};
    for (std::size_t k = 0; k < root.iterates.size(); ++k)
      rows.push_back({std::to_string(k + 1), format("%.12f", root.iterates[k].x), format("%+.2e", root.iterates[k].fx),
                      toString(root.iterates[k].kind),
                      format("%.1e", std::abs(brackets[k + 1].second - brackets[k + 1].first))});
    table(canvas, 870, 60, {0, 18, 132, 210, 330}, rows);
    chapter::save(canvas, out, "brent-root-finder");
  }
  return 0;
}
