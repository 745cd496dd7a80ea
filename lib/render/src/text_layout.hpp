// Internal: typesetting of the label markup of text.hpp into placed glyphs.
#pragma once

#include "font_cache.hpp"

#include <gjkx/render/text.hpp>

#include <string>
#include <vector>

namespace gjkx::render::detail {

// A glyph at pen position (x, y): pixels, x right, y up from the label's baseline.
struct PlacedGlyph {
  GlyphRef glyph;
  int size64 = 0;
  double x = 0.0;
  double y = 0.0;
};

// A filled rectangle (accent bars), pixels, y up.
struct PlacedRule {
  double x0 = 0.0, x1 = 0.0, y0 = 0.0, y1 = 0.0;
};

struct Layout {
  std::vector<PlacedGlyph> glyphs;
  std::vector<PlacedRule> rules;
  double advance = 0.0;
};

// Typesets `markup`; throws std::invalid_argument on malformed markup. The
// caller holds FontCache::lock().
Layout typeset(const std::string& markup, Font font, double size);

}  // namespace gjkx::render::detail
