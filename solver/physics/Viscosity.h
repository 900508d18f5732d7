#pragma once
/// @file Viscosity.h
/// @brief Viscous accelerations of the prediction step (thesis Eq. 2.16). Each scheme gives
/// its per-pair term; viscous_acceleration() sums both in one pass over the neighbours.

#include <algorithm>
#include <cmath>
#include <cstdint>

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
  /// Pair term (u_j - u_i) W, given du = u_j - u_i and w = W(r_ij).
  static Vec2 pair(Vec2 du, double w) { return du * w; }
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
  /// Pair term, given dr = r_j - r_i, du = u_j - u_i, r^2, w = W(r) and h^2 = (re/2)^2.
  static Vec2 pair(Vec2 dr, Vec2 du, double r2, double w, double h2) {
    // u_ij . r_ij = du . dr; receding pairs (>= 0) give nothing. Written without a branch:
    // the sign of a pair is unpredictable and a mispredicted branch costs more than the term.
    const double closing = std::max(0.0, -dot(du, dr));
    return dr * (closing * w / ((r2 + 0.01 * h2) * r2));
  }
};

/// Viscous acceleration of particle i: the Laplacian viscosity (if nu > 0) and the artificial
/// viscosity (if alpha > 0), summed in one pass over the neighbours.
inline Vec2 viscous_acceleration(const MpsOperators& ops,
                                 const Viscosity_Koshizuka1996Laplacian& visc,
                                 const ArtificialViscosity_Monaghan1992& art, std::int64_t i,
                                 IdRange nb, const double* x, const double* y, const double* u,
                                 const double* v) {
  const double h2 = 0.25 * ops.re() * ops.re();
  const bool with_art = art.alpha > 0.0;
  const Kernel& kernel = ops.kernel();
  const double xi = x[i], yi = y[i], ui = u[i], vi = v[i];
  const std::int32_t* id = nb.first;
  // Pairs at r >= re add zero (W = 0). Components as scalars, so that the loop vectorises (the
  // note of MpsOperators.h).
  double lap_x = 0.0, lap_y = 0.0, q_x = 0.0, q_y = 0.0;
#pragma omp simd reduction(+ : lap_x, lap_y, q_x, q_y)
  for (std::int64_t k = 0; k < nb.size(); ++k) {
    const std::int32_t j = id[k];
    const Vec2 dr{x[j] - xi, y[j] - yi};
    const double r2 = dot(dr, dr);
    const double w = kernel(std::sqrt(r2));
    const Vec2 du{u[j] - ui, v[j] - vi};
    const Vec2 l = Viscosity_Koshizuka1996Laplacian::pair(du, w);
    lap_x += l.x;
    lap_y += l.y;
    if (with_art) {
      const Vec2 q = ArtificialViscosity_Monaghan1992::pair(dr, du, r2, w, h2);
      q_x += q.x;
      q_y += q.y;
    }
  }
  const Vec2 lap{lap_x, lap_y}, q{q_x, q_y};
  return lap * visc.scale(ops) + q * (with_art ? art.scale(ops) : 0.0);
}

}  // namespace wcmps
