// Chapter 04's bodies and how they are drawn: two convex polygons P and Q moving in the
// plane z = 0 over [t_0, t_1], drawn at t_0 (outlined), at t_1 (filled) and at instants in
// between in the colour of their time, with their paths; and what the extrusion test (§3)
// and the §5 solver found: a separating line at both ends, or the time of impact.
#pragma once

#include "../chapter.hpp"

#include <gjkx/brent/time_of_impact.hpp>
#include <gjkx/extrusion/extrusion.hpp>
#include <gjkx/render/canvas.hpp>
#include <gjkx/support_mapping/placed.hpp>
#include <gjkx/support_mapping/polytope.hpp>

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

namespace extrusion_figures {

using namespace gjkx;
using namespace gjkx::render;
using V = Vector3<double>;
using P2 = Eigen::Vector2d;
using Body = Moving<Polytope<double>>;
using chapter::xy;

/// The time interval [t_0, t_1] of every figure of the chapter.
constexpr double t0 = 0, t1 = 1;
/// A verdict right or wrong; the separating space at t_0 and at t_1.
const Color right = palette::direction, wrong = palette::penetration;
const Color atStart = palette::highlight, atEnd = palette::trajectory;  // the separating space at t_0, t_1

inline std::vector<V> box(double w, double h) {
  return {V(-w / 2, -h / 2, 0), V(w / 2, -h / 2, 0), V(w / 2, h / 2, 0), V(-w / 2, h / 2, 0)};
}
inline Motion<double> glide(const V& start, const V& velocity) {
  return Motion<double>::constantVelocity(Pose<double>::translate(start), velocity);
}
inline Body body(const std::vector<V>& corners, const Motion<double>& motion) {
  return moving(Polytope<double>::polygon(corners), motion);
}

/// Two moving bodies, the side of each that its labels go to, and the world window.
struct Pair {
  Body P, Q;
  V sideP, sideQ;
  double xmin, xmax, ymin, ymax;
  bool keyAbove = false;  ///< the time key in the upper left corner, not the lower left
};

/// The colour of time t in [t_0, t_1], shared by both bodies, so that the poses of P and Q
/// at the same instant are seen as a pair: dark purple at t_0 through blue to green at t_1
/// (three stops of the viridis ramp, which stays readable on white and in grey).
inline Color timeColour(double t) {
  static const Color stops[] = {Color::hex(0x440154), Color::hex(0x31688e), Color::hex(0x35b779)};
  const double x = std::clamp((t - t0) / (t1 - t0), 0.0, 1.0) * 2;
  const int k = std::min(1, int(x));
  const double f = x - k;
  const Color &a = stops[k], &b = stops[k + 1];
  return Color{a.r + f * (b.r - a.r), a.g + f * (b.g - a.g), a.b + f * (b.b - a.b), 1.0};
}

/// A body at time t: in between (outlined in its time's colour), outlined (t_0), filled
/// (t_1), or at the time of impact.
enum class Look { Faint, Start, End, Impact, Chain };
inline void drawBody(Canvas& c, const Body& b, double t, bool isP, Look look) {
  const Color stroke = isP ? palette::bodyPStroke : palette::bodyQStroke;
  const Color fill = isP ? palette::bodyPFill : palette::bodyQFill;
  ShapeStyle shape{fill, Stroke{stroke, style::lineThin}};
  if (look == Look::Faint) shape = ShapeStyle{timeColour(t).withAlpha(0.05), Stroke{timeColour(t).withAlpha(0.75), 1.3}};
  if (look == Look::Chain) shape = ShapeStyle{timeColour(t).withAlpha(0.12), Stroke{timeColour(t), 2.0}};
  if (look == Look::Start) shape.fill = palette::none;
  if (look == Look::Impact) shape = ShapeStyle{palette::highlight.withAlpha(0.45), Stroke{stroke, style::lineThick}};
  std::vector<P2> outline;
  for (const V& v : b.shape.vertices()) outline.push_back(xy(b.at(t).worldFromBody(v)));
  c.polygon(outline, shape);
}

/// The path of a body's centre from t_0 to t_1, and its labels X(t_0) and X(t_1).
inline void drawMotion(Canvas& c, const Body& b, const std::string& name, const V& side, bool isP) {
  const TextStyle label{Font::Math, style::labelSize, isP ? palette::bodyPStroke : palette::bodyQStroke, 2.5};
  std::vector<P2> path;
  for (int k = 0; k <= 20; ++k) path.push_back(xy(b.at(t0 + (t1 - t0) * k / 20).center()));
  if ((path.back() - path.front()).norm() < 1e-9) {  // at rest: one label
    c.text(xy(b.at(t0).support(side)), name, label, chapter::toward(xy(side)));
    return;
  }
  c.arrow(path[19], path[20], style::trajectoryStroke);
  path.pop_back();
  c.polyline(path, style::trajectoryStroke);
  c.text(xy(b.at(t0).support(side)), name + "(t_0)", label, chapter::toward(xy(side)));
  c.text(xy(b.at(t1).support(side)), name + "(t_1)", label, chapter::toward(xy(side)));
}

/// The key of the time colours: a bar from t_0 to t_1 in the panel's lower left corner,
/// with a tick at each pose in between.
inline void drawTimeKey(Canvas& c, const Pair& pair, int between) {
  const double w = pair.xmax - pair.xmin, h = pair.ymax - pair.ymin;
  const P2 from(pair.xmin + 0.05 * w, pair.keyAbove ? pair.ymax - 0.08 * h : pair.ymin + 0.05 * h), to = from + P2(0.25 * w, 0);
  constexpr int pieces = 40;
  for (int k = 0; k < pieces; ++k)
    c.line(from + (to - from) * k / pieces, from + (to - from) * (k + 1) / pieces, Stroke{timeColour(t0 + (t1 - t0) * (k + 0.5) / pieces), 5});
  for (int k = 1; k < between; ++k) {
    const P2 at = from + (to - from) * k / between;
    c.line(at + P2(0, 0.012 * h), at + P2(0, 0.035 * h), Stroke{timeColour(t0 + (t1 - t0) * k / between), 1.5});
  }
  const TextStyle small{Font::Math, 13, palette::ink, 2.0, palette::background};
  c.text(from, "t_0", small, Anchor::Left);
  c.text(to, "t_1", small, Anchor::Right);
}

/// Both bodies at t_0 and t_1, `between` - 1 poses in between (both bodies' poses at the same
/// instant outlined in that instant's colour, with the key), and their motions.
inline void drawPair(Canvas& c, const Pair& pair, int between, bool key = true) {
  c.setWorldWindow(pair.xmin, pair.xmax, pair.ymin, pair.ymax);
  c.setClip(c.plotArea());
  for (int k = 1; k < between; ++k)
    for (const Body* b : {&pair.P, &pair.Q}) drawBody(c, *b, t0 + (t1 - t0) * k / between, b == &pair.P, Look::Faint);
  if (between > 1 && key) drawTimeKey(c, pair, between);
  for (const auto& [t, look] : {std::pair{t0, Look::Start}, std::pair{t1, Look::End}})
    for (const Body* b : {&pair.P, &pair.Q}) drawBody(c, *b, t, b == &pair.P, look);
  drawMotion(c, pair.P, "P", pair.sideP, true);
  drawMotion(c, pair.Q, "Q", pair.sideQ, false);
}

/// The point of the line normal to the unit s halfway between P(t) and Q(t) nearest the
/// midpoint of their centres.
inline P2 lineMiddle(const Pair& pair, const V& s, double t) {
  const double offset = 0.5 * (s.dot(pair.P.support(s, t)) + s.dot(pair.Q.support(-s, t)));
  const P2 foot = offset * xy(s), along(-s.y(), s.x());
  return foot + along * along.dot(0.5 * (xy(pair.P.at(t).center()) + xy(pair.Q.at(t).center())) - foot);
}

/// That line, `halfLength` long either side of lineMiddle: a separating line when SD > 0.
/// Its label `name` goes at its end `end` (+1 or -1).
inline void drawSeparatingLine(Canvas& c, const Pair& pair, const V& s, double t, const std::string& name,
                        const Color& color = palette::ink, double halfLength = 1.8, double end = 1) {
  const P2 middle = lineMiddle(pair, s, t), along = end * P2(-s.y(), s.x());
  c.line(middle - halfLength * along, middle + halfLength * along, Stroke{color, 1.4, style::dashed});
  if (!name.empty())
    c.text(middle + halfLength * along, name, TextStyle{Font::Math, style::labelSize, color, 2.5}, chapter::toward(along));
}

/// What the extrusion test found: the separating vector, as a separating line at t_0 and at
/// t_1; or, after the §5 solver, both bodies at the time of impact and the contact normal.
inline void drawFound(Canvas& c, const Pair& pair, const ExtrusionResult<double>& test, const ToiResult<double>& toi) {
  if (test.status == ExtrusionStatus::NoCollision) {
    drawSeparatingLine(c, pair, test.separatingVector, t0, "t_0");
    drawSeparatingLine(c, pair, test.separatingVector, t1, "t_1");
  }
  if (toi.status != ToiStatus::Hit) return;
  drawBody(c, pair.P, toi.time, true, Look::Impact);
  drawBody(c, pair.Q, toi.time, false, Look::Impact);
  const P2 tip = xy(toi.witnessP) + 1.1 * xy(toi.normal);
  c.arrow(xy(toi.witnessP), tip, Stroke{palette::ink, style::lineThick});
  c.point(xy(toi.witnessP), palette::witness, 4);
  c.text(tip, "n", TextStyle{Font::Math, style::labelSize, palette::ink, 2.5}, chapter::toward(xy(toi.normal)));
}

}  // namespace extrusion_figures
