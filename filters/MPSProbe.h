#ifndef MPSProbe_h
#define MPSProbe_h
/// @file MPSProbe.h
/// @brief Kernel interpolation of fluid particles at arbitrary points: the one place where the
/// filters turn particles into values at a point (grids, sections, polylines, the free
/// surface). Private to the module.

#include <string>
#include <vector>

#include "operators/WaterSpan.h"
#include "vtkNew.h"
#include "vtkSmartPointer.h"

class vtkDataArray;
class vtkIdList;
class vtkPointData;
class vtkPoints;
class vtkPolyData;
class vtkStaticPointLocator;
class vtkMPSKernel;

namespace wcmps_filters {

class ParticleProbe {
 public:
  /// fluid: fluid particles with the arrays to interpolate (ExtractFluid). dl, re > 0.
  ParticleProbe(vtkPolyData* fluid, double dl, double re, int correction);
  ~ParticleProbe();
  ParticleProbe(const ParticleProbe&) = delete;
  ParticleProbe& operator=(const ParticleProbe&) = delete;

  /// Interpolates at every point of points into new arrays of out (same names and component
  /// counts as the fluid's arrays), plus "coverage" and "vtkValidPointMask"; points with
  /// coverage below minCoverage get nullValue. Parallel over points (vtkSMPTools).
  void Probe(vtkPoints* points, double minCoverage, double nullValue, vtkPointData* out) const;

  /// The stretch [s0, s1] of the line p + s d (d a unit vector) where the water is, i.e.
  /// where coverage >= threshold: of all such stretches within the fluid's bounds grown by
  /// re, the longest (so a splash or a film cut off by the block is not taken for the water
  /// column). The line is scanned in steps of DL/4 and each end refined by bisection to
  /// DL/1000. found is false where the line meets no water.
  using Span = wcmps::WaterSpan;
  Span LongestWaterSpan(const double p[2], const double d[2], double threshold) const;

 private:
  /// Coverage at (x, y): sum_j W DL^2 / (pi re^2 / 10) (see vtkMPSParticlesToGrid); ids is
  /// scratch for the neighbour search, so a scan of many points allocates nothing.
  double Coverage(double x, double y, vtkIdList* ids) const;

  vtkPolyData* Fluid;
  double DL;
  double Re;
  double CoverageScale;
  vtkNew<vtkStaticPointLocator> Locator;
  vtkNew<vtkMPSKernel> Kernel;
};

}  // namespace wcmps_filters

#endif
