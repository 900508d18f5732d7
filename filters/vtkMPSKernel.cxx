#include "vtkMPSKernel.h"

#include <cmath>
#include <vector>

#include "operators/Kernel.h"
#include "vtkDataSet.h"
#include "vtkDoubleArray.h"
#include "vtkIdList.h"
#include "vtkObjectFactory.h"

vtkStandardNewMacro(vtkMPSKernel);

vtkMPSKernel::vtkMPSKernel() : Correction(LINEAR), MinimumConditioning(0.05) {
  // re = 3.5 DL at the study's DL = 0.005 m; the filters set it from each frame's "re".
  this->Radius = 0.0175;
  this->KernelFootprint = RADIUS;
  this->NormalizeWeights = true;
}

double vtkMPSKernel::Weight(double r, double re) {
  return wcmps::Kernel{re}(r);
}

vtkIdType vtkMPSKernel::ComputeWeights(double x[3], vtkIdList* pIds, vtkDoubleArray* prob,
                                       vtkDoubleArray* weights) {
  double weightSum = 0.0;
  return this->ComputeWeights(x, pIds, prob, weights, &weightSum);
}

vtkIdType vtkMPSKernel::ComputeWeights(double x[3], vtkIdList* pIds, vtkDoubleArray* prob,
                                       vtkDoubleArray* weights, double* weightSum) {
  const vtkIdType n = pIds->GetNumberOfIds();
  weights->SetNumberOfTuples(n);
  // Per thread and reused: vtkPointInterpolator calls this once per probed point, from its
  // SMP threads, and a fresh vector each call would allocate in that loop.
  thread_local std::vector<double> dx, dy;
  dx.resize(n);
  dy.resize(n);
  double xj[3];
  for (vtkIdType k = 0; k < n; ++k) {
    this->DataSet->GetPoint(pIds->GetId(k), xj);
    dx[k] = xj[0] - x[0];
    dy[k] = xj[1] - x[1];
  }
  return this->ComputeWeights(n, dx.data(), dy.data(), prob ? prob->GetPointer(0) : nullptr,
                              weights->GetPointer(0), weightSum);
}

vtkIdType vtkMPSKernel::ComputeWeights(vtkIdType n, const double* dx, const double* dy,
                                       const double* p, double* phi, double* weightSum) const {
  const wcmps::Kernel w{this->Radius};

  // First pass: the weights and their zeroth and first moments.
  double s = 0.0, raw = 0.0, mx = 0.0, my = 0.0;
  for (vtkIdType k = 0; k < n; ++k) {
    const double wk = w(std::sqrt(dx[k] * dx[k] + dy[k] * dy[k]));
    raw += wk;
    phi[k] = p ? wk * p[k] : wk;
    s += phi[k];
    mx += phi[k] * dx[k];
    my += phi[k] * dy[k];
  }
  *weightSum = raw;
  if (s <= 0.0) {
    return 0;
  }

  bool linear = this->Correction == LINEAR && n >= 3;
  double cxx = 0.0, cxy = 0.0, cyy = 0.0;
  const double bx = mx / s, by = my / s;
  if (linear) {
    for (vtkIdType k = 0; k < n; ++k) {
      const double ex = dx[k] - bx, ey = dy[k] - by;
      cxx += phi[k] * ex * ex;
      cxy += phi[k] * ex * ey;
      cyy += phi[k] * ey * ey;
    }
    cxx /= s;
    cxy /= s;
    cyy /= s;
    // Eigenvalues of the symmetric 2x2 C.
    const double mean = 0.5 * (cxx + cyy);
    const double dev = std::sqrt(0.25 * (cxx - cyy) * (cxx - cyy) + cxy * cxy);
    const double lmax = mean + dev, lmin = mean - dev;
    linear = lmax > 0.0 && lmin >= this->MinimumConditioning * lmax;
  }

  if (linear) {
    // g = C^-1 dbar, then phi_j = W_j / S (1 - g . (d_j - dbar)).
    const double det = cxx * cyy - cxy * cxy;
    const double gx = (cyy * bx - cxy * by) / det;
    const double gy = (cxx * by - cxy * bx) / det;
    for (vtkIdType k = 0; k < n; ++k) {
      const double ex = dx[k] - bx, ey = dy[k] - by;
      phi[k] = phi[k] / s * (1.0 - gx * ex - gy * ey);
    }
  } else if (this->NormalizeWeights) {
    for (vtkIdType k = 0; k < n; ++k) {
      phi[k] /= s;
    }
  }
  return n;
}

void vtkMPSKernel::PrintSelf(ostream& os, vtkIndent indent) {
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Correction: " << (this->Correction == LINEAR ? "Linear" : "Shepard") << "\n";
  os << indent << "MinimumConditioning: " << this->MinimumConditioning << "\n";
}
