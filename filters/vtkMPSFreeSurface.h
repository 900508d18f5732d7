/**
 * @class   vtkMPSFreeSurface
 * @brief   the water surface eta(x) of a wcmps frame, robust to splash
 *
 * At each station x the filter takes the vertical line through x, finds the water on it as
 * the sections do (coverage at least MinimumCoverage; of several wet stretches the longest,
 * so a splash, a droplet or a thin jet above the surface is not taken for it) and reports
 * the top of that stretch as eta(x). The same algorithm (operators/WaterSpan.h) serves the
 * solver's wave gauges.
 *
 * Stations: the x of each gauge added with AddGauge, or, with none, every Spacing (default
 * 0: the frame's DL) from the leftmost fluid particle to the rightmost.
 *
 * Within re of a side of the water (a vertical wall) the coverage misses that side as well
 * and the surface reads low: by about a third of DL on the column next to the wall
 * (measured on a lattice, tests/unit/test_filters.cpp).
 *
 * Output (vtkPolyData): a point (x, eta, 0) per station that meets water, joined by
 * polylines (broken where a station meets none), with point arrays "x" and "eta" (m) and,
 * with gauges, "gauge" (the gauge's index). Field data of the frame is passed.
 */

#ifndef vtkMPSFreeSurface_h
#define vtkMPSFreeSurface_h

#include <vector>

#include "vtkPolyDataAlgorithm.h"
#include "wcmpsFiltersModule.h"  // For export macro

class WCMPSFILTERS_EXPORT vtkMPSFreeSurface : public vtkPolyDataAlgorithm {
 public:
  static vtkMPSFreeSurface* New();
  vtkTypeMacro(vtkMPSFreeSurface, vtkPolyDataAlgorithm)
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * Station spacing when no gauges are given (default 0: the frame's DL).
   */
  vtkSetClampMacro(Spacing, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(Spacing, double);
  ///@}

  ///@{
  /**
   * Wave gauges: the x positions where eta is wanted (none by default).
   */
  void AddGauge(double x);
  void RemoveAllGauges();
  int GetNumberOfGauges() const { return static_cast<int>(this->Gauges.size()); }
  ///@}

  ///@{
  /**
   * The coverage that marks the edge of the water (default 0.5, as vtkMPSParticlesToGrid).
   */
  vtkSetClampMacro(MinimumCoverage, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(MinimumCoverage, double);
  ///@}

 protected:
  vtkMPSFreeSurface();
  ~vtkMPSFreeSurface() override = default;

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  double Spacing;
  double MinimumCoverage;
  std::vector<double> Gauges;

 private:
  vtkMPSFreeSurface(const vtkMPSFreeSurface&) = delete;
  void operator=(const vtkMPSFreeSurface&) = delete;
};

#endif
