#include "MPSProbe.h"

#include "operators/WaterSpan.h"

#include <algorithm>
#include <cmath>

#include "vtkCharArray.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkIdList.h"
#include "vtkMPSKernel.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSMPThreadLocalObject.h"
#include "vtkSMPTools.h"
#include "vtkStaticPointLocator.h"

namespace wcmps_filters {

ParticleProbe::ParticleProbe(vtkPolyData* fluid, double dl, double re, int correction)
    : Fluid(fluid), DL(dl), Re(re), CoverageScale(wcmps::coverage_scale(dl, re)) {
  this->Locator->SetDataSet(fluid);
  this->Locator->BuildLocator();
  this->Kernel->SetRadius(re);
  this->Kernel->SetCorrection(correction);
  this->Kernel->Initialize(this->Locator, fluid, fluid->GetPointData());
}

ParticleProbe::~ParticleProbe() = default;

double ParticleProbe::Coverage(double x, double y, vtkIdList* ids) const {
  double p[3] = {x, y, 0.0};
  this->Locator->FindPointsWithinRadius(this->Re, p, ids);
  double s = 0.0, q[3];
  for (vtkIdType k = 0; k < ids->GetNumberOfIds(); ++k) {
    this->Fluid->GetPoint(ids->GetId(k), q);
    s += vtkMPSKernel::Weight(std::hypot(q[0] - x, q[1] - y), this->Re);
  }
  return s * this->CoverageScale;
}

ParticleProbe::Span ParticleProbe::LongestWaterSpan(const double p[2], const double d[2],
                                                    double threshold) const {
  Span best;
  if (this->Fluid->GetNumberOfPoints() == 0) return best;
  // The s range in which the line crosses the fluid's bounds grown by re (slab method).
  double b[6];
  this->Fluid->GetBounds(b);
  double smin = -VTK_DOUBLE_MAX, smax = VTK_DOUBLE_MAX;
  for (int k = 0; k < 2; ++k) {
    const double lo = b[2 * k] - this->Re, hi = b[2 * k + 1] + this->Re;
    if (std::abs(d[k]) < 1e-15) {
      if (p[k] < lo || p[k] > hi) return best;
      continue;
    }
    double s_lo = (lo - p[k]) / d[k], s_hi = (hi - p[k]) / d[k];
    if (s_lo > s_hi) std::swap(s_lo, s_hi);
    smin = std::max(smin, s_lo);
    smax = std::min(smax, s_hi);
  }
  if (smin >= smax) return best;
  vtkNew<vtkIdList> ids;
  const auto wet = [&](double s) {
    return this->Coverage(p[0] + s * d[0], p[1] + s * d[1], ids) >= threshold;
  };
  return wcmps::longest_water_span(wet, smin, smax, 0.25 * this->DL, 1e-3 * this->DL);
}

namespace {

struct ProbeWorker {
  vtkPoints* Points;
  vtkPolyData* Fluid;
  vtkStaticPointLocator* Locator;
  vtkMPSKernel* Kernel;
  double Re;
  double CoverageScale;
  double MinCoverage;
  double NullValue;
  std::vector<const double*> In;  // fluid arrays (doubles, ExtractFluid)
  std::vector<double*> Out;
  std::vector<int> Components;
  vtkDoubleArray* Coverage;
  vtkCharArray* Mask;
  vtkSMPThreadLocalObject<vtkIdList> Ids;
  vtkSMPThreadLocalObject<vtkDoubleArray> Weights;

  void Initialize() {}

  void operator()(vtkIdType begin, vtkIdType end) {
    vtkIdList* ids = this->Ids.Local();
    vtkDoubleArray* weights = this->Weights.Local();
    double x[3];
    for (vtkIdType i = begin; i < end; ++i) {
      this->Points->GetPoint(i, x);
      x[2] = 0.0;
      vtkIdType n = 0;
      double wsum = 0.0;
      if (this->Fluid->GetNumberOfPoints() > 0) {
        this->Locator->FindPointsWithinRadius(this->Re, x, ids);
        n = this->Kernel->ComputeWeights(x, ids, nullptr, weights, &wsum);
      }
      const double coverage = wsum * this->CoverageScale;
      this->Coverage->SetValue(i, coverage);
      const bool valid = n > 0 && coverage >= this->MinCoverage;
      this->Mask->SetValue(i, valid ? 1 : 0);
      const double* phi = weights->GetPointer(0);
      for (size_t a = 0; a < this->In.size(); ++a) {
        const int nc = this->Components[a];
        double* out = this->Out[a] + i * nc;
        for (int c = 0; c < nc; ++c) out[c] = valid ? 0.0 : this->NullValue;
        if (!valid) continue;
        const double* in = this->In[a];
        for (vtkIdType k = 0; k < n; ++k) {
          const double* v = in + ids->GetId(k) * nc;
          for (int c = 0; c < nc; ++c) out[c] += phi[k] * v[c];
        }
      }
    }
  }

  void Reduce() {}
};

}  // namespace

void ParticleProbe::Probe(vtkPoints* points, double minCoverage, double nullValue,
                          vtkPointData* out) const {
  const vtkIdType n = points->GetNumberOfPoints();
  ProbeWorker worker;
  worker.Points = points;
  worker.Fluid = this->Fluid;
  worker.Locator = this->Locator;
  worker.Kernel = this->Kernel;
  worker.Re = this->Re;
  worker.CoverageScale = this->CoverageScale;
  worker.MinCoverage = minCoverage;
  worker.NullValue = nullValue;
  vtkPointData* in = this->Fluid->GetPointData();
  for (int a = 0; a < in->GetNumberOfArrays(); ++a) {
    auto* src = vtkDoubleArray::SafeDownCast(in->GetArray(a));
    if (!src) continue;  // ExtractFluid makes every array a vtkDoubleArray
    // Interpolated values are weighted sums: double whatever the particles' type.
    vtkNew<vtkDoubleArray> dst;
    dst->SetName(src->GetName());
    dst->SetNumberOfComponents(src->GetNumberOfComponents());
    dst->SetNumberOfTuples(n);
    out->AddArray(dst);
    worker.In.push_back(src->GetPointer(0));
    worker.Out.push_back(dst->GetPointer(0));
    worker.Components.push_back(src->GetNumberOfComponents());
  }
  vtkNew<vtkDoubleArray> coverage;
  coverage->SetName("coverage");
  coverage->SetNumberOfTuples(n);
  out->AddArray(coverage);
  vtkNew<vtkCharArray> mask;
  mask->SetName("vtkValidPointMask");
  mask->SetNumberOfTuples(n);
  out->AddArray(mask);
  worker.Coverage = coverage;
  worker.Mask = mask;
  vtkSMPTools::For(0, n, worker);
}

}  // namespace wcmps_filters
