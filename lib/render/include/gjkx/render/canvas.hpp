/// @file
/// @brief The offscreen canvas on which every figure of the paper is drawn.
///
/// A Canvas owns one OSMesa context and an anti-aliased (multisampled and
/// supersampled) framebuffer. Drawing happens panel by panel: choose a panel
/// (a pixel rectangle), then either a 2D world window (equal scaling in x and
/// y) or a 3D Camera, and draw in world coordinates; line widths, point radii,
/// arrow heads and fonts are in pixels. Labels are typeset with FreeType and
/// laid over the image when it is read (so they are always on top).
///
/// @code
/// using namespace gjkx::render;
/// Canvas canvas(800, 400);
/// canvas.setPanel({0, 0, 400, 400});
/// canvas.setWorldWindow(-2, 2, -2, 2);
/// canvas.title("Iteration 1");
/// canvas.axes();
/// canvas.polygon({{-1, -1}, {1, -1}, {0, 1}}, style::bodyP);
/// canvas.arrow({0, 0}, {1, 1}, style::directionStroke);
/// canvas.point({0, 0});
/// canvas.text({1, 1}, "s_1", mathLabel, Anchor::AboveRight);
/// canvas.setPanel({400, 0, 400, 400});
/// canvas.setCamera(Camera::orbit({0, 0, 0}, 1.8, 0.6, 0.4, 0.6, canvas.plotAspect()));
/// canvas.mesh(makeBox({-1, -1, -1}, {1, 1, 1}), MeshStyle{});
/// canvas.savePng("figure.png");
/// @endcode
#pragma once

#include <gjkx/render/camera.hpp>
#include <gjkx/render/image.hpp>
#include <gjkx/render/mesh.hpp>
#include <gjkx/render/style.hpp>
#include <gjkx/render/text.hpp>

#include <Eigen/Core>

#include <memory>
#include <string>
#include <vector>

namespace gjkx::render {

/// Where a label goes relative to the point it annotates (the side of the
/// point on which the label's ink box is placed, with a gap of style::labelGap).
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
  Color fill = palette::bodyPSolid;                ///< Base colour of the faces; alpha < 1 makes the mesh translucent.
  Stroke edges = Stroke{palette::ink, 1.2, {}};    ///< Stroke of the feature edges (see featureEdges()).
  bool drawEdges = true;                           ///< Whether to draw the feature edges.
  bool lit = true;                                 ///< Flat shading with the figures' light; false paints fill as is.
};

/// Quality and size settings of a Canvas (defaults from style.hpp).
struct CanvasOptions {
  int samples = style::msaaSamples;         ///< Multisamples per pixel (clamped to the GL limit; 1 disables MSAA).
  int supersample = style::supersample;     ///< Rendering scale averaged down on readback (1 to 4).
  Color background = palette::background;  ///< Colour of a cleared canvas.
};

/// An offscreen OpenGL (OSMesa) canvas for one figure of the paper; see the
/// file comment for an example. Not copyable; movable. Several canvases may
/// exist one after another or at the same time in one thread.
class Canvas {
 public:
  /// A @p width x @p height canvas cleared to the background, with one panel
  /// covering it. Throws std::invalid_argument naming "width", "height",
  /// "samples" or "supersample" for invalid values, std::runtime_error if no
  /// OSMesa context can be created.
  /// @param width Width of the figure in pixels (> 0).
  /// @param height Height of the figure in pixels (> 0).
  /// @param options Anti-aliasing settings and background.
  Canvas(int width, int height, const CanvasOptions& options = {});
  /// Destroys the OSMesa context and its framebuffers.
  ~Canvas();
  /// Moves the context of @p other into a new canvas.
  /// @param other The canvas to move from; it becomes unusable.
  Canvas(Canvas&& other) noexcept;
  /// Moves the context of @p other into this canvas (destroying this one's).
  /// @param other The canvas to move from; it becomes unusable.
  /// @return This canvas.
  Canvas& operator=(Canvas&& other) noexcept;
  Canvas(const Canvas&) = delete;             ///< Not copyable (owns a GL context).
  Canvas& operator=(const Canvas&) = delete;  ///< Not copyable (owns a GL context).

  /// Width of the figure in pixels.
  /// @return The width in pixels.
  int width() const;
  /// Height of the figure in pixels.
  /// @return The height in pixels.
  int height() const;
  /// Multisamples per pixel actually used (1 if multisampling is unavailable).
  /// @return The sample count.
  int samples() const;
  /// Supersampling factor actually used.
  /// @return The supersampling factor.
  int supersample() const;

  /// Fills the whole canvas with @p color and forgets all labels.
  /// @param color The new background.
  void clear(const Color& color = palette::background);

  // ---- panels -------------------------------------------------------------

  /// Makes @p rect (pixels, y down) the current panel of the figure: drawing
  /// is clipped to it, its depth buffer is cleared, the world window is reset
  /// to pixel units, and 3D drawing is off until setCamera(). The plot area
  /// is the panel minus @p padding on every side and @p titleBand at the top.
  /// Throws std::invalid_argument naming the field if the rectangle is empty
  /// or leaves the canvas.
  /// @param rect The panel in canvas pixels.
  /// @param padding Blank border inside the panel, in pixels.
  /// @param titleBand Height reserved for the title at the top, in pixels (0 for none).
  void setPanel(const PixelRect& rect, double padding = style::panelPadding, double titleBand = style::titleBand);
  /// The current panel.
  /// @return The panel in canvas pixels.
  PixelRect panel() const;
  /// The plot area of the current panel (where the world window is mapped).
  /// @return The plot area in canvas pixels.
  PixelRect plotArea() const;
  /// Width / height of the plot area, the aspect ratio to give perspective().
  /// @return Width divided by height of the plot area.
  double plotAspect() const;
  /// Maps the world window [xmin, xmax] x [ymin, ymax] into the plot area with
  /// equal scaling in x and y, centred (the window may grow in one direction).
  /// Throws std::invalid_argument if an interval is empty.
  /// @param xmin Smallest visible x.
  /// @param xmax Largest visible x.
  /// @param ymin Smallest visible y.
  /// @param ymax Largest visible y.
  void setWorldWindow(double xmin, double xmax, double ymin, double ymax);
  /// Pixels per world unit of the current 2D window.
  /// @return The scale of the world window.
  double pixelsPerUnit() const;
  /// Canvas pixel position (x right, y down) of the 2D world point @p world.
  /// @param world A point in world coordinates of the panel.
  /// @return The pixel position.
  Eigen::Vector2d toPixel(const Eigen::Vector2d& world) const;
  /// Restricts the drawing of lines, fills and meshes (not labels) to
  /// @p rect intersected with the current panel, e.g.
  /// `setClip(plotArea())` so that the long separating lines of a figure stop
  /// at the plot area instead of running into the title. setPanel() resets it.
  /// Throws std::invalid_argument if the intersection is empty.
  /// @param rect The clip rectangle in canvas pixels.
  void setClip(const PixelRect& rect);
  /// The rectangle drawing is currently clipped to.
  /// @return The clip rectangle in canvas pixels.
  PixelRect clip() const;
  /// Draws @p markup centred in the title band of the current panel.
  /// @param markup The title (tiny TeX-like markup, see text.hpp).
  /// @param style Font, size and colour of the title.
  void title(const std::string& markup, const TextStyle& style = titleText);
  /// Draws the outline of the current panel (for figures with boxed panels).
  /// @param stroke Colour and width of the frame.
  void frame(const Stroke& stroke = style::axisStroke);

  // ---- 2D, world coordinates of the current panel -------------------------

  /// A straight line from @p a to @p b.
  /// @param a Start point.
  /// @param b End point.
  /// @param stroke Colour, width and dashes.
  void line(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Stroke& stroke = {});
  /// A polyline through @p points, closed back to the first point if @p closed.
  /// @param points The vertices in order.
  /// @param stroke Colour, width and dashes.
  /// @param closed Whether to join the last point to the first.
  void polyline(const std::vector<Eigen::Vector2d>& points, const Stroke& stroke = {}, bool closed = false);
  /// A filled polygon with outline (any simple polygon; convex ones are typical).
  /// @param points The vertices in order (at least 3 for a fill).
  /// @param shape Fill colour (translucent fills blend) and outline.
  void polygon(const std::vector<Eigen::Vector2d>& points, const ShapeStyle& shape);
  /// A point marker: a disc of @p radiusPx pixels with an outline ring.
  /// @param p The point.
  /// @param fill Colour of the disc.
  /// @param radiusPx Radius in pixels.
  /// @param outline Stroke of the ring (noStroke for none).
  void point(const Eigen::Vector2d& p, const Color& fill = palette::witness, double radiusPx = style::pointRadius,
             const Stroke& outline = style::noStroke);
  /// An arrow from @p from to @p to with a filled head of @p headPx pixels.
  /// @param from Tail of the arrow.
  /// @param to Tip of the arrow.
  /// @param stroke Colour and width of the shaft (the head uses the colour).
  /// @param headPx Length of the head in pixels.
  void arrow(const Eigen::Vector2d& from, const Eigen::Vector2d& to, const Stroke& stroke = style::directionStroke,
             double headPx = style::arrowHead);
  /// A circle of world radius @p radius, filled and outlined.
  /// @param center The centre.
  /// @param radius The radius in world units.
  /// @param shape Fill (palette::none for none) and outline.
  void circle(const Eigen::Vector2d& center, double radius, const ShapeStyle& shape);
  /// A label at world point @p p, placed by @p anchor and shifted by
  /// @p offsetPx pixels (x right, y up).
  /// @param p The annotated point.
  /// @param markup The label (tiny TeX-like markup, see text.hpp).
  /// @param style Font, size, colour and halo.
  /// @param anchor Side of the point on which the label goes.
  /// @param offsetPx Extra shift in pixels, x right and y up.
  void text(const Eigen::Vector2d& p, const std::string& markup, const TextStyle& style = mathLabel,
            Anchor anchor = Anchor::Center, const Eigen::Vector2d& offsetPx = Eigen::Vector2d::Zero());
  /// Axes through the origin spanning the plot area, and a small origin marker.
  /// @param stroke Colour and width of the axes.
  /// @param originMarker Whether to mark the origin with a small circle.
  void axes(const Stroke& stroke = style::axisStroke, bool originMarker = true);

  // ---- 3D, world coordinates through the camera of the current panel ------

  /// Switches the current panel to 3D drawing through @p camera; NDC x and y
  /// in [-1, 1] cover the plot area.
  /// @param camera View and projection of the panel.
  void setCamera(const Camera& camera);
  /// The camera of the current panel.
  /// @return The camera set by setCamera().
  const Camera& camera() const;
  /// A flat-shaded triangle mesh (directional light plus ambient), depth
  /// tested, with its feature edges; translucent if the fill's alpha < 1.
  /// Throws std::invalid_argument for bad triangle indices; std::logic_error
  /// without a camera (as do all 3D calls).
  /// @param mesh The mesh in world coordinates.
  /// @param meshStyle Fill, lighting and edges.
  void mesh(const Mesh& mesh, const MeshStyle& meshStyle);
  /// A flat convex polygon in space (e.g. a supporting plane patch), unlit,
  /// depth tested, with an outline.
  /// @param points The vertices in order.
  /// @param shape Fill and outline.
  void polygon3(const std::vector<Eigen::Vector3d>& points, const ShapeStyle& shape);
  /// A depth-tested line segment in space.
  /// @param a Start point.
  /// @param b End point.
  /// @param stroke Colour, width and dashes.
  void line3(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Stroke& stroke = {});
  /// A depth-tested polyline in space.
  /// @param points The vertices in order.
  /// @param stroke Colour, width and dashes.
  /// @param closed Whether to join the last point to the first.
  void polyline3(const std::vector<Eigen::Vector3d>& points, const Stroke& stroke = {}, bool closed = false);
  /// A depth-tested point marker in space (a disc facing the viewer).
  /// @param p The point.
  /// @param fill Colour of the disc.
  /// @param radiusPx Radius in pixels.
  /// @param outline Stroke of the ring.
  void point3(const Eigen::Vector3d& p, const Color& fill = palette::witness, double radiusPx = style::pointRadius,
              const Stroke& outline = style::noStroke);
  /// A depth-tested arrow in space with a head of @p headPx pixels on screen.
  /// @param from Tail of the arrow.
  /// @param to Tip of the arrow.
  /// @param stroke Colour and width of the shaft.
  /// @param headPx Length of the head in pixels.
  void arrow3(const Eigen::Vector3d& from, const Eigen::Vector3d& to, const Stroke& stroke = style::directionStroke,
              double headPx = style::arrowHead);
  /// A label anchored at the projection of the 3D point @p p (never hidden;
  /// labels are laid over the image).
  /// @param p The annotated point.
  /// @param markup The label (tiny TeX-like markup, see text.hpp).
  /// @param style Font, size, colour and halo.
  /// @param anchor Side of the point on which the label goes.
  /// @param offsetPx Extra shift in pixels, x right and y up.
  void text3(const Eigen::Vector3d& p, const std::string& markup, const TextStyle& style = mathLabel,
             Anchor anchor = Anchor::Center, const Eigen::Vector2d& offsetPx = Eigen::Vector2d::Zero());
  /// Canvas pixel position (x right, y down) and NDC depth of the 3D point @p p.
  /// @param p A point of the scene.
  /// @return Pixel x, pixel y and depth.
  Eigen::Vector3d project(const Eigen::Vector3d& p) const;

  // ---- labels in pixel coordinates and output ------------------------------

  /// A label at canvas pixel (@p x, @p y) (y down), placed by @p anchor.
  /// @param x Column of the annotated position.
  /// @param y Row of the annotated position.
  /// @param markup The label (tiny TeX-like markup, see text.hpp).
  /// @param style Font, size, colour and halo.
  /// @param anchor Side of the position on which the label goes.
  void textAtPixel(double x, double y, const std::string& markup, const TextStyle& style = mathLabel,
                   Anchor anchor = Anchor::Center);
  /// The finished figure: resolves the anti-aliasing, reads the pixels back
  /// and lays the labels over them. Drawing may continue afterwards.
  /// @return The rendered figure.
  Image image();
  /// Writes image() as a deterministic PNG to @p path; throws
  /// std::runtime_error naming the path if it cannot be written.
  /// @param path The PNG file to create.
  void savePng(const std::string& path);

  /// Internal state (OSMesa context, framebuffers, panel); opaque to users.
  struct Impl;

 private:
  std::unique_ptr<Impl> impl_;
};

}  // namespace gjkx::render
