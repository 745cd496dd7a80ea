// Chapter 03: supporting distance (§2.3) and its maximum (§4), Fig. 3 of the paper.
//
// SD(P, Q, s) = s.S_Q(-s) - s.S_P(s) "is the signed distance between the supporting
// planes of P and Q in opposing directions of s". We draw, for two polygons in z = 0:
//   (a) a separating vector: the two supporting lines normal to s leave a gap, SD > 0;
//   (b) a direction that does not separate: the lines cross over, SD < 0;
//   (c) SD as a function of the direction's angle, with (a), (b) and the maximum marked;
//   (d) the maximum over all directions when P and Q are disjoint: the closest distance;
//   (e) the maximum when they intersect: minus the penetration depth (§4, "a negative
//       value is the penetration distance when they intersect");
//   (f) SD over the angle for the intersecting pair: it never reaches zero.
// Options move Q and turn s_a and s_b; --trace prints the directions drawn and their SD
// (docs/traces.md).
#include "../chapter.hpp"

#include <gjkx/render/canvas.hpp>
#include <gjkx/support_mapping/placed.hpp>
#include <gjkx/support_mapping/polytope.hpp>
#include <gjkx/supporting_distance/intersection.hpp>
#include <gjkx/supporting_distance/supporting_distance.hpp>

#include <cmath>
#include <optional>
#include <tuple>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

using namespace gjkx;
using namespace gjkx::render;
using V = Vector3<double>;
using chapter::xy;
using Body = Placed<Polytope<double>>;

namespace {

constexpr int kSamples = 1440;  // directions on the unit circle: a quarter degree apart

V direction(double angle) { return V(std::cos(angle), std::sin(angle), 0); }

using chapter::fixed;

std::vector<Eigen::Vector2d> outline(const Body& body) {
  std::vector<Eigen::Vector2d> points;
  for (const V& v : body.shape.vertices()) points.push_back(xy(body.worldFromBody(v)));
  return points;
}

void drawBodies(Canvas& canvas, const Body& P, const Body& Q) {
  canvas.polygon(outline(P), style::bodyP);
  canvas.polygon(outline(Q), style::bodyQ);
  // Each name on the far side of its body's centre, clear of the contact.
  const Eigen::Vector2d apart = (xy(Q.center()) - xy(P.center())).normalized();
  canvas.text(xy(P.center()) - 0.9 * apart, "P", TextStyle{Font::Math, 22, palette::bodyPStroke});
  canvas.text(xy(Q.center()) + 0.6 * apart, "Q", TextStyle{Font::Math, 22, palette::bodyQStroke});
}

// The supporting lines of P and Q normal to s, through S_P(s) and S_Q(-s), and the
// signed gap between them measured along s from S_P(s): green when positive, red when not.
// `qLabel`, when given, is the side of S_Q(-s) its name goes to (where the default side
// would put it over Q's outline).
void drawSupportingDistance(Canvas& canvas, const Body& P, const Body& Q, const V& s, const std::string& name,
                            std::optional<Anchor> qLabel = std::nullopt) {
  const V unit = s.normalized();
  const V sp = P.support(unit), sq = Q.support(-unit);
  const double sd = supportingDistance(P, Q, unit);
  const V along(-unit.y(), unit.x(), 0);
  for (const V& through : {sp, sq}) canvas.line(xy(through) - 30 * xy(along), xy(through) + 30 * xy(along), style::separatingStroke);
  const Color color = sd > 0 ? palette::direction : palette::penetration;
  // The gap, drawn between the supporting lines beyond both bodies (past the furthest
  // point of either along the lines), so it hides neither body nor the contact.
  const double reach = std::max(along.dot(P.support(along)), along.dot(Q.support(along)));
  const Eigen::Vector2d from = xy(sp) + (reach - along.dot(sp) + 0.6) * xy(along), to = from + sd * xy(unit);
  canvas.arrow(from, to, Stroke{color, style::lineThick});
  canvas.arrow(to, from, Stroke{color, style::lineThick});
  // Its value beside it, outward; when outward is down and to the left (towards the
  // panel's edge), over the arrow's upper end instead.
  const TextStyle valueStyle{Font::Math, style::labelSize, color, 3.0, palette::background};
  if (along.y() < 0) {
    const Eigen::Vector2d upper = from.y() > to.y() ? from : to;
    canvas.text(upper, "SD = " + fixed(sd), valueStyle, Anchor::AboveRight);
  } else {
    canvas.text(0.5 * (from + to) + 0.3 * xy(along), "SD = " + fixed(sd), valueStyle, chapter::toward(xy(along)));
  }
  // s itself, drawn from the panel's lower left corner.
  const Eigen::Vector2d corner(-1.2, -2.2);
  canvas.arrow(corner, corner + 1.6 * xy(unit), style::directionStroke);
  canvas.text(corner + 1.6 * xy(unit), name, TextStyle{Font::Math, style::labelSize, palette::direction},
              chapter::toward(xy(unit)));
  canvas.point(xy(sp), palette::bodyPStroke, 4.5);
  canvas.point(xy(sq), palette::bodyQStroke, 4.5);
  // The support points' names on the side away from the gap's arrow, over a halo.
  const TextStyle label{Font::Math, style::labelSize, palette::ink, 3.0, palette::background};
  canvas.text(xy(sp), "S_P(" + name + ")", label, chapter::toward(-xy(unit) - 1.5 * xy(along)));
  canvas.text(xy(sq), "S_Q(-" + name + ")", label, qLabel.value_or(chapter::toward(xy(unit) - 1.5 * xy(along))),
              qLabel ? Eigen::Vector2d(10, -30) : Eigen::Vector2d::Zero());
}

// SD over the angle of s in [0, 2 pi), scaled so the plot fills the panel.
// A marked direction of a profile: its angle, its name, and where its name goes.
struct Mark {
  double angle;
  std::string label;
  Anchor anchor;
};

void drawProfile(Canvas& canvas, const Body& P, const Body& Q, const std::vector<Mark>& marks) {
  std::vector<double> sd(kSamples);
  double lo = 0, hi = 0;
  for (int k = 0; k < kSamples; ++k) {
    sd[k] = supportingDistance(P, Q, direction(2 * M_PI * k / kSamples));
    lo = std::min(lo, sd[k]);
    hi = std::max(hi, sd[k]);
  }
  const double width = 1.6 * (hi - lo);  // x = angle scaled to this many SD units
  auto at = [&](double angle, double value) { return Eigen::Vector2d(angle / (2 * M_PI) * width, value); };
  canvas.setWorldWindow(-0.12 * width, 1.05 * width, lo - 0.15 * (hi - lo), hi + 0.3 * (hi - lo));
  canvas.setClip(canvas.plotArea());  // long lines stop at the plot area
  canvas.line(at(0, 0), at(2 * M_PI, 0), style::axisStroke);
  canvas.line(at(0, lo), at(0, hi), style::axisStroke);
  std::vector<Eigen::Vector2d> curve;
  for (int k = 0; k <= kSamples; ++k) curve.push_back(at(2 * M_PI * k / kSamples, sd[k % kSamples]));
  canvas.polyline(curve, Stroke{palette::ink, style::lineThin});
  canvas.text(at(1.5 * M_PI, 0), "angle of s", smallText, Anchor::Below);
  for (const auto& [angle, tick] : {std::pair<double, const char*>{0, "0"}, {M_PI, "\u03c0"}, {2 * M_PI, "2\u03c0"}}) {
    canvas.line(at(angle, 0), at(angle, 0) + Eigen::Vector2d(0, -0.03 * (hi - lo)), style::axisStroke);
    canvas.text(at(angle, 0), tick, smallText, angle > M_PI ? Anchor::BelowLeft : Anchor::BelowRight);
  }
  canvas.text(at(0, hi + 0.2 * (hi - lo)), "SD", mathLabel, Anchor::Left);
  for (const Mark& mark : marks) {
    const double value = supportingDistance(P, Q, direction(mark.angle));
    const Color color = value > 0 ? palette::direction : palette::penetration;
    canvas.line(at(mark.angle, 0), at(mark.angle, value), Stroke{color, 1.0, style::dotted});
    canvas.point(at(mark.angle, value), color, 4.5);
    canvas.text(at(mark.angle, value), mark.label, TextStyle{Font::Math, style::labelSize, color, 3.0}, mark.anchor);
  }
}

// The best of the sampled directions: the maximum supporting distance (§4).
MaximumSupportingDistance<double> maximum(const Body& P, const Body& Q) {
  std::vector<V> dirs;
  for (int k = 0; k < kSamples; ++k) dirs.push_back(direction(2 * M_PI * k / kSamples));
  return maximumSupportingDistance(P, Q, dirs);
}

double angleOf(const V& s) { return std::fmod(std::atan2(s.y(), s.x()) + 2 * M_PI, 2 * M_PI); }

// The directions the figure draws as a table (--trace): per direction, S_P(s), S_Q(-s) and
// SD(P, Q, s) = s.S_Q(-s) - s.S_P(s) (§2.3), positive when s is a separating vector.
void printDirections(const std::vector<std::tuple<std::string, const Body*, const Body*, V>>& rows) {
  using chapter::pointCell;
  chapter::TraceTable table{"fig03-supporting-distance: the directions drawn (§2.3, §4)",
                            {"panel", "s (unit)", "angle", "S_P(s)", "S_Q(-s)", "SD", "s separates"}, {}};
  for (const auto& [panel, P, Q, direction] : rows) {
    const V unit = direction.normalized();
    const double sd = supportingDistance(*P, *Q, unit);
    table.rows.push_back({panel, pointCell(unit, 4), fixed(angleOf(unit), 4), pointCell(V(P->support(unit))),
                          pointCell(V(Q->support(-unit))), fixed(sd, 6), sd > 0 ? "yes" : "no"});
  }
  table.print();
}

}  // namespace

int main(int argc, char** argv) {
  std::string out = ".", apartText = "6.5,0.5,0.3", insideText = "3.2,0.8,0.3";
  double separatingAngle = 0.75, otherAngle = 1.9;
  bool trace = false;
  CLI::App app{"Draws Fig. 3 of the paper in DIR: the supporting distance and its maximum. The options move Q and "
               "turn s_a and s_b; --trace prints the directions drawn (docs/traces.md)."};
  chapter::addFigureOptions(app, out);
  chapter::addTraceOption(app, trace);
  chapter::addPoseOption(app, "--q-apart", apartText,
                         "Q's pose in panels (a)-(d): where its origin goes, its angle (radians)");
  chapter::addPoseOption(app, "--q-inside", insideText, "Q's pose in panels (e)-(f), as --q-apart");
  app.add_option("--angle-a", separatingAngle, "the angle of s_a (radians)")
      ->check(CLI::Range(-100.0, 100.0))
      ->capture_default_str();
  app.add_option("--angle-b", otherAngle, "the angle of s_b (radians)")->check(CLI::Range(-100.0, 100.0))->capture_default_str();
  chapter::parseOrExit(app, argc, argv);
  std::filesystem::create_directories(out);

  const auto pentagon = Polytope<double>::polygon({V(0, 0, 0), V(3, -0.5, 0), V(4, 2, 0), V(2, 4, 0), V(-0.5, 2.5, 0)});
  const auto quad = Polytope<double>::polygon({V(0, 0, 0), V(2.5, 0.5, 0), V(2, 3, 0), V(-0.5, 2, 0)});
  const Body P = place(pentagon, Pose<double>::identity());
  const Body Qapart = place(quad, chapter::planarPose(chapter::numberList(apartText)));
  const Body Qinside = place(quad, chapter::planarPose(chapter::numberList(insideText)));

  const auto bestApart = maximum(P, Qapart);
  const auto bestInside = maximum(P, Qinside);
  const auto distance = gjk(P, Qapart);
  if (trace)
    printDirections({{"(a) s_a", &P, &Qapart, direction(separatingAngle)},
                     {"(b) s_b", &P, &Qapart, direction(otherAngle)},
                     {"(d) max, disjoint", &P, &Qapart, bestApart.direction},
                     {"(e) max, intersecting", &P, &Qinside, bestInside.direction}});

  const int W = 440, H = 380;
  Canvas canvas(3 * W, 2 * H);
  auto panel = [&](int col, int row, const std::string& title) {
    canvas.setPanel({col * W, row * H, W, H});
    canvas.title(title);
  };
  // The titles say what the directions do (for the figure's query: s_a separates, s_b does not).
  auto verdict = [&](double angle, const std::string& name) {
    const double sd = supportingDistance(P, Qapart, direction(angle));
    return sd > 0 ? name + " separates: SD > 0" : name + " does not separate: SD " + (sd < 0 ? "< 0" : "= 0");
  };
  panel(0, 0, "(a) " + verdict(separatingAngle, "s_a"));
  canvas.setWorldWindow(-2, 11, -3, 6);
  canvas.setClip(canvas.plotArea());  // long lines stop at the plot area
  drawBodies(canvas, P, Qapart);
  drawSupportingDistance(canvas, P, Qapart, direction(separatingAngle), "s_a");

  panel(1, 0, "(b) " + verdict(otherAngle, "s_b"));
  canvas.setWorldWindow(-2, 11, -3, 6);
  canvas.setClip(canvas.plotArea());  // long lines stop at the plot area
  drawBodies(canvas, P, Qapart);
  drawSupportingDistance(canvas, P, Qapart, direction(otherAngle), "s_b");

  panel(2, 0, "(c) SD(P, Q, s) over all directions");
  // The maximum lies just before s_a: its name goes to the left, s_a's to the right.
  drawProfile(canvas, P, Qapart,
              {{separatingAngle, "s_a", Anchor::AboveRight}, {otherAngle, "s_b", Anchor::Left}, {angleOf(bestApart.direction), "max", Anchor::AboveLeft}});

  panel(0, 1, "(d) disjoint: max SD = distance = " + fixed(bestApart.value));
  canvas.setWorldWindow(-2, 11, -3, 6);
  canvas.setClip(canvas.plotArea());  // long lines stop at the plot area
  drawBodies(canvas, P, Qapart);
  drawSupportingDistance(canvas, P, Qapart, bestApart.direction, "s", Anchor::BelowLeft);  // below the gap, clear of Q
  canvas.line(xy(distance.witnessP), xy(distance.witnessQ), Stroke{palette::ink, 1.0, style::dotted});

  panel(1, 1, "(e) intersecting: max SD = -depth = " + fixed(bestInside.value));
  canvas.setWorldWindow(-3, 9, -3, 6);
  canvas.setClip(canvas.plotArea());  // long lines stop at the plot area
  drawBodies(canvas, P, Qinside);
  drawSupportingDistance(canvas, P, Qinside, bestInside.direction, "s");

  panel(2, 1, "(f) intersecting: SD < 0 in every direction");
  drawProfile(canvas, P, Qinside, {{angleOf(bestInside.direction), "max", Anchor::AboveRight}});

  chapter::save(canvas, out, "fig03-supporting-distance");
  std::printf("disjoint:     max SD over %d directions = %.4f, GJK distance = %.4f\n", kSamples, bestApart.value,
              distance.distance);
  std::printf("intersecting: max SD over %d directions = %.4f (minus the penetration depth); static test: %s\n",
              kSamples, bestInside.value, toString(intersect(P, Qinside).status));
  return 0;
}
