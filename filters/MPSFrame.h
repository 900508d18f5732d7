#ifndef MPSFrame_h
#define MPSFrame_h
/// @file MPSFrame.h
/// @brief What the filters read from a wcmps frame: its field data (DL, re, n0) and its fluid
/// particles. Private to the module.

#include <string>
#include <vector>

#include "vtkSmartPointer.h"

class vtkDataArray;
class vtkFieldData;
class vtkPolyData;

namespace wcmps_filters {

/// The named one-value field-data array of the frame, or fallback if it has none.
double FieldValue(vtkFieldData* fd, const char* name, double fallback);

/// DL and re: the given value when positive, else the frame's field data; 0 if neither.
double FrameSpacing(vtkPolyData* frame, double given);
double FrameRadius(vtkPolyData* frame, double given);

/// DL and re of a frame (re: re_given when positive); false if it has no positive DL or re,
/// i.e. it is not a wcmps frame (the caller reports kNotAFrame).
bool FrameScales(vtkPolyData* frame, double re_given, double* dl, double* re);
inline constexpr const char* kNotAFrame =
    "The frame has no DL or re field data: it is not a wcmps frame.";

/// True for a point the "kind" array marks as fluid (0); every point when there is no "kind".
std::vector<char> FluidMask(vtkPolyData* frame);

/// The fluid particles of frame, with copies of the named point arrays as vtkDoubleArray
/// (FloatingPointArrays(frame) for all of them; none for the points alone). No cells: the
/// kernels only need points.
vtkSmartPointer<vtkPolyData> ExtractFluid(vtkPolyData* frame,
                                          const std::vector<std::string>& names);

/// The floating-point point arrays of frame, which are the ones worth interpolating (the
/// integer ones, kind, id and free_surface, are labels).
std::vector<std::string> FloatingPointArrays(vtkPolyData* frame);

}  // namespace wcmps_filters

#endif
