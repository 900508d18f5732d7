/**
 * @class   vtkMPSSectionAverages
 * @brief   depth-averaged velocity against X/L over the block (the study's Fig. 4-9)
 *
 * X is measured from the block's upslope top corner C along its top edge towards A, and L
 * is the top length CA (X/L = 0 at C, 1 at A); both come from the frame's "BlockOutline"
 * field data (corners C, A, G), so the stations move with the block. At NumberOfStations
 * equally spaced X/L from 0 to MaximumXOverL a section through C + X (A - C)/L, in the
 * bed-normal direction, is sampled from the bed or block surface to the free surface as by
 * vtkMPSSections, and its depth averages are reported.
 *
 * The bed normal is the one of the block's face CG, which lies on the bed, turned to point
 * up (the block slides along the bed); set BedNormal to override it.
 *
 * Output (vtkTable): "X_over_L", "X" (m), then the columns of vtkMPSSections' summary
 * ("section" named by X/L, "x0", "y0", "x1", "y1", "H", "mean_u_along", "mean_u_normal",
 * "mean_speed", "mean_pressure").
 *
 * @sa vtkMPSSections
 */

#ifndef vtkMPSSectionAverages_h
#define vtkMPSSectionAverages_h

#include "vtkTableAlgorithm.h"
#include "wcmpsFiltersModule.h"  // For export macro

class WCMPSFILTERS_EXPORT vtkMPSSectionAverages : public vtkTableAlgorithm {
 public:
  static vtkMPSSectionAverages* New();
  vtkTypeMacro(vtkMPSSectionAverages, vtkTableAlgorithm)
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The last station's X/L (default 3.5, the study's range).
   */
  vtkSetClampMacro(MaximumXOverL, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(MaximumXOverL, double);
  ///@}

  ///@{
  /**
   * Stations from X/L = 0 to MaximumXOverL, both included (default 36: steps of 0.1).
   */
  vtkSetClampMacro(NumberOfStations, int, 2, VTK_INT_MAX);
  vtkGetMacro(NumberOfStations, int);
  ///@}

  ///@{
  /**
   * Direction of the sections (default (0, 0): the normal of the block's face CG).
   */
  vtkSetVector2Macro(BedNormal, double);
  vtkGetVector2Macro(BedNormal, double);
  ///@}

  ///@{
  /**
   * Samples per section (default 51), and the coverage of the water's edge (default 0.5).
   */
  vtkSetClampMacro(NumberOfSamples, int, 2, VTK_INT_MAX);
  vtkGetMacro(NumberOfSamples, int);
  vtkSetClampMacro(MinimumCoverage, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(MinimumCoverage, double);
  ///@}

 protected:
  vtkMPSSectionAverages();
  ~vtkMPSSectionAverages() override = default;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  double MaximumXOverL;
  int NumberOfStations;
  double BedNormal[2];
  int NumberOfSamples;
  double MinimumCoverage;

 private:
  vtkMPSSectionAverages(const vtkMPSSectionAverages&) = delete;
  void operator=(const vtkMPSSectionAverages&) = delete;
};

#endif
