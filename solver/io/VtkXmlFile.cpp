#include "io/VtkXmlFile.h"

#include <vtkXMLWriter.h>

#include "core/Error.h"
#include "io/AtomicFile.h"

namespace wcmps {
namespace {

/// VTK 9.2 has no public setter for the stream an XML writer writes to (vtkXMLWriter::Stream is
/// protected; the writer uses it instead of a file when it is set). A pointer to the member,
/// formed in a subclass, reaches it.
struct StreamAccess : vtkXMLWriter {
  static void set(vtkXMLWriter& writer, std::ostream* stream) {
    writer.*(&StreamAccess::Stream) = stream;
  }
};

}  // namespace

void write_vtk_xml_atomically(vtkXMLWriter& writer, const std::filesystem::path& path) {
  AtomicOutputFile file(path);
  writer.WriteToOutputStringOff();
  StreamAccess::set(writer, &file.stream());
  const int ok = writer.Write();
  StreamAccess::set(writer, nullptr);  // the file's stream ends with this scope
  if (ok != 1 || writer.GetErrorCode() != 0) {
    throw IoError("cannot encode " + path.string());
  }
  file.commit();
}

}  // namespace wcmps
