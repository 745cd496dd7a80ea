// Chapter 04: the extrusion test (§1, §3), Figs. 1 and 4 of the paper.
//
// §1 sorts the intersection tests of two bodies over a time interval [t_0, t_1] into
// three kinds: static, sweeping and extrusion. §3 builds the extrusion test on GJK:
// "we determine whether the separating space ever vanishes in the interim by testing
// whether the spaces at t_0 and t_1 are disjoint". The bodies are polygons in the plane
// z = 0 moving over [0, 1]. Every verdict drawn is the library's (staticTest,
// sweepingTest, extrusionTest and the §5 solver timeOfImpact); a verdict is marked
// right or wrong against staticTest at 4001 instants, dense enough for these motions.
//
// Why this chapter calls §5's solver before chapter 05 introduces it: Fig. 4 of the paper
// ("extrusion tests robustly give correct results") is the §3 test *with §5 behind it*.
// Alone, the test only proves "no collision" or says "undecided" (§3: "we must further
// investigate [...] as described in section 5"); panel (c) is a §5 photo finish and (b),
// (d) are §5 hits, so their right verdicts, like the extrusion column of Fig. 1, need it.
#include "../chapter.hpp"

#include <gjkx/brent/time_of_impact.hpp>
#include <gjkx/extrusion/extrusion.hpp>
#include <gjkx/extrusion/static_sampling.hpp>
#include <gjkx/extrusion/sweeping.hpp>
#include <gjkx/render/canvas.hpp>
#include <gjkx/support_mapping/placed.hpp>
#include <gjkx/support_mapping/polytope.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <utility>
#include <vector>

using namespace gjkx;
using namespace gjkx::render;
using V = Vector3<double>;
using P2 = Eigen::Vector2d;
using Body = Moving<Polytope<double>>;
using chapter::xy;

namespace {

constexpr double t0 = 0, t1 = 1;
constexpr int kDirections = 1440;    // directions on the unit circle: a quarter degree apart
constexpr int kTruthSamples = 4001;  // instants of the reference static test
const Color right = palette::direction, wrong = palette::penetration;
const Color atStart = palette::highlight, atEnd = palette::trajectory;  // the separating space at t_0, t_1

std::string fixed(double x, int digits = 2) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.*f", digits, x);
  return buffer;
}

V direction(int k) { return V(std::cos(2 * M_PI * k / kDirections), std::sin(2 * M_PI * k / kDirections), 0); }

std::vector<V> box(double w, double h) {
  return {V(-w / 2, -h / 2, 0), V(w / 2, -h / 2, 0), V(w / 2, h / 2, 0), V(-w / 2, h / 2, 0)};
}
Motion<double> glide(const V& start, const V& velocity) {
  return Motion<double>::constantVelocity(Pose<double>::translate(start), velocity);
}
Body body(const std::vector<V>& corners, const Motion<double>& motion) {
  return moving(Polytope<double>::polygon(corners), motion);
}

// Two moving bodies, the side of each that its labels go to, and the world window.
struct Pair {
  Body P, Q;
  V sideP, sideQ;
  double xmin, xmax, ymin, ymax;
  bool keyAbove = false;  ///< the time key in the upper left corner, not the lower left
};

// The colour of time t in [t_0, t_1], shared by both bodies, so that the poses of P and Q
// at the same instant are seen as a pair: dark purple at t_0 through blue to green at t_1
// (three stops of the viridis ramp, which stays readable on white and in grey).
Color timeColour(double t) {
  static const Color stops[] = {Color::hex(0x440154), Color::hex(0x31688e), Color::hex(0x35b779)};
  const double x = std::clamp((t - t0) / (t1 - t0), 0.0, 1.0) * 2;
  const int k = std::min(1, int(x));
  const double f = x - k;
  const Color &a = stops[k], &b = stops[k + 1];
  return Color{a.r + f * (b.r - a.r), a.g + f * (b.g - a.g), a.b + f * (b.b - a.b), 1.0};
}

// A body at time t: in between (outlined in its time's colour), outlined (t_0), filled
// (t_1), or at the time of impact.
enum class Look { Faint, Start, End, Impact, Chain };
void drawBody(Canvas& c, const Body& b, double t, bool isP, Look look) {
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

// The path of a body's centre from t_0 to t_1, and its labels X(t_0) and X(t_1).
void drawMotion(Canvas& c, const Body& b, const std::string& name, const V& side, bool isP) {
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

// The key of the time colours: a bar from t_0 to t_1 in the panel's lower left corner,
// with a tick at each pose in between.
void drawTimeKey(Canvas& c, const Pair& pair, int between) {
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

// Both bodies at t_0 and t_1, `between` - 1 poses in between (both bodies' poses at the same
// instant outlined in that instant's colour, with the key), and their motions.
void drawPair(Canvas& c, const Pair& pair, int between, bool key = true) {
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

// The point of the line normal to the unit s halfway between P(t) and Q(t) nearest the
// midpoint of their centres.
P2 lineMiddle(const Pair& pair, const V& s, double t) {
  const double offset = 0.5 * (s.dot(pair.P.support(s, t)) + s.dot(pair.Q.support(-s, t)));
  const P2 foot = offset * xy(s), along(-s.y(), s.x());
  return foot + along * along.dot(0.5 * (xy(pair.P.at(t).center()) + xy(pair.Q.at(t).center())) - foot);
}

// That line, `halfLength` long either side of lineMiddle: a separating line when SD > 0.
// Its label `name` goes at its end `end` (+1 or -1).
void drawSeparatingLine(Canvas& c, const Pair& pair, const V& s, double t, const std::string& name,
                        const Color& color = palette::ink, double halfLength = 1.8, double end = 1) {
  const P2 middle = lineMiddle(pair, s, t), along = end * P2(-s.y(), s.x());
  c.line(middle - halfLength * along, middle + halfLength * along, Stroke{color, 1.4, style::dashed});
  if (!name.empty())
    c.text(middle + halfLength * along, name, TextStyle{Font::Math, style::labelSize, color, 2.5}, chapter::toward(along));
}

// What the extrusion test found: the separating vector, as a separating line at t_0 and at
// t_1; or, after the §5 solver, both bodies at the time of impact and the contact normal.
void drawFound(Canvas& c, const Pair& pair, const ExtrusionResult<double>& test, const ToiResult<double>& toi) {
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

// ---- The photo finish's chain (§5) -------------------------------------------------
// "a 'photo finish', in which the extrusion test fails for the complete time interval t_0
// to t_1 but succeeds when performed on the sequence of intervals t_0 to t_{x1}, t_{x1} to
// t_{x2}, ... t_{xn}, to t_1": every link of the chain has a vector that separates the
// bodies at both of its ends, hence (linear motion) all through it.

// One link [from, to] of the chain, and the unit vector of its complete test that separates
// the bodies at both of its ends by the most.
struct Link {
  double from, to;
  V s;
};

// The links of a photo finish from the solver's complete tests: test k covers
// [its start, the next test's start], the last one [its start, t_1].
std::vector<Link> chainOf(const Pair& pair, const ToiTrace<double>& trace) {
  std::vector<Link> chain;
  const auto& tests = trace.intervals;
  for (std::size_t k = 0; k < tests.size(); ++k) {
    const double from = tests[k].start, to = k + 1 < tests.size() ? tests[k + 1].start : t1;
    if (!(to > from)) continue;
    Link link{from, to, V::UnitX()};
    double best = -std::numeric_limits<double>::infinity();
    for (int j = 0; j < tests[k].separating.count; ++j) {
      const V s = tests[k].separating.vectors[j].normalized();
      const double margin = std::min(supportingDistanceAt(pair.P, pair.Q, s, from), supportingDistanceAt(pair.P, pair.Q, s, to));
      if (margin > best) best = margin, link.s = s;
    }
    chain.push_back(link);
  }
  return chain;
}

// The name of the k-th end of a chain of n links: t_0, t_{x1}, ..., t_{xn-1}, t_1.
std::string endName(std::size_t k, std::size_t links) {
  return k == 0 ? "t_0" : k == links ? "t_1" : "t_{x" + std::to_string(k) + "}";
}
// A link's colour: the time ramp's at its middle.
Color linkColour(const Link& link) { return timeColour(0.5 * (link.from + link.to)); }

// The colour of a Brent step kind, in the order of BrentStepKind, as in chapter 05's figures.
Color kindColour(BrentStepKind kind) {
  static const Color colors[] = {Color::hex(0x9E9E9E), palette::ink, palette::highlight, Color::hex(0xCC79A7),
                                 Color::hex(0x009E73), Color::hex(0xD55E00)};
  return colors[static_cast<int>(kind)];
}
const char* kindName(BrentStepKind kind) {
  switch (kind) {
    case BrentStepKind::Bisection: return "bisection";
    case BrentStepKind::Secant: return "secant";
    case BrentStepKind::InverseQuadratic: return "inverse quadratic";
    case BrentStepKind::MinimalStep: return "minimal step";
    case BrentStepKind::Leap: return "leap";
    case BrentStepKind::DistanceSecant: return "distance secant";
  }
  return "?";
}

// The world point under canvas pixel (px, py) of the current panel.
P2 worldAt(Canvas& c, double px, double py) {
  const P2 origin = c.toPixel(P2(0, 0));
  const double k = c.pixelsPerUnit();
  return P2((px - origin.x()) / k, (origin.y() - py) / k);
}

// The chain in the panel: both bodies at each end t_{xi} inside [t_0, t_1], outlined in
// its time's colour, and each link's separating line at the poses of both of its ends, in
// the link's colour. Below, the chain as a time line: a bar per link from t_0 to t_1, and
// above it the Brent iterates that found the ends, coloured by the rule that chose them.
void drawChain(Canvas& c, const Pair& pair, const ToiTrace<double>& trace, const std::vector<Link>& chain) {
  for (std::size_t k = 1; k < chain.size(); ++k)
    for (const Body* b : {&pair.P, &pair.Q}) drawBody(c, *b, chain[k].from, b == &pair.P, Look::Chain);
  // The lines' names go at one of their ends, clear of the bodies' labels and each other:
  // above a line flatter than 45 degrees, else at the end farther from them.
  std::vector<P2> labels;
  for (double t : {t0, t1})
    for (const P2& label : {xy(pair.P.at(t).support(pair.sideP)), xy(pair.Q.at(t).support(pair.sideQ))})
      labels.push_back(label);
  for (std::size_t k = 0; k < chain.size(); ++k) {
    const std::string name = "[" + endName(k, chain.size()) + ", " + endName(k + 1, chain.size()) + "]";
    const V& s = chain[k].s;
    const Color color = linkColour(chain[k]);
    const double halfLength = std::min(1.6, 1.25 / std::max(std::abs(s.x()), 1e-3));
    const P2 middle = lineMiddle(pair, s, chain[k].to), up = s.x() >= 0 ? P2(-s.y(), s.x()) : P2(s.y(), -s.x());
    const auto clearance = [&](const P2& at) {
      double nearest = std::numeric_limits<double>::infinity();
      for (const P2& label : labels) nearest = std::min(nearest, (at - label).norm());
      return nearest;
    };
    const bool flat = std::abs(up.y()) < std::sqrt(0.5);
    const double end = flat || clearance(middle + halfLength * up) >= clearance(middle - halfLength * up) ? 1 : -1;
    drawSeparatingLine(c, pair, s, chain[k].from, "", color, halfLength, end);
    const P2 tip = middle + end * halfLength * up;
    drawSeparatingLine(c, pair, s, chain[k].to, "", color, halfLength, end);
    c.text(tip, name, TextStyle{Font::Math, style::labelSize, color, 2.5}, flat ? Anchor::Above : chapter::toward(end * up));
    labels.push_back(tip);
  }
  // The time line, in pixels at the foot of the plot area.
  const PixelRect area = c.plotArea();
  const double y = area.y + area.height - 24, left = area.x + 58, right = area.x + area.width - 150;
  const auto X = [&](double t) { return left + (right - left) * (t - t0) / (t1 - t0); };
  const auto line = [&](double xa, double ya, double xb, double yb, const Stroke& stroke) {
    c.line(worldAt(c, xa, ya), worldAt(c, xb, yb), stroke);
  };
  const TextStyle small{Font::Sans, 12.5, palette::ink, 2.0, palette::background};
  c.textAtPixel(left - 10, y, "chain", small, Anchor::Left);
  for (const Link& link : chain) line(X(link.from) + 1.5, y, X(link.to) - 1.5, y, Stroke{linkColour(link), 8});
  for (std::size_t k = 0; k <= chain.size(); ++k) {
    const double x = X(k < chain.size() ? chain[k].from : t1);
    line(x, y - 7, x, y + 7, Stroke{palette::ink, 1.2});
    c.textAtPixel(x, y + 9, endName(k, chain.size()), TextStyle{Font::Math, 13, palette::ink, 2.0, palette::background},
                  Anchor::Below);
  }
  std::vector<BrentStepKind> kinds;  // the kinds seen, in order of first use
  std::vector<std::pair<double, int>> placed;
  for (const auto& step : trace.steps) {
    int stacked = 0;
    for (const auto& [x, n] : placed)
      if (std::abs(x - X(step.t)) < 6) stacked = std::max(stacked, n + 1);
    placed.push_back({X(step.t), stacked});
    c.point(worldAt(c, X(step.t), y - 14 - 8 * stacked), kindColour(step.kind), 3.5, Stroke{palette::background, 1});
    if (std::find(kinds.begin(), kinds.end(), step.kind) == kinds.end()) kinds.push_back(step.kind);
  }
  double ly = y - 16 - 15 * (kinds.size() - 1);
  c.textAtPixel(right + 16, ly - 16, "Brent iterates:", small, Anchor::Right);
  for (BrentStepKind kind : kinds) {
    c.textAtPixel(right + 16, ly, "\u25cf", TextStyle{Font::SansBold, 12, kindColour(kind)}, Anchor::Right);
    c.textAtPixel(right + 30, ly, kindName(kind), small, Anchor::Right);
    ly += 15;
  }
}

// ---- Space-time: x against t (Fig. 1, row A) -----------------------------------------
// "Extrusion intersection tests take a four-dimensional approach": each body swept through
// time is a solid in space-time, and the test asks whether the two solids meet. With x
// across and t upwards, a body's x-extent over [t_0, t_1] is a band: slanted while it
// moves, upright while it rests. In row A the bodies' y-extents overlap at every instant,
// so the bands meet exactly when the bodies do, and x against t shows all there is.
// The inset lies under the bodies, on the panel's own x axis, t from t_0 at `bottom` to t_1 at `top`.
enum class SpaceTime { Static, Sweeping, Extrusion };

// The x-extent [lo, hi] of a body at time t.
std::pair<double, double> xExtent(const Body& b, double t) {
  return {b.at(t).support(V(-1, 0, 0)).x(), b.at(t).support(V(1, 0, 0)).x()};
}

void drawSpaceTime(Canvas& c, const Pair& pair, SpaceTime mode, double bottom, double top, const ToiResult<double>* toi) {
  const auto Y = [&](double t) { return bottom + (top - bottom) * (t - t0) / (t1 - t0); };
  constexpr int samples = 64;
  const double axisX = pair.xmin + 0.4, right = pair.xmax - 0.1;
  const TextStyle small{Font::Math, 13, palette::ink, 2.0, palette::background};
  const TextStyle note{Font::Sans, 12, palette::ink, 2.0, palette::background};
  // The axes: t upwards, coloured by the time ramp (the key of the poses above), and x.
  for (int k = 0; k < 40; ++k)
    c.line(P2(axisX, Y(t0 + (t1 - t0) * k / 40)), P2(axisX, Y(t0 + (t1 - t0) * (k + 1) / 40)),
           Stroke{timeColour(t0 + (t1 - t0) * (k + 0.5) / 40), 4});
  c.arrow(P2(axisX, Y(t1)), P2(axisX, Y(t1) + 0.35), Stroke{palette::ink, 1.0}, 7);
  c.text(P2(axisX, Y(t1) + 0.35), "t", small, Anchor::Left);
  c.arrow(P2(axisX, bottom - 0.12), P2(right, bottom - 0.12), Stroke{palette::ink, 1.0}, 7);
  c.text(P2(right, bottom - 0.12), "x", small, Anchor::Above);
  c.text(P2(axisX, Y(t0)), "t_0", small, Anchor::Left);
  c.text(P2(axisX, Y(t1)), "t_1", small, Anchor::Left);
  if (mode == SpaceTime::Extrusion)  // a tick at each pose drawn above, in its colour
    for (int k = 1; k < 8; ++k)
      c.line(P2(axisX + 0.08, Y(t0 + (t1 - t0) * k / 8)), P2(axisX + 0.25, Y(t0 + (t1 - t0) * k / 8)),
             Stroke{timeColour(t0 + (t1 - t0) * k / 8), 1.5});
  // The bands: each body's x-extent at every t (faint where the test does not look).
  const double bandAlpha = mode == SpaceTime::Extrusion ? 0.55 : 0.18;
  for (const Body* b : {&pair.P, &pair.Q}) {
    const bool isP = b == &pair.P;
    std::vector<P2> band;
    for (int k = 0; k <= samples; ++k) band.push_back(P2(xExtent(*b, t0 + (t1 - t0) * k / samples).first, Y(t0 + (t1 - t0) * k / samples)));
    for (int k = samples; k >= 0; --k) band.push_back(P2(xExtent(*b, t0 + (t1 - t0) * k / samples).second, Y(t0 + (t1 - t0) * k / samples)));
    const Color stroke = isP ? palette::bodyPStroke : palette::bodyQStroke;
    c.polygon(band, ShapeStyle{(isP ? palette::bodyPFill : palette::bodyQFill).withAlpha(bandAlpha),
                               Stroke{stroke.withAlpha(mode == SpaceTime::Extrusion ? 1.0 : 0.35), 1.0}});
  }
  // Where the bands meet: the collision in space-time.
  std::vector<P2> lows, highs;
  for (int k = 0; k <= 4 * samples; ++k) {
    const double t = t0 + (t1 - t0) * k / (4 * samples);
    const auto [p0, p1] = xExtent(pair.P, t);
    const auto [q0, q1] = xExtent(pair.Q, t);
    if (std::max(p0, q0) > std::min(p1, q1)) continue;
    lows.push_back(P2(std::max(p0, q0), Y(t)));
    highs.push_back(P2(std::min(p1, q1), Y(t)));
  }
  if (mode == SpaceTime::Static) {  // two samples: the bodies' extents at t_0 and t_1 only
    for (double t : {t0, t1}) {
      c.line(P2(axisX, Y(t)), P2(right, Y(t)), Stroke{palette::ink, 1.0, style::dashed});
      for (const Body* b : {&pair.P, &pair.Q}) {
        const auto [lo, hi] = xExtent(*b, t);
        c.line(P2(lo, Y(t)), P2(hi, Y(t)), Stroke{b == &pair.P ? palette::bodyPStroke : palette::bodyQStroke, 5});
      }
    }
    c.text(P2(right, Y(t1)), "two samples, both apart: the meeting is between", note, Anchor::AboveLeft);
    return;
  }
  if (mode == SpaceTime::Sweeping) {  // each body's x over the whole interval, whenever it is there
    for (const Body* b : {&pair.P, &pair.Q}) {
      const auto [a0, a1] = xExtent(*b, t0);
      const auto [b0, b1] = xExtent(*b, t1);
      const double lo = std::min(a0, b0), hi = std::max(a1, b1);
      const bool isP = b == &pair.P;
      c.polygon({P2(lo, Y(t0)), P2(hi, Y(t0)), P2(hi, Y(t1)), P2(lo, Y(t1))},
                ShapeStyle{(isP ? palette::bodyPFill : palette::bodyQFill).withAlpha(0.35),
                           Stroke{isP ? palette::bodyPStroke : palette::bodyQStroke, 1.0, style::dashed}});
    }
    c.text(P2(right, Y(t1)), "each body's x over all of [t_0, t_1]: when is lost", note, Anchor::AboveLeft);
    return;
  }
  if (!lows.empty()) {  // the extrusion: the bands themselves, and where they meet
    std::vector<P2> meet = lows;
    meet.insert(meet.end(), highs.rbegin(), highs.rend());
    c.polygon(meet, ShapeStyle{palette::highlight.withAlpha(0.9), Stroke{palette::ink, 1.0}});
  }
  // The interval the test is asked about, as a bracket along t, and the time of impact.
  const double bx = right - 0.15;
  c.line(P2(bx, Y(t0)), P2(bx, Y(t1)), Stroke{palette::ink, 1.5});
  for (double t : {t0, t1}) c.line(P2(bx - 0.12, Y(t)), P2(bx, Y(t)), Stroke{palette::ink, 1.5});
  c.text(P2(bx, Y(t0 + 0.85 * (t1 - t0))), "[t_0, t_1]", small, Anchor::Left, P2(-4, 0));
  c.text(P2(right, Y(t1)), "the bodies swept through time meet", note, Anchor::AboveLeft);
  if (toi && toi->status == ToiStatus::Hit) {
    c.line(P2(axisX, Y(toi->time)), P2(bx, Y(toi->time)), Stroke{palette::penetration, 1.2, style::dashed});
    c.text(P2(bx, Y(toi->time)), "TOI", TextStyle{Font::Sans, 12, palette::penetration, 2.0, palette::background},
           Anchor::BelowLeft, P2(-6, 0));
  }
}

// Panel (col, row) of a grid of w x h cells, less a band of `band` pixels below it for the verdicts.
void panel(Canvas& c, int col, int row, int w, int h, int band, const std::string& title) {
  c.setPanel({col * w, row * h, w, h - band});
  c.title(title);
}
// The same for a panel whose top left corner is at pixel (x, y).
void panelAt(Canvas& c, int x, int y, int w, int h, int band, const std::string& title) {
  c.setPanel({x, y, w, h - band});
  c.title(title);
}

// A verdict in the band below the panel (made the current panel: labels are clipped to
// theirs): green with a tick when right, red with a cross when wrong; a gray note below.
void verdict(Canvas& c, const std::string& text, bool isRight, int band, const std::string& note = "") {
  const PixelRect p = c.panel();
  c.setPanel({p.x, p.y + p.height, p.width, band}, 0, 0);
  c.textAtPixel(p.x + p.width / 2.0, p.y + p.height + 12, text + (isRight ? "  \u2713" : "  \u2717"),
                TextStyle{Font::SansBold, 14, isRight ? right : wrong, 3.0}, Anchor::Center);
  if (!note.empty())
    c.textAtPixel(p.x + p.width / 2.0, p.y + p.height + 32, note, TextStyle{Font::Sans, 12, palette::separating, 3.0});
}

std::string said(bool collision) { return collision ? "collision" : "no collision"; }
// What a verdict is, said against the reference: right, missed, or a false alarm.
std::string judged(bool reported, bool truth) {
  return reported == truth ? " \u2014 right" : (reported ? " \u2014 false alarm" : " \u2014 missed");
}
// The §3 test's status, then the §5 solver's, for standard output.
std::string statuses(const ExtrusionResult<double>& test, const ToiResult<double>& toi) {
  return std::string(toString(test.status)) + " -> " + toString(toi.status) +
         (toi.status == ToiStatus::Hit ? " at t = " + fixed(toi.time, 4) : "");
}
bool collides(const Pair& pair) { return staticTest(pair.P, pair.Q, t0, t1, kTruthSamples); }

// The §3 test, then the §5 solver when the test is undecided; its verdict in words.
std::string solverVerdict(const ExtrusionResult<double>& test, const ToiResult<double>& toi) {
  if (test.status == ExtrusionStatus::NoCollision) return "extrusion: no collision";
  if (toi.status == ToiStatus::Hit) return "extrusion + \u00a75: collision at t = " + fixed(toi.time, 3);
  if (toi.status == ToiStatus::PhotoFinish) return "extrusion + \u00a75: no collision (photo finish)";
  return std::string("extrusion + \u00a75: ") + toString(toi.status);
}

// ---- Fig. 1: "Examples of intersection tests over time" ----------------------------
// "Static intersection tests check for intersection at specific instances in time [...]
// they may have actually passed straight through each other" (row A, left). "Sweeping
// intersection tests [...] conservatively report false alarms that never actually occur,
// because they do not account for the displacement of objects as they move" (row B,
// middle). "Extrusion intersection tests take a four-dimensional approach to detect
// spacio-temporal intersection directly, without misses or false alarms" (right column).
void figure1(const std::string& out, const Pair& passThrough, const Pair& crossing) {
  // Row A is taller: under its bodies, an inset of x against t (drawSpaceTime).
  const int W = 430, heights[] = {470, 350}, tops[] = {0, heights[0]};
  const double insetBottom = passThrough.ymin + 0.3, insetTop = insetBottom + 2.2;
  Canvas c(3 * W, heights[0] + heights[1]);
  std::string summary = "Fig. 1:";
  const std::pair<const Pair*, std::string> rows[] = {{&passThrough, "(A) pass-through"}, {&crossing, "(B) crossing paths"}};
  for (int row = 0; row < 2; ++row) {
    const Pair& pair = *rows[row].first;
    const int H = heights[row], top = tops[row];
    const bool inset = row == 0;
    const bool truth = collides(pair);
    // Static: the bodies at t_0 and t_1 only.
    panelAt(c, 0, top, W, H, 30, rows[row].second + ": static test at t_0 and t_1");
    drawPair(c, pair, 1);
    if (inset) drawSpaceTime(c, pair, SpaceTime::Static, insetBottom, insetTop, nullptr);
    const bool atEnds = staticTest(pair.P, pair.Q, t0, t1, 2);
    verdict(c, "static: " + said(atEnds) + judged(atEnds, truth), atEnds == truth, 30);
    // Sweeping: the swept hulls conv(X(t_0) \cup X(t_1)).
    panelAt(c, W, top, W, H, 30, rows[row].second + ": sweeping test");
    c.setWorldWindow(pair.xmin, pair.xmax, pair.ymin, pair.ymax);
    c.setClip(c.plotArea());
    for (const Body* b : {&pair.P, &pair.Q}) {
      std::vector<V> corners;
      for (double t : {t0, t1})
        for (const V& v : b->shape.vertices()) corners.push_back(b->at(t).worldFromBody(v));
      const bool isP = b == &pair.P;
      c.polygon(xy(Polytope<double>::polygon(corners).vertices()),
                ShapeStyle{isP ? palette::bodyPFill : palette::bodyQFill,
                           Stroke{isP ? palette::bodyPStroke : palette::bodyQStroke, 1.0, style::dashed}});
    }
    drawPair(c, pair, 1);
    if (inset) drawSpaceTime(c, pair, SpaceTime::Sweeping, insetBottom, insetTop, nullptr);
    const bool swept = sweepingTest(pair.P, pair.Q, t0, t1).status != IntersectionStatus::Disjoint;
    verdict(c, "sweeping: " + said(swept) + judged(swept, truth), swept == truth, 30);
    // Extrusion: the §3 test, then the §5 solver when it is undecided.
    panelAt(c, 2 * W, top, W, H, 30, rows[row].second + ": extrusion test");
    drawPair(c, pair, 8, !inset);  // with the inset, its t axis is the key of the poses' colours
    const auto test = extrusionTest(pair.P, pair.Q, t0, t1);
    const auto toi = timeOfImpact(pair.P, pair.Q, t0, t1);
    if (inset) drawSpaceTime(c, pair, SpaceTime::Extrusion, insetBottom, insetTop, &toi);
    drawFound(c, pair, test, toi);
    const bool extruded = reportsCollision(toi.status);
    verdict(c, solverVerdict(test, toi) + judged(extruded, truth), extruded == truth, 30);
    summary += std::string(" ") + "AB"[row] + ": reference " + said(truth) + ", static " + said(atEnds) + ", sweeping " +
               said(swept) + ", extrusion " + statuses(test, toi) + (row == 0 ? ";" : "");
  }
  c.savePng(out + "/fig01-intersection-tests.png");
  chapter::wrote(out + "/fig01-intersection-tests.png");
  std::printf("%s\n", summary.c_str());
}

// ---- Fig. 4: "Extrusion tests robustly give correct results" -----------------------
// "this extrusion test combines the complementary merits of both static and sweeping
// tests, and performs better for a broad scope of rigid body motion (Fig. 4)". Four
// motions, each decided by the extrusion test followed by the §5 solver: (a) a stack of
// blocks in free fall ("even over miniscule time intervals their swept volumes intersect,
// although the blocks themselves never come into contact"), (b) a head-on collision,
// (c) a glancing near miss, (d) one body overtaking another.
void figure4(const std::string& out, const std::vector<std::pair<Pair, std::string>>& panels) {
  const int W = 520, H = 400;
  Canvas c(2 * W, 2 * H);
  std::string summary = "Fig. 4:";
  for (std::size_t k = 0; k < panels.size(); ++k) {
    const Pair& pair = panels[k].first;
    panel(c, int(k % 2), int(k / 2), W, H, 50, panels[k].second);
    const auto test = extrusionTest(pair.P, pair.Q, t0, t1);
    ToiTrace<double> trace;
    const auto toi = timeOfImpact(pair.P, pair.Q, t0, t1, {}, &trace);
    if (toi.status == ToiStatus::PhotoFinish) {  // the chain's poses instead of evenly spaced ones
      drawPair(c, pair, 1);
      drawChain(c, pair, trace, chainOf(pair, trace));
    } else {
      drawPair(c, pair, 6);
    }
    drawFound(c, pair, test, toi);
    const bool truth = collides(pair), extruded = reportsCollision(toi.status);
    std::string text = solverVerdict(test, toi);  // a photo finish: a chain of restarts + 1 intervals
    if (toi.status == ToiStatus::PhotoFinish) text += ", " + std::to_string(toi.restarts + 1) + " intervals";
    const bool atEnds = staticTest(pair.P, pair.Q, t0, t1, 2);
    const bool swept = sweepingTest(pair.P, pair.Q, t0, t1).status != IntersectionStatus::Disjoint;
    verdict(c, text + judged(extruded, truth), extruded == truth, 50,
            "for comparison: static " + said(atEnds) + judged(atEnds, truth) + ",  sweeping " + said(swept) +
                judged(swept, truth));
    summary += std::string(" (") + "abcd"[k] + ") " + statuses(test, toi) + ", reference " + said(truth) +
               (k + 1 < panels.size() ? ";" : "");
  }
  c.savePng(out + "/fig04-extrusion-correct.png");
  chapter::wrote(out + "/fig04-extrusion-correct.png");
  std::printf("%s\n", summary.c_str());
}

// ---- The separating space at t_0 and t_1 (§3) --------------------------------------
// "Consider the space defined by all separating vectors between P(t_0) and Q(t_0). [...]
// if P and Q intersect at t_0, this space is null, otherwise it is an open pyramid
// extending away from the origin. [...] we determine whether the separating space ever
// vanishes in the interim by testing whether the spaces at t_0 and t_1 are disjoint."
// In the plane the pyramid is a wedge of directions: the arc of the unit circle where
// SD > 0. GJK's s_i at t_0 are tried in turn; one in both arcs proves no collision.

// The arcs of radius r over the runs of sampled directions where `inside` holds.
std::vector<std::vector<P2>> arcs(const std::vector<bool>& inside, double r) {
  const int n = int(inside.size());
  int outside = 0;  // start the scan outside every arc (n when every direction is inside)
  while (outside < n && inside[outside]) ++outside;
  std::vector<std::vector<P2>> found;
  for (int j = 0; j < n; ++j) {
    const int k = (outside + 1 + j) % n;
    if (!inside[k]) continue;
    if (j == 0 || !inside[(k + n - 1) % n]) found.emplace_back();
    found.back().push_back(r * xy(direction(k)));
  }
  return found;
}

// The wedges of the directions where `inside` holds, filled, with their arcs.
void drawWedges(Canvas& c, const std::vector<bool>& inside, double radius, const Color& color) {
  for (const auto& arc : arcs(inside, radius)) {
    std::vector<P2> wedge{P2(0, 0)};
    wedge.insert(wedge.end(), arc.begin(), arc.end());
    c.polygon(wedge, ShapeStyle{color.withAlpha(0.2), style::noStroke});
    c.polyline(arc, Stroke{color, 5});
  }
}

std::string degrees(const std::vector<bool>& inside) {
  return std::to_string(std::lround(360.0 * std::count(inside.begin(), inside.end(), true) / kDirections)) + "\u00b0";
}

// The directions panel: SD(t_0, s) > 0 and SD(t_1, s) > 0 on the unit circle, and GJK's s_i at t_0.
std::string drawSpace(Canvas& c, const Pair& pair, const ExtrusionTrace<double>& trace) {
  c.setWorldWindow(-1.45, 1.45, -1.6, 1.4);
  c.axes();
  std::vector<bool> start(kDirections), end(kDirections), both(kDirections);
  for (int k = 0; k < kDirections; ++k) {
    start[k] = supportingDistanceAt(pair.P, pair.Q, direction(k), t0) > 0;
    end[k] = supportingDistanceAt(pair.P, pair.Q, direction(k), t1) > 0;
    both[k] = start[k] && end[k];
  }
  c.circle({0, 0}, 1, ShapeStyle{palette::none, style::axisStroke});
  drawWedges(c, start, 1.0, atStart);
  drawWedges(c, end, 1.08, atEnd);
  for (const auto& arc : arcs(both, 0.92)) {  // the overlap: the vectors that separate over [t_0, t_1]
    c.line({0, 0}, arc.front(), Stroke{right, style::lineThin});
    c.line({0, 0}, arc.back(), Stroke{right, style::lineThin});
    c.polyline(arc, Stroke{right, 5});
  }
  // GJK's s_i at t_0 on the circle: hollow gray where SD(t_0) <= 0, orange where only
  // SD(t_0) > 0, green where both; one label for directions a few degrees apart.
  std::vector<std::pair<V, std::string>> labels;
  for (const auto& step : trace.steps) {
    const Color color = step.separatesEnd ? right : (step.separatesStart ? atStart : palette::separating);
    c.point(xy(step.s), step.separatesStart ? color : palette::background, 5.5, Stroke{color, 2});
    const std::string name = "s_" + std::to_string(step.i);
    if (!labels.empty() && labels.back().first.dot(step.s) > std::cos(0.15)) labels.back().second += ", " + name;
    else labels.push_back({step.s, name});
  }
  for (const auto& [s, name] : labels)
    c.text(1.16 * xy(s), name, TextStyle{Font::Math, style::labelSize, palette::ink, 2.5}, chapter::toward(xy(s)));
  const PixelRect p = c.panel();
  const std::pair<Color, std::string> legend[] = {
      {atStart, "SD(t_0, s) > 0: " + degrees(start)}, {atEnd, "SD(t_1, s) > 0: " + degrees(end)}, {right, "both: " + degrees(both)}};
  for (int k = 0; k < 3; ++k)
    c.textAtPixel(p.x + 16, p.y + p.height - 58 + 20 * k, legend[k].second,
                  TextStyle{Font::Sans, 13, legend[k].first, 2.5}, Anchor::Right);
  return degrees(start) + " at t_0, " + degrees(end) + " at t_1, overlap " + degrees(both);
}

// Top: a pair that misses, whose spaces at t_0 and t_1 overlap; bottom: one that collides,
// whose spaces are disjoint (for it the §5 solver finds the time of impact).
void separatingSpace(const std::string& out, const Pair& apart, const Pair& hitting) {
  const int W = 460, H = 430;
  Canvas c(2 * W, 2 * H);
  std::string summary = "separating space:";
  const std::pair<const Pair*, std::string> rows[] = {{&apart, "no collision"}, {&hitting, "collision"}};
  ExtrusionSettings<double> settings;
  settings.gjk.initialDirection = V(0, 1, 0);  // s_0: "an arbitrary nonzero vector" (a poor one, to show a few s_i)
  for (int row = 0; row < 2; ++row) {
    const Pair& pair = *rows[row].first;
    ExtrusionTrace<double> trace;
    const auto test = extrusionTest(pair.P, pair.Q, t0, t1, settings, nullptr, trace);
    panel(c, 0, row, W, H, 30, "(" + std::string(1, "ac"[row]) + ") " + rows[row].second + ": P and Q at t_0 and t_1");
    drawPair(c, pair, 1);
    const auto toi = timeOfImpact(pair.P, pair.Q, t0, t1);
    drawFound(c, pair, test, toi);
    const bool truth = collides(pair), extruded = reportsCollision(toi.status);
    verdict(c, solverVerdict(test, toi) + judged(extruded, truth), extruded == truth, 30);
    panel(c, 1, row, W, H, 30, "(" + std::string(1, "bd"[row]) + ") separating directions s at t_0 and t_1");
    summary += std::string(row ? "; " : " ") + rows[row].second + ": " + drawSpace(c, pair, trace) + ", " +
               std::to_string(trace.steps.size()) + " s_i, " + statuses(test, toi);
  }
  c.savePng(out + "/separating-space.png");
  chapter::wrote(out + "/separating-space.png");
  std::printf("%s\n", summary.c_str());
}

}  // namespace

int main(int argc, char** argv) {
  const std::string out = chapter::outputFolder(argc, argv);

  // Fig. 1 (A): a small fast square passes straight through a thin fixed plate.
  const Pair passThrough{body(box(0.5, 0.5), glide(V(-3, 0.2, 0), V(6, -0.4, 0))),
                         body(box(0.2, 3.2), Motion<double>::fixed(Pose<double>::identity())),
                         V(0, 1, 0), V(0, 1, 0), -4, 4, -5.2, 2.4};
  // Fig. 1 (B): paths that cross, the crossing passed at different times.
  const Pair crossing{body(box(0.6, 0.6), glide(V(-3.5, 0, 0), V(6, 0, 0))),
                      body(box(0.6, 0.6), glide(V(0.8, -1.2, 0), V(3, 3, 0))), V(0, -1, 0), V(-1, 1, 0), -4.2, 4.6, -2.4, 2.4,
                      true};
  figure1(out, passThrough, crossing);

  // Fig. 4: (a) a stack of two blocks in free fall, (b) head on, (c) near miss, (d) overtaking.
  const auto fall = [](double y) {
    return Motion<double>::constantAcceleration(Pose<double>::translate(V(-2, y, 0)), V(4, 0, 0), V(0, -6, 0));
  };
  const std::vector<V> triangle{V(-0.6, -0.5, 0), V(0.7, 0, 0), V(-0.6, 0.5, 0)};
  const std::vector<V> wedge{V(-0.7, 0, 0), V(0.5, -0.6, 0), V(0.6, 0.5, 0)};
  const std::vector<std::pair<Pair, std::string>> panels{
      {Pair{body(box(1.6, 0.7), fall(0.5)), body(box(1.6, 0.7), fall(1.35)), V(-1, -1, 0), V(1, 1, 0), -3.5, 3.5, -3.2, 2.2},
       "(a) falling together, never touching"},
      {Pair{body(triangle, glide(V(-3, -0.3, 0), V(5, 0.3, 0))), body(wedge, glide(V(3, 0.3, 0), V(-4, -0.2, 0))),
            V(0, -1, 0), V(0, 1, 0), -4.2, 4.2, -1.6, 1.6},
       "(b) head-on collision"},
      {Pair{body(triangle, glide(V(-3, -0.55, 0), V(6, 0, 0))), body(wedge, glide(V(3, 0.62, 0), V(-6, 0, 0))), V(0, -1, 0),
            V(0, 1, 0), -4.2, 4.2, -2.6, 1.6},
       "(c) glancing near miss: a photo finish"},
      {Pair{body(triangle, glide(V(-3.6, 0, 0), V(7, 0.2, 0))), body(box(0.9, 0.9), glide(V(-1.2, 0.1, 0), V(3, 0, 0))),
            V(0, -1, 0), V(0, 1, 0), -4.5, 4.5, -1.6, 1.6},
       "(d) overtaking"}};
  figure4(out, panels);

  // The separating space: a pair that misses (arcs overlap) and one that collides (arcs disjoint).
  const std::vector<V> kite{V(-0.8, -0.3, 0), V(0.4, -0.6, 0), V(0.8, 0.4, 0), V(-0.2, 0.7, 0)};
  const Pair apart{body(kite, glide(V(-2.5, -0.5, 0), V(2, 0.5, 0))), body(triangle, glide(V(1.5, -1, 0), V(0, 3, 0))),
                   V(0, -1, 0), V(1, 0, 0), -3.6, 3.6, -2.4, 2.8};
  const Pair hitting{body(kite, glide(V(-2.5, -0.5, 0), V(5, 1, 0))), body(triangle, glide(V(1.5, -1, 0), V(-1, 1.5, 0))),
                     V(0, -1, 0), V(1, 0, 0), -3.6, 3.6, -2.4, 2.8};
  separatingSpace(out, apart, hitting);
  return 0;
}
