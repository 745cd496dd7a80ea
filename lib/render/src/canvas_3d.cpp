// The 3D drawing calls of the Canvas: flat-shaded meshes, lines, points,
// arrows and labels seen through the Camera of a panel (3D figures of the paper).
#include "canvas_impl.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <map>
#include <numeric>
#include <stdexcept>

namespace gjkx::render {

namespace {

using detail::ScreenPoint;

// Overlays (points, arrow heads) are pulled this fraction of their distance
// towards the eye so that they are not hidden by the surface they lie on.
constexpr double kOverlayBias = 0.01;

// Distance of a clip-space point from the near plane (>= 0: in front of it).
double nearDistance(const Eigen::Vector4d& c) { return c.z() + c.w(); }

// Sutherland-Hodgman clipping of a polygon against the near plane.
std::vector<Eigen::Vector4d> clipNear(const std::vector<Eigen::Vector4d>& poly) {
  std::vector<Eigen::Vector4d> out;
  for (std::size_t i = 0; i < poly.size(); ++i) {
    const Eigen::Vector4d& a = poly[i];
    const Eigen::Vector4d& b = poly[(i + 1) % poly.size()];
    const double da = nearDistance(a), db = nearDistance(b);
    if (da >= 0.0) out.push_back(a);
    if ((da >= 0.0) != (db >= 0.0)) out.push_back(a + (b - a) * (da / (da - db)));
  }
  return out;
}

}  // namespace

void Canvas::Impl::require3d(const char* what) const {
  if (!has3d) throw std::logic_error(std::string("Canvas::") + what + ": call setCamera() for the panel first");
}

void Canvas::setCamera(const Camera& camera) {
  impl_->camera = camera;
  impl_->has3d = true;
}

const Camera& Canvas::camera() const {
  impl_->require3d("camera");
  return impl_->camera;
}

namespace {

// Clip coordinates of p, optionally pulled towards the eye (see kOverlayBias).
Eigen::Vector4d toClip(const Camera& cam, const Eigen::Vector3d& p, double bias) {
  Eigen::Vector4d eye = cam.view * p.homogeneous();
  if (bias > 0.0) {
    if (cam.isOrthographic()) eye.z() += bias * 2.0 / std::abs(cam.projection(2, 2));
    else eye.head<3>() *= (1.0 - bias);
  }
  return cam.projection * eye;
}

ScreenPoint toScreenFromClip(const PixelRect& plot, const Eigen::Vector4d& c) {
  const Eigen::Vector3d ndc = c.head<3>() / c.w();
  return ScreenPoint{plot.x + 0.5 * (ndc.x() + 1.0) * plot.width, plot.y + 0.5 * (1.0 - ndc.y()) * plot.height,
                     ndc.z()};
}

}  // namespace

Eigen::Vector3d Canvas::project(const Eigen::Vector3d& p) const {
  impl_->require3d("project");
  const ScreenPoint s = toScreenFromClip(impl_->plot, toClip(impl_->camera, p, 0.0));
  return Eigen::Vector3d(s.x, s.y, s.z);
}

void Canvas::mesh(const Mesh& m, const MeshStyle& meshStyle) {
  Impl& s = *impl_;
  s.require3d("mesh");
  validateMesh(m);
  if (m.vertices.empty() || m.triangles.empty()) return;
  const Camera& cam = s.camera;
  const bool ortho = cam.isOrthographic();
  const Eigen::Matrix3d rot = cam.view.block<3, 3>(0, 0);
  const Eigen::Vector3d eye = cam.eye(), viewDir = rot.transpose() * Eigen::Vector3d::UnitZ();
  const Eigen::Vector3d light = Eigen::Vector3d(-0.30, 0.45, 0.84).normalized();  // eye space: upper left, front
  const Eigen::Vector3d centroid =
      std::accumulate(m.vertices.begin(), m.vertices.end(), Eigen::Vector3d(Eigen::Vector3d::Zero())) /
      static_cast<double>(m.vertices.size());

  struct Face {
    std::vector<ScreenPoint> tris;
    Color color;
    double depth;  // eye-space z of the centroid (more negative is farther)
  };
  std::vector<Face> faces;
  std::vector<bool> front(m.triangles.size(), false);
  for (std::size_t t = 0; t < m.triangles.size(); ++t) {
    const auto& tri = m.triangles[t];
    const Eigen::Vector3d& a = m.vertices[static_cast<std::size_t>(tri[0])];
    const Eigen::Vector3d& b = m.vertices[static_cast<std::size_t>(tri[1])];
    const Eigen::Vector3d& c = m.vertices[static_cast<std::size_t>(tri[2])];
    Eigen::Vector3d n = (b - a).cross(c - a);
    if (!(n.norm() > 0.0)) continue;
    n.normalize();
    const Eigen::Vector3d center = (a + b + c) / 3.0;
    if (n.dot(center - centroid) < 0.0) n = -n;  // outward for convex meshes
    front[t] = n.dot(ortho ? viewDir : Eigen::Vector3d(eye - center)) > 0.0;
    const Eigen::Vector3d towardsViewer = front[t] ? n : Eigen::Vector3d(-n);
    const double intensity =
        style::lightAmbient + style::lightDiffuse * std::max(0.0, (rot * towardsViewer).dot(light));
    Color color = meshStyle.fill;
    if (meshStyle.lit) {
      color.r = std::min(1.0, color.r * intensity);
      color.g = std::min(1.0, color.g * intensity);
      color.b = std::min(1.0, color.b * intensity);
    }
    const std::vector<Eigen::Vector4d> poly =
        clipNear({toClip(cam, a, 0.0), toClip(cam, b, 0.0), toClip(cam, c, 0.0)});
    if (poly.size() < 3) continue;
    Face f{{}, color, (cam.view * center.homogeneous()).z()};
    for (std::size_t i = 1; i + 1 < poly.size(); ++i)
      for (const Eigen::Vector4d* v : {&poly[0], &poly[i], &poly[i + 1]}) f.tris.push_back(toScreenFromClip(s.plot, *v));
    faces.push_back(std::move(f));
  }
  const bool translucent = meshStyle.fill.a < 1.0;
  if (translucent)
    std::stable_sort(faces.begin(), faces.end(), [](const Face& x, const Face& y) { return x.depth < y.depth; });

  // Feature edges; for translucent meshes the hidden ones go below the faces.
  std::vector<std::pair<int, int>> backEdges, frontEdges;
  if (meshStyle.drawEdges && !meshStyle.edges.color.invisible()) {
    std::map<std::pair<int, int>, bool> seenFromFront;
    for (std::size_t t = 0; t < m.triangles.size(); ++t)
      for (int k = 0; k < 3; ++k) {
        const int u = m.triangles[t][static_cast<std::size_t>(k)], v = m.triangles[t][static_cast<std::size_t>((k + 1) % 3)];
        bool& f = seenFromFront[{std::min(u, v), std::max(u, v)}];
        f = f || front[t];
      }
    for (const auto& e : featureEdges(m)) (seenFromFront[e] || !translucent ? frontEdges : backEdges).push_back(e);
  }
  const auto drawEdges = [&](const std::vector<std::pair<int, int>>& edges) {
    for (const auto& [u, v] : edges)
      line3(m.vertices[static_cast<std::size_t>(u)], m.vertices[static_cast<std::size_t>(v)], meshStyle.edges);
  };
  drawEdges(backEdges);

  std::vector<ScreenPoint> tris;
  std::vector<Color> colors;
  for (const Face& f : faces) {
    tris.insert(tris.end(), f.tris.begin(), f.tris.end());
    colors.insert(colors.end(), f.tris.size() / 3, f.color);
  }
  s.beginPrimitive(true, !translucent);
  // Push the faces back so edges (half their width beside the true edge) stay visible.
  const double edgeWidth = meshStyle.drawEdges ? meshStyle.edges.width : 0.0;
  glEnable(GL_POLYGON_OFFSET_FILL);
  glPolygonOffset(static_cast<GLfloat>(s.ss * (0.5 * edgeWidth + 1.0)), 4.0f);
  s.emitTrianglesColored(tris, colors);
  glDisable(GL_POLYGON_OFFSET_FILL);

  drawEdges(frontEdges);
}

void Canvas::polygon3(const std::vector<Eigen::Vector3d>& points, const ShapeStyle& shape) {
  Impl& s = *impl_;
  s.require3d("polygon3");
  std::vector<Eigen::Vector4d> clip;
  for (const auto& p : points) clip.push_back(toClip(s.camera, p, 0.0));
  const std::vector<Eigen::Vector4d> poly = clipNear(clip);
  std::vector<ScreenPoint> screen;
  for (const auto& c : poly) screen.push_back(toScreenFromClip(s.plot, c));
  if (screen.size() >= 3 && !shape.fill.invisible()) {
    std::vector<ScreenPoint> fan;
    for (std::size_t i = 1; i + 1 < screen.size(); ++i) fan.insert(fan.end(), {screen[0], screen[i], screen[i + 1]});
    s.beginPrimitive(true, shape.fill.a >= 1.0);
    glEnable(GL_POLYGON_OFFSET_FILL);
    glPolygonOffset(static_cast<GLfloat>(s.ss * (0.5 * shape.outline.width + 1.0)), 4.0f);
    s.emitTriangles(fan, shape.fill);
    glDisable(GL_POLYGON_OFFSET_FILL);
  }
  polyline3(points, shape.outline, true);
}

void Canvas::line3(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Stroke& stroke) {
  polyline3({a, b}, stroke, false);
}

void Canvas::polyline3(const std::vector<Eigen::Vector3d>& points, const Stroke& stroke, bool closed) {
  Impl& s = *impl_;
  s.require3d("polyline3");
  if (points.empty()) return;
  std::vector<Eigen::Vector4d> clip;
  for (const auto& p : points) clip.push_back(toClip(s.camera, p, 0.0));
  if (closed && clip.size() > 2) clip.push_back(clip.front());
  // Runs of the polyline in front of the near plane, cut where it crosses it.
  std::vector<ScreenPoint> run;
  const auto flush = [&]() {
    if (!run.empty()) s.strokePath(run, false, stroke, true);
    run.clear();
  };
  if (clip.size() == 1) {
    if (nearDistance(clip[0]) >= 0.0) s.strokePath({toScreenFromClip(s.plot, clip[0])}, false, stroke, true);
    return;
  }
  for (std::size_t i = 0; i + 1 < clip.size(); ++i) {
    Eigen::Vector4d a = clip[i], b = clip[i + 1];
    const double da = nearDistance(a), db = nearDistance(b);
    if (da < 0.0 && db < 0.0) {
      flush();
      continue;
    }
    if (da < 0.0) a = a + (b - a) * (da / (da - db));
    if (db < 0.0) b = a + (b - a) * (nearDistance(a) / (nearDistance(a) - db));
    if (run.empty() || da < 0.0) {
      flush();
      run.push_back(toScreenFromClip(s.plot, a));
    }
    run.push_back(toScreenFromClip(s.plot, b));
    if (db < 0.0) flush();
  }
  flush();
}

void Canvas::point3(const Eigen::Vector3d& p, const Color& fill, double radiusPx, const Stroke& outline) {
  Impl& s = *impl_;
  s.require3d("point3");
  const Eigen::Vector4d c = toClip(s.camera, p, kOverlayBias);
  if (nearDistance(c) < 0.0) return;
  s.disc(toScreenFromClip(s.plot, c), radiusPx, fill, outline, true);
}

void Canvas::arrow3(const Eigen::Vector3d& from, const Eigen::Vector3d& to, const Stroke& stroke, double headPx) {
  Impl& s = *impl_;
  s.require3d("arrow3");
  Eigen::Vector4d a = toClip(s.camera, from, 0.2 * kOverlayBias), b = toClip(s.camera, to, kOverlayBias);
  const double da = nearDistance(a), db = nearDistance(b);
  if (da < 0.0 && db < 0.0) return;
  if (db < 0.0) {  // the tip is behind the eye: only the visible part of the shaft
    line3(from, to, stroke);
    return;
  }
  if (da < 0.0) a = a + (b - a) * (da / (da - db));
  s.arrowPath(toScreenFromClip(s.plot, a), toScreenFromClip(s.plot, b), stroke, headPx, true);
}

void Canvas::text3(const Eigen::Vector3d& p, const std::string& markup, const TextStyle& style, Anchor anchor,
                   const Eigen::Vector2d& offsetPx) {
  Impl& s = *impl_;
  s.require3d("text3");
  const Eigen::Vector4d c = toClip(s.camera, p, 0.0);
  if (nearDistance(c) < 0.0 || c.w() <= 0.0) return;
  const ScreenPoint q = toScreenFromClip(s.plot, c);
  s.queueLabel(q.x, q.y, markup, style, anchor, offsetPx);
}

}  // namespace gjkx::render
