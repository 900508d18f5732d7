/**
 * @class   vtkMPSKernel
 * @brief   the MPS weight function as a VTK interpolation kernel, with a linear correction
 *
 * The weight is the one the solver uses (thesis Eq. 2.3; Shakibaeinia & Jin 2012):
 *
 *     W(r) = (1 - r/re)^3  for r < re,  0 otherwise,   re = Radius.
 *
 * Two ways of turning the weights W_j of the particles within re into interpolation weights:
 *
 * - SHEPARD: phi_j = W_j / sum W (normalised; when NormalizeWeights is off, W_j as they are).
 *   Reproduces a constant exactly, a linear field only where the neighbours are symmetric.
 * - LINEAR (default): moving least squares with a linear basis and the weights W (Lancaster &
 *   Salkauskas 1981), written about the weighted centroid dbar of the offsets d_j = x_j - x:
 *
 *       phi_j = W_j / S [1 - dbar^T C^-1 (d_j - dbar)],   S = sum W_j,
 *       C = sum W_j (d_j - dbar)(d_j - dbar)^T / S.
 *
 *   The phi_j sum to 1 and reproduce every linear field exactly. Where C is near singular
 *   (its smaller eigenvalue below MinimumConditioning times the larger: neighbours on a line,
 *   or one or two particles) the kernel falls back to SHEPARD for that point.
 *
 * Works in the x-y plane (the z coordinates are ignored): the solver is 2D.
 *
 * The kernel can be given to vtkPointInterpolator like any vtkGeneralizedKernel; the wcmps
 * filters call it directly so that one neighbour search yields the weights and the coverage.
 *
 * @sa vtkMPSParticlesToGrid vtkPointInterpolator vtkShepardKernel
 */

#ifndef vtkMPSKernel_h
#define vtkMPSKernel_h

#include "vtkGeneralizedKernel.h"
#include "wcmpsFiltersModule.h"  // For export macro

class vtkDoubleArray;
class vtkIdList;

class WCMPSFILTERS_EXPORT vtkMPSKernel : public vtkGeneralizedKernel {
 public:
  static vtkMPSKernel* New();
  vtkTypeMacro(vtkMPSKernel, vtkGeneralizedKernel)
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum CorrectionType { SHEPARD = 0, LINEAR = 1 };

  ///@{
  /**
   * How weights become interpolation weights: SHEPARD or LINEAR (default LINEAR).
   */
  vtkSetClampMacro(Correction, int, SHEPARD, LINEAR);
  vtkGetMacro(Correction, int);
  void SetCorrectionToShepard() { this->SetCorrection(SHEPARD); }
  void SetCorrectionToLinear() { this->SetCorrection(LINEAR); }
  ///@}

  ///@{
  /**
   * Smallest ratio of the eigenvalues of C for which LINEAR is used (default 0.05). An
   * interior point of a lattice has 1, a point on a flat free surface about 0.3; a point
   * whose neighbours lie nearly on a line has almost 0, where the linear fit is undetermined.
   */
  vtkSetClampMacro(MinimumConditioning, double, 0.0, 1.0);
  vtkGetMacro(MinimumConditioning, double);
  ///@}

  // Re-use any superclass signatures that we don't override.
  using vtkGeneralizedKernel::ComputeWeights;

  /**
   * The interpolation weights at x of the points pIds (from ComputeBasis). prob, if given,
   * multiplies each W_j. Returns the number of weights, 0 where no point has W > 0.
   */
  vtkIdType ComputeWeights(double x[3], vtkIdList* pIds, vtkDoubleArray* prob,
                           vtkDoubleArray* weights) override;

  /**
   * Same, and sets weightSum to sum W_j (before any normalisation, without prob): the
   * number density of the points at x.
   */
  vtkIdType ComputeWeights(double x[3], vtkIdList* pIds, vtkDoubleArray* prob,
                           vtkDoubleArray* weights, double* weightSum);

  /**
   * Same, from the offsets d_j = x_j - x of n points (dx, dy) instead of their ids: the
   * weights go to phi (n values). The one implementation; the overloads above gather the
   * offsets and call it. Thread-safe (reads only the settings).
   */
  vtkIdType ComputeWeights(vtkIdType n, const double* dx, const double* dy, const double* prob,
                           double* phi, double* weightSum) const;

  /**
   * W(r) for kernel radius re.
   */
  static double Weight(double r, double re);

 protected:
  vtkMPSKernel();
  ~vtkMPSKernel() override = default;

  int Correction;
  double MinimumConditioning;

 private:
  vtkMPSKernel(const vtkMPSKernel&) = delete;
  void operator=(const vtkMPSKernel&) = delete;
};

#endif
