/// @file
/// @brief The canvas on which every figure of the paper is drawn: Cairo for lines, shapes
/// and text (Pango), OSMesa for the 3D scenes, PNG, SVG or PDF out.
///
/// Drawing happens panel by panel: choose a panel (a pixel rectangle), then either a 2D
/// world window (equal scaling in x and y) or a 3D Camera, and draw in world coordinates;
/// line widths, point radii, arrow heads and fonts are in pixels. 2D drawing is recorded
/// as Cairo vectors. A panel's 3D drawing (meshes, polygons and lines in space, depth
/// tested) is rendered offscreen by OSMesa, supersampled, into an image that Cairo lays
/// into the plot area; points and arrows in space, and every label, are drawn by Cairo
/// over it. Labels are laid over everything when the figure is written.
///
/// @code
/// using namespace gjkx::render;
/// Canvas canvas(800, 400);
/// canvas.setPanel({0, 0, 400, 400});
/// canvas.setWorldWindow(-2, 2, -2, 2);
/// canvas.title("Iteration 1");
/// canvas.polygon({{-1, -1}, {1, -1}, {0, 1}}, style::bodyP);
/// canvas.arrow({0, 0}, {1, 1}, style::directionStroke);
/// canvas.text({1, 1}, "s_1", mathLabel, Anchor::AboveRight);
/// canvas.setPanel({400, 0, 400, 400});
/// canvas.setCamera(Camera::orbit({0, 0, 0}, 1.8, 0.6, 0.4, 0.6, canvas.plotAspect()));
/// canvas.mesh(makeBox({-1, -1, -1}, {1, 1, 1}), MeshStyle{});
/// canvas.save("figure.svg");  // or .png, .pdf
/// @endcode
#pragma once

#include <gjkx/render/camera.hpp>
#include <gjkx/render/image.hpp>
#include <gjkx/render/mesh.hpp>
#include <gjkx/render/text.hpp>

#include <Eigen/Core>

#include <memory>
#include <string>
#include <vector>

namespace gjkx::render {

/// Where a label goes relative to the point it annotates: the side of the point on
/// which the label's ink box is placed, style::labelGap away.
enum class Anchor {
  Center,      ///< Centred on the point.
  Above,       ///< Above the point, centred horizontally.
  Below,       ///< Below the point, centred horizontally.
  Left,        ///< Left of the point, centred vertically.
  Right,       ///< Right of the point, centred vertically.
  AboveLeft,   ///< Above and to the left of the point.
  AboveRight,  ///< Above and to the right of the point.
  BelowLeft,   ///< Below and to the left of the point.
  BelowRight,  ///< Below and to the right of the point.
};

/// How a triangle mesh of a 3D figure is drawn.
struct MeshStyle {
  Color fill = palette::bodyPSolid;              ///< Colour of the faces; alpha < 1 makes the mesh translucent.
  Stroke edges = Stroke{palette::ink, 1.2, {}};  ///< Stroke of the feature edges (see featureEdges()); solid.
  bool drawEdges = true;                         ///< Whether to draw the feature edges.
  bool lit = true;                               ///< Flat shading by the figures' light; false paints fill as is.
};

/// Whether this build draws 3D (it found OSMesa); without it the 3D calls throw
/// std::runtime_error, and only the chapters without 3D figures are built.
bool canDraw3d();

/// A canvas for one figure of the paper; see the file comment. Movable, not copyable.
class Canvas {
 public:
  /// A @p width x @p height canvas of @p background with one panel covering it; throws
  /// std::invalid_argument naming "width" or "height" if one is not positive.
  Canvas(int width, int height, const Color& background = palette::background);
  ~Canvas();                                  ///< Frees the Cairo surfaces.
  Canvas(Canvas&& other) noexcept;             ///< Takes over @p other's drawing.
  Canvas& operator=(Canvas&& other) noexcept;  ///< Takes over @p other's drawing.
  Canvas(const Canvas&) = delete;              ///< Not copyable.
  Canvas& operator=(const Canvas&) = delete;   ///< Not copyable.

  /// Width of the figure in pixels.
  int width() const;
  /// Height of the figure in pixels.
  int height() const;
  /// Forgets everything drawn and every label; the figure becomes @p color.
  void clear(const Color& color = palette::background);

  // ---- panels ------------------------------------------------------------------------

  /// Makes @p rect (pixels, y down) the current panel: drawing is clipped to it, the
  /// world window is reset to pixel units, and 3D is off until setCamera(). The plot
  /// area is the panel minus @p padding on every side and @p titleBand at the top.
  /// Throws std::invalid_argument naming the field if the rectangle is empty or leaves
  /// the canvas.
  void setPanel(const PixelRect& rect, double padding = style::panelPadding, double titleBand = style::titleBand);
  /// The current panel in canvas pixels.
  PixelRect panel() const;
  /// The plot area of the current panel, where the world window is mapped.
  PixelRect plotArea() const;
  /// Width over height of the plot area: the aspect ratio to give perspective().
  double plotAspect() const;
  /// Maps [xmin, xmax] x [ymin, ymax] into the plot area with equal scaling in x and y,
  /// centred (the window may grow in one direction); throws std::invalid_argument
  /// naming "xmax" or "ymax" if an interval is empty.
  void setWorldWindow(double xmin, double xmax, double ymin, double ymax);
  /// Pixels per world unit of the current 2D window.
  double pixelsPerUnit() const;
  /// Canvas pixel position (x right, y down) of the 2D world point @p world.
  Eigen::Vector2d toPixel(const Eigen::Vector2d& world) const;
  /// Restricts lines, fills and meshes (not labels) to @p rect within the panel, e.g.
  /// `setClip(plotArea())` so that long lines stop at the plot area instead of running
  /// into the title; setPanel() resets it. Throws std::invalid_argument if the two do
  /// not overlap.
  void setClip(const PixelRect& rect);
  /// The rectangle drawing is currently clipped to.
  PixelRect clip() const;
  /// Draws @p markup centred in the title band of the current panel.
  void title(const std::string& markup, const TextStyle& style = titleText);
  /// Draws the outline of the current panel (for figures with boxed panels).
  void frame(const Stroke& stroke = style::axisStroke);

  // ---- 2D, world coordinates of the current panel ------------------------------------

  /// A straight line from @p a to @p b.
  void line(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Stroke& stroke = {});
  /// A polyline through @p points, closed back to the first point if @p closed.
  void polyline(const std::vector<Eigen::Vector2d>& points, const Stroke& stroke = {}, bool closed = false);
  /// A filled and outlined polygon (any simple polygon).
  void polygon(const std::vector<Eigen::Vector2d>& points, const ShapeStyle& shape);
  /// A point marker: a disc of @p radiusPx pixels, its outline ring inside that radius.
  void point(const Eigen::Vector2d& p, const Color& fill = palette::witness, double radiusPx = style::pointRadius,
             const Stroke& outline = style::noStroke);
  /// An arrow from @p from to @p to with a filled head @p headPx pixels long.
  void arrow(const Eigen::Vector2d& from, const Eigen::Vector2d& to, const Stroke& stroke = style::directionStroke,
             double headPx = style::arrowHead);
  /// A circle of world radius @p radius (> 0, else std::invalid_argument), filled and outlined.
  void circle(const Eigen::Vector2d& center, double radius, const ShapeStyle& shape);
  /// A label at world point @p p, on the side @p anchor, shifted by @p offsetPx pixels
  /// (x right, y up).
  void text(const Eigen::Vector2d& p, const std::string& markup, const TextStyle& style = mathLabel,
            Anchor anchor = Anchor::Center, const Eigen::Vector2d& offsetPx = Eigen::Vector2d::Zero());
  /// Axes through the origin across the plot area, and a small circle at the origin.
  void axes(const Stroke& stroke = style::axisStroke, bool originMarker = true);

  // ---- 3D, world coordinates through the camera of the current panel -----------------

  /// Switches the current panel to 3D through @p camera; NDC x and y in [-1, 1] cover
  /// the plot area.
  void setCamera(const Camera& camera);
  /// The camera of the current panel; std::logic_error without one (as every 3D call).
  const Camera& camera() const;
  /// A flat-shaded triangle mesh (one colour per face from a directional light plus
  /// ambient), depth tested, with its feature edges; translucent if the fill's alpha < 1
  /// (faces sorted back to front). Throws std::invalid_argument for bad indices.
  void mesh(const Mesh& mesh, const MeshStyle& meshStyle);
  /// A flat polygon in space (e.g. a supporting plane's patch), unlit, depth tested,
  /// with its outline.
  void polygon3(const std::vector<Eigen::Vector3d>& points, const ShapeStyle& shape);
  /// A depth-tested solid line segment in space.
  void line3(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Stroke& stroke = {});
  /// A depth-tested solid polyline in space.
  void polyline3(const std::vector<Eigen::Vector3d>& points, const Stroke& stroke = {}, bool closed = false);
  /// A point marker at the projection of @p p, drawn over the panel's 3D scene.
  void point3(const Eigen::Vector3d& p, const Color& fill = palette::witness, double radiusPx = style::pointRadius,
              const Stroke& outline = style::noStroke);
  /// An arrow between the projections of @p from and @p to, over the panel's 3D scene.
  void arrow3(const Eigen::Vector3d& from, const Eigen::Vector3d& to, const Stroke& stroke = style::directionStroke,
              double headPx = style::arrowHead);
  /// A label at the projection of @p p (never hidden; see text()).
  void text3(const Eigen::Vector3d& p, const std::string& markup, const TextStyle& style = mathLabel,
             Anchor anchor = Anchor::Center, const Eigen::Vector2d& offsetPx = Eigen::Vector2d::Zero());
  /// Canvas pixel position (x right, y down) and NDC depth of the 3D point @p p.
  Eigen::Vector3d project(const Eigen::Vector3d& p) const;

  // ---- labels in pixel coordinates and output ----------------------------------------

  /// A label at canvas pixel (@p x, @p y) (y down), on the side @p anchor.
  void textAtPixel(double x, double y, const std::string& markup, const TextStyle& style = mathLabel,
                   Anchor anchor = Anchor::Center);
  /// The finished figure as pixels, labels on top. Drawing may continue afterwards.
  Image image();
  /// Writes the finished figure to @p path as PNG, SVG or PDF, by its extension (.png,
  /// .svg, .pdf); throws std::invalid_argument for another extension and
  /// std::runtime_error naming the path if it cannot be written.
  void save(const std::string& path);

  /// Internal state (Cairo surfaces, the panel, the pending 3D scene, the labels).
  struct Impl;

 private:
  std::unique_ptr<Impl> impl_;
};

}  // namespace gjkx::render
