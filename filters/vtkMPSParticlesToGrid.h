/**
 * @class   vtkMPSParticlesToGrid
 * @brief   interpolate the fluid particles of a wcmps frame onto a regular grid
 *
 * The input is a particle frame (vtkPolyData, one point per particle, as `wcmps run` writes
 * it). Only fluid particles (point array "kind" = 0; every point if there is no "kind")
 * contribute. At every grid point x the filter finds the fluid particles within re and
 * interpolates each requested point array with vtkMPSKernel (MPS weight, linear correction
 * by default).
 *
 * Output point arrays, besides the interpolated ones:
 * - "coverage": sum_j W(|x - x_j|) DL^2 / (pi re^2 / 10), the fluid's number density at x
 *   over its mean value in the bulk: about 1 inside the water, 0.5 on its edge (a free
 *   surface, or a wall: walls are not fluid), 0 far from any particle.
 * - "vtkValidPointMask" (char, VTK's name for it): 1 where coverage >= MinimumCoverage,
 *   0 elsewhere. Where it is 0 every interpolated array holds NullValue.
 *
 * The grid spans SamplingBounds with spacing Spacing (z is one layer at 0). With the
 * defaults it is computed from each frame: spacing DL (field data "DL"), bounds those of the
 * fluid particles grown by DL/2 (the edge of the water), so the grid of a frame depends on
 * the frame. Set both to fix one grid for a whole series.
 *
 * Field data of the frame (DL, re, TimeValue, BlockOutline, ...) is passed to the output.
 *
 * @sa vtkMPSKernel vtkPointInterpolator
 */

#ifndef vtkMPSParticlesToGrid_h
#define vtkMPSParticlesToGrid_h

#include <string>
#include <vector>

#include "vtkImageAlgorithm.h"
#include "wcmpsFiltersModule.h"  // For export macro

class WCMPSFILTERS_EXPORT vtkMPSParticlesToGrid : public vtkImageAlgorithm {
 public:
  static vtkMPSParticlesToGrid* New();
  vtkTypeMacro(vtkMPSParticlesToGrid, vtkImageAlgorithm)
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * Grid spacing in metres (default 0: the frame's DL).
   */
  vtkSetClampMacro(Spacing, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(Spacing, double);
  ///@}

  ///@{
  /**
   * Grid bounds (xmin, xmax, ymin, ymax, zmin, zmax), z ignored. Default (1, -1, 1, -1, 0,
   * 0), an empty box, which means: the fluid's bounds grown by DL/2, per frame.
   */
  vtkSetVector6Macro(SamplingBounds, double);
  vtkGetVector6Macro(SamplingBounds, double);
  ///@}

  ///@{
  /**
   * Kernel radius re in metres (default 0: the frame's "re").
   */
  vtkSetClampMacro(Radius, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(Radius, double);
  ///@}

  ///@{
  /**
   * vtkMPSKernel::SHEPARD or vtkMPSKernel::LINEAR (default LINEAR).
   */
  vtkSetClampMacro(Correction, int, 0, 1);
  vtkGetMacro(Correction, int);
  ///@}

  ///@{
  /**
   * Grid points with a coverage below this are masked (default 0.5: the edge of the water,
   * where the number density of a half-plane of particles is half its bulk value).
   */
  vtkSetClampMacro(MinimumCoverage, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(MinimumCoverage, double);
  ///@}

  ///@{
  /**
   * The value of every interpolated array at a masked point (default NaN, which VTK's colour
   * maps and ParaView show in their "NaN colour").
   */
  vtkSetMacro(NullValue, double);
  vtkGetMacro(NullValue, double);
  ///@}

  ///@{
  /**
   * The point arrays to interpolate. None named (the default): every floating-point point
   * array of the frame (velocity, pressure, number_density, and speed and vorticity after
   * vtkMPSSpeedVorticity); integer arrays (kind, id, free_surface) are labels, not fields.
   */
  void AddArrayName(const char* name);
  void ClearArrayNames();
  int GetNumberOfArrayNames() const { return static_cast<int>(this->ArrayNames.size()); }
  ///@}

 protected:
  vtkMPSParticlesToGrid();
  ~vtkMPSParticlesToGrid() override = default;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestUpdateExtent(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  double Spacing;
  double SamplingBounds[6];
  double Radius;
  int Correction;
  double MinimumCoverage;
  double NullValue;
  std::vector<std::string> ArrayNames;

 private:
  vtkMPSParticlesToGrid(const vtkMPSParticlesToGrid&) = delete;
  void operator=(const vtkMPSParticlesToGrid&) = delete;
};

#endif
