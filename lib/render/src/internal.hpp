// Internal: what the renderer's files share (not installed).
#pragma once

#include <gjkx/render/canvas.hpp>

#include <cairo.h>

#include <array>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace gjkx::render::detail {

// A Cairo image surface (ARGB32 or RGB24) as straight-alpha RGBA8.
Image fromSurface(cairo_surface_t* surface);

// Draws `markup` with its pen origin at (x, baseline), the halo first if the style has one.
void showText(cairo_t* cr, double x, double baseline, const std::string& markup, const TextStyle& style);

// One draw call of a panel's 3D scene, in clip coordinates: triangles (three vertices
// each) or line segments (two each), one colour (RGBA bytes) per triangle or segment.
struct Batch3d {
  bool lines = false;
  std::vector<Eigen::Vector4d> vertices;
  std::vector<std::array<std::uint8_t, 4>> colors;
  double lineWidth = 1.0;    // pixels
  bool depthWrite = true;    // opaque things hide what comes after them
  double offset = 0.0;       // pushes triangles back (pixels) so that edges on them stay visible
};

// Renders the batches in order with OSMesa into a premultiplied ARGB32 surface of
// width x height pixels (supersampled by style::supersample and averaged); the caller
// destroys it. Throws std::runtime_error in a build without OSMesa.
cairo_surface_t* renderScene(const std::vector<Batch3d>& batches, int width, int height);

// A label waiting to be laid over the figure: its pen origin in whole pixels.
struct Label {
  double x = 0.0, baseline = 0.0;
  std::string markup;
  TextStyle style;
  PixelRect clip;
};

// Cairo's drawing of the figures' strokes, fills, point markers and arrows, in canvas pixels.
void setColor(cairo_t* cr, const Color& c);
void strokePath(cairo_t* cr, const std::vector<Eigen::Vector2d>& points, bool closed, const Stroke& stroke);
void fillPath(cairo_t* cr, const std::vector<Eigen::Vector2d>& points, const Color& color);
void disc(cairo_t* cr, const Eigen::Vector2d& c, double radius, const Color& fill, const Stroke& outline);
void arrowPath(cairo_t* cr, const Eigen::Vector2d& tail, const Eigen::Vector2d& tip, const Stroke& stroke, double headPx);

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
  std::vector<detail::Batch3d> scene;                    // the panel's 3D drawing, not yet rendered
  std::vector<std::function<void(cairo_t*)>> overlays;  // what Cairo draws over that scene
  std::vector<detail::Label> labels;

  ~Impl();
  void reset(const Color& color);  // a fresh recording surface of `color`
  void flush3d();                  // renders the pending scene and lays it, then its overlays, into the plot area
  void render(cairo_t* target);    // the finished figure: the recording, then the labels
  void queueLabel(double x, double y, const std::string& markup, const TextStyle& style, Anchor anchor,
                  const Eigen::Vector2d& offsetPx);
  Eigen::Vector2d toScreen(const Eigen::Vector2d& world) const;
  void require3d(const char* what) const;
  // 2D drawing in canvas pixels: after the pending 3D scene, clipped.
  template <typename Draw>
  void draw(const Draw& f) {
    flush3d();
    cairo_save(cr);
    cairo_rectangle(cr, clip.x, clip.y, clip.width, clip.height);
    cairo_clip(cr);
    f(cr);
    cairo_restore(cr);
  }
};

}  // namespace gjkx::render
