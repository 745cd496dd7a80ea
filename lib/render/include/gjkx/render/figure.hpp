/// @file
/// @brief A figure of the paper as a grid of equally sized panels on one Canvas.
#pragma once

#include <gjkx/render/canvas.hpp>

#include <string>

namespace gjkx::render {

/// A figure made of cols x rows panels of panelWidth x panelHeight pixels
/// (e.g. the iterations of GJK side by side in Fig. 2). Select a panel with
/// panel(), then draw on the returned Canvas in that panel's coordinates.
///
/// @code
/// gjkx::render::Figure fig(3, 1, 320, 300);
/// auto& c = fig.panel(0, 0);
/// c.setWorldWindow(-3, 3, -3, 3);
/// c.title("(a) V_P and V_Q");
/// // ... draw ...
/// fig.savePng(outDir + "/fig2.png");
/// @endcode
class Figure {
 public:
  /// A blank figure. Throws std::invalid_argument naming "cols", "rows",
  /// "panelWidth" or "panelHeight" if one is not positive.
  /// @param cols Number of panel columns.
  /// @param rows Number of panel rows.
  /// @param panelWidth Width of each panel in pixels.
  /// @param panelHeight Height of each panel in pixels.
  /// @param options Anti-aliasing settings and background of the canvas.
  Figure(int cols, int rows, int panelWidth, int panelHeight, const CanvasOptions& options = {});

  /// Makes panel (@p col, @p row) current (column 0 is left, row 0 the top)
  /// and returns the canvas to draw on. Throws std::out_of_range for a panel
  /// outside the grid.
  /// @param col Column of the panel.
  /// @param row Row of the panel.
  /// @param titleBand Height reserved for the panel title (0 for none).
  /// @return The figure's canvas, set to the panel.
  Canvas& panel(int col, int row, double titleBand = style::titleBand);

  /// The canvas of the whole figure (e.g. for a label spanning panels).
  /// @return The canvas.
  Canvas& canvas() { return canvas_; }
  /// Number of panel columns.
  /// @return The column count.
  int cols() const { return cols_; }
  /// Number of panel rows.
  /// @return The row count.
  int rows() const { return rows_; }
  /// The pixel rectangle of panel (@p col, @p row).
  /// @param col Column of the panel.
  /// @param row Row of the panel.
  /// @return The panel in canvas pixels.
  PixelRect panelRect(int col, int row) const;

  /// The finished figure (see Canvas::image()).
  /// @return The rendered figure.
  Image image() { return canvas_.image(); }
  /// Writes the figure as a deterministic PNG file (see Canvas::savePng()).
  /// @param path The PNG file to create.
  void savePng(const std::string& path) { canvas_.savePng(path); }

 private:
  static int checked(int value, const char* field);
  int cols_, rows_, panelWidth_, panelHeight_;
  Canvas canvas_;
};

}  // namespace gjkx::render
