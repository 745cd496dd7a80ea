/// @file
/// @brief A forked worker with a wall-time limit: work that a kept library may not finish
/// (HACD's decomposition, a method of the study's extreme cases) runs in a fork()ed child,
/// which is killed when its time is up.
///
/// A library loop that never looks at a clock cannot be stopped from inside: HACD's
/// call-back returns a bool that HACD ignores, and its cancel flag is read only before the
/// merging starts, where real meshes spend minutes. A child process can always be stopped.
/// The child writes what it has to say (progress, then its answer) to a pipe; the parent
/// reads it as it comes, so the child never blocks on a full pipe, and hands each piece to
/// the caller. POSIX only. The decomposition (convex_decomposition.hpp) and the study's
/// watchdog (gjkx/study/watchdog.hpp) both run on it.
#pragma once

#include <cstddef>
#include <functional>
#include <string_view>

namespace gjkx {

/// How a forked worker ended.
struct WorkerEnd {
  bool exited = false;    ///< the child returned from its work and exited (see `exitCode`)
  int exitCode = 0;       ///< its exit status when it exited (the work's return value; 3: it threw)
  bool timedOut = false;  ///< it ran past its limit and was killed
  int signal = 0;         ///< the signal that ended it otherwise (a crash: SIGSEGV, SIGABRT, ...)
  double seconds = 0;     ///< wall time, fork to end
};

/// Runs `work(fd)` in a fork()ed child and waits for it at most `limit` seconds of wall time.
///
/// The child writes to the pipe `fd`; its return value is its exit status (an exception that
/// escapes `work` is exit status 3). It starts with the default signal actions, whatever
/// handlers the caller installed (a test framework's), so that a fault kills it, and with an
/// alarm a little after `limit`, should the parent fail to kill it. The parent hands every
/// chunk the child writes to `onOutput` as it arrives, and calls `onTick(seconds so far)` at
/// least every `tick` seconds while the child runs (for a progress bar); a child still
/// running at `limit` is killed (SIGKILL). Throws std::runtime_error if pipe() or fork() fails.
WorkerEnd runForked(const std::function<int(int fd)>& work, double limit,
                    const std::function<void(std::string_view)>& onOutput,
                    const std::function<void(double)>& onTick = {}, double tick = 0.1);

/// Writes all `size` bytes of `data` to `fd` (retrying short writes); false if it could not.
bool writeAll(int fd, const void* data, std::size_t size);

}  // namespace gjkx
