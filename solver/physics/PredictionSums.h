#pragma once
/// @file PredictionSums.h
/// @brief The pass of the prediction over a particle's neighbours at (r^n, u^n): the viscous
/// terms (physics/Viscosity.h) and, where the number density is evolved, everything else the
/// step needs from the pairs before the pressure: the number density's rate and diffusion
/// (physics/NumberDensity_Jandaghian2020.h), the summed n and the concentration gradient G
/// (operators/DensitySums.h) that the free-surface scan and the shifting read. They read the same
/// pairs at the same positions and velocities, and each pass over the lists is bound by its
/// square root and division per pair, so they share one: the rate needs 1/r, the artificial
/// viscosity 1/((r^2 + 0.01 h^2) r^2), and both come from the one division
/// 1/((r^2 + 0.01 h^2) r^2 r); the summed n and G need no division.
///
///     lap   = sum_j (u_j - u_i) W_ij                        (Viscosity_Koshizuka1996Laplacian)
///     q     = sum_j f_ij (r_j - r_i)                       (ArtificialViscosity_Monaghan1992)
///     rate  = sum_j W'(r_ij) (r_ij . (u_ij + s_ij)) / r_ij  (Dn/Dt of the summed n, exactly)
///     lapl  = sum_{j fluid} (n_j - n_i + h . (r_i - r_j)) W_ij   (the diffusion's sum)
///     n     = sum_j W_ij                                   (the summed n, Eq. 2.4)
///     G     = (1/F0) sum_j [a_ij - b dn_ij] F'(r_ij) e_ij  (DensitySums.h)
///
/// with r_ij = r_i - r_j, u_ij = u_i - u_j, s_ij the same of the particle shifting's velocities
/// of the last step (0 without it: ParticleShifting_Sun2017.h), h = n0 g / c0^2 (Fourtakas et al.
/// 2019; 0 for Molteni & Colagrossi 2009). dn_ij = n_j - n_i is the difference of the number
/// densities the particles carry (a boundary particle carries i's, taken to its depth:
/// n0 g . (r_j - r_i) / c0^2), and b dn_ij takes the gradient of the carried n out of G: the
/// concentration gradient that the water's compression, hydrostatic or dynamic, puts into the
/// arrangement (DensitySums.h; b = 2 kappa F0 / (S_F n0), LatticeConstants). The shifting then
/// moves particles towards the arrangement their own n asks for, not down the compression: with
/// G alone it pushes still water up against its weight (the mean pressure climbs by 8 kPa in
/// 2 s), and follows an acoustic wave's compression out of phase with n (a breathing mode of the
/// flat tank grows to +-200 Pa). Pairs at r >= re add zero (W = W' = F' = 0); no branch, so the
/// loop vectorises (the note of MpsOperators.h).

#include <cmath>
#include <cstdint>

#include "core/Vec2.h"
#include "neighbours/NeighbourList.h"
#include "operators/Kernel.h"
#include "operators/MpsOperators.h"
#include "physics/Viscosity.h"
#include "physics/WallSlip_Colagrossi2003.h"

namespace wcmps {

struct PredictionSums {
  Vec2 lap;           ///< sum of the Laplacian viscosity's pair terms
  Vec2 q;             ///< sum of the artificial viscosity's pair terms
  double rate = 0.0;  ///< Dn/Dt (1/s)
  double lapl = 0.0;  ///< the diffusion's sum (-)
  double n = 0.0;     ///< the summed number density at r^n
  Vec2 gradient;      ///< G (1/m)
};

/// The number density's inputs of the pass: n^n of every particle (finite everywhere; fluid
/// ones are used), the first fluid index, h, and the constants of G (operators/DensitySums.h):
/// 1/F0, the anti-clumping R (0: none), 1/W(DL), b, and n0 g / c0^2 (boundary particles' dn).
struct DensityInputs {
  const double* n = nullptr;
  std::int64_t fluid_begin = 0;
  Vec2 hydrostatic;
  double inv_f0 = 0.0;
  double clumping_r = 0.0;
  double inv_w_dl = 0.0;
  double compression = 0.0;
  Vec2 carried;
  const double* shift_u = nullptr;  ///< the shifting's velocity of every particle (0: none)
  const double* shift_v = nullptr;
};

/// The artificial viscosity's walls (physics/WallSlip_Colagrossi2003.h): the wall tangent of every
/// particle, (0, 0) for a fluid particle. Null: no-slip walls.
struct SlipInputs {
  const double* tangent_x = nullptr;
  const double* tangent_y = nullptr;
};

/// kShift: the rate reads the shift's velocities (d.shift_u, d.shift_v); without it they are not
/// loaded at all (two gathers per pair less). kSlip: the artificial viscosity's pairs read the
/// relative velocity without its part along slip's tangent of j (WallSlip_Colagrossi2003.h).
template <bool kArtificial, bool kDensity, bool kShift = false, bool kSlip = false>
PredictionSums prediction_sums(const Kernel& kernel, std::int64_t i, IdRange nb, const double* x,
                               const double* y, const double* u, const double* v,
                               const DensityInputs& d, const SlipInputs& slip = {}) {
  // Plain doubles and a copy of the kernel in the loop: with Vec2 and the kernel by reference
  // GCC 12 leaves this loop scalar.
  const Kernel w = kernel;
  const double inv_re = w.inv_re;
  const double soft0 = 0.01 * 0.25 * w.re * w.re;  // 0.01 h^2
  const double xi = x[i], yi = y[i], ui = u[i], vi = v[i];
  const double* n = d.n;
  const double ni = kDensity ? n[i] : 0.0;
  const double hx = d.hydrostatic.x, hy = d.hydrostatic.y;
  const double clump = d.clumping_r * (d.inv_w_dl * d.inv_w_dl) * (d.inv_w_dl * d.inv_w_dl);
  const double b = d.compression;
  const double cx = d.carried.x, cy = d.carried.y;
  const std::int64_t fluid_begin = d.fluid_begin;
  const double* su = d.shift_u;
  const double* sv = d.shift_v;
  const double sui = kShift ? su[i] : 0.0, svi = kShift ? sv[i] : 0.0;
  const double* tx = slip.tangent_x;
  const double* ty = slip.tangent_y;
  const std::int32_t* id = nb.first;
  // The rate's constant factor -3/re and G's 3/(re^2 F0) are applied once, after the loop; and
  // R s^4 = R (W / W(DL))^4 = clump W^4. Fewer operations per pair: the pass is bound by them.
  double lap_x = 0.0, lap_y = 0.0, q_x = 0.0, q_y = 0.0, rate = 0.0, lapl = 0.0, n_sum = 0.0,
         g_x = 0.0, g_y = 0.0;
#pragma omp simd reduction(+ : lap_x, lap_y, q_x, q_y, rate, lapl, n_sum, g_x, g_y)
  for (std::int64_t k = 0; k < nb.size(); ++k) {
    const std::int32_t j = id[k];
    const double dx = x[j] - xi, dy = y[j] - yi;  // r_j - r_i
    const double r2 = dx * dx + dy * dy;
    const double r = std::sqrt(r2);
    const double qk = ramp(1.0 - r * inv_re);
    const double q2 = qk * qk;
    const double wij = q2 * qk;
    const double du = u[j] - ui, dv = v[j] - vi;
    // The relative velocity the rate reads: u's, and the shift's where it enters n.
    double mu = du, mv = dv;
    if constexpr (kShift) {
      mu += su[j] - sui;
      mv += sv[j] - svi;
    }
    lap_x += Viscosity_Koshizuka1996Laplacian::pair(du, wij);
    lap_y += Viscosity_Koshizuka1996Laplacian::pair(dv, wij);
    // The artificial viscosity's relative velocity: at a free-slip wall, its normal part alone.
    double au = du, av = dv;
    if constexpr (kSlip) WallSlip_Colagrossi2003::normal_part(tx[j], ty[j], au, av);
    if constexpr (kArtificial && kDensity) {
      const double soft_r2 = (r2 + soft0) * r2;
      const double inv = 1.0 / (soft_r2 * r);
      const double f =
          ArtificialViscosity_Monaghan1992::pair_factor_over(dx, dy, au, av, wij, r * inv);
      q_x += f * dx;
      q_y += f * dy;
      // W'(r)/r = (-3/re) q^2 / r, 1/r = soft r^2 inv; r_ij . u_ij = (r_j - r_i) . (u_j - u_i).
      rate += q2 * (soft_r2 * inv) * (dx * mu + dy * mv);
    } else if constexpr (kArtificial) {
      const double f = ArtificialViscosity_Monaghan1992::pair_factor_over(
          dx, dy, au, av, wij, 1.0 / ((r2 + soft0) * r2));
      q_x += f * dx;
      q_y += f * dy;
    } else if constexpr (kDensity) {
      rate += q2 / r * (dx * mu + dy * mv);
    }
    if constexpr (kDensity) {
      // Both loaded and selected, not branched on (a branch would keep the loop scalar).
      const bool fluid = j >= fluid_begin;
      const double nj = n[j];
      const double dn = fluid ? nj - ni : cx * dx + cy * dy;
      lapl += fluid ? (dn - hx * dx - hy * dy) * wij : 0.0;
      n_sum += wij;
      const double w2 = wij * wij;
      const double g = q2 * (1.0 + clump * w2 * w2 - b * dn);
      g_x += g * dx;
      g_y += g * dy;
    }
  }
  const double rate_scale = -3.0 * inv_re, g_scale = 3.0 * inv_re * inv_re * d.inv_f0;
  PredictionSums p;
  p.lap = {lap_x, lap_y};
  p.q = {q_x, q_y};
  p.rate = rate * rate_scale;
  p.lapl = lapl;
  p.n = n_sum;
  p.gradient = {g_x * g_scale, g_y * g_scale};
  return p;
}

/// Viscous acceleration of particle i: the Laplacian viscosity (if nu > 0) and the artificial
/// viscosity (if alpha > 0, at free-slip walls where slip has tangents), summed in one pass over
/// the neighbours.
inline Vec2 viscous_acceleration(const MpsOperators& ops,
                                 const Viscosity_Koshizuka1996Laplacian& visc,
                                 const ArtificialViscosity_Monaghan1992& art, std::int64_t i,
                                 IdRange nb, const double* x, const double* y, const double* u,
                                 const double* v, const SlipInputs& slip = {}) {
  if (art.alpha > 0.0) {
    const auto s =
        slip.tangent_x
            ? prediction_sums<true, false, false, true>(ops.kernel(), i, nb, x, y, u, v, {}, slip)
            : prediction_sums<true, false>(ops.kernel(), i, nb, x, y, u, v, {});
    return s.lap * visc.scale(ops) + s.q * art.scale(ops);
  }
  return prediction_sums<false, false>(ops.kernel(), i, nb, x, y, u, v, {}).lap * visc.scale(ops);
}

}  // namespace wcmps
