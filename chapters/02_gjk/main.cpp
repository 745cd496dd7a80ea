// Chapter 02: GJK (§2.2), Fig. 2 of the paper.
//
// "Figure 2 illustrates an example execution of GJK, with sets V_P and V_Q on the
// left, and the corresponding Minkowski sum V_Q - V_P on the right."
//
// We run GJK on two polygons in the plane z = 0 with a GjkTrace, and draw one pair
// of panels per iteration i:
//   left:  P and Q, the support points S_P(s_i) and S_Q(-s_i) with their supporting
//          lines normal to s_i, and the vertex sets V_P and V_Q kept after the step;
//   right: the Minkowski difference V_Q - V_P, the origin, s_i, the new vertex
//          w_i = S_Q(-s_i) - S_P(s_i), the simplex kept (thick) and its closest point z.
// Each left panel's title says whether s_i is a separating vector (SD > 0, §2.3): here
// s_1 to s_5 are, s_0 is not.
// The run is the one tests/gjk/test_gjk_figure2_steps.cpp replays by hand. Options change
// the query (the shapes, their poses, s_0), and --trace prints the run as a table
// (docs/traces.md).
#include "../chapter.hpp"

#include <gjkx/gjk/gjk.hpp>
#include <gjkx/render/canvas.hpp>
#include <gjkx/support_mapping/polytope.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

using namespace gjkx;
using namespace gjkx::render;
using V = Vector3<double>;
using chapter::xy;

namespace {

constexpr double kHalo = 3.0;  // pixels of background behind a label, so lines under it do not cut it
constexpr TextStyle haloLabel{Font::Math, style::labelSize, palette::ink, kHalo, palette::background};

using chapter::fixed;

// The world windows of the two panels: the bodies (left) and V_Q - V_P near the origin (right).
struct Windows {
  double x0 = -1, x1 = 15, y0 = -3.4, y1 = 10.5;  // the bodies
  double mx0 = -1.5, mx1 = 10, my0 = -4, my1 = 10;  // the part of V_Q - V_P near the origin
  Eigen::Vector2d qLabel{13.6, 7.2};                // where Q's name goes
};

// A long line through `through`, normal to s: the supporting line (plane) of §2.3.
void supportingLine(Canvas& canvas, const V& through, const V& s, const Stroke& stroke) {
  const Eigen::Vector2d n = xy(s).normalized();
  const Eigen::Vector2d along(-n.y(), n.x());
  canvas.line(xy(through) - 40 * along, xy(through) + 40 * along, stroke);
}

// Left panel of iteration i: P and Q in the world, and the sets V_P and V_Q.
void drawBodies(Canvas& canvas, const Polytope<double>& P, const Polytope<double>& Q, const GjkIteration<double>& it,
                const Windows& w) {
  canvas.setWorldWindow(w.x0, w.x1, w.y0, w.y1);
  canvas.setClip(canvas.plotArea());  // long lines stop at the plot area
  // §2.3: "If this distance is positive, then s_i is called a separating vector".
  canvas.title("i = " + std::to_string(it.i) + ":  V_P and V_Q,  s_" + std::to_string(it.i) +
               (it.supportingDistance > 0 ? " separates" : " does not separate"));
  canvas.polygon(xy(P.vertices()), style::bodyP);
  canvas.polygon(xy(Q.vertices()), style::bodyQ);
  canvas.text(xy(P.center()), "P", TextStyle{Font::Math, 22, palette::bodyPStroke});
  canvas.text(w.qLabel, "Q", TextStyle{Font::Math, 22, palette::bodyQStroke});
  // The supporting lines of P and Q normal to s_i, through S_P(s_i) and S_Q(-s_i).
  supportingLine(canvas, it.supportP, it.s, Stroke{palette::bodyPStroke, 1.2, style::dashed});
  supportingLine(canvas, it.supportQ, it.s, Stroke{palette::bodyQStroke, 1.2, style::dashed});
  canvas.arrow(xy(it.supportP), xy(it.supportP) + 2.2 * xy(it.s).normalized(), style::directionStroke);
  canvas.text(xy(it.supportP) + 2.2 * xy(it.s).normalized(), "s_" + std::to_string(it.i),
              TextStyle{Font::Math, style::labelSize, palette::direction, kHalo}, chapter::toward(xy(it.s)));
  // V_P and V_Q: the support points the simplex keeps.
  std::vector<Eigen::Vector2d> vp, vq;
  for (int k = 0; k < it.simplex.size; ++k) {
    vp.push_back(xy(it.simplex.vertices[k].p));
    vq.push_back(xy(it.simplex.vertices[k].q));
  }
  if (vp.size() > 1) {
    canvas.polyline(vp, Stroke{palette::bodyPStroke, style::lineThick}, vp.size() > 2);
    canvas.polyline(vq, Stroke{palette::bodyQStroke, style::lineThick}, vq.size() > 2);
  }
  for (const auto& p : vp) canvas.point(p, palette::bodyPStroke, 4.5);
  for (const auto& q : vq) canvas.point(q, palette::bodyQStroke, 4.5);
  canvas.point(xy(it.supportP), palette::background, 6, Stroke{palette::bodyPStroke, 2});
  canvas.point(xy(it.supportQ), palette::background, 6, Stroke{palette::bodyQStroke, 2});
  // Each support point's label goes beside its point along the supporting line (P's on the
  // lower side, Q's on the upper), over a halo so the outlines and dashed lines under it do
  // not cut the letters; tilted into the body, away from s_i's arrow, unless the line is
  // level, when the body's edge lies along it and the label goes outside, under (over) it.
  const Eigen::Vector2d unit = xy(it.s).normalized(), along(-unit.y(), unit.x());
  const bool level = std::abs(along.y()) < 0.3;
  const Eigen::Vector2d sideP = level ? Eigen::Vector2d(std::abs(along.x()), 0) : along.y() < 0 ? along : Eigen::Vector2d(-along);
  const double tilt = level ? 0.6 : -0.6;
  canvas.text(xy(it.supportP), "S_P(s_" + std::to_string(it.i) + ")", haloLabel, chapter::toward(sideP + tilt * unit));
  canvas.text(xy(it.supportQ), "S_Q(-s_" + std::to_string(it.i) + ")", haloLabel, chapter::toward(-sideP - tilt * unit));
  if (it.step == GjkStep::Converged) {  // the closest points, joined
    canvas.line(xy(it.simplex.witnessP()), xy(it.simplex.witnessQ()), Stroke{palette::ink, 1.5, style::dotted});
    canvas.point(xy(it.simplex.witnessP()), palette::witness, 4);
    canvas.point(xy(it.simplex.witnessQ()), palette::witness, 4);
  }
}

// Right panel of iteration i: V_Q - V_P, s_i, w_i, the simplex kept and z.
void drawMinkowski(Canvas& canvas, const Polytope<double>& QminusP, const GjkIteration<double>& it,
                   const Windows& window) {
  canvas.setWorldWindow(window.mx0, window.mx1, window.my0, window.my1);  // the part of V_Q - V_P near the origin
  canvas.setClip(canvas.plotArea());        // long lines stop at the plot area
  const char* verdict = it.supportingDistance > 0 ? " > 0" : " < 0";
  canvas.title("V_Q - V_P:  SD = " + fixed(it.supportingDistance) + verdict + ",  MD = " + fixed(it.minkowskiDistance));
  canvas.axes();
  canvas.polygon(xy(QminusP.vertices()), style::minkowski);
  const V w = it.supportQ - it.supportP;
  // The supporting line of V_Q - V_P normal to s_i through w_i: its signed distance
  // from the origin along s_i is SD(P, Q, s_i). Positive: s_i separates P and Q.
  supportingLine(canvas, w, it.s, style::separatingStroke);
  const Eigen::Vector2d sUnit = xy(it.s).normalized();
  const double arrowLength = std::min(2.5, xy(it.s).norm());
  canvas.arrow({0, 0}, arrowLength * sUnit, style::directionStroke);
  canvas.text(arrowLength * sUnit, "s_" + std::to_string(it.i), TextStyle{Font::Math, style::labelSize, palette::direction, kHalo},
              it.s.y() < 0 ? Anchor::Left : Anchor::Below);
  // The simplex kept: the feature of V_Z closest to the origin.
  std::vector<Eigen::Vector2d> kept;
  for (int k = 0; k < it.simplex.size; ++k) kept.push_back(xy(it.simplex.vertices[k].w));
  if (kept.size() >= 3) canvas.polygon(kept, style::simplex);
  if (kept.size() == 2) canvas.line(kept[0], kept[1], style::simplexStroke);
  for (const auto& k : kept) canvas.point(k, palette::simplex, 4);
  canvas.point(xy(w), palette::background, 6, Stroke{palette::highlight, 2.5});
  canvas.line({0, 0}, xy(it.z), Stroke{palette::ink, 1.0, style::dotted});
  canvas.point(xy(it.z), palette::witness, 4.5);
  // w_i and z: one label when they are the same point (the first iteration); else w_i's
  // to the right, on V_Q - V_P, and z's to the left, on the origin's side.
  const std::string wName = "w_" + std::to_string(it.i);
  if ((xy(w) - xy(it.z)).norm() < 0.3) {
    canvas.text(xy(w), "z = " + wName, haloLabel, Anchor::AboveRight);
  } else {
    canvas.text(xy(w), wName, haloLabel, Anchor::Right);
    canvas.text(xy(it.z), "z", haloLabel, Anchor::Left);
  }
}

// The run as a table (--trace): per iteration i, s_i, S_P(s_i), S_Q(-s_i), the supporting
// distance SD (§2.3), the kept simplex as V_P and V_Q, z and the Minkowski distance MD = |z|.
void printTrace(const GjkTrace<double>& trace, const GjkResult<double>& result) {
  using chapter::pointCell;
  chapter::TraceTable table{"fig02-gjk-2d: GJK iteration by iteration (§2.2, Fig. 2)",
                            {"i", "s_i", "S_P(s_i)", "S_Q(-s_i)", "SD", "V_P", "V_Q", "z", "MD", "step"}, {}};
  for (const auto& it : trace.iterations) {
    std::string vp, vq;
    for (int k = 0; k < it.simplex.size; ++k) {
      vp += (k ? " " : "") + pointCell(it.simplex.vertices[k].p);
      vq += (k ? " " : "") + pointCell(it.simplex.vertices[k].q);
    }
    table.rows.push_back({std::to_string(it.i), pointCell(it.s), pointCell(it.supportP), pointCell(it.supportQ),
                          fixed(it.supportingDistance, 6), vp, vq, pointCell(it.z), fixed(it.minkowskiDistance, 6),
                          toString(it.step)});
  }
  table.print();
  std::printf("result: %s after %d iterations, distance %.6f\n\n", toString(result.status), result.iterations,
              result.distance);
}

// The windows of a reader's query: each panel's points and the origin, with a margin.
Windows windowsOf(const Polytope<double>& P, const Polytope<double>& Q, const Polytope<double>& QminusP) {
  auto bounds = [](std::vector<V> points, double& x0, double& x1, double& y0, double& y1) {
    points.push_back(V::Zero());
    V lo = points[0], hi = points[0];
    for (const V& p : points) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
    const double margin = 0.15 * std::max(hi.x() - lo.x(), hi.y() - lo.y()) + 0.5;
    x0 = lo.x() - margin, x1 = hi.x() + margin, y0 = lo.y() - margin, y1 = hi.y() + margin;
  };
  Windows w;
  std::vector<V> both = P.vertices();
  both.insert(both.end(), Q.vertices().begin(), Q.vertices().end());
  bounds(both, w.x0, w.x1, w.y0, w.y1);
  bounds(QminusP.vertices(), w.mx0, w.mx1, w.my0, w.my1);
  w.qLabel = xy(Q.center());
  return w;
}

// A shape of the plane z = 0 from its option's text, placed at `pose`: "box:W,H" (centred on
// its origin), "ngon:R,N" (N corners on a circle of radius R) or "polygon:X1,Y1,X2,Y2,..."
// (the hull of the points); a bad text ends the program naming `option`.
Polytope<double> shapeOf(const CLI::App& app, const std::string& option, const std::string& text,
                         const Pose<double>& pose) {
  const std::size_t colon = text.find(':');
  const std::string kind = text.substr(0, colon);
  const std::vector<double> n = colon == std::string::npos ? std::vector<double>{} : chapter::numberList(text.substr(colon + 1));
  std::vector<V> corners;
  if (kind == "box" && n.size() == 2 && n[0] > 0 && n[1] > 0) {
    corners = {V(-n[0] / 2, -n[1] / 2, 0), V(n[0] / 2, -n[1] / 2, 0), V(n[0] / 2, n[1] / 2, 0), V(-n[0] / 2, n[1] / 2, 0)};
  } else if (kind == "ngon" && n.size() == 2 && n[0] > 0 && n[1] >= 3 && n[1] <= 360 && n[1] == std::floor(n[1])) {
    for (int k = 0; k < int(n[1]); ++k)
      corners.push_back(V(n[0] * std::cos(2 * M_PI * k / n[1]), n[0] * std::sin(2 * M_PI * k / n[1]), 0));
  } else if (kind == "polygon" && n.size() >= 6 && n.size() % 2 == 0) {
    for (std::size_t k = 0; k < n.size(); k += 2) corners.push_back(V(n[k], n[k + 1], 0));
  } else {
    chapter::badOption(app, option,
                       "expected box:W,H or ngon:R,N or polygon:X1,Y1,X2,Y2,X3,Y3,... (positive sizes, 3 to 360 "
                       "corners), got '" + text + "'");
  }
  for (V& c : corners) c = pose(c);
  try {
    return Polytope<double>::polygon(corners);
  } catch (const std::exception& e) {
    chapter::badOption(app, option, e.what());
  }
}

}  // namespace

int main(int argc, char** argv) {
  std::string out = ".", pText, qText, pAt = "0,0", qAt = "0,0", s0Text = "0,-1";
  bool printing = false;
  CLI::App app{"Draws Fig. 2 of the paper in DIR: GJK iteration by iteration. --p, --q, --p-at, --q-at and --s0 "
               "change the query; --trace prints the run (docs/traces.md)."};
  chapter::addFigureOptions(app, out);
  chapter::addTraceOption(app, printing);
  auto* pOption = app.add_option("--p", pText, "the shape P: box:W,H, ngon:R,N or polygon:X1,Y1,X2,Y2,... "
                                               "(default: Fig. 2's quadrilateral)");
  auto* qOption = app.add_option("--q", qText, "the shape Q, as --p (default: Fig. 2's pentagon)");
  auto* pAtOption = chapter::addPoseOption(app, "--p-at", pAt, "P's pose: where its origin goes, its angle (radians)");
  auto* qAtOption = chapter::addPoseOption(app, "--q-at", qAt, "Q's pose, as --p-at");
  auto* s0Option = app.add_option("--s0", s0Text, "s_0, GJK's first search direction (§2.2: \"an arbitrary nonzero "
                                                  "vector\")")
                       ->check(chapter::numbers(2, 2, "X,Y"))
                       ->capture_default_str();
  chapter::parseOrExit(app, argc, argv);
  const std::vector<double> s0 = chapter::numberList(s0Text);
  if (s0[0] == 0 && s0[1] == 0) chapter::badOption(app, "--s0", "s_0 must be nonzero");
  std::filesystem::create_directories(out);
  const bool query = pOption->count() + qOption->count() + pAtOption->count() + qAtOption->count() + s0Option->count() > 0;

  // The scene of Fig. 2 (and of the step-by-step test), or the reader's.
  const Pose<double> poseP = chapter::planarPose(chapter::numberList(pAt)), poseQ = chapter::planarPose(chapter::numberList(qAt));
  const auto P = pOption->count() ? shapeOf(app, "--p", pText, poseP)
                                  : shapeOf(app, "--p", "polygon:0,0,5,0,6,6,0,5", poseP);
  const auto Q = qOption->count() ? shapeOf(app, "--q", qText, poseQ)
                                  : shapeOf(app, "--q", "polygon:11,3,12,3,14,5,9,9,10,5", poseQ);
  GjkSettings<double> settings;
  settings.initialDirection = V(s0[0], s0[1], 0);  // s_0: "an arbitrary nonzero vector"
  GjkTrace<double> trace;
  const GjkResult<double> result = gjk(P, Q, settings, nullptr, trace);

  // V_Q - V_P, the convex hull of all differences q - p.
  std::vector<V> differences;
  for (const V& q : Q.vertices())
    for (const V& p : P.vertices()) differences.push_back(q - p);
  const auto QminusP = Polytope<double>::polygon(differences);
  const Windows windows = query ? windowsOf(P, Q, QminusP) : Windows{};
  if (printing) printTrace(trace, result);

  // Two iterations per row, each a pair of panels.
  const int panelW = 360, panelH = 320, perRow = 2;
  const int count = static_cast<int>(trace.iterations.size());
  const int rows = (count + perRow - 1) / perRow;
  Canvas canvas(2 * perRow * panelW, rows * panelH);
  for (int i = 0; i < count; ++i) {
    const int x = (i % perRow) * 2 * panelW, y = (i / perRow) * panelH;
    canvas.setPanel({x, y, panelW, panelH});
    drawBodies(canvas, P, Q, trace.iterations[i], windows);
    canvas.setPanel({x + panelW, y, panelW, panelH});
    drawMinkowski(canvas, QminusP, trace.iterations[i], windows);
  }
  chapter::save(canvas, out, "fig02-gjk-2d");
  if (query)
    std::printf("GJK: %s after %d iterations, distance %.6f\n", toString(result.status), result.iterations, result.distance);
  else
    std::printf("GJK: %s after %d iterations, distance %.6f (15/sqrt(17) = %.6f)\n", toString(result.status),
                result.iterations, result.distance, 15 / std::sqrt(17.0));
  return 0;
}
