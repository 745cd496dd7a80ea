// gjkx_animate --view spacetime: a scene in the plane z = 0 as §3 sees it. Left, the plane:
// the bodies at time t, their earlier poses outlined in the colour of their time (as Figs. 1
// and 4 draw a motion). Right, space-time (x, y, t), time going up: each body's extrusion,
// the solid its outline sweeps from the first frame shown to t, growing as the animation
// runs. "Extrusion intersection tests take a four-dimensional approach to detect
// spacio-temporal intersection directly" (§1); in the plane the extrusions are 3D solids,
// and two bodies collide exactly where theirs meet.
#pragma once

#include "scene_view.hpp"

#include <gjkx/render/canvas.hpp>
#include <gjkx/support_mapping/polytope.hpp>

#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

namespace animation {

/// The colour of time t in [t0, t1]: dark purple through blue to green (three stops of the
/// viridis ramp, as chapter 04 colours the poses of a motion).
inline Color timeColor(double t, double t0, double t1) {
  static const Color stops[] = {Color::hex(0x440154), Color::hex(0x31688e), Color::hex(0x35b779)};
  const double x = std::clamp(t1 > t0 ? (t - t0) / (t1 - t0) : 0.0, 0.0, 1.0) * 2;
  const int k = std::min(1, int(x));
  return mix(stops[k], stops[k + 1], x - k);
}

/// The outline of body b's projection on the plane z = 0 at `frame`.
inline std::vector<Eigen::Vector2d> outlineAt(const BodyLook& look, const RunFrame& frame, std::size_t b) {
  std::vector<Eigen::Vector2d> flat;
  for (const V3& v : look.surface.vertices) {
    const V3 p = frame.orientation[b] * v + frame.position[b];
    flat.emplace_back(p.x(), p.y());
  }
  return hull2d(flat);
}

/// Draws frame `shown[upTo]` as the file comment says: the plane in the left half of
/// `canvas` (`top` pixels down, `height` tall), space-time in the right half; `view`'s box
/// frames the plane (x, y) and its angles turn the space-time camera.
inline void drawSpaceTime(gjkx::render::Canvas& canvas, const std::vector<BodyLook>& looks, const std::vector<RunFrame>& shown,
                          std::size_t upTo, const View& view, int top, int height) {
  using namespace gjkx::render;
  const int half = canvas.width() / 2;
  const double t0 = shown.front().time, t1 = shown.back().time, now = shown[upTo].time;
  // The plane.
  canvas.setPanel({0, top, half, height}, 6, 24);
  canvas.title("the plane z = 0 at t, earlier poses in their time's colour", smallText);
  View plane = view;
  plane.kind = "xy";
  setView(canvas, plane);
  for (std::size_t b = 0; b < looks.size(); ++b) {
    if (looks[b].isStatic) continue;
    for (std::size_t k = 0; k < upTo; k += std::max<std::size_t>(1, shown.size() / 12))
      canvas.polygon(outlineAt(looks[b], shown[k], b),
                     ShapeStyle{palette::none, Stroke{timeColor(shown[k].time, t0, t1).withAlpha(0.7), 1.2}});
  }
  for (std::size_t b = 0; b < looks.size(); ++b)
    drawBody(canvas, looks[b], shown[upTo].position[b], shown[upTo].orientation[b], plane, looks[b].color,
             mix(looks[b].color, palette::ink, 0.6));
  // Space-time: t scaled so that the time shown is as tall as the plane's framed box is wide.
  const double extent = std::max(view.hi.x() - view.lo.x(), view.hi.y() - view.lo.y());
  const double scale = extent / std::max(t1 - t0, 1e-9);
  const auto lift = [&](const Eigen::Vector2d& p, double t) { return V3(p.x(), p.y(), (t - t0) * scale); };
  canvas.setPanel({half, top, canvas.width() - half, height}, 6, 24);
  canvas.title("space-time (x, y, t): each body's extrusion from t_0 to t", smallText);
  const V3 lo(view.lo.x(), view.lo.y(), 0), hi(view.hi.x(), view.hi.y(), extent);
  canvas.setCamera(Camera::orbit(0.5 * (lo + hi), 0.5 * (hi - lo).norm() / view.zoom, view.azimuth, view.elevation, 0.6,
                                 canvas.plotAspect()));
  canvas.setClip(canvas.plotArea());
  // The floor of space-time, t = t_0, and the time axis.
  canvas.polygon3({lift({lo.x(), lo.y()}, t0), lift({hi.x(), lo.y()}, t0), lift({hi.x(), hi.y()}, t0), lift({lo.x(), hi.y()}, t0)},
                  ShapeStyle{Color::hex(0xF2F2F2), Stroke{palette::axis, 1.0}});
  canvas.arrow3(lift({lo.x(), lo.y()}, t0), lift({lo.x(), lo.y()}, t1 + 0.08 * (t1 - t0)), style::axisStroke);
  canvas.text3(lift({lo.x(), lo.y()}, t1 + 0.08 * (t1 - t0)), "t", mathLabel, Anchor::Above);
  for (std::size_t b = 0; b < looks.size(); ++b) {
    if (looks[b].isStatic) continue;
    for (std::size_t k = 0; k < upTo; ++k) {  // a slab between frames k and k + 1: the hull of both outlines
      std::vector<gjkx::Vector3<double>> points;
      for (const auto& p : outlineAt(looks[b], shown[k], b)) points.push_back(lift(p, shown[k].time));
      for (const auto& p : outlineAt(looks[b], shown[k + 1], b)) points.push_back(lift(p, shown[k + 1].time));
      try {
        canvas.mesh(chapter::meshOf(gjkx::Polytope<double>::hull(points)),
                    MeshStyle{mix(looks[b].color, timeColor(shown[k].time, t0, t1), 0.25), Stroke{palette::ink, 0.5}, false, true});
      } catch (const std::invalid_argument&) {  // a flat slab (no time between the frames): nothing to draw
      }
    }
    // The body at t: its outline on top of its extrusion.
    std::vector<V3> ring;
    for (const auto& p : outlineAt(looks[b], shown[upTo], b)) ring.push_back(lift(p, now));
    canvas.polyline3(ring, Stroke{mix(looks[b].color, palette::ink, 0.6), 2.0}, true);
  }
}

}  // namespace animation
