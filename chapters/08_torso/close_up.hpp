// Fig. 5's close-ups: under each panel of the whole scene, the same instant framed on the
// bones alone, so that they read at first sight (in the whole scene, framed on the plant and
// the fall, the torso is about 70 pixels tall). A bone thrown far from the others is left
// out of the framing, as the scattered and settled panels would otherwise zoom out again.
// The plant and the floor are drawn too: a bone is seen where it lies.
#pragma once

#include "torso_model.hpp"

#include <gjkx/render/canvas.hpp>

#include <algorithm>
#include <cstdio>
#include <utility>
#include <vector>

namespace torso {

/// The box around the bones of `frame` (anything with per-bone `position` and `orientation`,
/// as Fig. 5's frames have), grown by a twentieth: of the bones whose centres lie within 45 cm
/// of the bones' median centre (the whole torso while it holds together, the pile at the plant
/// once it has broken, not the bones thrown far), and not fallen off the floor (below z = -0.05).
template <typename Frame>
std::pair<V3, V3> bonesBox(const SceneLayout& layout, const Frame& frame) {
  std::vector<std::pair<V3, V3>> boxes;
  std::vector<V3> centers;
  for (std::size_t b = 0; b < layout.bones.size(); ++b) {
    V3 lo = V3::Constant(1e300), hi = V3::Constant(-1e300);
    for (const V3& v : layout.bones[b].mesh.vertices) {
      const V3 p = frame.orientation[b] * v + frame.position[b];
      lo = lo.cwiseMin(p);
      hi = hi.cwiseMax(p);
    }
    if (hi.z() < -0.05) continue;
    boxes.emplace_back(lo, hi);
    centers.push_back(0.5 * (lo + hi));
  }
  const auto median = [](std::vector<double> x) {
    std::nth_element(x.begin(), x.begin() + long(x.size() / 2), x.end());
    return x[x.size() / 2];
  };
  V3 middle;
  for (int axis = 0; axis < 3; ++axis) {
    std::vector<double> x;
    for (const V3& c : centers) x.push_back(c[axis]);
    middle[axis] = median(x);
  }
  std::vector<double> distance;
  for (const V3& c : centers) distance.push_back((c - middle).norm());
  const double reach = 0.45;  // m: from the torso's middle to its ends (about 0.65 m long), and a margin
  V3 lo = V3::Constant(1e300), hi = V3::Constant(-1e300);
  for (std::size_t b = 0; b < boxes.size(); ++b)
    if (distance[b] <= reach) {
      lo = lo.cwiseMin(boxes[b].first);
      hi = hi.cwiseMax(boxes[b].second);
    }
  const V3 grow = 0.05 * (hi - lo);
  return {lo - grow, hi + grow};
}

/// Height in pixels of Fig. 5's row of close-ups.
constexpr int closeUpHeight = 440;

/// Fig. 5's row of close-ups, below the row of the whole scene (`top` pixels down, panels
/// `width` wide): each of `panels` (the instants of the row above, named `names`) drawn by
/// `drawScene(canvas, layout, frame, box)` framed on bonesBox(), with a frame around it.
template <typename Frame, typename DrawScene>
void closeUpRow(gjkx::render::Canvas& canvas, const SceneLayout& layout, const std::vector<Frame>& panels,
                const std::vector<const char*>& names, int width, int top, DrawScene drawScene) {
  using namespace gjkx::render;
  for (std::size_t p = 0; p < panels.size(); ++p) {
    canvas.setPanel({int(p) * width, top, width, closeUpHeight});
    const auto box = bonesBox(layout, panels[p]);
    char title[96];
    std::snprintf(title, sizeof title, "close-up of the bones, %s (%.2f m across)", names[p], (box.second - box.first).norm());
    canvas.title(title, TextStyle{Font::Sans, 14, palette::ink, 0.0, palette::background});
    canvas.setClip(canvas.plotArea());
    drawScene(canvas, layout, panels[p], box);
    const PixelRect r = canvas.plotArea();
    canvas.setPanel({int(p) * width, top, width, closeUpHeight}, 0, 0);
    canvas.setWorldWindow(0, width, 0, closeUpHeight);
    const double x0 = r.x - int(p) * width, y0 = closeUpHeight - (r.y - top), x1 = x0 + r.width, y1 = y0 - r.height;
    canvas.polyline({{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}, Stroke{Color::hex(0xB0B0B0), 1.0}, true);
  }
}

}  // namespace torso
