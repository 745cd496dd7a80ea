// The panels of the chapter's figures and the verdicts written under them: each test's
// answer, judged right or wrong against the static test at many instants (the reference).
#pragma once

#include "../formatting.hpp"
#include "moving_pair.hpp"

#include <gjkx/extrusion/static_sampling.hpp>

#include <string>

namespace extrusion_figures {

using chapter::fixed;

/// The instants of the reference static test, dense enough for the chapter's motions.
constexpr int kTruthSamples = 4001;

/// Panel (col, row) of a grid of w x h cells, less a band of `band` pixels below it for the verdicts.
inline void panel(Canvas& c, int col, int row, int w, int h, int band, const std::string& title) {
  c.setPanel({col * w, row * h, w, h - band});
  c.title(title);
}
/// The same for a panel whose top left corner is at pixel (x, y).
inline void panelAt(Canvas& c, int x, int y, int w, int h, int band, const std::string& title) {
  c.setPanel({x, y, w, h - band});
  c.title(title);
}

/// A verdict in the band below the panel (made the current panel: labels are clipped to
/// theirs): green with a tick when right, red with a cross when wrong; a gray note below.
inline void verdict(Canvas& c, const std::string& text, bool isRight, int band, const std::string& note = "") {
  const PixelRect p = c.panel();
  c.setPanel({p.x, p.y + p.height, p.width, band}, 0, 0);
  c.textAtPixel(p.x + p.width / 2.0, p.y + p.height + 12, text + (isRight ? "  \u2713" : "  \u2717"),
                TextStyle{Font::SansBold, 14, isRight ? right : wrong, 3.0}, Anchor::Center);
  if (!note.empty())
    c.textAtPixel(p.x + p.width / 2.0, p.y + p.height + 32, note, TextStyle{Font::Sans, 12, palette::separating, 3.0});
}

/// A test's answer in words.
inline std::string said(bool collision) { return collision ? "collision" : "no collision"; }
/// What a verdict is, said against the reference: right, missed, or a false alarm.
inline std::string judged(bool reported, bool truth) {
  return reported == truth ? " \u2014 right" : (reported ? " \u2014 false alarm" : " \u2014 missed");
}
/// The §3 test's status, then the §5 solver's, for standard output.
inline std::string statuses(const ExtrusionResult<double>& test, const ToiResult<double>& toi) {
  return std::string(toString(test.status)) + " -> " + toString(toi.status) +
         (toi.status == ToiStatus::Hit ? " at t = " + fixed(toi.time, 4) : "");
}
/// The reference: the static test at kTruthSamples instants of [t_0, t_1].
inline bool collides(const Pair& pair) { return staticTest(pair.P, pair.Q, t0, t1, kTruthSamples); }

/// The §3 test, then the §5 solver when the test is undecided; its verdict in words.
inline std::string solverVerdict(const ExtrusionResult<double>& test, const ToiResult<double>& toi) {
  if (test.status == ExtrusionStatus::NoCollision) return "extrusion: no collision";
  if (toi.status == ToiStatus::Hit) return "extrusion + \u00a75: collision at t = " + fixed(toi.time, 3);
  if (toi.status == ToiStatus::PhotoFinish) return "extrusion + \u00a75: no collision (photo finish)";
  return std::string("extrusion + \u00a75: ") + toString(toi.status);
}

}  // namespace extrusion_figures
