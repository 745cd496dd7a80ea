// Rasterisation of typeset labels into coverage masks and their compositing
// onto the figure images.
#include <gjkx/render/text.hpp>

#include "font_cache.hpp"
#include "text_layout.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace gjkx::render {

namespace {

struct Placed {
  const detail::GlyphBitmap* bitmap;
  int x0, y0;  // top-left pixel, y down from the baseline
};

}  // namespace

TextMask rasterizeText(const std::string& markup, Font font, double sizePx) {
  detail::FontCache& cache = detail::FontCache::instance();
  auto lock = cache.lock();
  const detail::Layout layout = detail::typeset(markup, font, sizePx);

  std::vector<Placed> placed;
  int minX = std::numeric_limits<int>::max(), minY = minX, maxX = std::numeric_limits<int>::min(), maxY = maxX;
  for (const detail::PlacedGlyph& g : layout.glyphs) {
    // Whole-pixel baseline, quarter-pixel horizontal positions.
    double fx = std::floor(g.x);
    int phase = static_cast<int>(std::lround((g.x - fx) * 4.0));
    if (phase == 4) {
      fx += 1.0;
      phase = 0;
    }
    const detail::GlyphBitmap& bm = cache.bitmap(g.glyph, g.size64, phase);
    if (bm.width == 0 || bm.rows == 0) continue;
    const int x0 = static_cast<int>(fx) + bm.left;
    const int y0 = -static_cast<int>(std::lround(g.y)) - bm.top;
    placed.push_back(Placed{&bm, x0, y0});
    minX = std::min(minX, x0);
    minY = std::min(minY, y0);
    maxX = std::max(maxX, x0 + bm.width);
    maxY = std::max(maxY, y0 + bm.rows);
  }
  for (const detail::PlacedRule& r : layout.rules) {
    minX = std::min(minX, static_cast<int>(std::floor(r.x0)));
    maxX = std::max(maxX, static_cast<int>(std::ceil(r.x1)));
    minY = std::min(minY, static_cast<int>(std::floor(-r.y1)));
    maxY = std::max(maxY, static_cast<int>(std::ceil(-r.y0)));
  }

  TextMask mask;
  mask.extent.advance = layout.advance;
  if (minX >= maxX || minY >= maxY) return mask;  // nothing inked (empty or blank label)

  // Ink-tight box: first accumulate into the bounding box, then trim blank borders.
  const int w = maxX - minX, h = maxY - minY;
  std::vector<int> acc(static_cast<std::size_t>(w) * static_cast<std::size_t>(h), 0);
  for (const Placed& p : placed)
    for (int r = 0; r < p.bitmap->rows; ++r)
      for (int c = 0; c < p.bitmap->width; ++c)
        acc[static_cast<std::size_t>((p.y0 + r - minY) * w + (p.x0 + c - minX))] +=
            p.bitmap->pixels[static_cast<std::size_t>(r * p.bitmap->width + c)];
  for (const detail::PlacedRule& rule : layout.rules)
    for (int py = 0; py < h; ++py)
      for (int px = 0; px < w; ++px) {
        // Exact area of the pixel covered by the rectangle (y up => row -y).
        const double x = px + minX, top = -(py + minY);
        const double ox = std::max(0.0, std::min(x + 1.0, rule.x1) - std::max(x, rule.x0));
        const double oy = std::max(0.0, std::min(top, rule.y1) - std::max(top - 1.0, rule.y0));
        acc[static_cast<std::size_t>(py * w + px)] += static_cast<int>(std::lround(ox * oy * 255.0));
      }

  int c0 = w, c1 = -1, r0 = h, r1 = -1;
  for (int py = 0; py < h; ++py)
    for (int px = 0; px < w; ++px)
      if (acc[static_cast<std::size_t>(py * w + px)] > 0) {
        c0 = std::min(c0, px);
        c1 = std::max(c1, px);
        r0 = std::min(r0, py);
        r1 = std::max(r1, py);
      }
  if (c1 < 0) return mask;
  mask.width = c1 - c0 + 1;
  mask.height = r1 - r0 + 1;
  mask.originX = -(minX + c0);
  mask.originY = -(minY + r0);
  mask.coverage.resize(static_cast<std::size_t>(mask.width) * static_cast<std::size_t>(mask.height));
  for (int py = 0; py < mask.height; ++py)
    for (int px = 0; px < mask.width; ++px)
      mask.coverage[static_cast<std::size_t>(py * mask.width + px)] =
          static_cast<std::uint8_t>(std::min(255, acc[static_cast<std::size_t>((py + r0) * w + (px + c0))]));
  mask.extent.left = -mask.originX;
  mask.extent.right = mask.width - mask.originX;
  mask.extent.ascent = mask.originY;
  mask.extent.descent = mask.height - mask.originY;
  return mask;
}

TextExtent measureText(const std::string& markup, Font font, double sizePx) {
  return rasterizeText(markup, font, sizePx).extent;
}

void drawTextMask(Image& image, int x, int baseline, const TextMask& mask, const TextStyle& style,
                  const PixelRect& clip) {
  if (mask.width == 0 || mask.height == 0) return;
  const int left = x - mask.originX, top = baseline - mask.originY;
  const auto visible = [&](int px, int py) {
    return clip.contains(px, py) && px >= 0 && py >= 0 && px < image.width && py < image.height;
  };
  if (style.halo > 0.0) {
    // Dilate the coverage by a disc of radius `halo` and paint it first.
    const int r = static_cast<int>(std::ceil(style.halo));
    for (int py = -r; py < mask.height + r; ++py)
      for (int px = -r; px < mask.width + r; ++px) {
        double best = 0.0;
        for (int dy = -r; dy <= r && best < 1.0; ++dy)
          for (int dx = -r; dx <= r; ++dx) {
            const int sx = px + dx, sy = py + dy;
            if (sx < 0 || sy < 0 || sx >= mask.width || sy >= mask.height) continue;
            const double d = std::sqrt(double(dx * dx + dy * dy));
            const double weight = std::clamp(style.halo + 0.5 - d, 0.0, 1.0);
            // Partly covered pixels of thin strokes count as solid ink for the halo.
            const double ink = std::min(1.0, 2.0 * mask.coverage[static_cast<std::size_t>(sy * mask.width + sx)] / 255.0);
            best = std::max(best, weight * ink);
          }
        if (best > 0.0 && visible(left + px, top + py)) image.blend(left + px, top + py, style.haloColor, best);
      }
  }
  for (int py = 0; py < mask.height; ++py)
    for (int px = 0; px < mask.width; ++px) {
      const std::uint8_t c = mask.coverage[static_cast<std::size_t>(py * mask.width + px)];
      if (c && visible(left + px, top + py)) image.blend(left + px, top + py, style.color, c / 255.0);
    }
}

void drawText(Image& image, double x, double baseline, const std::string& markup, const TextStyle& style,
              const PixelRect& clip) {
  const TextMask mask = rasterizeText(markup, style.font, style.size);
  drawTextMask(image, static_cast<int>(std::lround(x)), static_cast<int>(std::lround(baseline)), mask, style, clip);
}

}  // namespace gjkx::render
