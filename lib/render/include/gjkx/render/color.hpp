/// @file
/// @brief RGBA colours of the paper's figures.
#pragma once

#include <cstdint>

namespace gjkx::render {

/// A straight (not premultiplied) RGBA colour with components in [0, 1]; every stroke,
/// fill and label of the figures is painted with one.
struct Color {
  double r = 0.0;  ///< Red component in [0, 1].
  double g = 0.0;  ///< Green component in [0, 1].
  double b = 0.0;  ///< Blue component in [0, 1].
  double a = 1.0;  ///< Opacity in [0, 1]; 0 is fully transparent.

  /// The colour 0xRRGGBB with opacity @p alpha, as the palette writes its entries.
  static constexpr Color hex(std::uint32_t rgb24, double alpha = 1.0) {
    return Color{((rgb24 >> 16) & 0xFFu) / 255.0, ((rgb24 >> 8) & 0xFFu) / 255.0, (rgb24 & 0xFFu) / 255.0, alpha};
  }
  /// This colour with opacity @p alpha, e.g. a translucent fill made from a stroke colour.
  constexpr Color withAlpha(double alpha) const { return Color{r, g, b, alpha}; }
  /// True if the colour paints nothing (opacity 0): "no fill" and "no outline".
  constexpr bool invisible() const { return a <= 0.0; }
};

/// The colour a fraction @p t of the way from @p x to @p y (t = 0 gives x).
constexpr Color mix(const Color& x, const Color& y, double t) {
  return Color{x.r + (y.r - x.r) * t, x.g + (y.g - x.g) * t, x.b + (y.b - x.b) * t, x.a + (y.a - x.a) * t};
}

}  // namespace gjkx::render
