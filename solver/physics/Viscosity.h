#pragma once
/// @file Viscosity.h
/// @brief Viscous accelerations of the prediction step (thesis Eq. 2.16). Each scheme gives
/// its per-pair term; viscous_acceleration() sums both in one pass over the neighbours.

#include <cmath>
#include <cstdint>
#include <utility>

#include "core/Vec2.h"
#include "neighbours/NeighbourList.h"
#include "operators/MpsOperators.h"

namespace wcmps {

/// nu lap(u) with the MPS Laplacian of Koshizuka & Oka (1996), Eq. 2.7:
///     a_i = nu 2d/(lambda n0) sum_j (u_j - u_i) W(r_ij).
/// Boundary particles carry zero velocity, which makes walls no-slip.
struct Viscosity_Koshizuka1996Laplacian {
  double nu;  ///< kinematic viscosity (m^2/s)

  /// Factor of the summed pair terms.
  double scale(const MpsOperators& ops) const {
    return nu * 2.0 * 2.0 / (ops.lambda() * ops.n0());  // d = 2
  }
  /// Pair term (u_j - u_i) W of one velocity component, given du = u_j - u_i and w = W(r_ij).
  static double pair(double du, double w) { return du * w; }
};

/// Artificial viscosity of Monaghan (1992, Annu. Rev. Astron. Astrophys. 30, 543-574, Eq. 4.1)
/// written in MPS form: each approaching pair (u_ij . r_ij < 0, u_ij = u_i - u_j,
/// r_ij = r_i - r_j) gets the pairwise pressure
///
///     q_ij = rho alpha c0 h (-u_ij . r_ij) / (r_ij^2 + 0.01 h^2),   h = re / 2,
///
/// which acts through the MPS gradient (Eq. 2.5):  a_i = -d/(rho n0) sum_j q_ij r_ji W / r^2.
/// Pairs are symmetric, so momentum is conserved; only approaching pairs are damped, so it
/// removes the particle-scale acoustic noise of a weakly compressible fluid with less effect on
/// shear than a viscosity would have. Not part of the study's method: alpha = 0 switches it off.
struct ArtificialViscosity_Monaghan1992 {
  double alpha;  ///< (-)
  double c0;     ///< sound speed (m/s)

  double scale(const MpsOperators& ops) const {
    return -alpha * c0 * (0.5 * ops.re()) * 2.0 / ops.n0();  // d = 2
  }
  /// Pair term = factor times dr, given dr = r_j - r_i, du = u_j - u_i, r^2, w = W(r) and
  /// h^2 = (re/2)^2.
  static double pair_factor(double dx, double dy, double du, double dv, double r2, double w,
                            double h2) {
    // u_ij . r_ij = du . dr; receding pairs (>= 0) give nothing. Written without a branch:
    // the sign of a pair is unpredictable and a mispredicted branch costs more than the term.
    const double closing = ramp(-(du * dx + dv * dy));
    return closing * w / ((r2 + 0.01 * h2) * r2);
  }
};

/// Sums over i's neighbours of the Laplacian viscosity's pair terms and, if kArtificial, of the
/// artificial viscosity's. Pairs at r >= re add zero (W = 0); no branch, so the loop vectorises
/// (the note of MpsOperators.h).
template <bool kArtificial>
std::pair<Vec2, Vec2> viscous_pair_sums(const Kernel& kernel, std::int64_t i, IdRange nb,
                                        const double* x, const double* y, const double* u,
                                        const double* v) {
  // Plain doubles and a copy of the kernel in the loop: with Vec2 and the kernel by reference
  // GCC 12 leaves this loop scalar.
  const Kernel w = kernel;
  const double h2 = 0.25 * w.re * w.re;
  const double xi = x[i], yi = y[i], ui = u[i], vi = v[i];
  const std::int32_t* id = nb.first;
  double lap_x = 0.0, lap_y = 0.0, q_x = 0.0, q_y = 0.0;
#pragma omp simd reduction(+ : lap_x, lap_y, q_x, q_y)
  for (std::int64_t k = 0; k < nb.size(); ++k) {
    const std::int32_t j = id[k];
    const double dx = x[j] - xi, dy = y[j] - yi;
    const double r2 = dx * dx + dy * dy;
    const double wij = w(std::sqrt(r2));
    const double du = u[j] - ui, dv = v[j] - vi;
    lap_x += Viscosity_Koshizuka1996Laplacian::pair(du, wij);
    lap_y += Viscosity_Koshizuka1996Laplacian::pair(dv, wij);
    if constexpr (kArtificial) {
      const double f = ArtificialViscosity_Monaghan1992::pair_factor(dx, dy, du, dv, r2, wij, h2);
      q_x += f * dx;
      q_y += f * dy;
    }
  }
  return {{lap_x, lap_y}, {q_x, q_y}};
}

/// Viscous acceleration of particle i: the Laplacian viscosity (if nu > 0) and the artificial
/// viscosity (if alpha > 0), summed in one pass over the neighbours.
inline Vec2 viscous_acceleration(const MpsOperators& ops,
                                 const Viscosity_Koshizuka1996Laplacian& visc,
                                 const ArtificialViscosity_Monaghan1992& art, std::int64_t i,
                                 IdRange nb, const double* x, const double* y, const double* u,
                                 const double* v) {
  if (art.alpha > 0.0) {
    const auto [lap, q] = viscous_pair_sums<true>(ops.kernel(), i, nb, x, y, u, v);
    return lap * visc.scale(ops) + q * art.scale(ops);
  }
  return viscous_pair_sums<false>(ops.kernel(), i, nb, x, y, u, v).first * visc.scale(ops);
}

}  // namespace wcmps
