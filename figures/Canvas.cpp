#include "Canvas.h"

#include <vtkAxis.h>
#include <vtkBrush.h>
#include <vtkChartXY.h>
#include <vtkColorLegend.h>
#include <vtkContextScene.h>
#include <vtkContextView.h>
#include <vtkDoubleArray.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPNGWriter.h>
#include <vtkPen.h>
#include <vtkPlotArea.h>
#include <vtkPlotHistogram2D.h>
#include <vtkPlotLine.h>
#include <vtkPlotPoints.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkScalarsToColors.h>
#include <vtkTable.h>
#include <vtkTextProperty.h>
#include <vtkUnsignedCharArray.h>
#include <vtkWindowToImageFilter.h>

#include <algorithm>
#include <cmath>

#include "core/Error.h"
#include "io/AtomicFile.h"

namespace wcmps::figures {
namespace {

// Margins of the layout, in pixels: room for a panel's title above its plot area, for tick
// labels and the axis title below and to the left, and for the colour bar on the right.
constexpr int kLeft = 78, kBottom = 58, kTop = 34, kRight = 18, kBarWidth = 150;

vtkSmartPointer<vtkTable> table_of(const std::vector<double>& x,
                                   const std::vector<std::vector<double>>& ys) {
  vtkNew<vtkTable> t;
  vtkNew<vtkDoubleArray> xa;
  xa->SetName("x");
  for (double v : x) xa->InsertNextValue(v);
  t->AddColumn(xa);
  for (size_t k = 0; k < ys.size(); ++k) {
    vtkNew<vtkDoubleArray> ya;
    ya->SetName(("y" + std::to_string(k)).c_str());
    for (double v : ys[k]) ya->InsertNextValue(v);
    t->AddColumn(ya);
  }
  return t;
}

/// A convex polygon as the area between its lower and upper edges, sampled at its vertices'
/// x (both edges are linear between them).
void add_polygon(vtkChartXY* chart, const Polygon& poly) {
  const size_t n = poly.x.size();
  if (n < 3) return;
  std::vector<double> xs(poly.x);
  std::sort(xs.begin(), xs.end());
  std::vector<double> lo, hi;
  for (double x : xs) {
    double ymin = INFINITY, ymax = -INFINITY;
    for (size_t i = 0; i < n; ++i) {
      const size_t j = (i + 1) % n;
      const double x0 = poly.x[i], x1 = poly.x[j];
      if (x < std::min(x0, x1) - 1e-12 || x > std::max(x0, x1) + 1e-12) continue;
      const double y = std::abs(x1 - x0) < 1e-12
                           ? std::min(poly.y[i], poly.y[j])
                           : poly.y[i] + (poly.y[j] - poly.y[i]) * (x - x0) / (x1 - x0);
      const double y2 = std::abs(x1 - x0) < 1e-12 ? std::max(poly.y[i], poly.y[j]) : y;
      ymin = std::min(ymin, y);
      ymax = std::max(ymax, y2);
    }
    lo.push_back(ymin);
    hi.push_back(ymax);
  }
  auto* area = vtkPlotArea::SafeDownCast(chart->AddPlot(vtkChart::AREA));
  area->SetInputData(table_of(xs, {lo, hi}));
  area->SetInputArray(0, "x");
  area->SetInputArray(1, "y0");
  area->SetInputArray(2, "y1");
  area->SetColor(poly.fill[0], poly.fill[1], poly.fill[2], 255);
  area->SetLegendVisibility(false);
}

void add_series(vtkChartXY* chart, const Series& s) {
  vtkPlot* plot = chart->AddPlot(s.markers ? vtkChart::POINTS : vtkChart::LINE);
  plot->SetInputData(table_of(s.x, {s.y}), 0, 1);
  plot->SetColor(s.colour[0], s.colour[1], s.colour[2], 255);
  plot->SetWidth(s.width);
  plot->SetLabel(s.label);
  plot->SetLegendVisibility(!s.label.empty());
  if (auto* points = vtkPlotPoints::SafeDownCast(plot)) {
    points->SetMarkerStyle(s.markers ? vtkPlotPoints::CIRCLE : vtkPlotPoints::NONE);
    if (s.markers) points->SetMarkerSize(7.0f);
  }
  if (auto* line = vtkPlotLine::SafeDownCast(plot)) line->SetPolyLine(!s.segments);
  if (s.dashed) plot->GetPen()->SetLineType(vtkPen::DASH_LINE);
}

void style_axis(vtkAxis* axis, const std::string& title, const std::array<double, 2>& range) {
  axis->SetTitle(title);
  axis->SetBehavior(vtkAxis::FIXED);
  axis->SetRange(range[0], range[1]);
  axis->GetTitleProperties()->SetFontSize(15);
  axis->GetTitleProperties()->BoldOff();
  axis->GetLabelProperties()->SetFontSize(13);
  axis->SetGridVisible(false);
}

}  // namespace

Rgb palette(std::size_t i) {
  // Okabe & Ito's colour-blind-safe set.
  static const Rgb kColours[] = {{0, 114, 178}, {213, 94, 0},   {0, 158, 115}, {204, 121, 167},
                                 {230, 159, 0}, {86, 180, 233}, {0, 0, 0},     {240, 228, 66}};
  return kColours[i % (sizeof kColours / sizeof kColours[0])];
}

std::array<int, 2> plot_area_size(int width, int height, int columns, int panels, bool colour_bar) {
  const int cols = std::max(1, std::min(columns, panels));
  const int rows = std::max(1, (panels + cols - 1) / cols);
  return {(width - (colour_bar ? kBarWidth : 0)) / cols - kLeft - kRight,
          height / rows - kBottom - kTop};
}

void equal_scales(std::array<double, 2>& x, std::array<double, 2>& y,
                  const std::array<int, 2>& area) {
  const double sx = (x[1] - x[0]) / area[0], sy = (y[1] - y[0]) / area[1];
  std::array<double, 2>& widen = sx > sy ? y : x;
  const double half = 0.5 * std::max(sx, sy) * (sx > sy ? area[1] : area[0]);
  const double mid = 0.5 * (widen[0] + widen[1]);
  widen = {mid - half, mid + half};
}

Layout render_png(Figure& fig, const std::filesystem::path& file) {
  vtkNew<vtkContextView> view;
  view->GetRenderWindow()->SetOffScreenRendering(1);
  view->GetRenderWindow()->SetMultiSamples(0);
  view->GetRenderWindow()->SetSize(fig.width, fig.height);
  view->GetRenderer()->SetBackground(1.0, 1.0, 1.0);

  const int bar = fig.colour_bar ? kBarWidth : 0;
  const int cols = std::max(1, std::min<int>(fig.columns, static_cast<int>(fig.panels.size())));
  const int rows = (static_cast<int>(fig.panels.size()) + cols - 1) / cols;
  const int cell_w = (fig.width - bar) / cols, cell_h = fig.height / std::max(rows, 1);
  Layout layout;
  for (size_t k = 0; k < fig.panels.size(); ++k) {
    Panel& p = fig.panels[k];
    const int col = static_cast<int>(k) % cols, row = static_cast<int>(k) / cols;
    const int x0 = col * cell_w + kLeft, y0 = fig.height - (row + 1) * cell_h + kBottom;
    const int w = cell_w - kLeft - kRight, h = cell_h - kBottom - kTop;
    if (fig.equal_scales) equal_scales(p.x_range, p.y_range, {w, h});
    vtkNew<vtkChartXY> chart;
    chart->SetLayoutStrategy(vtkChart::AXES_TO_RECT);
    chart->SetSize(vtkRectf(x0, y0, w, h));
    chart->SetTitle(p.note.empty() ? p.title : p.title + ": " + p.note);
    chart->GetTitleProperties()->SetFontSize(15);
    chart->GetTitleProperties()->BoldOff();
    style_axis(chart->GetAxis(vtkAxis::BOTTOM), p.x_title, p.x_range);
    style_axis(chart->GetAxis(vtkAxis::LEFT), p.y_title, p.y_range);
    chart->SetShowLegend(p.legend);
    if (p.legend) chart->GetLegend()->GetLabelProperties()->SetFontSize(12);
    if (p.field) {
      vtkNew<vtkPlotHistogram2D> map;
      map->SetInputData(p.field->image);
      map->SetTransferFunction(p.field->colours);
      map->SetLegendVisibility(false);
      chart->AddPlot(map);
    }
    for (const Polygon& poly : p.polygons) add_polygon(chart, poly);
    for (const Series& s : p.series) add_series(chart, s);
    // vtkChartXY paints neither its axes nor its title without a plot: an empty panel (a dry
    // section) gets an invisible one, a white point in a corner.
    const Series blank{"", {p.x_range[0]}, {p.y_range[0]}, {255, 255, 255}, 0.1f};
    if (p.series.empty() && p.polygons.empty() && !p.field) add_series(chart, blank);
    view->GetScene()->AddItem(chart);
    layout.plots.push_back({x0, y0, w, h});
  }
  if (fig.colour_bar) {
    vtkNew<vtkColorLegend> legend;
    legend->SetTransferFunction(fig.colour_bar->colours);
    legend->SetTitle(fig.colour_bar->title);
    legend->SetOrientation(vtkColorLegend::VERTICAL);
    const int bx = fig.width - bar + 16, by = kBottom, bw = 22, bh = fig.height - kBottom - kTop;
    legend->SetPosition(vtkRectf(bx, by, bw, bh));
    legend->SetDrawBorder(false);
    legend->GetLabelProperties()->SetFontSize(13);
    legend->Update();  // builds the bar's image (a chart would do it for its own legend)
    view->GetScene()->AddItem(legend);
    layout.colour_bar = std::array<int, 4>{bx, by, bw, bh};
  }

  view->GetRenderWindow()->Render();
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(view->GetRenderWindow());
  grab->SetInputBufferTypeToRGB();
  grab->ReadFrontBufferOff();
  grab->Update();
  // Encoded in memory, written atomically by us (a full disk is then an IoError, not half a
  // PNG).
  vtkNew<vtkPNGWriter> png;
  png->SetInputConnection(grab->GetOutputPort());
  png->WriteToMemoryOn();
  png->Write();
  vtkUnsignedCharArray* bytes = png->GetResult();
  if (png->GetErrorCode() != 0 || !bytes || bytes->GetNumberOfValues() == 0) {
    throw IoError(file.string() + ": cannot encode the image");
  }
  write_file_atomically(file,
                        std::string_view(reinterpret_cast<const char*>(bytes->GetPointer(0)),
                                         static_cast<std::size_t>(bytes->GetNumberOfValues())));
  return layout;
}

}  // namespace wcmps::figures
