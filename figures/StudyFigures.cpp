#include "StudyFigures.h"

#include <vtkDataArray.h>
#include <vtkDiscretizableColorTransferFunction.h>
#include <vtkFieldData.h>
#include <vtkImageData.h>
#include <vtkMPSFreeSurface.h>
#include <vtkMPSParticlesToGrid.h>
#include <vtkMPSPolylineProbe.h>
#include <vtkMPSSectionAverages.h>
#include <vtkMPSSections.h>
#include <vtkMPSSpeedVorticity.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkSMPTools.h>
#include <vtkTable.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>

#include "Canvas.h"
#include "OffscreenDisplay.h"
#include "core/Error.h"
#include "core/ExitCodes.h"
#include "core/TerminalProgress.h"
#include "io/AtomicFile.h"
#include "io/FrameReader.h"
#include "io/RunDirectory.h"
#include "io/RunLock.h"
#include "io/SeriesIndex.h"
#include "scene/CaseParser.h"

namespace fs = std::filesystem;

namespace wcmps {
namespace {

using figures::Figure;
using figures::Panel;
using figures::Polygon;
using figures::Rgb;
using figures::Series;

const Rgb kBlock{110, 72, 40}, kBed{0, 0, 0}, kWater{0, 90, 181}, kAlong{0, 114, 178},
    kNormal{213, 94, 0};

std::string fmt(const char* f, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, f, v);
  return buf;
}

/// One section's profile at one time (empty when it meets no water).
struct Profile {
  std::string name;
  double depth = 0.0;  ///< H (m)
  std::vector<double> y_over_h, u_along, u_normal, pressure;
};

/// Everything the figures take from one frame.
struct FrameData {
  double time = 0.0;
  std::vector<double> block_x, block_y;  ///< C, A, G
  std::vector<double> surface_x, surface_eta;
  std::vector<Profile> sections;
  std::vector<double> x_over_l, mean_along, mean_normal;
  std::vector<double> top_fraction, top_pressure;  ///< along C -> A
  vtkSmartPointer<vtkImageData> grid;              ///< speed, vorticity, velocity, mask
};

/// A measured velocity sample ([figures] measured_profiles).
struct MeasuredSample {
  double time, y_over_h, u_along, u_normal;
  std::string section;
};

/// A run and the frames of its figure times.
struct RunData {
  fs::path dir;
  CaseSpec spec;
  std::vector<FrameData> frames;
  std::array<double, 4> window{};  ///< x0, x1, y0, y1 of the map panels (m)
  std::string tag;                 ///< in file names: the case name, with DL if not unique
  std::vector<std::array<double, 3>> measured_surface;  ///< time, x, eta
  std::vector<MeasuredSample> measured_profiles;
};

/// A CSV file of measured data: a header row naming the columns, then numbers (the section
/// column excepted). Returns the wanted columns of every row, as text; throws IoError naming
/// the file and the missing column or the bad line.
std::vector<std::vector<std::string>> read_measured(const std::string& file,
                                                    const std::vector<std::string>& wanted) {
  std::ifstream in(file);
  if (!in) throw IoError(file + ": cannot open the measured data file");
  std::string line;
  const auto split = [](const std::string& l) {
    std::vector<std::string> cells;
    std::stringstream ss(l);
    std::string cell;
    while (std::getline(ss, cell, ',')) {
      while (!cell.empty() && (cell.back() == '\r' || cell.back() == ' ')) cell.pop_back();
      while (!cell.empty() && cell.front() == ' ') cell.erase(cell.begin());
      cells.push_back(cell);
    }
    return cells;
  };
  if (!std::getline(in, line)) throw IoError(file + ": empty, expected a header row");
  const auto header = split(line);
  std::vector<size_t> index;
  for (const auto& w : wanted) {
    const auto it = std::find(header.begin(), header.end(), w);
    if (it == header.end()) {
      std::string have;
      for (const auto& h : header) have += (have.empty() ? "" : ", ") + h;
      throw IoError(file + ": no column \"" + w + "\" (it has: " + have + ")");
    }
    index.push_back(static_cast<size_t>(it - header.begin()));
  }
  std::vector<std::vector<std::string>> rows;
  int number = 1;
  while (std::getline(in, line)) {
    ++number;
    if (line.find_first_not_of(" \r") == std::string::npos) continue;
    const auto cells = split(line);
    std::vector<std::string> row;
    for (size_t k = 0; k < index.size(); ++k) {
      if (index[k] >= cells.size()) {
        throw IoError(file + ":" + std::to_string(number) + ": no value in column \"" + wanted[k] +
                      "\"");
      }
      row.push_back(cells[index[k]]);
    }
    rows.push_back(row);
  }
  return rows;
}

double measured_number(const std::string& file, const std::string& cell, const std::string& col) {
  char* end = nullptr;
  const double v = std::strtod(cell.c_str(), &end);
  if (cell.empty() || *end != '\0' || !std::isfinite(v)) {
    throw IoError(file + ": \"" + cell + "\" in column \"" + col + "\" is not a number");
  }
  return v;
}

void load_measured(const FiguresSpec& f, RunData& r) {
  if (!f.measured_surface.empty()) {
    const std::vector<std::string> cols = {"time [s]", "x [m]", "eta [m]"};
    for (const auto& row : read_measured(f.measured_surface, cols)) {
      std::array<double, 3> v{};
      for (size_t k = 0; k < 3; ++k) v[k] = measured_number(f.measured_surface, row[k], cols[k]);
      r.measured_surface.push_back(v);
    }
  }
  if (!f.measured_profiles.empty()) {
    const std::vector<std::string> cols = {"time [s]", "section", "Y [-]", "u_along [m/s]",
                                           "u_normal [m/s]"};
    for (const auto& row : read_measured(f.measured_profiles, cols)) {
      MeasuredSample m{};
      m.time = measured_number(f.measured_profiles, row[0], cols[0]);
      m.section = row[1];
      m.y_over_h = measured_number(f.measured_profiles, row[2], cols[2]);
      m.u_along = measured_number(f.measured_profiles, row[3], cols[3]);
      m.u_normal = measured_number(f.measured_profiles, row[4], cols[4]);
      r.measured_profiles.push_back(m);
    }
  }
}

/// Measured data belongs to a figure time within the frames' matching tolerance.
bool same_time(double a, double b) {
  return std::abs(a - b) <= 1e-4;
}

std::vector<double> column(vtkTable* t, const char* name) {
  std::vector<double> out;
  vtkAbstractArray* a = t->GetColumnByName(name);
  for (vtkIdType r = 0; a && r < t->GetNumberOfRows(); ++r) {
    out.push_back(t->GetValueByName(r, name).ToDouble());
  }
  return out;
}

std::vector<double> point_values(vtkPolyData* p, const char* name, int comp = 0) {
  std::vector<double> out;
  vtkDataArray* a = p->GetPointData()->GetArray(name);
  for (vtkIdType i = 0; a && i < a->GetNumberOfTuples(); ++i)
    out.push_back(a->GetComponent(i, comp));
  return out;
}

/// The map window: around the block at every figure time, up to above the still water.
std::array<double, 4> map_window(const std::vector<FrameData>& frames) {
  double x0 = INFINITY, x1 = -INFINITY, y0 = INFINITY;
  for (const auto& f : frames) {
    for (size_t k = 0; k < f.block_x.size(); ++k) {
      x0 = std::min(x0, f.block_x[k]);
      x1 = std::max(x1, f.block_x[k]);
      y0 = std::min(y0, f.block_y[k]);
    }
  }
  // Room for the flow over and ahead of the block (the study's Fig. 4-10 spans about 3 L
  // downslope of it), and for the surface above.
  const double l = x1 - x0;
  return {x0 - 0.5 * l, x1 + 1.5 * l, y0 - 0.3 * l, 0.03};
}

/// x rounded up to two significant digits (a colour bar's end).
double nice_ceiling(double x) {
  const double p = std::pow(10.0, std::floor(std::log10(x)) - 1.0);
  return std::ceil(x / p - 1e-9) * p;
}

/// The frame's time and block (its BlockOutline, corners C, A, G).
FrameData block_of(vtkPolyData* frame, const fs::path& file, double time) {
  FrameData d;
  d.time = time;
  vtkDataArray* outline = frame->GetFieldData()->GetArray("BlockOutline");
  if (!outline || outline->GetNumberOfTuples() < 3) {
    throw IoError(file.string() + ": no BlockOutline: figures need a case with a [block]");
  }
  for (vtkIdType k = 0; k < 3; ++k) {
    d.block_x.push_back(outline->GetComponent(k, 0));
    d.block_y.push_back(outline->GetComponent(k, 1));
  }
  return d;
}

/// Everything else the figures take from the frame, the grid over `window`.
void add_products(FrameData& d, vtkPolyData* frame, const CaseSpec& spec,
                  const std::array<double, 4>& window) {
  vtkNew<vtkMPSFreeSurface> surface;
  surface->SetInputData(frame);
  surface->Update();
  d.surface_x = point_values(surface->GetOutput(), "x");
  d.surface_eta = point_values(surface->GetOutput(), "eta");

  vtkNew<vtkMPSSections> sections;
  sections->SetNumberOfSamples(spec.post.section_samples);
  sections->SetInputData(frame);
  sections->Update();
  vtkPolyData* prof = sections->GetOutput();
  vtkTable* summary = sections->GetSummary();
  const auto index = point_values(prof, "section");
  const auto y = point_values(prof, "Y"), ua = point_values(prof, "u_along"),
             un = point_values(prof, "u_normal"), p = point_values(prof, "pressure");
  for (vtkIdType r = 0; r < summary->GetNumberOfRows(); ++r) {
    Profile pr;
    pr.name = summary->GetValueByName(r, "section").ToString();
    pr.depth = summary->GetValueByName(r, "H").ToDouble();
    for (size_t i = 0; i < index.size(); ++i) {
      if (static_cast<vtkIdType>(index[i]) != r) continue;
      pr.y_over_h.push_back(y[i]);
      pr.u_along.push_back(ua[i]);
      pr.u_normal.push_back(un[i]);
      pr.pressure.push_back(p[i]);
    }
    d.sections.push_back(pr);
  }

  vtkNew<vtkMPSSectionAverages> averages;
  averages->SetMaximumXOverL(spec.post.average_max_x_over_l);
  averages->SetNumberOfStations(spec.post.average_stations);
  averages->SetInputData(frame);
  averages->Update();
  d.x_over_l = column(averages->GetOutput(), "X_over_L");
  d.mean_along = column(averages->GetOutput(), "mean_u_along");
  d.mean_normal = column(averages->GetOutput(), "mean_u_normal");

  vtkNew<vtkMPSPolylineProbe> top;
  top->SetInputData(frame);
  top->Update();
  d.top_fraction = point_values(top->GetOutput(), "arc_fraction");
  d.top_pressure = point_values(top->GetOutput(), "pressure");

  vtkNew<vtkMPSSpeedVorticity> sv;
  sv->SetInputData(frame);
  if (spec.post.corrected_gradient) sv->SetGradientToCorrected();
  vtkNew<vtkMPSParticlesToGrid> grid;
  grid->SetInputConnection(sv->GetOutputPort());
  const double h = spec.post.grid_spacing > 0.0 ? spec.post.grid_spacing : spec.dl;
  grid->SetSpacing(h);
  const double* w = window.data();
  grid->SetSamplingBounds(w[0], w[1], w[2], w[3], 0.0, 0.0);
  for (const char* name : {"speed", "vorticity", "velocity"}) grid->AddArrayName(name);
  grid->Update();
  d.grid = grid->GetOutput();
}

/// A single-component image of one array of the grid, for vtkPlotHistogram2D.
vtkSmartPointer<vtkImageData> scalar_image(vtkImageData* grid, const char* name) {
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->CopyStructure(grid);
  image->GetPointData()->SetScalars(grid->GetPointData()->GetArray(name));
  return image;
}

/// The q-quantile of |values| over the valid points of every frame's grid.
double quantile_abs(const std::vector<FrameData>& frames, const char* name, double q) {
  std::vector<double> v;
  for (const auto& f : frames) {
    vtkDataArray* a = f.grid->GetPointData()->GetArray(name);
    for (vtkIdType i = 0; a && i < a->GetNumberOfTuples(); ++i) {
      const double x = a->GetComponent(i, 0);
      if (std::isfinite(x)) v.push_back(std::abs(x));
    }
  }
  if (v.empty()) return 1.0;
  const size_t k = std::min(v.size() - 1, static_cast<size_t>(q * (v.size() - 1)));
  std::nth_element(v.begin(), v.begin() + static_cast<long>(k), v.end());
  return std::max(v[k], 1e-9);
}

/// The bed of a [tank] across the x range: the slope y = -x tan(slope) down to the bottom.
Series bed_line(const CaseSpec& spec, double x0, double x1) {
  Series s;
  s.colour = kBed;
  s.width = 2.5f;
  if (!spec.tank) return s;
  const double t = std::tan(spec.tank->slope_deg * M_PI / 180.0);
  const double toe = spec.tank->depth / t;
  s.x = {x0, std::max(x0, std::min(toe, x1)), x1};
  for (double x : s.x) s.y.push_back(-std::min(x * t, spec.tank->depth));
  return s;
}

Polygon block_polygon(const FrameData& f) {
  return {f.block_x, f.block_y, kBlock};
}

std::string time_title(const RunData& r, double t) {
  return r.spec.name + ", t = " + fmt("%.2f", t) + " s";
}

// ---------------------------------------------------------------------------------------
// The figures. Each returns the figure and a sentence on what it shows.

Figure surface_figure(const RunData& r, int w, int h) {
  Figure fig{w, h, 2, {}, std::nullopt, false};
  // From the block to a metre beyond; from under the block's lowest corner to the crest.
  const double x0 = r.window[0], x1 = r.window[0] + 1.0;
  double lo = 0.0, hi = 0.01;
  for (const auto& f : r.frames) {
    for (double y : f.block_y) lo = std::min(lo, y - 0.03);
  }
  for (const auto& f : r.frames) {
    for (size_t i = 0; i < f.surface_x.size(); ++i) {
      if (f.surface_x[i] >= x0 && f.surface_x[i] <= x1) hi = std::max(hi, f.surface_eta[i]);
    }
  }
  for (const auto& f : r.frames) {
    Panel p;
    p.title = time_title(r, f.time);
    p.x_title = "x [m]";
    p.y_title = "y [m]";
    p.x_range = {x0, x1};
    p.y_range = {lo, hi + 0.01};
    p.polygons.push_back(block_polygon(f));
    p.series.push_back(bed_line(r.spec, x0, x1));
    p.series.push_back({"computed", f.surface_x, f.surface_eta, kWater, 2.0f});
    Series measured{"measured", {}, {}, {0, 0, 0}, 1.0f};
    measured.markers = true;
    for (const auto& m : r.measured_surface) {
      if (same_time(m[0], f.time)) measured.x.push_back(m[1]), measured.y.push_back(m[2]);
    }
    if (!measured.x.empty()) {
      p.series.push_back(measured);
      p.legend = true;
    }
    fig.panels.push_back(p);
  }
  return fig;
}

Figure profile_figure(const RunData& r, size_t section, int w, int h) {
  Figure fig{w, h, 2, {}, std::nullopt, false};
  double lo = 0.0, hi = 0.0;
  for (const auto& f : r.frames) {
    for (const auto* u : {&f.sections[section].u_along, &f.sections[section].u_normal}) {
      for (double v : *u) {
        if (std::isfinite(v)) lo = std::min(lo, v), hi = std::max(hi, v);
      }
    }
  }
  for (const auto& m : r.measured_profiles) {
    if (m.section != r.spec.sections[section].name) continue;
    lo = std::min({lo, m.u_along, m.u_normal});
    hi = std::max({hi, m.u_along, m.u_normal});
  }
  if (hi - lo < 1e-6) lo = -0.1, hi = 0.1;  // dry at every time: a plain velocity axis
  const double pad = 0.1 * (hi - lo);
  for (const auto& f : r.frames) {
    const Profile& pr = f.sections[section];
    Panel p;
    p.title = r.spec.name + ", section " + pr.name + ", t = " + fmt("%.2f", f.time) + " s";
    p.x_title = "velocity [m/s]";
    p.y_title = "Y = h/H [-]";
    p.x_range = {lo - pad, hi + pad};
    p.y_range = {0.0, 1.0};
    if (pr.y_over_h.empty()) {
      p.note = "no water";
    } else {
      p.series.push_back({"along the bed", pr.u_along, pr.y_over_h, kAlong, 2.0f});
      p.series.push_back({"normal to the bed", pr.u_normal, pr.y_over_h, kNormal, 2.0f});
      p.legend = true;
    }
    Series along{"measured, along", {}, {}, kAlong, 1.0f},
        normal{"measured, normal", {}, {}, kNormal, 1.0f};
    along.markers = normal.markers = true;
    for (const auto& m : r.measured_profiles) {
      if (m.section != pr.name || !same_time(m.time, f.time)) continue;
      along.x.push_back(m.u_along);
      along.y.push_back(m.y_over_h);
      normal.x.push_back(m.u_normal);
      normal.y.push_back(m.y_over_h);
    }
    if (!along.x.empty()) {
      p.series.push_back(along);
      p.series.push_back(normal);
      p.legend = true;
    }
    fig.panels.push_back(p);
  }
  return fig;
}

Figure averages_figure(const RunData& r, int w, int h) {
  Figure fig{w, h, 2, {}, std::nullopt, false};
  double lo = 0.0, hi = 0.0;
  for (const auto& f : r.frames) {
    for (const auto* u : {&f.mean_along, &f.mean_normal}) {
      for (double v : *u) {
        if (std::isfinite(v)) lo = std::min(lo, v), hi = std::max(hi, v);
      }
    }
  }
  const double pad = 0.1 * std::max(hi - lo, 0.01);
  const char* names[] = {"along the bed", "normal to the bed"};
  for (int c = 0; c < 2; ++c) {
    Panel p;
    p.title = r.spec.name + ": depth-averaged velocity " + names[c];
    p.x_title = "X/L [-]";
    p.y_title = "mean velocity [m/s]";
    p.x_range = {0.0, r.spec.post.average_max_x_over_l};
    p.y_range = {lo - pad, hi + pad};
    for (size_t k = 0; k < r.frames.size(); ++k) {
      const auto& f = r.frames[k];
      p.series.push_back({"t = " + fmt("%.2f", f.time) + " s", f.x_over_l,
                          c == 0 ? f.mean_along : f.mean_normal, figures::palette(k), 2.0f});
    }
    p.legend = true;
    fig.panels.push_back(p);
  }
  return fig;
}

vtkSmartPointer<vtkDiscretizableColorTransferFunction> speed_colours(double top) {
  // Viridis at five stops; NaN (no water) white.
  auto lut = vtkSmartPointer<vtkDiscretizableColorTransferFunction>::New();
  const double stops[5][3] = {{0.267, 0.005, 0.329},
                              {0.230, 0.322, 0.546},
                              {0.128, 0.567, 0.551},
                              {0.369, 0.789, 0.383},
                              {0.993, 0.906, 0.144}};
  for (int k = 0; k < 5; ++k)
    lut->AddRGBPoint(top * k / 4.0, stops[k][0], stops[k][1], stops[k][2]);
  lut->SetNanColor(1.0, 1.0, 1.0);
  // Filled contours, as the study draws U: 14 bands of equal width.
  lut->DiscretizeOn();
  lut->SetNumberOfValues(14);
  lut->Build();
  return lut;
}

vtkSmartPointer<vtkDiscretizableColorTransferFunction> vorticity_colours(double top) {
  // Moreland's cool-warm diverging map, light grey at zero; NaN (no water) light grey.
  auto lut = vtkSmartPointer<vtkDiscretizableColorTransferFunction>::New();
  lut->SetColorSpaceToDiverging();
  lut->AddRGBPoint(-top, 0.230, 0.299, 0.754);
  lut->AddRGBPoint(0.0, 0.865, 0.865, 0.865);
  lut->AddRGBPoint(top, 0.706, 0.016, 0.150);
  lut->SetNanColor(1.0, 1.0, 1.0);
  // Filled contours in 16 bands, an even number so that zero is a band edge.
  lut->DiscretizeOn();
  lut->SetNumberOfValues(16);
  lut->Build();
  return lut;
}

Panel map_panel(const RunData& r, const FrameData& f) {
  Panel p;
  p.title = time_title(r, f.time);
  p.x_title = "x [m]";
  p.y_title = "y [m]";
  p.x_range = {r.window[0], r.window[1]};
  p.y_range = {r.window[2], r.window[3]};
  p.polygons.push_back(block_polygon(f));
  p.series.push_back(bed_line(r.spec, r.window[0] - 1.0, r.window[1] + 1.0));
  return p;
}

Figure speed_figure(const RunData& r, int w, int h) {
  Figure fig{w, h, 2, {}, std::nullopt, true};
  // The colour range: up to the 99.5th percentile of U over all panels, so that one splash
  // particle does not wash the map out; the same for every panel, so they compare.
  auto lut = speed_colours(nice_ceiling(quantile_abs(r.frames, "speed", 0.995)));
  for (const auto& f : r.frames) {
    Panel p = map_panel(r, f);
    p.field = figures::Field{scalar_image(f.grid, "speed"), lut};
    fig.panels.push_back(p);
  }
  fig.colour_bar = figures::ColourBar{lut, "U [m/s]"};
  return fig;
}

Figure vorticity_figure(const RunData& r, int w, int h) {
  Figure fig{w, h, 2, {}, std::nullopt, true};
  // Symmetric about zero, to the 98th percentile of |omega|: the wall layers' extremes would
  // otherwise leave the flow white.
  const double top = nice_ceiling(quantile_abs(r.frames, "vorticity", 0.98));
  auto lut = vorticity_colours(top);
  const double umax = quantile_abs(r.frames, "speed", 0.995);
  for (const auto& f : r.frames) {
    Panel p = map_panel(r, f);
    p.field = figures::Field{scalar_image(f.grid, "vorticity"), lut};
    // Vectors on a coarser lattice: about 24 across the window; the longest (the 99.5th
    // percentile of U) as long as 0.9 of their spacing.
    int dims[3];
    f.grid->GetDimensions(dims);
    double spacing[3], origin[3];
    f.grid->GetSpacing(spacing);
    f.grid->GetOrigin(origin);
    const int stride =
        std::max(1, static_cast<int>(std::lround((r.window[1] - r.window[0]) / 24.0 / spacing[0])));
    const double scale = 0.9 * stride * spacing[0] / umax;
    vtkDataArray* vel = f.grid->GetPointData()->GetArray("velocity");
    Series arrows;
    arrows.colour = {0, 0, 0};
    arrows.width = 1.0f;
    arrows.segments = true;
    for (int j = stride / 2; j < dims[1]; j += stride) {
      for (int i = stride / 2; i < dims[0]; i += stride) {
        const vtkIdType id = i + static_cast<vtkIdType>(j) * dims[0];
        const double u = vel->GetComponent(id, 0), v = vel->GetComponent(id, 1);
        if (!std::isfinite(u) || !std::isfinite(v) || std::hypot(u, v) * scale < 0.1 * spacing[0])
          continue;
        const double x = origin[0] + i * spacing[0], y = origin[1] + j * spacing[1];
        const double tx = x + u * scale, ty = y + v * scale;
        // Shaft, then the two strokes of the head (a third of the length, 25 degrees off).
        const double hx = -0.33 * u * scale, hy = -0.33 * v * scale;
        const double c = std::cos(0.436), s = std::sin(0.436);
        const double seg[3][4] = {{x, y, tx, ty},
                                  {tx, ty, tx + c * hx - s * hy, ty + s * hx + c * hy},
                                  {tx, ty, tx + c * hx + s * hy, ty - s * hx + c * hy}};
        for (const auto& sg : seg) {
          arrows.x.insert(arrows.x.end(), {sg[0], sg[2]});
          arrows.y.insert(arrows.y.end(), {sg[1], sg[3]});
        }
      }
    }
    p.series.push_back(arrows);
    fig.panels.push_back(p);
  }
  fig.colour_bar = figures::ColourBar{lut, "vorticity [1/s]"};
  return fig;
}

Figure pressure_figure(const RunData& r, int w, int h) {
  Figure fig{w, h, 2, {}, std::nullopt, false};
  for (const char* name : {"A", "C", "G"}) {
    size_t s = 0;
    while (s < r.spec.sections.size() && r.spec.sections[s].name != name) ++s;
    if (s == r.spec.sections.size()) continue;
    Panel p;
    p.title = r.spec.name + ": pressure along section " + name;
    p.x_title = "pressure [Pa]";
    p.y_title = "Y = h/H [-]";
    double hi = 1.0;
    for (const auto& f : r.frames) {
      for (double v : f.sections[s].pressure)
        if (std::isfinite(v)) hi = std::max(hi, v);
    }
    p.x_range = {0.0, 1.1 * hi};
    p.y_range = {0.0, 1.0};
    for (size_t k = 0; k < r.frames.size(); ++k) {
      const Profile& pr = r.frames[k].sections[s];
      if (pr.y_over_h.empty()) continue;  // dry at that time
      p.series.push_back({"t = " + fmt("%.2f", r.frames[k].time) + " s", pr.pressure, pr.y_over_h,
                          figures::palette(k), 2.0f});
    }
    p.legend = true;
    fig.panels.push_back(p);
  }
  Panel top;
  top.title = r.spec.name + ": pressure along the block's top, C to A";
  top.x_title = "distance from C / CA [-]";
  top.y_title = "pressure [Pa]";
  double lo = 0.0, hi = 1.0;
  for (const auto& f : r.frames) {
    for (double v : f.top_pressure) {
      if (std::isfinite(v)) lo = std::min(lo, v), hi = std::max(hi, v);
    }
  }
  top.x_range = {0.0, 1.0};
  top.y_range = {lo - 0.1 * (hi - lo), hi + 0.1 * (hi - lo)};
  for (size_t k = 0; k < r.frames.size(); ++k) {
    top.series.push_back({"t = " + fmt("%.2f", r.frames[k].time) + " s", r.frames[k].top_fraction,
                          r.frames[k].top_pressure, figures::palette(k), 2.0f});
  }
  top.legend = true;
  fig.panels.push_back(top);
  return fig;
}

/// One section at one time in two runs of the same case at different DL (Fig. A-5).
Figure resolution_figure(const RunData& a, const RunData& b, size_t section, size_t frame, int w,
                         int h) {
  Figure fig{w, h, 1, {}, std::nullopt, false};
  Panel p;
  const Profile& pa = a.frames[frame].sections[section];
  const Profile& pb = b.frames[frame].sections[section];
  p.title = a.spec.name + ", section " + pa.name + ", t = " + fmt("%.2f", a.frames[frame].time) +
            " s: DL " + fmt("%g", a.spec.dl * 1000) + " mm and " + fmt("%g", b.spec.dl * 1000) +
            " mm";
  p.x_title = "velocity [m/s]";
  p.y_title = "Y = h/H [-]";
  double lo = 0.0, hi = 0.0;
  for (const Profile* pr : {&pa, &pb}) {
    for (const auto* u : {&pr->u_along, &pr->u_normal}) {
      for (double v : *u) {
        if (std::isfinite(v)) lo = std::min(lo, v), hi = std::max(hi, v);
      }
    }
  }
  const double pad = 0.1 * std::max(hi - lo, 0.01);
  p.x_range = {lo - pad, hi + pad};
  p.y_range = {0.0, 1.0};
  int k = 0;
  for (const auto* run : {&a, &b}) {
    const Profile& pr = run->frames[frame].sections[section];
    const std::string dl = "DL " + fmt("%g", run->spec.dl * 1000) + " mm";
    const Rgb c = figures::palette(static_cast<size_t>(k++));
    p.series.push_back({dl + ", along the bed", pr.u_along, pr.y_over_h, c, 2.0f});
    Series normal{dl + ", normal to the bed", pr.u_normal, pr.y_over_h, c, 2.0f};
    normal.dashed = true;
    p.series.push_back(normal);
  }
  p.legend = true;
  if (pa.y_over_h.empty() && pb.y_over_h.empty()) p.note = "no water";
  fig.panels.push_back(p);
  return fig;
}

nlohmann::json layout_json(const Figure& fig, const figures::Layout& layout) {
  nlohmann::json panels = nlohmann::json::array();
  for (size_t k = 0; k < fig.panels.size(); ++k) {
    const Panel& p = fig.panels[k];
    nlohmann::json j = {{"title", p.title},
                        {"plot_area_px", layout.plots[k]},
                        {"x_range", p.x_range},
                        {"y_range", p.y_range}};
    if (!p.polygons.empty()) {
      j["block"] = {{"x", p.polygons[0].x}, {"y", p.polygons[0].y}};
    }
    panels.push_back(j);
  }
  nlohmann::json out = {{"width", fig.width}, {"height", fig.height}, {"panels", panels}};
  if (layout.colour_bar) {
    const double* r = fig.colour_bar->colours->GetRange();
    out["colour_bar"] = {
        {"area_px", *layout.colour_bar}, {"title", fig.colour_bar->title}, {"range", {r[0], r[1]}}};
  }
  return out;
}

}  // namespace

int figures_command(const FiguresOptions& o) {
  if (o.runs.empty()) {
    std::cerr << "wcmps: error: figures: no run directory given\n";
    return exit_code::kUsage;
  }
  if (o.width < 200 || o.height < 150 || o.width > 8000 || o.height > 8000) {
    std::cerr << "wcmps: error: figures: --size must be between 200x150 and 8000x8000 pixels\n";
    return exit_code::kUsage;
  }
  const auto start = std::chrono::steady_clock::now();
  std::vector<RunData> runs;
  std::vector<std::vector<const SeriesEntry*>> picked;
  std::vector<std::vector<SeriesEntry>> series;
  for (const auto& dir : o.runs) {
    const fs::path run(dir);
    if (const std::string problem = run_directory_problem(run); !problem.empty()) {
      std::cerr << "wcmps: error: " << problem << '\n';
      return exit_code::kUsage;
    }
    const fs::path pvd = run / RunFiles::kSeries, case_copy = run / RunFiles::kCase;
    RunData r;
    r.dir = run;
    try {
      r.spec = parse_case_file(case_copy.string());
      series.push_back(read_series(pvd));
      // Measured data named by the run's copy of the case (its paths resolved against the
      // run directory), or by the case file given with --case.
      const FiguresSpec measured =
          o.case_file.empty() ? r.spec.figures : parse_case_file(o.case_file).figures;
      try {
        load_measured(measured, r);
      } catch (const IoError& e) {
        std::cerr << "wcmps: error: " << e.what() << '\n';
        return exit_code::kBadCase;  // bad input, named; nothing written yet
      }
    } catch (const CaseError& e) {
      std::cerr << "wcmps: error: " << e.what() << '\n';
      return exit_code::kBadCase;
    } catch (const IoError& e) {
      std::cerr << "wcmps: error: " << e.what() << '\n';
      return exit_code::kIo;
    }
    if (!r.spec.tank || !r.spec.block || r.spec.sections.empty()) {
      std::cerr << "wcmps: error: " << dir << ": the study's figures need a case with a [tank], "
                << "a [block] and [[section]]s (case " << r.spec.name << " has not)\n";
      return exit_code::kUsage;
    }
    const std::vector<double> times = o.times ? *o.times : r.spec.output_times;
    std::vector<const SeriesEntry*> frames;
    for (const double t : times) {
      const SeriesEntry* e = frame_at(series.back(), t);
      if (!e) {
        std::cerr << "wcmps: error: " << pvd.string() << " has no frame at t = " << t << " s\n";
        return exit_code::kUsage;
      }
      frames.push_back(e);
    }
    if (frames.empty()) {
      std::cerr << "wcmps: error: " << dir << ": no times to draw (the case has no [output] "
                << "times; give --times)\n";
      return exit_code::kUsage;
    }
    picked.push_back(frames);
    runs.push_back(std::move(r));
  }

  const fs::path out = o.output_dir.empty() ? runs.front().dir / "figures" : fs::path(o.output_dir);
  // Writing into the first run's directory: not while a run has it (io/RunLock.h).
  std::optional<RunLock> lock;
  if (o.output_dir.empty()) {
    try {
      lock.emplace(runs.front().dir, "wcmps figures");
    } catch (const IoError& e) {
      std::cerr << "wcmps: error: " << e.what() << '\n';
      return exit_code::kIo;
    }
  }
  std::unique_ptr<OffscreenDisplay> display;
  try {
    display = std::make_unique<OffscreenDisplay>();
  } catch (const DisplayError& e) {
    std::cerr << "wcmps: error: figures: " << e.what() << '\n';
    return exit_code::kNoDisplay;
  }
  std::cout << "rendering through " << display->description() << '\n';
  vtkSMPTools::SetBackend("STDThread");

  nlohmann::json files = nlohmann::json::array();
  TerminalProgress progress;  // while the frames are read and their products computed
  try {
    std::error_code ec;
    fs::create_directories(out, ec);
    if (ec || !fs::is_directory(out)) throw IoError(out.string() + ": cannot create the directory");
    for (size_t k = 0; k < runs.size(); ++k) {
      RunData& r = runs[k];
      // Each frame read once; the block's positions at every time fix one map window, then
      // the products are computed over it.
      std::vector<vtkSmartPointer<vtkPolyData>> frames;
      std::vector<FrameData> blocks;
      for (const SeriesEntry* e : picked[k]) {
        progress.show("figures: run " + std::to_string(k + 1) + " of " +
                          std::to_string(runs.size()) + ", reading frame " +
                          std::to_string(frames.size() + 1) + " of " +
                          std::to_string(picked[k].size()),
                      true);
        frames.push_back(read_frame_file(r.dir / e->file));
        blocks.push_back(block_of(frames.back(), r.dir / e->file, e->time));
      }
      // Widened to the map panels' shape, so that the grid fills them at equal scales.
      const std::array<double, 4> w = map_window(blocks);
      std::array<double, 2> x{w[0], w[1]}, y{w[2], w[3]};
      figures::equal_scales(
          x, y,
          figures::plot_area_size(o.width, o.height, 2, static_cast<int>(blocks.size()), true));
      r.window = {x[0], x[1], y[0], y[1]};
      for (size_t i = 0; i < frames.size(); ++i) {
        progress.show("figures: run " + std::to_string(k + 1) + " of " +
                          std::to_string(runs.size()) + ", surface, sections and grid of frame " +
                          std::to_string(i + 1) + " of " + std::to_string(frames.size()),
                      true);
        add_products(blocks[i], frames[i], r.spec, r.window);
      }
      r.frames = std::move(blocks);
    }
    progress.done();
    auto emit = [&](Figure fig, const std::string& name, const std::string& kind, const RunData& r,
                    const std::string& shows) {
      const figures::Layout layout = render_png(fig, out / name);
      nlohmann::json times = nlohmann::json::array();
      for (const auto& f : r.frames) times.push_back(f.time);
      nlohmann::json j = {{"file", name},          {"figure", kind}, {"case", r.spec.name},
                          {"run", r.dir.string()}, {"times", times}, {"shows", shows}};
      j.update(layout_json(fig, layout));
      files.push_back(j);
      std::cout << "  " << name << '\n';
    };
    const int w = o.width, h = o.height;
    for (RunData& r : runs) {
      r.tag = r.spec.name;
      for (const RunData& other : runs) {
        if (&other != &r && other.spec.name == r.spec.name) {
          r.tag += "_dl" + fmt("%g", r.spec.dl * 1000);
        }
      }
    }
    for (const RunData& r : runs) {
      const std::string c = r.tag;
      emit(surface_figure(r, w, h), "surface_" + c + ".png", "surface", r,
           "water surface with the block in place, one panel per time (thesis Fig. 4-1/4-2)");
      for (size_t s = 0; s < r.spec.sections.size(); ++s) {
        const std::string sec = r.spec.sections[s].name;
        emit(profile_figure(r, s, w, h), "profiles_" + c + "_" + sec + ".png", "profiles", r,
             "velocity along and normal to the bed against Y = h/H at section " + sec +
                 ", one panel per time (thesis Fig. 4-3 ... 4-8)");
      }
      emit(averages_figure(r, w, h), "section_averages_" + c + ".png", "section_averages", r,
           "depth-averaged velocity against X/L over the block, one curve per time (thesis "
           "Fig. 4-9)");
      emit(speed_figure(r, w, h), "speed_" + c + ".png", "speed", r,
           "speed U on the interpolated grid, block and bed drawn, one colour scale for every "
           "time (thesis Fig. 4-10)");
      emit(vorticity_figure(r, w, h), "vorticity_" + c + ".png", "vorticity", r,
           "vorticity (MPS gradient) with velocity vectors, diverging colours centred on zero "
           "(thesis Fig. 4-11)");
      emit(pressure_figure(r, w, h), "pressure_" + c + ".png", "pressure", r,
           "pressure along sections A, C, G and along the block's top C to A, one curve per "
           "time (thesis Fig. A-1 ... A-4)");
    }
    // Resolution: every pair of runs of the same case name at different DL, at section A (or
    // the first) and the last common time.
    for (size_t a = 0; a < runs.size(); ++a) {
      for (size_t b = a + 1; b < runs.size(); ++b) {
        const RunData &ra = runs[a], &rb = runs[b];
        const bool same_case = ra.spec.tank && rb.spec.tank &&
                               ra.spec.tank->slope_deg == rb.spec.tank->slope_deg &&
                               ra.spec.sections.size() == rb.spec.sections.size();
        if (!same_case || ra.spec.dl == rb.spec.dl || ra.frames.size() != rb.frames.size())
          continue;
        size_t s = 0;
        while (s + 1 < ra.spec.sections.size() && ra.spec.sections[s].name != "A") ++s;
        const size_t f = ra.frames.size() - 1;
        const std::string name = "resolution_" + ra.spec.name + "_" + ra.spec.sections[s].name +
                                 "_dl" + fmt("%g", ra.spec.dl * 1000) + "_dl" +
                                 fmt("%g", rb.spec.dl * 1000) + ".png";
        emit(resolution_figure(ra, rb, s, f, w, h), name, "resolution", ra,
             "one section at two particle sizes (thesis Fig. A-5)");
      }
    }
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const nlohmann::json index = {
        {"rendering", display->description()}, {"seconds", seconds}, {"files", files}};
    write_file_atomically(out / "figures.json", index.dump(2) + "\n");
    std::cout << "wrote " << files.size() << " figures to " << out.string() << " in "
              << fmt("%.1f", seconds) << " s\n";
  } catch (const IoError& e) {
    std::cerr << "wcmps: error: " << e.what() << '\n';
    return exit_code::kIo;
  }
  return exit_code::kOk;
}

}  // namespace wcmps
