// What every chapter program shares: its command line (--out DIR --format png|svg|pdf,
// parsed by CLI11), the saving of its figures,
// the formatting of numbers and tables (formatting.hpp) and the conversion of the
// library's 3D vectors to the plane of a 2D figure.
#pragma once

#include "command_line.hpp"
#include "formatting.hpp"

#include <gjkx/motion/vector.hpp>
#include <gjkx/render/canvas.hpp>

#include <Eigen/Core>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

namespace chapter {

/// Declares `--out DIR` (into `out`) and `--format png|svg|pdf` (into figureFormat()) on
/// `app`: every chapter program's options for its figures.
inline void addFigureOptions(CLI::App& app, std::string& out) {
  app.add_option("--out", out, "the folder for the figures, created if needed")->type_name("DIR")->capture_default_str();
  addFormatOption(app);
}

/// The output folder from `--out DIR` (default: the current folder), created if needed, and
/// the figures' format from `--format` (see addFigureOptions()). `--help` prints the usage
/// and exits 0; any other argument is an error (exit status 2).
inline std::string outputFolder(int argc, char** argv) {
  std::string out = ".";
  CLI::App app{"Draws this chapter's figures of the paper in DIR, as PNG (the default), SVG or PDF files."};
  addFigureOptions(app, out);
  parseOrExit(app, argc, argv);
  std::filesystem::create_directories(out);
  return out;
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
