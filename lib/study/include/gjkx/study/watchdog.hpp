/// @file
/// @brief The fork watchdog of the study's table of extreme cases: runs one method on one
/// case in a fork()ed child with a wall-time limit, so that a hang, a crash or a throw
/// of the method becomes a cell of the table instead of ending the run.
///
/// Holds (namespace gjkx::study): `AnswerKind` (how an answer came back), `GuardedRun` (how
/// the child ended), `guarded` (the watchdog) and `setText` (for the answers' fixed text
/// buffers: an answer crosses a pipe from the child, so it is a plain struct). POSIX only.
#pragma once

#include <gjkx/mesh/forked_worker.hpp>

#include <csignal>
#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>

namespace gjkx::study {

/// How a method's answer came back (a plain struct: it crosses a pipe from the child).
enum class AnswerKind : int {
  Answer,            ///< the method answered
  Cap,               ///< the method said its iteration cap ran out
  NumericalFailure,  ///< the method said it met a non-finite number
  Exception,         ///< the method threw (the watchdog's child caught it)
};

/// Copies `text` into a fixed buffer of an answer (cut to fit, always terminated).
inline void setText(char* out, std::size_t size, const std::string& text) {
  std::snprintf(out, size, "%s", text.c_str());
}

/// How a guarded run ended.
struct GuardedRun {
  bool finished = false;  ///< the child wrote its answer and exited
  bool timedOut = false;  ///< the watchdog killed it
  int signal = 0;         ///< the signal that ended it otherwise
  double seconds = 0;     ///< wall time, fork to end
};

/// Runs `f()` (returning a trivially copyable Answer) in a fork()ed child, with `limit`
/// seconds of wall time (gjkx::runForked, the mesh stage's forked worker): a child that runs
/// longer is killed (a hang), one that dies of a signal crashed. An exception is caught in
/// the child and sent back as an answer of kind `AnswerKind::Exception` with its what() in
/// `message`. `Answer` needs the members `AnswerKind kind` and `char message[N]`.
template <typename Answer, typename F>
GuardedRun guarded(F&& f, double limit, Answer& answer) {
  static_assert(std::is_trivially_copyable_v<Answer>, "the answer crosses a pipe");
  std::string bytes;
  const WorkerEnd end = runForked(
      [&](int fd) {
        Answer a{};
        try {
          a = f();
        } catch (const std::exception& e) {
          a = Answer{};
          a.kind = AnswerKind::Exception;
          setText(a.message, sizeof a.message, e.what());
        } catch (...) {
          a = Answer{};
          a.kind = AnswerKind::Exception;
          setText(a.message, sizeof a.message, "unknown exception");
        }
        return writeAll(fd, &a, sizeof a) ? 0 : 3;
      },
      limit, [&](std::string_view chunk) { bytes.append(chunk); });
  GuardedRun run;
  run.timedOut = end.timedOut;
  run.signal = end.timedOut ? 0 : end.signal;
  run.seconds = end.seconds;
  run.finished = end.exited && end.exitCode == 0 && bytes.size() == sizeof answer;
  if (run.finished) std::memcpy(&answer, bytes.data(), sizeof answer);
  return run;
}

}  // namespace gjkx::study
