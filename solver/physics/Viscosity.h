#pragma once
/// @file Viscosity.h
/// @brief Viscous acceleration of the prediction step (thesis Eq. 2.16): nu lap(u) with the MPS
/// Laplacian of Koshizuka & Oka (1996), Eq. 2.7. Boundary particles carry zero velocity, which
/// makes walls no-slip.

#include <cstdint>

#include "core/Vec2.h"
#include "operators/MpsOperators.h"

namespace wcmps {

struct Viscosity_Koshizuka1996Laplacian {
  double nu;  ///< kinematic viscosity (m^2/s)

  Vec2 acceleration(const MpsOperators& ops, std::int64_t i, IdRange nb, const double* x,
                    const double* y, const double* u, const double* v) const {
    return nu * ops.laplacian(i, nb, x, y, u, v);
  }
};

}  // namespace wcmps

namespace wcmps {

/// Artificial viscosity of Monaghan (1992, Annu. Rev. Astron. Astrophys. 30, 543-574, Eq. 4.1)
/// written in MPS form: each approaching pair (u_ij . r_ij < 0, u_ij = u_i - u_j,
/// r_ij = r_i - r_j) gets the pairwise pressure
///
///     q_ij = rho alpha c0 h (-u_ij . r_ij) / (r_ij^2 + 0.01 h^2),   h = re / 2,
///
/// which acts through the MPS gradient (Eq. 2.5):  a_i = -d/(rho n0) sum_j q_ij r_ji W / r^2.
/// Pairs are symmetric, so momentum is conserved; only approaching pairs are damped, so it
/// removes the particle-scale acoustic noise of a weakly compressible fluid with little effect
/// on shear. Not part of the study's method: alpha = 0 switches it off.
struct ArtificialViscosity_Monaghan1992 {
  double alpha;  ///< (-)
  double c0;     ///< sound speed (m/s)

  Vec2 acceleration(const MpsOperators& ops, std::int64_t i, IdRange nb, const double* x,
                    const double* y, const double* u, const double* v) const {
    const double re = ops.re();
    const double h = 0.5 * re;
    const double eps = 0.01 * h * h;
    double ax = 0.0, ay = 0.0;
    for (const std::int32_t j : nb) {
      const double dx = x[j] - x[i], dy = y[j] - y[i];  // r_ji
      const double r2 = dx * dx + dy * dy;
      if (r2 >= re * re) continue;
      // u_ij . r_ij = (u_i - u_j) . (r_i - r_j) = (u_j - u_i) . (r_j - r_i)
      const double approach = (u[j] - u[i]) * dx + (v[j] - v[i]) * dy;
      if (approach >= 0.0) continue;
      const double q = -approach / (r2 + eps);  // q_ij / (rho alpha c0 h)
      const double f = q * ops.kernel()(std::sqrt(r2)) / r2;
      ax += f * dx;
      ay += f * dy;
    }
    const double c = -alpha * c0 * h * 2.0 / ops.n0();  // d = 2
    return {c * ax, c * ay};
  }
};

}  // namespace wcmps
