#include "vtkMPSFreeSurface.h"

#include <cmath>

#include "MPSFrame.h"
#include "MPSProbe.h"
#include "operators/WaterSpan.h"
#include "vtkCellArray.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkIntArray.h"
#include "vtkMPSKernel.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSMPTools.h"

vtkStandardNewMacro(vtkMPSFreeSurface);

vtkMPSFreeSurface::vtkMPSFreeSurface() : Spacing(0.0), MinimumCoverage(wcmps::kWaterEdgeCoverage) {}

void vtkMPSFreeSurface::AddGauge(double x) {
  this->Gauges.push_back(x);
  this->Modified();
}

void vtkMPSFreeSurface::RemoveAllGauges() {
  this->Gauges.clear();
  this->Modified();
}

int vtkMPSFreeSurface::RequestData(vtkInformation*, vtkInformationVector** inputVector,
                                   vtkInformationVector* outputVector) {
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0]);
  vtkPolyData* output = vtkPolyData::GetData(outputVector);
  if (!input || !output) return 0;
  double dl = 0.0, re = 0.0;
  if (!wcmps_filters::FrameScales(input, 0.0, &dl, &re)) {
    vtkErrorMacro(<< wcmps_filters::kNotAFrame);
    return 0;
  }
  vtkSmartPointer<vtkPolyData> fluid = wcmps_filters::ExtractFluid(input, {});
  const wcmps_filters::ParticleProbe probe(fluid, dl, re, vtkMPSKernel::LINEAR);

  std::vector<double> stations = this->Gauges;
  if (stations.empty() && fluid->GetNumberOfPoints() > 0) {
    double b[6];
    fluid->GetBounds(b);
    const double h = this->Spacing > 0.0 ? this->Spacing : dl;
    // From the first particle to the last: on the water's side edges themselves the coverage
    // is about the threshold, and whether a station there is wet is a matter of round-off.
    const double x0 = b[0], x1 = b[1];
    const int n = static_cast<int>(std::floor((x1 - x0) / h + 1e-9));
    for (int k = 0; k <= n; ++k) stations.push_back(x0 + k * h);
  }
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkCellArray> lines;
  vtkNew<vtkDoubleArray> xs, eta;
  xs->SetName("x");
  eta->SetName("eta");
  vtkNew<vtkIntArray> gauge;
  gauge->SetName("gauge");
  std::vector<vtkIdType> run;
  const auto flush = [&]() {
    if (run.size() >= 2) lines->InsertNextCell(static_cast<vtkIdType>(run.size()), run.data());
    run.clear();
  };
  // The stations are independent: scan them in parallel, then join them in order.
  std::vector<wcmps_filters::ParticleProbe::Span> spans(stations.size());
  vtkSMPTools::For(0, static_cast<vtkIdType>(stations.size()), [&](vtkIdType b, vtkIdType e) {
    for (vtkIdType k = b; k < e; ++k) {
      const double p[2] = {stations[static_cast<size_t>(k)], 0.0}, up[2] = {0.0, 1.0};
      spans[static_cast<size_t>(k)] = probe.LongestWaterSpan(p, up, this->MinimumCoverage);
    }
  });
  for (size_t k = 0; k < stations.size(); ++k) {
    const auto& span = spans[k];
    if (!span.found) {
      flush();
      continue;
    }
    run.push_back(points->InsertNextPoint(stations[k], span.s1, 0.0));
    xs->InsertNextValue(stations[k]);
    eta->InsertNextValue(span.s1);
    gauge->InsertNextValue(static_cast<int>(k));
  }
  flush();
  output->SetPoints(points);
  output->SetLines(lines);
  output->GetPointData()->AddArray(xs);
  output->GetPointData()->AddArray(eta);
  if (!this->Gauges.empty()) output->GetPointData()->AddArray(gauge);
  output->GetFieldData()->ShallowCopy(input->GetFieldData());
  return 1;
}

void vtkMPSFreeSurface::PrintSelf(ostream& os, vtkIndent indent) {
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Spacing: " << this->Spacing << (this->Spacing > 0.0 ? "" : " (DL)") << "\n";
  os << indent << "Gauges:";
  for (const double x : this->Gauges) os << " " << x;
  os << (this->Gauges.empty() ? " (none: every Spacing)" : "") << "\n";
  os << indent << "MinimumCoverage: " << this->MinimumCoverage << "\n";
}
