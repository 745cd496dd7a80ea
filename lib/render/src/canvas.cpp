// The Canvas of the paper's figures: OSMesa context, multisampled framebuffer,
// panels, readback with supersampling and label compositing.
#include "canvas_impl.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace gjkx::render {

namespace {

template <typename F>
void fetch(F& fn, const char* name) {
  fn = reinterpret_cast<F>(OSMesaGetProcAddress(name));
  if (!fn) throw std::runtime_error(std::string("Canvas: OpenGL function ") + name + " is not available");
}

GLuint makeRenderbuffer(const detail::GlFunctions& gl, int samples, GLenum format, int w, int h) {
  GLuint rb = 0;
  gl.genRenderbuffers(1, &rb);
  gl.bindRenderbuffer(GL_RENDERBUFFER, rb);
  gl.renderbufferStorageMultisample(GL_RENDERBUFFER, samples > 1 ? samples : 0, format, w, h);
  return rb;
}

}  // namespace

// ---- context and framebuffers ------------------------------------------------

Canvas::Impl::~Impl() { destroyGl(); }

void Canvas::Impl::create(const CanvasOptions& options) {
  context = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, nullptr);
  if (!context) throw std::runtime_error("Canvas: OSMesaCreateContextExt failed");
  osmesaBuffer.assign(4, 0);
  if (!OSMesaMakeCurrent(context, osmesaBuffer.data(), GL_UNSIGNED_BYTE, 1, 1))
    throw std::runtime_error("Canvas: OSMesaMakeCurrent failed");
  fetch(gl.genFramebuffers, "glGenFramebuffers");
  fetch(gl.deleteFramebuffers, "glDeleteFramebuffers");
  fetch(gl.bindFramebuffer, "glBindFramebuffer");
  fetch(gl.framebufferRenderbuffer, "glFramebufferRenderbuffer");
  fetch(gl.checkFramebufferStatus, "glCheckFramebufferStatus");
  fetch(gl.genRenderbuffers, "glGenRenderbuffers");
  fetch(gl.deleteRenderbuffers, "glDeleteRenderbuffers");
  fetch(gl.bindRenderbuffer, "glBindRenderbuffer");
  fetch(gl.renderbufferStorageMultisample, "glRenderbufferStorageMultisample");
  fetch(gl.blitFramebuffer, "glBlitFramebuffer");
  fetch(gl.blendFuncSeparate, "glBlendFuncSeparate");

  GLint maxSamples = 1, maxSize = 0;
  glGetIntegerv(GL_MAX_SAMPLES, &maxSamples);
  glGetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &maxSize);
  ss = options.supersample;
  while (ss > 1 && (width * ss > maxSize || height * ss > maxSize)) --ss;
  if (width * ss > maxSize) throw std::invalid_argument("Canvas: width exceeds the GL limit " + std::to_string(maxSize));
  if (height * ss > maxSize) throw std::invalid_argument("Canvas: height exceeds the GL limit " + std::to_string(maxSize));
  samples = std::clamp(options.samples, 1, std::max(1, static_cast<int>(maxSamples)));

  const auto build = [&]() {
    const int w = width * ss, h = height * ss;
    resolveColor = makeRenderbuffer(gl, 1, GL_RGBA8, w, h);
    gl.genFramebuffers(1, &resolveFbo);
    gl.bindFramebuffer(GL_FRAMEBUFFER, resolveFbo);
    gl.framebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, resolveColor);
    if (gl.checkFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) return false;
    drawColor = makeRenderbuffer(gl, samples, GL_RGBA8, w, h);
    drawDepth = makeRenderbuffer(gl, samples, GL_DEPTH24_STENCIL8, w, h);
    gl.genFramebuffers(1, &drawFbo);
    gl.bindFramebuffer(GL_FRAMEBUFFER, drawFbo);
    gl.framebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, drawColor);
    gl.framebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER, drawDepth);
    return gl.checkFramebufferStatus(GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE && glGetError() == GL_NO_ERROR;
  };
  if (!build()) {
    // No multisampling: fall back to plain supersampling (at least 3 x 3).
    destroyGl();
    context = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, nullptr);
    if (!context || !OSMesaMakeCurrent(context, osmesaBuffer.data(), GL_UNSIGNED_BYTE, 1, 1))
      throw std::runtime_error("Canvas: OSMesa context lost while falling back to supersampling");
    samples = 1;
    ss = std::max(ss, 3);
    while (ss > 1 && (width * ss > maxSize || height * ss > maxSize)) --ss;
    if (!build()) throw std::runtime_error("Canvas: cannot create an OpenGL framebuffer object");
  }
  glViewport(0, 0, width * ss, height * ss);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glDisable(GL_LIGHTING);
  glDisable(GL_CULL_FACE);
  glDepthFunc(GL_LEQUAL);
  glDepthRange(0.0, 1.0);
}

void Canvas::Impl::destroyGl() {
  if (!context) return;
  OSMesaMakeCurrent(context, osmesaBuffer.data(), GL_UNSIGNED_BYTE, 1, 1);
  if (gl.deleteFramebuffers) {
    if (drawFbo) gl.deleteFramebuffers(1, &drawFbo);
    if (resolveFbo) gl.deleteFramebuffers(1, &resolveFbo);
  }
  if (gl.deleteRenderbuffers) {
    const GLuint rbs[3] = {drawColor, drawDepth, resolveColor};
    for (GLuint rb : rbs)
      if (rb) gl.deleteRenderbuffers(1, &rb);
  }
  drawFbo = resolveFbo = drawColor = drawDepth = resolveColor = 0;
  glFinish();
  OSMesaMakeCurrent(nullptr, nullptr, 0, 0, 0);
  OSMesaDestroyContext(context);
  context = nullptr;
}

void Canvas::Impl::makeCurrent() {
  if (!context) throw std::logic_error("Canvas: used after being moved from");
  if (OSMesaGetCurrentContext() != context) {
    if (!OSMesaMakeCurrent(context, osmesaBuffer.data(), GL_UNSIGNED_BYTE, 1, 1))
      throw std::runtime_error("Canvas: OSMesaMakeCurrent failed");
  }
  gl.bindFramebuffer(GL_FRAMEBUFFER, drawFbo);
}

// ---- primitive emission ---------------------------------------------------------

void Canvas::Impl::beginPrimitive(bool depthTest, bool depthWrite) {
  makeCurrent();
  glEnable(GL_SCISSOR_TEST);
  glScissor(clip.x * ss, (height - clip.y - clip.height) * ss, clip.width * ss, clip.height * ss);
  glEnable(GL_BLEND);
  gl.blendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
  if (depthTest) glEnable(GL_DEPTH_TEST);
  else glDisable(GL_DEPTH_TEST);
  glDepthMask(depthWrite ? GL_TRUE : GL_FALSE);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glDisable(GL_STENCIL_TEST);
  glDisable(GL_POLYGON_OFFSET_FILL);
}

void Canvas::Impl::emitTriangles(const std::vector<detail::ScreenPoint>& tris, const Color& color) {
  glColor4d(color.r, color.g, color.b, color.a);
  glBegin(GL_TRIANGLES);
  for (const detail::ScreenPoint& p : tris)
    glVertex3d(2.0 * p.x / width - 1.0, 1.0 - 2.0 * p.y / height, std::clamp(p.z, -1.0, 1.0));
  glEnd();
}

void Canvas::Impl::emitTrianglesColored(const std::vector<detail::ScreenPoint>& tris,
                                        const std::vector<Color>& colors) {
  glBegin(GL_TRIANGLES);
  for (std::size_t i = 0; i < tris.size(); ++i) {
    const Color& c = colors[i / 3];
    glColor4d(c.r, c.g, c.b, c.a);
    const detail::ScreenPoint& p = tris[i];
    glVertex3d(2.0 * p.x / width - 1.0, 1.0 - 2.0 * p.y / height, std::clamp(p.z, -1.0, 1.0));
  }
  glEnd();
}

// ---- Canvas: life cycle -------------------------------------------------------------

Canvas::Canvas(int width, int height, const CanvasOptions& options) : impl_(std::make_unique<Impl>()) {
  if (width <= 0) throw std::invalid_argument("Canvas: width must be positive, got " + std::to_string(width));
  if (height <= 0) throw std::invalid_argument("Canvas: height must be positive, got " + std::to_string(height));
  if (options.samples < 1) throw std::invalid_argument("Canvas: samples must be at least 1");
  if (options.supersample < 1 || options.supersample > 4)
    throw std::invalid_argument("Canvas: supersample must be in [1, 4]");
  impl_->width = width;
  impl_->height = height;
  impl_->background = options.background;
  impl_->create(options);
  setPanel(PixelRect{0, 0, width, height}, 0.0, 0.0);
  clear(options.background);
}

Canvas::~Canvas() = default;
Canvas::Canvas(Canvas&& other) noexcept = default;
Canvas& Canvas::operator=(Canvas&& other) noexcept = default;

int Canvas::width() const { return impl_->width; }
int Canvas::height() const { return impl_->height; }
int Canvas::samples() const { return impl_->samples; }
int Canvas::supersample() const { return impl_->ss; }

void Canvas::clear(const Color& color) {
  impl_->makeCurrent();
  glDisable(GL_SCISSOR_TEST);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glDepthMask(GL_TRUE);
  glStencilMask(0xFF);
  glClearColor(static_cast<GLfloat>(color.r), static_cast<GLfloat>(color.g), static_cast<GLfloat>(color.b),
               static_cast<GLfloat>(color.a));
  glClearDepth(1.0);
  glClearStencil(0);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  impl_->labels.clear();
}

// ---- panels ------------------------------------------------------------------------

void Canvas::setPanel(const PixelRect& rect, double padding, double titleBand) {
  Impl& s = *impl_;
  if (rect.width <= 0) throw std::invalid_argument("Canvas::setPanel: width must be positive");
  if (rect.height <= 0) throw std::invalid_argument("Canvas::setPanel: height must be positive");
  if (rect.x < 0 || rect.x + rect.width > s.width) throw std::invalid_argument("Canvas::setPanel: x range leaves the canvas");
  if (rect.y < 0 || rect.y + rect.height > s.height) throw std::invalid_argument("Canvas::setPanel: y range leaves the canvas");
  if (!(padding >= 0.0)) throw std::invalid_argument("Canvas::setPanel: padding must not be negative");
  if (!(titleBand >= 0.0)) throw std::invalid_argument("Canvas::setPanel: titleBand must not be negative");
  s.panel = rect;
  s.clip = rect;
  s.padding = padding;
  s.titleBand = titleBand;
  const int pad = static_cast<int>(std::lround(padding)), band = static_cast<int>(std::lround(titleBand));
  s.plot = PixelRect{rect.x + pad, rect.y + pad + band, std::max(1, rect.width - 2 * pad),
                     std::max(1, rect.height - 2 * pad - band)};
  s.scale = 1.0;
  s.pixelCenter = Eigen::Vector2d(s.plot.x + 0.5 * s.plot.width, s.plot.y + 0.5 * s.plot.height);
  s.worldCenter = Eigen::Vector2d(0.5 * s.plot.width, 0.5 * s.plot.height);
  s.has3d = false;
  // A fresh depth and stencil buffer for the panel.
  s.makeCurrent();
  glEnable(GL_SCISSOR_TEST);
  glScissor(rect.x * s.ss, (s.height - rect.y - rect.height) * s.ss, rect.width * s.ss, rect.height * s.ss);
  glDepthMask(GL_TRUE);
  glStencilMask(0xFF);
  glClearDepth(1.0);
  glClearStencil(0);
  glClear(GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
}

PixelRect Canvas::panel() const { return impl_->panel; }

void Canvas::setClip(const PixelRect& rect) {
  const PixelRect& p = impl_->panel;
  const int x0 = std::max(rect.x, p.x), y0 = std::max(rect.y, p.y);
  const int x1 = std::min(rect.x + rect.width, p.x + p.width), y1 = std::min(rect.y + rect.height, p.y + p.height);
  if (x1 <= x0 || y1 <= y0) throw std::invalid_argument("Canvas::setClip: rect does not overlap the panel");
  impl_->clip = PixelRect{x0, y0, x1 - x0, y1 - y0};
}

PixelRect Canvas::clip() const { return impl_->clip; }
PixelRect Canvas::plotArea() const { return impl_->plot; }
double Canvas::plotAspect() const { return double(impl_->plot.width) / double(impl_->plot.height); }

void Canvas::setWorldWindow(double xmin, double xmax, double ymin, double ymax) {
  if (!(xmax > xmin)) throw std::invalid_argument("Canvas::setWorldWindow: xmax must exceed xmin");
  if (!(ymax > ymin)) throw std::invalid_argument("Canvas::setWorldWindow: ymax must exceed ymin");
  Impl& s = *impl_;
  s.scale = std::min(s.plot.width / (xmax - xmin), s.plot.height / (ymax - ymin));
  s.worldCenter = Eigen::Vector2d(0.5 * (xmin + xmax), 0.5 * (ymin + ymax));
}

double Canvas::pixelsPerUnit() const { return impl_->scale; }

Eigen::Vector2d Canvas::toPixel(const Eigen::Vector2d& world) const {
  const detail::ScreenPoint p = impl_->toScreen(world);
  return Eigen::Vector2d(p.x, p.y);
}

detail::ScreenPoint Canvas::Impl::toScreen(const Eigen::Vector2d& world) const {
  return detail::ScreenPoint{pixelCenter.x() + (world.x() - worldCenter.x()) * scale,
                             pixelCenter.y() - (world.y() - worldCenter.y()) * scale, 0.0};
}

void Canvas::title(const std::string& markup, const TextStyle& style) {
  const Impl& s = *impl_;
  const TextMask mask = rasterizeText(markup, style.font, style.size);
  // The band between the panel's top edge and its plot area; baselines depend
  // on the font size only, so the titles of a row of panels line up.
  const double bandTop = s.panel.y + (s.titleBand > 0.0 ? 0.5 * s.padding : 0.0);
  const double band = s.titleBand > 0.0 ? s.plot.y - bandTop : 1.4 * style.size;
  const double baseline = bandTop + 0.5 * band + 0.36 * style.size;
  const double x = s.panel.x + 0.5 * s.panel.width - 0.5 * (mask.extent.left + mask.extent.right);
  impl_->labels.push_back(detail::PendingLabel{mask, style, static_cast<int>(std::lround(x)),
                                               static_cast<int>(std::lround(baseline)), s.panel});
}

// ---- labels and output ------------------------------------------------------------

void Canvas::Impl::queueLabel(double x, double y, const std::string& markup, const TextStyle& style, Anchor anchor,
                              const Eigen::Vector2d& offsetPx) {
  TextMask mask = rasterizeText(markup, style.font, style.size);
  const TextExtent& e = mask.extent;
  const double gap = style::labelGap;
  double pen = x - 0.5 * (e.left + e.right);
  double base = y + 0.5 * (e.ascent - e.descent);
  switch (anchor) {
    case Anchor::Right: case Anchor::AboveRight: case Anchor::BelowRight: pen = x + gap - e.left; break;
    case Anchor::Left: case Anchor::AboveLeft: case Anchor::BelowLeft: pen = x - gap - e.right; break;
    default: break;
  }
  switch (anchor) {
    case Anchor::Above: case Anchor::AboveLeft: case Anchor::AboveRight: base = y - gap - e.descent; break;
    case Anchor::Below: case Anchor::BelowLeft: case Anchor::BelowRight: base = y + gap + e.ascent; break;
    default: break;
  }
  pen += offsetPx.x();
  base -= offsetPx.y();
  labels.push_back(detail::PendingLabel{std::move(mask), style, static_cast<int>(std::lround(pen)),
                                        static_cast<int>(std::lround(base)), panel});
}

void Canvas::textAtPixel(double x, double y, const std::string& markup, const TextStyle& style, Anchor anchor) {
  impl_->queueLabel(x, y, markup, style, anchor, Eigen::Vector2d::Zero());
}

void Canvas::text(const Eigen::Vector2d& p, const std::string& markup, const TextStyle& style, Anchor anchor,
                  const Eigen::Vector2d& offsetPx) {
  const detail::ScreenPoint q = impl_->toScreen(p);
  impl_->queueLabel(q.x, q.y, markup, style, anchor, offsetPx);
}

Image Canvas::image() {
  Impl& s = *impl_;
  s.makeCurrent();
  const int w = s.width * s.ss, h = s.height * s.ss;
  glDisable(GL_SCISSOR_TEST);  // the scissor would clip the blit
  s.gl.bindFramebuffer(GL_READ_FRAMEBUFFER, s.drawFbo);
  s.gl.bindFramebuffer(GL_DRAW_FRAMEBUFFER, s.resolveFbo);
  s.gl.blitFramebuffer(0, 0, w, h, 0, 0, w, h, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  s.gl.bindFramebuffer(GL_READ_FRAMEBUFFER, s.resolveFbo);
  std::vector<unsigned char> pixels(static_cast<std::size_t>(w) * static_cast<std::size_t>(h) * 4);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, w, h, GL_RGBA, GL_UNSIGNED_BYTE, pixels.data());
  s.gl.bindFramebuffer(GL_FRAMEBUFFER, s.drawFbo);
  if (const GLenum err = glGetError(); err != GL_NO_ERROR)
    throw std::runtime_error("Canvas::image: OpenGL error " + std::to_string(err) + " while reading back");

  // Average ss x ss blocks; GL rows are bottom-up, image rows top-down.
  Image out(s.width, s.height, s.background);
  const int n = s.ss * s.ss;
  for (int y = 0; y < s.height; ++y)
    for (int x = 0; x < s.width; ++x) {
      int sum[4] = {0, 0, 0, 0};
      for (int dy = 0; dy < s.ss; ++dy) {
        const std::size_t row = static_cast<std::size_t>(h - 1 - (y * s.ss + dy));
        for (int dx = 0; dx < s.ss; ++dx) {
          const std::size_t i = (row * static_cast<std::size_t>(w) + static_cast<std::size_t>(x * s.ss + dx)) * 4;
          for (int c = 0; c < 4; ++c) sum[c] += pixels[i + static_cast<std::size_t>(c)];
        }
      }
      const std::size_t o = (static_cast<std::size_t>(y) * static_cast<std::size_t>(s.width) + static_cast<std::size_t>(x)) * 4;
      for (int c = 0; c < 4; ++c) out.rgba[o + static_cast<std::size_t>(c)] = static_cast<std::uint8_t>((sum[c] + n / 2) / n);
    }
  for (const detail::PendingLabel& label : s.labels)
    drawTextMask(out, label.x, label.baseline, label.mask, label.style, label.clip);
  return out;
}

void Canvas::savePng(const std::string& path) { writePng(image(), path); }

}  // namespace gjkx::render
