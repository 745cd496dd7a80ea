// Chapter 05's plots of a value over time (or of f over x): the axes, a sampled curve, the
// numbered iterates coloured by the rule that chose them, and legends.
#pragma once

#include "../chapter.hpp"

#include <gjkx/render/canvas.hpp>
#include <gjkx/root_solver/brent_method.hpp>

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

namespace brent_figures {

using namespace gjkx::render;
using P2 = Eigen::Vector2d;
using chapter::format;

/// Instants at which a curve is drawn.
constexpr int kSamples = 801;
/// The text of legends and tables.
const TextStyle kSmall{Font::Sans, 12.5, palette::ink, 2.0};

/// One colour per complete extrusion test (interval).
inline Color intervalColor(std::size_t k) {
  static const Color colors[] = {Color::hex(0x0072B2), Color::hex(0x2E8540), Color::hex(0x7B4EA3),
                                 Color::hex(0x009E9E), Color::hex(0xB8860B)};
  return colors[k % 5];
}
/// One colour per Brent step kind, in the order of BrentStepKind.
inline Color kindColor(gjkx::BrentStepKind kind) {
  static const Color colors[] = {Color::hex(0x9E9E9E), palette::ink, palette::highlight, Color::hex(0xCC79A7),
                                 Color::hex(0x009E73), Color::hex(0xD55E00)};
  return colors[static_cast<int>(kind)];
}

/// setWorldWindow scales x and y alike, so t in [ta, tb] is stretched to `width` value
/// units (as chapter 03 stretches the angle of s). Curves are clipped to [ta, tb] x [lo, hi].
struct Plot {
  double ta, tb, lo, hi, width;
  P2 at(double t, double v) const { return P2((t - ta) / (tb - ta) * width, v); }
};

/// The axes of a plot over [ta, tb] x [lo, hi] with ticks every tStep and vStep; `below` (a
/// fraction of hi - lo) is kept free under the t axis.
inline Plot plotAxes(Canvas& canvas, double ta, double tb, double lo, double hi, double tStep, double vStep,
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

/// A polyline of f(t) over [from, to] within the plot.
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

/// An iterate (t, value) and the rule that chose it.
struct Mark {
  double t, value;
  gjkx::BrentStepKind kind;
};
/// A numbered marker per iterate, coloured by its step kind; labels of iterates that fall on
/// top of each other are stacked upwards.
inline void numberedMarkers(Canvas& canvas, const Plot& plot, const std::vector<Mark>& marks) {
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

/// Legend lines from pixel (x, y) down: a coloured sample (a dot, or a short line) and its text.
inline void legend(Canvas& canvas, double x, double y, const std::vector<std::pair<Color, std::string>>& items,
                   bool dots) {
  for (const auto& [color, text] : items) {
    canvas.textAtPixel(x, y, dots ? "\u25cf" : "\u2014\u2014", TextStyle{Font::SansBold, 13, color}, Anchor::Right);
    canvas.textAtPixel(x + 26, y, text, kSmall, Anchor::Right);
    y += 17;
  }
}

}  // namespace brent_figures
