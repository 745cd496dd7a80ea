// gjkx_animate as a user runs it (docs/animations.md): a falling box run by gjkx_simulate,
// animated, and the animated WebP decoded back by libwebp's demuxer (WebPAnimDecoder): its
// size, its frame count and that the box moves from one frame to the next; the cradle's
// Timewarp story; and bad input named.
#include "../run_program.hpp"

#include <catch2/catch.hpp>

#include <webp/demux.h>

#include <fstream>
#include <iterator>
#include <string>
#include <vector>

namespace {

/// An animated WebP decoded: its size and each frame's pixels (RGBA) and end time (ms).
struct Decoded {
  int width = 0, height = 0, frameCount = 0;
  std::vector<std::vector<std::uint8_t>> frames;
  std::vector<int> timestamps;
};

Decoded decode(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  REQUIRE(in);
  const std::vector<char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const WebPData data{reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size()};
  WebPAnimDecoderOptions options;
  REQUIRE(WebPAnimDecoderOptionsInit(&options));
  options.color_mode = MODE_RGBA;
  WebPAnimDecoder* decoder = WebPAnimDecoderNew(&data, &options);
  REQUIRE(decoder != nullptr);  // a valid animated WebP
  WebPAnimInfo info;
  REQUIRE(WebPAnimDecoderGetInfo(decoder, &info));
  Decoded d;
  d.width = int(info.canvas_width);
  d.height = int(info.canvas_height);
  d.frameCount = int(info.frame_count);
  std::uint8_t* pixels = nullptr;
  int timestamp = 0;
  while (WebPAnimDecoderGetNext(decoder, &pixels, &timestamp)) {
    d.frames.emplace_back(pixels, pixels + std::size_t(d.width) * std::size_t(d.height) * 4);
    d.timestamps.push_back(timestamp);
  }
  WebPAnimDecoderDelete(decoder);
  return d;
}

void write(const std::filesystem::path& file, const std::string& text) {
  std::ofstream out(file);
  out << text;
  REQUIRE(out);
}

// A box dropped from 0.5 m onto a floor whose top is at 0: in 0.25 s (6 frames at 24 frames
// a second) it falls 0.31 m, turning as it falls, and reaches nothing.
const std::string kFallingBox = R"({ "gravity": [0, 0, -9.81], "frame_rate": 24, "duration": 0.25, "scalar": "double",
  "contact": "microcollisions", "bodies": [
  { "name": "floor", "shape": {"box": [1, 1, 0.1]}, "position": [0, 0, -0.1], "static": true },
  { "name": "box", "shape": {"box": [0.1, 0.1, 0.1]}, "position": [0, 0, 0.5], "angular_velocity": [1, 2, 0] } ] })";

}  // namespace

TEST_CASE("gjkx_animate draws a gjkx_simulate run as an animated WebP in which the falling box moves") {
  const auto dir = test::freshFolder("gjkx-animate", "box");
  write(dir / "box.json", kFallingBox);
  const auto run = test::runProgram(GJKX_SIMULATE, (dir / "box.json").string() + " --out " + (dir / "run").string() + " --quiet");
  INFO(run.output);
  REQUIRE(run.status == 0);
  for (const std::string view : {"3d", "xz", "spacetime"}) {
    SECTION("view " + view) {
      const auto file = dir / ("box-" + view + ".webp");
      const auto r = test::runProgram(GJKX_ANIMATE, (dir / "box.json").string() + " " + (dir / "run").string() + " --out " +
                                                        file.string() + " --size 160x120 --hold 500 --view " + view);
      INFO(r.output);
      REQUIRE(r.status == 0);
      const Decoded d = decode(file);
      CHECK(d.width == 160);
      CHECK(d.height == 120);
      // The scene's start and its 6 frames, each shown 1/24 s (42 ms), the last held 500 ms more.
      REQUIRE(d.frameCount == 7);
      REQUIRE(d.frames.size() == 7);
      CHECK(d.timestamps.front() == 42);
      CHECK(d.timestamps.back() == 6 * 42 + 42 + 500);
      for (std::size_t k = 1; k < d.frames.size(); ++k) {
        INFO("frame " << k);
        CHECK(d.frames[k] != d.frames[k - 1]);  // the box has moved
      }
    }
  }
  SECTION("--from and --to choose the frames, --fps their pace") {
    const auto file = dir / "part.webp";
    const auto r = test::runProgram(GJKX_ANIMATE, (dir / "box.json").string() + " " + (dir / "run").string() + " --out " +
                                                      file.string() + " --size 96x96 --from 0.1 --to 0.2 --fps 10 --hold 0 --view xz");
    INFO(r.output);
    REQUIRE(r.status == 0);
    const Decoded d = decode(file);
    CHECK(d.frameCount == 2);  // frames 3 and 4 (t = 0.125 and 0.167 s) lie in [0.1, 0.2]
    CHECK(d.timestamps.back() == 200);  // each shown 1/10 s
  }
  SECTION("bad input is named") {
    std::filesystem::create_directories(dir / "empty");
    auto r = test::runProgram(GJKX_ANIMATE, (dir / "box.json").string() + " " + (dir / "empty").string() + " --out " + (dir / "x.webp").string());
    CHECK(r.status == 1);
    CHECK_THAT(r.output, Catch::Contains("bodies.csv: cannot read"));
    std::filesystem::copy_file(dir / "run" / "bodies.csv", dir / "empty" / "bodies.csv");
    r = test::runProgram(GJKX_ANIMATE, (dir / "box.json").string() + " " + (dir / "empty").string() + " --out " + (dir / "x.webp").string());
    CHECK(r.status == 1);
    CHECK_THAT(r.output, Catch::Contains("frames.csv: cannot read"));
    // A scene with a body more than the run's: each frame of bodies.csv lacks one.
    std::string more = kFallingBox;
    more.insert(more.rfind(']'), R"(, { "name": "ball", "shape": {"sphere": 0.1}, "position": [0.5, 0, 0.5] })");
    write(dir / "more.json", more);
    r = test::runProgram(GJKX_ANIMATE, (dir / "more.json").string() + " " + (dir / "run").string() + " --out " + (dir / "x.webp").string());
    CHECK(r.status == 1);
    CHECK_THAT(r.output, Catch::Contains("frame 1 has 2 bodies, the scene") && Catch::Contains("has 3"));
    // A scene without the run's box.
    std::string fewer = kFallingBox.substr(0, kFallingBox.find(",\n  { \"name\": \"box\"")) + " ] }";
    write(dir / "fewer.json", fewer);
    r = test::runProgram(GJKX_ANIMATE, (dir / "fewer.json").string() + " " + (dir / "run").string() + " --out " + (dir / "x.webp").string());
    CHECK(r.status == 1);
    CHECK_THAT(r.output, Catch::Contains("body 'box' is not in the scene"));
    CHECK_FALSE(std::filesystem::exists(dir / "x.webp"));
    // A bad command line: exit status 2.
    r = test::runProgram(GJKX_ANIMATE, (dir / "box.json").string() + " " + (dir / "run").string() + " --out x.webp --size 10");
    CHECK(r.status == 2);
    CHECK_THAT(r.output, Catch::Contains("--size"));
  }
  std::filesystem::remove_all(dir);
}

TEST_CASE("gjkx_animate --timewarp tells the cradle's Timewarp story, which the world's own trace confirms") {
  const auto dir = test::freshFolder("gjkx-animate", "cradle");
  const auto file = dir / "cradle.webp";
  // The replay that draws each ball at its local time checks its trace against a World's
  // event by event, and fails if they part.
  const auto r = test::runProgram(GJKX_ANIMATE, std::string(GJKX_SCENES) + "/cradle.json --timewarp --frames 2 --view xy --size 320x240 --out " + file.string());
  INFO(r.output);
  REQUIRE(r.status == 0);
  const Decoded d = decode(file);
  CHECK(d.width == 320);
  CHECK(d.height == 240);
  // Frame 1 alone: its start, the five balls flying (5 pictures), the collision of ball1 and
  // ball2, their rollback, their flights on (5), the frame's end: at least 14 pictures.
  CHECK(d.frameCount >= 14);
  std::filesystem::remove_all(dir);
}
