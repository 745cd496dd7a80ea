// A panel's 3D scene rendered offscreen by OSMesa, into an image that Cairo lays into the
// figure. Drawn so that the pixels do not depend on the processor the rasteriser runs on:
// one colour per triangle (flat, no interpolation, no dithering), vertices snapped to a
// sixteenth of a sample (the rasteriser's fixed point then rounds them all alike), and
// supersampling averaged here rather than the driver's multisampling.
#include "internal.hpp"

#include <stdexcept>

#ifdef GJKX_HAVE_OSMESA
#define GL_GLEXT_PROTOTYPES
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <GL/glext.h>

#include <cmath>
#include <memory>
#include <type_traits>
#endif

namespace gjkx::render {

#ifndef GJKX_HAVE_OSMESA

bool canDraw3d() { return false; }

cairo_surface_t* detail::renderScene(const std::vector<Batch3d>&, int, int) {
  throw std::runtime_error("this build of gjkx found no OSMesa: it draws no 3D figure");
}

#else

bool canDraw3d() { return true; }

namespace {

// A clip-space vertex in front of the eye, moved to the nearest sixteenth of a sample on
// a w x h viewport (w = 1 after the division); others are left to GL's clipping.
Eigen::Vector4d snapped(const Eigen::Vector4d& c, int w, int h) {
  if (!(c.w() > 0.0)) return c;
  const auto snap = [](double ndc, int size) { return std::round((ndc + 1.0) * 0.5 * size * 16.0) / (16.0 * 0.5 * size) - 1.0; };
  return Eigen::Vector4d(snap(c.x() / c.w(), w), snap(c.y() / c.w(), h), c.z() / c.w(), 1.0);
}

}  // namespace

cairo_surface_t* detail::renderScene(const std::vector<Batch3d>& batches, int width, int height) {
  const int ss = style::supersample, w = width * ss, h = height * ss;
  std::unique_ptr<std::remove_pointer_t<OSMesaContext>, void (*)(OSMesaContext)> context(
      OSMesaCreateContextExt(OSMESA_BGRA, 24, 0, 0, nullptr), OSMesaDestroyContext);
  if (!context) throw std::runtime_error("OSMesa: cannot create a context");
  // BGRA bytes are Cairo's ARGB32 on a little-endian machine, and the blending below
  // leaves them premultiplied, as Cairo wants them.
  std::vector<std::uint32_t> pixels(std::size_t(w) * std::size_t(h));
  if (!OSMesaMakeCurrent(context.get(), pixels.data(), GL_UNSIGNED_BYTE, w, h))
    throw std::runtime_error("OSMesa: cannot render " + std::to_string(w) + " x " + std::to_string(h) + " pixels");
  OSMesaPixelStore(OSMESA_Y_UP, 0);  // the first row is the top one, as in Cairo
  glViewport(0, 0, w, h);
  glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
  glClearDepth(1.0);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LEQUAL);
  glEnable(GL_BLEND);
  glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
  glShadeModel(GL_FLAT);
  glDisable(GL_DITHER);
  for (const Batch3d& b : batches) {
    glDepthMask(b.depthWrite ? GL_TRUE : GL_FALSE);
    if (b.offset > 0.0) glEnable(GL_POLYGON_OFFSET_FILL);
    else glDisable(GL_POLYGON_OFFSET_FILL);
    glPolygonOffset(GLfloat(ss * b.offset), 4.0f);
    glLineWidth(GLfloat(ss * b.lineWidth));
    const std::size_t n = b.lines ? 2 : 3;
    glBegin(b.lines ? GL_LINES : GL_TRIANGLES);
    for (std::size_t i = 0; i < b.vertices.size(); ++i) {
      const auto& c = b.colors[i / n];
      glColor4ub(c[0], c[1], c[2], c[3]);
      const Eigen::Vector4d v = snapped(b.vertices[i], w, h);
      glVertex4d(v.x(), v.y(), v.z(), v.w());
    }
    glEnd();
  }
  glFinish();
  if (glGetError() != GL_NO_ERROR) throw std::runtime_error("OSMesa: OpenGL failed to render a 3D scene");
  OSMesaMakeCurrent(nullptr, nullptr, 0, 0, 0);

  // Each ss x ss block of samples averaged into one pixel, channel by channel.
  cairo_surface_t* out = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, width, height);
  unsigned char* data = cairo_image_surface_get_data(out);
  const int stride = cairo_image_surface_get_stride(out), samples = ss * ss;
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      std::uint32_t sum[4] = {0, 0, 0, 0};
      for (int dy = 0; dy < ss; ++dy)
        for (int dx = 0; dx < ss; ++dx) {
          const std::uint32_t p = pixels[std::size_t(y * ss + dy) * std::size_t(w) + std::size_t(x * ss + dx)];
          for (int c = 0; c < 4; ++c) sum[c] += (p >> (8 * c)) & 0xFFu;
        }
      std::uint32_t pixel = 0;
      for (int c = 0; c < 4; ++c) pixel |= ((sum[c] + samples / 2) / samples) << (8 * c);
      *reinterpret_cast<std::uint32_t*>(data + std::ptrdiff_t(y) * stride + 4 * x) = pixel;
    }
  cairo_surface_mark_dirty(out);
  return out;
}

#endif

}  // namespace gjkx::render
