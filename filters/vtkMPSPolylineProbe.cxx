#include "vtkMPSPolylineProbe.h"

#include <cmath>
#include <limits>

#include "MPSFrame.h"
#include "MPSProbe.h"
#include "vtkCellArray.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkMPSKernel.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"

vtkStandardNewMacro(vtkMPSPolylineProbe);

vtkMPSPolylineProbe::vtkMPSPolylineProbe() : NumberOfSamples(101), MinimumCoverage(0.0) {}

void vtkMPSPolylineProbe::AddPoint(double x, double y) {
  this->Points.insert(this->Points.end(), {x, y});
  this->Modified();
}

void vtkMPSPolylineProbe::RemoveAllPoints() {
  this->Points.clear();
  this->Modified();
}

int vtkMPSPolylineProbe::RequestData(vtkInformation*, vtkInformationVector** inputVector,
                                     vtkInformationVector* outputVector) {
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0]);
  vtkPolyData* output = vtkPolyData::GetData(outputVector);
  if (!input || !output) return 0;
  double dl = 0.0, re = 0.0;
  if (!wcmps_filters::FrameScales(input, 0.0, &dl, &re)) {
    vtkErrorMacro(<< wcmps_filters::kNotAFrame);
    return 0;
  }
  std::vector<double> corners = this->Points;
  if (corners.empty()) {
    vtkDataArray* outline = input->GetFieldData()->GetArray("BlockOutline");
    if (!outline || outline->GetNumberOfTuples() < 2) {
      vtkErrorMacro("No polyline points were given and the frame has no BlockOutline.");
      return 0;
    }
    corners = {outline->GetComponent(0, 0), outline->GetComponent(0, 1),
               outline->GetComponent(1, 0), outline->GetComponent(1, 1)};
  }
  if (corners.size() < 4) {
    vtkErrorMacro("A polyline needs two points or more.");
    return 0;
  }
  // Cumulative arc length at each corner.
  const size_t nc = corners.size() / 2;
  std::vector<double> arc(nc, 0.0);
  for (size_t k = 1; k < nc; ++k) {
    arc[k] = arc[k - 1] + std::hypot(corners[2 * k] - corners[2 * k - 2],
                                     corners[2 * k + 1] - corners[2 * k - 1]);
  }
  const double total = arc.back();
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkDoubleArray> arc_length, arc_fraction;
  arc_length->SetName("arc_length");
  arc_fraction->SetName("arc_fraction");
  size_t seg = 0;
  for (int k = 0; k < this->NumberOfSamples; ++k) {
    const double f = static_cast<double>(k) / (this->NumberOfSamples - 1);
    const double s = f * total;
    while (seg + 2 < nc && arc[seg + 1] < s) ++seg;
    const double len = arc[seg + 1] - arc[seg];
    const double t = len > 0.0 ? (s - arc[seg]) / len : 0.0;
    points->InsertNextPoint(
        corners[2 * seg] + t * (corners[2 * seg + 2] - corners[2 * seg]),
        corners[2 * seg + 1] + t * (corners[2 * seg + 3] - corners[2 * seg + 1]), 0.0);
    arc_length->InsertNextValue(s);
    arc_fraction->InsertNextValue(f);
  }
  vtkSmartPointer<vtkPolyData> fluid =
      wcmps_filters::ExtractFluid(input, wcmps_filters::FloatingPointArrays(input));
  const wcmps_filters::ParticleProbe probe(fluid, dl, re, vtkMPSKernel::LINEAR);
  probe.Probe(points, this->MinimumCoverage, std::numeric_limits<double>::quiet_NaN(),
              output->GetPointData());
  std::vector<vtkIdType> ids(static_cast<size_t>(this->NumberOfSamples));
  for (size_t k = 0; k < ids.size(); ++k) ids[k] = static_cast<vtkIdType>(k);
  vtkNew<vtkCellArray> line;
  line->InsertNextCell(static_cast<vtkIdType>(ids.size()), ids.data());
  output->SetPoints(points);
  output->SetLines(line);
  output->GetPointData()->AddArray(arc_length);
  output->GetPointData()->AddArray(arc_fraction);
  output->GetFieldData()->ShallowCopy(input->GetFieldData());
  return 1;
}

void vtkMPSPolylineProbe::PrintSelf(ostream& os, vtkIndent indent) {
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Points:";
  for (size_t k = 0; k + 1 < this->Points.size(); k += 2) {
    os << " (" << this->Points[k] << ", " << this->Points[k + 1] << ")";
  }
  os << (this->Points.empty() ? " (block top C to A)" : "") << "\n";
  os << indent << "NumberOfSamples: " << this->NumberOfSamples << "\n";
  os << indent << "MinimumCoverage: " << this->MinimumCoverage << "\n";
}
