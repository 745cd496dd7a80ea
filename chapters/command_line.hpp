// The command line of every program of the chapters, through one kept parser, CLI11
// (Debian's libcli11-dev, header only). A program declares its options on a CLI::App
// and calls chapter::parseOrExit(); --help and bad arguments behave the same everywhere.
#pragma once

#include <CLI/CLI.hpp>

#include <cstdio>
#include <cstdlib>
#include <string>

namespace chapter {

/// The exit status of a bad command line (an unknown argument, a missing or malformed value).
constexpr int kUsageError = 2;

/// Parses argc/argv with `app`, or ends the program: `-h`/`--help` prints the help on
/// standard output and exits 0; a bad command line prints what was wrong, prefixed with
/// the program's name, on standard error and exits with kUsageError.
inline void parseOrExit(CLI::App& app, int argc, char** argv) {
  app.failure_message([](const CLI::App* program, const CLI::Error& e) {
    return program->get_name() + ": " + CLI::FailureMessage::simple(program, e);
  });
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    std::exit(app.exit(e) == 0 ? 0 : kUsageError);
  }
}

/// A progress bar on standard error for a program that runs frames (gjkx_simulate,
/// gjkx_bullet_scene): frame `frame` of `frames` done, after `wall` seconds.
inline void progress(int frame, int frames, double wall) {
  const int width = 40, done = frames > 0 ? frame * width / frames : width;
  std::fprintf(stderr, "\r[%s%s] frame %d/%d  %.1f s", std::string(std::size_t(done), '#').c_str(),
               std::string(std::size_t(width - done), ' ').c_str(), frame, frames, wall);
  std::fflush(stderr);
}

}  // namespace chapter
