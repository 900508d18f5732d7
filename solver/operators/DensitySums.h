#pragma once
/// @file DensitySums.h
/// @brief The sums over a particle's neighbours that the free-surface scan and the shifting
/// need, in one pass (each pass over the lists is bound by its square root per pair):
///
///     n_i = sum_j W(r_ij)                          (Eq. 2.4, the summed density)
///     G_i = (1/F0) sum_j a_ij F'(r_ij) e_ij        (a concentration gradient)
///
/// with e_ij = (r_i - r_j) / r_ij. G is the gradient of the particles' concentration
/// C = sum_j F(r_ij) / F0 measured with the kernel F(r) = q^3 (1 - 3q/4), q = 1 - r/re (F0 its
/// lattice sum, so C = 1 on the full lattice), whose derivative F'(r) = -3 q^2 r / re^2 makes
/// F'(r) e_ij = -3 q^2 (r_i - r_j) / re^2: the gradient without a division. (That of W,
/// W'(r) e_ij = -3 q^2 (r_i - r_j) / (re r), needs 1/r, and the division cost a third of the
/// pass.) F has W's support and smoothness, and C measures what n/n0 does: where the
/// neighbourhood is thinned and towards where it is crowded. a_ij = 1, or the anti-clumping
/// weight 1 + R (W_ij / W(DL))^4 of Monaghan (2000) that particle shifting uses (Sun et al.
/// 2017). The free-surface scan takes its normal from G, the shifting its move.
///
/// Water compressed under its weight has a concentration gradient of its own: a lattice at
/// n/n0 = s has C = 1 + (k_F / k_W)(s - 1), k_F = sum(-F' r) / (2 F0) and
/// k_W = sum(-W' r) / (2 n0) = 1 / C_grad being the two kernels' response to a strain (they
/// differ on the lattice; both are 1 in the continuum), so still water, whose n/n0 = s follows
/// the equation of state with ds/dy = g/c0^2 s^(1 - gamma), has G = (k_F / k_W) s^(1 - gamma)
/// g / c0^2. Where n is evolved by continuity, the particles carry their compression in n,
/// and the shifting must act on the arrangement's departure from it only: physics/
/// PredictionSums.h takes the gradient of the carried n out of G pair by pair (b dn_ij, with
/// kappa = LatticeConstants::concentration_response; a test checks it on a hydrostatic lattice).
/// Without it, shifting pushes still water up against its own compression. Under the summed
/// density n is the arrangement itself, and nothing is taken out.
///
/// Used at r* where the number density is summed (and for wall particles); where it is evolved,
/// physics/PredictionSums.h takes the same sums at r^n in the prediction's pass. Pairs beyond
/// re add exactly zero (W = F' = 0 there), and the loop has no branch, so several pairs are
/// summed at once (the note of MpsOperators.h).

#include <cmath>
#include <cstdint>

#include "core/Vec2.h"
#include "neighbours/NeighbourList.h"
#include "operators/Kernel.h"

namespace wcmps {

struct DensitySums {
  double n = 0.0;
  Vec2 gradient;  ///< G (1/m)
};

/// F(r) = q^3 (1 - 3q/4), the kernel of the concentration C whose gradient is G.
inline double concentration_kernel(const Kernel& w, double r) {
  const double q = ramp(1.0 - r * w.inv_re);
  return q * q * q * (1.0 - 0.75 * q);
}

/// Fixed inputs of density_sums(): the kernel and the constants of G.
struct DensitySumsSetup {
  Kernel kernel;
  double inv_f0 = 0.0;      ///< 1 / F0, the lattice sum of F
  double clumping_r = 0.0;  ///< R of the anti-clumping weight (Sun et al. 2017 take 0.2)
  double inv_w_dl = 0.0;    ///< 1 / W(DL)
};

/// The sums of particle i: n always; G if kGradient (with the anti-clumping weight if
/// setup.clumping_r > 0).
template <bool kGradient>
DensitySums density_sums(const DensitySumsSetup& setup, std::int64_t i, IdRange nb, const double* x,
                         const double* y) {
  // Plain doubles: GCC 12 keeps this loop vectorised only so (see physics/PredictionSums.h).
  const double inv_re = setup.kernel.inv_re;
  const double f_scale = -3.0 * inv_re * inv_re;  // F'(r) e_ij = f_scale q^2 (r_i - r_j)
  const double r_clump = setup.clumping_r, inv_w_dl = setup.inv_w_dl;
  const double xi = x[i], yi = y[i];
  const std::int32_t* id = nb.first;
  double n = 0.0, gx = 0.0, gy = 0.0;
#pragma omp simd reduction(+ : n, gx, gy)
  for (std::int64_t k = 0; k < nb.size(); ++k) {
    const std::int32_t j = id[k];
    const double dx = xi - x[j], dy = yi - y[j];
    const double r = std::sqrt(dx * dx + dy * dy);
    const double q = ramp(1.0 - r * inv_re);
    const double w = q * q * q;
    n += w;
    if constexpr (kGradient) {
      const double s = w * inv_w_dl, s2 = s * s;
      const double f = f_scale * q * q * (1.0 + r_clump * s2 * s2);
      gx += f * dx;
      gy += f * dy;
    }
  }
  return {n, {gx * setup.inv_f0, gy * setup.inv_f0}};
}

}  // namespace wcmps
