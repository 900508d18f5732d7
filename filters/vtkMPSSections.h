/**
 * @class   vtkMPSSections
 * @brief   velocity and pressure profiles of a wcmps frame along measuring sections
 *
 * Each section is a straight line given by a point and a direction n (normalised here),
 * pointing from the bed towards the surface; the study's sections are fixed in space and
 * normal to the bed. Along it the filter finds the water (where the fluid's coverage, see
 * vtkMPSParticlesToGrid, is at least MinimumCoverage; of several stretches the longest) and
 * samples NumberOfSamples equally spaced points from its start (the bed, the block's surface
 * or any wall) to the free surface, interpolating every floating-point array of the fluid
 * particles with vtkMPSKernel.
 *
 * Output 0 (vtkPolyData): the samples, one polyline per section, with the interpolated
 * arrays, "coverage", "section" (index), "h" (m from the start of the water), "Y" = h/H (0
 * at the bed, 1 at the surface), and the velocity in the bed-aligned frame: "u_along" along
 * t = (n_y, -n_x) (n turned clockwise by 90 degrees, downslope for the study's beds) and
 * "u_normal" along n. The field data of the frame is passed, with "SectionNames".
 *
 * Output 1 (vtkTable): a row per section: "section" (name), "x0", "y0" (start of the water),
 * "x1", "y1" (free surface), "H" (m), and the depth averages "mean_u_along",
 * "mean_u_normal", "mean_speed", "mean_pressure" (trapezoid rule over the samples, exact for
 * a linear profile). A section that meets no water has no samples, H = 0 and NaN averages.
 *
 * @sa vtkMPSSectionAverages vtkMPSParticlesToGrid
 */

#ifndef vtkMPSSections_h
#define vtkMPSSections_h

#include <string>
#include <vector>

#include "vtkPolyDataAlgorithm.h"
#include "wcmpsFiltersModule.h"  // For export macro

class vtkTable;

class WCMPSFILTERS_EXPORT vtkMPSSections : public vtkPolyDataAlgorithm {
 public:
  static vtkMPSSections* New();
  vtkTypeMacro(vtkMPSSections, vtkPolyDataAlgorithm)
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The sections: name, a point (x, y) and a direction (nx, ny) from bed to surface.
   * None added (the default): the frame's own, field data "SectionNames" and "SectionLines"
   * (x, y, nx, ny), which `wcmps run` writes from the case's [[section]]s.
   */
  void AddSection(const char* name, double x, double y, double nx, double ny);
  void RemoveAllSections();
  int GetNumberOfSections() const { return static_cast<int>(this->Names.size()); }
  ///@}

  ///@{
  /**
   * Samples per section, both ends included (default 51: Y in steps of 0.02).
   */
  vtkSetClampMacro(NumberOfSamples, int, 2, VTK_INT_MAX);
  vtkGetMacro(NumberOfSamples, int);
  ///@}

  ///@{
  /**
   * The coverage that marks the edge of the water (default 0.5, as vtkMPSParticlesToGrid).
   */
  vtkSetClampMacro(MinimumCoverage, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(MinimumCoverage, double);
  ///@}

  ///@{
  /**
   * vtkMPSKernel::SHEPARD or vtkMPSKernel::LINEAR (default LINEAR).
   */
  vtkSetClampMacro(Correction, int, 0, 1);
  vtkGetMacro(Correction, int);
  ///@}

  /**
   * The table of output 1.
   */
  vtkTable* GetSummary();

 protected:
  vtkMPSSections();
  ~vtkMPSSections() override = default;

  int FillOutputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  int NumberOfSamples;
  double MinimumCoverage;
  int Correction;
  std::vector<std::string> Names;
  std::vector<double> Lines;  // x, y, nx, ny per section

 private:
  vtkMPSSections(const vtkMPSSections&) = delete;
  void operator=(const vtkMPSSections&) = delete;
};

#endif
