// Strokes (solid and dashed, round joins and caps), fills, discs and arrows of
// the paper's figures, tessellated in canvas pixels; and the 2D drawing calls.
#include "canvas_impl.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace gjkx::render {

namespace {

using detail::ScreenPoint;
constexpr double kPi = 3.14159265358979323846;

ScreenPoint lerp(const ScreenPoint& a, const ScreenPoint& b, double t) {
  return ScreenPoint{a.x + (b.x - a.x) * t, a.y + (b.y - a.y) * t, a.z + (b.z - a.z) * t};
}

double dist(const ScreenPoint& a, const ScreenPoint& b) { return std::hypot(b.x - a.x, b.y - a.y); }

int circleSegments(double radiusPx, int ss) {
  return std::clamp(static_cast<int>(std::ceil(2.0 * kPi * radiusPx * ss / 2.0)), 10, 160);
}

void appendDisc(std::vector<ScreenPoint>& tris, const ScreenPoint& c, double r, int ss) {
  const int n = circleSegments(r, ss);
  for (int i = 0; i < n; ++i) {
    const double a0 = 2.0 * kPi * i / n, a1 = 2.0 * kPi * (i + 1) / n;
    tris.push_back(c);
    tris.push_back(ScreenPoint{c.x + r * std::cos(a0), c.y + r * std::sin(a0), c.z});
    tris.push_back(ScreenPoint{c.x + r * std::cos(a1), c.y + r * std::sin(a1), c.z});
  }
}

void appendRing(std::vector<ScreenPoint>& tris, const ScreenPoint& c, double r0, double r1, int ss) {
  const int n = circleSegments(r1, ss);
  for (int i = 0; i < n; ++i) {
    const double a0 = 2.0 * kPi * i / n, a1 = 2.0 * kPi * (i + 1) / n;
    const ScreenPoint p00{c.x + r0 * std::cos(a0), c.y + r0 * std::sin(a0), c.z};
    const ScreenPoint p01{c.x + r0 * std::cos(a1), c.y + r0 * std::sin(a1), c.z};
    const ScreenPoint p10{c.x + r1 * std::cos(a0), c.y + r1 * std::sin(a0), c.z};
    const ScreenPoint p11{c.x + r1 * std::cos(a1), c.y + r1 * std::sin(a1), c.z};
    tris.insert(tris.end(), {p00, p10, p11, p00, p11, p01});
  }
}

// A solid polyline of the given width with round joins and caps.
void appendSolidStroke(std::vector<ScreenPoint>& tris, const std::vector<ScreenPoint>& pts, double width, int ss) {
  const double h = 0.5 * width;
  for (std::size_t i = 0; i + 1 < pts.size(); ++i) {
    const ScreenPoint& a = pts[i];
    const ScreenPoint& b = pts[i + 1];
    const double len = dist(a, b);
    if (len < 1e-9) continue;
    const double nx = -(b.y - a.y) / len * h, ny = (b.x - a.x) / len * h;
    const ScreenPoint a0{a.x + nx, a.y + ny, a.z}, a1{a.x - nx, a.y - ny, a.z};
    const ScreenPoint b0{b.x + nx, b.y + ny, b.z}, b1{b.x - nx, b.y - ny, b.z};
    tris.insert(tris.end(), {a0, b0, b1, a0, b1, a1});
  }
  for (const ScreenPoint& p : pts) appendDisc(tris, p, h, ss);
}

// Cuts a path into dashes; round caps lengthen each dash by the width, so the
// drawn parts are shortened accordingly (dashes shorter than the width become dots).
std::vector<std::vector<ScreenPoint>> dashPieces(const std::vector<ScreenPoint>& path, const Dash& dash, double width) {
  const double on = std::max(0.0, dash.on - width), off = dash.off + (dash.on - on);
  std::vector<std::vector<ScreenPoint>> pieces;
  std::vector<ScreenPoint> current;
  bool drawing = true;
  double left = on;  // length left in the current dash or gap
  current.push_back(path.front());
  for (std::size_t i = 0; i + 1 < path.size(); ++i) {
    ScreenPoint a = path[i];
    const ScreenPoint& b = path[i + 1];
    double len = dist(a, b);
    while (len >= left) {
      const ScreenPoint cut = lerp(a, b, len > 0.0 ? left / len : 0.0);
      if (drawing) {
        current.push_back(cut);
        pieces.push_back(current);
        current.clear();
      } else {
        current.push_back(cut);
      }
      drawing = !drawing;
      len -= left;
      a = cut;
      left = drawing ? on : off;
      if (on <= 0.0 && drawing) {  // dots: a zero-length dash
        pieces.push_back({a});
        current.clear();
        drawing = false;
        left = off;
      }
    }
    left -= len;
    if (drawing) current.push_back(b);
  }
  if (drawing && !current.empty()) pieces.push_back(current);
  return pieces;
}

bool isConvex(const std::vector<ScreenPoint>& poly) {
  int sign = 0;
  const std::size_t n = poly.size();
  for (std::size_t i = 0; i < n; ++i) {
    const ScreenPoint& a = poly[i];
    const ScreenPoint& b = poly[(i + 1) % n];
    const ScreenPoint& c = poly[(i + 2) % n];
    const double cross = (b.x - a.x) * (c.y - b.y) - (b.y - a.y) * (c.x - b.x);
    if (std::abs(cross) < 1e-12) continue;
    const int s = cross > 0 ? 1 : -1;
    if (sign != 0 && s != sign) return false;
    sign = s;
  }
  return true;
}

}  // namespace

void Canvas::Impl::strokePath(const std::vector<ScreenPoint>& path, bool closed, const Stroke& stroke, bool depthTest) {
  if (stroke.color.invisible() || !(stroke.width > 0.0) || path.empty()) return;
  std::vector<ScreenPoint> full = path;
  if (closed && path.size() > 2) full.push_back(path.front());
  std::vector<ScreenPoint> tris;
  if (stroke.dash.solid() || full.size() < 2) {
    appendSolidStroke(tris, full, stroke.width, ss);
  } else {
    for (const auto& piece : dashPieces(full, stroke.dash, stroke.width)) appendSolidStroke(tris, piece, stroke.width, ss);
  }
  beginPrimitive(depthTest, depthTest);
  if (stroke.color.a >= 1.0) {
    emitTriangles(tris, stroke.color);
    return;
  }
  // Translucent: paint every sample once (the quads and discs overlap), then clear the stencil.
  glEnable(GL_STENCIL_TEST);
  glStencilMask(0xFF);
  glStencilFunc(GL_EQUAL, 0, 0xFF);
  glStencilOp(GL_KEEP, GL_KEEP, GL_INCR);
  emitTriangles(tris, stroke.color);
  glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
  glDepthMask(GL_FALSE);
  glStencilFunc(GL_ALWAYS, 0, 0xFF);
  glStencilOp(GL_ZERO, GL_ZERO, GL_ZERO);
  emitTriangles(tris, stroke.color);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glDisable(GL_STENCIL_TEST);
}

void Canvas::Impl::fillPolygon(const std::vector<ScreenPoint>& poly, const Color& color, bool depthTest) {
  if (color.invisible() || poly.size() < 3) return;
  std::vector<ScreenPoint> fan;
  for (std::size_t i = 1; i + 1 < poly.size(); ++i) fan.insert(fan.end(), {poly[0], poly[i], poly[i + 1]});
  beginPrimitive(depthTest, depthTest && color.a >= 1.0);
  if (isConvex(poly)) {
    emitTriangles(fan, color);
    return;
  }
  // Any simple polygon: even-odd parity in the stencil, then cover (and reset) it.
  glEnable(GL_STENCIL_TEST);
  glStencilMask(0x01);
  glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
  glDepthMask(GL_FALSE);
  glStencilFunc(GL_ALWAYS, 0, 0x01);
  glStencilOp(GL_KEEP, GL_KEEP, GL_INVERT);
  emitTriangles(fan, color);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glStencilFunc(GL_NOTEQUAL, 0, 0x01);
  glStencilOp(GL_ZERO, GL_ZERO, GL_ZERO);
  emitTriangles(fan, color);
  glStencilMask(0xFF);
  glDisable(GL_STENCIL_TEST);
}

void Canvas::Impl::disc(const ScreenPoint& c, double radius, const Color& fill, const Stroke& outline, bool depthTest) {
  if (!(radius > 0.0)) return;
  const bool ring = !outline.color.invisible() && outline.width > 0.0;
  if (!fill.invisible()) {
    std::vector<ScreenPoint> tris;
    appendDisc(tris, c, ring ? radius - 0.5 * outline.width : radius, ss);
    beginPrimitive(depthTest, depthTest);
    emitTriangles(tris, fill);
  }
  if (ring) {
    std::vector<ScreenPoint> tris;
    appendRing(tris, c, std::max(0.0, radius - outline.width), radius, ss);
    beginPrimitive(depthTest, depthTest);
    emitTriangles(tris, outline.color);
  }
}

void Canvas::Impl::arrowPath(ScreenPoint tail, ScreenPoint tip, const Stroke& stroke, double headPx, bool depthTest) {
  const double len = dist(tail, tip);
  if (len < 1e-9 || stroke.color.invisible()) return;
  const double ux = (tip.x - tail.x) / len, uy = (tip.y - tail.y) / len;
  const double h = std::min(std::max(headPx, 0.0), len);
  const double halfWidth = std::max(0.36 * h, 0.9 * stroke.width);
  // The shaft ends inside the head so its round cap does not show at the tip.
  const double shaftEnd = std::max(0.0, len - 0.6 * h);
  if (shaftEnd > 0.0) strokePath({tail, lerp(tail, tip, shaftEnd / len)}, false, stroke, depthTest);
  if (h <= 0.0) return;
  const ScreenPoint base = lerp(tip, tail, h / len), notch = lerp(tip, tail, 0.78 * h / len);
  const ScreenPoint left{base.x - uy * halfWidth, base.y + ux * halfWidth, base.z};
  const ScreenPoint right{base.x + uy * halfWidth, base.y - ux * halfWidth, base.z};
  beginPrimitive(depthTest, depthTest);
  emitTriangles({tip, left, notch, tip, notch, right}, stroke.color);
}

// ---- 2D drawing calls --------------------------------------------------------------------

void Canvas::line(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Stroke& stroke) {
  impl_->strokePath({impl_->toScreen(a), impl_->toScreen(b)}, false, stroke, false);
}

void Canvas::polyline(const std::vector<Eigen::Vector2d>& points, const Stroke& stroke, bool closed) {
  std::vector<ScreenPoint> path;
  for (const auto& p : points) path.push_back(impl_->toScreen(p));
  impl_->strokePath(path, closed, stroke, false);
}

void Canvas::polygon(const std::vector<Eigen::Vector2d>& points, const ShapeStyle& shape) {
  std::vector<ScreenPoint> path;
  for (const auto& p : points) path.push_back(impl_->toScreen(p));
  impl_->fillPolygon(path, shape.fill, false);
  impl_->strokePath(path, true, shape.outline, false);
}

void Canvas::point(const Eigen::Vector2d& p, const Color& fill, double radiusPx, const Stroke& outline) {
  impl_->disc(impl_->toScreen(p), radiusPx, fill, outline, false);
}

void Canvas::arrow(const Eigen::Vector2d& from, const Eigen::Vector2d& to, const Stroke& stroke, double headPx) {
  impl_->arrowPath(impl_->toScreen(from), impl_->toScreen(to), stroke, headPx, false);
}

void Canvas::circle(const Eigen::Vector2d& center, double radius, const ShapeStyle& shape) {
  if (!(radius > 0.0)) throw std::invalid_argument("Canvas::circle: radius must be positive");
  const int n = std::clamp(static_cast<int>(std::ceil(2.0 * kPi * radius * impl_->scale / 2.0)), 24, 720);
  std::vector<ScreenPoint> path;
  for (int i = 0; i < n; ++i) {
    const double a = 2.0 * kPi * i / n;
    path.push_back(impl_->toScreen(center + radius * Eigen::Vector2d(std::cos(a), std::sin(a))));
  }
  impl_->fillPolygon(path, shape.fill, false);
  impl_->strokePath(path, true, shape.outline, false);
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

void Canvas::frame(const Stroke& stroke) {
  const PixelRect& r = impl_->panel;
  const double h = 0.5 * stroke.width;
  impl_->strokePath({{r.x + h, r.y + h, 0.0}, {r.x + r.width - h, r.y + h, 0.0},
                     {r.x + r.width - h, r.y + r.height - h, 0.0}, {r.x + h, r.y + r.height - h, 0.0}},
                    true, stroke, false);
}

}  // namespace gjkx::render
