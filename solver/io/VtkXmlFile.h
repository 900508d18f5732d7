#pragma once
/// @file VtkXmlFile.h
/// @brief A VTK XML file (a frame, a grid) streamed to its temporary name and renamed into
/// place: no copy of the encoded file in memory, and a full disk reported as an IoError.

#include <filesystem>

class vtkXMLWriter;

namespace wcmps {

/// Runs `writer` (its input set) into `path` through an AtomicOutputFile; throws IoError naming
/// the file when the encoding or a write fails. The writer's FileName is not used.
void write_vtk_xml_atomically(vtkXMLWriter& writer, const std::filesystem::path& path);

}  // namespace wcmps
