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
// The run is the one tests/gjk/test_gjk_figure2_steps.cpp replays by hand.
#include "../chapter.hpp"

#include <gjkx/gjk/gjk.hpp>
#include <gjkx/render/canvas.hpp>
#include <gjkx/support_mapping/polytope.hpp>

#include <cstdio>
#include <string>

using namespace gjkx;
using namespace gjkx::render;
using V = Vector3<double>;
using chapter::xy;

namespace {

constexpr double kHalo = 3.0;  // pixels of background behind a label, so lines under it do not cut it
constexpr TextStyle haloLabel{Font::Math, style::labelSize, palette::ink, kHalo, palette::background};

using chapter::fixed;

// A long line through `through`, normal to s: the supporting line (plane) of §2.3.
void supportingLine(Canvas& canvas, const V& through, const V& s, const Stroke& stroke) {
  const Eigen::Vector2d n = xy(s).normalized();
  const Eigen::Vector2d along(-n.y(), n.x());
  canvas.line(xy(through) - 40 * along, xy(through) + 40 * along, stroke);
}

// Left panel of iteration i: P and Q in the world, and the sets V_P and V_Q.
void drawBodies(Canvas& canvas, const Polytope<double>& P, const Polytope<double>& Q, const GjkIteration<double>& it) {
  canvas.setWorldWindow(-1, 15, -3.4, 10.5);
  canvas.setClip(canvas.plotArea());  // long lines stop at the plot area
  // §2.3: "If this distance is positive, then s_i is called a separating vector".
  canvas.title("i = " + std::to_string(it.i) + ":  V_P and V_Q,  s_" + std::to_string(it.i) +
               (it.supportingDistance > 0 ? " separates" : " does not separate"));
  canvas.polygon(xy(P.vertices()), style::bodyP);
  canvas.polygon(xy(Q.vertices()), style::bodyQ);
  canvas.text(xy(P.center()), "P", TextStyle{Font::Math, 22, palette::bodyPStroke});
  canvas.text({13.6, 7.2}, "Q", TextStyle{Font::Math, 22, palette::bodyQStroke});
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
void drawMinkowski(Canvas& canvas, const Polytope<double>& QminusP, const GjkIteration<double>& it) {
  canvas.setWorldWindow(-1.5, 10, -4, 10);  // the part of V_Q - V_P near the origin
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

}  // namespace

int main(int argc, char** argv) {
  const std::string out = chapter::outputFolder(argc, argv);

  // The scene of Fig. 2 (and of the step-by-step test).
  const auto P = Polytope<double>::polygon({V(0, 0, 0), V(5, 0, 0), V(6, 6, 0), V(0, 5, 0)});
  const auto Q = Polytope<double>::polygon({V(11, 3, 0), V(12, 3, 0), V(14, 5, 0), V(9, 9, 0), V(10, 5, 0)});
  GjkSettings<double> settings;
  settings.initialDirection = V(0, -1, 0);  // s_0: "an arbitrary nonzero vector"
  GjkTrace<double> trace;
  const GjkResult<double> result = gjk(P, Q, settings, nullptr, trace);

  // V_Q - V_P, the convex hull of all differences q - p.
  std::vector<V> differences;
  for (const V& q : Q.vertices())
    for (const V& p : P.vertices()) differences.push_back(q - p);
  const auto QminusP = Polytope<double>::polygon(differences);

  // Two iterations per row, each a pair of panels.
  const int panelW = 360, panelH = 320, perRow = 2;
  const int count = static_cast<int>(trace.iterations.size());
  const int rows = (count + perRow - 1) / perRow;
  Canvas canvas(2 * perRow * panelW, rows * panelH);
  for (int i = 0; i < count; ++i) {
    const int x = (i % perRow) * 2 * panelW, y = (i / perRow) * panelH;
    canvas.setPanel({x, y, panelW, panelH});
    drawBodies(canvas, P, Q, trace.iterations[i]);
    canvas.setPanel({x + panelW, y, panelW, panelH});
    drawMinkowski(canvas, QminusP, trace.iterations[i]);
  }
  chapter::save(canvas, out, "fig02-gjk-2d");
  std::printf("GJK: %s after %d iterations, distance %.6f (15/sqrt(17) = %.6f)\n", toString(result.status),
              result.iterations, result.distance, 15 / std::sqrt(17.0));
  return 0;
}
