// Internal: the FreeType faces and glyph cache behind text.hpp (not installed).
#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <mutex>
#include <tuple>
#include <vector>

namespace gjkx::render::detail {

// The DejaVu faces the labels of the figures are set in.
enum class Face : int { Sans = 0, SansBold, Serif, SerifItalic, SerifBold, SerifBoldItalic, MathFallback, Count };

// True for the faces that slant (italic correction of scripts and accents).
inline bool isItalic(Face f) { return f == Face::SerifItalic || f == Face::SerifBoldItalic; }

// A glyph of a face, after falling back to other faces for missing characters.
struct GlyphRef {
  Face face = Face::Sans;
  unsigned index = 0;
  bool operator<(const GlyphRef& o) const { return std::tie(face, index) < std::tie(o.face, o.index); }
};

// Unhinted metrics in pixels, y up from the baseline.
struct GlyphMetrics {
  double advance = 0.0;
  double xMin = 0.0, xMax = 0.0, yMin = 0.0, yMax = 0.0;
  bool inked = false;
};

// A rendered glyph: `rows` x `width` coverage bytes; its top-left pixel is at
// (left, -top) from the pen position on the baseline (y down).
struct GlyphBitmap {
  int width = 0, rows = 0, left = 0, top = 0;
  std::vector<std::uint8_t> pixels;
};

// Process-wide cache of faces and glyphs; callers hold lock() while using it.
class FontCache {
 public:
  static FontCache& instance();
  std::unique_lock<std::mutex> lock() { return std::unique_lock<std::mutex>(mutex_); }

  GlyphRef resolve(Face preferred, char32_t codepoint);
  GlyphMetrics metrics(GlyphRef glyph, int size64);
  // `phase` in [0, 4): horizontal offset of phase / 4 pixel.
  const GlyphBitmap& bitmap(GlyphRef glyph, int size64, int phase);
  double kerning(GlyphRef left, GlyphRef right, int size64);

  FontCache(const FontCache&) = delete;
  FontCache& operator=(const FontCache&) = delete;
  ~FontCache();

 private:
  FontCache();
  struct Impl;
  std::unique_ptr<Impl> impl_;
  std::mutex mutex_;
};

}  // namespace gjkx::render::detail
