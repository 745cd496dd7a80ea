// The forked worker (gjkx/mesh/forked_worker.hpp).
#include <gjkx/mesh/forked_worker.hpp>

#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <stdexcept>

namespace gjkx {

bool writeAll(int fd, const void* data, std::size_t size) {
  const auto* bytes = static_cast<const char*>(data);
  while (size > 0) {
    const ssize_t n = ::write(fd, bytes, size);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    bytes += n;
    size -= std::size_t(n);
  }
  return true;
}

WorkerEnd runForked(const std::function<int(int fd)>& work, double limit,
                    const std::function<void(std::string_view)>& onOutput, const std::function<void(double)>& onTick,
                    double tick) {
  int fds[2];
  if (::pipe(fds) != 0) throw std::runtime_error("forked worker: pipe() failed");
  std::fflush(stdout);  // what the parent buffered is not written twice
  std::fflush(stderr);
  const auto start = std::chrono::steady_clock::now();
  const pid_t pid = ::fork();
  if (pid < 0) {
    ::close(fds[0]);
    ::close(fds[1]);
    throw std::runtime_error("forked worker: fork() failed");
  }
  if (pid == 0) {
    ::close(fds[0]);
    for (const int sig : {SIGSEGV, SIGBUS, SIGILL, SIGFPE, SIGABRT, SIGTERM, SIGINT, SIGALRM, SIGPIPE})
      std::signal(sig, SIG_DFL);
    ::alarm(unsigned(std::ceil(std::min(limit, 1e6))) + 2);  // a second watchdog, should the parent's fail
    int status = 3;
    try {
      status = work(fds[1]);
    } catch (...) {
      status = 3;
    }
    ::close(fds[1]);
    ::_exit(status);  // no atexit handlers, no flushing of the parent's buffers
  }
  ::close(fds[1]);
  const auto elapsed = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); };
  WorkerEnd end;
  int status = 0;
  bool open = true;  // the pipe: closed when the child closes its end (it exited, most likely)
  char buffer[1 << 14];
  for (;;) {
    const double now = elapsed();
    if (now >= limit) {
      ::kill(pid, SIGKILL);
      ::waitpid(pid, &status, 0);
      end.timedOut = true;
      break;
    }
    if (!open) {  // wait for the exit, in short naps (the child may still be tidying up)
      const pid_t r = ::waitpid(pid, &status, WNOHANG);
      if (r == pid) break;
      ::usleep(200);
      continue;
    }
    const double wait = std::min(limit - now, onTick ? tick : limit - now);
    pollfd p{fds[0], POLLIN, 0};
    const int ready = ::poll(&p, 1, int(std::ceil(std::min(wait, 3600.0) * 1000)));
    if (ready > 0) {
      const ssize_t n = ::read(fds[0], buffer, sizeof buffer);
      if (n > 0) onOutput(std::string_view(buffer, std::size_t(n)));
      else if (n == 0 || errno != EINTR) open = false;
    }
    if (onTick) onTick(elapsed());
  }
  ::close(fds[0]);
  end.seconds = elapsed();
  if (!end.timedOut) {
    if (WIFSIGNALED(status)) {
      end.signal = WTERMSIG(status);
      end.timedOut = end.signal == SIGALRM;
    } else if (WIFEXITED(status)) {
      end.exited = true;
      end.exitCode = WEXITSTATUS(status);
    }
  }
  return end;
}

}  // namespace gjkx
