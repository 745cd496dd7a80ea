// brent-root-finder.png: Brent's method alone (§5: "a root solver that cleverly combines
// bisection, the secant method, and inverse quadratic interpolation"), on his own example
// x^3 - 2x - 5 over [1, 3], with the bracket after each iterate.
#pragma once

#include "solver_plot.hpp"

#include <gjkx/root_solver/brent_method.hpp>

#include <cmath>
#include <string>
#include <utility>
#include <vector>

namespace brent_figures {

/// The bracket [a, b] after each iterate of `root` (first the start [a, b]): the root stays
/// between the two ends where f has opposite signs, and each iterate replaces the end whose
/// sign it shares.
template <typename F>
std::vector<std::pair<double, double>> bracketsOf(const RootResult<double>& root, double a0, double b0, F&& f) {
  std::vector<std::pair<double, double>> brackets = {{a0, b0}};
  for (const auto& it : root.iterates) {
    auto [a, b] = brackets.back();
    ((it.fx < 0) == (f(a) < 0) ? a : b) = it.x;
    brackets.push_back({a, b});
  }
  return brackets;
}

/// Draws the root finder's figure of `root`, Brent's method on f over [1, 3], in `out`.
template <typename F>
void rootFinderFigure(const std::string& out, const RootResult<double>& root, F&& f) {
  const auto brackets = bracketsOf(root, 1.0, 3.0, f);
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

}  // namespace brent_figures
