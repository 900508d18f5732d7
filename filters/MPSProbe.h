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

  /// Appends the fluid points within re of (x, y): their ids and offsets x_j - x.
  void Neighbours(double x, double y, std::vector<vtkIdType>& ids, std::vector<double>& dx,
                  std::vector<double>& dy) const;

 private:
  /// Coverage at (x, y): sum_j W DL^2 / (pi re^2 / 10) (see vtkMPSParticlesToGrid).
  double Coverage(double x, double y) const;

  /// Calls f(id, dx, dy) for every fluid point j within re of (x, y), with d = x_j - x.
  template <class F>
  void ForEachNear(double x, double y, F&& f) const;

  vtkPolyData* Fluid;
  double DL;
  double Re;
  double CoverageScale;
  vtkNew<vtkMPSKernel> Kernel;
  /// The fluid's points binned in square cells of side BinSize >= re (a counting sort, built
  /// once): the points within re of any point lie in the 3 x 3 cells around it. The positions are
  /// stored bin by bin, so a search reads contiguous memory and calls nothing virtual; this
  /// replaced vtkStaticPointLocator, whose searches and GetPoint calls took half of a 2 mm grid's
  /// time (docs/filters.md, "Cost").
  double BinX0 = 0.0, BinY0 = 0.0, BinSize = 1.0;
  int BinNX = 0, BinNY = 0;
  std::vector<vtkIdType> BinStart;   ///< BinNX * BinNY + 1 offsets into the three below
  std::vector<vtkIdType> BinId;      ///< point ids, bin by bin
  std::vector<double> BinPX, BinPY;  ///< their positions
};

}  // namespace wcmps_filters

#endif
