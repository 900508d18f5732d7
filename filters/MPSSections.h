#ifndef MPSSections_h
#define MPSSections_h
/// @file MPSSections.h
/// @brief Velocity and pressure profiles along straight sections through the water, shared by
/// vtkMPSSections and vtkMPSSectionAverages. Private to the module.

#include <string>
#include <vector>

class vtkPolyData;
class vtkTable;

namespace wcmps_filters {

class ParticleProbe;

/// A straight line through the water: a point on it and its unit direction n, pointing from
/// the bed towards the surface. The bed-aligned frame is t = (n_y, -n_x) (n turned clockwise
/// by 90 degrees: downslope for the study's beds) and n.
struct SectionLine {
  std::string name;
  double origin[2];
  double normal[2];
};

/// Samples every line at n points from the start of its water (bed, block or wall) to the
/// free surface (ParticleProbe::LongestWaterSpan with the given coverage threshold).
///
/// profiles (may be null) gets a point per sample and a polyline per section, with the
/// interpolated arrays and "section" (index), "h" (m from the start of the water), "Y" = h/H,
/// "u_along" and "u_normal" (m/s, when there is a "velocity").
///
/// summary gets a row per section: "section" (name), "x0", "y0" (start of the water), "x1",
/// "y1" (free surface), "H" (m), and the depth averages (trapezoid rule over the samples)
/// "mean_u_along", "mean_u_normal", "mean_speed" (of the interpolated velocity),
/// "mean_pressure". A line that meets no water has H = 0 and NaN averages.
void SampleSections(const ParticleProbe& probe, const std::vector<SectionLine>& lines, int samples,
                    double threshold, vtkPolyData* profiles, vtkTable* summary);

}  // namespace wcmps_filters

#endif
