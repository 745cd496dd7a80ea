// What every chapter program shares: its command line (--out DIR --format png|svg|pdf
// --trace, and the options that change a figure's query, parsed by CLI11), the trace it
// prints as a table, the saving of its figures,
// the formatting of numbers and tables (formatting.hpp) and the conversion of the
// library's 3D vectors to the plane of a 2D figure.
#pragma once

#include "command_line.hpp"
#include "formatting.hpp"

#include <gjkx/motion/pose.hpp>
#include <gjkx/motion/vector.hpp>
#include <gjkx/render/canvas.hpp>

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

namespace chapter {

/// Declares `--out DIR` (into `out`) and `--format png|svg|pdf` (into figureFormat()) on
/// `app`: every chapter program's options for its figures.
inline void addFigureOptions(CLI::App& app, std::string& out) {
  app.add_option("--out", out, "the folder for the figures, created if needed")->type_name("DIR")->capture_default_str();
  addFormatOption(app);
}

/// Declares `--trace` (into `trace`) on `app`: the program prints its stage's trace for the
/// figure's query as tables on standard output, one row per step (docs/traces.md).
inline void addTraceOption(CLI::App& app, bool& trace) {
  app.add_flag("--trace", trace, "print the stage's trace for the figure's query, one row per step");
}

/// The numbers of a comma-separated option value ("1,-2.5,0"), or an empty list when the text
/// is not such a list.
inline std::vector<double> numberList(const std::string& text) {
  std::vector<double> numbers;
  std::stringstream in(text);
  for (std::string field; std::getline(in, field, ',');) {
    std::size_t used = 0;
    double x = 0;
    try {
      x = std::stod(field, &used);
    } catch (const std::exception&) {
      return {};
    }
    if (used != field.size() || !std::isfinite(x)) return {};
    numbers.push_back(x);
  }
  if (!text.empty() && text.back() == ',') return {};
  return numbers;
}

/// A CLI11 check that an option's value is a list of `fewest` to `most` numbers separated by
/// commas, named `what` in the error ("X,Y" or "X,Y[,ANGLE]"): a bad value fails the parse
/// with the option's name and exit status kUsageError.
inline CLI::Validator numbers(std::size_t fewest, std::size_t most, const std::string& what) {
  return CLI::Validator(
      [=](std::string& text) -> std::string {
        const std::size_t n = numberList(text).size();
        if (n < fewest || n > most) return "expected " + what + " (numbers separated by commas), got '" + text + "'";
        return "";
      },
      what);
}

/// Prints `message` about option `option` on standard error, prefixed with the program's name,
/// and exits with kUsageError: for a value the option's own check cannot judge alone.
[[noreturn]] inline void badOption(const CLI::App& app, const std::string& option, const std::string& message) {
  std::fprintf(stderr, "%s: %s: %s\n", app.get_name().c_str(), option.c_str(), message.c_str());
  std::exit(kUsageError);
}

/// A round step of about span / count, for the ticks of an axis: 1, 2 or 5 times a power of ten.
inline double roundStep(double span, int count) {
  const double raw = span / count, power = std::pow(10.0, std::floor(std::log10(raw)));
  for (double m : {1.0, 2.0, 5.0})
    if (m * power >= raw) return m * power;
  return 10 * power;
}

/// A pose of the plane z = 0 from an option's numbers "X,Y[,ANGLE]": the origin moved to
/// (X, Y), turned by ANGLE radians about z (0 when absent).
inline gjkx::Pose<double> planarPose(const std::vector<double>& xyAngle) {
  return gjkx::Pose<double>::fromAxisAngle(gjkx::Vector3<double>::UnitZ(), xyAngle.size() > 2 ? xyAngle[2] : 0.0,
                                           gjkx::Vector3<double>(xyAngle.at(0), xyAngle.at(1), 0));
}

/// Declares the option `name`, a pose of the plane "X,Y[,ANGLE]" (read with planarPose()),
/// into `text` (its default shown in the help); a bad value is refused naming the option.
inline CLI::Option* addPoseOption(CLI::App& app, const std::string& name, std::string& text, const std::string& what) {
  return app.add_option(name, text, what)->check(numbers(2, 3, "X,Y[,ANGLE]"))->capture_default_str();
}

/// A trace printed as a table on standard output (--trace): its title, then the header and
/// one row per step, each column padded to its widest cell.
struct TraceTable {
  std::string title;                           ///< what the table traces, printed above it
  std::vector<std::string> header;             ///< the columns' names
  std::vector<std::vector<std::string>> rows;  ///< one row per step

  /// Prints the table (and a blank line after it) on standard output.
  void print() const {
    std::vector<std::size_t> width(header.size(), 0);
    for (std::size_t c = 0; c < header.size(); ++c) width[c] = header[c].size();
    for (const auto& row : rows)
      for (std::size_t c = 0; c < row.size() && c < width.size(); ++c) width[c] = std::max(width[c], displayWidth(row[c]));
    std::printf("%s\n", title.c_str());
    auto line = [&](const std::vector<std::string>& cells) {
      std::string text;
      for (std::size_t c = 0; c < cells.size(); ++c) {
        text += cells[c];
        if (c + 1 < cells.size()) text += std::string(width[c] - displayWidth(cells[c]) + 2, ' ');
      }
      std::printf("%s\n", text.c_str());
    };
    line(header);
    for (const auto& row : rows) line(row);
    std::printf("\n");
  }

  /// The characters a cell takes on a terminal: its UTF-8 code points.
  static std::size_t displayWidth(const std::string& text) {
    std::size_t n = 0;
    for (const char c : text) n += (static_cast<unsigned char>(c) & 0xC0) != 0x80;
    return n;
  }
};

/// A point of the plane as a trace's cell: "(x, y)" with `digits` digits after the point.
template <typename S>
std::string pointCell(const gjkx::Vector3<S>& v, int digits = 3) {
  return "(" + fixed(double(v.x()), digits) + ", " + fixed(double(v.y()), digits) + ")";
}

/// Where a figure was written, said on standard output.
inline void wrote(const std::string& path) { std::printf("wrote %s\n", path.c_str()); }

/// Writes `canvas` as the figure `name` in `folder`, in the format of `--format`
/// (figureFormat()): folder/name.png, .svg or .pdf; says where, and returns the path.
inline std::string save(gjkx::render::Canvas& canvas, const std::string& folder, const std::string& name) {
  const std::string path = folder + "/" + name + "." + figureFormat();
  canvas.save(path);
  wrote(path);
  return path;
}

/// A point of the plane z = 0 as the renderer's 2D point.
template <typename S>
Eigen::Vector2d xy(const gjkx::Vector3<S>& v) {
  return Eigen::Vector2d(double(v.x()), double(v.y()));
}

/// Many points of the plane z = 0 as the renderer's 2D points.
template <typename S>
std::vector<Eigen::Vector2d> xy(const std::vector<gjkx::Vector3<S>>& points) {
  std::vector<Eigen::Vector2d> out;
  for (const auto& p : points) out.push_back(xy(p));
  return out;
}

/// The label anchor that puts a label on the side of a point that `direction` points to.
inline gjkx::render::Anchor toward(const Eigen::Vector2d& direction) {
  using gjkx::render::Anchor;
  static const Anchor compass[8] = {Anchor::Right, Anchor::AboveRight, Anchor::Above, Anchor::AboveLeft,
                                    Anchor::Left,  Anchor::BelowLeft,  Anchor::Below, Anchor::BelowRight};
  const double turns = std::atan2(direction.y(), direction.x()) / (2 * M_PI);
  return compass[(static_cast<int>(std::lround(turns * 8)) % 8 + 8) % 8];
}

}  // namespace chapter
