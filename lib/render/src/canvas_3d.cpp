// The 3D drawing calls of the Canvas (the 3D figures of the paper): meshes, polygons and
// lines in space become a panel's scene for OSMesa (scene_gl.cpp); points, arrows and
// labels in space are drawn by Cairo over it, at their projections.
#include "internal.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <stdexcept>

namespace gjkx::render {

namespace {

std::array<std::uint8_t, 4> bytes(const Color& c) {
  const auto byte = [](double v) { return std::uint8_t(std::lround(std::clamp(v, 0.0, 1.0) * 255.0)); };
  return {byte(c.r), byte(c.g), byte(c.b), byte(c.a)};
}

Eigen::Vector4d toClip(const Camera& camera, const Eigen::Vector3d& p) {
  return camera.projection * (camera.view * p.homogeneous());
}

// Line segments (pairs of points) of one colour and width as a batch of the scene.
detail::Batch3d segments(const Camera& camera, const std::vector<Eigen::Vector3d>& ends, const Stroke& stroke) {
  detail::Batch3d b;
  b.lines = true;
  b.lineWidth = stroke.width;
  for (const auto& p : ends) b.vertices.push_back(toClip(camera, p));
  b.colors.assign(ends.size() / 2, bytes(stroke.color));
  return b;
}

// Where a 3D point appears on the canvas, if it is in front of the eye.
bool onScreen(const Camera& camera, const PixelRect& plot, const Eigen::Vector3d& p, Eigen::Vector2d& pixel) {
  const Eigen::Vector4d c = toClip(camera, p);
  if (!(c.w() > 0.0)) return false;
  pixel = Eigen::Vector2d(plot.x + 0.5 * (c.x() / c.w() + 1.0) * plot.width, plot.y + 0.5 * (1.0 - c.y() / c.w()) * plot.height);
  return true;
}

}  // namespace

void Canvas::Impl::require3d(const char* what) const {
  if (!has3d) throw std::logic_error(std::string("Canvas::") + what + ": call setCamera() for the panel first");
}

void Canvas::setCamera(const Camera& camera) {
  impl_->flush3d();
  impl_->camera = camera;
  impl_->has3d = true;
}

const Camera& Canvas::camera() const {
  impl_->require3d("camera");
  return impl_->camera;
}

Eigen::Vector3d Canvas::project(const Eigen::Vector3d& p) const {
  impl_->require3d("project");
  const Eigen::Vector4d c = toClip(impl_->camera, p);
  const PixelRect& plot = impl_->plot;
  return Eigen::Vector3d(plot.x + 0.5 * (c.x() / c.w() + 1.0) * plot.width,
                         plot.y + 0.5 * (1.0 - c.y() / c.w()) * plot.height, c.z() / c.w());
}

void Canvas::mesh(const Mesh& m, const MeshStyle& meshStyle) {
  Impl& s = *impl_;
  s.require3d("mesh");
  validateMesh(m);
  if (m.vertices.empty() || m.triangles.empty()) return;
  const Camera& cam = s.camera;
  const Eigen::Matrix3d rot = cam.view.block<3, 3>(0, 0);
  const Eigen::Vector3d eye = cam.eye(), viewDir = rot.transpose() * Eigen::Vector3d::UnitZ();
  const Eigen::Vector3d light = Eigen::Vector3d(-0.30, 0.45, 0.84).normalized();  // eye space: upper left, front
  const Eigen::Vector3d centroid =
      std::accumulate(m.vertices.begin(), m.vertices.end(), Eigen::Vector3d(Eigen::Vector3d::Zero())) / double(m.vertices.size());
  const auto corner = [&](std::size_t t, int k) -> const Eigen::Vector3d& { return m.vertices[std::size_t(m.triangles[t][std::size_t(k)])]; };

  // Flat shading per face: the triangles of one plane (neighbours whose normals agree to
  // rounding) take the normal of the first of them, so a face has one colour, exactly.
  std::vector<Eigen::Vector3d> normal(m.triangles.size(), Eigen::Vector3d::Zero());
  std::map<std::pair<int, int>, std::size_t> firstAtEdge;
  for (std::size_t t = 0; t < m.triangles.size(); ++t) {
    const Eigen::Vector3d n = (corner(t, 1) - corner(t, 0)).cross(corner(t, 2) - corner(t, 0));
    if (n.norm() > 0.0) normal[t] = n.normalized();
    for (int k = 0; k < 3; ++k) {
      const int u = m.triangles[t][std::size_t(k)], v = m.triangles[t][std::size_t((k + 1) % 3)];
      const auto [it, first] = firstAtEdge.emplace(std::make_pair(std::min(u, v), std::max(u, v)), t);
      if (!first && std::abs(normal[it->second].dot(normal[t])) > 1.0 - 1e-12) normal[t] = normal[it->second];
    }
  }
  struct Face {
    std::size_t t;
    double depth;  // eye-space z of the centre (more negative is farther)
    std::array<std::uint8_t, 4> color;
    bool front;
  };
  std::vector<Face> faces;
  for (std::size_t t = 0; t < m.triangles.size(); ++t) {
    if (normal[t].isZero()) continue;
    const Eigen::Vector3d centre = (corner(t, 0) + corner(t, 1) + corner(t, 2)) / 3.0;
    Eigen::Vector3d n = normal[t];
    if (n.dot(centre - centroid) < 0.0) n = -n;  // outward, for convex meshes
    const bool front = n.dot(cam.isOrthographic() ? viewDir : Eigen::Vector3d(eye - centre)) > 0.0;
    const double intensity = style::lightAmbient + style::lightDiffuse * std::max(0.0, (rot * (front ? n : -n)).dot(light));
    Color c = meshStyle.fill;
    if (meshStyle.lit) c = Color{std::min(1.0, c.r * intensity), std::min(1.0, c.g * intensity), std::min(1.0, c.b * intensity), c.a};
    faces.push_back(Face{t, (cam.view * centre.homogeneous()).z(), bytes(c), front});
  }
  const bool translucent = meshStyle.fill.a < 1.0;
  // A translucent mesh is blended back to front: its far side first, then its near side
  // (exact for a convex mesh), each from the farthest triangle on.
  if (translucent)
    std::stable_sort(faces.begin(), faces.end(), [](const Face& x, const Face& y) {
      return x.front != y.front ? y.front : x.depth < y.depth;
    });

  // Feature edges; those of a translucent mesh's far side go below its faces.
  std::vector<Eigen::Vector3d> backEdges, frontEdges;
  if (meshStyle.drawEdges && !meshStyle.edges.color.invisible()) {
    std::map<std::pair<int, int>, bool> seenFromFront;
    for (const Face& f : faces)
      for (int k = 0; k < 3; ++k) {
        const int u = m.triangles[f.t][std::size_t(k)], v = m.triangles[f.t][std::size_t((k + 1) % 3)];
        seenFromFront[{std::min(u, v), std::max(u, v)}] |= f.front;
      }
    for (const auto& [u, v] : featureEdges(m)) {
      auto& edges = seenFromFront[{u, v}] || !translucent ? frontEdges : backEdges;
      edges.push_back(m.vertices[std::size_t(u)]);
      edges.push_back(m.vertices[std::size_t(v)]);
    }
  }
  if (!backEdges.empty()) s.scene.push_back(segments(cam, backEdges, meshStyle.edges));
  detail::Batch3d triangles;
  triangles.depthWrite = !translucent;
  triangles.offset = (meshStyle.drawEdges ? 0.5 * meshStyle.edges.width : 0.0) + 1.0;
  for (const Face& f : faces) {
    for (int k = 0; k < 3; ++k) triangles.vertices.push_back(toClip(cam, corner(f.t, k)));
    triangles.colors.push_back(f.color);
  }
  s.scene.push_back(std::move(triangles));
  if (!frontEdges.empty()) s.scene.push_back(segments(cam, frontEdges, meshStyle.edges));
}

void Canvas::polygon3(const std::vector<Eigen::Vector3d>& points, const ShapeStyle& shape) {
  Impl& s = *impl_;
  s.require3d("polygon3");
  if (points.size() >= 3 && !shape.fill.invisible()) {
    detail::Batch3d fan;
    fan.depthWrite = shape.fill.a >= 1.0;
    fan.offset = 0.5 * shape.outline.width + 1.0;
    for (std::size_t i = 1; i + 1 < points.size(); ++i) {
      for (const auto* p : {&points[0], &points[i], &points[i + 1]}) fan.vertices.push_back(toClip(s.camera, *p));
      fan.colors.push_back(bytes(shape.fill));
    }
    s.scene.push_back(std::move(fan));
  }
  polyline3(points, shape.outline, true);
}

void Canvas::line3(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Stroke& stroke) {
  polyline3({a, b}, stroke, false);
}

void Canvas::polyline3(const std::vector<Eigen::Vector3d>& points, const Stroke& stroke, bool closed) {
  impl_->require3d("polyline3");
  if (points.size() < 2 || stroke.color.invisible() || !(stroke.width > 0.0)) return;
  std::vector<Eigen::Vector3d> ends;
  for (std::size_t i = 0; i + 1 < points.size(); ++i) ends.insert(ends.end(), {points[i], points[i + 1]});
  if (closed && points.size() > 2) ends.insert(ends.end(), {points.back(), points.front()});
  impl_->scene.push_back(segments(impl_->camera, ends, stroke));
}

void Canvas::point3(const Eigen::Vector3d& p, const Color& fill, double radiusPx, const Stroke& outline) {
  impl_->require3d("point3");
  Eigen::Vector2d c;
  if (onScreen(impl_->camera, impl_->plot, p, c))
    impl_->overlays.push_back([=](cairo_t* cr) { detail::disc(cr, c, radiusPx, fill, outline); });
}

void Canvas::arrow3(const Eigen::Vector3d& from, const Eigen::Vector3d& to, const Stroke& stroke, double headPx) {
  impl_->require3d("arrow3");
  Eigen::Vector2d a, b;
  if (onScreen(impl_->camera, impl_->plot, from, a) && onScreen(impl_->camera, impl_->plot, to, b))
    impl_->overlays.push_back([=](cairo_t* cr) { detail::arrowPath(cr, a, b, stroke, headPx); });
}

void Canvas::text3(const Eigen::Vector3d& p, const std::string& markup, const TextStyle& style, Anchor anchor,
                   const Eigen::Vector2d& offsetPx) {
  impl_->require3d("text3");
  Eigen::Vector2d q;
  if (onScreen(impl_->camera, impl_->plot, p, q)) impl_->queueLabel(q.x(), q.y(), markup, style, anchor, offsetPx);
}

}  // namespace gjkx::render
