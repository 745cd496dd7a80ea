/// @file
/// @brief Labels and titles of the paper's figures: a tiny TeX-like markup, set by Pango.
///
/// Labels are written in a TeX-like markup so the paper's notation reads well in the
/// chapters' code; pangoMarkup() translates it to Pango's markup, and Pango lays it out:
///
/// | markup | meaning |
/// |--------|---------|
/// | V_P, s_{12}, 10^4 | subscript, superscript (one character or a braced group) |
/// | \$...\$ | switches math style on and off inside a Sans label |
/// | \\alpha, \\le, \\in, ... | Greek letters and common math symbols |
/// | \\, and \\; and \\quad | thin, medium and wide spaces |
/// | a backslash before _ ^ { } $ or a backslash | that character literally |
///
/// (The table shows the markup itself; in a C++ string literal each backslash is doubled.)
/// In math style (Font::Math, or between dollar signs) letters are italic serif, digits
/// and symbols upright serif, and a hyphen is a minus sign. Unknown commands and
/// unbalanced braces throw std::invalid_argument.
#pragma once

#include <gjkx/render/style.hpp>

#include <string>

namespace gjkx::render {

/// The typefaces of the paper's figures (DejaVu, Debian's fonts-dejavu-core).
enum class Font {
  Math,      ///< Math labels such as V_P or s_1: italic serif letters, upright digits.
  Sans,      ///< Panel titles and plain annotations.
  SansBold,  ///< Emphasised titles.
};

/// How a label or title of a figure is set and painted.
struct TextStyle {
  Font font = Font::Math;                 ///< Typeface (math labels by default).
  double size = style::labelSize;         ///< Font size in pixels (the em size).
  Color color = palette::ink;             ///< Colour of the glyphs.
  double halo = 0.0;                      ///< Radius in pixels of a halo around the glyphs (0: none).
  Color haloColor = palette::background;  ///< Colour of the halo, normally the figure background.
};

inline constexpr TextStyle mathLabel{Font::Math, style::labelSize, palette::ink, 0.0, palette::background};  ///< Math labels (V_P, s_1, ...).
inline constexpr TextStyle titleText{Font::Sans, style::titleSize, palette::ink, 0.0, palette::background};  ///< Panel titles.
inline constexpr TextStyle smallText{Font::Sans, style::smallSize, palette::ink, 0.0, palette::background};  ///< Small annotations.

/// The ink box of a label relative to its pen origin on the baseline, in pixels (x to the
/// right, ascent up, descent down); the Canvas places labels beside points by it.
struct TextExtent {
  double left = 0.0;     ///< Leftmost ink relative to the pen origin (may be negative).
  double right = 0.0;    ///< Rightmost ink relative to the pen origin.
  double ascent = 0.0;   ///< Ink above the baseline.
  double descent = 0.0;  ///< Ink below the baseline (subscripts increase it).
  double advance = 0.0;  ///< Width of the label's line as Pango lays it out.

  double width() const { return right - left; }     ///< Width of the ink box.
  double height() const { return ascent + descent; }  ///< Height of the ink box.
};

/// @p markup (the file comment's TeX-like markup) as Pango markup in @p font: the one
/// place where the figures' notation becomes Pango's spans, sub and sup.
std::string pangoMarkup(const std::string& markup, Font font);

/// The ink box of @p markup set in @p font at @p sizePx pixels (> 0, else
/// std::invalid_argument), as the Canvas draws it.
TextExtent measureText(const std::string& markup, Font font, double sizePx);

}  // namespace gjkx::render
