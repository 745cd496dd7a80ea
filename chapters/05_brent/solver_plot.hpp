// Chapter 05's picture of a solver run (§5): the maximum supporting distance over time with
// the approximation of every complete extrusion test and Brent's iterates, the bodies, and
// the run's trace as tables on the figure.
#pragma once

#include "plot.hpp"
#include "solver_runs.hpp"
#include "toi_trace.hpp"

#include <algorithm>
#include <string>
#include <utility>
#include <vector>

namespace brent_figures {

using chapter::xy;
/// Rows of text, the first the header.
using Rows = std::vector<std::vector<std::string>>;

/// The step kinds' colours; the solver's own steps (its leap, its probe at the distance secant:
/// not Brent's rules) only where `run` took one.
inline void kindLegend(Canvas& canvas, double x, double y, const Run* run = nullptr) {
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

/// The curves' legend.
inline void lineLegend(Canvas& canvas, double x, double y) {
  legend(canvas, x, y,
         {{palette::ink.withAlpha(0.3), "true max SD (GJK; exhaustive when intersecting)"},
          {intervalColor(0), "approximation: max over the stored s_k (thick)"},
          {intervalColor(0).withAlpha(0.6), "SD(t, s_k) of each stored vector (thin)"},
          {intervalColor(1), "next complete test (dashed: its start, a restart)"}},
         false);
}

/// The §5 picture over [ta, tb]: the reported TOI, the tolerance band, the true maximum SD
/// (a wide gray band beneath), for every complete test the lines SD(t, s_k) of its stored
/// vectors (thin) and their maximum (thick) from its start to t_1, its start dashed (a
/// restart), and the iterates.
inline Plot solverPlot(Canvas& canvas, const Body& P, const Body& Q, const Run& run, double ta, double tb, double lo,
                       double hi, double tStep, double vStep, double below = 0) {
  const Plot plot = plotAxes(canvas, ta, tb, lo, hi, tStep, vStep, "t", "max SD", below);
  if (reportsCollision(run.result.status)) {
    canvas.line(plot.at(run.result.time, lo), plot.at(run.result.time, hi), Stroke{palette::penetration, 1.5});
    canvas.text(plot.at(run.result.time, hi), "TOI", TextStyle{Font::Sans, 13, palette::penetration, 2},
                Anchor::BelowLeft, P2(-2, 0));
  }
  const double tol = run.tolerance();
  canvas.polygon({plot.at(ta, 0), plot.at(tb, 0), plot.at(tb, tol), plot.at(ta, tol)},
                 ShapeStyle{palette::penetration.withAlpha(0.16), style::noStroke});
  canvas.text(plot.at(tb, tol), "tol", TextStyle{Font::Math, 14, palette::penetration, 2}, Anchor::AboveLeft);
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

/// The outline of a moving polygon at time t, in the figure's plane.
inline std::vector<P2> outline(const Body& body, double t) {
  const auto placed = body.at(t);
  std::vector<P2> points;
  for (const V& v : body.shape.vertices()) points.push_back(xy(placed.worldFromBody(v)));
  return points;
}

/// The world window (x0, x1) x (y0, y1); P, and the dotted path of Q's centre.
inline void bodiesPanel(Canvas& canvas, const Body& P, const Body& Q, double x0, double x1, double y0, double y1) {
  canvas.setWorldWindow(x0, x1, y0, y1);
  canvas.setClip(canvas.plotArea());
  std::vector<P2> path;
  for (int k = 0; k <= 100; ++k) path.push_back(xy(Q.at(k / 100.0).center()));
  canvas.polyline(path, Stroke{palette::trajectory, 1.0, style::dotted});
  canvas.polygon(outline(P, 0), style::bodyP);
  canvas.text(xy(P.at(0).center()), "P", TextStyle{Font::Math, 22, palette::bodyPStroke});
}

/// Rows of text in columns from pixel (x, y) down, the first row bold; with `swatches`, a
/// square in the colour of interval r - 1 before row r.
inline void table(Canvas& canvas, double x, double y, const std::vector<double>& columns, const Rows& rows,
                  bool swatches = false) {
  for (std::size_t r = 0; r < rows.size(); ++r) {
    for (std::size_t c = 0; c < rows[r].size(); ++c)
      canvas.textAtPixel(x + columns[c], y + 18 * r, rows[r][c], r == 0 ? TextStyle{Font::SansBold, 12.5} : kSmall,
                         Anchor::Right);
    if (swatches && r > 0)
      canvas.textAtPixel(x - 16, y + 18 * r, "\u25a0", TextStyle{Font::Sans, 13, intervalColor(r - 1)}, Anchor::Right);
  }
}

/// The trace as two tables from pixel (x, y): one row per iterate (t_x, its kind, the
/// approximate maximum SD, what followed), then one per complete extrusion test.
inline void traceTables(Canvas& canvas, double x, double y, const Run& run) {
  Rows steps = {{"#", "t_x", "kind", "\u2248 max SD", "then"}};
  Rows tests = {{"complete test on", "verdict", "distance at start", "stored s_k"}};
  for (std::size_t i = 0; i < run.trace.steps.size(); ++i) {
    const auto& step = run.trace.steps[i];
    steps.push_back({std::to_string(i + 1), format("%.6f", step.t), toString(step.kind),
                     format("%.4f", step.approximateMaxSd), stepThen(run.trace, step)});
  }
  for (const auto& test : run.trace.intervals)
    tests.push_back({"[" + format("%.6f", test.start) + ", 1]", toString(test.status),
                     format("%.4f", test.distanceAtStart), std::to_string(test.separating.count)});
  table(canvas, x, y, {0, 16, 84, 202, 276}, steps);
  table(canvas, x, y + 18 * steps.size() + 14, {0, 140, 280, 400}, tests, true);
}

}  // namespace brent_figures
