// Tests of the renderer that draws the paper's figures: determinism, fills, antialiasing,
// text markup, PNG, SVG and PDF, the kept figures' comparison, 3D depth testing, bad input.
#include "kept_figures.hpp"

#include <gjkx/render/canvas.hpp>
#include <gjkx/render/text.hpp>

#include <catch2/catch.hpp>

#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <string>
#include <vector>

using namespace gjkx::render;
using Eigen::Vector2d;
using Eigen::Vector3d;

namespace {

// Each test case runs as its own process, and CTest runs them side by side: the process id
// keeps one case's files apart from another's.
std::string tempPath(const std::string& name) {
  return (std::filesystem::temp_directory_path() /
          ("gjkx_render_test_" + std::to_string(::getpid()) + "_" + name)).string();
}

std::vector<char> fileBytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::vector<char>(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

// A small 2D scene with every kind of 2D primitive and a label.
void drawScene(Canvas& c) {
  c.setPanel({0, 0, 160, 120});
  c.setWorldWindow(-3, 3, -3, 3);
  c.title("Scene $s_1$");
  c.axes();
  c.polygon({{-2, -2}, {0, -2.5}, {0.5, 0}, {-1.5, 1}}, style::bodyP);
  c.polygon({{0, 0}, {2, 0.5}, {1.5, 2}}, style::bodyQ);
  c.line({-3, 2}, {3, -1}, style::separatingStroke);
  c.arrow({0, 0}, {1, -1.5}, style::directionStroke);
  c.point({0.5, 0});
  c.circle({-2, 2}, 0.5, ShapeStyle{palette::highlight.withAlpha(0.3), style::highlightStroke});
  c.text({1, -1.5}, "s_1", mathLabel, Anchor::BelowRight);
  c.text({-1, -1}, "V_P");
}

// The cube [-1, 1]^3 as 12 triangles, two per face.
Mesh cube() {
  Mesh m;
  for (int i = 0; i < 8; ++i) m.vertices.emplace_back(i & 1 ? 1 : -1, i & 2 ? 1 : -1, i & 4 ? 1 : -1);
  m.triangles = {{0, 2, 3}, {0, 3, 1}, {4, 5, 7}, {4, 7, 6}, {0, 1, 5}, {0, 5, 4},
                 {2, 6, 7}, {2, 7, 3}, {0, 4, 6}, {0, 6, 2}, {1, 3, 7}, {1, 7, 5}};
  return m;
}

// What a canvas draws, read back from the PNG it writes.
struct Drawn {
  kept::Pixels pixels;
  std::array<std::uint8_t, 4> pixel(int x, int y) const { return pixels.rgba(x, y); }
};

Drawn drawn(Canvas& c) {
  const std::string path = tempPath("drawn.png");
  c.save(path);
  Drawn d{kept::readPng(path)};
  std::remove(path.c_str());
  return d;
}

bool isWhite(const std::array<std::uint8_t, 4>& p) { return p[0] == 255 && p[1] == 255 && p[2] == 255; }

int expectedBlend(double fill, double alpha) { return static_cast<int>(std::lround(255.0 * (1.0 - alpha + fill * alpha))); }

}  // namespace

TEST_CASE("drawing the same scene twice gives identical pixels and PNG bytes", "[render]") {
  Drawn first, second;
  {
    Canvas a(160, 120);
    drawScene(a);
    first = drawn(a);
    a.save(tempPath("det_a.png"));
  }
  {
    Canvas b(160, 120);
    drawScene(b);
    second = drawn(b);
    b.save(tempPath("det_b.png"));
  }
  REQUIRE(first.pixels.width == 160);
  REQUIRE(first.pixels.height == 120);
  CHECK(first.pixels.argb == second.pixels.argb);
  const auto bytesA = fileBytes(tempPath("det_a.png"));
  CHECK(!bytesA.empty());
  CHECK(bytesA == fileBytes(tempPath("det_b.png")));
  // Something was drawn at all.
  int inked = 0;
  for (int y = 0; y < 120; ++y)
    for (int x = 0; x < 160; ++x) inked += !isWhite(first.pixel(x, y));
  CHECK(inked > 500);
  std::remove(tempPath("det_a.png").c_str());
  std::remove(tempPath("det_b.png").c_str());
}

TEST_CASE("many canvases one after another and side by side", "[render]") {
  Drawn reference;
  for (int i = 0; i < 12; ++i) {
    Canvas c(160, 120);
    drawScene(c);
    const Drawn img = drawn(c);
    if (i == 0) reference = img;
    else CHECK(img.pixels.argb == reference.pixels.argb);
  }
  // Two live canvases drawn alternately keep their own contexts.
  Canvas x(160, 120), y(160, 120);
  x.setWorldWindow(0, 10, 0, 10);
  y.setWorldWindow(0, 10, 0, 10);
  x.polygon({{0, 0}, {10, 0}, {10, 10}, {0, 10}}, ShapeStyle{Color::hex(0xFF0000), style::noStroke});
  y.polygon({{0, 0}, {10, 0}, {10, 10}, {0, 10}}, ShapeStyle{Color::hex(0x0000FF), style::noStroke});
  const auto px = drawn(x).pixel(80, 60), py = drawn(y).pixel(80, 60);
  CHECK(px[0] == 255);
  CHECK(px[2] == 0);
  CHECK(py[0] == 0);
  CHECK(py[2] == 255);
  // A moved canvas keeps working.
  Canvas moved = std::move(x);
  CHECK(drawn(moved).pixel(10, 10)[0] == 255);
}

TEST_CASE("a translucent polygon covers its inside with its fill blended on white", "[render]") {
  Canvas c(100, 100);
  c.setWorldWindow(0, 10, 0, 10);
  const Color fill = palette::bodyPFill;
  c.polygon({{2, 2}, {8, 2}, {8, 8}, {2, 8}}, ShapeStyle{fill, style::bodyPStroke});
  const Drawn img = drawn(c);
  const auto inside = img.pixel(50, 50);
  CHECK(std::abs(inside[0] - expectedBlend(fill.r, fill.a)) <= 2);
  CHECK(std::abs(inside[1] - expectedBlend(fill.g, fill.a)) <= 2);
  CHECK(std::abs(inside[2] - expectedBlend(fill.b, fill.a)) <= 2);
  CHECK(inside[3] == 255);
  CHECK(isWhite(img.pixel(5, 5)));
  CHECK(isWhite(img.pixel(95, 50)));
  // The outline is dark: the pixel on the left edge (x = 2 world = 20 px) is much darker than the fill.
  CHECK(img.pixel(20, 50)[0] < inside[0] - 60);
  // A non-convex polygon leaves its notch empty.
  Canvas d(100, 100);
  d.setWorldWindow(0, 10, 0, 10);
  d.polygon({{1, 1}, {9, 1}, {9, 9}, {5, 3}, {1, 9}}, ShapeStyle{Color::hex(0x000000), style::noStroke});
  const Drawn notch = drawn(d);
  CHECK(isWhite(notch.pixel(50, 20)));        // world (5, 8): inside the notch
  CHECK(notch.pixel(50, 80)[0] < 10);         // world (5, 2): inside the polygon
  CHECK(notch.pixel(20, 50)[0] < 10);         // world (2, 5): inside the left lobe
}

TEST_CASE("a diagonal line is anti-aliased", "[render]") {
  Canvas c(100, 100);
  c.setWorldWindow(0, 10, 0, 10);
  c.line({1, 1}, {9, 6}, Stroke{palette::ink, 1.5, {}});
  const Drawn img = drawn(c);
  int intermediate = 0, dark = 0;
  for (int y = 0; y < img.pixels.height; ++y)
    for (int x = 0; x < img.pixels.width; ++x) {
      const int v = img.pixel(x, y)[0];
      if (v > 20 && v < 235) ++intermediate;
      if (v <= 100) ++dark;
    }
  CHECK(dark > 40);
  CHECK(intermediate > 60);
}

TEST_CASE("drawing is clipped to the panel, or to a narrower clip rectangle", "[render]") {
  Canvas c(200, 100);
  c.setPanel({0, 0, 100, 100}, 10, 20);
  c.setWorldWindow(0, 10, 0, 10);
  c.line({-100, 5}, {100, 5}, Stroke{palette::ink, 3, {}});  // far beyond the panel
  c.line({5, -100}, {5, 100}, Stroke{palette::ink, 3, {}});
  c.setClip(c.plotArea());
  c.line({-100, 2}, {100, 2}, Stroke{palette::ink, 3, {}});
  c.line({2, -100}, {2, 100}, Stroke{palette::ink, 3, {}});
  const PixelRect plot = c.plotArea();
  CHECK(plot.x == 10);
  CHECK(plot.y == 30);
  const Drawn img = drawn(c);
  const Eigen::Vector2d v5 = c.toPixel({5, 5}), v2 = c.toPixel({2, 2});
  const int col5 = static_cast<int>(std::lround(v5.x())), col2 = static_cast<int>(std::lround(v2.x()));
  CHECK(img.pixel(col5, 2)[0] < 60);             // unclipped line reaches the panel's top edge
  CHECK(isWhite(img.pixel(col2, 2)));            // clipped line stops at the plot area
  CHECK(img.pixel(col2, plot.y + 5)[0] < 60);
  CHECK(isWhite(img.pixel(150, static_cast<int>(std::lround(v5.y())))));  // nothing in the other half
  CHECK_THROWS_AS(c.setClip({150, 0, 10, 10}), std::invalid_argument);
}

TEST_CASE("labels are typeset with subscripts and drawn in their box", "[render]") {
  const TextExtent s = measureText("s", Font::Math, 20);
  const TextExtent s12 = measureText("s_{12}", Font::Math, 20);
  CHECK(s.width() > 0);
  CHECK(s12.width() > s.width());
  CHECK(s12.descent > s.descent + 2);  // the subscript sits below the baseline
  CHECK(s12.advance > s.advance);
  CHECK(measureText("10^4", Font::Math, 20).ascent > measureText("10", Font::Math, 20).ascent);
  CHECK(measureText("S_P(s_1)", Font::Math, 20).width() > measureText("S", Font::Math, 20).width());
  CHECK(measureText("", Font::Sans, 20).width() == 0);
  CHECK_THROWS_AS(measureText("s_{12", Font::Math, 20), std::invalid_argument);
  CHECK_THROWS_AS(measureText("\\nosuchcommand", Font::Math, 20), std::invalid_argument);
  CHECK_THROWS_AS(measureText("x", Font::Math, 0), std::invalid_argument);

  Canvas c(120, 80);
  c.textAtPixel(60, 40, "V_P", mathLabel, Anchor::Center);
  const Drawn img = drawn(c);
  const TextExtent e = measureText("V_P", Font::Math, mathLabel.size);
  int changedInside = 0, changedOutside = 0;
  for (int y = 0; y < img.pixels.height; ++y)
    for (int x = 0; x < img.pixels.width; ++x) {
      // Antialiasing may touch the pixel beyond a fractional edge of the ink box.
      const bool inBox = std::abs(x - 60) <= e.width() / 2 + 2 && std::abs(y - 40) <= e.height() / 2 + 2;
      if (!isWhite(img.pixel(x, y))) ++(inBox ? changedInside : changedOutside);
    }
  CHECK(changedInside > 20);
  CHECK(changedOutside == 0);
}

TEST_CASE("the label markup becomes Pango markup: sub, sup, italic math letters, escapes", "[render]") {
  CHECK(pangoMarkup("V_P", Font::Math) == "<i>V</i><sub><i>P</i></sub>");
  CHECK(pangoMarkup("s_{12}^2", Font::Math) == "<i>s</i><sub>12</sub><sup>2</sup>");
  CHECK(pangoMarkup("-x", Font::Math) == "−<i>x</i>");                        // a minus sign
  CHECK(pangoMarkup("a-b & c", Font::Sans) == "a-b &amp; c");                  // plain text, escaped for Pango
  CHECK(pangoMarkup("t_c", Font::Sans) == "t<sub>c</sub>");
  CHECK(pangoMarkup("$x$ \\alpha", Font::Sans).find("<span font_family=\"DejaVu Serif\"><i>x</i></span>") == 0);
  CHECK(pangoMarkup("\\alpha\\le\\_", Font::Math) == "<i>α</i>≤_");
  CHECK_THROWS_AS(pangoMarkup("s_", Font::Math), std::invalid_argument);
}

TEST_CASE("a figure is written as PNG, SVG or PDF by its extension", "[render]") {
  Canvas c(160, 120);
  drawScene(c);
  const auto starts = [](const std::string& path, const std::string& head) {
    const std::vector<char> bytes = fileBytes(path);
    return bytes.size() > 200 && std::string(bytes.begin(), bytes.begin() + std::ptrdiff_t(head.size())) == head;
  };
  c.save(tempPath("out.png"));
  c.save(tempPath("out.svg"));
  c.save(tempPath("out.pdf"));
  CHECK(starts(tempPath("out.png"), "\x89PNG"));
  CHECK(starts(tempPath("out.svg"), "<?xml"));
  CHECK(starts(tempPath("out.pdf"), "%PDF"));
  CHECK(kept::compare(kept::readPng(tempPath("out.png")), drawn(c).pixels, 0).differingPixels == 0);
  for (const char* ext : {"png", "svg", "pdf"}) std::remove(tempPath(std::string("out.") + ext).c_str());
  CHECK_THROWS_AS(c.save(tempPath("out.jpg")), std::invalid_argument);
  CHECK_THROWS_AS(c.save(tempPath("no_such_dir/out.svg")), std::runtime_error);
}

TEST_CASE("kept figures: a PNG read back, compared pixel by pixel within the tolerance", "[render]") {
  Canvas c(160, 120);
  drawScene(c);
  const kept::Pixels img = drawn(c).pixels;
  const kept::Diff same = kept::compare(img, img, 0);
  CHECK(same.sameSize);
  CHECK(same.differingPixels == 0);
  CHECK(same.maxChannelDifference == 0);
  CHECK(same.same());

  kept::Pixels changed = img;
  changed.argb[10 * 160 + 10] = 0xFF000000u;  // black
  changed.argb[10 * 160 + 11] = 0xFFFAFAFAu;  // a small change: within the threshold of a white pixel
  const kept::Diff diff = kept::compare(img, changed);
  CHECK(diff.sameSize);
  CHECK(diff.differingPixels == 1);
  CHECK(diff.maxChannelDifference >= 200);
  CHECK(diff.differingFraction == Approx(1.0 / (160.0 * 120.0)));
  CHECK(diff.same());  // one pixel of 19,200 is within kTolerance
  kept::Pixels smaller = img;
  smaller.width = 10;
  CHECK_FALSE(kept::compare(img, smaller).same());

  const std::string missing = tempPath("no_such_dir/none.png");
  try {
    kept::readPng(missing);
    FAIL("readPng of a missing file must throw");
  } catch (const std::runtime_error& e) {
    CHECK(std::string(e.what()).find(missing) != std::string::npos);
  }
  const std::string notPng = tempPath("not_a_png.png");
  std::ofstream(notPng) << "hello";
  CHECK_THROWS_AS(kept::readPng(notPng), std::runtime_error);
  std::remove(notPng.c_str());
}

TEST_CASE("a lit cube is drawn and the depth test hides what is behind", "[render]") {
  Canvas c(120, 120);
  if (!canDraw3d()) {  // a build without OSMesa says so when a 3D figure is written
    c.setCamera(Camera{lookAt({3, 2.5, 2}, {0, 0, 0}, {0, 0, 1}), perspective(0.8, 1, 0.1, 20)});
    c.mesh(cube(), MeshStyle{});
    CHECK_THROWS_AS(drawn(c), std::runtime_error);
    return;
  }
  c.setCamera(Camera{lookAt({3, 2.5, 2}, {0, 0, 0}, {0, 0, 1}), perspective(0.8, c.plotAspect(), 0.1, 20)});
  c.mesh(cube(), MeshStyle{});
  const Drawn cube = drawn(c);
  CHECK(!isWhite(cube.pixel(60, 60)));
  CHECK(isWhite(cube.pixel(2, 2)));
  // Faces at different angles to the light get different shades.
  CHECK(cube.pixel(60, 40) != cube.pixel(60, 80));
  // One colour per face, exactly: the two triangles of the top face (split along a
  // diagonal) are shaded alike, so no seam runs across it.
  const auto top = cube.pixel(58, 30);
  int seam = 0;
  for (int x = 40; x <= 76; ++x)
    for (int y = 26; y <= 34; ++y) seam += cube.pixel(x, y) != top;
  CHECK(seam == 0);

  const auto centreAfter = [](bool redFirst) {
    Canvas d(80, 80);
    d.setCamera(Camera{lookAt({0, 0, 0}, {0, 0, -1}, {0, 1, 0}), perspective(1.0, 1.0, 0.5, 50)});
    Mesh red, blue;
    red.vertices = {{-5, -5, -10}, {5, -5, -10}, {0, 5, -10}};
    red.triangles = {{0, 1, 2}};
    blue.vertices = {{-1, -1, -3}, {1, -1, -3}, {0, 1, -3}};
    blue.triangles = {{0, 1, 2}};
    const MeshStyle redStyle{Color::hex(0xFF0000), style::noStroke, false, false};
    const MeshStyle blueStyle{Color::hex(0x0000FF), style::noStroke, false, false};
    if (redFirst) {
      d.mesh(red, redStyle);
      d.mesh(blue, blueStyle);
    } else {
      d.mesh(blue, blueStyle);
      d.mesh(red, redStyle);
    }
    return drawn(d).pixel(40, 40);
  };
  const auto a = centreAfter(true), b = centreAfter(false);
  CHECK(a[2] == 255);
  CHECK(a[0] == 0);
  CHECK(b[2] == 255);
  CHECK(b[0] == 0);

  // 3D calls without a camera are a usage error.
  Canvas e(40, 40);
  CHECK_THROWS_AS(e.line3({0, 0, 0}, {1, 1, 1}), std::logic_error);
}

TEST_CASE("invalid sizes throw std::invalid_argument naming the field", "[render]") {
  const auto message = [](auto&& make) {
    try {
      make();
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string("no exception");
  };
  CHECK(message([] { Canvas c(0, 10); }).find("width") != std::string::npos);
  CHECK(message([] { Canvas c(10, -1); }).find("height") != std::string::npos);
  Canvas c(50, 50);
  CHECK(message([&] { c.setPanel({0, 0, 0, 10}); }).find("width") != std::string::npos);
  CHECK(message([&] { c.setWorldWindow(1, 1, 0, 1); }).find("xmax") != std::string::npos);
  CHECK_THROWS_AS(c.setPanel({40, 0, 20, 10}), std::invalid_argument);
  CHECK_THROWS_AS(perspective(0.0, 1.0, 0.1, 1.0), std::invalid_argument);
}
