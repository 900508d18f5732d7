/**
 * @class   vtkMPSPolylineProbe
 * @brief   particle fields of a wcmps frame sampled along a polyline (e.g. pressure from C to A)
 *
 * Samples NumberOfSamples points equally spaced in arc length along the polyline through the
 * points added with AddPoint, and interpolates every floating-point array of the fluid
 * particles there with vtkMPSKernel. With no points added, the polyline is the block's top
 * edge from C to A (the study's Fig. A-4), from the frame's "BlockOutline" field data.
 *
 * A line along a wall lies on the edge of the water, where the coverage is about 0.5 and
 * the values are the linear correction's extrapolation from the water side; so by default
 * (MinimumCoverage 0) every sample with a fluid particle within re gets a value, and only
 * samples with none get NaN.
 *
 * Output (vtkPolyData): the samples as one polyline, with the interpolated arrays,
 * "coverage", "vtkValidPointMask", "arc_length" (m from the first point) and
 * "arc_fraction" (0 to 1). Field data of the frame is passed.
 */

#ifndef vtkMPSPolylineProbe_h
#define vtkMPSPolylineProbe_h

#include <vector>

#include "vtkPolyDataAlgorithm.h"
#include "wcmpsFiltersModule.h"  // For export macro

class WCMPSFILTERS_EXPORT vtkMPSPolylineProbe : public vtkPolyDataAlgorithm {
 public:
  static vtkMPSPolylineProbe* New();
  vtkTypeMacro(vtkMPSPolylineProbe, vtkPolyDataAlgorithm)
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The polyline's points (none by default: the block's top edge C to A).
   */
  void AddPoint(double x, double y);
  void RemoveAllPoints();
  ///@}

  ///@{
  /**
   * Samples along the polyline, both ends included (default 101).
   */
  vtkSetClampMacro(NumberOfSamples, int, 2, VTK_INT_MAX);
  vtkGetMacro(NumberOfSamples, int);
  ///@}

  ///@{
  /**
   * Samples with a coverage below this get NaN (default 0: any fluid particle within re).
   */
  vtkSetClampMacro(MinimumCoverage, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(MinimumCoverage, double);
  ///@}

 protected:
  vtkMPSPolylineProbe();
  ~vtkMPSPolylineProbe() override = default;

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  int NumberOfSamples;
  double MinimumCoverage;
  std::vector<double> Points;  // x, y per point

 private:
  vtkMPSPolylineProbe(const vtkMPSPolylineProbe&) = delete;
  void operator=(const vtkMPSPolylineProbe&) = delete;
};

#endif
