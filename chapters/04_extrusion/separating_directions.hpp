// The separating space of §3 drawn in the plane: the arcs of the unit circle whose
// directions s separate P and Q (SD > 0) at t_0 and at t_1, their overlap, and the s_i of
// GJK at t_0 that the extrusion test tried.
#pragma once

#include "moving_pair.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

namespace extrusion_figures {

constexpr int kDirections = 1440;    // directions on the unit circle: a quarter degree apart

inline V direction(int k) { return V(std::cos(2 * M_PI * k / kDirections), std::sin(2 * M_PI * k / kDirections), 0); }

/// The arcs of radius r over the runs of sampled directions where `inside` holds.
inline std::vector<std::vector<P2>> arcs(const std::vector<bool>& inside, double r) {
  const int n = int(inside.size());
  int outside = 0;  // start the scan outside every arc (n when every direction is inside)
  while (outside < n && inside[outside]) ++outside;
  std::vector<std::vector<P2>> found;
  for (int j = 0; j < n; ++j) {
    const int k = (outside + 1 + j) % n;
    if (!inside[k]) continue;
    if (j == 0 || !inside[(k + n - 1) % n]) found.emplace_back();
    found.back().push_back(r * xy(direction(k)));
  }
  return found;
}

/// The wedges of the directions where `inside` holds, filled, with their arcs.
inline void drawWedges(Canvas& c, const std::vector<bool>& inside, double radius, const Color& color) {
  for (const auto& arc : arcs(inside, radius)) {
    std::vector<P2> wedge{P2(0, 0)};
    wedge.insert(wedge.end(), arc.begin(), arc.end());
    c.polygon(wedge, ShapeStyle{color.withAlpha(0.2), style::noStroke});
    c.polyline(arc, Stroke{color, 5});
  }
}

inline std::string degrees(const std::vector<bool>& inside) {
  return std::to_string(std::lround(360.0 * std::count(inside.begin(), inside.end(), true) / kDirections)) + "\u00b0";
}

/// The directions panel: SD(t_0, s) > 0 and SD(t_1, s) > 0 on the unit circle, and GJK's s_i at t_0.
inline std::string drawSpace(Canvas& c, const Pair& pair, const ExtrusionTrace<double>& trace) {
  c.setWorldWindow(-1.45, 1.45, -1.6, 1.4);
  c.axes();
  std::vector<bool> start(kDirections), end(kDirections), both(kDirections);
  for (int k = 0; k < kDirections; ++k) {
    start[k] = supportingDistanceAt(pair.P, pair.Q, direction(k), t0) > 0;
    end[k] = supportingDistanceAt(pair.P, pair.Q, direction(k), t1) > 0;
    both[k] = start[k] && end[k];
  }
  c.circle({0, 0}, 1, ShapeStyle{palette::none, style::axisStroke});
  drawWedges(c, start, 1.0, atStart);
  drawWedges(c, end, 1.08, atEnd);
  for (const auto& arc : arcs(both, 0.92)) {  // the overlap: the vectors that separate over [t_0, t_1]
    c.line({0, 0}, arc.front(), Stroke{right, style::lineThin});
    c.line({0, 0}, arc.back(), Stroke{right, style::lineThin});
    c.polyline(arc, Stroke{right, 5});
  }
  // GJK's s_i at t_0 on the circle: hollow gray where SD(t_0) <= 0, orange where only
  // SD(t_0) > 0, green where both; one label for directions a few degrees apart.
  std::vector<std::pair<V, std::string>> labels;
  for (const auto& step : trace.steps) {
    const Color color = step.separatesEnd ? right : (step.separatesStart ? atStart : palette::separating);
    c.point(xy(step.s), step.separatesStart ? color : palette::background, 5.5, Stroke{color, 2});
    const std::string name = "s_" + std::to_string(step.i);
    if (!labels.empty() && labels.back().first.dot(step.s) > std::cos(0.15)) labels.back().second += ", " + name;
    else labels.push_back({step.s, name});
  }
  for (const auto& [s, name] : labels)
    c.text(1.16 * xy(s), name, TextStyle{Font::Math, style::labelSize, palette::ink, 2.5}, chapter::toward(xy(s)));
  const PixelRect p = c.panel();
  const std::pair<Color, std::string> legend[] = {
      {atStart, "SD(t_0, s) > 0: " + degrees(start)}, {atEnd, "SD(t_1, s) > 0: " + degrees(end)}, {right, "both: " + degrees(both)}};
  for (int k = 0; k < 3; ++k)
    c.textAtPixel(p.x + 16, p.y + p.height - 58 + 20 * k, legend[k].second,
                  TextStyle{Font::Sans, 13, legend[k].first, 2.5}, Anchor::Right);
  return degrees(start) + " at t_0, " + degrees(end) + " at t_1, overlap " + degrees(both);
}

}  // namespace extrusion_figures
