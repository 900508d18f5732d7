/**
 * @class   vtkMPSSpeedVorticity
 * @brief   speed U and vorticity omega of a wcmps frame's particles, with the MPS gradient
 *
 * Adds two point arrays to the particles:
 * - "speed" U = sqrt(u^2 + v^2) (m/s), on every particle;
 * - "vorticity" omega = dv/dx - du/dy (1/s; positive anticlockwise, x right and y up, the
 *   study's Eq. 4.1), on fluid particles; NaN on wall and ghost particles.
 *
 * The derivatives are taken with one of two gradient operators over the neighbours within re
 * (fluid, wall and ghost particles alike: walls carry their own velocity, at rest or moving
 * with the block, which makes the velocity gradient next to them the no-slip one):
 *
 * - MPS (default): Koshizuka & Oka (1996), thesis Eq. 2.5 and 4.2-4.3,
 *       <grad phi>_i = d/n0 sum_j (phi_j - phi_i) (r_j - r_i) / r_ij^2 W(r_ij),  d = 2.
 *   (The study's Eq. 4.2-4.3 print y_j - y_i under dv/dx and x_j - x_i under du/dy; Eq. 2.5,
 *   which they restate, pairs each derivative with its own coordinate, as here.) Exact for a
 *   linear field inside a regular lattice; near the free surface, where neighbours are missing
 *   on one side, it underestimates gradients (about halves them on the surface).
 * - CORRECTED: the same sum with the renormalisation matrix of Randles & Libersky (1996) in
 *   the MPS form of Khayyer & Gotoh (2011),
 *       <grad phi>_i = 1/n0 sum_j (phi_j - phi_i) C_i (r_j - r_i) / r_ij^2 W(r_ij),
 *       C_i = [1/n0 sum_j W(r_ij) (r_j - r_i)(r_j - r_i)^T / r_ij^2]^-1,
 *   exact for every linear field wherever C_i exists; where it is near singular (fewer than
 *   three neighbours, or all on a line) the particle falls back to MPS.
 *
 * re and n0 come from the frame's field data ("re", "n0") unless set.
 */

#ifndef vtkMPSSpeedVorticity_h
#define vtkMPSSpeedVorticity_h

#include "vtkPolyDataAlgorithm.h"
#include "wcmpsFiltersModule.h"  // For export macro

class WCMPSFILTERS_EXPORT vtkMPSSpeedVorticity : public vtkPolyDataAlgorithm {
 public:
  static vtkMPSSpeedVorticity* New();
  vtkTypeMacro(vtkMPSSpeedVorticity, vtkPolyDataAlgorithm)
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum GradientType { MPS = 0, CORRECTED = 1 };

  ///@{
  /**
   * The gradient operator: MPS (default) or CORRECTED.
   */
  vtkSetClampMacro(Gradient, int, MPS, CORRECTED);
  vtkGetMacro(Gradient, int);
  void SetGradientToMPS() { this->SetGradient(MPS); }
  void SetGradientToCorrected() { this->SetGradient(CORRECTED); }
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
   * Initial number density n0 (default 0: the frame's "n0").
   */
  vtkSetClampMacro(N0, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(N0, double);
  ///@}

  ///@{
  /**
   * The velocity point array (default "velocity"; its first two components are u and v).
   */
  vtkSetStringMacro(VelocityArrayName);
  vtkGetStringMacro(VelocityArrayName);
  ///@}

 protected:
  vtkMPSSpeedVorticity();
  ~vtkMPSSpeedVorticity() override;

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  int Gradient;
  double Radius;
  double N0;
  char* VelocityArrayName;

 private:
  vtkMPSSpeedVorticity(const vtkMPSSpeedVorticity&) = delete;
  void operator=(const vtkMPSSpeedVorticity&) = delete;
};

#endif
