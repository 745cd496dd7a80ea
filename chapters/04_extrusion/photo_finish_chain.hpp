// The photo finish's chain of intervals (§5), drawn for Fig. 4 (c): the links the solver's
// complete extrusion tests proved apart, their separating lines, and a time line of the
// Brent iterates that found their ends.
#pragma once

#include "moving_pair.hpp"

#include <gjkx/brent/time_of_impact.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace extrusion_figures {

// "a 'photo finish', in which the extrusion test fails for the complete time interval t_0
// to t_1 but succeeds when performed on the sequence of intervals t_0 to t_{x1}, t_{x1} to
// t_{x2}, ... t_{xn}, to t_1": every link of the chain has a vector that separates the
// bodies at both of its ends, hence (linear motion) all through it.

/// One link [from, to] of the chain, and the unit vector of its complete test that separates
/// the bodies at both of its ends by the most.
struct Link {
  double from, to;
  V s;
};

/// The links of a photo finish from the solver's complete tests: test k covers
/// [its start, the next test's start], the last one [its start, t_1].
inline std::vector<Link> chainOf(const Pair& pair, const ToiTrace<double>& trace) {
  std::vector<Link> chain;
  const auto& tests = trace.intervals;
  for (std::size_t k = 0; k < tests.size(); ++k) {
    const double from = tests[k].start, to = k + 1 < tests.size() ? tests[k + 1].start : t1;
    if (!(to > from)) continue;
    Link link{from, to, V::UnitX()};
    double best = -std::numeric_limits<double>::infinity();
    for (int j = 0; j < tests[k].separating.count; ++j) {
      const V s = tests[k].separating.vectors[j].normalized();
      const double margin = std::min(supportingDistanceAt(pair.P, pair.Q, s, from), supportingDistanceAt(pair.P, pair.Q, s, to));
      if (margin > best) best = margin, link.s = s;
    }
    chain.push_back(link);
  }
  return chain;
}

/// The name of the k-th end of a chain of n links: t_0, t_{x1}, ..., t_{xn-1}, t_1.
inline std::string endName(std::size_t k, std::size_t links) {
  return k == 0 ? "t_0" : k == links ? "t_1" : "t_{x" + std::to_string(k) + "}";
}
/// A link's colour: the time ramp's at its middle.
inline Color linkColour(const Link& link) { return timeColour(0.5 * (link.from + link.to)); }

/// The colour of a Brent step kind, in the order of BrentStepKind, as in chapter 05's figures.
inline Color kindColour(BrentStepKind kind) {
  static const Color colors[] = {Color::hex(0x9E9E9E), palette::ink, palette::highlight, Color::hex(0xCC79A7),
                                 Color::hex(0x009E73), Color::hex(0xD55E00)};
  return colors[static_cast<int>(kind)];
}
inline const char* kindName(BrentStepKind kind) {
  switch (kind) {
    case BrentStepKind::Bisection: return "bisection";
    case BrentStepKind::Secant: return "secant";
    case BrentStepKind::InverseQuadratic: return "inverse quadratic";
    case BrentStepKind::MinimalStep: return "minimal step";
    case BrentStepKind::Leap: return "leap";
    case BrentStepKind::DistanceSecant: return "distance secant";
  }
  return "?";
}

/// The world point under canvas pixel (px, py) of the current panel.
inline P2 worldAt(Canvas& c, double px, double py) {
  const P2 origin = c.toPixel(P2(0, 0));
  const double k = c.pixelsPerUnit();
  return P2((px - origin.x()) / k, (origin.y() - py) / k);
}

/// The chain in the panel: both bodies at each end t_{xi} inside [t_0, t_1], outlined in
/// its time's colour, and each link's separating line at the poses of both of its ends, in
/// the link's colour. Below, the chain as a time line: a bar per link from t_0 to t_1, and
/// above it the Brent iterates that found the ends, coloured by the rule that chose them.
inline void drawChain(Canvas& c, const Pair& pair, const ToiTrace<double>& trace, const std::vector<Link>& chain) {
  for (std::size_t k = 1; k < chain.size(); ++k)
    for (const Body* b : {&pair.P, &pair.Q}) drawBody(c, *b, chain[k].from, b == &pair.P, Look::Chain);
  // The lines' names go at one of their ends, clear of the bodies' labels and each other:
  // above a line flatter than 45 degrees, else at the end farther from them.
  std::vector<P2> labels;
  for (double t : {t0, t1})
    for (const P2& label : {xy(pair.P.at(t).support(pair.sideP)), xy(pair.Q.at(t).support(pair.sideQ))})
      labels.push_back(label);
  for (std::size_t k = 0; k < chain.size(); ++k) {
    const std::string name = "[" + endName(k, chain.size()) + ", " + endName(k + 1, chain.size()) + "]";
    const V& s = chain[k].s;
    const Color color = linkColour(chain[k]);
    const double halfLength = std::min(1.6, 1.25 / std::max(std::abs(s.x()), 1e-3));
    const P2 middle = lineMiddle(pair, s, chain[k].to), up = s.x() >= 0 ? P2(-s.y(), s.x()) : P2(s.y(), -s.x());
    const auto clearance = [&](const P2& at) {
      double nearest = std::numeric_limits<double>::infinity();
      for (const P2& label : labels) nearest = std::min(nearest, (at - label).norm());
      return nearest;
    };
    const bool flat = std::abs(up.y()) < std::sqrt(0.5);
    const double end = flat || clearance(middle + halfLength * up) >= clearance(middle - halfLength * up) ? 1 : -1;
    drawSeparatingLine(c, pair, s, chain[k].from, "", color, halfLength, end);
    const P2 tip = middle + end * halfLength * up;
    drawSeparatingLine(c, pair, s, chain[k].to, "", color, halfLength, end);
    c.text(tip, name, TextStyle{Font::Math, style::labelSize, color, 2.5}, flat ? Anchor::Above : chapter::toward(end * up));
    labels.push_back(tip);
  }
  // The time line, in pixels at the foot of the plot area.
  const PixelRect area = c.plotArea();
  const double y = area.y + area.height - 24, left = area.x + 58, right = area.x + area.width - 150;
  const auto X = [&](double t) { return left + (right - left) * (t - t0) / (t1 - t0); };
  const auto line = [&](double xa, double ya, double xb, double yb, const Stroke& stroke) {
    c.line(worldAt(c, xa, ya), worldAt(c, xb, yb), stroke);
  };
  const TextStyle small{Font::Sans, 12.5, palette::ink, 2.0, palette::background};
  c.textAtPixel(left - 10, y, "chain", small, Anchor::Left);
  for (const Link& link : chain) line(X(link.from) + 1.5, y, X(link.to) - 1.5, y, Stroke{linkColour(link), 8});
  for (std::size_t k = 0; k <= chain.size(); ++k) {
    const double x = X(k < chain.size() ? chain[k].from : t1);
    line(x, y - 7, x, y + 7, Stroke{palette::ink, 1.2});
    c.textAtPixel(x, y + 9, endName(k, chain.size()), TextStyle{Font::Math, 13, palette::ink, 2.0, palette::background},
                  Anchor::Below);
  }
  std::vector<BrentStepKind> kinds;  // the kinds seen, in order of first use
  std::vector<std::pair<double, int>> placed;
  for (const auto& step : trace.steps) {
    int stacked = 0;
    for (const auto& [x, n] : placed)
      if (std::abs(x - X(step.t)) < 6) stacked = std::max(stacked, n + 1);
    placed.push_back({X(step.t), stacked});
    c.point(worldAt(c, X(step.t), y - 14 - 8 * stacked), kindColour(step.kind), 3.5, Stroke{palette::background, 1});
    if (std::find(kinds.begin(), kinds.end(), step.kind) == kinds.end()) kinds.push_back(step.kind);
  }
  double ly = y - 16 - 15 * (kinds.size() - 1);
  c.textAtPixel(right + 16, ly - 16, "Brent iterates:", small, Anchor::Right);
  for (BrentStepKind kind : kinds) {
    c.textAtPixel(right + 16, ly, "\u25cf", TextStyle{Font::SansBold, 12, kindColour(kind)}, Anchor::Right);
    c.textAtPixel(right + 30, ly, kindName(kind), small, Anchor::Right);
    ly += 15;
  }
}

}  // namespace extrusion_figures
