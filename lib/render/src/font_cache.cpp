// FreeType faces (DejaVu) and the glyph cache of the figures' labels.
#include "font_cache.hpp"

#include <ft2build.h>
#include FT_FREETYPE_H
#include FT_OUTLINE_H

#include <array>
#include <stdexcept>
#include <string>

#ifndef GJKX_FONT_DIR
#define GJKX_FONT_DIR "/usr/share/fonts/truetype/dejavu"
#endif

namespace gjkx::render::detail {

namespace {

constexpr std::array<const char*, static_cast<int>(Face::Count)> kFiles = {
    "DejaVuSans.ttf",         "DejaVuSans-Bold.ttf",      "DejaVuSerif.ttf",         "DejaVuSerif-Italic.ttf",
    "DejaVuSerif-Bold.ttf",   "DejaVuSerif-BoldItalic.ttf", "DejaVuMathTeXGyre.ttf"};

// Faces tried, in order, when the preferred one lacks a character.
constexpr std::array<Face, 3> kFallbacks = {Face::Sans, Face::Serif, Face::MathFallback};

}  // namespace

struct FontCache::Impl {
  FT_Library library = nullptr;
  std::array<FT_Face, static_cast<int>(Face::Count)> faces{};
  std::array<bool, static_cast<int>(Face::Count)> tried{};
  std::array<int, static_cast<int>(Face::Count)> currentSize{};
  std::map<std::tuple<GlyphRef, int>, GlyphMetrics> metrics;
  std::map<std::tuple<GlyphRef, int, int>, GlyphBitmap> bitmaps;

  // The face, loaded on first use; null if the file is missing (fallback faces only).
  FT_Face face(Face f, bool required) {
    const auto i = static_cast<std::size_t>(f);
    if (!tried[i]) {
      tried[i] = true;
      const std::string path = std::string(GJKX_FONT_DIR) + "/" + kFiles[i];
      if (FT_New_Face(library, path.c_str(), 0, &faces[i]) != 0) faces[i] = nullptr;
      currentSize[i] = -1;
    }
    if (!faces[i] && required)
      throw std::runtime_error(std::string("gjkx::render text: cannot load the font '") + GJKX_FONT_DIR + "/" +
                               kFiles[i] + "'");
    return faces[i];
  }

  FT_Face sized(Face f, int size64) {
    FT_Face ft = face(f, true);
    const auto i = static_cast<std::size_t>(f);
    if (currentSize[i] != size64) {
      if (FT_Set_Char_Size(ft, 0, size64, 72, 72) != 0)
        throw std::runtime_error("gjkx::render text: cannot set font size " + std::to_string(size64 / 64.0));
      currentSize[i] = size64;
    }
    return ft;
  }
};

FontCache& FontCache::instance() {
  static FontCache cache;
  return cache;
}

FontCache::FontCache() : impl_(std::make_unique<Impl>()) {
  if (FT_Init_FreeType(&impl_->library) != 0) throw std::runtime_error("gjkx::render text: cannot initialise FreeType");
}

FontCache::~FontCache() {
  for (FT_Face f : impl_->faces)
    if (f) FT_Done_Face(f);
  FT_Done_FreeType(impl_->library);
}

GlyphRef FontCache::resolve(Face preferred, char32_t codepoint) {
  FT_Face ft = impl_->face(preferred, true);
  if (unsigned index = FT_Get_Char_Index(ft, codepoint); index != 0 || codepoint == 0)
    return GlyphRef{preferred, index};
  for (Face f : kFallbacks) {
    if (FT_Face fb = impl_->face(f, false))
      if (unsigned index = FT_Get_Char_Index(fb, codepoint); index != 0) return GlyphRef{f, index};
  }
  return GlyphRef{preferred, 0};  // .notdef box
}

GlyphMetrics FontCache::metrics(GlyphRef glyph, int size64) {
  const auto key = std::make_tuple(glyph, size64);
  if (auto it = impl_->metrics.find(key); it != impl_->metrics.end()) return it->second;
  FT_Face ft = impl_->sized(glyph.face, size64);
  if (FT_Load_Glyph(ft, glyph.index, FT_LOAD_NO_HINTING | FT_LOAD_NO_BITMAP) != 0)
    throw std::runtime_error("gjkx::render text: cannot load glyph " + std::to_string(glyph.index));
  GlyphMetrics m;
  m.advance = ft->glyph->linearHoriAdvance / 65536.0;
  if (ft->glyph->format == FT_GLYPH_FORMAT_OUTLINE && ft->glyph->outline.n_points > 0) {
    FT_BBox box;
    FT_Outline_Get_CBox(&ft->glyph->outline, &box);
    m.xMin = box.xMin / 64.0;
    m.xMax = box.xMax / 64.0;
    m.yMin = box.yMin / 64.0;
    m.yMax = box.yMax / 64.0;
    m.inked = true;
  }
  impl_->metrics.emplace(key, m);
  return m;
}

const GlyphBitmap& FontCache::bitmap(GlyphRef glyph, int size64, int phase) {
  const auto key = std::make_tuple(glyph, size64, phase);
  if (auto it = impl_->bitmaps.find(key); it != impl_->bitmaps.end()) return it->second;
  FT_Face ft = impl_->sized(glyph.face, size64);
  // Light hinting keeps the vertical metrics crisp and the advances exact.
  if (FT_Load_Glyph(ft, glyph.index, FT_LOAD_TARGET_LIGHT | FT_LOAD_NO_BITMAP) != 0)
    throw std::runtime_error("gjkx::render text: cannot load glyph " + std::to_string(glyph.index));
  GlyphBitmap out;
  if (ft->glyph->format == FT_GLYPH_FORMAT_OUTLINE) {
    FT_Outline_Translate(&ft->glyph->outline, phase * 16, 0);
    if (FT_Render_Glyph(ft->glyph, FT_RENDER_MODE_NORMAL) != 0)
      throw std::runtime_error("gjkx::render text: cannot render glyph " + std::to_string(glyph.index));
    const FT_Bitmap& bm = ft->glyph->bitmap;
    out.width = static_cast<int>(bm.width);
    out.rows = static_cast<int>(bm.rows);
    out.left = ft->glyph->bitmap_left;
    out.top = ft->glyph->bitmap_top;
    out.pixels.resize(static_cast<std::size_t>(out.width) * static_cast<std::size_t>(out.rows));
    for (int r = 0; r < out.rows; ++r)
      for (int c = 0; c < out.width; ++c)
        out.pixels[static_cast<std::size_t>(r * out.width + c)] = bm.buffer[r * bm.pitch + c];
  }
  return impl_->bitmaps.emplace(key, std::move(out)).first->second;
}

double FontCache::kerning(GlyphRef left, GlyphRef right, int size64) {
  if (left.face != right.face) return 0.0;
  FT_Face ft = impl_->sized(left.face, size64);
  if (!FT_HAS_KERNING(ft)) return 0.0;
  FT_Vector k{0, 0};
  if (FT_Get_Kerning(ft, left.index, right.index, FT_KERNING_UNFITTED, &k) != 0) return 0.0;
  return k.x / 64.0;
}

}  // namespace gjkx::render::detail
