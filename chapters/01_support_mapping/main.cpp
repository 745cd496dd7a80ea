// Chapter 01: support mappings (§2.1).
//
// "For a convex polyhedron X and a vector s, assume there exists a routine S_X(s) that
// returns the supporting vertex of X in the direction s." Every shape of the library
// is such a routine. This chapter draws two figures:
//   support-mapping-shapes.png:        the supporting vertex of six shapes in three
//                                      directions, with the supporting plane there;
//   support-mapping-hill-climbing.png: hill climbing on a polytope of 300 vertices,
//                                      from a cold start and from a warm-start hint.
// A curved shape is drawn from its support mapping alone: the hull of its support
// points over many directions. --direction and --vertices change the hill climb's query,
// and --trace prints the climbs vertex by vertex (docs/traces.md).
#include "../chapter.hpp"
#include "../shape_meshes.hpp"

#include <gjkx/render/canvas.hpp>
#include <gjkx/support_mapping/placed.hpp>
#include <gjkx/support_mapping/shape.hpp>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <random>
#include <string>
#include <vector>

using namespace gjkx;
using namespace gjkx::render;
using V = Vector3<double>;

namespace {

using chapter::meshFromSupport;
using chapter::meshOf;

// A small square of the supporting plane through x, normal to s.
std::vector<Eigen::Vector3d> planePatch(const V& x, const V& s, double half) {
  const V n = s.normalized();
  const V u = n.unitOrthogonal(), v = n.cross(u);
  return {x + half * (u + v), x + half * (v - u), x - half * (u + v), x + half * (u - v)};
}

// Three directions across the camera's view (right, up, down-left), so none is foreshortened.
const std::vector<V> kDirections = {V(-0.2, 1, 0.15), V(-0.45, -0.05, 0.9), V(0.7, -0.75, -0.5)};
const Color kDirectionColors[3] = {palette::direction, palette::highlight, palette::trajectory};

template <typename X>
void drawSupports(Canvas& canvas, const X& shape) {
  for (int k = 0; k < 3; ++k) {
    const V s = kDirections[k].normalized();
    const V x = shape.support(s);
    canvas.polygon3(planePatch(x, s, 0.45), ShapeStyle{kDirectionColors[k].withAlpha(0.18), Stroke{kDirectionColors[k], 1.0}});
    canvas.arrow3(shape.center(), shape.center() + 1.9 * s, Stroke{kDirectionColors[k], style::lineThin});
    canvas.text3(shape.center() + 1.9 * s, "s_" + std::to_string(k + 1),
                 TextStyle{Font::Math, style::labelSize, kDirectionColors[k]}, Anchor::AboveRight);
    canvas.point3(x, kDirectionColors[k], 5, Stroke{palette::ink, 1.0});
  }
}

void shapesFigure(const std::string& out) {
  const Segment<double> segment(V(0.3, -1.1, -0.5), V(-0.3, 1.1, 0.5));
  const Triangle<double> triangle(V(-1, -0.8, 0), V(1.1, -0.3, 0.2), V(-0.2, 1, -0.2));
  const Box<double> box(V(0.9, 0.6, 0.5));
  const Sphere<double> sphere(0.9);
  const Capsule<double> capsule(V(-0.7, 0, -0.3), V(0.7, 0, 0.3), 0.45);
  std::mt19937 rng(1);
  std::normal_distribution<double> gauss;
  std::vector<V> cloud;
  for (int k = 0; k < 40; ++k) cloud.push_back(V(gauss(rng), 0.75 * gauss(rng), 0.6 * gauss(rng)).normalized());
  const auto polytope = Polytope<double>::hull(cloud);

  const int W = 380, H = 340;
  Canvas canvas(3 * W, 2 * H);
  int panel = 0;
  auto next = [&](const std::string& title) {
    canvas.setPanel({(panel % 3) * W, (panel / 3) * H, W, H});
    ++panel;
    canvas.title(title);
    canvas.setCamera(Camera::orbit(Eigen::Vector3d::Zero(), 1.9, 0.5, 0.45, 0.6, canvas.plotAspect()));
  };
  const MeshStyle solid{palette::bodyPFill.withAlpha(0.55), Stroke{palette::bodyPStroke, 1.0}, true, true};

  next("segment: the end farther along s");
  canvas.line3(segment.a, segment.b, Stroke{palette::bodyPStroke, style::lineThick});
  drawSupports(canvas, segment);
  next("triangle: the vertex farthest along s");
  canvas.polygon3({triangle.a, triangle.b, triangle.c}, style::bodyP);
  drawSupports(canvas, triangle);
  next("box: the corner in the octant of s");
  canvas.mesh(meshFromSupport(box, 60), solid);
  drawSupports(canvas, box);
  next("sphere: r s / |s|");
  canvas.mesh(meshFromSupport(sphere), MeshStyle{solid.fill, solid.edges, false, true});
  drawSupports(canvas, sphere);
  next("capsule: segment + ball");
  canvas.mesh(meshFromSupport(capsule), MeshStyle{solid.fill, solid.edges, false, true});
  drawSupports(canvas, capsule);
  next("polytope (" + std::to_string(polytope.vertexCount()) + " vertices): hill climbing");
  canvas.mesh(meshOf(polytope), solid);
  drawSupports(canvas, polytope);

  chapter::save(canvas, out, "support-mapping-shapes");
}

// One panel: the climb from `hint` to S_X(s), vertex by vertex.
void drawClimb(Canvas& canvas, const Polytope<double>& X, const V& s, int hint, double lookDown, const std::string& title) {
  const std::vector<int> path = X.climbPath(s, hint);
  const size_t steps = path.size() - 1;
  canvas.title(title + ": " + std::to_string(steps) + (steps == 1 ? " step" : " steps"));
  // Look at the path from the side (across s, from its vertex farthest off the s axis),
  // tilted towards s by `lookDown`, so the path and s both lie across the view.
  const V axis = s.normalized();
  V side = axis.unitOrthogonal();
  for (int v : path) {
    const V off = X.vertex(v) - X.vertex(v).dot(axis) * axis;
    if (off.norm() > 0.2) side = off.normalized();
  }
  const V view = (side + lookDown * axis).normalized();
  canvas.setCamera(Camera::orbit(Eigen::Vector3d::Zero(), 1.4, std::atan2(view.y(), view.x()),
                                 std::asin(std::clamp(view.z(), -0.9, 0.9)), 0.6, canvas.plotAspect()));
  canvas.mesh(meshOf(X), MeshStyle{palette::minkowskiFill.withAlpha(0.9), Stroke{palette::minkowskiStroke, 0.8}, true, true});
  std::vector<Eigen::Vector3d> points;
  for (int v : path) points.push_back(1.004 * X.vertex(v));  // just above the surface
  canvas.polyline3(points, style::highlightStroke);
  for (size_t k = 0; k < path.size(); ++k) canvas.point3(points[k], palette::highlight, 3.5);
  canvas.point3(points.front(), palette::background, 6, Stroke{palette::ink, 2});
  canvas.text3(points.front(), "hint", mathLabel, Anchor::BelowLeft);
  canvas.point3(points.back(), palette::direction, 6, Stroke{palette::ink, 1.5});
  canvas.text3(points.back(), "S_X(s)", mathLabel, Anchor::AboveRight);
  canvas.arrow3(points.back(), points.back() + 0.35 * s.normalized(), style::directionStroke);
  canvas.text3(points.back() + 0.35 * s.normalized(), "s", TextStyle{Font::Math, style::labelSize, palette::direction},
               Anchor::Right);
}

// The climb from `hint` to S_X(s) as a table (--trace): per step the vertex, s.x there, the
// dot products s.x_n of its neighbours, and the step taken (to the best neighbour while it
// is strictly better along s, as Polytope::support climbs).
void printClimb(const std::string& title, const Polytope<double>& X, const V& s, int hint) {
  chapter::TraceTable table{title, {"step", "vertex", "s.x", "neighbours n: s.x_n", "step taken"}, {}};
  const std::vector<int> path = X.climbPath(s, hint);
  for (std::size_t k = 0; k < path.size(); ++k) {
    const int v = path[k];
    std::string neighbours;
    for (int n : X.neighbours(v))
      neighbours += (neighbours.empty() ? "" : " ") + std::to_string(n) + ": " + chapter::fixed(s.dot(X.vertex(n)), 6);
    table.rows.push_back({std::to_string(k), std::to_string(v), chapter::fixed(s.dot(X.vertex(v)), 6), neighbours,
                          k + 1 < path.size() ? "to " + std::to_string(path[k + 1])
                                              : "stop: no neighbour higher, S_X(s) = vertex " + std::to_string(v)});
  }
  table.print();
}

void hillClimbingFigure(const std::string& out, const V& direction, int vertices, bool trace) {
  std::mt19937 rng(3);
  std::normal_distribution<double> gauss;
  std::vector<V> points;
  for (int k = 0; k < vertices; ++k) points.push_back(V(gauss(rng), gauss(rng), gauss(rng)).normalized());
  const auto X = Polytope<double>::hull(points);
  const V s = direction.normalized();
  const V previous = Eigen::AngleAxisd(0.45, V::UnitX()) * s;  // last query's direction, about 26 degrees away
  SupportHint warm = X.supportIndexLinearScan(-s);               // a cold start: the vertex opposite the answer
  const int cold = warm;
  X.support(previous, warm);                                     // a warm start: the answer to the last query
  if (trace) {
    printClimb("support-mapping-hill-climbing: cold start (§2.1, s = " + chapter::fixed(s.x(), 4) + ", " +
                   chapter::fixed(s.y(), 4) + ", " + chapter::fixed(s.z(), 4) + ")",
               X, s, cold);
    printClimb("support-mapping-hill-climbing: warm start from the last answer", X, s, warm);
  }

  const int W = 480, H = 440;
  Canvas canvas(2 * W, H);
  canvas.setPanel({0, 0, W, H});
  drawClimb(canvas, X, s, cold, 0.5, "cold start from the far side");
  canvas.setPanel({W, 0, W, H});
  drawClimb(canvas, X, s, warm, 2.0, "warm start from the last answer");
  chapter::save(canvas, out, "support-mapping-hill-climbing");
  std::printf("hill climbing on %d vertices: %zu steps cold, %zu steps warm\n", X.vertexCount(),
              X.climbPath(s, cold).size() - 1, X.climbPath(s, warm).size() - 1);
}

}  // namespace

int main(int argc, char** argv) {
  std::string out = ".", direction = "0.3,-0.2,1";
  int vertices = 300;
  bool trace = false;
  CLI::App app{"Draws chapter 01's figures in DIR: support mappings and hill climbing. --direction and --vertices "
               "change the hill climb's query; --trace prints the climbs (docs/traces.md)."};
  chapter::addFigureOptions(app, out);
  chapter::addTraceOption(app, trace);
  app.add_option("--direction", direction, "s, the direction of the hill climb")
      ->check(chapter::numbers(3, 3, "X,Y,Z"))
      ->capture_default_str();
  app.add_option("--vertices", vertices, "the points on the unit sphere the polytope is the hull of")
      ->check(CLI::Range(4, 100000))
      ->capture_default_str();
  chapter::parseOrExit(app, argc, argv);
  const std::vector<double> s = chapter::numberList(direction);
  if (s[0] == 0 && s[1] == 0 && s[2] == 0) chapter::badOption(app, "--direction", "s must be nonzero");
  std::filesystem::create_directories(out);
  shapesFigure(out);
  hillClimbingFigure(out, V(s[0], s[1], s[2]), vertices, trace);
  return 0;
}
