// The command line of every program of the chapters, through one kept parser, CLI11
// (Debian's libcli11-dev, header only). A program declares its options on a CLI::App
// and calls chapter::parseOrExit(); --help and bad arguments behave the same everywhere.
#pragma once

#include <CLI/CLI.hpp>

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

}  // namespace chapter
