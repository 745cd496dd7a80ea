// The command line of every program of the chapters, through one kept parser, CLI11
// (Debian's libcli11-dev, header only). A program declares its options on a CLI::App
// and calls chapter::parseOrExit(); --help and bad arguments behave the same everywhere.
#pragma once

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <sstream>
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

/// The format of the figures, from `--format` (png, the default and what figures/ keeps;
/// svg or pdf for vectors, e.g. for slides or a paper).
inline std::string& figureFormat() {
  static std::string format = "png";
  return format;
}

/// Declares `--format png|svg|pdf` (into figureFormat()) on `app`: every program that draws
/// figures takes it.
inline void addFormatOption(CLI::App& app) {
  app.add_option("--format", figureFormat(), "the figures' format")
      ->check(CLI::IsMember({"png", "svg", "pdf"}))
      ->capture_default_str();
}

/// gnuplot's terminal for figureFormat() (pngcairo, svg or pdfcairo), `width` x `height`
/// pixels (a PDF at 96 pixels an inch), with `font`: the line a gnuplot script starts with.
inline std::string gnuplotTerminal(double width, double height, const std::string& font) {
  std::ostringstream line;
  if (figureFormat() == "pdf") line << "set terminal pdfcairo size " << width / 96 << "in," << height / 96 << "in";
  else line << "set terminal " << (figureFormat() == "svg" ? "svg" : "pngcairo") << " size " << width << "," << height;
  line << " font '" << font << "'\n";
  return line.str();
}

/// A progress bar on standard error: `done` of its 40 marks filled, then `what`, then
/// `wall` seconds. It rewrites its own line (a carriage return, and the rest of the line
/// cleared); the caller ends the line when the work is over.
inline void progressBar(int done, const std::string& what, double wall) {
  constexpr int width = 40;
  done = std::clamp(done, 0, width);
  std::fprintf(stderr, "\r[%s%s] %s  %.1f s\x1b[K", std::string(std::size_t(done), '#').c_str(),
               std::string(std::size_t(width - done), ' ').c_str(), what.c_str(), wall);
  std::fflush(stderr);
}

/// A progress bar on standard error for a program that runs frames (gjkx_simulate,
/// gjkx_bullet_scene): frame `frame` of `frames` done, after `wall` seconds.
inline void progress(int frame, int frames, double wall) {
  progressBar(frames > 0 ? frame * 40 / frames : 40, "frame " + std::to_string(frame) + "/" + std::to_string(frames),
              wall);
}

/// The same bar for a mesh's convex decomposition before a run (gjkx_simulate): HACD's phase
/// and how far it has come, the seconds spent and the budget; the bar's line ends when the
/// decomposition does (its phase "done").
inline void decompositionProgress(const std::string& mesh, const char* phase, double fraction, double seconds,
                                  double budget) {
  char budgetText[32];
  std::snprintf(budgetText, sizeof budgetText, "%g", budget);
  const std::string name = mesh.substr(mesh.find_last_of('/') + 1);  // the file's name: the line stays short
  progressBar(int(fraction * 40), "decomposing " + name + " (" + phase + ", budget " + budgetText + " s)", seconds);
  if (std::string(phase) == "done") std::fprintf(stderr, "\n");
}

}  // namespace chapter
