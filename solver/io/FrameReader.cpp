#include "io/FrameReader.h"

#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkXMLPolyDataReader.h>

#include "core/Error.h"

namespace wcmps {

vtkSmartPointer<vtkPolyData> read_frame_file(const std::filesystem::path& file) {
  vtkNew<vtkXMLPolyDataReader> reader;
  reader->SetFileName(file.string().c_str());
  reader->Update();
  vtkSmartPointer<vtkPolyData> frame = reader->GetOutput();
  if (reader->GetErrorCode() != 0 || !frame || frame->GetNumberOfPoints() == 0) {
    throw IoError(file.string() + ": cannot read the frame");
  }
  return frame;
}

}  // namespace wcmps
