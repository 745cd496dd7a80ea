// The kept figures of figures/: a PNG read back, two renderings of a figure compared, and
// the tolerance within which a regenerated figure is the kept one. Shared by the `figures`
// target (gjkx_keep_figures, which rewrites a kept PNG only beyond the tolerance) and the
// figure tests (tests/figures/test_figures.cpp), so both hold a figure to the same rule.
#pragma once

#include <cairo.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <stdexcept>
#include <string>
#include <vector>

namespace kept {

/// A regenerated figure is the kept one if at most this fraction of its pixels differ by
/// more than kChannelThreshold in some channel: another machine's rasteriser or font
/// library may round the last bit of an edge's coverage otherwise.
constexpr double kTolerance = 0.005;
/// The largest difference of one channel (of 255) that still counts as the same.
constexpr int kChannelThreshold = 8;

/// A PNG's pixels as Cairo reads them: 32-bit words, alpha in the high byte, premultiplied.
struct Pixels {
  int width = 0, height = 0;
  std::vector<std::uint32_t> argb;

  /// Red, green, blue and alpha (straight, not premultiplied) of pixel (x, y), y from the top.
  std::array<std::uint8_t, 4> rgba(int x, int y) const {
    const std::uint32_t p = argb[std::size_t(y) * std::size_t(width) + std::size_t(x)], a = p >> 24;
    const auto c = [&](int shift) { return std::uint8_t(a == 0 ? 0 : std::min(255u, ((p >> shift & 0xFFu) * 255u + a / 2) / a)); };
    return {c(16), c(8), c(0), std::uint8_t(a)};
  }
};

/// Reads the PNG file `path`; std::runtime_error naming it if it cannot.
inline Pixels readPng(const std::string& path) {
  cairo_surface_t* s = cairo_image_surface_create_from_png(path.c_str());
  const cairo_status_t status = cairo_surface_status(s);
  Pixels out;
  if (status == CAIRO_STATUS_SUCCESS) {
    out.width = cairo_image_surface_get_width(s);
    out.height = cairo_image_surface_get_height(s);
    const bool opaque = cairo_image_surface_get_format(s) == CAIRO_FORMAT_RGB24;  // its alpha byte is unused
    for (int y = 0; y < out.height; ++y)
      for (int x = 0; x < out.width; ++x) {
        const auto* row = reinterpret_cast<const std::uint32_t*>(cairo_image_surface_get_data(s) + std::ptrdiff_t(y) * cairo_image_surface_get_stride(s));
        out.argb.push_back(opaque ? row[x] | 0xFF000000u : row[x]);
      }
  }
  cairo_surface_destroy(s);
  if (status != CAIRO_STATUS_SUCCESS) throw std::runtime_error("cannot read " + path + ": " + cairo_status_to_string(status));
  return out;
}

/// How far apart two renderings of a figure are.
struct Diff {
  bool sameSize = false;            ///< Whether both have the same width and height.
  std::size_t differingPixels = 0;  ///< Pixels with a channel differing by more than the threshold.
  double differingFraction = 1.0;   ///< differingPixels over the pixel count (1 if the sizes differ).
  int maxChannelDifference = 255;   ///< Largest difference of one channel (255 if the sizes differ).

  /// Whether the two are the same figure: the same size, and within kTolerance.
  bool same() const { return sameSize && differingFraction <= kTolerance; }
};

/// Compares two renderings pixel by pixel: a pixel differs if one of its channels differs
/// by more than `threshold`.
inline Diff compare(const Pixels& a, const Pixels& b, int threshold = kChannelThreshold) {
  Diff d;
  d.sameSize = a.width == b.width && a.height == b.height && a.argb.size() == b.argb.size();
  if (!d.sameSize) return d;
  d.maxChannelDifference = 0;
  for (std::size_t i = 0; i < a.argb.size(); ++i) {
    int worst = 0;
    for (int shift = 0; shift < 32; shift += 8)
      worst = std::max(worst, std::abs(int(a.argb[i] >> shift & 0xFFu) - int(b.argb[i] >> shift & 0xFFu)));
    d.maxChannelDifference = std::max(d.maxChannelDifference, worst);
    d.differingPixels += worst > threshold;
  }
  d.differingFraction = a.argb.empty() ? 0.0 : double(d.differingPixels) / double(a.argb.size());
  return d;
}

}  // namespace kept
