/// @file
/// @brief The canvas every figure of the paper is drawn on: Cairo draws lines, shapes and
/// text (set by Pango), OSMesa the 3D scenes, and the figure is written as PNG, SVG or PDF.
///
/// A figure is drawn panel by panel: choose a panel (a pixel rectangle), then a 2D world
/// window (equal scaling in x and y) or a 3D Camera, and draw in world coordinates; widths,
/// radii, arrow heads and fonts are in pixels. 2D drawing is kept as Cairo vectors. A
/// panel's meshes, polygons and lines in space are rendered by OSMesa, depth tested and
/// supersampled, into an image laid into the panel; points and arrows in space are drawn
/// by Cairo over it, and every label over everything when the figure is written:
///
/// @code
/// Canvas canvas(400, 400);
/// canvas.setWorldWindow(-2, 2, -2, 2);
/// canvas.polygon({{-1, -1}, {1, -1}, {0, 1}}, style::bodyP);
/// canvas.text({0, 1}, "s_1", mathLabel, Anchor::AboveRight);
/// canvas.save("figure.svg");  // or .png, .pdf
/// @endcode
#pragma once

#include <gjkx/render/camera.hpp>
#include <gjkx/render/text.hpp>

#include <Eigen/Core>

#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace gjkx::render {

/// A rectangle of pixels, x to the right and y down from the top-left corner of a figure.
struct PixelRect {
  int x = 0;       ///< Left column.
  int y = 0;       ///< Top row.
  int width = 0;   ///< Width in pixels.
  int height = 0;  ///< Height in pixels.
};

/// The side of the annotated point on which a label's ink box goes, style::labelGap away.
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

/// A triangle mesh of a 3D figure (a polytope, a convex piece, a bone): vertices, and
/// triangles as triples of vertex indices, either winding (shading is two-sided).
struct Mesh {
  std::vector<Eigen::Vector3d> vertices;      ///< Vertex positions in world coordinates.
  std::vector<std::array<int, 3>> triangles;  ///< Triangles as indices into vertices.
};

/// How a triangle mesh of a 3D figure is drawn.
struct MeshStyle {
  Color fill = palette::bodyPSolid;              ///< Colour of the faces; alpha < 1 makes the mesh translucent.
  Stroke edges = Stroke{palette::ink, 1.2, {}};  ///< Stroke of the feature edges (see Canvas::mesh()); solid.
  bool drawEdges = true;                         ///< Whether to draw the feature edges.
  bool lit = true;                               ///< Flat shading by the figures' light; false paints fill as is.
};

/// Whether this build draws 3D (it found OSMesa); without, writing a 3D figure throws
/// std::runtime_error, and only the chapters without 3D figures are built.
bool canDraw3d();

/// A canvas for one figure of the paper (see the file comment); movable.
class Canvas {
 public:
  /// A @p width x @p height canvas of @p background with one panel covering it; throws
  /// std::invalid_argument naming "width" or "height" if one is not positive.
  Canvas(int width, int height, const Color& background = palette::background);
  ~Canvas();                                   ///< Frees the Cairo surfaces.
  Canvas(Canvas&& other) noexcept;             ///< Takes over @p other's drawing.
  Canvas& operator=(Canvas&& other) noexcept;  ///< Takes over @p other's drawing.
  /// Width of the figure in pixels.
  int width() const;
  /// Height of the figure in pixels.
  int height() const;

  /// Makes @p rect (pixels, y down) the current panel: drawing is clipped to it, the world
  /// window is pixels, and 3D is off until setCamera(). The plot area is the panel less
  /// @p padding on every side and @p titleBand at the top. Throws std::invalid_argument
  /// naming the field if the rectangle is empty or leaves the canvas.
  void setPanel(const PixelRect& rect, double padding = style::panelPadding, double titleBand = style::titleBand);
  /// The current panel in canvas pixels.
  PixelRect panel() const;
  /// The plot area of the current panel, where the world window is mapped.
  PixelRect plotArea() const;
  /// Width over height of the plot area: the aspect ratio to give a Camera.
  double plotAspect() const;
  /// Maps [xmin, xmax] x [ymin, ymax] into the plot area with equal scaling, centred (the
  /// window may grow in one direction); std::invalid_argument naming "xmax" or "ymax" if
  /// an interval is empty.
  void setWorldWindow(double xmin, double xmax, double ymin, double ymax);
  /// Pixels per world unit of the current 2D window.
  double pixelsPerUnit() const;
  /// Canvas pixel (x right, y down) of the 2D world point @p world.
  Eigen::Vector2d toPixel(const Eigen::Vector2d& world) const;
  /// Restricts lines, fills and meshes (not labels) to @p rect within the panel, e.g. to
  /// the plot area so that long lines do not run into the title; setPanel() resets it.
  /// Throws std::invalid_argument if the two do not overlap.
  void setClip(const PixelRect& rect);
  /// Draws @p markup centred in the title band of the current panel.
  void title(const std::string& markup, const TextStyle& style = titleText);

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
  /// A label at world point @p p, on the side @p anchor, moved by @p offsetPx (x right, y up).
  void text(const Eigen::Vector2d& p, const std::string& markup, const TextStyle& style = mathLabel,
            Anchor anchor = Anchor::Center, const Eigen::Vector2d& offsetPx = Eigen::Vector2d::Zero());
  /// Axes through the origin across the plot area, and a small circle at the origin.
  void axes(const Stroke& stroke = style::axisStroke, bool originMarker = true);

  /// Switches the current panel to 3D through @p camera, NDC [-1, 1] covering the plot
  /// area. Every 3D call without a camera throws std::logic_error.
  void setCamera(const Camera& camera);
  /// A triangle mesh, flat shaded (one colour per face from a directional light plus
  /// ambient), depth tested, with its feature edges (those of one triangle, and those where
  /// two meet at more than a degree: a polytope's true edges, not its faces' diagonals);
  /// translucent if the fill's alpha < 1. Throws std::invalid_argument naming the triangle
  /// if an index is out of range.
  void mesh(const Mesh& mesh, const MeshStyle& meshStyle);
  /// A flat polygon in space (e.g. a supporting plane's patch), unlit, with its outline.
  void polygon3(const std::vector<Eigen::Vector3d>& points, const ShapeStyle& shape);
  /// A solid line segment in space.
  void line3(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Stroke& stroke = {});
  /// A solid polyline in space, closed back to the first point if @p closed.
  void polyline3(const std::vector<Eigen::Vector3d>& points, const Stroke& stroke = {}, bool closed = false);
  /// A point marker (see point()) at the projection of @p p, over the panel's 3D scene.
  void point3(const Eigen::Vector3d& p, const Color& fill = palette::witness, double radiusPx = style::pointRadius,
              const Stroke& outline = style::noStroke);
  /// An arrow (see arrow()) between the projections of @p from and @p to, over the 3D scene.
  void arrow3(const Eigen::Vector3d& from, const Eigen::Vector3d& to, const Stroke& stroke = style::directionStroke,
              double headPx = style::arrowHead);
  /// A label (see text()) at the projection of @p p.
  void text3(const Eigen::Vector3d& p, const std::string& markup, const TextStyle& style = mathLabel,
             Anchor anchor = Anchor::Center, const Eigen::Vector2d& offsetPx = Eigen::Vector2d::Zero());

  /// A label at canvas pixel (@p x, @p y) (y down), on the side @p anchor.
  void textAtPixel(double x, double y, const std::string& markup, const TextStyle& style = mathLabel,
                   Anchor anchor = Anchor::Center);
  /// Writes the finished figure, labels on top, to @p path as PNG, SVG or PDF by its
  /// extension (std::invalid_argument for another; std::runtime_error if it cannot write);
  /// drawing may go on afterwards. The same figure gives the same bytes of PNG.
  void save(const std::string& path);
  /// The finished figure as save() would write it, as pixels: width() x height() of them,
  /// row by row from the top, 4 bytes each (red, green, blue, alpha; not premultiplied),
  /// e.g. a frame of an animation. Drawing may go on afterwards.
  std::vector<std::uint8_t> rgba();

  struct Impl;  ///< Cairo's surfaces, the panel, the pending 3D scene, the labels.

 private:
  std::unique_ptr<Impl> impl_;
};

}  // namespace gjkx::render
