// A figure of the paper as a grid of panels on one Canvas.
#include <gjkx/render/figure.hpp>

#include <stdexcept>
#include <string>

namespace gjkx::render {

int Figure::checked(int value, const char* field) {
  if (value <= 0) throw std::invalid_argument(std::string("Figure: ") + field + " must be positive, got " + std::to_string(value));
  return value;
}

Figure::Figure(int cols, int rows, int panelWidth, int panelHeight, const CanvasOptions& options)
    : cols_(checked(cols, "cols")),
      rows_(checked(rows, "rows")),
      panelWidth_(checked(panelWidth, "panelWidth")),
      panelHeight_(checked(panelHeight, "panelHeight")),
      canvas_(cols * panelWidth, rows * panelHeight, options) {}

PixelRect Figure::panelRect(int col, int row) const {
  if (col < 0 || col >= cols_) throw std::out_of_range("Figure: panel column " + std::to_string(col) + " outside the grid");
  if (row < 0 || row >= rows_) throw std::out_of_range("Figure: panel row " + std::to_string(row) + " outside the grid");
  return PixelRect{col * panelWidth_, row * panelHeight_, panelWidth_, panelHeight_};
}

Canvas& Figure::panel(int col, int row, double titleBand) {
  canvas_.setPanel(panelRect(col, row), style::panelPadding, titleBand);
  return canvas_;
}

}  // namespace gjkx::render
