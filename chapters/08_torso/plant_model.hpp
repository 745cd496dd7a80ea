// The aquatic plant of the paper's §6 experiment, which the torso is dropped onto: "an
// aquatic plant fixed in space with 8640 triangles". Made here as an Amazon-sword-like
// rosette: a flower stalk 1 m tall and its leaves, each a stalk (petiole) and a thin
// drooping blade 3 mm thick: the paper's flat objects (chapter 08, torso_model.hpp).
#pragma once

#include "shapes.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace torso {

/// The plant: a flower stalk and `leaves` leaves (stalk and thin blade), about 1 m tall,
/// standing at the origin on z = 0; fixed, one mesh of several closed parts.
inline gjkx::TriangleMesh buildPlant(int leaves) {
  gjkx::TriangleMesh plant;
  plant.source = "plant";
  // The flower stalk.
  const std::vector<V3> stalk = bezier(V3(0, 0, 0.004), V3(0, 0, 0.4), V3(0.02, 0.01, 0.75), V3(0.03, 0.02, 1.0), 24);
  append(plant, sweep(stalk, [](int) { return V3(1, 0, 0); },
                      [](int k) {
                        const double r = lerp(0.006, 0.003, k / 23.0);
                        return profile(8, r, r, r, r);
                      },
                      0.003, "plant stalk"));
  Random random(20060101u);  // the plant is fixed: its own seed, not the drop's
  for (int j = 0; j < leaves; ++j) {
    const double azimuth = j * 2.39996 + random.uniform(-0.2, 0.2);
    const V3 out(std::cos(azimuth), std::sin(azimuth), 0), across(-out.y(), out.x(), 0);
    const double height = random.uniform(0.35, 0.7), reach = random.uniform(0.08, 0.22);
    const V3 base = 0.02 * out + V3(0, 0, 0.004);
    const V3 end = reach * out + V3(0, 0, height);
    const std::vector<V3> petiole = bezier(base, base + V3(0, 0, 0.5 * height), end - 0.5 * reach * out - V3(0, 0, 0.15 * height),
                                           end, 14);
    append(plant, sweep(petiole, [&](int) { return across; },
                        [](int k) {
                          const double r = lerp(0.0055, 0.0035, k / 13.0);
                          return profile(6, r, r, r, r);
                        },
                        0.003, "plant petiole"));
    // The blade: a lance-shaped outline, rising then drooping along its midrib, folded
    // a little along it, 3 mm thick at the middle, thinning to the rim.
    const double length = random.uniform(0.26, 0.4), width = random.uniform(0.045, 0.07);
    const double pitch = random.uniform(0.25, 0.7), droop = random.uniform(0.6, 1.1);
    std::vector<V2> outline;
    const int half = 26;
    for (int i = 0; i <= half; ++i) {
      const double s = length * i / half;
      outline.emplace_back(s, width * std::pow(std::max(0.0, std::sin(M_PI * s / length)), 0.7) * (1 - 0.3 * s / length));
    }
    for (int i = half - 1; i >= 1; --i) outline.emplace_back(outline[std::size_t(i)].x(), -outline[std::size_t(i)].y());
    const V3 start = end - 0.01 * out;
    auto place = [&](const V2& p, double h) {
      // Midrib by small steps along a direction turning down from `pitch` by `droop` over the length.
      V3 m = start;
      const int steps = 16;
      for (int q = 0; q < steps; ++q) {
        const double s = p.x() * (q + 0.5) / steps, angle = pitch - droop * s / length;
        m += (p.x() / steps) * (std::cos(angle) * out + std::sin(angle) * V3(0, 0, 1));
      }
      const double angle = pitch - droop * p.x() / length;
      const V3 normal = (std::cos(angle) * V3(0, 0, 1) - std::sin(angle) * out).normalized();
      return V3(m + p.y() * across + (h + 0.25 * std::fabs(p.y())) * normal);
    };
    append(plant, plate(outline, {0.66, 0.33}, [](const V2&, int) { return 0.0015; }, place, "plant leaf"));
  }
  requireClosedOriented(plant);
  return plant;
}

}  // namespace torso
