/// @file
/// @brief Line widths, sizes and stroke presets shared by all figures of the paper.
///
/// Every size is in pixels of the final image. The presets pair the colours of palette.hpp
/// with widths and dashes, so that e.g. body P looks the same in every figure.
#pragma once

#include <gjkx/render/palette.hpp>

namespace gjkx::render {

/// A dash pattern in pixels along a stroke (round caps included); on = 0 is a solid line.
struct Dash {
  double on = 0.0;   ///< Length of a drawn dash in pixels; 0 means solid.
  double off = 0.0;  ///< Length of a gap between dashes in pixels.

  constexpr bool solid() const { return on <= 0.0 || off <= 0.0; }  ///< Whether the line is solid.
};

/// How a line of a figure is drawn (round joins and caps).
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

inline constexpr double lineThin = 1.5;  ///< Width of ordinary lines (outlines of bodies) in all figures, in pixels.
inline constexpr double lineThick = 2.5;  ///< Width of emphasised lines (the GJK simplex of Fig. 2), in pixels.
inline constexpr double lineHair = 1.0;  ///< Width of hairlines (axes, grids, construction lines), in pixels.
inline constexpr double pointRadius = 3.5;  ///< Radius of point markers (vertices, witness points), in pixels.
inline constexpr double arrowHead = 11.0;  ///< Length of arrow heads (search directions s_i), in pixels.
inline constexpr Dash dashed{7.0, 5.0};  ///< Dash pattern of separating lines and supporting planes.
inline constexpr Dash dotted{2.0, 3.5};  ///< Finer dash pattern for auxiliary constructions.

inline constexpr double titleSize = 16.0;  ///< Font size of panel titles (sans serif), in pixels.
inline constexpr double labelSize = 17.0;  ///< Font size of math labels (V_P, s_1, ...), in pixels.
inline constexpr double smallSize = 12.0;  ///< Font size of small annotations and tick labels, in pixels.
inline constexpr double labelGap = 4.0;  ///< Gap between a labelled point and its label, in pixels.

inline constexpr double panelPadding = 10.0;  ///< Blank border inside every panel of a figure, in pixels.
inline constexpr double titleBand = 26.0;  ///< Height reserved at the top of a panel for its title, in pixels.

/// Supersampling of the 3D scenes: OSMesa renders them this many times larger in x and
/// y, and each block of supersample x supersample pixels is averaged into one (16 samples
/// a pixel, the same on every processor, unlike the rasteriser's multisampling).
inline constexpr int supersample = 4;

inline constexpr double lightAmbient = 0.55;  ///< Ambient part of the flat shading of the 3D figures' meshes.
inline constexpr double lightDiffuse = 0.5;  ///< Diffuse part of the flat shading of the 3D figures' meshes.

inline constexpr Stroke bodyPStroke{palette::bodyPStroke, lineThin, {}};  ///< Outline of body P.
inline constexpr Stroke bodyQStroke{palette::bodyQStroke, lineThin, {}};  ///< Outline of body Q.
inline constexpr Stroke minkowskiStroke{palette::minkowskiStroke, lineThin, {}};  ///< Outline of the Minkowski difference V_Q - V_P.
inline constexpr Stroke simplexStroke{palette::simplex, lineThick, {}};  ///< Edges of the GJK simplex (thick black).
inline constexpr Stroke directionStroke{palette::direction, lineThin, {}};  ///< Search directions s_i (green arrows).
inline constexpr Stroke separatingStroke{palette::separating, lineThin, dashed};  ///< Separating lines and supporting planes (dashed gray).
inline constexpr Stroke penetrationStroke{palette::penetration, lineThin, {}};  ///< Penetration depth and negative distances (red).
inline constexpr Stroke highlightStroke{palette::highlight, lineThick, {}};  ///< Highlighted feature of the current step (orange, thick).
inline constexpr Stroke trajectoryStroke{palette::trajectory, lineThin, {}};  ///< Trajectories of moving bodies (purple).
inline constexpr Stroke axisStroke{palette::axis, lineHair, {}};  ///< Coordinate axes through the origin (gray hairline).
inline constexpr Stroke noStroke{palette::none, 0.0, {}};  ///< Invisible stroke: "no outline".

inline constexpr ShapeStyle bodyP{palette::bodyPFill, bodyPStroke};  ///< Body P: translucent blue fill, dark blue outline.
inline constexpr ShapeStyle bodyQ{palette::bodyQFill, bodyQStroke};  ///< Body Q: translucent red fill, dark red outline.
inline constexpr ShapeStyle minkowski{palette::minkowskiFill, minkowskiStroke};  ///< The Minkowski difference V_Q - V_P: light gray fill, dark gray outline.
inline constexpr ShapeStyle simplex{palette::simplexFill, simplexStroke};  ///< The GJK simplex: faint fill, thick black edges.

}  // namespace style
}  // namespace gjkx::render
