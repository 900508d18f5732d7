#pragma once
/// @file FrameReader.h
/// @brief Reads one frame (.vtp) of a run back, for the commands that post-process it.

#include <vtkSmartPointer.h>

#include <filesystem>

class vtkPolyData;

namespace wcmps {

/// The frame's particles and field data; throws IoError naming the file if it cannot be
/// read or holds no particles.
vtkSmartPointer<vtkPolyData> read_frame_file(const std::filesystem::path& file);

}  // namespace wcmps
