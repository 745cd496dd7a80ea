/// @file
/// @brief The one named palette shared by all figures of the paper.
///
/// Black line drawings on white with light fills, as the paper's; every recurring object
/// (body P, body Q, V_Q - V_P, the simplex, the directions, ...) has one colour.
#pragma once

#include <gjkx/render/color.hpp>

/// The named colours of the paper's figures (all chapters use these).
namespace gjkx::render::palette {

inline constexpr Color background = Color::hex(0xFFFFFF);  ///< Background of every figure of the paper: white.
inline constexpr Color ink = Color::hex(0x1A1A1A);  ///< Default ink of lines, points and labels in the figures: near black.
inline constexpr Color none = Color{0.0, 0.0, 0.0, 0.0};  ///< Fully transparent colour: "no fill" / "no outline" in the figures.

inline constexpr Color bodyPFill = Color::hex(0x5B8DC9, 0.28);  ///< Fill of body P (object A in Figs. 1-2): translucent muted blue.
inline constexpr Color bodyPStroke = Color::hex(0x1F3D73);  ///< Outline of body P: dark blue.
inline constexpr Color bodyQFill = Color::hex(0xE07B53, 0.28);  ///< Fill of body Q (object B in Figs. 1-2): translucent muted red-orange.
inline constexpr Color bodyQStroke = Color::hex(0x8E2F1A);  ///< Outline of body Q: dark red.
inline constexpr Color minkowskiFill = Color::hex(0x9E9E9E, 0.22);  ///< Fill of the Minkowski difference V_Q - V_P (Fig. 2): light gray.
inline constexpr Color minkowskiStroke = Color::hex(0x4D4D4D);  ///< Outline of the Minkowski difference V_Q - V_P: dark gray.
inline constexpr Color bodyPSolid = Color::hex(0xA7C3E8);  ///< Opaque surface of body P in the 3D figures (light blue, shaded by the light).
inline constexpr Color bodyQSolid = Color::hex(0xF0B9A0);  ///< Opaque surface of body Q in the 3D figures (light red-orange).
inline constexpr Color minkowskiSolid = Color::hex(0xD0D0D0);  ///< Opaque surface of the Minkowski difference V_Q - V_P in the 3D figures (light gray).
inline constexpr Color simplex = Color::hex(0x000000);  ///< Edges and vertices of the GJK simplex (Fig. 2, drawn thick): black.
inline constexpr Color simplexFill = Color::hex(0x000000, 0.07);  ///< Light fill of the GJK simplex in Fig. 2.
inline constexpr Color direction = Color::hex(0x2E8540);  ///< Search directions s_i of GJK (Fig. 2 arrows): green.
inline constexpr Color witness = Color::hex(0x000000);  ///< Closest point and witness points (Figs. 2-3): black dot.
inline constexpr Color separating = Color::hex(0x808080);  ///< Separating lines and supporting planes (drawn dashed): gray.
inline constexpr Color penetration = Color::hex(0xC62828);  ///< Negative distances, penetration depth and collisions: red.
inline constexpr Color highlight = Color::hex(0xE69F00);  ///< Highlight of the current step or the feature under discussion: orange.
inline constexpr Color trajectory = Color::hex(0x7B4EA3);  ///< Trajectories and swept volumes of moving bodies (spacio-temporal figures): purple.
inline constexpr Color axis = Color::hex(0xA0A0A0);  ///< Coordinate axes through the origin: light gray.
inline constexpr Color grid = Color::hex(0xE4E4E4);  ///< Background grid lines, if a figure draws any: very light gray.

}  // namespace gjkx::render::palette
