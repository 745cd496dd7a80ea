// The Canvas of the paper's figures: panels and their mappings, 2D drawing by Cairo into
// a recording surface, labels by Pango over it, and the figure written as PNG, SVG or PDF.
// The 3D calls (canvas_3d.cpp) hand a panel's scene to OSMesa (scene_gl.cpp).
#include "internal.hpp"

#include <cairo-pdf.h>
#include <cairo-svg.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <stdexcept>

namespace gjkx::render {

namespace detail {

void setColor(cairo_t* cr, const Color& c) { cairo_set_source_rgba(cr, c.r, c.g, c.b, c.a); }

void strokePath(cairo_t* cr, const std::vector<Eigen::Vector2d>& points, bool closed, const Stroke& stroke) {
  if (stroke.color.invisible() || !(stroke.width > 0.0) || points.empty()) return;
  cairo_new_path(cr);
  for (const auto& p : points) cairo_line_to(cr, p.x(), p.y());
  if (points.size() == 1) cairo_line_to(cr, points[0].x(), points[0].y());  // a dot
  if (closed && points.size() > 2) cairo_close_path(cr);
  cairo_set_line_width(cr, stroke.width);
  cairo_set_line_cap(cr, CAIRO_LINE_CAP_ROUND);
  cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
  if (stroke.dash.solid()) {
    cairo_set_dash(cr, nullptr, 0, 0.0);
  } else {  // round caps lengthen every dash by the width: the pattern's dash includes them
    const double on = std::max(0.0, stroke.dash.on - stroke.width);
    const double pattern[2] = {on, stroke.dash.off + stroke.dash.on - on};
    cairo_set_dash(cr, pattern, 2, 0.0);
  }
  setColor(cr, stroke.color);
  cairo_stroke(cr);
}

void fillPath(cairo_t* cr, const std::vector<Eigen::Vector2d>& points, const Color& color) {
  if (color.invisible() || points.size() < 3) return;
  cairo_new_path(cr);
  for (const auto& p : points) cairo_line_to(cr, p.x(), p.y());
  cairo_close_path(cr);
  cairo_set_fill_rule(cr, CAIRO_FILL_RULE_EVEN_ODD);
  setColor(cr, color);
  cairo_fill(cr);
}

void disc(cairo_t* cr, const Eigen::Vector2d& c, double radius, const Color& fill, const Stroke& outline) {
  if (!(radius > 0.0)) return;
  const bool ring = !outline.color.invisible() && outline.width > 0.0;
  const double inner = ring ? radius - 0.5 * outline.width : radius;  // the ring's middle
  cairo_new_path(cr);
  cairo_arc(cr, c.x(), c.y(), std::max(0.0, inner), 0.0, 2.0 * M_PI);
  if (!fill.invisible()) {
    setColor(cr, fill);
    cairo_fill_preserve(cr);
  }
  if (ring) {
    cairo_set_line_width(cr, outline.width);
    cairo_set_dash(cr, nullptr, 0, 0.0);
    setColor(cr, outline.color);
    cairo_stroke_preserve(cr);
  }
  cairo_new_path(cr);
}

void arrowPath(cairo_t* cr, const Eigen::Vector2d& tail, const Eigen::Vector2d& tip, const Stroke& stroke,
               double headPx) {
  const double length = (tip - tail).norm();
  if (length < 1e-9 || stroke.color.invisible()) return;
  const Eigen::Vector2d u = (tip - tail) / length, normal(-u.y(), u.x());
  const double head = std::clamp(headPx, 0.0, length), halfWidth = std::max(0.36 * head, 0.9 * stroke.width);
  // The shaft ends inside the head, so that its round cap does not show at the tip.
  if (length - 0.6 * head > 0.0) strokePath(cr, {tail, tip - 0.6 * head * u}, false, Stroke{stroke.color, stroke.width, {}});
  if (head <= 0.0) return;
  const Eigen::Vector2d base = tip - head * u, notch = tip - 0.78 * head * u;
  fillPath(cr, {tip, base + halfWidth * normal, notch, base - halfWidth * normal}, stroke.color);
}

}  // namespace detail

using detail::Label;

// ---- the canvas's surfaces --------------------------------------------------------------

Canvas::Impl::~Impl() {
  if (cr) cairo_destroy(cr);
  if (record) cairo_surface_destroy(record);
}

void Canvas::Impl::reset(const Color& color) {
  if (cr) cairo_destroy(cr);
  if (record) cairo_surface_destroy(record);
  const cairo_rectangle_t extents{0.0, 0.0, double(width), double(height)};
  record = cairo_recording_surface_create(CAIRO_CONTENT_COLOR_ALPHA, &extents);
  cr = cairo_create(record);
  detail::setColor(cr, color);
  cairo_paint(cr);
  background = color;
  labels.clear();
  scene.clear();
  overlays.clear();
}

void Canvas::Impl::flush3d() {
  if (scene.empty() && overlays.empty()) return;
  cairo_save(cr);
  cairo_rectangle(cr, clip.x, clip.y, clip.width, clip.height);
  cairo_clip(cr);
  if (!scene.empty()) {
    // The camera maps NDC [-1, 1] to the plot area; the scene is drawn over the whole clip
    // rectangle (a floor may run to the panel's edges), so clip space is mapped to it.
    Eigen::Matrix4d toRect = Eigen::Matrix4d::Identity();
    toRect(0, 0) = double(plot.width) / clip.width;
    toRect(0, 3) = double(plot.width + 2 * (plot.x - clip.x)) / clip.width - 1.0;
    toRect(1, 1) = double(plot.height) / clip.height;
    toRect(1, 3) = 1.0 - double(plot.height + 2 * (plot.y - clip.y)) / clip.height;
    for (auto& batch : scene)
      for (auto& v : batch.vertices) v = Eigen::Vector4d(toRect(0, 0) * v.x() + toRect(0, 3) * v.w(), toRect(1, 1) * v.y() + toRect(1, 3) * v.w(), v.z(), v.w());
    cairo_surface_t* image = detail::renderScene(scene, clip.width, clip.height);
    cairo_set_source_surface(cr, image, clip.x, clip.y);
    cairo_paint(cr);
    cairo_surface_destroy(image);
  }
  for (const auto& draw : overlays) draw(cr);
  cairo_restore(cr);
  scene.clear();
  overlays.clear();
}

void Canvas::Impl::render(cairo_t* target) {
  flush3d();
  cairo_set_source_surface(target, record, 0.0, 0.0);
  cairo_paint(target);
  for (const Label& label : labels) {
    cairo_save(target);
    cairo_rectangle(target, label.clip.x, label.clip.y, label.clip.width, label.clip.height);
    cairo_clip(target);
    detail::showText(target, label.x, label.baseline, label.markup, label.style);
    cairo_restore(target);
  }
}

// ---- Canvas: life cycle -----------------------------------------------------------------

Canvas::Canvas(int width, int height, const Color& background) : impl_(std::make_unique<Impl>()) {
  if (width <= 0) throw std::invalid_argument("Canvas: width must be positive, got " + std::to_string(width));
  if (height <= 0) throw std::invalid_argument("Canvas: height must be positive, got " + std::to_string(height));
  impl_->width = width;
  impl_->height = height;
  impl_->reset(background);
  setPanel(PixelRect{0, 0, width, height}, 0.0, 0.0);
}

Canvas::~Canvas() = default;
Canvas::Canvas(Canvas&& other) noexcept = default;
Canvas& Canvas::operator=(Canvas&& other) noexcept = default;

int Canvas::width() const { return impl_->width; }
int Canvas::height() const { return impl_->height; }
void Canvas::clear(const Color& color) { impl_->reset(color); }

// ---- panels -----------------------------------------------------------------------------

void Canvas::setPanel(const PixelRect& rect, double padding, double titleBand) {
  Impl& s = *impl_;
  if (rect.width <= 0) throw std::invalid_argument("Canvas::setPanel: width must be positive");
  if (rect.height <= 0) throw std::invalid_argument("Canvas::setPanel: height must be positive");
  if (rect.x < 0 || rect.x + rect.width > s.width) throw std::invalid_argument("Canvas::setPanel: x range leaves the canvas");
  if (rect.y < 0 || rect.y + rect.height > s.height) throw std::invalid_argument("Canvas::setPanel: y range leaves the canvas");
  if (!(padding >= 0.0)) throw std::invalid_argument("Canvas::setPanel: padding must not be negative");
  if (!(titleBand >= 0.0)) throw std::invalid_argument("Canvas::setPanel: titleBand must not be negative");
  s.flush3d();
  s.panel = s.clip = rect;
  s.padding = padding;
  s.titleBand = titleBand;
  const int pad = int(std::lround(padding)), band = int(std::lround(titleBand));
  s.plot = PixelRect{rect.x + pad, rect.y + pad + band, std::max(1, rect.width - 2 * pad),
                     std::max(1, rect.height - 2 * pad - band)};
  s.scale = 1.0;
  s.pixelCenter = Eigen::Vector2d(s.plot.x + 0.5 * s.plot.width, s.plot.y + 0.5 * s.plot.height);
  s.worldCenter = Eigen::Vector2d(0.5 * s.plot.width, 0.5 * s.plot.height);
  s.has3d = false;
}

PixelRect Canvas::panel() const { return impl_->panel; }
PixelRect Canvas::plotArea() const { return impl_->plot; }
double Canvas::plotAspect() const { return double(impl_->plot.width) / double(impl_->plot.height); }
PixelRect Canvas::clip() const { return impl_->clip; }

void Canvas::setClip(const PixelRect& rect) {
  const PixelRect& p = impl_->panel;
  const int x0 = std::max(rect.x, p.x), y0 = std::max(rect.y, p.y);
  const int x1 = std::min(rect.x + rect.width, p.x + p.width), y1 = std::min(rect.y + rect.height, p.y + p.height);
  if (x1 <= x0 || y1 <= y0) throw std::invalid_argument("Canvas::setClip: rect does not overlap the panel");
  impl_->flush3d();
  impl_->clip = PixelRect{x0, y0, x1 - x0, y1 - y0};
}

void Canvas::setWorldWindow(double xmin, double xmax, double ymin, double ymax) {
  if (!(xmax > xmin)) throw std::invalid_argument("Canvas::setWorldWindow: xmax must exceed xmin");
  if (!(ymax > ymin)) throw std::invalid_argument("Canvas::setWorldWindow: ymax must exceed ymin");
  Impl& s = *impl_;
  s.scale = std::min(s.plot.width / (xmax - xmin), s.plot.height / (ymax - ymin));
  s.worldCenter = Eigen::Vector2d(0.5 * (xmin + xmax), 0.5 * (ymin + ymax));
}

double Canvas::pixelsPerUnit() const { return impl_->scale; }
Eigen::Vector2d Canvas::toPixel(const Eigen::Vector2d& world) const { return impl_->toScreen(world); }

Eigen::Vector2d Canvas::Impl::toScreen(const Eigen::Vector2d& world) const {
  return Eigen::Vector2d(pixelCenter.x() + (world.x() - worldCenter.x()) * scale,
                         pixelCenter.y() - (world.y() - worldCenter.y()) * scale);
}

void Canvas::title(const std::string& markup, const TextStyle& style) {
  Impl& s = *impl_;
  const TextExtent e = measureText(markup, style.font, style.size);
  // The band between the panel's top and its plot area; the baseline depends on the
  // font size only, so the titles of a row of panels line up.
  const double bandTop = s.panel.y + (s.titleBand > 0.0 ? 0.5 * s.padding : 0.0);
  const double band = s.titleBand > 0.0 ? s.plot.y - bandTop : 1.4 * style.size;
  const double baseline = bandTop + 0.5 * band + 0.36 * style.size;
  const double x = s.panel.x + 0.5 * s.panel.width - 0.5 * (e.left + e.right);
  s.labels.push_back(Label{std::round(x), std::round(baseline), markup, style, s.panel});
}

void Canvas::frame(const Stroke& stroke) {
  const PixelRect& r = impl_->panel;
  const double h = 0.5 * stroke.width;
  impl_->draw([&](cairo_t* cr) {
    detail::strokePath(cr, {{r.x + h, r.y + h}, {r.x + r.width - h, r.y + h}, {r.x + r.width - h, r.y + r.height - h},
                            {r.x + h, r.y + r.height - h}}, true, stroke);
  });
}

// ---- 2D drawing -------------------------------------------------------------------------

void Canvas::line(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Stroke& stroke) {
  polyline({a, b}, stroke, false);
}

void Canvas::polyline(const std::vector<Eigen::Vector2d>& points, const Stroke& stroke, bool closed) {
  std::vector<Eigen::Vector2d> path;
  for (const auto& p : points) path.push_back(impl_->toScreen(p));
  impl_->draw([&](cairo_t* cr) { detail::strokePath(cr, path, closed, stroke); });
}

void Canvas::polygon(const std::vector<Eigen::Vector2d>& points, const ShapeStyle& shape) {
  std::vector<Eigen::Vector2d> path;
  for (const auto& p : points) path.push_back(impl_->toScreen(p));
  impl_->draw([&](cairo_t* cr) {
    detail::fillPath(cr, path, shape.fill);
    detail::strokePath(cr, path, true, shape.outline);
  });
}

void Canvas::point(const Eigen::Vector2d& p, const Color& fill, double radiusPx, const Stroke& outline) {
  const Eigen::Vector2d c = impl_->toScreen(p);
  impl_->draw([&](cairo_t* cr) { detail::disc(cr, c, radiusPx, fill, outline); });
}

void Canvas::arrow(const Eigen::Vector2d& from, const Eigen::Vector2d& to, const Stroke& stroke, double headPx) {
  const Eigen::Vector2d a = impl_->toScreen(from), b = impl_->toScreen(to);
  impl_->draw([&](cairo_t* cr) { detail::arrowPath(cr, a, b, stroke, headPx); });
}

void Canvas::circle(const Eigen::Vector2d& center, double radius, const ShapeStyle& shape) {
  if (!(radius > 0.0)) throw std::invalid_argument("Canvas::circle: radius must be positive");
  const Eigen::Vector2d c = impl_->toScreen(center);
  const double r = radius * impl_->scale;
  impl_->draw([&](cairo_t* cr) {
    cairo_new_path(cr);
    cairo_arc(cr, c.x(), c.y(), r, 0.0, 2.0 * M_PI);
    if (!shape.fill.invisible()) {
      detail::setColor(cr, shape.fill);
      cairo_fill_preserve(cr);
    }
    cairo_new_path(cr);
    cairo_arc(cr, c.x(), c.y(), r, 0.0, 2.0 * M_PI);
    cairo_close_path(cr);
    if (!shape.outline.color.invisible() && shape.outline.width > 0.0) {
      cairo_set_line_width(cr, shape.outline.width);
      cairo_set_dash(cr, nullptr, 0, 0.0);
      detail::setColor(cr, shape.outline.color);
      cairo_stroke(cr);
    }
    cairo_new_path(cr);
  });
}

void Canvas::axes(const Stroke& stroke, bool originMarker) {
  const Impl& s = *impl_;
  const double x0 = s.worldCenter.x() + (s.plot.x - s.pixelCenter.x()) / s.scale;
  const double x1 = s.worldCenter.x() + (s.plot.x + s.plot.width - s.pixelCenter.x()) / s.scale;
  const double y0 = s.worldCenter.y() - (s.plot.y + s.plot.height - s.pixelCenter.y()) / s.scale;
  const double y1 = s.worldCenter.y() - (s.plot.y - s.pixelCenter.y()) / s.scale;
  if (y0 <= 0.0 && 0.0 <= y1) line({x0, 0.0}, {x1, 0.0}, stroke);
  if (x0 <= 0.0 && 0.0 <= x1) line({0.0, y0}, {0.0, y1}, stroke);
  if (originMarker && x0 <= 0.0 && 0.0 <= x1 && y0 <= 0.0 && 0.0 <= y1)
    point({0.0, 0.0}, palette::background, 3.0, Stroke{mix(stroke.color, palette::ink, 0.5), 1.2, {}});
}

// ---- labels -----------------------------------------------------------------------------

void Canvas::Impl::queueLabel(double x, double y, const std::string& markup, const TextStyle& style, Anchor anchor,
                              const Eigen::Vector2d& offsetPx) {
  const TextExtent e = measureText(markup, style.font, style.size);
  const double gap = style::labelGap;
  double pen = x - 0.5 * (e.left + e.right), base = y + 0.5 * (e.ascent - e.descent);
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
  // Whole pixels for the pen, so that a label looks the same wherever it is placed.
  labels.push_back(Label{std::round(pen + offsetPx.x()), std::round(base - offsetPx.y()), markup, style, panel});
}

void Canvas::textAtPixel(double x, double y, const std::string& markup, const TextStyle& style, Anchor anchor) {
  impl_->queueLabel(x, y, markup, style, anchor, Eigen::Vector2d::Zero());
}

void Canvas::text(const Eigen::Vector2d& p, const std::string& markup, const TextStyle& style, Anchor anchor,
                  const Eigen::Vector2d& offsetPx) {
  const Eigen::Vector2d q = impl_->toScreen(p);
  impl_->queueLabel(q.x(), q.y(), markup, style, anchor, offsetPx);
}

// ---- output -----------------------------------------------------------------------------

namespace {

// An image surface of the figure's size: RGB24 when the background is opaque (a PNG
// without an alpha channel), else ARGB32.
cairo_surface_t* imageSurface(const Canvas::Impl& s) {
  return cairo_image_surface_create(s.background.a >= 1.0 ? CAIRO_FORMAT_RGB24 : CAIRO_FORMAT_ARGB32, s.width, s.height);
}

void check(cairo_surface_t* surface, const std::string& path) {
  if (const cairo_status_t status = cairo_surface_status(surface); status != CAIRO_STATUS_SUCCESS) {
    cairo_surface_destroy(surface);
    throw std::runtime_error("cannot write " + path + ": " + cairo_status_to_string(status));
  }
}

}  // namespace

Image Canvas::image() {
  cairo_surface_t* surface = imageSurface(*impl_);
  cairo_t* cr = cairo_create(surface);
  impl_->render(cr);
  cairo_destroy(cr);
  Image out = detail::fromSurface(surface);
  cairo_surface_destroy(surface);
  return out;
}

void Canvas::save(const std::string& path) {
  const std::size_t dot = path.find_last_of('.');
  std::string extension = dot == std::string::npos ? "" : path.substr(dot + 1);
  for (char& c : extension) c = char(std::tolower(static_cast<unsigned char>(c)));
  const double w = impl_->width, h = impl_->height;
  cairo_surface_t* surface = extension == "png"   ? imageSurface(*impl_)
                             : extension == "svg" ? cairo_svg_surface_create(path.c_str(), w, h)
                             : extension == "pdf" ? cairo_pdf_surface_create(path.c_str(), w, h)
                                                  : nullptr;
  if (!surface) throw std::invalid_argument("Canvas::save: " + path + " is not .png, .svg or .pdf");
  check(surface, path);
  cairo_t* cr = cairo_create(surface);
  impl_->render(cr);
  cairo_destroy(cr);
  const cairo_status_t written = extension == "png" ? cairo_surface_write_to_png(surface, path.c_str()) : CAIRO_STATUS_SUCCESS;
  cairo_surface_finish(surface);
  check(surface, path);
  cairo_surface_destroy(surface);
  if (written != CAIRO_STATUS_SUCCESS) throw std::runtime_error("cannot write " + path + ": " + cairo_status_to_string(written));
}

}  // namespace gjkx::render
