#include "MPSProbe.h"

#include "operators/WaterSpan.h"

#include <algorithm>
#include <cmath>

#include "operators/Kernel.h"

#include "vtkCharArray.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkMPSKernel.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSMPThreadLocal.h"
#include "vtkSMPTools.h"

namespace wcmps_filters {

ParticleProbe::ParticleProbe(vtkPolyData* fluid, double dl, double re, int correction)
    : Fluid(fluid), DL(dl), Re(re), CoverageScale(wcmps::coverage_scale(dl, re)) {
  this->Kernel->SetRadius(re);
  this->Kernel->SetCorrection(correction);
  const vtkIdType n = fluid->GetNumberOfPoints();
  if (n == 0) return;
  double b[6];
  fluid->GetBounds(b);
  this->BinX0 = b[0];
  this->BinY0 = b[2];
  // Cells of side re, or larger if re is so small against the spread of the points that
  // there would be more cells than points (the 3 x 3 cells around a point still hold its
  // circle of radius re).
  this->BinSize = std::max(re, std::sqrt((b[1] - b[0]) * (b[3] - b[2]) / static_cast<double>(n)));
  const double size = this->BinSize;
  this->BinNX = static_cast<int>((b[1] - b[0]) / size) + 1;
  this->BinNY = static_cast<int>((b[3] - b[2]) / size) + 1;
  // Counting sort of the points by bin.
  std::vector<vtkIdType> bin(n);
  this->BinStart.assign(static_cast<size_t>(this->BinNX) * this->BinNY + 1, 0);
  double p[3];
  for (vtkIdType k = 0; k < n; ++k) {
    fluid->GetPoint(k, p);
    const int i = std::min(static_cast<int>((p[0] - b[0]) / size), this->BinNX - 1);
    const int j = std::min(static_cast<int>((p[1] - b[2]) / size), this->BinNY - 1);
    bin[k] = static_cast<vtkIdType>(j) * this->BinNX + i;
    ++this->BinStart[bin[k] + 1];
  }
  for (size_t c = 1; c < this->BinStart.size(); ++c) this->BinStart[c] += this->BinStart[c - 1];
  std::vector<vtkIdType> next(this->BinStart.begin(), this->BinStart.end() - 1);
  this->BinId.resize(n);
  this->BinPX.resize(n);
  this->BinPY.resize(n);
  for (vtkIdType k = 0; k < n; ++k) {
    fluid->GetPoint(k, p);
    const vtkIdType slot = next[bin[k]]++;
    this->BinId[slot] = k;
    this->BinPX[slot] = p[0];
    this->BinPY[slot] = p[1];
  }
}

ParticleProbe::~ParticleProbe() = default;

template <class F>
void ParticleProbe::ForEachNear(double x, double y, F&& f) const {
  if (this->BinStart.empty()) return;
  // Cell coordinates as doubles first: a point far outside (or NaN) must not overflow an int.
  const double cx = std::floor((x - this->BinX0) / this->BinSize);
  const double cy = std::floor((y - this->BinY0) / this->BinSize);
  if (!(cx >= -1.0 && cx <= this->BinNX && cy >= -1.0 && cy <= this->BinNY)) return;
  const int i0 = std::max(static_cast<int>(cx) - 1, 0);
  const int i1 = std::min(static_cast<int>(cx) + 1, this->BinNX - 1);
  const int j0 = std::max(static_cast<int>(cy) - 1, 0);
  const int j1 = std::min(static_cast<int>(cy) + 1, this->BinNY - 1);
  const double re2 = this->Re * this->Re;
  for (int j = j0; j <= j1; ++j) {
    // The cells i0..i1 of row j are contiguous in the sorted arrays.
    const vtkIdType row = static_cast<vtkIdType>(j) * this->BinNX;
    const vtkIdType begin = this->BinStart[row + i0], end = this->BinStart[row + i1 + 1];
    for (vtkIdType k = begin; k < end; ++k) {
      const double dx = this->BinPX[k] - x, dy = this->BinPY[k] - y;
      if (dx * dx + dy * dy <= re2) f(this->BinId[k], dx, dy);
    }
  }
}

void ParticleProbe::Neighbours(double x, double y, std::vector<vtkIdType>& ids,
                               std::vector<double>& dx, std::vector<double>& dy) const {
  this->ForEachNear(x, y, [&](vtkIdType id, double ddx, double ddy) {
    ids.push_back(id);
    dx.push_back(ddx);
    dy.push_back(ddy);
  });
}

double ParticleProbe::Coverage(double x, double y) const {
  double s = 0.0;
  const wcmps::Kernel w{this->Re};
  this->ForEachNear(x, y,
                    [&](vtkIdType, double dx, double dy) { s += w(std::sqrt(dx * dx + dy * dy)); });
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
  const auto wet = [&](double s) {
    return this->Coverage(p[0] + s * d[0], p[1] + s * d[1]) >= threshold;
  };
  return wcmps::longest_water_span(wet, smin, smax, 0.25 * this->DL, 1e-3 * this->DL);
}

namespace {

/// Per thread: the neighbours of the point being probed.
struct Near {
  std::vector<vtkIdType> ids;
  std::vector<double> dx, dy, phi;
};

struct ProbeWorker {
  vtkPoints* Points;
  const ParticleProbe* Probe;
  const vtkMPSKernel* Kernel;
  double CoverageScale;
  double MinCoverage;
  double NullValue;
  std::vector<const double*> In;  // fluid arrays (doubles, ExtractFluid)
  std::vector<double*> Out;
  std::vector<int> Components;
  vtkDoubleArray* Coverage;
  vtkCharArray* Mask;
  vtkSMPThreadLocal<Near> Scratch;

  void Initialize() {}

  void operator()(vtkIdType begin, vtkIdType end) {
    Near& near = this->Scratch.Local();
    double x[3];
    for (vtkIdType i = begin; i < end; ++i) {
      this->Points->GetPoint(i, x);
      near.ids.clear();
      near.dx.clear();
      near.dy.clear();
      this->Probe->Neighbours(x[0], x[1], near.ids, near.dx, near.dy);
      const vtkIdType count = static_cast<vtkIdType>(near.ids.size());
      near.phi.resize(near.ids.size());
      double wsum = 0.0;
      const vtkIdType n = count > 0
                              ? this->Kernel->ComputeWeights(count, near.dx.data(), near.dy.data(),
                                                             nullptr, near.phi.data(), &wsum)
                              : 0;
      const double coverage = wsum * this->CoverageScale;
      this->Coverage->SetValue(i, coverage);
      const bool valid = n > 0 && coverage >= this->MinCoverage;
      this->Mask->SetValue(i, valid ? 1 : 0);
      const double* phi = near.phi.data();
      for (size_t a = 0; a < this->In.size(); ++a) {
        const int nc = this->Components[a];
        double* out = this->Out[a] + i * nc;
        for (int c = 0; c < nc; ++c) out[c] = valid ? 0.0 : this->NullValue;
        if (!valid) continue;
        const double* in = this->In[a];
        for (vtkIdType k = 0; k < n; ++k) {
          const double* v = in + near.ids[k] * nc;
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
  worker.Probe = this;
  worker.Kernel = this->Kernel;
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
