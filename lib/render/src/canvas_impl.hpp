// Internal: the state of a Canvas and its GL drawing helpers (not installed).
#pragma once

#include <gjkx/render/canvas.hpp>

#include <GL/osmesa.h>
#include <GL/gl.h>
#include <GL/glext.h>

#include <vector>

namespace gjkx::render {

namespace detail {

// GL entry points beyond GL 1.1, fetched through OSMesaGetProcAddress.
struct GlFunctions {
  PFNGLGENFRAMEBUFFERSPROC genFramebuffers = nullptr;
  PFNGLDELETEFRAMEBUFFERSPROC deleteFramebuffers = nullptr;
  PFNGLBINDFRAMEBUFFERPROC bindFramebuffer = nullptr;
  PFNGLFRAMEBUFFERRENDERBUFFERPROC framebufferRenderbuffer = nullptr;
  PFNGLCHECKFRAMEBUFFERSTATUSPROC checkFramebufferStatus = nullptr;
  PFNGLGENRENDERBUFFERSPROC genRenderbuffers = nullptr;
  PFNGLDELETERENDERBUFFERSPROC deleteRenderbuffers = nullptr;
  PFNGLBINDRENDERBUFFERPROC bindRenderbuffer = nullptr;
  PFNGLRENDERBUFFERSTORAGEMULTISAMPLEPROC renderbufferStorageMultisample = nullptr;
  PFNGLBLITFRAMEBUFFERPROC blitFramebuffer = nullptr;
  PFNGLBLENDFUNCSEPARATEPROC blendFuncSeparate = nullptr;
};

// A vertex in canvas pixels (x right, y down, fractional) with NDC depth z.
struct ScreenPoint {
  double x = 0.0, y = 0.0, z = 0.0;
};

// A label waiting to be laid over the image.
struct PendingLabel {
  TextMask mask;
  TextStyle style;
  int x = 0, baseline = 0;
  PixelRect clip;
};

}  // namespace detail

struct Canvas::Impl {
  // Size and anti-aliasing.
  int width = 0, height = 0, ss = 1, samples = 1;
  Color background;
  // GL objects.
  OSMesaContext context = nullptr;
  std::vector<unsigned char> osmesaBuffer;  // 1 x 1: rendering goes to FBOs
  detail::GlFunctions gl;
  GLuint drawFbo = 0, drawColor = 0, drawDepth = 0;  // multisampled (or single-sampled fallback)
  GLuint resolveFbo = 0, resolveColor = 0;           // single-sampled, read back
  // Current panel and its mappings.
  PixelRect panel, plot, clip;
  double padding = 0.0, titleBand = 0.0;
  double scale = 1.0;                            // pixels per world unit (2D)
  Eigen::Vector2d worldCenter{0.0, 0.0}, pixelCenter{0.0, 0.0};
  bool has3d = false;
  Camera camera;
  std::vector<detail::PendingLabel> labels;

  ~Impl();
  void create(const CanvasOptions& options);
  void destroyGl();
  void makeCurrent();

  // ---- GL helpers, all in canvas pixels (canvas.cpp) ----
  // Sets scissor to the panel, blending on, depth test as requested.
  void beginPrimitive(bool depthTest, bool depthWrite);
  void emitTriangles(const std::vector<detail::ScreenPoint>& tris, const Color& color);
  void emitTrianglesColored(const std::vector<detail::ScreenPoint>& tris, const std::vector<Color>& colors);

  // ---- geometry (canvas_geometry.cpp) ----
  void strokePath(const std::vector<detail::ScreenPoint>& path, bool closed, const Stroke& stroke, bool depthTest);
  void fillPolygon(const std::vector<detail::ScreenPoint>& poly, const Color& color, bool depthTest);
  void disc(const detail::ScreenPoint& c, double radius, const Color& fill, const Stroke& outline, bool depthTest);
  void arrowPath(detail::ScreenPoint tail, detail::ScreenPoint tip, const Stroke& stroke, double headPx,
                 bool depthTest);
  void queueLabel(double x, double y, const std::string& markup, const TextStyle& style, Anchor anchor,
                  const Eigen::Vector2d& offsetPx);

  // ---- 2D / 3D mappings ----
  detail::ScreenPoint toScreen(const Eigen::Vector2d& world) const;
  void require3d(const char* what) const;
};

}  // namespace gjkx::render
