#include "operators/LatticeConstants.h"

#include <cmath>

#include "operators/DensitySums.h"
#include "operators/Kernel.h"

namespace wcmps {

namespace {

/// kappa of LatticeConstants: rows at y_j = DL (j - eps j^2 / 2), so that the spacing
/// DL (1 - eps (j + 1/2)) shrinks upwards and the density grows along +y; G_y of the particle at
/// the origin over the central difference of the summed n/n0 of the particles one row above
/// and below.
double concentration_response(double dl, double re, double n0, double f0) {
  const Kernel w{re};
  const int k = static_cast<int>(std::ceil(re / dl)) + 2;
  const double eps = 1e-4;
  const auto row_y = [&](int j) { return dl * (j - 0.5 * eps * j * j); };
  // n of the particle (0, j0) and G_y of the particle at the origin.
  const auto n_at = [&](int j0) {
    double n = 0.0;
    for (int j = j0 - k; j <= j0 + k; ++j) {
      for (int i = -k; i <= k; ++i) {
        if (i == 0 && j == j0) continue;
        n += w(std::hypot(i * dl, row_y(j) - row_y(j0)));
      }
    }
    return n;
  };
  double g = 0.0;
  for (int j = -k; j <= k; ++j) {
    for (int i = -k; i <= k; ++i) {
      if (i == 0 && j == 0) continue;
      const double dy = -row_y(j);  // (r_i - r_j).y
      const double q = ramp(1.0 - std::hypot(i * dl, dy) * w.inv_re);
      g += -3.0 * q * q * dy / (re * re);
    }
  }
  const double dn_dy = (n_at(1) - n_at(-1)) / (n0 * (row_y(1) - row_y(-1)));
  return (g / f0) / dn_dy;
}

}  // namespace

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
      c.concentration_sum += concentration_kernel(w, r);
      const double q = 1.0 - r / re;
      c.concentration_gradient_sum += 0.5 * 3.0 * q * q * r * r / (re * re);  // -F' r / 2
    }
  }
  c.lambda = sum_wr2 / c.n0;
  c.gradient_correction = 2.0 * c.n0 / sum_dwr;  // d = 2
  c.concentration_response = concentration_response(dl, re, c.n0, c.concentration_sum);
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
