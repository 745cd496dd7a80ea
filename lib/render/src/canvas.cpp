// The Canvas of the paper's figures: panels and their mappings, 2D drawing by Cairo into a
// recording surface, labels by Pango over it, and the figure written as PNG, SVG or PDF.
// The 3D calls are in scene.cpp.
#include "internal.hpp"

#include <cairo-pdf.h>
#include <cairo-svg.h>

#include <algorithm>
#include <cctype>
#include <cstring>
#include <cmath>
#include <stdexcept>

namespace gjkx::render {

namespace {

void strokePath(cairo_t* cr, const std::vector<Eigen::Vector2d>& points, bool closed, const Stroke& stroke) {
  if (stroke.color.invisible() || !(stroke.width > 0.0) || points.empty()) return;
  cairo_new_path(cr);
  for (const auto& p : points) cairo_line_to(cr, p.x(), p.y());
  if (points.size() == 1) cairo_line_to(cr, points[0].x(), points[0].y());  // a dot
  if (closed && points.size() > 2) cairo_close_path(cr);
  cairo_set_line_width(cr, stroke.width);
  cairo_set_line_cap(cr, CAIRO_LINE_CAP_ROUND);
  cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
  // Round caps lengthen every dash by the width, so the pattern's dash includes them.
  const double on = std::max(0.0, stroke.dash.on - stroke.width), pattern[2] = {on, stroke.dash.off + stroke.dash.on - on};
  cairo_set_dash(cr, pattern, stroke.dash.solid() ? 0 : 2, 0.0);
  detail::setColor(cr, stroke.color);
  cairo_stroke(cr);
}

void fillPath(cairo_t* cr, const std::vector<Eigen::Vector2d>& points, const Color& color) {
  if (color.invisible() || points.size() < 3) return;
  cairo_new_path(cr);
  for (const auto& p : points) cairo_line_to(cr, p.x(), p.y());
  cairo_set_fill_rule(cr, CAIRO_FILL_RULE_EVEN_ODD);
  detail::setColor(cr, color);
  cairo_fill(cr);
}

}  // namespace

// A disc with its outline ring inside the radius (point markers, and Canvas::circle()).
void detail::disc(cairo_t* cr, const Eigen::Vector2d& c, double radius, const Color& fill, const Stroke& outline) {
  if (!(radius > 0.0)) return;
  const bool ring = !outline.color.invisible() && outline.width > 0.0;
  cairo_new_path(cr);
  cairo_arc(cr, c.x(), c.y(), std::max(0.0, ring ? radius - 0.5 * outline.width : radius), 0.0, 2.0 * M_PI);
  setColor(cr, fill);
  if (!fill.invisible()) cairo_fill_preserve(cr);
  cairo_set_line_width(cr, outline.width);
  cairo_set_dash(cr, nullptr, 0, 0.0);
  setColor(cr, outline.color);
  if (ring) cairo_stroke_preserve(cr);
  cairo_new_path(cr);
}

void detail::arrowPath(cairo_t* cr, const Eigen::Vector2d& tail, const Eigen::Vector2d& tip, const Stroke& stroke, double headPx) {
  const double length = (tip - tail).norm();
  if (length < 1e-9 || stroke.color.invisible()) return;
  const Eigen::Vector2d u = (tip - tail) / length, normal(-u.y(), u.x()), base = tip - std::clamp(headPx, 0.0, length) * u;
  const double head = std::clamp(headPx, 0.0, length), halfWidth = std::max(0.36 * head, 0.9 * stroke.width);
  // The shaft ends inside the head, so that its round cap does not show at the tip.
  if (length > 0.6 * head) strokePath(cr, {tail, tip - 0.6 * head * u}, false, Stroke{stroke.color, stroke.width, {}});
  fillPath(cr, {tip, base + halfWidth * normal, tip - 0.78 * head * u, base - halfWidth * normal}, stroke.color);
}

Canvas::Canvas(int width, int height, const Color& background) : impl_(std::make_unique<Impl>()) {
  if (width <= 0) throw std::invalid_argument("Canvas: width must be positive, got " + std::to_string(width));
  if (height <= 0) throw std::invalid_argument("Canvas: height must be positive, got " + std::to_string(height));
  Impl& s = *impl_;
  s.width = width;
  s.height = height;
  s.background = background;
  const cairo_rectangle_t extents{0.0, 0.0, double(width), double(height)};
  s.record = cairo_recording_surface_create(CAIRO_CONTENT_COLOR_ALPHA, &extents);
  s.cr = cairo_create(s.record);
  detail::setColor(s.cr, background);
  cairo_paint(s.cr);
  setPanel(PixelRect{0, 0, width, height}, 0.0, 0.0);
}

Canvas::~Canvas() = default;
Canvas::Canvas(Canvas&& other) noexcept = default;
Canvas& Canvas::operator=(Canvas&& other) noexcept = default;
int Canvas::width() const { return impl_->width; }
int Canvas::height() const { return impl_->height; }
PixelRect Canvas::panel() const { return impl_->panel; }
PixelRect Canvas::plotArea() const { return impl_->plot; }
double Canvas::plotAspect() const { return double(impl_->plot.width) / double(impl_->plot.height); }
double Canvas::pixelsPerUnit() const { return impl_->scale; }
Eigen::Vector2d Canvas::toPixel(const Eigen::Vector2d& world) const { return impl_->toScreen(world); }

void Canvas::setPanel(const PixelRect& rect, double padding, double titleBand) {
  Impl& s = *impl_;
  if (rect.width <= 0) throw std::invalid_argument("Canvas::setPanel: width must be positive");
  if (rect.height <= 0) throw std::invalid_argument("Canvas::setPanel: height must be positive");
  if (rect.x < 0 || rect.y < 0 || rect.x + rect.width > s.width || rect.y + rect.height > s.height)
    throw std::invalid_argument("Canvas::setPanel: the rectangle leaves the canvas");
  if (!(padding >= 0.0 && titleBand >= 0.0)) throw std::invalid_argument("Canvas::setPanel: padding and titleBand must not be negative");
  s.flush3d();
  s.panel = s.clip = rect;
  s.padding = padding;
  s.titleBand = titleBand;
  const int pad = int(std::lround(padding)), band = int(std::lround(titleBand));
  s.plot = PixelRect{rect.x + pad, rect.y + pad + band, std::max(1, rect.width - 2 * pad), std::max(1, rect.height - 2 * pad - band)};
  s.scale = 1.0;
  s.pixelCenter = Eigen::Vector2d(s.plot.x + 0.5 * s.plot.width, s.plot.y + 0.5 * s.plot.height);
  s.worldCenter = Eigen::Vector2d(0.5 * s.plot.width, 0.5 * s.plot.height);
  s.has3d = false;
}

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
  impl_->scale = std::min(impl_->plot.width / (xmax - xmin), impl_->plot.height / (ymax - ymin));
  impl_->worldCenter = Eigen::Vector2d(0.5 * (xmin + xmax), 0.5 * (ymin + ymax));
}

void Canvas::line(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Stroke& stroke) { polyline({a, b}, stroke, false); }

void Canvas::polyline(const std::vector<Eigen::Vector2d>& points, const Stroke& stroke, bool closed) {
  std::vector<Eigen::Vector2d> path;
  for (const auto& p : points) path.push_back(impl_->toScreen(p));
  impl_->draw([&](cairo_t* cr) { strokePath(cr, path, closed, stroke); });
}

void Canvas::polygon(const std::vector<Eigen::Vector2d>& points, const ShapeStyle& shape) {
  std::vector<Eigen::Vector2d> path;
  for (const auto& p : points) path.push_back(impl_->toScreen(p));
  impl_->draw([&](cairo_t* cr) { fillPath(cr, path, shape.fill); });
  polyline(points, shape.outline, true);
}

void Canvas::point(const Eigen::Vector2d& p, const Color& fill, double radiusPx, const Stroke& outline) {
  impl_->draw([&](cairo_t* cr) { detail::disc(cr, impl_->toScreen(p), radiusPx, fill, outline); });
}

void Canvas::arrow(const Eigen::Vector2d& from, const Eigen::Vector2d& to, const Stroke& stroke, double headPx) {
  impl_->draw([&](cairo_t* cr) { detail::arrowPath(cr, impl_->toScreen(from), impl_->toScreen(to), stroke, headPx); });
}

void Canvas::circle(const Eigen::Vector2d& center, double radius, const ShapeStyle& shape) {
  if (!(radius > 0.0)) throw std::invalid_argument("Canvas::circle: radius must be positive");
  // A disc whose outline ring is centred on the circle: half of it inside, half outside.
  const double r = radius * impl_->scale + (shape.outline.color.invisible() ? 0.0 : 0.5 * shape.outline.width);
  impl_->draw([&](cairo_t* cr) { detail::disc(cr, impl_->toScreen(center), r, shape.fill, shape.outline); });
}

void Canvas::axes(const Stroke& stroke, bool originMarker) {
  const Impl& s = *impl_;
  const Eigen::Vector2d lo = s.worldCenter + Eigen::Vector2d(s.plot.x - s.pixelCenter.x(), s.pixelCenter.y() - s.plot.y - s.plot.height) / s.scale;
  const Eigen::Vector2d hi = lo + Eigen::Vector2d(s.plot.width, s.plot.height) / s.scale;
  const bool x = lo.x() <= 0.0 && 0.0 <= hi.x(), y = lo.y() <= 0.0 && 0.0 <= hi.y();
  if (y) line({lo.x(), 0.0}, {hi.x(), 0.0}, stroke);
  if (x) line({0.0, lo.y()}, {0.0, hi.y()}, stroke);
  if (originMarker && x && y) point({0.0, 0.0}, palette::background, 3.0, Stroke{mix(stroke.color, palette::ink, 0.5), 1.2, {}});
}

void Canvas::title(const std::string& markup, const TextStyle& style) {
  Impl& s = *impl_;
  const TextExtent e = measureText(markup, style.font, style.size);
  // The band between the panel's top and its plot area; the baseline depends on the font
  // size only, so the titles of a row of panels line up.
  const double bandTop = s.panel.y + (s.titleBand > 0.0 ? 0.5 * s.padding : 0.0);
  const double band = s.titleBand > 0.0 ? s.plot.y - bandTop : 1.4 * style.size;
  const double x = std::round(s.panel.x + 0.5 * s.panel.width - 0.5 * (e.left + e.right));
  const double baseline = std::round(bandTop + 0.5 * band + 0.36 * style.size);
  s.onTop(s.labels, [=](cairo_t* cr) { detail::showText(cr, x, baseline, markup, style); });
}

void Canvas::Impl::queueLabel(const Eigen::Vector2d& at, const std::string& markup, const TextStyle& style, Anchor anchor,
                              const Eigen::Vector2d& offsetPx) {
  const TextExtent e = measureText(markup, style.font, style.size);
  const double gap = style::labelGap;
  double pen = at.x() - 0.5 * (e.left + e.right), base = at.y() + 0.5 * (e.ascent - e.descent);
  if (anchor == Anchor::Right || anchor == Anchor::AboveRight || anchor == Anchor::BelowRight) pen = at.x() + gap - e.left;
  if (anchor == Anchor::Left || anchor == Anchor::AboveLeft || anchor == Anchor::BelowLeft) pen = at.x() - gap - e.right;
  if (anchor == Anchor::Above || anchor == Anchor::AboveLeft || anchor == Anchor::AboveRight) base = at.y() - gap - e.descent;
  if (anchor == Anchor::Below || anchor == Anchor::BelowLeft || anchor == Anchor::BelowRight) base = at.y() + gap + e.ascent;
  // Whole pixels for the pen, so that a label looks the same wherever it is placed.
  const double x = std::round(pen + offsetPx.x()), baseline = std::round(base - offsetPx.y());
  onTop(labels, [=](cairo_t* cr) { detail::showText(cr, x, baseline, markup, style); });
}

void Canvas::textAtPixel(double x, double y, const std::string& markup, const TextStyle& style, Anchor anchor) {
  impl_->queueLabel({x, y}, markup, style, anchor, Eigen::Vector2d::Zero());
}

void Canvas::text(const Eigen::Vector2d& p, const std::string& markup, const TextStyle& style, Anchor anchor,
                  const Eigen::Vector2d& offsetPx) {
  impl_->queueLabel(impl_->toScreen(p), markup, style, anchor, offsetPx);
}

// The finished figure on `surface`: the pending 3D scene, the recording, then what goes on top.
void Canvas::Impl::finish(cairo_surface_t* surface) {
  flush3d();
  cairo_t* target = cairo_create(surface);
  cairo_set_source_surface(target, record, 0.0, 0.0);
  cairo_paint(target);
  for (const auto* list : {&overlays, &labels})
    for (const auto& draw : *list) draw(target);
  cairo_destroy(target);
}

std::vector<std::uint8_t> Canvas::rgba() {
  cairo_surface_t* surface = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, impl_->width, impl_->height);
  impl_->finish(surface);
  cairo_surface_flush(surface);
  // Cairo's ARGB32 is premultiplied, one native-endian 32-bit word a pixel.
  const unsigned char* data = cairo_image_surface_get_data(surface);
  const int stride = cairo_image_surface_get_stride(surface);
  std::vector<std::uint8_t> out(std::size_t(impl_->width) * std::size_t(impl_->height) * 4);
  for (int y = 0; y < impl_->height; ++y)
    for (int x = 0; x < impl_->width; ++x) {
      std::uint32_t word;
      std::memcpy(&word, data + std::size_t(y) * std::size_t(stride) + 4 * std::size_t(x), 4);
      const std::uint32_t a = word >> 24;
      std::uint8_t* p = &out[(std::size_t(y) * std::size_t(impl_->width) + std::size_t(x)) * 4];
      for (int c = 0; c < 3; ++c) {
        const std::uint32_t v = (word >> (16 - 8 * c)) & 0xFFu;
        p[c] = std::uint8_t(a == 0 ? 0 : std::min<std::uint32_t>(255, (v * 255 + a / 2) / a));
      }
      p[3] = std::uint8_t(a);
    }
  cairo_surface_destroy(surface);
  return out;
}

void Canvas::save(const std::string& path) {
  std::string extension = path.substr(std::min(path.size(), path.find_last_of('.') + 1));
  for (char& c : extension) c = char(std::tolower(static_cast<unsigned char>(c)));
  const double w = impl_->width, h = impl_->height;
  // A PNG of an opaque background has no alpha channel (RGB24); Cairo's writer adds no time stamp.
  cairo_surface_t* surface =
      extension == "png"   ? cairo_image_surface_create(impl_->background.a >= 1.0 ? CAIRO_FORMAT_RGB24 : CAIRO_FORMAT_ARGB32, int(w), int(h))
      : extension == "svg" ? cairo_svg_surface_create(path.c_str(), w, h)
      : extension == "pdf" ? cairo_pdf_surface_create(path.c_str(), w, h)
                           : nullptr;
  if (!surface) throw std::invalid_argument("Canvas::save: " + path + " is not .png, .svg or .pdf");
  impl_->finish(surface);
  const cairo_status_t written = extension == "png" ? cairo_surface_write_to_png(surface, path.c_str()) : CAIRO_STATUS_SUCCESS;
  cairo_surface_finish(surface);
  const cairo_status_t status = written != CAIRO_STATUS_SUCCESS ? written : cairo_surface_status(surface);
  cairo_surface_destroy(surface);
  if (status != CAIRO_STATUS_SUCCESS) throw std::runtime_error("cannot write " + path + ": " + cairo_status_to_string(status));
}

}  // namespace gjkx::render
