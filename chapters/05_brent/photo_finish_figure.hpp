// brent-photo-finish.png: a photo finish (§5). A 3.2 x 0.6 bar moves by (-8, 1) over the
// corner of the block P and turns by -2 rad: no single direction separates them at both t_0
// and t_1, yet "the extrusion test fails for the complete time interval t_0 to t_1 but
// succeeds when performed on the sequence of intervals t_0 to t_x1, t_x1 to t_x2, ... t_xn to t_1".
#pragma once

#include "solver_plot.hpp"

#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

namespace brent_figures {

/// Draws the photo-finish figure of `run` (the bar Q passing the block P over [0, 1]) in `out`.
inline void photoFinishFigure(const std::string& out, const Body& P, const Body& Q, const Run& run) {
  double common = -1e300, closest = 1e300;  // the best single direction for t_0 and t_1; the true minimum
  for (const V& s : unitDirections(3600))
    common = std::max(common, std::min(supportingDistanceAt(P, Q, s, 0.0), supportingDistanceAt(P, Q, s, 1.0)));
  for (int k = 0; k < kSamples; ++k) closest = std::min(closest, trueMaximumSd(P, Q, double(k) / (kSamples - 1)));
  std::printf("  best single direction: min(SD(t_0, s), SD(t_1, s)) = %.4f; true max SD >= %.4f on [0, 1]\n", common,
              closest);
  // The chain [c_0, c_1], [c_1, c_2], ... [c_n, 1]: the complete tests' starts, and per
  // link the stored vector that separates best at both its ends (its proof).
  const auto& tests = run.trace.intervals;
  std::vector<double> chain;
  std::vector<V> proof;
  for (const auto& test : tests) chain.push_back(test.start);
  chain.push_back(1.0);
  for (std::size_t k = 0; k < tests.size(); ++k) {
    auto both = [&](const V& s) {
      return std::min(supportingDistanceAt(P, Q, s, chain[k]), supportingDistanceAt(P, Q, s, chain[k + 1]));
    };
    const auto first = tests[k].separating.vectors.begin(), last = first + tests[k].separating.count;
    proof.push_back(*std::max_element(first, last, [&](const V& a, const V& b) { return both(a) < both(b); }));
  }
  auto name = [&](std::size_t k) {
    return k == 0 ? "t_0" : k + 1 == chain.size() ? "t_1" : "t_{x" + std::to_string(k) + "}";
  };

  Canvas canvas(1320, 460 + 80 + 18 * int(run.trace.steps.size() + tests.size() + 2));
  canvas.setPanel({0, 0, 880, 460});
  canvas.title("(a) the first test fails, yet max SD stays above tol: a photo finish in " +
               std::to_string(tests.size()) + " intervals");
  const Plot plot = solverPlot(canvas, P, Q, run, 0, 1, -1.5, 3.0, 0.1, 0.5, 0.22);
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
  kindLegend(canvas, 680, 60, &run);

  canvas.setPanel({880, 0, 440, 460});
  canvas.title("(b) Q at the chain's times, each link's separating line");
  bodiesPanel(canvas, P, Q, -5.6, 5.6, -2.4, 5.2);
  canvas.polygon(outline(Q, 0), style::bodyQ);
  canvas.polygon(outline(Q, 1), ShapeStyle{palette::none, Stroke{palette::bodyQStroke, 1.0, style::dashed}});
  for (std::size_t k = 0; k < chain.size(); ++k) {
    if (k > 0 && k + 1 < chain.size())
      canvas.polygon(outline(Q, chain[k]), ShapeStyle{palette::none, Stroke{intervalColor(k), 1.5}});
    canvas.text(xy(Q.at(chain[k]).center()), name(k), TextStyle{Font::Math, 15, palette::ink, 2});
  }
  for (std::size_t k = 0; k < proof.size(); ++k) {  // normal to s, between P and Q at both ends of link k
    const V& s = proof[k];
    const V onP = P.at(0).support(s);
    const double hQ = std::min(s.dot(Q.at(chain[k]).support(-s)), s.dot(Q.at(chain[k + 1]).support(-s)));
    const P2 middle = xy(V(onP + 0.5 * (hQ - s.dot(onP)) * s)), along(-s.y(), s.x());
    canvas.line(middle - 3.5 * along, middle + 3.5 * along, Stroke{intervalColor(k), 1.5, style::dashed});
  }
  canvas.text(P2(0, -2.6), "best single s for t_0 and t_1: SD \u2264 " + format("%.2f", common), kSmall);

  canvas.setPanel({0, 460, 1320, canvas.height() - 460});
  canvas.title("(c) the solver's trace: Brent's iterates, and the complete extrusion tests (the chain)");
  traceTables(canvas, 130, 460 + 46, run);
  lineLegend(canvas, 780, 460 + 46);
  chapter::save(canvas, out, "brent-photo-finish");
}

}  // namespace brent_figures
