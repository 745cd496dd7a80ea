// The bodies of a scene as gjkx_animate draws them: each body's surface in its shape's own
// frame (the frame whose origin bodies.csv gives), its colour, and one frame of a run drawn
// in 3D through a camera (OSMesa) or in 2D as a projection on a coordinate plane (Cairo).
#pragma once

#include "../shape_meshes.hpp"
#include "scene_run.hpp"

#include <gjkx/mesh/triangle_mesh.hpp>
#include <gjkx/render/canvas.hpp>
#include <gjkx/support_mapping/polytope.hpp>
#include <gjkx/timewarp/body.hpp>
#include <gjkx/timewarp/scene.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace animation {

using gjkx::render::Color;
using V3 = Eigen::Vector3d;

/// What a body looks like: its surface in its shape's frame, and its colour.
struct BodyLook {
  gjkx::render::Mesh surface;  ///< vertices in the shape's frame
  Color color;                 ///< its faces' colour
  bool isStatic = false;       ///< a static body (drawn light, left out of the framing)
  bool isConvex = true;        ///< one convex piece (its 2D outline is its hull's)
};

/// The surface of a scene's shape in its own frame: a box or polytope as its hull, a sphere,
/// capsule or cylinder as the hull of its support points (shape_meshes.hpp), a mesh as its
/// file gives it, read as the world reads it (node transforms applied, then the scale).
/// Throws std::runtime_error naming the body if its shape cannot be made or read.
inline gjkx::render::Mesh surfaceOf(const gjkx::Scene& scene, const gjkx::BodySpec& body) {
  const gjkx::ShapeSpec& spec = body.shape;
  try {
    if (spec.kind == gjkx::ShapeSpec::Kind::Mesh) {
      const std::string path = !spec.meshPath.empty() && spec.meshPath[0] == '/' ? spec.meshPath : scene.folder + "/" + spec.meshPath;
      const gjkx::TriangleMesh mesh = gjkx::readMesh(path, gjkx::MeshRequirements{false, true});
      gjkx::render::Mesh out{{}, mesh.triangles};
      for (const V3& v : mesh.vertices) out.vertices.push_back(v.cwiseProduct(spec.meshScale));
      return out;
    }
    if (spec.kind == gjkx::ShapeSpec::Kind::Polytope) return chapter::meshOf(gjkx::Polytope<double>::hull(spec.points));
    if (spec.kind == gjkx::ShapeSpec::Kind::Box) {
      std::vector<V3> corners;
      for (int k = 0; k < 8; ++k)
        corners.push_back(spec.halfExtents.cwiseProduct(V3(k & 1 ? 1 : -1, k & 2 ? 1 : -1, k & 4 ? 1 : -1)));
      return chapter::meshOf(gjkx::Polytope<double>::hull(corners));
    }
    return chapter::meshFromSupport(gjkx::convexShapeOf<double>(spec, spec.points), 400);
  } catch (const std::exception& e) {
    throw std::runtime_error(scene.source + ": body '" + body.name + "': cannot draw its shape: " + e.what());
  }
}

/// Colours of the moving bodies, in turn: soft, told apart on white and in grey.
inline const std::vector<Color>& bodyColors() {
  static const std::vector<Color> colors = {Color::hex(0x7FA7D9), Color::hex(0xE8A27C), Color::hex(0x8CC084),
                                            Color::hex(0xD9C27F), Color::hex(0xB39DD6), Color::hex(0x7CC4C4)};
  return colors;
}

/// The look of every body of `scene`. A body's colour is the first of `colors` (a name
/// prefix and its colour; the prefix "*" matches every body) whose prefix begins its name;
/// else light grey for a static body and bodyColors() in turn for the moving ones.
inline std::vector<BodyLook> looksOf(const gjkx::Scene& scene, const std::vector<std::pair<std::string, Color>>& colors) {
  std::vector<BodyLook> looks;
  std::map<std::string, gjkx::render::Mesh> read;  // a mesh file used by many bodies is read once
  int moving = 0;
  for (const gjkx::BodySpec& b : scene.bodies) {
    BodyLook look;
    look.isStatic = b.isStatic;
    look.isConvex = b.shape.kind != gjkx::ShapeSpec::Kind::Mesh || b.shape.meshCollision == gjkx::ShapeSpec::MeshCollision::Hull;
    if (b.shape.kind == gjkx::ShapeSpec::Kind::Mesh) {
      std::ostringstream key;
      key << b.shape.meshPath << '|' << b.shape.meshScale.transpose();
      auto found = read.find(key.str());
      if (found == read.end()) found = read.emplace(key.str(), surfaceOf(scene, b)).first;
      look.surface = found->second;
    } else {
      look.surface = surfaceOf(scene, b);
    }
    look.color = b.isStatic ? Color::hex(0xDADADA) : bodyColors()[std::size_t(moving) % bodyColors().size()];
    if (!b.isStatic) ++moving;
    for (const auto& [prefix, color] : colors)
      if (prefix == "*" || b.name.rfind(prefix, 0) == 0) {
        look.color = color;
        break;
      }
    looks.push_back(std::move(look));
  }
  return looks;
}

/// A body's surface placed at `position` and `orientation` (of its shape's frame).
inline gjkx::render::Mesh placed(const gjkx::render::Mesh& surface, const V3& position, const Eigen::Quaterniond& orientation) {
  gjkx::render::Mesh out{{}, surface.triangles};
  out.vertices.reserve(surface.vertices.size());
  for (const V3& v : surface.vertices) out.vertices.push_back(orientation * v + position);
  return out;
}

/// How the frames are seen: in 3D from a camera on a sphere around the framed box, or in
/// 2D projected on a coordinate plane (x right and y up for "xy", x and z for "xz", y and z
/// for "yz").
struct View {
  std::string kind = "3d";   ///< "3d", "xy", "xz" or "yz"
  double azimuth = -0.9;     ///< 3D: radians about z from the x axis
  double elevation = 0.35;   ///< 3D: radians above the horizon
  double zoom = 1;           ///< > 1 comes closer
  V3 lo = V3::Zero(), hi = V3::Zero();  ///< the framed box
  /// The two world axes of a 2D view (x right, y up on screen).
  std::pair<int, int> axes() const { return kind == "xy" ? std::pair{0, 1} : kind == "xz" ? std::pair{0, 2} : std::pair{1, 2}; }
};

/// The box that frames the moving bodies of `frames`: per axis, the range their vertices
/// cover once the bodies farthest out (a tenth at each end, when there are ten or more) are
/// left out, so that a few bodies thrown far do not shrink the rest to specks. Static bodies
/// are framed only when nothing moves.
inline std::pair<V3, V3> framing(const std::vector<BodyLook>& looks, const std::vector<RunFrame>& frames) {
  bool anyMoving = false;
  for (const BodyLook& l : looks) anyMoving = anyMoving || !l.isStatic;
  V3 lo = V3::Constant(1e300), hi = V3::Constant(-1e300);
  for (const RunFrame& f : frames) {
    std::vector<std::pair<V3, V3>> boxes;
    for (std::size_t b = 0; b < looks.size(); ++b) {
      if (anyMoving && looks[b].isStatic) continue;
      V3 blo = V3::Constant(1e300), bhi = V3::Constant(-1e300);
      for (const V3& v : looks[b].surface.vertices) {
        const V3 p = f.orientation[b] * v + f.position[b];
        blo = blo.cwiseMin(p);
        bhi = bhi.cwiseMax(p);
      }
      boxes.emplace_back(blo, bhi);
    }
    const std::size_t cut = boxes.size() >= 10 ? boxes.size() / 10 : 0;
    for (int axis = 0; axis < 3; ++axis) {
      std::vector<double> low, high;
      for (const auto& [a, b] : boxes) {
        low.push_back(a[axis]);
        high.push_back(b[axis]);
      }
      std::sort(low.begin(), low.end());
      std::sort(high.begin(), high.end());
      lo[axis] = std::min(lo[axis], low[cut]);
      hi[axis] = std::max(hi[axis], high[high.size() - 1 - cut]);
    }
  }
  return {lo, hi};
}

/// Sets the current panel of `canvas` to see the world as `view` does: a camera (3D), or a
/// world window on the view's plane with drawing clipped to the plot area (2D).
inline void setView(gjkx::render::Canvas& canvas, const View& view) {
  using namespace gjkx::render;
  const V3 center = 0.5 * (view.lo + view.hi);
  if (view.kind == "3d") {
    const double radius = std::max(0.5 * (view.hi - view.lo).norm(), 1e-6) / view.zoom;
    canvas.setCamera(Camera::orbit(center, radius, view.azimuth, view.elevation, 0.6, canvas.plotAspect()));
    canvas.setClip(canvas.plotArea());
    return;
  }
  const auto [u, w] = view.axes();
  const double hu = std::max(0.5 * (view.hi[u] - view.lo[u]), 1e-6) * 1.08 / view.zoom;
  const double hw = std::max(0.5 * (view.hi[w] - view.lo[w]), 1e-6) * 1.08 / view.zoom;
  canvas.setWorldWindow(center[u] - hu, center[u] + hu, center[w] - hw, center[w] + hw);
  canvas.setClip(canvas.plotArea());
}

/// The convex hull of points in the plane, counter-clockwise (Andrew's monotone chain):
/// the outline of a convex body's projection.
inline std::vector<Eigen::Vector2d> hull2d(std::vector<Eigen::Vector2d> p) {
  if (p.size() < 3) return p;
  std::sort(p.begin(), p.end(), [](const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
    return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y());
  });
  const auto cross = [](const Eigen::Vector2d& o, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
    return (a.x() - o.x()) * (b.y() - o.y()) - (a.y() - o.y()) * (b.x() - o.x());
  };
  std::vector<Eigen::Vector2d> h(2 * p.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {  // lower hull
    while (k >= 2 && cross(h[k - 2], h[k - 1], p[i]) <= 0) --k;
    h[k++] = p[i];
  }
  for (std::size_t i = p.size() - 1, t = k + 1; i-- > 0;) {  // upper hull
    while (k >= t && cross(h[k - 2], h[k - 1], p[i]) <= 0) --k;
    h[k++] = p[i];
  }
  h.resize(k > 1 ? k - 1 : k);
  return h;
}

/// Draws one body with the look `look` at `position` and `orientation` (of its shape's
/// frame) as `view` sees it (setView first), filled with `fill` (translucent if its alpha is
/// below 1) and outlined in `edge`.
inline void drawBody(gjkx::render::Canvas& canvas, const BodyLook& look, const V3& position, const Eigen::Quaterniond& orientation,
                     const View& view, const Color& fill, const Color& edge) {
  using namespace gjkx::render;
  const Mesh m = placed(look.surface, position, orientation);
  if (view.kind == "3d") {
    canvas.mesh(m, MeshStyle{fill, Stroke{edge, 0.6}, look.isConvex, true});
    return;
  }
  const auto [u, w] = view.axes();
  if (look.isConvex) {  // the outline of its projection: the hull of its projected vertices
    std::vector<Eigen::Vector2d> flat;
    for (const V3& v : m.vertices) flat.emplace_back(v[u], v[w]);
    canvas.polygon(hull2d(flat), ShapeStyle{fill, Stroke{edge, 1.3}});
    return;
  }
  for (const auto& t : m.triangles)
    canvas.polygon({{m.vertices[t[0]][u], m.vertices[t[0]][w]}, {m.vertices[t[1]][u], m.vertices[t[1]][w]},
                    {m.vertices[t[2]][u], m.vertices[t[2]][w]}},
                   ShapeStyle{fill, style::noStroke});
}

/// The middle of a body's top as `view` sees it (2D: the top of its projection; 3D: above
/// its vertices' mean by its highest z): where its label goes.
inline V3 topOf(const BodyLook& look, const V3& position, const Eigen::Quaterniond& orientation, const View& view) {
  const int up = view.kind == "xy" ? 1 : 2;
  double best = -1e300;
  V3 center = V3::Zero();
  for (const V3& v : look.surface.vertices) {
    const V3 p = orientation * v + position;
    best = std::max(best, p[up]);
    center += p;
  }
  center /= double(std::max<std::size_t>(1, look.surface.vertices.size()));
  center[up] = best;
  return center;
}

/// Draws the bodies at `frame` in the current panel of `canvas` as `view` sees them.
inline void drawFrame(gjkx::render::Canvas& canvas, const std::vector<BodyLook>& looks, const RunFrame& frame, const View& view) {
  setView(canvas, view);
  for (std::size_t b = 0; b < looks.size(); ++b)
    drawBody(canvas, looks[b], frame.position[b], frame.orientation[b], view, looks[b].color,
             view.kind == "3d" ? gjkx::render::palette::ink : mix(looks[b].color, gjkx::render::palette::ink, 0.6));
}

}  // namespace animation
