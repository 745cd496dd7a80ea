/// @file
/// @brief RGBA8 images, PNG files (through Cairo) and the comparison that decides whether a
/// regenerated figure of the paper is the kept one.
#pragma once

#include <gjkx/render/palette.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace gjkx::render {

/// A rectangle of pixels, x to the right and y down from the top-left corner of a
/// figure; the panels of the figures are PixelRects.
struct PixelRect {
  int x = 0;       ///< Left column.
  int y = 0;       ///< Top row.
  int width = 0;   ///< Width in pixels.
  int height = 0;  ///< Height in pixels.

  /// True if the pixel (@p px, @p py) lies inside the rectangle.
  bool contains(int px, int py) const { return px >= x && py >= y && px < x + width && py < y + height; }
};

/// An 8-bit RGBA image (straight alpha), rows from the top, 4 bytes per pixel: a
/// rendered figure, or a kept PNG read back.
struct Image {
  int width = 0;                   ///< Width in pixels.
  int height = 0;                  ///< Height in pixels.
  std::vector<std::uint8_t> rgba;  ///< width * height * 4 bytes, row-major from the top row.

  /// An empty (0 x 0) image.
  Image() = default;
  /// A @p width x @p height image filled with @p fill; throws std::invalid_argument
  /// naming "width" or "height" if one is not positive.
  Image(int width, int height, Color fill = palette::background);
  /// Red, green, blue and alpha of pixel (@p x, @p y), y counted from the top row.
  std::array<std::uint8_t, 4> pixel(int x, int y) const;
  /// Overwrites pixel (@p x, @p y) with @p value (RGBA).
  void setPixel(int x, int y, const std::array<std::uint8_t, 4>& value);
};

/// Writes @p image as a PNG file (Cairo's writer: no time stamp, so the same image
/// gives the same bytes); throws std::runtime_error naming @p path if it cannot.
void writePng(const Image& image, const std::string& path);

/// Reads the PNG file @p path; throws std::runtime_error naming the path if it cannot
/// be opened or is no PNG.
Image readPng(const std::string& path);

/// How far apart two renderings of a figure are (see compareImages()).
struct ImageDiff {
  bool sameSize = false;            ///< Whether both images have the same width and height.
  std::size_t differingPixels = 0;  ///< Pixels with a channel differing by more than the threshold.
  double differingFraction = 0.0;   ///< differingPixels over the pixel count (1 if the sizes differ).
  int maxChannelDifference = 0;     ///< Largest difference of one channel (255 if the sizes differ).

  /// Whether the images have the same size and at most @p maxFraction of the pixels differ.
  bool within(double maxFraction) const { return sameSize && differingFraction <= maxFraction; }
};

/// Compares two images pixel by pixel: a pixel differs if one of its channels differs
/// by more than @p threshold.
ImageDiff compareImages(const Image& a, const Image& b, int threshold = 8);

/// The tolerance of a kept figure: a regenerated figure is the kept one if at most this
/// fraction of its pixels differ (compareImages()' threshold). The figure tests hold the
/// chapters to it, and the `figures` target rewrites a kept PNG only beyond it, so that
/// another machine's last bit of antialiasing leaves figures/ untouched.
inline constexpr double keptFigureTolerance = 0.005;

}  // namespace gjkx::render
