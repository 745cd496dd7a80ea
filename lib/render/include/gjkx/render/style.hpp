/// @file
/// @brief Line widths, sizes and stroke presets shared by all figures of the paper.
///
/// Every size is in pixels of the final image. The presets pair the colours of
/// palette.hpp with widths and dash patterns, so that e.g. body P looks the
/// same in Fig. 1, Fig. 2 and the 3D figures.
#pragma once

#include <gjkx/render/palette.hpp>

namespace gjkx::render {

/// A dash pattern in pixels along a stroke; the default (on = 0) is a solid
/// line. Separating lines and supporting planes of the figures are dashed.
struct Dash {
  double on = 0.0;   ///< Length of a drawn dash in pixels; 0 means solid.
  double off = 0.0;  ///< Length of a gap between dashes in pixels.

  /// True if the pattern draws a solid line (used by every figure's strokes).
  /// @return Whether no dashes are drawn.
  constexpr bool solid() const { return on <= 0.0 || off <= 0.0; }
};

/// How a line of a figure is drawn: colour, width in pixels and dash pattern.
/// Lines have round joins and round caps.
struct Stroke {
  Color color = palette::ink;  ///< Colour (and opacity) of the line.
  double width = 1.5;          ///< Width of the line in pixels.
  Dash dash = {};              ///< Dash pattern; solid by default.
};

/// Fill and outline of a region of a figure (body P, body Q, V_Q - V_P, ...).
struct ShapeStyle {
  Color fill = palette::none;  ///< Colour of the inside; palette::none for no fill.
  Stroke outline = {};         ///< The outline; a transparent colour for none.
};

/// The sizes and stroke presets of the paper's figures.
namespace style {

/// Width of ordinary lines (outlines of bodies) in all figures, in pixels.
inline constexpr double lineThin = 1.5;
/// Width of emphasised lines (the GJK simplex of Fig. 2), in pixels.
inline constexpr double lineThick = 2.5;
/// Width of hairlines (axes, grids, construction lines), in pixels.
inline constexpr double lineHair = 1.0;
/// Radius of point markers (vertices, witness points), in pixels.
inline constexpr double pointRadius = 3.5;
/// Width of the outline ring of point markers, in pixels.
inline constexpr double pointOutline = 1.0;
/// Length of arrow heads (search directions s_i), in pixels.
inline constexpr double arrowHead = 11.0;
/// Dash pattern of separating lines and supporting planes.
inline constexpr Dash dashed = Dash{7.0, 5.0};
/// Finer dash pattern for auxiliary constructions.
inline constexpr Dash dotted = Dash{2.0, 3.5};

/// Font size of panel titles (sans serif), in pixels.
inline constexpr double titleSize = 16.0;
/// Font size of math labels (V_P, s_1, ...), in pixels.
inline constexpr double labelSize = 17.0;
/// Font size of small annotations and tick labels, in pixels.
inline constexpr double smallSize = 12.0;
/// Gap between a labelled point and its label, in pixels.
inline constexpr double labelGap = 4.0;

/// Blank border inside every panel of a figure, in pixels.
inline constexpr double panelPadding = 10.0;
/// Height reserved at the top of a panel for its title, in pixels.
inline constexpr double titleBand = 26.0;

/// Supersampling of the 3D scenes: OSMesa renders them this many times larger in x and
/// y, and each block of supersample x supersample pixels is averaged into one (16 samples
/// a pixel, the same on every processor, unlike the rasteriser's multisampling).
inline constexpr int supersample = 4;

/// Ambient part of the flat shading of the 3D figures' meshes.
inline constexpr double lightAmbient = 0.55;
/// Diffuse part of the flat shading of the 3D figures' meshes.
inline constexpr double lightDiffuse = 0.5;

/// Outline of body P.
inline constexpr Stroke bodyPStroke = Stroke{palette::bodyPStroke, lineThin, {}};
/// Outline of body Q.
inline constexpr Stroke bodyQStroke = Stroke{palette::bodyQStroke, lineThin, {}};
/// Outline of the Minkowski difference V_Q - V_P.
inline constexpr Stroke minkowskiStroke = Stroke{palette::minkowskiStroke, lineThin, {}};
/// Edges of the GJK simplex (thick black).
inline constexpr Stroke simplexStroke = Stroke{palette::simplex, lineThick, {}};
/// Search directions s_i (green arrows).
inline constexpr Stroke directionStroke = Stroke{palette::direction, lineThin, {}};
/// Separating lines and supporting planes (dashed gray).
inline constexpr Stroke separatingStroke = Stroke{palette::separating, lineThin, dashed};
/// Penetration depth and negative distances (red).
inline constexpr Stroke penetrationStroke = Stroke{palette::penetration, lineThin, {}};
/// Highlighted feature of the current step (orange, thick).
inline constexpr Stroke highlightStroke = Stroke{palette::highlight, lineThick, {}};
/// Trajectories of moving bodies (purple).
inline constexpr Stroke trajectoryStroke = Stroke{palette::trajectory, lineThin, {}};
/// Coordinate axes through the origin (gray hairline).
inline constexpr Stroke axisStroke = Stroke{palette::axis, lineHair, {}};
/// Invisible stroke: "no outline".
inline constexpr Stroke noStroke = Stroke{palette::none, 0.0, {}};

/// Body P: translucent blue fill, dark blue outline.
inline constexpr ShapeStyle bodyP = ShapeStyle{palette::bodyPFill, bodyPStroke};
/// Body Q: translucent red fill, dark red outline.
inline constexpr ShapeStyle bodyQ = ShapeStyle{palette::bodyQFill, bodyQStroke};
/// The Minkowski difference V_Q - V_P: light gray fill, dark gray outline.
inline constexpr ShapeStyle minkowski = ShapeStyle{palette::minkowskiFill, minkowskiStroke};
/// The GJK simplex: faint fill, thick black edges.
inline constexpr ShapeStyle simplex = ShapeStyle{palette::simplexFill, simplexStroke};

}  // namespace style
}  // namespace gjkx::render
