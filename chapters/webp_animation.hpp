// An animation a browser shows inline: frames of RGBA pixels encoded as an animated WebP by
// libwebp's WebPAnimEncoder (Debian's libwebp-dev; webp/mux.h). The encoder keeps only
// what changed from one frame to the next, so a scene that moves little costs little.
#pragma once

#include <webp/encode.h>
#include <webp/mux.h>

#include <cstdint>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

namespace chapter {

/// An animated WebP being made, frame by frame (see the file comment).
class WebpAnimation {
 public:
  /// An animation of `width` x `height` pixels; `quality` in [0, 100] is the lossy encoder's
  /// (libwebp's -q), or a negative number for lossless frames. Throws std::invalid_argument
  /// naming the field if a size is not positive, std::runtime_error if libwebp refuses.
  WebpAnimation(int width, int height, double quality) : width_(width), height_(height), quality_(quality) {
    if (width <= 0 || width > WEBP_MAX_DIMENSION) throw std::invalid_argument("animation: width must be in [1, 16383], got " + std::to_string(width));
    if (height <= 0 || height > WEBP_MAX_DIMENSION) throw std::invalid_argument("animation: height must be in [1, 16383], got " + std::to_string(height));
    WebPAnimEncoderOptions options;
    if (!WebPAnimEncoderOptionsInit(&options)) throw std::runtime_error("animation: libwebp's version does not match its header");
    options.anim_params.loop_count = 0;  // for ever
    options.anim_params.bgcolor = 0xFFFFFFFF;
    options.allow_mixed = quality >= 0 ? 1 : 0;  // lossy frames may be lossless where that is smaller
    encoder_ = WebPAnimEncoderNew(width, height, &options);
    if (!encoder_) throw std::runtime_error("animation: WebPAnimEncoderNew failed");
  }
  ~WebpAnimation() { WebPAnimEncoderDelete(encoder_); }
  WebpAnimation(const WebpAnimation&) = delete;
  WebpAnimation& operator=(const WebpAnimation&) = delete;

  /// Adds a frame shown for `milliseconds` (> 0): `rgba` holds width x height pixels, row
  /// by row from the top, 4 bytes each (red, green, blue, alpha), as Canvas::rgba() gives.
  void add(const std::vector<std::uint8_t>& rgba, int milliseconds) {
    if (rgba.size() != std::size_t(width_) * std::size_t(height_) * 4)
      throw std::invalid_argument("animation: a frame of " + std::to_string(rgba.size()) + " bytes, not " +
                                  std::to_string(width_) + " x " + std::to_string(height_) + " x 4");
    if (milliseconds <= 0) throw std::invalid_argument("animation: a frame's duration must be positive");
    WebPConfig config;
    if (!WebPConfigInit(&config)) throw std::runtime_error("animation: WebPConfigInit failed");
    config.lossless = quality_ < 0 ? 1 : 0;
    config.quality = float(quality_ < 0 ? 75 : quality_);  // lossless: the effort spent
    config.method = 4;
    WebPPicture picture;
    if (!WebPPictureInit(&picture)) throw std::runtime_error("animation: WebPPictureInit failed");
    picture.use_argb = 1;
    picture.width = width_;
    picture.height = height_;
    if (!WebPPictureImportRGBA(&picture, rgba.data(), width_ * 4)) throw std::runtime_error("animation: out of memory");
    const int added = WebPAnimEncoderAdd(encoder_, &picture, time_, &config);
    WebPPictureFree(&picture);
    if (!added) throw std::runtime_error(std::string("animation: ") + WebPAnimEncoderGetError(encoder_));
    time_ += milliseconds;
    ++frames_;
  }

  /// The frames added so far.
  int frames() const { return frames_; }
  /// The animation's length so far, in milliseconds.
  int milliseconds() const { return time_; }

  /// Writes the animation to `path` (a .webp file); returns its size in bytes. Throws
  /// std::runtime_error naming the file if there is no frame or it cannot be written.
  long save(const std::string& path) {
    if (frames_ == 0) throw std::runtime_error(path + ": an animation needs at least one frame");
    if (!WebPAnimEncoderAdd(encoder_, nullptr, time_, nullptr))  // the end of the last frame
      throw std::runtime_error(std::string("animation: ") + WebPAnimEncoderGetError(encoder_));
    WebPData data;
    WebPDataInit(&data);
    if (!WebPAnimEncoderAssemble(encoder_, &data))
      throw std::runtime_error(std::string("animation: ") + WebPAnimEncoderGetError(encoder_));
    std::FILE* file = std::fopen(path.c_str(), "wb");
    const bool written = file && std::fwrite(data.bytes, 1, data.size, file) == data.size;
    const bool closed = file && std::fclose(file) == 0;
    const long size = long(data.size);
    WebPDataClear(&data);
    if (!written || !closed) throw std::runtime_error(path + ": cannot write the animation");
    return size;
  }

 private:
  WebPAnimEncoder* encoder_ = nullptr;
  int width_ = 0, height_ = 0;
  double quality_ = 80;
  int time_ = 0;  // milliseconds: where the next frame starts
  int frames_ = 0;
};

}  // namespace chapter
