#include "vtkMPSSectionAverages.h"

#include <cmath>
#include <cstdio>

#include "MPSFrame.h"
#include "MPSProbe.h"
#include "MPSSections.h"
#include "operators/WaterSpan.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMPSKernel.h"
#include "vtkObjectFactory.h"
#include "vtkPolyData.h"
#include "vtkTable.h"

vtkStandardNewMacro(vtkMPSSectionAverages);

vtkMPSSectionAverages::vtkMPSSectionAverages()
    : MaximumXOverL(3.5),
      NumberOfStations(36),
      BedNormal{0.0, 0.0},
      NumberOfSamples(51),
      MinimumCoverage(wcmps::kWaterEdgeCoverage) {}

int vtkMPSSectionAverages::FillInputPortInformation(int, vtkInformation* info) {
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  return 1;
}

int vtkMPSSectionAverages::RequestData(vtkInformation*, vtkInformationVector** inputVector,
                                       vtkInformationVector* outputVector) {
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0]);
  vtkTable* output = vtkTable::GetData(outputVector);
  if (!input || !output) return 0;
  double dl = 0.0, re = 0.0;
  if (!wcmps_filters::FrameScales(input, 0.0, &dl, &re)) {
    vtkErrorMacro(<< wcmps_filters::kNotAFrame);
    return 0;
  }
  vtkDataArray* outline = input->GetFieldData()->GetArray("BlockOutline");
  if (!outline || outline->GetNumberOfTuples() < 3 || outline->GetNumberOfComponents() < 2) {
    vtkErrorMacro(
        "The frame has no BlockOutline field data (corners C, A, G): section "
        "averages are measured along a block's top edge.");
    return 0;
  }
  const double cx = outline->GetComponent(0, 0), cy = outline->GetComponent(0, 1);
  const double ax = outline->GetComponent(1, 0), ay = outline->GetComponent(1, 1);
  const double gx = outline->GetComponent(2, 0), gy = outline->GetComponent(2, 1);
  const double length = std::hypot(ax - cx, ay - cy);
  double n[2] = {this->BedNormal[0], this->BedNormal[1]};
  if (std::hypot(n[0], n[1]) <= 0.0) {
    // CG lies on the bed: its normal, turned upwards.
    n[0] = -(gy - cy);
    n[1] = gx - cx;
    if (n[1] < 0.0) {
      n[0] = -n[0];
      n[1] = -n[1];
    }
  }
  const double nl = std::hypot(n[0], n[1]);
  n[0] /= nl;
  n[1] /= nl;
  std::vector<wcmps_filters::SectionLine> lines;
  std::vector<double> xl;
  for (int k = 0; k < this->NumberOfStations; ++k) {
    const double q = this->MaximumXOverL * k / (this->NumberOfStations - 1);
    char name[32];
    std::snprintf(name, sizeof name, "X/L=%.3g", q);
    lines.push_back({name, {cx + q * (ax - cx), cy + q * (ay - cy)}, {n[0], n[1]}});
    xl.push_back(q);
  }
  vtkSmartPointer<vtkPolyData> fluid =
      wcmps_filters::ExtractFluid(input, wcmps_filters::FloatingPointArrays(input));
  const wcmps_filters::ParticleProbe probe(fluid, dl, re, vtkMPSKernel::LINEAR);
  vtkNew<vtkTable> summary;
  wcmps_filters::SampleSections(probe, lines, this->NumberOfSamples, this->MinimumCoverage, nullptr,
                                summary);
  vtkNew<vtkDoubleArray> x_over_l, x;
  x_over_l->SetName("X_over_L");
  x->SetName("X");
  for (const double q : xl) {
    x_over_l->InsertNextValue(q);
    x->InsertNextValue(q * length);
  }
  output->AddColumn(x_over_l);
  output->AddColumn(x);
  for (vtkIdType c = 0; c < summary->GetNumberOfColumns(); ++c) {
    output->AddColumn(summary->GetColumn(c));
  }
  output->GetFieldData()->ShallowCopy(input->GetFieldData());
  return 1;
}

void vtkMPSSectionAverages::PrintSelf(ostream& os, vtkIndent indent) {
  this->Superclass::PrintSelf(os, indent);
  os << indent << "MaximumXOverL: " << this->MaximumXOverL << "\n";
  os << indent << "NumberOfStations: " << this->NumberOfStations << "\n";
  os << indent << "BedNormal: (" << this->BedNormal[0] << ", " << this->BedNormal[1] << ")"
     << (std::hypot(this->BedNormal[0], this->BedNormal[1]) > 0.0 ? "" : " (face CG)") << "\n";
  os << indent << "NumberOfSamples: " << this->NumberOfSamples << "\n";
  os << indent << "MinimumCoverage: " << this->MinimumCoverage << "\n";
}
