// Internal: what the renderer's files share (not installed).
#pragma once

#include <gjkx/render/canvas.hpp>

#include <cairo.h>

#include <array>
#include <cstdint>
#include <functional>
#include <stdexcept>

namespace gjkx::render::detail {

inline void setColor(cairo_t* cr, const Color& c) { cairo_set_source_rgba(cr, c.r, c.g, c.b, c.a); }
// Draws `markup` with its pen origin at (x, baseline), its halo first if it has one (text.cpp).
void showText(cairo_t* cr, double x, double baseline, const std::string& markup, const TextStyle& style);
// Point markers and arrows in canvas pixels (canvas.cpp).
void disc(cairo_t* cr, const Eigen::Vector2d& c, double radius, const Color& fill, const Stroke& outline);
void arrowPath(cairo_t* cr, const Eigen::Vector2d& tail, const Eigen::Vector2d& tip, const Stroke& stroke, double headPx);

// One draw call of a panel's 3D scene in clip coordinates: triangles (three vertices each)
// or line segments (two each), one colour (RGBA bytes) per triangle or segment.
struct Batch3d {
  bool lines = false;
  std::vector<Eigen::Vector4d> vertices;
  std::vector<std::array<std::uint8_t, 4>> colors;
  double lineWidth = 1.0;  // pixels
  bool depthWrite = true;  // opaque things hide what comes after them
  double offset = 0.0;     // pushes triangles back (pixels' worth of depth) so that edges on them show
};

}  // namespace gjkx::render::detail

namespace gjkx::render {

struct Canvas::Impl {
  int width = 0, height = 0;
  Color background;
  cairo_surface_t* record = nullptr;  // everything drawn so far, as Cairo vectors
  cairo_t* cr = nullptr;
  PixelRect panel, plot, clip;
  double padding = 0.0, titleBand = 0.0, scale = 1.0;  // scale: pixels per world unit (2D)
  Eigen::Vector2d worldCenter{0.0, 0.0}, pixelCenter{0.0, 0.0};
  bool has3d = false;
  Camera camera;
  std::vector<detail::Batch3d> scene;  // the panel's 3D drawing, not yet rendered (scene.cpp)
  // Drawn over everything when the figure is written, each clipped to its panel: points and
  // arrows in space (over their scene), then every label.
  std::vector<std::function<void(cairo_t*)>> overlays, labels;

  ~Impl() {
    cairo_destroy(cr);
    cairo_surface_destroy(record);
  }
  void flush3d();  // renders the pending scene into the clip rectangle (scene.cpp)
  void finish(cairo_surface_t* surface);  // the finished figure: the recording, then overlays and labels
  void queueLabel(const Eigen::Vector2d& at, const std::string& markup, const TextStyle& style, Anchor anchor,
                  const Eigen::Vector2d& offsetPx);
  void require3d(const char* what) const {  // every 3D call needs the panel's camera
    if (!has3d) throw std::logic_error(std::string("Canvas::") + what + ": call setCamera() for the panel first");
  }
  Eigen::Vector2d toScreen(const Eigen::Vector2d& world) const {
    return pixelCenter + scale * Eigen::Vector2d(world.x() - worldCenter.x(), worldCenter.y() - world.y());
  }
  template <typename Draw>
  void draw(const Draw& f) {  // 2D drawing in canvas pixels: over the pending 3D scene, clipped
    flush3d();
    cairo_save(cr);
    cairo_rectangle(cr, clip.x, clip.y, clip.width, clip.height);
    cairo_clip(cr);
    f(cr);
    cairo_restore(cr);
  }
  template <typename Draw>
  void onTop(std::vector<std::function<void(cairo_t*)>>& list, const Draw& f) {  // kept for the end, clipped to the panel
    list.push_back([f, r = panel](cairo_t* target) {
      cairo_save(target);
      cairo_rectangle(target, r.x, r.y, r.width, r.height);
      cairo_clip(target);
      f(target);
      cairo_restore(target);
    });
  }
};

}  // namespace gjkx::render
