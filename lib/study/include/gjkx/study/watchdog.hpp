/// @file
/// @brief The fork watchdog of the study's table of extreme cases: runs one method on one
/// case in a fork()ed child with a wall-time limit, so that a hang, a crash or a throw
/// of the method becomes a cell of the table instead of ending the run.
///
/// Holds (namespace gjkx::study): `AnswerKind` (how an answer came back), `GuardedRun` (how
/// the child ended), `guarded` (the watchdog) and `setText` (for the answers' fixed text
/// buffers: an answer crosses a pipe from the child, so it is a plain struct). POSIX only.
#pragma once

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <thread>
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
/// seconds of wall time: a child that runs longer is killed (a hang), one that dies of a
/// signal crashed. An exception is caught in the child and sent back as an answer of kind
/// `AnswerKind::Exception` with its what() in `message`. `Answer` needs the members
/// `AnswerKind kind` and `char message[N]`.
template <typename Answer, typename F>
GuardedRun guarded(F&& f, double limit, Answer& answer) {
  static_assert(std::is_trivially_copyable_v<Answer>, "the answer crosses a pipe");
  GuardedRun run;
  int fds[2];
  if (pipe(fds) != 0) throw std::runtime_error("watchdog: pipe() failed");
  std::fflush(stdout);
  std::fflush(stderr);
  const auto start = std::chrono::steady_clock::now();
  const pid_t pid = fork();
  if (pid < 0) throw std::runtime_error("watchdog: fork() failed");
  if (pid == 0) {
    close(fds[0]);
    // The default actions, whatever handlers the caller installed (a test framework's, say):
    // a fault kills the child, and the parent reads the signal.
    for (const int sig : {SIGSEGV, SIGBUS, SIGILL, SIGFPE, SIGABRT, SIGTERM, SIGINT, SIGALRM}) std::signal(sig, SIG_DFL);
    alarm(unsigned(std::ceil(limit)) + 2);  // a second watchdog, should the parent's fail
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
    const ssize_t written = write(fds[1], &a, sizeof a);
    _exit(written == ssize_t(sizeof a) ? 0 : 3);
  }
  close(fds[1]);
  int status = 0;
  auto pause = std::chrono::microseconds(20);
  for (;;) {
    const pid_t r = waitpid(pid, &status, WNOHANG);
    if (r == pid) break;
    if (std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() > limit) {
      kill(pid, SIGKILL);
      waitpid(pid, &status, 0);
      run.timedOut = true;
      break;
    }
    std::this_thread::sleep_for(pause);
    pause = std::min(pause * 2, std::chrono::microseconds(2000));
  }
  run.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (!run.timedOut) {
    if (WIFSIGNALED(status)) {
      run.signal = WTERMSIG(status);
      if (run.signal == SIGALRM) run.timedOut = true;
    } else if (WIFEXITED(status) && WEXITSTATUS(status) == 0) {
      run.finished = read(fds[0], &answer, sizeof answer) == ssize_t(sizeof answer);
    }
  }
  close(fds[0]);
  return run;
}

}  // namespace gjkx::study
