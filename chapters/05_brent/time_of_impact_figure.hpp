// brent-time-of-impact.png: a time of impact (§5). In the figure's query Q, a 2 x 1.2 box,
// moves by (-5, -1) and turns by -0.8 rad over [0, 1] onto the fixed P, so SD along a fixed
// direction is not linear in t; a reader's query (chapter 05's options) is drawn the same way.
#pragma once

#include "solver_plot.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace brent_figures {

/// The plot's windows of the time-of-impact figure: (a) over [0, 1], (b) the bodies, (c) close
/// to the time of impact.
struct ToiWindows {
  double lo = -1.5, hi = 3.0, vStep = 0.5;                  ///< (a): max SD from lo to hi, ticks every vStep
  double x0 = -1.8, x1 = 7.6, y0 = -2.5, y1 = 2.4;          ///< (b): the world window
  double ta = 0.694, tb = 0.701, zoomHi = 0.08;             ///< (c): [ta, tb] x [0, zoomHi]
  double tStep = 0.001, zoomStep = 0.01;                    ///< (c): its ticks
};

/// The windows of a reader's query: (a) the range of the true maximum SD, (b) the bodies'
/// extent over [0, 1], (c) 0.007 around the time of impact (or the last iterate).
inline ToiWindows windowsOf(const Body& P, const Body& Q, const Run& run) {
  ToiWindows w;
  double lo = 0, hi = run.tolerance();
  V low = V::Constant(1e300), high = V::Constant(-1e300);
  for (int k = 0; k <= 100; ++k) {
    const double t = k / 100.0, value = trueMaximumSd(P, Q, t);
    lo = std::min(lo, value), hi = std::max(hi, value);
    for (const Body* body : {&P, &Q})
      for (const V& v : body->shape.vertices()) {
        const V x = body->at(t).worldFromBody(v);
        low = low.cwiseMin(x), high = high.cwiseMax(x);
      }
  }
  w.vStep = chapter::roundStep(hi - lo, 8);
  w.lo = std::floor(lo / w.vStep) * w.vStep, w.hi = std::ceil(hi / w.vStep) * w.vStep;
  w.x0 = low.x() - 0.8, w.x1 = high.x() + 0.8, w.y0 = low.y() - 0.8, w.y1 = high.y() + 0.8;
  double centre = 0.5;
  if (reportsCollision(run.result.status)) centre = run.result.time;
  else if (!run.trace.steps.empty()) centre = run.trace.steps.back().t;
  w.ta = std::max(0.0, centre - 0.0035), w.tb = std::min(1.0, w.ta + 0.007), w.ta = w.tb - 0.007;
  w.zoomHi = 1.6 * run.tolerance(), w.zoomStep = chapter::roundStep(w.zoomHi, 8);
  return w;
}

/// Draws the time-of-impact figure of `run` (P, Q over [0, 1]) in `out`, in the windows `w`.
inline void timeOfImpactFigure(const std::string& out, const Body& P, const Body& Q, const Run& run,
                               const ToiWindows& w) {
  const bool hit = reportsCollision(run.result.status);
  const double toi = run.result.time;
  Canvas canvas(1320, 820);
  canvas.setPanel({0, 0, 880, 410});
  canvas.title(hit ? "(a) max SD(P(t), Q(t), s) and §5's approximations: a hit at TOI = " + format("%.4f", toi)
                   : "(a) max SD(P(t), Q(t), s) and §5's approximations: " + std::string(toString(run.result.status)));
  solverPlot(canvas, P, Q, run, 0, 1, w.lo, w.hi, 0.1, w.vStep);
  kindLegend(canvas, 680, 60, &run);
  lineLegend(canvas, 100, 300);

  canvas.setPanel({880, 0, 440, 410});
  canvas.title(hit ? "(b) Q at t_0, t_1, the iterates (faint) and the TOI" : "(b) Q at t_0, t_1 and the iterates (faint)");
  bodiesPanel(canvas, P, Q, w.x0, w.x1, w.y0, w.y1);
  for (const auto& step : run.trace.steps)
    canvas.polygon(outline(Q, step.t), ShapeStyle{palette::none, Stroke{palette::bodyQStroke.withAlpha(0.35), 1}});
  canvas.polygon(outline(Q, 0), style::bodyQ);
  canvas.polygon(outline(Q, 1), ShapeStyle{palette::none, Stroke{palette::bodyQStroke, 1.0, style::dashed}});
  if (hit) {
    canvas.polygon(outline(Q, toi), ShapeStyle{palette::highlight.withAlpha(0.25), style::highlightStroke});
    canvas.line(xy(run.result.witnessP), xy(run.result.witnessQ), Stroke{palette::ink, 2});
  }
  canvas.text(xy(Q.at(0).center()), "Q(t_0)", mathLabel);
  canvas.text(xy(Q.at(1).center()), "Q(t_1)", mathLabel, Anchor::Below, P2(0, -40));
  if (hit) canvas.text(xy(Q.at(toi).center()), "Q(TOI)", mathLabel, Anchor::Below, P2(10, -26));

  canvas.setPanel({0, 410, 700, 410});
  canvas.title(hit ? "(c) close to the TOI: the tolerance band, iterates 2 to " + std::to_string(run.trace.steps.size())
                   : "(c) close to the last iterate: the tolerance band");
  solverPlot(canvas, P, Q, run, w.ta, w.tb, 0.0, w.zoomHi, w.tStep, w.zoomStep);

  canvas.setPanel({700, 410, 620, 410});
  canvas.title("(d) the solver's trace");
  traceTables(canvas, canvas.plotArea().x + 20, canvas.plotArea().y + 10, run);
  chapter::save(canvas, out, "brent-time-of-impact");
}

}  // namespace brent_figures
