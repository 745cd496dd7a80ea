/// @file
/// @brief RGBA8 images, deterministic PNG files and image comparison for the
/// paper's figures (written by the chapters, compared by the figure tests).
#pragma once

#include <gjkx/render/palette.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace gjkx::render {

/// A rectangle of pixels, x to the right and y down from the top-left corner
/// of a figure image; panels of the figures are PixelRects.
struct PixelRect {
  int x = 0;       ///< Left column.
  int y = 0;       ///< Top row.
  int width = 0;   ///< Width in pixels.
  int height = 0;  ///< Height in pixels.

  /// True if the pixel (@p px, @p py) lies inside the rectangle.
  /// @param px Column.
  /// @param py Row.
  /// @return Whether the pixel is inside.
  bool contains(int px, int py) const { return px >= x && py >= y && px < x + width && py < y + height; }
};

/// An 8-bit RGBA image, rows from top to bottom, 4 bytes per pixel; the
/// rendered form of every figure of the paper.
struct Image {
  int width = 0;                   ///< Width in pixels.
  int height = 0;                  ///< Height in pixels.
  std::vector<std::uint8_t> rgba;  ///< width * height * 4 bytes, row-major from the top row.

  /// An empty (0 x 0) image.
  Image() = default;

  /// A @p width x @p height image filled with @p fill (a blank figure).
  /// Throws std::invalid_argument naming "width" or "height" if one is not positive.
  /// @param width Width in pixels (> 0).
  /// @param height Height in pixels (> 0).
  /// @param fill Colour of every pixel.
  Image(int width, int height, Color fill = palette::background);

  /// The four channels of pixel (@p x, @p y), y counted from the top row.
  /// @param x Column in [0, width).
  /// @param y Row in [0, height).
  /// @return Red, green, blue and alpha bytes.
  std::array<std::uint8_t, 4> pixel(int x, int y) const;

  /// Overwrites pixel (@p x, @p y) with @p value (RGBA).
  /// @param x Column in [0, width).
  /// @param y Row in [0, height).
  /// @param value The new red, green, blue and alpha bytes.
  void setPixel(int x, int y, const std::array<std::uint8_t, 4>& value);

  /// Blends @p color with the given @p coverage in [0, 1] over pixel (@p x, @p y)
  /// ("source over"); pixels outside the image are ignored. Used to draw the
  /// figures' labels.
  /// @param x Column.
  /// @param y Row.
  /// @param color The colour laid over the pixel (its alpha is honoured).
  /// @param coverage Fraction of the pixel covered, in [0, 1].
  void blend(int x, int y, const Color& color, double coverage);
};

/// Encodes @p image as PNG bytes. Deterministic: fixed compression level and
/// filters, no time or text chunks, so the same figure gives the same bytes.
/// Images whose pixels are all opaque are stored as RGB, others as RGBA.
/// @param image The image to encode (must not be empty).
/// @return The bytes of the PNG file.
std::vector<std::uint8_t> encodePng(const Image& image);

/// Writes @p image to the PNG file @p path (see encodePng()); throws
/// std::runtime_error naming the path if the file cannot be written.
/// Used by every chapter to store the paper's figures.
/// @param image The image to write.
/// @param path The file to create or overwrite.
void writePng(const Image& image, const std::string& path);

/// Decodes PNG bytes of any colour type and depth into an RGBA8 image; throws
/// std::runtime_error mentioning @p what if they are not a valid PNG.
/// @param bytes The PNG file contents.
/// @param what A name for the data (usually its path) used in error messages.
/// @return The decoded image.
Image decodePng(const std::vector<std::uint8_t>& bytes, const std::string& what = "PNG data");

/// Reads the PNG file @p path into an RGBA8 image; throws std::runtime_error
/// naming the path if it cannot be opened or decoded. Used by the tests that
/// compare regenerated figures with the kept ones.
/// @param path The PNG file to read.
/// @return The image in the file.
Image readPng(const std::string& path);

/// The result of compareImages(): how far apart two renderings of a figure are.
struct ImageDiff {
  bool sameSize = false;             ///< True if both images have the same width and height.
  std::size_t differingPixels = 0;   ///< Pixels with some channel differing by more than the threshold.
  double differingFraction = 0.0;    ///< differingPixels divided by the pixel count (1 if sizes differ).
  int maxChannelDifference = 0;      ///< Largest absolute difference of one channel (255 if sizes differ).

  /// True if the images have the same size and at most @p maxFraction of the
  /// pixels differ; the acceptance test of the regenerated figures.
  /// @param maxFraction Tolerated fraction of differing pixels, e.g. 0.001.
  /// @return Whether the images agree within the tolerance.
  bool within(double maxFraction) const {
    return sameSize && differingFraction <= maxFraction;
  }
};

/// Compares two images pixel by pixel: a pixel differs if one of its channels
/// differs by more than @p threshold. Used to check regenerated figures
/// against the kept PNGs with a small tolerance.
/// @param a The first image.
/// @param b The second image.
/// @param threshold Largest per-channel difference still counted as equal.
/// @return Size agreement, differing pixels and the largest channel difference.
ImageDiff compareImages(const Image& a, const Image& b, int threshold = 8);

}  // namespace gjkx::render
