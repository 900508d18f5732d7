#include "MPSFrame.h"

#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"

namespace wcmps_filters {

double FieldValue(vtkFieldData* fd, const char* name, double fallback) {
  vtkDataArray* a = fd ? vtkDataArray::SafeDownCast(fd->GetAbstractArray(name)) : nullptr;
  if (!a || a->GetNumberOfTuples() < 1) {
    return fallback;
  }
  return a->GetComponent(0, 0);
}

double FrameSpacing(vtkPolyData* frame, double given) {
  return given > 0.0 ? given : FieldValue(frame->GetFieldData(), "DL", 0.0);
}

double FrameRadius(vtkPolyData* frame, double given) {
  return given > 0.0 ? given : FieldValue(frame->GetFieldData(), "re", 0.0);
}

bool FrameScales(vtkPolyData* frame, double re_given, double* dl, double* re) {
  *dl = FrameSpacing(frame, 0.0);
  *re = FrameRadius(frame, re_given);
  return *dl > 0.0 && *re > 0.0;
}

std::vector<char> FluidMask(vtkPolyData* frame) {
  const vtkIdType n = frame->GetNumberOfPoints();
  std::vector<char> fluid(static_cast<size_t>(n), 1);
  vtkDataArray* kind = frame->GetPointData()->GetArray("kind");
  if (kind) {
    for (vtkIdType i = 0; i < n; ++i) {
      fluid[static_cast<size_t>(i)] = kind->GetComponent(i, 0) == 0.0;
    }
  }
  return fluid;
}

std::vector<std::string> FloatingPointArrays(vtkPolyData* frame) {
  std::vector<std::string> names;
  vtkPointData* pd = frame->GetPointData();
  for (int a = 0; a < pd->GetNumberOfArrays(); ++a) {
    vtkDataArray* arr = pd->GetArray(a);
    if (arr && arr->GetName() &&
        (arr->GetDataType() == VTK_FLOAT || arr->GetDataType() == VTK_DOUBLE)) {
      names.emplace_back(arr->GetName());
    }
  }
  return names;
}

vtkSmartPointer<vtkPolyData> ExtractFluid(vtkPolyData* frame,
                                          const std::vector<std::string>& names) {
  const std::vector<char> fluid = FluidMask(frame);
  const vtkIdType n = frame->GetNumberOfPoints();
  vtkIdType count = 0;
  for (const char f : fluid) {
    count += f;
  }
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(count);
  auto out = vtkSmartPointer<vtkPolyData>::New();
  out->SetPoints(points);
  std::vector<std::pair<vtkDataArray*, vtkDataArray*>> copies;
  for (const auto& name : names) {
    vtkDataArray* src = frame->GetPointData()->GetArray(name.c_str());
    if (!src) {
      continue;
    }
    // Doubles whatever the frame's type: the kernels sum them with double weights.
    auto dst = vtkSmartPointer<vtkDoubleArray>::New();
    dst->SetName(src->GetName());
    dst->SetNumberOfComponents(src->GetNumberOfComponents());
    dst->SetNumberOfTuples(count);
    out->GetPointData()->AddArray(dst);
    copies.emplace_back(src, dst);
  }
  double x[3];
  vtkIdType k = 0;
  for (vtkIdType i = 0; i < n; ++i) {
    if (!fluid[static_cast<size_t>(i)]) {
      continue;
    }
    frame->GetPoint(i, x);
    points->SetPoint(k, x);
    for (auto& c : copies) {
      c.second->SetTuple(k, i, c.first);
    }
    ++k;
  }
  out->GetFieldData()->ShallowCopy(frame->GetFieldData());
  return out;
}

}  // namespace wcmps_filters
