#include "vtkMPSSections.h"

#include <cmath>

#include "MPSFrame.h"
#include "MPSProbe.h"
#include "MPSSections.h"
#include "operators/WaterSpan.h"
#include "vtkFieldData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMPSKernel.h"
#include "vtkObjectFactory.h"
#include "vtkPolyData.h"
#include "vtkStringArray.h"
#include "vtkTable.h"

vtkStandardNewMacro(vtkMPSSections);

vtkMPSSections::vtkMPSSections()
    : NumberOfSamples(51),
      MinimumCoverage(wcmps::kWaterEdgeCoverage),
      Correction(vtkMPSKernel::LINEAR) {
  this->SetNumberOfOutputPorts(2);
}

void vtkMPSSections::AddSection(const char* name, double x, double y, double nx, double ny) {
  const double len = std::hypot(nx, ny);
  if (len <= 0.0) {
    vtkErrorMacro("Section " << (name ? name : "") << " has a zero direction.");
    return;
  }
  this->Names.emplace_back(name ? name : "");
  this->Lines.insert(this->Lines.end(), {x, y, nx / len, ny / len});
  this->Modified();
}

void vtkMPSSections::RemoveAllSections() {
  this->Names.clear();
  this->Lines.clear();
  this->Modified();
}

vtkTable* vtkMPSSections::GetSummary() {
  return vtkTable::SafeDownCast(this->GetOutputDataObject(1));
}

int vtkMPSSections::FillOutputPortInformation(int port, vtkInformation* info) {
  info->Set(vtkDataObject::DATA_TYPE_NAME(), port == 1 ? "vtkTable" : "vtkPolyData");
  return 1;
}

int vtkMPSSections::RequestData(vtkInformation*, vtkInformationVector** inputVector,
                                vtkInformationVector* outputVector) {
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0]);
  vtkPolyData* profiles = vtkPolyData::GetData(outputVector, 0);
  vtkTable* summary = vtkTable::GetData(outputVector, 1);
  if (!input || !profiles || !summary) return 0;
  double dl = 0.0, re = 0.0;
  if (!wcmps_filters::FrameScales(input, 0.0, &dl, &re)) {
    vtkErrorMacro(<< wcmps_filters::kNotAFrame);
    return 0;
  }
  std::vector<wcmps_filters::SectionLine> lines;
  for (size_t k = 0; k < this->Names.size(); ++k) {
    const double* l = &this->Lines[4 * k];
    lines.push_back({this->Names[k], {l[0], l[1]}, {l[2], l[3]}});
  }
  if (lines.empty()) {
    // None added: the case's sections, which `wcmps run` writes into every frame.
    auto* names =
        vtkStringArray::SafeDownCast(input->GetFieldData()->GetAbstractArray("SectionNames"));
    vtkDataArray* given = input->GetFieldData()->GetArray("SectionLines");
    if (!names || !given || given->GetNumberOfComponents() != 4 ||
        given->GetNumberOfTuples() != names->GetNumberOfValues()) {
      vtkErrorMacro(
          "No sections: add some (AddSection), or use a frame that lists its case's "
          "sections (field data SectionNames and SectionLines).");
      return 0;
    }
    for (vtkIdType k = 0; k < names->GetNumberOfValues(); ++k) {
      double l[4];
      given->GetTuple(k, l);
      const double len = std::hypot(l[2], l[3]);
      if (!(len > 0.0)) continue;
      lines.push_back({names->GetValue(k), {l[0], l[1]}, {l[2] / len, l[3] / len}});
    }
  }
  vtkSmartPointer<vtkPolyData> fluid =
      wcmps_filters::ExtractFluid(input, wcmps_filters::FloatingPointArrays(input));
  const wcmps_filters::ParticleProbe probe(fluid, dl, re, this->Correction);
  wcmps_filters::SampleSections(probe, lines, this->NumberOfSamples, this->MinimumCoverage,
                                profiles, summary);
  profiles->GetFieldData()->ShallowCopy(input->GetFieldData());
  vtkNew<vtkStringArray> names;
  names->SetName("SectionNames");
  for (const auto& l : lines) names->InsertNextValue(l.name);
  profiles->GetFieldData()->AddArray(names);
  return 1;
}

void vtkMPSSections::PrintSelf(ostream& os, vtkIndent indent) {
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Sections: " << this->Names.size() << "\n";
  for (size_t k = 0; k < this->Names.size(); ++k) {
    const double* l = &this->Lines[4 * k];
    os << indent.GetNextIndent() << this->Names[k] << ": (" << l[0] << ", " << l[1]
       << ") direction (" << l[2] << ", " << l[3] << ")\n";
  }
  os << indent << "NumberOfSamples: " << this->NumberOfSamples << "\n";
  os << indent << "MinimumCoverage: " << this->MinimumCoverage << "\n";
  os << indent << "Correction: " << (this->Correction ? "Linear" : "Shepard") << "\n";
}
