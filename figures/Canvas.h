#pragma once
/// @file Canvas.h
/// @brief A figure of panels drawn with VTK's chart classes (vtkChartXY, vtkPlotLine,
/// vtkPlotArea, vtkPlotHistogram2D, vtkColorLegend) and written off-screen as PNG.
///
/// The layout is fixed in pixels, not left to the charts: each panel's plot area (its axes'
/// rectangle) is placed on a grid, so that panels compare, a map panel can have equal scales
/// on x and y (one metre is as long across as up), and tests know where the block and the
/// colour bar are (the layout is reported in figures.json).

#include <array>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <vtkSmartPointer.h>

class vtkImageData;
class vtkScalarsToColors;

namespace wcmps::figures {

using Rgb = std::array<unsigned char, 3>;

/// A curve or set of points; NaN in y breaks a line (a dry stretch, a missing sample).
struct Series {
  std::string label;  ///< in the legend; empty: not listed
  std::vector<double> x, y;
  Rgb colour{0, 0, 0};
  float width = 2.0f;
  bool dashed = false;
  bool markers = false;   ///< points only (measured data)
  bool segments = false;  ///< pairs of points as separate segments (vectors)
};

/// A filled polygon (the block), drawn as the area between its lower and upper edges.
struct Polygon {
  std::vector<double> x, y;
  Rgb fill{0, 0, 0};
};

/// A 2D field on a regular grid, coloured by a transfer function.
struct Field {
  vtkSmartPointer<vtkImageData> image;  ///< one double component
  vtkSmartPointer<vtkScalarsToColors> colours;
};

struct Panel {
  std::string title, x_title, y_title;
  std::array<double, 2> x_range{0, 1}, y_range{0, 1};
  std::optional<Field> field;
  std::vector<Polygon> polygons;
  std::vector<Series> series;
  bool legend = false;
  std::string note;  ///< appended to the title (e.g. "no water at this section")
};

struct ColourBar {
  vtkSmartPointer<vtkScalarsToColors> colours;
  std::string title;
};

/// Pixel rectangles (x, y from the bottom left, width, height) of what was drawn.
struct Layout {
  std::vector<std::array<int, 4>> plots;  ///< each panel's plot area
  std::optional<std::array<int, 4>> colour_bar;
};

struct Figure {
  int width = 1200, height = 800;
  int columns = 2;
  std::vector<Panel> panels;
  std::optional<ColourBar> colour_bar;  ///< one bar for every panel, on the right
  /// Plot areas with the same metres per pixel on x and y: each panel's ranges are widened
  /// to its plot area's shape.
  bool equal_scales = false;
};

/// The size in pixels (width, height) of each panel's plot area in a figure of that size,
/// columns and number of panels, with or without a colour bar.
std::array<int, 2> plot_area_size(int width, int height, int columns, int panels, bool colour_bar);

/// Widens the shorter of two ranges about its middle so that a unit spans as many pixels
/// along x as along y in a plot area of `area` pixels (width, height).
void equal_scales(std::array<double, 2>& x, std::array<double, 2>& y,
                  const std::array<int, 2>& area);

/// Renders the figure off-screen and writes it as PNG (temporary name, then rename).
/// Throws IoError if the file cannot be written.
Layout render_png(Figure& figure, const std::filesystem::path& file);

/// A palette of distinguishable colours for curves (one per time or run).
Rgb palette(std::size_t i);

}  // namespace wcmps::figures
