// RGBA8 images, deterministic PNG encoding/decoding through libpng, and the
// pixel comparison used to check regenerated figures of the paper.
#include <gjkx/render/image.hpp>

#include <png.h>

#include <algorithm>
#include <cmath>
#include <csetjmp>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <stdexcept>

namespace gjkx::render {

namespace {

std::uint8_t toByte(double v) {
  return static_cast<std::uint8_t>(std::lround(std::clamp(v, 0.0, 1.0) * 255.0));
}

void checkSize(int width, int height) {
  if (width <= 0) throw std::invalid_argument("Image: width must be positive, got " + std::to_string(width));
  if (height <= 0) throw std::invalid_argument("Image: height must be positive, got " + std::to_string(height));
}

// ---- PNG writing (libpng reports errors with longjmp; no C++ objects are
// created between setjmp and the end of the guarded function).

struct WriteSink {
  std::vector<std::uint8_t>* out;
};

void pngWrite(png_structp png, png_bytep data, png_size_t length) {
  auto* sink = static_cast<WriteSink*>(png_get_io_ptr(png));
  sink->out->insert(sink->out->end(), data, data + length);
}

void pngFlush(png_structp) {}

void pngSilentWarning(png_structp, png_const_charp) {}

bool encodeGuarded(png_structp png, png_infop info, const Image& image, bool opaque,
                   png_bytep* rows, WriteSink* sink) {
  if (setjmp(png_jmpbuf(png))) return false;
  png_set_write_fn(png, sink, pngWrite, pngFlush);
  png_set_IHDR(png, info, static_cast<png_uint_32>(image.width), static_cast<png_uint_32>(image.height),
               8, opaque ? PNG_COLOR_TYPE_RGB : PNG_COLOR_TYPE_RGBA, PNG_INTERLACE_NONE,
               PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  // Fixed settings: the same image always gives the same bytes.
  png_set_compression_level(png, 9);
  png_set_compression_mem_level(png, 8);
  png_set_compression_strategy(png, 0 /* Z_DEFAULT_STRATEGY */);
  png_set_compression_window_bits(png, 15);
  png_set_filter(png, PNG_FILTER_TYPE_BASE, PNG_ALL_FILTERS);
  png_write_info(png, info);
  if (opaque) png_set_filler(png, 0, PNG_FILLER_AFTER);  // drop the alpha byte
  png_write_image(png, rows);
  png_write_end(png, nullptr);
  return true;
}

// ---- PNG reading.

struct ReadSource {
  const std::vector<std::uint8_t>* bytes;
  std::size_t pos;
};

void pngRead(png_structp png, png_bytep data, png_size_t length) {
  auto* src = static_cast<ReadSource*>(png_get_io_ptr(png));
  if (src->pos + length > src->bytes->size()) png_error(png, "unexpected end of data");
  std::memcpy(data, src->bytes->data() + src->pos, length);
  src->pos += length;
}

// Reads the header and sets up transformations to 8-bit RGBA.
bool decodeHeaderGuarded(png_structp png, png_infop info, ReadSource* src, png_uint_32* width,
                         png_uint_32* height) {
  if (setjmp(png_jmpbuf(png))) return false;
  png_set_read_fn(png, src, pngRead);
  png_read_info(png, info);
  *width = png_get_image_width(png, info);
  *height = png_get_image_height(png, info);
  const int colorType = png_get_color_type(png, info);
  const int depth = png_get_bit_depth(png, info);
  if (depth == 16) png_set_strip_16(png);
  if (colorType == PNG_COLOR_TYPE_PALETTE) png_set_palette_to_rgb(png);
  if (colorType == PNG_COLOR_TYPE_GRAY && depth < 8) png_set_expand_gray_1_2_4_to_8(png);
  if (png_get_valid(png, info, PNG_INFO_tRNS)) png_set_tRNS_to_alpha(png);
  if (colorType == PNG_COLOR_TYPE_GRAY || colorType == PNG_COLOR_TYPE_GRAY_ALPHA) png_set_gray_to_rgb(png);
  if (!(colorType & PNG_COLOR_MASK_ALPHA) && !png_get_valid(png, info, PNG_INFO_tRNS))
    png_set_filler(png, 0xFF, PNG_FILLER_AFTER);
  png_set_interlace_handling(png);
  png_read_update_info(png, info);
  return png_get_rowbytes(png, info) == static_cast<png_size_t>(*width) * 4;
}

bool decodeRowsGuarded(png_structp png, png_infop info, png_bytep* rows) {
  if (setjmp(png_jmpbuf(png))) return false;
  png_read_image(png, rows);
  png_read_end(png, info);
  return true;
}

}  // namespace

Image::Image(int w, int h, Color fill) : width(w), height(h) {
  checkSize(w, h);
  const std::array<std::uint8_t, 4> px{toByte(fill.r), toByte(fill.g), toByte(fill.b), toByte(fill.a)};
  rgba.resize(static_cast<std::size_t>(w) * static_cast<std::size_t>(h) * 4);
  for (std::size_t i = 0; i < rgba.size(); i += 4) std::copy(px.begin(), px.end(), rgba.begin() + static_cast<std::ptrdiff_t>(i));
}

std::array<std::uint8_t, 4> Image::pixel(int x, int y) const {
  if (x < 0 || y < 0 || x >= width || y >= height)
    throw std::out_of_range("Image::pixel: (" + std::to_string(x) + ", " + std::to_string(y) + ") outside the image");
  const std::size_t i = (static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x)) * 4;
  return {rgba[i], rgba[i + 1], rgba[i + 2], rgba[i + 3]};
}

void Image::setPixel(int x, int y, const std::array<std::uint8_t, 4>& value) {
  if (x < 0 || y < 0 || x >= width || y >= height)
    throw std::out_of_range("Image::setPixel: (" + std::to_string(x) + ", " + std::to_string(y) + ") outside the image");
  const std::size_t i = (static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x)) * 4;
  std::copy(value.begin(), value.end(), rgba.begin() + static_cast<std::ptrdiff_t>(i));
}

void Image::blend(int x, int y, const Color& color, double coverage) {
  if (x < 0 || y < 0 || x >= width || y >= height) return;
  const double a = std::clamp(color.a * coverage, 0.0, 1.0);
  if (a <= 0.0) return;
  const std::size_t i = (static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x)) * 4;
  const double src[3] = {color.r, color.g, color.b};
  for (int c = 0; c < 3; ++c) {
    const double dst = rgba[i + static_cast<std::size_t>(c)] / 255.0;
    rgba[i + static_cast<std::size_t>(c)] = toByte(dst * (1.0 - a) + src[c] * a);
  }
  const double dstA = rgba[i + 3] / 255.0;
  rgba[i + 3] = toByte(a + dstA * (1.0 - a));
}

std::vector<std::uint8_t> encodePng(const Image& image) {
  if (image.width <= 0 || image.height <= 0 ||
      image.rgba.size() != static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height) * 4)
    throw std::invalid_argument("encodePng: image is empty or its rgba size does not match width * height * 4");
  bool opaque = true;
  for (std::size_t i = 3; i < image.rgba.size(); i += 4) opaque = opaque && image.rgba[i] == 0xFF;
  std::vector<png_bytep> rows(static_cast<std::size_t>(image.height));
  for (int y = 0; y < image.height; ++y)
    rows[static_cast<std::size_t>(y)] = const_cast<png_bytep>(image.rgba.data() + static_cast<std::size_t>(y) * static_cast<std::size_t>(image.width) * 4);
  std::vector<std::uint8_t> out;
  WriteSink sink{&out};
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, pngSilentWarning);
  if (!png) throw std::runtime_error("encodePng: cannot create the libpng write structure");
  png_infop info = png_create_info_struct(png);
  if (!info) {
    png_destroy_write_struct(&png, nullptr);
    throw std::runtime_error("encodePng: cannot create the libpng info structure");
  }
  const bool ok = encodeGuarded(png, info, image, opaque, rows.data(), &sink);
  png_destroy_write_struct(&png, &info);
  if (!ok) throw std::runtime_error("encodePng: libpng failed to encode the image");
  return out;
}

void writePng(const Image& image, const std::string& path) {
  const std::vector<std::uint8_t> bytes = encodePng(image);
  std::unique_ptr<std::FILE, int (*)(std::FILE*)> file(std::fopen(path.c_str(), "wb"), &std::fclose);
  if (!file) throw std::runtime_error("writePng: cannot open '" + path + "' for writing");
  if (std::fwrite(bytes.data(), 1, bytes.size(), file.get()) != bytes.size())
    throw std::runtime_error("writePng: cannot write '" + path + "'");
  if (std::fclose(file.release()) != 0) throw std::runtime_error("writePng: cannot close '" + path + "'");
}

Image decodePng(const std::vector<std::uint8_t>& bytes, const std::string& what) {
  if (bytes.size() < 8 || png_sig_cmp(bytes.data(), 0, 8) != 0)
    throw std::runtime_error("readPng: '" + what + "' is not a PNG file");
  png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, pngSilentWarning);
  if (!png) throw std::runtime_error("readPng: cannot create the libpng read structure");
  png_infop info = png_create_info_struct(png);
  if (!info) {
    png_destroy_read_struct(&png, nullptr, nullptr);
    throw std::runtime_error("readPng: cannot create the libpng info structure");
  }
  ReadSource src{&bytes, 0};
  png_uint_32 width = 0, height = 0;
  if (!decodeHeaderGuarded(png, info, &src, &width, &height) || width == 0 || height == 0 ||
      width > 65536u || height > 65536u) {
    png_destroy_read_struct(&png, &info, nullptr);
    throw std::runtime_error("readPng: '" + what + "' has an unsupported or corrupt header");
  }
  Image image;
  image.width = static_cast<int>(width);
  image.height = static_cast<int>(height);
  image.rgba.assign(static_cast<std::size_t>(width) * height * 4, 0);
  std::vector<png_bytep> rows(height);
  for (png_uint_32 y = 0; y < height; ++y) rows[y] = image.rgba.data() + static_cast<std::size_t>(y) * width * 4;
  const bool ok = decodeRowsGuarded(png, info, rows.data());
  png_destroy_read_struct(&png, &info, nullptr);
  if (!ok) throw std::runtime_error("readPng: '" + what + "' is corrupt");
  return image;
}

Image readPng(const std::string& path) {
  std::unique_ptr<std::FILE, int (*)(std::FILE*)> file(std::fopen(path.c_str(), "rb"), &std::fclose);
  if (!file) throw std::runtime_error("readPng: cannot open '" + path + "' for reading");
  std::vector<std::uint8_t> bytes;
  std::uint8_t buffer[65536];
  std::size_t n = 0;
  while ((n = std::fread(buffer, 1, sizeof buffer, file.get())) > 0) bytes.insert(bytes.end(), buffer, buffer + n);
  if (std::ferror(file.get())) throw std::runtime_error("readPng: cannot read '" + path + "'");
  return decodePng(bytes, path);
}

ImageDiff compareImages(const Image& a, const Image& b, int threshold) {
  ImageDiff diff;
  diff.sameSize = a.width == b.width && a.height == b.height && a.rgba.size() == b.rgba.size();
  if (!diff.sameSize) {
    diff.differingPixels = std::max(a.rgba.size(), b.rgba.size()) / 4;
    diff.differingFraction = 1.0;
    diff.maxChannelDifference = 255;
    return diff;
  }
  for (std::size_t i = 0; i < a.rgba.size(); i += 4) {
    int worst = 0;
    for (std::size_t c = 0; c < 4; ++c) worst = std::max(worst, std::abs(int(a.rgba[i + c]) - int(b.rgba[i + c])));
    diff.maxChannelDifference = std::max(diff.maxChannelDifference, worst);
    if (worst > threshold) ++diff.differingPixels;
  }
  const std::size_t count = a.rgba.size() / 4;
  diff.differingFraction = count ? static_cast<double>(diff.differingPixels) / static_cast<double>(count) : 0.0;
  return diff;
}

}  // namespace gjkx::render
