// Chapter 07: Mirtich's Timewarp, the ordering of the collisions the paper's solver finds (§5-§6).
//
// §5: the extrusion solver "returns either 'no collision' or the time of impact for a whole
// interval", which is what Timewarp (Mirtich, "Timewarp Rigid Body Simulation", SIGGRAPH
// 2000) needs: every body runs ahead on its own local time, and a collision found late, at
// t_c before the local times of its bodies, rolls back only those two bodies to t_c. Two
// figures, drawn from the world's own trace (WorldSettings::trace) of a Newton's cradle in
// space (five balls, the first 3 cm from a row of four 2 cm apart, e = 1, no gravity, the
// first ball at 1 m/s), over three frames of 1/24 s:
//   fig-timewarp-spacetime.png  one row per ball, simulated time to the right: each ball's
//       local time flown to the frame's end, the collisions (red) between the rows, the
//       paths discarded by a rollback (grey, raised, with the arrow back to t_c) and the
//       path re-flown from t_c; the balls a collision does not touch keep their flight;
//   fig-timewarp-orderings.png  the same three frames under the three orderings (Timewarp,
//       the time-of-impact heap, fixed steps with static tests), each with its counts of
//       pair checks, collisions, rollbacks and body flights discarded.
// Nothing in a figure depends on the wall clock: the trace and the counters are exact
// functions of the scene. --scene draws any gjkx_simulate scene instead of the cradle and
// --frames sets the frames drawn; --trace prints the Timewarp run event by event
// (docs/traces.md).
#include "../chapter.hpp"
#include "runs.hpp"

#include <gjkx/render/canvas.hpp>
#include <gjkx/timewarp/scene.hpp>
#include <gjkx/timewarp/world.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <regex>
#include <string>
#include <vector>

using namespace gjkx;
using namespace gjkx::render;
using P2 = Eigen::Vector2d;
using namespace timewarp_figures;

namespace {

const Color kFlight = Color::hex(0x1F5FA8);     // a flight from the frame's start
const Color kReflown = Color::hex(0xD9730D);    // a flight re-flown from a collision
const Color kDiscarded = Color::hex(0x9A9A9A);  // a path a rollback (or a cut) discarded
const Color kCollision = palette::penetration;  // a collision
const TextStyle kSmall{Font::Sans, 13, palette::ink, 2.0};
const TextStyle kSmallGrey{Font::Sans, 12, Color::hex(0x5A5A5A), 2.0};

// ---- the trace as pieces of path per body --------------------------------------------------

// A flight of one body: flown over [start, end], kept up to `keep` (the rest discarded by a
// later rollback or cut), raised to `lane` where discarded so that discarded pieces that
// overlap in time do not hide each other.
struct Piece {
  int body;
  double start, end, keep;
  bool fromCollision;  // flown from a collision (not from the frame's start)
  int lane = 0;
};
struct Collision {
  int i, j;
  double t;
  int number;  // in the order the ordering resolved them
};
struct Rollback {
  int body;
  double from, to;  // the local time before and after
  int number;       // of the collision that caused it
};
struct Story {
  std::vector<Piece> pieces;
  std::vector<Collision> collisions;
  std::vector<Rollback> rollbacks;
  long checks = 0;
};

Story tell(const Run& r) {
  Story s;
  std::vector<bool> afterCollision(r.names.size(), false);
  for (const TraceEvent& e : r.trace) {
    switch (e.kind) {
      case TraceEvent::Kind::Advance: {
        // A new flight from `from` cuts the body's earlier flights that ran past it.
        for (Piece& p : s.pieces)
          if (p.body == e.body && p.keep > e.from + 1e-12) p.keep = std::max(p.start, e.from);
        s.pieces.push_back({e.body, e.from, e.to, e.to, afterCollision[std::size_t(e.body)], 0});
        afterCollision[std::size_t(e.body)] = false;
        break;
      }
      case TraceEvent::Kind::Collision:
        s.collisions.push_back({e.body, e.other, e.to, int(s.collisions.size()) + 1});
        afterCollision[std::size_t(e.body)] = afterCollision[std::size_t(e.other)] = true;
        break;
      case TraceEvent::Kind::Rollback:
        s.rollbacks.push_back({e.body, e.from, e.to, int(s.collisions.size())});
        break;
      case TraceEvent::Kind::Check: ++s.checks; break;
    }
  }
  // Lanes: the discarded part of a piece goes one lane above every earlier discarded part
  // of the same body that it overlaps in time.
  for (std::size_t a = 0; a < s.pieces.size(); ++a) {
    Piece& p = s.pieces[a];
    if (p.keep >= p.end - 1e-12) continue;
    std::vector<int> used;
    for (std::size_t b = 0; b < a; ++b) {
      const Piece& q = s.pieces[b];
      if (q.body == p.body && q.keep < q.end - 1e-12 && q.keep < p.end - 1e-12 && p.keep < q.end - 1e-12)
        used.push_back(q.lane);
    }
    p.lane = 1;
    while (std::count(used.begin(), used.end(), p.lane)) ++p.lane;
  }
  return s;
}

// ---- drawing -----------------------------------------------------------------------------

// The plot: time [0, tEnd] to pixels [x0, x1]; body rows from y0 down, `rowH` apart.
struct Layout {
  double x0, x1, y0, rowH, laneH, tEnd;
  double tick = 0.01;  // seconds between ticks of the time axis (every other one labelled)
  double X(double t) const { return x0 + (x1 - x0) * t / tEnd; }
  double Y(int body, int lane = 0) const { return y0 + rowH * (body + 0.62) - laneH * lane; }
};

// The canvas in pixel units, y up: world (x, y) is pixel (x, height - y).
struct Pixels {
  Canvas& c;
  double height;
  P2 at(double x, double y) const { return P2(x, height - y); }
};

// A curved arrow from a discarded local time back to t_c (above the row).
void backArrow(Pixels& px, const Layout& L, const Rollback& r, int lane) {
  const double xa = L.X(r.from), xb = L.X(r.to), ya = L.Y(r.body, lane), yb = L.Y(r.body, 0);
  const double lift = 10 + 7 * lane;
  std::vector<P2> arc;
  const int n = 24;
  for (int k = 0; k <= n; ++k) {
    const double u = double(k) / n;
    const double x = xa + (xb - xa) * u;
    const double y = ya + (yb - ya) * u - lift * std::sin(M_PI * u);
    arc.push_back(px.at(x, y));
  }
  const Stroke stroke{kCollision.withAlpha(0.85), 1.6};
  arc.pop_back();
  px.c.polyline(arc, stroke);
  px.c.arrow(arc.back(), px.at(xb, yb - 2.5), stroke, 9);
}

void drawStory(Canvas& c, double height, const Layout& L, const Run& r, const Story& s, bool numbers,
               bool arrows) {
  Pixels px{c, height};
  const int bodies = int(r.names.size());
  // Frames: alternate shading, dashed ends, labels.
  for (int f = 0; f < r.frames; ++f) {
    const double a = L.X(f / r.frameRate), b = L.X((f + 1) / r.frameRate);
    const double top = L.y0 - 4, bottom = L.y0 + L.rowH * bodies;
    if (f % 2 == 1)
      c.polygon({px.at(a, top), px.at(b, top), px.at(b, bottom), px.at(a, bottom)},
                ShapeStyle{Color::hex(0xF1F1F1), style::noStroke});
    c.line(px.at(b, top), px.at(b, bottom), Stroke{palette::axis, 1.0, style::dashed});
    c.text(px.at(0.5 * (a + b), top), "frame " + std::to_string(f + 1), kSmallGrey, Anchor::Below, P2(0, -2));
  }
  // Rows: names and a hairline.
  for (int b = 0; b < bodies; ++b) {
    c.line(px.at(L.x0, L.Y(b)), px.at(L.x1, L.Y(b)), Stroke{palette::grid, 1.0});
    c.text(px.at(L.x0, L.Y(b)), r.names[std::size_t(b)], TextStyle{Font::Sans, 14, palette::ink, 2.0}, Anchor::Left,
           P2(-8, 0));
  }
  // Discarded parts first (under everything), then kept parts on the row's line.
  for (const Piece& p : s.pieces) {
    if (p.keep >= p.end - 1e-12) continue;
    const double y = L.Y(p.body, p.lane);
    c.line(px.at(L.X(p.keep), y), px.at(L.X(p.end), y), Stroke{kDiscarded, 3.0, Dash{6, 4}});
    // Struck out: short slashes along it.
    for (double x = L.X(p.keep) + 8; x < L.X(p.end) - 3; x += 16)
      c.line(px.at(x - 3, y - 4), px.at(x + 3, y + 4), Stroke{kDiscarded, 1.4});
    c.line(px.at(L.X(p.end), y - 5), px.at(L.X(p.end), y + 5), Stroke{kDiscarded, 2.0});
  }
  for (const Piece& p : s.pieces) {
    if (p.keep <= p.start + 1e-12) continue;
    const double y = L.Y(p.body);
    c.line(px.at(L.X(p.start), y), px.at(L.X(p.keep), y), Stroke{p.fromCollision ? kReflown : kFlight, 4.0});
    c.line(px.at(L.X(p.start), y - 6), px.at(L.X(p.start), y + 6), Stroke{palette::ink, 1.2});
  }
  if (arrows)
    for (const Rollback& rb : s.rollbacks) {
      int lane = 1;  // the lane of the piece whose end it leaves
      for (const Piece& p : s.pieces)
        if (p.body == rb.body && std::abs(p.end - rb.from) < 1e-12 && p.keep < p.end - 1e-12) lane = p.lane;
      backArrow(px, L, rb, lane);
    }
  // Collisions: a red line between the two rows, a dot on each, the number.
  for (const Collision& k : s.collisions) {
    const double x = L.X(k.t);
    c.line(px.at(x, L.Y(k.i)), px.at(x, L.Y(k.j)), Stroke{kCollision, 2.2});
    for (int b : {k.i, k.j}) c.point(px.at(x, L.Y(b)), kCollision, 5, Stroke{palette::background, 1.5});
    if (numbers)
      c.text(px.at(x, 0.5 * (L.Y(k.i) + L.Y(k.j))), std::to_string(k.number),
             TextStyle{Font::SansBold, 14, kCollision, 3.0}, Anchor::Right, P2(5, 0));
  }
  // The time axis.
  const double yAxis = L.y0 + L.rowH * bodies + 2;
  c.line(px.at(L.x0, yAxis), px.at(L.x1, yAxis), style::axisStroke);
  for (double t = 0; t <= L.tEnd + 1e-9; t += L.tick) {
    const bool major = std::lround(t / L.tick) % 2 == 0;
    c.line(px.at(L.X(t), yAxis), px.at(L.X(t), yAxis + (major ? 5 : 3)), style::axisStroke);
    if (major)
      c.text(px.at(L.X(t), yAxis + 5), format(L.tick >= 0.01 ? "%.2f" : "%.3f", t), smallText, Anchor::Below, P2(0, -1));
  }
  c.text(px.at(L.x1, yAxis + 5), "simulated time (s)", kSmall, Anchor::BelowLeft, P2(0, -18));
}

// An ordering's name as the scene file writes it, with its underscore escaped for the markup.
std::string escaped(const std::string& name) {
  std::string text;
  for (char ch : name) text += ch == '_' ? std::string("\\_") : std::string(1, ch);
  return text;
}

// The legend of the drawing, one line from pixel x along y.
void legend(Canvas& c, double height, double x, double y, bool rollbacks) {
  Pixels px{c, height};
  auto sample = [&](const Stroke& stroke, const std::string& text, double width) {
    c.line(px.at(x, y), px.at(x + 30, y), stroke);
    c.text(px.at(x + 38, y), text, kSmall, Anchor::Right);
    x += width;
  };
  sample(Stroke{kFlight, 4.0}, "flown from the frame's start (kept)", 290);
  sample(Stroke{kReflown, 4.0}, "re-flown from a collision (kept)", 275);
  sample(Stroke{kDiscarded, 3.0, Dash{6, 4}}, rollbacks ? "discarded by a rollback to t_c" : "flown, then discarded", 270);
  c.line(px.at(x, y), px.at(x + 30, y), Stroke{kCollision, 2.2});
  c.point(px.at(x + 15, y), kCollision, 5, Stroke{palette::background, 1.5});
  c.text(px.at(x + 38, y), "collision at t_c", kSmall, Anchor::Right);
}

std::string balls(const Run& r, const std::vector<int>& which) {
  std::string text;
  for (std::size_t k = 0; k < which.size(); ++k)
    text += (k == 0 ? "" : k + 1 == which.size() ? " and " : ", ") + r.names[std::size_t(which[k])];
  return text.empty() ? "none" : text;
}

// ---- fig-timewarp-spacetime.png --------------------------------------------------------

// `custom`: a reader's scene, laid out for its bodies and collisions (the cradle's is as the
// paper's figure is kept).
void spacetime(const std::string& out, const Run& r, bool custom) {
  const Story s = tell(r);
  const int rows = int(r.names.size());
  const int W = 1250, H = custom ? 74 + 78 * rows + 110 + 19 * int(s.collisions.size()) : 650;
  Canvas c(W, H);
  c.setPanel({0, 0, W, H}, 0, 0);
  c.setWorldWindow(0, W, 0, H);
  c.title("");
  Pixels px{c, double(H)};
  c.text(px.at(W / 2.0, 14),
         custom ? "Timewarp: every body's local time runs to the frame's end; a collision found there rolls back "
                  "only its two bodies"
                : "Timewarp on a Newton's cradle: every ball's local time runs to the frame's end; "
                  "a collision found there rolls back only its two balls",
         TextStyle{Font::SansBold, 16, palette::ink}, Anchor::Below);
  Layout L{110, double(W) - 40, 74, 78, 13, r.frames / r.frameRate};
  if (custom) L.tick = chapter::roundStep(L.tEnd, 12);
  drawStory(c, H, L, r, s, true, true);
  if (!custom) {
    // Where a ball's local time stands after the first flight of frame 1, and what the
    // frame's end means.
    const double T1 = 1 / kFrameRate;
    c.text(px.at(L.X(T1), L.Y(4)), "local time of ball5: T_1", kSmallGrey, Anchor::BelowLeft, P2(-4, -4));
    c.text(px.at(L.X(2 * T1), L.Y(4)), "queue empty: frame 2 final", kSmallGrey, Anchor::BelowLeft, P2(-4, -4));
  }
  double y = L.y0 + L.rowH * rows + 52;
  legend(c, H, 110, y, true);
  // What happened, collision by collision, from the trace.
  y += 28;
  for (const Collision& k : s.collisions) {
    std::vector<int> rolled, untouched;
    std::string from;
    for (const Rollback& rb : s.rollbacks)
      if (rb.number == k.number) {
        rolled.push_back(rb.body);
        from = format("%.4f s", rb.from);
      }
    for (int b = 0; b < int(r.names.size()); ++b)
      if (b != k.i && b != k.j) untouched.push_back(b);
    const int frame = int(std::floor(k.t * r.frameRate)) + 1;
    std::string line = std::to_string(k.number) + ".  frame " + std::to_string(frame) + ": " +
                       r.names[std::size_t(k.i)] + " hits " + r.names[std::size_t(k.j)] + " at t_c = " +
                       format("%.4f s", k.t) + ", found after both had flown to " + from + "; rolled back to t_c: " +
                       balls(r, rolled) + ";  not touched: " + balls(r, untouched);
    c.text(px.at(110, y), line, kSmall, Anchor::Right);
    y += 19;
  }
  chapter::save(c, out, "fig-timewarp-spacetime");
}

// ---- fig-timewarp-orderings.png --------------------------------------------------------

void orderings(const std::string& out, const std::vector<Run>& runs, bool custom) {
  const int W = 1250, panelH = custom ? 100 + 46 * int(runs[0].names.size()) : 330, H = panelH * int(runs.size()) + 70;
  Canvas c(W, H);
  c.setPanel({0, 0, W, H}, 0, 0);
  c.setWorldWindow(0, W, 0, H);
  Pixels px{c, double(H)};
  const char* titles[] = {"Timewarp: a collision rolls back only its two balls",
                          "time-of-impact heap: every ball is advanced to each impact",
                          "fixed steps (8 per frame), static tests at each step's end: collisions found late"};
  for (std::size_t k = 0; k < runs.size(); ++k) {
    const Run& r = runs[k];
    const Story s = tell(r);
    const double top = 40 + panelH * double(k);
    std::string title = titles[k];
    if (custom) title = std::regex_replace(std::regex_replace(title, std::regex("balls"), "bodies"), std::regex("ball"), "body");
    c.text(px.at(110, top - 8), "\"" + escaped(orderingName(r.ordering)) + "\": " + title,
           TextStyle{Font::SansBold, 15, palette::ink}, Anchor::BelowRight);
    const FrameCounters& t = r.total;
    const std::string counts = "pair checks " + std::to_string(t.collisionChecks) + "   collisions " +
                               std::to_string(t.collisions) + "   rollbacks " + std::to_string(t.rollbacks) +
                               "   body flights cut " + std::to_string(t.bodiesRolledBack) + "   events " +
                               std::to_string(t.events) + "   deepest penetration " +
                               format("%.1f mm", 1000 * t.maxPenetration);
    c.text(px.at(110, top + 12), counts, TextStyle{Font::Sans, 13.5, kCollision.withAlpha(1), 2.0},
           Anchor::BelowRight);
    Layout L{110, double(W) - 40, top + 52, 46, 9, r.frames / r.frameRate};
    if (custom) L.tick = chapter::roundStep(L.tEnd, 12);
    drawStory(c, H, L, r, s, false, r.ordering == Ordering::Timewarp);
    std::printf("%-10s pair checks %ld, collisions %ld, rollbacks %ld, body flights cut %ld, events %ld, "
                "deepest penetration %.6f m, tunnelled %ld\n",
                orderingName(r.ordering), t.collisionChecks, t.collisions, t.rollbacks, t.bodiesRolledBack,
                t.events, t.maxPenetration, t.tunnelled);
  }
  legend(c, H, 110, H - 14, false);
  chapter::save(c, out, "fig-timewarp-orderings");
}

}  // namespace

int main(int argc, char** argv) {
  std::string out = ".", scenePath;
  int frames = kFrames;
  bool trace = false;
  CLI::App app{"Draws chapter 07's figures in DIR: Timewarp on a Newton's cradle, or on a scene of your own "
               "(--scene), under the three orderings. --trace prints the Timewarp run event by event "
               "(docs/traces.md)."};
  chapter::addFigureOptions(app, out);
  chapter::addTraceOption(app, trace);
  app.add_option("--scene", scenePath, "a scene file, as gjkx_simulate runs (default: the cradle)")->type_name("FILE");
  app.add_option("--frames", frames, "the frames run and drawn (at most the scene's)")
      ->check(CLI::Range(1, 10000))
      ->capture_default_str();
  chapter::parseOrExit(app, argc, argv);
  std::optional<Scene> scene;
  if (!scenePath.empty()) {
    try {
      scene = loadScene(scenePath);
    } catch (const std::exception& e) {
      chapter::badOption(app, "--scene", e.what());
    }
  }
  std::filesystem::create_directories(out);
  const bool custom = scene.has_value() || frames != kFrames;
  std::vector<Run> runs;
  for (Ordering o : {Ordering::Timewarp, Ordering::ToiHeap, Ordering::FixedStep}) runs.push_back(run(o, scene, frames));
  if (trace) printTrace(runs[0]);
  spacetime(out, runs[0], custom);
  orderings(out, runs, custom);
  return 0;
}
