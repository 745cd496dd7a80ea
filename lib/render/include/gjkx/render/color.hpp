/// @file
/// @brief RGBA colours of the renderer that draws the figures of the paper.
#pragma once

#include <cstdint>

namespace gjkx::render {

/// A straight (not premultiplied) RGBA colour with components in [0, 1]; every
/// stroke, fill and label of the paper's figures (Fig. 1 to the last one) is
/// painted with one.
struct Color {
  double r = 0.0;  ///< Red component in [0, 1].
  double g = 0.0;  ///< Green component in [0, 1].
  double b = 0.0;  ///< Blue component in [0, 1].
  double a = 1.0;  ///< Opacity in [0, 1]; 0 is fully transparent.

  /// The colour 0xRRGGBB with opacity @p alpha, as the palette of the paper's
  /// figures writes its entries.
  /// @param rgb24 Red, green and blue as the hexadecimal number 0xRRGGBB.
  /// @param alpha Opacity in [0, 1].
  /// @return The colour.
  static constexpr Color hex(std::uint32_t rgb24, double alpha = 1.0) {
    return Color{((rgb24 >> 16) & 0xFFu) / 255.0, ((rgb24 >> 8) & 0xFFu) / 255.0,
                 (rgb24 & 0xFFu) / 255.0, alpha};
  }

  /// This colour with its opacity replaced, e.g. a translucent fill of body P
  /// in Fig. 2 made from its stroke colour.
  /// @param alpha The new opacity in [0, 1].
  /// @return The colour with the new opacity.
  constexpr Color withAlpha(double alpha) const { return Color{r, g, b, alpha}; }

  /// True if the colour paints nothing (opacity 0); the figures use it for
  /// "no fill" and "no outline".
  /// @return Whether the opacity is zero.
  constexpr bool invisible() const { return a <= 0.0; }
};

/// Exact component-wise equality of two colours (used by the tests of the
/// figures' palette).
/// @param x The first colour.
/// @param y The second colour.
/// @return Whether all four components are equal.
constexpr bool operator==(const Color& x, const Color& y) {
  return x.r == y.r && x.g == y.g && x.b == y.b && x.a == y.a;
}

/// Component-wise inequality of two colours (the figures' palette tests).
/// @param x The first colour.
/// @param y The second colour.
/// @return Whether some component differs.
constexpr bool operator!=(const Color& x, const Color& y) { return !(x == y); }

/// The colour a fraction @p t of the way from @p x to @p y (t = 0 gives x),
/// used to derive shades of the palette for the figures.
/// @param x The colour at t = 0.
/// @param y The colour at t = 1.
/// @param t The interpolation parameter, normally in [0, 1].
/// @return The interpolated colour.
constexpr Color mix(const Color& x, const Color& y, double t) {
  return Color{x.r + (y.r - x.r) * t, x.g + (y.g - x.g) * t, x.b + (y.b - x.b) * t,
               x.a + (y.a - x.a) * t};
}

}  // namespace gjkx::render
