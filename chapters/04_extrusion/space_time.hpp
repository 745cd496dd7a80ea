// Fig. 1, row A's inset: the two bodies swept through time as bands of x against t, drawn
// for each of the three kinds of test (what a static, a sweeping and an extrusion test see).
#pragma once

#include "moving_pair.hpp"

#include <algorithm>
#include <utility>
#include <vector>

namespace extrusion_figures {

/// "Extrusion intersection tests take a four-dimensional approach": each body swept through
/// time is a solid in space-time, and the test asks whether the two solids meet. With x
/// across and t upwards, a body's x-extent over [t_0, t_1] is a band: slanted while it
/// moves, upright while it rests. In row A the bodies' y-extents overlap at every instant,
/// so the bands meet exactly when the bodies do, and x against t shows all there is.
/// The inset lies under the bodies, on the panel's own x axis, t from t_0 at `bottom` to t_1 at `top`.
enum class SpaceTime { Static, Sweeping, Extrusion };

/// The x-extent [lo, hi] of a body at time t.
inline std::pair<double, double> xExtent(const Body& b, double t) {
  return {b.at(t).support(V(-1, 0, 0)).x(), b.at(t).support(V(1, 0, 0)).x()};
}

inline void drawSpaceTime(Canvas& c, const Pair& pair, SpaceTime mode, double bottom, double top, const ToiResult<double>* toi) {
  const auto Y = [&](double t) { return bottom + (top - bottom) * (t - t0) / (t1 - t0); };
  constexpr int samples = 64;
  const double axisX = pair.xmin + 0.4, right = pair.xmax - 0.1;
  const TextStyle small{Font::Math, 13, palette::ink, 2.0, palette::background};
  const TextStyle note{Font::Sans, 12, palette::ink, 2.0, palette::background};
  // The axes: t upwards, coloured by the time ramp (the key of the poses above), and x.
  for (int k = 0; k < 40; ++k)
    c.line(P2(axisX, Y(t0 + (t1 - t0) * k / 40)), P2(axisX, Y(t0 + (t1 - t0) * (k + 1) / 40)),
           Stroke{timeColour(t0 + (t1 - t0) * (k + 0.5) / 40), 4});
  c.arrow(P2(axisX, Y(t1)), P2(axisX, Y(t1) + 0.35), Stroke{palette::ink, 1.0}, 7);
  c.text(P2(axisX, Y(t1) + 0.35), "t", small, Anchor::Left);
  c.arrow(P2(axisX, bottom - 0.12), P2(right, bottom - 0.12), Stroke{palette::ink, 1.0}, 7);
  c.text(P2(right, bottom - 0.12), "x", small, Anchor::Above);
  c.text(P2(axisX, Y(t0)), "t_0", small, Anchor::Left);
  c.text(P2(axisX, Y(t1)), "t_1", small, Anchor::Left);
  if (mode == SpaceTime::Extrusion)  // a tick at each pose drawn above, in its colour
    for (int k = 1; k < 8; ++k)
      c.line(P2(axisX + 0.08, Y(t0 + (t1 - t0) * k / 8)), P2(axisX + 0.25, Y(t0 + (t1 - t0) * k / 8)),
             Stroke{timeColour(t0 + (t1 - t0) * k / 8), 1.5});
  // The bands: each body's x-extent at every t (faint where the test does not look).
  const double bandAlpha = mode == SpaceTime::Extrusion ? 0.55 : 0.18;
  for (const Body* b : {&pair.P, &pair.Q}) {
    const bool isP = b == &pair.P;
    std::vector<P2> band;
    for (int k = 0; k <= samples; ++k) band.push_back(P2(xExtent(*b, t0 + (t1 - t0) * k / samples).first, Y(t0 + (t1 - t0) * k / samples)));
    for (int k = samples; k >= 0; --k) band.push_back(P2(xExtent(*b, t0 + (t1 - t0) * k / samples).second, Y(t0 + (t1 - t0) * k / samples)));
    const Color stroke = isP ? palette::bodyPStroke : palette::bodyQStroke;
    c.polygon(band, ShapeStyle{(isP ? palette::bodyPFill : palette::bodyQFill).withAlpha(bandAlpha),
                               Stroke{stroke.withAlpha(mode == SpaceTime::Extrusion ? 1.0 : 0.35), 1.0}});
  }
  // Where the bands meet: the collision in space-time.
  std::vector<P2> lows, highs;
  for (int k = 0; k <= 4 * samples; ++k) {
    const double t = t0 + (t1 - t0) * k / (4 * samples);
    const auto [p0, p1] = xExtent(pair.P, t);
    const auto [q0, q1] = xExtent(pair.Q, t);
    if (std::max(p0, q0) > std::min(p1, q1)) continue;
    lows.push_back(P2(std::max(p0, q0), Y(t)));
    highs.push_back(P2(std::min(p1, q1), Y(t)));
  }
  if (mode == SpaceTime::Static) {  // two samples: the bodies' extents at t_0 and t_1 only
    for (double t : {t0, t1}) {
      c.line(P2(axisX, Y(t)), P2(right, Y(t)), Stroke{palette::ink, 1.0, style::dashed});
      for (const Body* b : {&pair.P, &pair.Q}) {
        const auto [lo, hi] = xExtent(*b, t);
        c.line(P2(lo, Y(t)), P2(hi, Y(t)), Stroke{b == &pair.P ? palette::bodyPStroke : palette::bodyQStroke, 5});
      }
    }
    c.text(P2(right, Y(t1)), "two samples, both apart: the meeting is between", note, Anchor::AboveLeft);
    return;
  }
  if (mode == SpaceTime::Sweeping) {  // each body's x over the whole interval, whenever it is there
    for (const Body* b : {&pair.P, &pair.Q}) {
      const auto [a0, a1] = xExtent(*b, t0);
      const auto [b0, b1] = xExtent(*b, t1);
      const double lo = std::min(a0, b0), hi = std::max(a1, b1);
      const bool isP = b == &pair.P;
      c.polygon({P2(lo, Y(t0)), P2(hi, Y(t0)), P2(hi, Y(t1)), P2(lo, Y(t1))},
                ShapeStyle{(isP ? palette::bodyPFill : palette::bodyQFill).withAlpha(0.35),
                           Stroke{isP ? palette::bodyPStroke : palette::bodyQStroke, 1.0, style::dashed}});
    }
    c.text(P2(right, Y(t1)), "each body's x over all of [t_0, t_1]: when is lost", note, Anchor::AboveLeft);
    return;
  }
  if (!lows.empty()) {  // the extrusion: the bands themselves, and where they meet
    std::vector<P2> meet = lows;
    meet.insert(meet.end(), highs.rbegin(), highs.rend());
    c.polygon(meet, ShapeStyle{palette::highlight.withAlpha(0.9), Stroke{palette::ink, 1.0}});
  }
  // The interval the test is asked about, as a bracket along t, and the time of impact.
  const double bx = right - 0.15;
  c.line(P2(bx, Y(t0)), P2(bx, Y(t1)), Stroke{palette::ink, 1.5});
  for (double t : {t0, t1}) c.line(P2(bx - 0.12, Y(t)), P2(bx, Y(t)), Stroke{palette::ink, 1.5});
  c.text(P2(bx, Y(t0 + 0.85 * (t1 - t0))), "[t_0, t_1]", small, Anchor::Left, P2(-4, 0));
  c.text(P2(right, Y(t1)), "the bodies swept through time meet", note, Anchor::AboveLeft);
  if (toi && toi->status == ToiStatus::Hit) {
    c.line(P2(axisX, Y(toi->time)), P2(bx, Y(toi->time)), Stroke{palette::penetration, 1.2, style::dashed});
    c.text(P2(bx, Y(toi->time)), "TOI", TextStyle{Font::Sans, 12, palette::penetration, 2.0, palette::background},
           Anchor::BelowLeft, P2(-6, 0));
  }
}

}  // namespace extrusion_figures
