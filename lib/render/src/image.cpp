// RGBA8 images of the figures, PNG files through Cairo, and their comparison.
#include <gjkx/render/image.hpp>

#include "internal.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <stdexcept>

namespace gjkx::render {

Image::Image(int w, int h, Color fill) : width(w), height(h) {
  if (w <= 0) throw std::invalid_argument("Image: width must be positive, got " + std::to_string(w));
  if (h <= 0) throw std::invalid_argument("Image: height must be positive, got " + std::to_string(h));
  const auto byte = [](double v) { return static_cast<std::uint8_t>(std::lround(std::clamp(v, 0.0, 1.0) * 255.0)); };
  const std::uint8_t px[4] = {byte(fill.r), byte(fill.g), byte(fill.b), byte(fill.a)};
  rgba.resize(std::size_t(w) * std::size_t(h) * 4);
  for (std::size_t i = 0; i < rgba.size(); ++i) rgba[i] = px[i % 4];
}

std::array<std::uint8_t, 4> Image::pixel(int x, int y) const {
  const std::size_t i = (std::size_t(y) * std::size_t(width) + std::size_t(x)) * 4;
  return {rgba[i], rgba[i + 1], rgba[i + 2], rgba[i + 3]};
}

void Image::setPixel(int x, int y, const std::array<std::uint8_t, 4>& value) {
  std::copy(value.begin(), value.end(), rgba.begin() + std::ptrdiff_t((std::size_t(y) * std::size_t(width) + std::size_t(x)) * 4));
}

namespace detail {

// Cairo's ARGB32 is premultiplied and native-endian (one uint32 per pixel): converted both ways.
Image fromSurface(cairo_surface_t* surface) {
  cairo_surface_flush(surface);
  Image out(cairo_image_surface_get_width(surface), cairo_image_surface_get_height(surface));
  const int stride = cairo_image_surface_get_stride(surface);
  const unsigned char* data = cairo_image_surface_get_data(surface);
  const bool opaque = cairo_image_surface_get_format(surface) == CAIRO_FORMAT_RGB24;
  for (int y = 0; y < out.height; ++y)
    for (int x = 0; x < out.width; ++x) {
      const auto p = *reinterpret_cast<const std::uint32_t*>(data + std::ptrdiff_t(y) * stride + 4 * x);
      const unsigned a = opaque ? 255u : p >> 24;
      const auto channel = [&](int shift) {
        const unsigned c = (p >> shift) & 0xFFu;
        return std::uint8_t(a == 0 ? 0 : std::min(255u, (c * 255u + a / 2) / a));
      };
      out.setPixel(x, y, {channel(16), channel(8), channel(0), std::uint8_t(a)});
    }
  return out;
}

}  // namespace detail

void writePng(const Image& image, const std::string& path) {
  cairo_surface_t* s = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, image.width, image.height);
  unsigned char* data = cairo_image_surface_get_data(s);
  const int stride = cairo_image_surface_get_stride(s);
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const auto p = image.pixel(x, y);
      const auto pre = [&](int c) { return std::uint32_t((p[std::size_t(c)] * p[3] + 127) / 255); };
      *reinterpret_cast<std::uint32_t*>(data + std::ptrdiff_t(y) * stride + 4 * x) =
          std::uint32_t(p[3]) << 24 | pre(0) << 16 | pre(1) << 8 | pre(2);
    }
  cairo_surface_mark_dirty(s);
  const cairo_status_t status = cairo_surface_write_to_png(s, path.c_str());
  cairo_surface_destroy(s);
  if (status != CAIRO_STATUS_SUCCESS)
    throw std::runtime_error("cannot write " + path + ": " + cairo_status_to_string(status));
}

Image readPng(const std::string& path) {
  cairo_surface_t* s = cairo_image_surface_create_from_png(path.c_str());
  const cairo_status_t status = cairo_surface_status(s);
  if (status != CAIRO_STATUS_SUCCESS) {
    cairo_surface_destroy(s);
    throw std::runtime_error("cannot read " + path + ": " + cairo_status_to_string(status));
  }
  Image out = detail::fromSurface(s);
  cairo_surface_destroy(s);
  return out;
}

ImageDiff compareImages(const Image& a, const Image& b, int threshold) {
  ImageDiff d;
  d.sameSize = a.width == b.width && a.height == b.height && a.rgba.size() == b.rgba.size();
  if (!d.sameSize) {
    d.differingFraction = 1.0;
    d.maxChannelDifference = 255;
    return d;
  }
  for (std::size_t i = 0; i < a.rgba.size(); i += 4) {
    int worst = 0;
    for (std::size_t c = 0; c < 4; ++c) worst = std::max(worst, std::abs(int(a.rgba[i + c]) - int(b.rgba[i + c])));
    d.maxChannelDifference = std::max(d.maxChannelDifference, worst);
    d.differingPixels += worst > threshold;
  }
  d.differingFraction = a.rgba.empty() ? 0.0 : double(d.differingPixels) / double(a.rgba.size() / 4);
  return d;
}

}  // namespace gjkx::render
