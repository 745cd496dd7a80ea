// The 3D calls of the Canvas (the 3D figures of the paper): meshes, polygons and lines in
// space become the panel's scene, which OSMesa renders offscreen into an image that Cairo
// lays into the figure; points, arrows and labels in space are drawn by Cairo over it.
//
// The scene's pixels do not depend on the processor the rasteriser runs on: one colour per
// face (flat, no dithering), vertices snapped to a sixteenth of a sample (the rasteriser's
// fixed point rounds them all alike), supersampling averaged here, not by multisampling.
#include "internal.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <numeric>

#ifdef GJKX_HAVE_OSMESA
#define GL_GLEXT_PROTOTYPES
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <GL/glext.h>
#endif

namespace gjkx::render {

using detail::Batch3d;

namespace {

std::array<std::uint8_t, 4> bytes(const Color& c) {
  const auto byte = [](double v) { return std::uint8_t(std::lround(std::clamp(v, 0.0, 1.0) * 255.0)); };
  return {byte(c.r), byte(c.g), byte(c.b), byte(c.a)};
}

Eigen::Vector4d toClip(const Camera& camera, const Eigen::Vector3d& p) { return camera.projection * (camera.view * p.homogeneous()); }

// Line segments (pairs of points) of one stroke as a batch of the scene.
Batch3d segments(const Camera& camera, const std::vector<Eigen::Vector3d>& ends, const Stroke& stroke) {
  Batch3d b{true, {}, std::vector<std::array<std::uint8_t, 4>>(ends.size() / 2, bytes(stroke.color)), stroke.width};
  for (const auto& p : ends) b.vertices.push_back(toClip(camera, p));
  return b;
}

#ifndef GJKX_HAVE_OSMESA
constexpr bool kHaveOsmesa = false;
cairo_surface_t* renderScene(const std::vector<Batch3d>&, int, int) {
  throw std::runtime_error("this build of gjkx found no OSMesa: it draws no 3D figure");
}
#else
constexpr bool kHaveOsmesa = true;
cairo_surface_t* renderScene(const std::vector<Batch3d>& batches, int width, int height) {
  const int ss = style::supersample, w = width * ss, h = height * ss;
  const std::unique_ptr<osmesa_context, void (*)(OSMesaContext)> context(
      OSMesaCreateContextExt(OSMESA_BGRA, 24, 0, 0, nullptr), OSMesaDestroyContext);
  // BGRA bytes are Cairo's ARGB32 on a little-endian machine, and the blending below leaves
  // them premultiplied, as Cairo wants them. The first row is the top one, as in Cairo.
  std::vector<std::uint32_t> samples(std::size_t(w) * std::size_t(h));
  if (!context || !OSMesaMakeCurrent(context.get(), samples.data(), GL_UNSIGNED_BYTE, w, h))
    throw std::runtime_error("OSMesa: cannot render " + std::to_string(w) + " x " + std::to_string(h) + " pixels");
  OSMesaPixelStore(OSMESA_Y_UP, 0);
  glViewport(0, 0, w, h);
  glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LEQUAL);
  glEnable(GL_BLEND);
  glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
  glShadeModel(GL_FLAT);
  glDisable(GL_DITHER);
  const auto snap = [](double ndc, int size) { return std::round((ndc + 1.0) * 8.0 * size) / (8.0 * size) - 1.0; };
  for (const Batch3d& b : batches) {
    glDepthMask(b.depthWrite ? GL_TRUE : GL_FALSE);
    (b.offset > 0.0 ? glEnable : glDisable)(GL_POLYGON_OFFSET_FILL);
    glPolygonOffset(GLfloat(ss * b.offset), 4.0f);
    glLineWidth(GLfloat(ss * b.lineWidth));
    glBegin(b.lines ? GL_LINES : GL_TRIANGLES);
    for (std::size_t i = 0; i < b.vertices.size(); ++i) {
      const auto& c = b.colors[i / (b.lines ? 2 : 3)];
      glColor4ub(c[0], c[1], c[2], c[3]);
      const Eigen::Vector4d& v = b.vertices[i];  // in front of the eye: snapped, else left to GL's clipping
      if (v.w() > 0.0) glVertex4d(snap(v.x() / v.w(), w), snap(v.y() / v.w(), h), v.z() / v.w(), 1.0);
      else glVertex4d(v.x(), v.y(), v.z(), v.w());
    }
    glEnd();
  }
  glFinish();
  const bool failed = glGetError() != GL_NO_ERROR;
  OSMesaMakeCurrent(nullptr, nullptr, 0, 0, 0);
  if (failed) throw std::runtime_error("OSMesa: OpenGL failed to render a 3D scene");
  // Each ss x ss block of samples averaged into one pixel, channel by channel.
  cairo_surface_t* out = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, width, height);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      std::uint32_t sum[4] = {0, 0, 0, 0}, pixel = 0;
      for (int k = 0; k < ss * ss; ++k)
        for (int c = 0; c < 4; ++c) sum[c] += samples[std::size_t(y * ss + k / ss) * std::size_t(w) + std::size_t(x * ss + k % ss)] >> (8 * c) & 0xFFu;
      for (int c = 0; c < 4; ++c) pixel |= (sum[c] + ss * ss / 2) / (ss * ss) << (8 * c);
      reinterpret_cast<std::uint32_t*>(cairo_image_surface_get_data(out) + std::ptrdiff_t(y) * cairo_image_surface_get_stride(out))[x] = pixel;
    }
  cairo_surface_mark_dirty(out);
  return out;
}
#endif

// Where a 3D point appears on the canvas, if it is in front of the eye.
bool onScreen(const Canvas::Impl& s, const Eigen::Vector3d& p, Eigen::Vector2d& pixel) {
  const Eigen::Vector4d c = toClip(s.camera, p);
  pixel = Eigen::Vector2d(s.plot.x + 0.5 * (c.x() / c.w() + 1.0) * s.plot.width, s.plot.y + 0.5 * (1.0 - c.y() / c.w()) * s.plot.height);
  return c.w() > 0.0;
}

}  // namespace

bool canDraw3d() { return kHaveOsmesa; }

void Canvas::Impl::flush3d() {
  if (scene.empty()) return;
  // The camera maps NDC [-1, 1] to the plot area; the scene covers the whole clip rectangle
  // (a floor may run to the panel's edges), so clip space is mapped to it.
  const double sx = double(plot.width) / clip.width, tx = double(plot.width + 2 * (plot.x - clip.x)) / clip.width - 1.0;
  const double sy = double(plot.height) / clip.height, ty = 1.0 - double(plot.height + 2 * (plot.y - clip.y)) / clip.height;
  for (auto& batch : scene)
    for (auto& v : batch.vertices) v = Eigen::Vector4d(sx * v.x() + tx * v.w(), sy * v.y() + ty * v.w(), v.z(), v.w());
  cairo_surface_t* image = renderScene(scene, clip.width, clip.height);
  scene.clear();
  cairo_set_source_surface(cr, image, clip.x, clip.y);  // the image is the clip rectangle
  cairo_paint(cr);
  cairo_surface_destroy(image);
}

void Canvas::setCamera(const Camera& camera) {
  impl_->flush3d();
  impl_->camera = camera;
  impl_->has3d = true;
}

void Canvas::mesh(const Mesh& m, const MeshStyle& meshStyle) {
  Impl& s = *impl_;
  s.require3d("mesh");
  const int count = int(m.vertices.size());
  for (std::size_t t = 0; t < m.triangles.size(); ++t)
    for (int i : m.triangles[t])
      if (i < 0 || i >= count)
        throw std::invalid_argument("Canvas::mesh: triangle " + std::to_string(t) + " refers to vertex " + std::to_string(i) + " of " + std::to_string(count));
  if (m.vertices.empty()) return;
  const Camera& cam = s.camera;
  const Eigen::Matrix3d rot = cam.view.block<3, 3>(0, 0);
  const Eigen::Vector3d eye = cam.eye(), lightDir = Eigen::Vector3d(-0.30, 0.45, 0.84).normalized();  // eye space: upper left, front
  const Eigen::Vector3d centroid = std::accumulate(m.vertices.begin(), m.vertices.end(), Eigen::Vector3d(Eigen::Vector3d::Zero())) / count;
  const auto corner = [&](std::size_t t, int k) -> const Eigen::Vector3d& { return m.vertices[std::size_t(m.triangles[t][std::size_t(k)])]; };
  const auto edgeOf = [&](std::size_t t, int k) {
    const int u = m.triangles[t][std::size_t(k)], v = m.triangles[t][std::size_t((k + 1) % 3)];
    return std::make_pair(std::min(u, v), std::max(u, v));
  };
  // Each edge (smaller, larger vertex) with its triangles and their normals, oriented so
  // that two consistently wound triangles of a flat face give the same one.
  std::vector<Eigen::Vector3d> raw(m.triangles.size(), Eigen::Vector3d::Zero());
  std::map<std::pair<int, int>, std::vector<std::pair<std::size_t, Eigen::Vector3d>>> edges;
  for (std::size_t t = 0; t < m.triangles.size(); ++t) {
    const Eigen::Vector3d n = (corner(t, 1) - corner(t, 0)).cross(corner(t, 2) - corner(t, 0));
    if (n.norm() > 0.0) raw[t] = n.normalized();
    for (int k = 0; k < 3; ++k)
      if (edgeOf(t, k).first != edgeOf(t, k).second)
        edges[edgeOf(t, k)].emplace_back(t, edgeOf(t, k).first == m.triangles[t][std::size_t(k)] ? raw[t] : Eigen::Vector3d(-raw[t]));
  }
  // Flat shading per face: the triangles of one plane (neighbours whose normals agree to
  // rounding) take the normal of the first of them, so that a face has one colour, exactly.
  std::vector<Eigen::Vector3d> normal = raw;
  for (std::size_t t = 0; t < m.triangles.size(); ++t)
    for (int k = 0; k < 3; ++k)
      if (const auto at = edges.find(edgeOf(t, k)); at != edges.end() && std::abs(raw[at->second.front().first].dot(raw[t])) > 1.0 - 1e-12)
        normal[t] = normal[at->second.front().first];
  struct Face {
    std::size_t t;
    double depth;  // eye-space z of the centre (more negative is farther)
    std::array<std::uint8_t, 4> color;
    bool front;
  };
  std::vector<Face> faces;
  std::map<std::pair<int, int>, bool> seenFromFront;
  for (std::size_t t = 0; t < m.triangles.size(); ++t) {
    if (normal[t].isZero()) continue;
    const Eigen::Vector3d centre = (corner(t, 0) + corner(t, 1) + corner(t, 2)) / 3.0;
    const Eigen::Vector3d n = normal[t].dot(centre - centroid) < 0.0 ? Eigen::Vector3d(-normal[t]) : normal[t];  // outward (convex)
    const bool front = n.dot(eye - centre) > 0.0;
    const double light = style::lightAmbient + style::lightDiffuse * std::max(0.0, (rot * (front ? n : -n)).dot(lightDir));
    const Color& f = meshStyle.fill;
    const Color c = meshStyle.lit ? Color{std::min(1.0, f.r * light), std::min(1.0, f.g * light), std::min(1.0, f.b * light), f.a} : f;
    faces.push_back(Face{t, (cam.view * centre.homogeneous()).z(), bytes(c), front});
    for (int k = 0; k < 3; ++k) seenFromFront[edgeOf(t, k)] |= front;
  }
  // A translucent mesh is blended back to front: its far side first, then its near side
  // (exact for a convex mesh), each from the farthest triangle on.
  const bool translucent = meshStyle.fill.a < 1.0;
  if (translucent)
    std::stable_sort(faces.begin(), faces.end(), [](const Face& x, const Face& y) { return x.front != y.front ? y.front : x.depth < y.depth; });
  // Feature edges: of one triangle, or where two meet at more than a degree (not the
  // diagonals of flat faces). Those of a translucent mesh's far side go below its faces.
  std::vector<Eigen::Vector3d> backEdges, frontEdges;
  for (const auto& [edge, at] : edges)
    if (meshStyle.drawEdges && !meshStyle.edges.color.invisible() && (at.size() != 2 || -at[0].second.dot(at[1].second) < std::cos(M_PI / 180.0)))
      for (int u : {edge.first, edge.second}) (seenFromFront[edge] || !translucent ? frontEdges : backEdges).push_back(m.vertices[std::size_t(u)]);
  if (!backEdges.empty()) s.scene.push_back(segments(cam, backEdges, meshStyle.edges));
  Batch3d triangles{false, {}, {}, 1.0, !translucent, (meshStyle.drawEdges ? 0.5 * meshStyle.edges.width : 0.0) + 1.0};
  for (const Face& f : faces) {
    for (int k = 0; k < 3; ++k) triangles.vertices.push_back(toClip(cam, corner(f.t, k)));
    triangles.colors.push_back(f.color);
  }
  s.scene.push_back(std::move(triangles));
  if (!frontEdges.empty()) s.scene.push_back(segments(cam, frontEdges, meshStyle.edges));
}

void Canvas::polygon3(const std::vector<Eigen::Vector3d>& points, const ShapeStyle& shape) {
  impl_->require3d("polygon3");
  if (points.size() >= 3 && !shape.fill.invisible()) {
    Batch3d fan{false, {}, {}, 1.0, shape.fill.a >= 1.0, 0.5 * shape.outline.width + 1.0};
    for (std::size_t i = 1; i + 1 < points.size(); ++i) {
      for (const auto* p : {&points[0], &points[i], &points[i + 1]}) fan.vertices.push_back(toClip(impl_->camera, *p));
      fan.colors.push_back(bytes(shape.fill));
    }
    impl_->scene.push_back(std::move(fan));
  }
  polyline3(points, shape.outline, true);
}

void Canvas::line3(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Stroke& stroke) { polyline3({a, b}, stroke, false); }

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
  if (onScreen(*impl_, p, c)) impl_->onTop(impl_->overlays, [=](cairo_t* cr) { detail::disc(cr, c, radiusPx, fill, outline); });
}

void Canvas::arrow3(const Eigen::Vector3d& from, const Eigen::Vector3d& to, const Stroke& stroke, double headPx) {
  impl_->require3d("arrow3");
  Eigen::Vector2d a, b;
  if (onScreen(*impl_, from, a) && onScreen(*impl_, to, b))
    impl_->onTop(impl_->overlays, [=](cairo_t* cr) { detail::arrowPath(cr, a, b, stroke, headPx); });
}

void Canvas::text3(const Eigen::Vector3d& p, const std::string& markup, const TextStyle& style, Anchor anchor,
                   const Eigen::Vector2d& offsetPx) {
  impl_->require3d("text3");
  Eigen::Vector2d q;
  if (onScreen(*impl_, p, q)) impl_->queueLabel(q, markup, style, anchor, offsetPx);
}

}  // namespace gjkx::render
