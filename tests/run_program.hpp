// Running one of the project's programs as a user runs it, for the tests that check a
// program's output and exit status (gjkx_simulate, gjkx_bullet_scene).
#pragma once

#include <catch2/catch.hpp>

#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <string>

namespace test {

/// What a program did.
struct ProgramResult {
  int status = -1;     ///< the exit status (-1 when it did not exit normally)
  std::string output;  ///< standard output and standard error together
};

/// Runs `program` with `arguments` (a shell command line's tail) and collects its output.
inline ProgramResult runProgram(const std::string& program, const std::string& arguments) {
  const std::string command = "\"" + program + "\" " + arguments + " 2>&1";
  ProgramResult r;
  FILE* pipe = popen(command.c_str(), "r");
  REQUIRE(pipe != nullptr);
  char buffer[4096];
  for (std::size_t n; (n = std::fread(buffer, 1, sizeof buffer, pipe)) > 0;) r.output.append(buffer, n);
  const int raw = pclose(pipe);
  r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  return r;
}

/// An empty folder of its own under the temporary folder: `prefix`-`name`-<process id>.
inline std::filesystem::path freshFolder(const std::string& prefix, const std::string& name) {
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / (prefix + "-" + name + "-" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

}  // namespace test
