#pragma once
/// @file Viscosity.h
/// @brief Viscous accelerations of the prediction step (thesis Eq. 2.16). Each scheme gives
/// its per-pair term; physics/PredictionSums.h sums them in the prediction's one pass over the
/// neighbours (viscous_acceleration()).

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
    return pair_factor_over(dx, dy, du, dv, w, 1.0 / ((r2 + 0.01 * h2) * r2));
  }
  /// The same given inv = 1 / ((r^2 + 0.01 h^2) r^2), computed by the caller (who may share its
  /// division with another term).
  static double pair_factor_over(double dx, double dy, double du, double dv, double w, double inv) {
    // u_ij . r_ij = du . dr; receding pairs (>= 0) give nothing. Written without a branch:
    // the sign of a pair is unpredictable and a mispredicted branch costs more than the term.
    const double closing = ramp(-(du * dx + dv * dy));
    return closing * w * inv;
  }
};

}  // namespace wcmps
