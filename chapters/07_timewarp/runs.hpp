// Chapter 07's runs: the Newton's cradle (or a reader's scene) under an ordering, traced
// (WorldSettings::trace), frame by frame; and the Timewarp run printed event by event
// (--trace, docs/traces.md).
#pragma once

#include "../chapter.hpp"

#include <gjkx/timewarp/scene.hpp>
#include <gjkx/timewarp/world.hpp>

#include <algorithm>
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

namespace timewarp_figures {

using namespace gjkx;
using chapter::format;

/// The cradle's frames drawn.
constexpr int kFrames = 3;
/// The paper's frames per second.
constexpr double kFrameRate = 24;

/// The cradle: ball1 at 1 m/s towards four balls at rest 2 cm apart, no gravity, e = 1, no
/// friction. It hits ball2 at t = 0.03 s, and the momentum runs down the row every 0.02 s:
/// two collisions in the second frame, one in each of the others.
inline Scene cradle(Ordering ordering, int frames) {
  std::string bodies;
  for (int k = 0; k < 5; ++k)
    bodies += std::string(k ? "," : "") + R"({ "name": "ball)" + std::to_string(k + 1) +
              R"(", "shape": {"sphere": 0.1}, "position": [)" + format("%.2f", k == 0 ? -0.01 : 0.22 * k) +
              R"(, 0, 0], "velocity": [)" + (k == 0 ? "1" : "0") + ", 0, 0] }";
  return parseScene(R"({ "gravity": [0, 0, 0], "frame_rate": 24, "duration": )" + format("%.6f", frames / kFrameRate) +
                        R"(, "restitution": 1, "friction": 0, "scalar": "double", "contact": "microcollisions", "ordering": ")" +
                        orderingName(ordering) + R"(", "bodies": [)" + bodies + "] }",
                    "cradle");
}

/// One run of a scene: its trace and its counters summed over the frames drawn, and where
/// each frame's events start in the trace.
struct Run {
  Ordering ordering;
  std::vector<std::string> names;
  std::vector<TraceEvent> trace;
  FrameCounters total;
  int frames = kFrames;                  ///< frames run
  double frameRate = kFrameRate;         ///< frames per second
  std::vector<std::size_t> frameStarts;  ///< the index of each frame's first event in `trace`
};

/// Runs the first `frames` frames of `scene` (the cradle when absent) under `ordering`.
inline Run run(Ordering ordering, const std::optional<Scene>& scene, int frames) {
  WorldSettings settings;
  settings.trace = true;
  Scene ordered = scene ? *scene : cradle(ordering, frames);
  ordered.run.ordering = ordering;
  World world(ordered, settings);
  Run r{ordering, {}, {}, {}, kFrames, kFrameRate, {}};
  r.frameRate = ordered.frameRate;
  for (r.frames = 0; !world.done() && r.frames < frames; ++r.frames) {
    r.frameStarts.push_back(world.trace().size());
    r.total += world.step().counters;
  }
  for (const WorldBody& b : world.bodies()) r.names.push_back(b.name);
  r.trace = world.trace();
  return r;
}

/// The Timewarp run event by event (--trace): each record of the world's trace with the
/// frame, the kind, the bodies, the times, the global virtual time and every body's local time.
/// The global virtual time is the time of the earliest event still queued; events are taken in
/// time order, so it is the time of the last collision taken (the interval's start T0 before
/// any), and each frame ends when its queue is empty: the GVT passes T1.
inline void printTrace(const Run& r) {
  const std::size_t n = r.names.size();
  const bool all = n <= 10;  // every body's local time, or only the event's bodies'
  std::string order;  // the bodies, in the order of the local times' column
  for (std::size_t b = 0; b < n; ++b) order += (b ? " " : "") + r.names[b];
  chapter::TraceTable table{"fig-timewarp-spacetime: the Timewarp run event by event (Mirtich's Timewarp, §5-§6)",
                            {"#", "frame", "event", "body", "other", "from", "to", "GVT",
                             all ? "local times (" + order + ")" : "local times of its bodies"},
                            {}};
  std::vector<double> local(n, 0.0);
  const char* kinds[] = {"advance", "collision", "rollback", "check"};
  std::size_t frame = 0;
  double gvt = 0;
  for (std::size_t k = 0; k < r.trace.size(); ++k) {
    while (frame < r.frameStarts.size() && r.frameStarts[frame] <= k) {
      gvt = std::max(gvt, frame / r.frameRate);
      ++frame;
    }
    const TraceEvent& e = r.trace[k];
    switch (e.kind) {
      case TraceEvent::Kind::Advance: local[std::size_t(e.body)] = e.to, gvt = std::max(gvt, e.from); break;
      case TraceEvent::Kind::Rollback: local[std::size_t(e.body)] = e.to; break;
      case TraceEvent::Kind::Collision: gvt = std::max(gvt, e.to); break;
      case TraceEvent::Kind::Check: gvt = std::max(gvt, e.from); break;
    }
    std::string times;
    for (std::size_t b = 0; b < n; ++b)
      if (all || int(b) == e.body || int(b) == e.other)
        times += (times.empty() ? "" : " ") + (all ? "" : r.names[b] + ": ") + format("%.6f", local[b]);
    table.rows.push_back({std::to_string(k + 1), std::to_string(frame), kinds[int(e.kind)], r.names[std::size_t(e.body)],
                          e.other >= 0 ? r.names[std::size_t(e.other)] : "-", format("%.6f", e.from),
                          format("%.6f", e.to), format("%.6f", gvt), times});
  }
  table.print();
  const FrameCounters& t = r.total;
  std::printf("timewarp over %d frames: %zu events traced, collisions %ld, rollbacks %ld, body flights cut %ld, "
              "pair checks %ld\n\n",
              r.frames, r.trace.size(), t.collisions, t.rollbacks, t.bodiesRolledBack, t.collisionChecks);
}

}  // namespace timewarp_figures
