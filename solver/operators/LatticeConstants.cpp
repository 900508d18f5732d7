#include "operators/LatticeConstants.h"

#include <cmath>

#include "operators/Kernel.h"

namespace wcmps {

LatticeConstants square_lattice_constants(double dl, double re) {
  const Kernel w{re};
  const int k = static_cast<int>(std::ceil(re / dl));
  LatticeConstants c;
  double sum_wr2 = 0.0, sum_dwr = 0.0;
  for (int i = -k; i <= k; ++i) {
    for (int j = -k; j <= k; ++j) {
      if (i == 0 && j == 0) continue;
      const double r = dl * std::sqrt(static_cast<double>(i * i + j * j));
      if (r >= re) continue;
      ++c.neighbours;
      c.n0 += w(r);
      sum_wr2 += w(r) * r * r;
      sum_dwr -= w.derivative(r) * r;
    }
  }
  c.lambda = sum_wr2 / c.n0;
  c.gradient_correction = 2.0 * c.n0 / sum_dwr;  // d = 2
  return c;
}

double rectangular_lattice_number_density(double dx, double dy, double re) {
  const Kernel w{re};
  const int kx = static_cast<int>(std::ceil(re / dx));
  const int ky = static_cast<int>(std::ceil(re / dy));
  double n = 0.0;
  for (int i = -kx; i <= kx; ++i) {
    for (int j = -ky; j <= ky; ++j) {
      if (i != 0 || j != 0) n += w(std::hypot(i * dx, j * dy));
    }
  }
  return n;
}

double row_spacing_for_density_ratio(double dl, double re, double ratio) {
  const double target = ratio * rectangular_lattice_number_density(dl, dl, re);
  // n decreases monotonically with dy; bisect on [dl / (2 ratio), dl].
  double lo = 0.5 * dl / ratio, hi = dl;
  for (int k = 0; k < 60; ++k) {
    const double mid = 0.5 * (lo + hi);
    (rectangular_lattice_number_density(dl, mid, re) > target ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

}  // namespace wcmps
