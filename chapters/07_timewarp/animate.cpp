// gjkx_animate: a run of a scene as an animation a browser shows inline (animated WebP).
//
//   gjkx_animate SCENE.json RUN_DIR --out FILE.webp [--view 3d|xy|xz|yz] [--size WxH]
//                [--fps N] [--from T] [--to T]
//
// reads RUN_DIR/bodies.csv and RUN_DIR/frames.csv, written by `gjkx_simulate SCENE.json --out
// RUN_DIR` (or by gjkx_bullet_scene), draws the scene's bodies at each frame, in 3D through a
// camera around the moving bodies or in 2D projected on a coordinate plane (or, for a scene in
// the plane z = 0, beside its extrusion in space-time: space_time_view.hpp), and encodes the
// frames with libwebp's animation encoder (webp_animation.hpp). Each frame says its simulated
// time and the collisions and rollbacks of the run's frame.
//
//   gjkx_animate SCENE.json --timewarp --out FILE.webp
//
// runs the (small) scene itself under Timewarp with the world's trace on and shows what the
// ordering does (local_times.hpp): every body drawn at its own local time, the bodies
// running ahead of the global virtual time, each rollback flashing the discarded flight.
//
// Bad input ends the program with exit status 1 and a message naming the file and what is
// wrong (a missing CSV, a run of another scene); a bad command line exits 2.
#include "../command_line.hpp"
#include "../webp_animation.hpp"
#include "local_times.hpp"
#include "scene_run.hpp"
#include "scene_view.hpp"
#include "space_time_view.hpp"

#include <gjkx/render/canvas.hpp>
#include <gjkx/timewarp/scene.hpp>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

using namespace gjkx::render;

namespace {

/// A colour given on the command line as RRGGBB (a leading # allowed).
Color parseColor(const std::string& text) {
  const std::string hex = !text.empty() && text[0] == '#' ? text.substr(1) : text;
  if (hex.size() != 6 || hex.find_first_not_of("0123456789abcdefABCDEF") != std::string::npos)
    throw std::invalid_argument("--color: '" + text + "' is not a colour RRGGBB");
  return Color::hex(std::uint32_t(std::stoul(hex, nullptr, 16)));
}

std::string format(const char* spec, double x) {
  char text[64];
  std::snprintf(text, sizeof text, spec, x);
  return text;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Draws a run of a gjkx scene (gjkx_simulate's bodies.csv and frames.csv) as an animated WebP, or, "
               "with --timewarp, runs a small scene and shows Timewarp's local times and rollbacks.",
               "gjkx_animate"};
  std::string scenePath, runDir, out, view = "3d", size = "640x480", title;
  std::vector<std::string> colorSpecs;
  double fps = 0, from = 0, to = 1e300, azimuth = -50, elevation = 20, zoom = 1, quality = 80;
  int every = 1, hold = 1000;
  bool timewarp = false;
  animation::TimewarpOptions tw;
  app.add_option("scene", scenePath, "the scene file (JSON) the run was made of")->required()->check(CLI::ExistingFile);
  app.add_option("run", runDir, "the run's folder (gjkx_simulate SCENE --out RUN_DIR); not with --timewarp");
  app.add_option("--out", out, "the animation to write (an animated WebP)")->required();
  app.add_option("--view", view,
                 "3d: a camera around the moving bodies; xy, xz, yz: projected on that plane; spacetime: a scene in "
                 "the plane z = 0 beside its extrusion in space-time (x, y, t)")
      ->check(CLI::IsMember({"3d", "xy", "xz", "yz", "spacetime"}))
      ->capture_default_str();
  app.add_option("--size", size, "width x height of the animation in pixels")->capture_default_str();
  app.add_option("--fps", fps, "frames shown per second (default: the scene's frame rate, so real time)")
      ->check(CLI::PositiveNumber);
  app.add_option("--from", from, "the first simulated time shown (s)")->check(CLI::NonNegativeNumber);
  app.add_option("--to", to, "the last simulated time shown (s)")->check(CLI::NonNegativeNumber);
  app.add_option("--every", every, "show every Nth frame of the run")->check(CLI::PositiveNumber)->capture_default_str();
  app.add_option("--hold", hold, "milliseconds the last frame is held before the animation loops")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  app.add_option("--azimuth", azimuth, "3d and spacetime: the camera's angle about z from the x axis (degrees)")->capture_default_str();
  app.add_option("--elevation", elevation, "3d and spacetime: the camera's angle above the horizon (degrees, in (-90, 90))")
      ->check(CLI::Range(-89.0, 89.0))
      ->capture_default_str();
  app.add_option("--zoom", zoom, "> 1 comes closer to the framed bodies")->check(CLI::PositiveNumber)->capture_default_str();
  app.add_option("--quality", quality, "the WebP encoder's quality in [0, 100], or -1 for lossless frames")
      ->check(CLI::Range(-1.0, 100.0))
      ->capture_default_str();
  app.add_option("--color", colorSpecs, "PREFIX=RRGGBB: the colour of the bodies whose names begin with PREFIX (* for all)")
      ->type_name("PREFIX=RRGGBB ...");
  app.add_option("--title", title, "the line above the bodies (default: the scene file's name)");
  app.add_flag("--timewarp", timewarp,
               "run the scene under Timewarp with the trace on, and show each body at its own local time");
  app.add_option("--frames", tw.frames, "with --timewarp: the frames of the scene to run")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  chapter::parseOrExit(app, argc, argv);

  int width = 0, height = 0;
  if (std::sscanf(size.c_str(), "%dx%d", &width, &height) != 2 || width < 64 || height < 64 || width > 4096 || height > 4096) {
    std::cerr << "gjkx_animate: --size: '" << size << "' is not WIDTHxHEIGHT with each in [64, 4096]\n";
    return chapter::kUsageError;
  }
  if (timewarp == !runDir.empty()) {
    std::cerr << "gjkx_animate: give the run's folder RUN_DIR, or --timewarp (which runs the scene itself), not both\n";
    return chapter::kUsageError;
  }
  if (!(to > from)) {
    std::cerr << "gjkx_animate: --to must be after --from\n";
    return chapter::kUsageError;
  }
  if ((view == "3d" || view == "spacetime") && !canDraw3d()) {
    std::cerr << "gjkx_animate: this build draws no 3D (no OSMesa): use --view xy, xz or yz\n";
    return 1;
  }
  try {
    const gjkx::Scene scene = gjkx::loadScene(scenePath);
    std::vector<std::pair<std::string, Color>> colors;
    for (const std::string& spec : colorSpecs) {
      const auto eq = spec.find('=');
      if (eq == std::string::npos || eq == 0) throw std::invalid_argument("--color: '" + spec + "' is not PREFIX=RRGGBB");
      colors.emplace_back(spec.substr(0, eq), parseColor(spec.substr(eq + 1)));
    }
    const std::vector<animation::BodyLook> looks = animation::looksOf(scene, colors);
    if (title.empty()) title = std::filesystem::path(scenePath).filename().string();
    animation::View camera;
    camera.kind = view;
    camera.azimuth = azimuth * M_PI / 180;
    camera.elevation = elevation * M_PI / 180;
    camera.zoom = zoom;
    chapter::WebpAnimation movie(width, height, quality);
    if (timewarp) {
      tw.title = title;
      animation::animateTimewarp(scene, looks, camera, tw, movie, width, height);
    } else {
      std::vector<animation::RunFrame> shown;
      int k = 0;
      for (const animation::RunFrame& f : animation::readRun(runDir, scene))
        if (f.time >= from - 1e-9 && f.time <= to + 1e-9 && k++ % every == 0) shown.push_back(f);
      if (shown.empty()) throw std::runtime_error(runDir + ": no frame between --from and --to");
      std::tie(camera.lo, camera.hi) = animation::framing(looks, shown);
      const int ms = std::max(1, int(std::lround(1000.0 * every / (fps > 0 ? fps * every : scene.frameRate))));
      for (std::size_t i = 0; i < shown.size(); ++i) {
        const animation::RunFrame& f = shown[i];
        Canvas canvas(width, height);
        canvas.setPanel({0, 0, width, height}, 6, 30);
        canvas.title(title);
        if (view == "spacetime") animation::drawSpaceTime(canvas, looks, shown, i, camera, 34, height - 62);
        else animation::drawFrame(canvas, looks, f, camera);
        canvas.setPanel({0, 0, width, height}, 0, 0);
        std::string caption = "t = " + format("%.3f s", f.time);
        if (f.frame > 0)
          caption += "   frame " + std::to_string(f.frame) + ": " + std::to_string(f.collisions) + " collisions, " +
                     std::to_string(f.rollbacks) + " rollbacks";
        canvas.textAtPixel(10, height - 10, caption, TextStyle{Font::Sans, 13, palette::ink, 2.0}, Anchor::AboveRight);
        movie.add(canvas.rgba(), i + 1 == shown.size() ? ms + hold : ms);
      }
    }
    const long bytes = movie.save(out);
    std::printf("wrote %s: %d frames, %.1f s, %dx%d, %ld bytes\n", out.c_str(), movie.frames(),
                movie.milliseconds() / 1000.0, width, height, bytes);
  } catch (const std::exception& e) {
    std::cerr << "gjkx_animate: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
