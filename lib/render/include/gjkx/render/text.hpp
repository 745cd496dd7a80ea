/// @file
/// @brief Labels and titles of the paper's figures, rasterised with FreeType.
///
/// Labels use a tiny TeX-like markup so the paper's notation reads well:
///
/// | markup | meaning |
/// |--------|---------|
/// | V_P, s_{12} | subscript (one character or a braced group) |
/// | 10^4, s_1^2 | superscript; a subscript and a superscript stack |
/// | \$...\$ | switches math style on and off inside a Sans title |
/// | \\alpha, \\in, \\le, ... | Greek letters and common math symbols |
/// | \\vec{s}, \\bar{x}, \\hat{n}, \\tilde{x}, \\dot{x} | accents |
/// | \\mathrm{..}, \\mathbf{..}, \\boldsymbol{..}, \\text{..} | upright, bold, bold italic, plain text |
/// | \\, and \\; and \\quad | thin, medium and wide spaces |
/// | a backslash before _ ^ { } $ or a backslash | that character literally |
///
/// (The table shows the markup itself; in a C++ string literal each backslash is doubled.)
///
/// In math style (Font::Math, or between dollar signs) letters are italic
/// serif, digits and symbols upright serif, and a hyphen becomes a minus sign;
/// spaces are kept as typed. UTF-8 text is accepted. Unknown commands and
/// unbalanced braces throw std::invalid_argument.
#pragma once

#include <gjkx/render/image.hpp>
#include <gjkx/render/style.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace gjkx::render {

/// The typefaces of the paper's figures.
enum class Font {
  Math,      ///< Math labels such as V_P or s_1: italic serif letters, upright digits (DejaVu Serif).
  Sans,      ///< Panel titles and plain annotations (DejaVu Sans).
  SansBold,  ///< Emphasised titles (DejaVu Sans Bold).
  Serif,     ///< Upright serif text (DejaVu Serif).
};

/// How a label or title of a figure is typeset and painted.
struct TextStyle {
  Font font = Font::Math;            ///< Typeface (math labels by default).
  double size = style::labelSize;    ///< Font size in pixels (the em size).
  Color color = palette::ink;        ///< Colour of the glyphs.
  double halo = 0.0;                 ///< Radius in pixels of a background-coloured halo behind the glyphs (0: none).
  Color haloColor = palette::background;  ///< Colour of the halo, normally the figure background.
};

/// Math labels of the figures (V_P, s_1, ...): italic serif, ink.
inline constexpr TextStyle mathLabel = TextStyle{Font::Math, style::labelSize, palette::ink, 0.0, palette::background};
/// Panel titles of the figures: sans serif, ink.
inline constexpr TextStyle titleText = TextStyle{Font::Sans, style::titleSize, palette::ink, 0.0, palette::background};
/// Small plain annotations (tick labels, notes): sans serif.
inline constexpr TextStyle smallText = TextStyle{Font::Sans, style::smallSize, palette::ink, 0.0, palette::background};

/// The ink box of a typeset label relative to its pen origin on the baseline,
/// in whole pixels (x to the right, ascent up, descent down). The figures use
/// it to place labels next to points without overlapping them.
struct TextExtent {
  int left = 0;      ///< Leftmost inked column relative to the pen origin (may be negative).
  int right = 0;     ///< One past the rightmost inked column relative to the pen origin.
  int ascent = 0;    ///< Rows of ink above the baseline.
  int descent = 0;   ///< Rows of ink below the baseline (subscripts increase it).
  double advance = 0.0;  ///< Where the pen ends, in pixels from the origin.

  /// Width of the ink box in pixels.
  /// @return right - left.
  int width() const { return right - left; }
  /// Height of the ink box in pixels.
  /// @return ascent + descent.
  int height() const { return ascent + descent; }
};

/// A typeset label as a grayscale coverage mask, ready to be laid over a
/// figure image.
struct TextMask {
  int width = 0;     ///< Width of the mask in pixels.
  int height = 0;    ///< Height of the mask in pixels.
  int originX = 0;   ///< Column of the pen origin inside the mask.
  int originY = 0;   ///< Row of the baseline inside the mask.
  std::vector<std::uint8_t> coverage;  ///< width * height bytes, 255 = fully inked, rows from the top.
  TextExtent extent; ///< The ink box (the mask is exactly this box).
};

/// Typesets @p markup (see the file comment) and rasterises it with FreeType
/// (grayscale anti-aliasing, deterministic). Used for every label of the figures.
/// @param markup The label in the tiny TeX-like markup.
/// @param font The typeface.
/// @param sizePx The font size in pixels (> 0).
/// @return The coverage mask and ink box.
TextMask rasterizeText(const std::string& markup, Font font, double sizePx);

/// The ink box of @p markup, for laying out the figures' labels (same
/// typesetting as rasterizeText()).
/// @param markup The label in the tiny TeX-like markup.
/// @param font The typeface.
/// @param sizePx The font size in pixels (> 0).
/// @return The ink box and the advance.
TextExtent measureText(const std::string& markup, Font font, double sizePx);

/// Paints @p markup onto @p image with its pen origin at pixel (@p x, @p baseline)
/// (rounded to whole pixels so glyphs stay crisp), clipped to @p clip. Draws
/// the halo of @p style first if it has one. The Canvas uses it for all labels.
/// @param image The figure image to paint on.
/// @param x Column of the pen origin.
/// @param baseline Row of the baseline.
/// @param markup The label in the tiny TeX-like markup.
/// @param style Font, size, colour and halo.
/// @param clip Only pixels inside this rectangle are touched.
void drawText(Image& image, double x, double baseline, const std::string& markup, const TextStyle& style,
              const PixelRect& clip);

/// Paints an already rasterised label (see rasterizeText()) with its pen origin
/// at whole pixel (@p x, @p baseline), clipped to @p clip.
/// @param image The figure image to paint on.
/// @param x Column of the pen origin.
/// @param baseline Row of the baseline.
/// @param mask The rasterised label.
/// @param style Colour and halo (font and size are already in the mask).
/// @param clip Only pixels inside this rectangle are touched.
void drawTextMask(Image& image, int x, int baseline, const TextMask& mask, const TextStyle& style,
                  const PixelRect& clip);

}  // namespace gjkx::render
