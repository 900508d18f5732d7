#include "MPSSections.h"

#include <cmath>
#include <limits>

#include "MPSProbe.h"
#include "vtkCellArray.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkStringArray.h"
#include "vtkTable.h"

namespace wcmps_filters {

namespace {

vtkDoubleArray* AddColumn(vtkTable* t, const char* name) {
  vtkNew<vtkDoubleArray> a;
  a->SetName(name);
  t->AddColumn(a);
  return a;
}

/// Trapezoid rule over equally spaced samples: the mean of f over [0, 1].
double DepthMean(const std::vector<double>& f) {
  if (f.size() < 2) return std::numeric_limits<double>::quiet_NaN();
  double s = 0.5 * (f.front() + f.back());
  for (size_t k = 1; k + 1 < f.size(); ++k) s += f[k];
  return s / static_cast<double>(f.size() - 1);
}

}  // namespace

void SampleSections(const ParticleProbe& probe, const std::vector<SectionLine>& lines, int samples,
                    double threshold, vtkPolyData* profiles, vtkTable* summary) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkCellArray> cells;
  vtkNew<vtkIntArray> section_id;
  section_id->SetName("section");
  vtkNew<vtkDoubleArray> h_array, y_array;
  h_array->SetName("h");
  y_array->SetName("Y");

  vtkNew<vtkStringArray> names;
  names->SetName("section");
  summary->AddColumn(names);
  vtkDoubleArray* x0 = AddColumn(summary, "x0");
  vtkDoubleArray* y0 = AddColumn(summary, "y0");
  vtkDoubleArray* x1 = AddColumn(summary, "x1");
  vtkDoubleArray* y1 = AddColumn(summary, "y1");
  vtkDoubleArray* depth = AddColumn(summary, "H");
  vtkDoubleArray* m_along = AddColumn(summary, "mean_u_along");
  vtkDoubleArray* m_normal = AddColumn(summary, "mean_u_normal");
  vtkDoubleArray* m_speed = AddColumn(summary, "mean_speed");
  vtkDoubleArray* m_pressure = AddColumn(summary, "mean_pressure");

  std::vector<ParticleProbe::Span> spans;
  for (size_t l = 0; l < lines.size(); ++l) {
    const SectionLine& line = lines[l];
    const ParticleProbe::Span span = probe.LongestWaterSpan(line.origin, line.normal, threshold);
    spans.push_back(span);
    if (!span.found) continue;
    const double height = span.s1 - span.s0;
    std::vector<vtkIdType> ids;
    for (int k = 0; k < samples; ++k) {
      const double y = samples > 1 ? static_cast<double>(k) / (samples - 1) : 0.0;
      const double s = span.s0 + y * height;
      ids.push_back(points->InsertNextPoint(line.origin[0] + s * line.normal[0],
                                            line.origin[1] + s * line.normal[1], 0.0));
      section_id->InsertNextValue(static_cast<int>(l));
      h_array->InsertNextValue(y * height);
      y_array->InsertNextValue(y);
    }
    cells->InsertNextCell(static_cast<vtkIdType>(ids.size()), ids.data());
  }

  // Every sample gets a value: its ends sit on the edge of the water (coverage ~ threshold).
  vtkNew<vtkPointData> values;
  probe.Probe(points, 0.0, nan, values);
  vtkDataArray* velocity = values->GetArray("velocity");
  vtkDataArray* pressure = values->GetArray("pressure");
  vtkNew<vtkDoubleArray> u_along, u_normal;
  u_along->SetName("u_along");
  u_normal->SetName("u_normal");

  vtkIdType next = 0;
  for (size_t l = 0; l < lines.size(); ++l) {
    const SectionLine& line = lines[l];
    const ParticleProbe::Span& span = spans[l];
    names->InsertNextValue(line.name);
    const double sa = span.found ? span.s0 : nan, sb = span.found ? span.s1 : nan;
    x0->InsertNextValue(line.origin[0] + sa * line.normal[0]);
    y0->InsertNextValue(line.origin[1] + sa * line.normal[1]);
    x1->InsertNextValue(line.origin[0] + sb * line.normal[0]);
    y1->InsertNextValue(line.origin[1] + sb * line.normal[1]);
    depth->InsertNextValue(span.found ? sb - sa : 0.0);
    std::vector<double> fa, fn, fs, fp;
    if (span.found) {
      const double tx = line.normal[1], ty = -line.normal[0];
      for (int k = 0; k < samples; ++k, ++next) {
        if (velocity) {
          const double u = velocity->GetComponent(next, 0), v = velocity->GetComponent(next, 1);
          const double a = u * tx + v * ty, n = u * line.normal[0] + v * line.normal[1];
          u_along->InsertNextValue(a);
          u_normal->InsertNextValue(n);
          fa.push_back(a);
          fn.push_back(n);
          fs.push_back(std::hypot(u, v));
        }
        if (pressure) fp.push_back(pressure->GetComponent(next, 0));
      }
    }
    m_along->InsertNextValue(fa.empty() ? nan : DepthMean(fa));
    m_normal->InsertNextValue(fn.empty() ? nan : DepthMean(fn));
    m_speed->InsertNextValue(fs.empty() ? nan : DepthMean(fs));
    m_pressure->InsertNextValue(fp.empty() ? nan : DepthMean(fp));
  }

  if (profiles) {
    profiles->SetPoints(points);
    profiles->SetLines(cells);
    vtkPointData* pd = profiles->GetPointData();
    pd->ShallowCopy(values);
    pd->AddArray(section_id);
    pd->AddArray(h_array);
    pd->AddArray(y_array);
    if (velocity) {
      pd->AddArray(u_along);
      pd->AddArray(u_normal);
    }
  }
}

}  // namespace wcmps_filters
