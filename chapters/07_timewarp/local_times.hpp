// gjkx_animate --timewarp: Timewarp (Mirtich 2000; §5-§6) shown event by event.
//
// Above, every body is drawn where it is at its own local time, with that time over it;
// below, one row per moving body against simulated time: the flight it has flown (blue from
// the frame's start, orange re-flown from a collision), the flights a rollback discarded
// (grey, raised), the collisions (red), the frame ends, and the global virtual time (green):
// the time before which no body's history changes any more. The animation steps through the
// world's trace (TraceEvent): a flight slides the body's local time ahead; a collision found
// late flashes its pair; a rollback shows the discarded flight as a red ghost where the body
// had run to, and the body back at t_c, while the bodies the collision does not touch keep
// their flights.
#pragma once

#include "../webp_animation.hpp"
#include "scene_view.hpp"
#include "timewarp_replay.hpp"

#include <gjkx/render/canvas.hpp>

#include <algorithm>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

namespace animation {

/// What --timewarp draws.
struct TimewarpOptions {
  int frames = 3;      ///< frames of the scene run
  std::string title;   ///< the line at the top
  int beatMs = 160;    ///< how long one step of the animation is shown (ms)
};

namespace detail {

using gjkx::TraceEvent;
using P2 = Eigen::Vector2d;

const Color kFlown = Color::hex(0x1F5FA8);      // flown from the frame's start (as fig-timewarp-spacetime)
const Color kReflown = Color::hex(0xD9730D);    // re-flown from a collision
const Color kDiscarded = Color::hex(0x9A9A9A);  // discarded by a rollback
const Color kCollision = gjkx::render::palette::penetration;
const Color kGvt = Color::hex(0x2E8540);

/// A piece of a body's row: flown over [a, b], kept or discarded.
struct Segment {
  double a, b;
  bool reflown, discarded;
};

/// Where the story stands: each body's local time and flight, the rows, the collisions.
struct Story {
  std::vector<double> local;                  // per body
  std::vector<int> flight;                    // per body: its flight in the frame's paths, -1: none yet
  std::vector<bool> afterCollision;           // per body: its next flight is re-flown
  std::vector<std::vector<Segment>> rows;     // per body
  std::vector<std::pair<double, std::pair<int, int>>> collisions;  // t_c and the pair
  struct Ghost {
    int body;
    gjkx::BodyState state;
    double time;
  };
  std::vector<Ghost> ghosts;  // the discarded flights' ends, shown while `ghostBeats` lasts
  int ghostBeats = 0;
  std::vector<int> flashing;  // bodies shown in the collision's colour
  long checks = 0;
};

inline std::string ms(double seconds) {
  char text[32];
  std::snprintf(text, sizeof text, "%.1f ms", 1000 * seconds);
  return text;
}

/// The names of `bodies` as "a, b and c".
inline std::string names(const Replay& replay, const std::vector<int>& bodies) {
  std::string text;
  for (std::size_t k = 0; k < bodies.size(); ++k)
    text += (k == 0 ? "" : k + 1 == bodies.size() ? " and " : ", ") + replay.names[std::size_t(bodies[k])];
  return text.empty() ? "none" : text;
}

}  // namespace detail

/// Runs the first options.frames frames of `scene` under Timewarp (timewarp_replay.hpp) and
/// adds the story to `movie` (see the file comment); bodies drawn with `looks` as `view` sees them.
inline void animateTimewarp(const gjkx::Scene& scene, const std::vector<BodyLook>& looks, View view,
                            const TimewarpOptions& options, chapter::WebpAnimation& movie, int width, int height) {
  using namespace gjkx::render;
  using namespace detail;
  const Replay replay = replayTimewarp(scene, options.frames);
  const std::size_t n = replay.names.size();
  const double tEnd = replay.frames.back().T1;
  std::vector<int> moving;
  for (std::size_t b = 0; b < n; ++b)
    if (!replay.isStatic[b]) moving.push_back(int(b));
  if (moving.empty()) throw std::runtime_error(scene.source + ": no moving body: Timewarp has nothing to show");

  // A body's shape frame at a state (bodies.csv's pose).
  const auto poseOf = [&](std::size_t b, const gjkx::BodyState& s) {
    return std::make_pair(s.worldFromBody(replay.frameOrigin[b]), Eigen::Quaterniond(s.worldFromBody.rotation));
  };
  // The framing: every flight's ends, discarded ones too.
  std::vector<RunFrame> extremes;
  for (const ReplayFrame& f : replay.frames) {
    RunFrame start = startOf(scene);
    for (std::size_t b = 0; b < n; ++b) {
      std::tie(start.position[b], start.orientation[b]) = poseOf(b, f.start[b]);
      for (const gjkx::PathPiece& p : f.paths[b]) {
        extremes.push_back(startOf(scene));
        for (std::size_t c = 0; c < n; ++c) std::tie(extremes.back().position[c], extremes.back().orientation[c]) = poseOf(c, f.start[c]);
        std::tie(extremes.back().position[b], extremes.back().orientation[b]) = poseOf(b, p.path.end);
      }
    }
    extremes.push_back(start);
  }
  std::tie(view.lo, view.hi) = framing(looks, extremes);

  // The layout: a caption, the bodies, the rows of local times.
  const int W = width, H = height;
  const double chartTop = 0.50 * H, rowH = std::min(34.0, (H - chartTop - 70) / std::max<std::size_t>(1, moving.size()));
  const double x0 = 90, x1 = W - 70;
  const auto X = [&](double t) { return x0 + (x1 - x0) * t / tEnd; };
  const auto rowY = [&](std::size_t k) { return chartTop + 28 + rowH * (double(k) + 0.6); };
  const auto at = [&](double x, double y) { return P2(x, H - y); };  // pixels, y down, in the full-canvas window
  const TextStyle small{Font::Sans, 12.5, palette::ink, 2.0};
  const TextStyle grey{Font::Sans, 12, Color::hex(0x5A5A5A), 2.0};

  Story story;
  story.rows.assign(n, {});
  story.afterCollision.assign(n, false);

  // One picture of the story, `caption` saying what just happened; GVT at `gvt`.
  const auto draw = [&](const ReplayFrame& frame, const std::string& caption, double gvt, int beats) {
    Canvas c(W, H);
    // The bodies, each at its local time; the ghosts of discarded flights first.
    c.setPanel({0, 52, W, int(chartTop) - 52}, 4, 0);
    setView(c, view);
    for (const auto& g : story.ghosts) {
      const auto [x, q] = poseOf(std::size_t(g.body), g.state);
      const Color tint = story.ghostBeats > 1 ? kCollision : kDiscarded;
      drawBody(c, looks[std::size_t(g.body)], x, q, view, tint.withAlpha(0.22), tint);
    }
    for (std::size_t b = 0; b < n; ++b) {
      const int k = story.flight[b];
      const gjkx::BodyState s = k < 0 ? frame.start[b] : frame.paths[b][std::size_t(k)].path.stateAt(story.local[b]);
      const auto [x, q] = poseOf(b, s);
      const bool flash = std::count(story.flashing.begin(), story.flashing.end(), int(b)) > 0;
      // Translucent, so that a body that ran into another shows the overlap.
      const Color fill = (flash ? mix(looks[b].color, kCollision, 0.6) : looks[b].color).withAlpha(replay.isStatic[b] ? 1.0 : 0.78);
      drawBody(c, looks[b], x, q, view, fill, view.kind == "3d" ? palette::ink : mix(fill.withAlpha(1), palette::ink, 0.6));
      if (replay.isStatic[b]) continue;
      const V3 top = topOf(looks[b], x, q, view);
      const std::string label = replay.names[b] + ": " + ms(story.local[b]);
      const TextStyle style{Font::Sans, 12, story.local[b] > gvt + 1e-12 ? kReflown : palette::ink, 2.5};
      if (view.kind == "3d") c.text3(top, label, style, Anchor::Above);
      else {
        const auto [u, w] = view.axes();
        c.text(P2(top[u], top[w]), label, style, Anchor::Above, P2(0, (b % 2) * 14.0));
      }
    }
    // Everything else in canvas pixels.
    c.setPanel({0, 0, W, H}, 0, 0);
    c.setWorldWindow(0, W, 0, H);
    c.text(at(W / 2.0, 6), options.title, TextStyle{Font::SansBold, 15, palette::ink}, Anchor::Below);
    c.text(at(W / 2.0, 28), caption, TextStyle{Font::Sans, 13.5, palette::ink, 2.0}, Anchor::Below);
    // Frames: shaded alternately, dashed ends, names.
    const double top = chartTop + 24, bottom = rowY(moving.size() - 1) + 0.5 * rowH;
    for (std::size_t f = 0; f < replay.frames.size(); ++f) {
      const double a = X(replay.frames[f].T0), b = X(replay.frames[f].T1);
      if (f % 2 == 1) c.polygon({at(a, top), at(b, top), at(b, bottom), at(a, bottom)}, ShapeStyle{Color::hex(0xF1F1F1), style::noStroke});
      c.line(at(b, top), at(b, bottom), Stroke{palette::axis, 1.0, style::dashed});
      c.text(at(0.5 * (a + b), top), "frame " + std::to_string(f + 1), grey, Anchor::Above);
    }
    for (std::size_t k = 0; k < moving.size(); ++k) {
      const std::size_t b = std::size_t(moving[k]);
      const double y = rowY(k);
      c.line(at(x0, y), at(x1, y), Stroke{palette::grid, 1.0});
      c.text(at(x0, y), replay.names[b], small, Anchor::Left, P2(-6, 0));
      for (const Segment& s : story.rows[b])
        if (s.discarded) c.line(at(X(s.a), y - 0.32 * rowH), at(X(s.b), y - 0.32 * rowH), Stroke{kDiscarded, 3.0, Dash{5, 3}});
      for (const Segment& s : story.rows[b])
        if (!s.discarded && s.b > s.a) c.line(at(X(s.a), y), at(X(s.b), y), Stroke{s.reflown ? kReflown : kFlown, 5.0});
      c.point(at(X(story.local[b]), y), palette::ink, 3.5);
    }
    for (const auto& [t, pair] : story.collisions) {
      std::vector<double> ys;  // the rows of the pair's moving bodies
      for (std::size_t k = 0; k < moving.size(); ++k)
        if (moving[k] == pair.first || moving[k] == pair.second) ys.push_back(rowY(k));
      if (ys.size() == 2) c.line(at(X(t), ys[0]), at(X(t), ys[1]), Stroke{kCollision, 2.0});
      for (double y : ys) c.point(at(X(t), y), kCollision, 4.5, Stroke{palette::background, 1.2});
    }
    // The global virtual time, and the time axis.
    c.line(at(X(gvt), top - 4), at(X(gvt), bottom + 4), Stroke{kGvt, 2.0});
    c.text(at(X(gvt), bottom + 4), "GVT " + ms(gvt), TextStyle{Font::SansBold, 12, kGvt, 2.0}, Anchor::Below);
    const double yAxis = bottom + 22;
    c.line(at(x0, yAxis), at(x1, yAxis), style::axisStroke);
    c.text(at(0.5 * (x0 + x1), yAxis), "simulated time", grey, Anchor::Below, P2(0, -14));
    c.text(at(x0, yAxis), "0", grey, Anchor::Below);
    for (const ReplayFrame& f : replay.frames) c.text(at(X(f.T1), yAxis), ms(f.T1), grey, Anchor::Below);
    c.text(at(x0, H - 8), "pair checks so far: " + std::to_string(story.checks) +
                              "    blue: flown from the frame's start   orange: re-flown from a collision   grey: discarded by a rollback   green: global virtual time",
           grey, Anchor::AboveRight, P2(-80, 0));
    movie.add(c.rgba(), options.beatMs * beats);
  };

  story.local.assign(n, 0.0);
  for (std::size_t fi = 0; fi < replay.frames.size(); ++fi) {
    const ReplayFrame& frame = replay.frames[fi];
    story.flight.assign(n, -1);
    std::vector<int> advances(n, 0);
    for (const TraceEvent& e : frame.events)
      if (e.kind == TraceEvent::Kind::Advance) ++advances[std::size_t(e.body)];
    std::vector<int> next(n);  // the next flight of each body in the frame's paths
    for (std::size_t b = 0; b < n; ++b) next[b] = int(frame.paths[b].size()) - advances[b];
    for (std::size_t b = 0; b < n; ++b) {
      story.local[b] = frame.T0;
      if (next[b] > 0) story.flight[b] = next[b] - 1;  // flown before the frame's events (after an impulse at T0)
    }
    // The global virtual time after event e: the earliest local time, and the earliest time a
    // later rollback of the frame goes back to (hindsight: the trace is known in full).
    const auto gvtAfter = [&](std::size_t e) {
      double g = frame.T1;
      for (int b : moving) g = std::min(g, story.local[std::size_t(b)]);
      for (std::size_t k = e + 1; k < frame.events.size(); ++k)
        if (frame.events[k].kind == TraceEvent::Kind::Rollback) g = std::min(g, frame.events[k].to);
      return g;
    };
    draw(frame, "frame " + std::to_string(fi + 1) + " starts: every body at T_0 = " + ms(frame.T0), gvtAfter(0), 3);
    // The flights of `group`, their local times sliding ahead together.
    const auto showAdvances = [&](const std::vector<TraceEvent>& group, std::size_t last) {
      std::vector<int> who;
      for (const TraceEvent& a : group) {
        const std::size_t b = std::size_t(a.body);
        story.flight[b] = next[b]++;
        story.rows[b].push_back({a.from, a.from, story.afterCollision[b], false});
        story.afterCollision[b] = false;
        who.push_back(a.body);
      }
      const bool fromCollision = group.front().from > frame.T0;
      const std::string verb = who.size() == 1 ? " flies" : " fly";
      const std::string caption = fromCollision ? names(replay, who) + verb + " on from t_c = " + ms(group.front().from) + " to the frame's end"
                                                : names(replay, who) + verb + " ahead on their own, each to T_1 = " + ms(group.front().to);
      constexpr int slides = 5;
      for (int s = 1; s <= slides; ++s) {
        for (const TraceEvent& a : group) {
          const std::size_t b = std::size_t(a.body);
          story.local[b] = a.from + (a.to - a.from) * s / slides;
          story.rows[b].back().b = story.local[b];
        }
        if (story.ghostBeats > 0 && --story.ghostBeats == 0) story.ghosts.clear();
        draw(frame, caption, gvtAfter(last), 1);
      }
    };
    // The rollbacks of `group`: a ghost where each body had run to, the body back at t_c.
    const auto showRollbacks = [&](const std::vector<TraceEvent>& group, std::size_t last) {
      std::vector<int> who, untouched;
      for (const TraceEvent& r : group) {
        const std::size_t b = std::size_t(r.body);
        const int k = story.flight[b];
        story.ghosts.push_back({r.body, k < 0 ? frame.start[b] : frame.paths[b][std::size_t(k)].path.stateAt(r.from), r.from});
        std::vector<Segment> kept;  // the row's flights past t_c are discarded
        for (Segment s : story.rows[b]) {
          if (s.discarded || s.b <= r.to + 1e-12) {
            kept.push_back(s);
            continue;
          }
          kept.push_back({std::max(s.a, r.to), s.b, s.reflown, true});
          if (s.a < r.to) kept.push_back({s.a, r.to, s.reflown, false});
        }
        story.rows[b] = kept;
        story.local[b] = r.to;
        who.push_back(r.body);
      }
      for (int b : moving)
        if (std::find(who.begin(), who.end(), b) == who.end()) untouched.push_back(b);
      story.ghostBeats = 4;
      story.flashing = who;
      draw(frame, "rolled back to t_c = " + ms(group.front().to) + ": " + names(replay, who) +
                      " (the flights past t_c discarded); not touched: " + names(replay, untouched),
           gvtAfter(last), 6);
      story.flashing.clear();
    };
    std::size_t e = 0;
    while (e < frame.events.size()) {
      const TraceEvent& first = frame.events[e];
      if (first.kind == TraceEvent::Kind::Check) {
        ++story.checks;
        ++e;
        continue;
      }
      if (first.kind == TraceEvent::Kind::Collision) {
        const int i = first.body, j = first.other;
        story.collisions.push_back({first.to, {i, j}});
        story.afterCollision[std::size_t(i)] = story.afterCollision[std::size_t(j)] = true;
        story.flashing = {i, j};
        std::string ahead;
        for (int b : {i, j})
          if (!replay.isStatic[std::size_t(b)]) ahead += (ahead.empty() ? "" : ", ") + replay.names[std::size_t(b)] + " at " + ms(story.local[std::size_t(b)]);
        draw(frame, "collision of " + replay.names[std::size_t(i)] + " and " + replay.names[std::size_t(j)] + " found at t_c = " +
                        ms(first.to) + ", after they ran past it (" + ahead + ")",
             gvtAfter(e), 5);
        story.flashing.clear();
        // Its response: the rollbacks to t_c, then the flights on from t_c (checks between counted).
        std::vector<TraceEvent> rollbacks, flights;
        std::size_t last = e, k = e + 1;
        for (; k < frame.events.size(); ++k) {
          const TraceEvent& r = frame.events[k];
          if (r.kind == TraceEvent::Kind::Check) continue;
          if (r.kind == TraceEvent::Kind::Rollback && r.to == first.to) rollbacks.push_back(r);
          else if (r.kind == TraceEvent::Kind::Advance && r.from == first.to) flights.push_back(r);
          else break;
          last = k;
        }
        for (std::size_t c = e + 1; c <= last; ++c) story.checks += frame.events[c].kind == TraceEvent::Kind::Check;
        if (!rollbacks.empty()) showRollbacks(rollbacks, last);
        if (!flights.empty()) showAdvances(flights, last);
        e = last + 1;
        continue;
      }
      // Flights (or rollbacks) in a row, checks between them counted, are shown together.
      std::vector<TraceEvent> group;
      std::size_t last = e;
      for (std::size_t k = e; k < frame.events.size(); ++k) {
        if (frame.events[k].kind == TraceEvent::Kind::Check) continue;
        if (frame.events[k].kind != first.kind) break;
        group.push_back(frame.events[k]);
        last = k;
      }
      for (std::size_t k = e; k <= last; ++k) story.checks += frame.events[k].kind == TraceEvent::Kind::Check;
      if (first.kind == TraceEvent::Kind::Advance) showAdvances(group, last);
      else showRollbacks(group, last);
      e = last + 1;
    }
    story.flashing.clear();
    story.ghosts.clear();
    story.ghostBeats = 0;
    draw(frame, "frame " + std::to_string(fi + 1) + " final: no event left before T_1 = " + ms(frame.T1) +
                    "; the global virtual time passes it",
         frame.T1, 6);
  }
}

}  // namespace animation
