#include "vtkMPSParticlesToGrid.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "MPSFrame.h"
#include "MPSProbe.h"
#include "operators/WaterSpan.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMPSKernel.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkStreamingDemandDrivenPipeline.h"

vtkStandardNewMacro(vtkMPSParticlesToGrid);

vtkMPSParticlesToGrid::vtkMPSParticlesToGrid()
    : Spacing(0.0),
      SamplingBounds{1.0, -1.0, 1.0, -1.0, 0.0, 0.0},
      Radius(0.0),
      Correction(vtkMPSKernel::LINEAR),
      MinimumCoverage(wcmps::kWaterEdgeCoverage),
      NullValue(std::numeric_limits<double>::quiet_NaN()) {}

void vtkMPSParticlesToGrid::AddArrayName(const char* name) {
  if (name &&
      std::find(this->ArrayNames.begin(), this->ArrayNames.end(), name) == this->ArrayNames.end()) {
    this->ArrayNames.emplace_back(name);
    this->Modified();
  }
}

void vtkMPSParticlesToGrid::ClearArrayNames() {
  if (!this->ArrayNames.empty()) {
    this->ArrayNames.clear();
    this->Modified();
  }
}

int vtkMPSParticlesToGrid::FillInputPortInformation(int, vtkInformation* info) {
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  return 1;
}

namespace {

struct Sampling {
  double origin[3] = {0.0, 0.0, 0.0};
  double spacing = 0.0;
  int extent[6] = {0, -1, 0, -1, 0, 0};
};

bool FixedBounds(const double b[6]) {
  return b[0] < b[1] && b[2] < b[3];
}

Sampling MakeSampling(const double b[6], double h) {
  Sampling s;
  s.spacing = h;
  s.origin[0] = b[0];
  s.origin[1] = b[2];
  // The last point at or just past the upper bound: the grid covers the whole box.
  s.extent[1] = static_cast<int>(std::ceil((b[1] - b[0]) / h - 1e-9));
  s.extent[3] = static_cast<int>(std::ceil((b[3] - b[2]) / h - 1e-9));
  return s;
}

void SetOutputSampling(vtkInformation* outInfo, const Sampling& s) {
  const double spacing[3] = {s.spacing, s.spacing, s.spacing};
  outInfo->Set(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), s.extent, 6);
  outInfo->Set(vtkDataObject::ORIGIN(), s.origin, 3);
  outInfo->Set(vtkDataObject::SPACING(), spacing, 3);
}

}  // namespace

int vtkMPSParticlesToGrid::RequestInformation(vtkInformation*, vtkInformationVector**,
                                              vtkInformationVector* outputVector) {
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  if (this->Spacing > 0.0 && FixedBounds(this->SamplingBounds)) {
    SetOutputSampling(outInfo, MakeSampling(this->SamplingBounds, this->Spacing));
  } else {
    // The grid depends on the frame (its DL and fluid bounds): known in RequestData only.
    outInfo->Remove(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT());
  }
  return 1;
}

int vtkMPSParticlesToGrid::RequestUpdateExtent(vtkInformation*, vtkInformationVector** inputVector,
                                               vtkInformationVector*) {
  // Particles are not split into pieces: every grid point may need any particle.
  vtkInformation* inInfo = inputVector[0]->GetInformationObject(0);
  inInfo->Set(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER(), 0);
  inInfo->Set(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES(), 1);
  return 1;
}

int vtkMPSParticlesToGrid::RequestData(vtkInformation*, vtkInformationVector** inputVector,
                                       vtkInformationVector* outputVector) {
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0]);
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  vtkImageData* output = vtkImageData::GetData(outputVector);
  if (!input || !output) {
    return 0;
  }
  double dl = 0.0, re = 0.0;
  if (!wcmps_filters::FrameScales(input, this->Radius, &dl, &re)) {
    vtkErrorMacro(<< wcmps_filters::kNotAFrame);
    return 0;
  }
  const double h = this->Spacing > 0.0 ? this->Spacing : dl;
  vtkSmartPointer<vtkPolyData> fluid = wcmps_filters::ExtractFluid(
      input,
      this->ArrayNames.empty() ? wcmps_filters::FloatingPointArrays(input) : this->ArrayNames);

  double bounds[6];
  std::copy(this->SamplingBounds, this->SamplingBounds + 6, bounds);
  if (!FixedBounds(bounds)) {
    if (fluid->GetNumberOfPoints() == 0) {
      vtkErrorMacro("The frame has no fluid particles and no SamplingBounds were set.");
      return 0;
    }
    fluid->GetBounds(bounds);
    bounds[0] -= 0.5 * dl;
    bounds[1] += 0.5 * dl;
    bounds[2] -= 0.5 * dl;
    bounds[3] += 0.5 * dl;
  }
  const Sampling s = MakeSampling(bounds, h);
  SetOutputSampling(outInfo, s);
  output->SetExtent(const_cast<int*>(s.extent));
  output->SetOrigin(s.origin[0], s.origin[1], 0.0);
  output->SetSpacing(h, h, h);

  const vtkIdType n = output->GetNumberOfPoints();
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(n);
  double x[3];
  for (vtkIdType i = 0; i < n; ++i) {
    output->GetPoint(i, x);
    points->SetPoint(i, x);
  }
  const wcmps_filters::ParticleProbe probe(fluid, dl, re, this->Correction);
  probe.Probe(points, this->MinimumCoverage, this->NullValue, output->GetPointData());
  output->GetFieldData()->ShallowCopy(input->GetFieldData());
  return 1;
}

void vtkMPSParticlesToGrid::PrintSelf(ostream& os, vtkIndent indent) {
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Spacing: " << this->Spacing << (this->Spacing > 0.0 ? "" : " (DL)") << "\n";
  os << indent << "SamplingBounds: (" << this->SamplingBounds[0] << ", " << this->SamplingBounds[1]
     << ", " << this->SamplingBounds[2] << ", " << this->SamplingBounds[3] << ")"
     << (FixedBounds(this->SamplingBounds) ? "" : " (fluid)") << "\n";
  os << indent << "Radius: " << this->Radius << (this->Radius > 0.0 ? "" : " (re)") << "\n";
  os << indent << "Correction: " << (this->Correction ? "Linear" : "Shepard") << "\n";
  os << indent << "MinimumCoverage: " << this->MinimumCoverage << "\n";
  os << indent << "NullValue: " << this->NullValue << "\n";
  os << indent << "ArrayNames:";
  for (const auto& name : this->ArrayNames) {
    os << " " << name;
  }
  os << (this->ArrayNames.empty() ? " (every floating-point array)" : "") << "\n";
}
