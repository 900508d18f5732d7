#pragma once
/// @file PredictionSumsAvx512.h
/// @brief The prediction's fused pass of the default scheme (the artificial viscosity and the
/// evolved number density: `prediction_sums<true, true, kShift>` of PredictionSums.h) written for
/// AVX-512, eight pairs per instruction, with the same sums and the same operations per pair.
///
/// GCC 12 vectorises the portable loop four pairs wide (the build's preferred width) and spends
/// most of its instructions on what is not the method: an emulated gather of each of the five to
/// seven fields a pair reads (a load and a shuffle per lane), nine accumulators spilled to the
/// stack, and a scalar loop over each list's last 0 to 7 pairs, which took a third of the pass
/// (docs/performance.md, "The stabilised step's cost"). Here each neighbour's fields are one
/// 64-byte row (operators/PairRows.h, packed once per step by `pack_prediction_rows`), eight rows
/// are loaded and transposed into eight field vectors (24 shuffles for all fields), the
/// accumulators stay in registers, and a list's last 1 to 7 pairs take one more vector iteration
/// whose spare lanes are placed 2 re away (every term of such a lane is a product with W, W' or F',
/// all 0 there).
///
/// The sums are the portable loop's, pair for pair; they differ from it by rounding only (the
/// order of the additions, and where the compiler fused a multiply and an add), which the unit
/// test `PredictionSumsAvx512.*` bounds against the portable loop.

#include <cstdint>

#include "core/Parallel.h"
#include "operators/PairRows.h"
#include "physics/PredictionSums.h"

namespace wcmps {

/// The rows of particles [0, count) from their fields (shift_u, shift_v: null for none; slip:
/// the free-slip walls' tangents, or none), one pass over the particles per step: 64 bytes
/// written per particle against the pass's 64 read per pair. A boundary particle (j <
/// fluid_begin) carries its tangent in place of its n (PairRows.h).
inline void pack_prediction_rows(PairRows& rows, std::int64_t count, const double* x,
                                 const double* y, const double* u, const double* v, const double* n,
                                 const double* su, const double* sv, std::int64_t fluid_begin,
                                 const SlipInputs& slip = {}) {
  if (static_cast<std::int64_t>(rows.size()) < count) rows.resize(static_cast<std::size_t>(count));
  PairRow* r = rows.data();
  const double* tx = slip.tangent_x;
  const double* ty = slip.tangent_y;
  parallel_for(0, count, [=](std::int64_t j) {
    const bool boundary = j < fluid_begin;
    const double n_or_ty = boundary ? (ty ? ty[j] : 0.0) : n[j];
    const double t_x = boundary && tx ? tx[j] : 0.0;
    r[j] = {{x[j], y[j], u[j], v[j], n_or_ty, su ? su[j] : 0.0, sv ? sv[j] : 0.0, t_x}};
  });
}

#if WCMPS_PAIRS_AVX512

/// prediction_sums<true, true, kShift, kSlip> (PredictionSums.h) of particle i from the rows of
/// every particle (d.n, d.shift_u, d.shift_v and the walls' tangents are read from the rows).
template <bool kShift, bool kSlip = false>
PredictionSums prediction_sums_avx512(const Kernel& kernel, std::int64_t i, IdRange nb,
                                      const PairRow* rows, const DensityInputs& d) {
  const double inv_re = kernel.inv_re;
  const double soft0 = 0.01 * 0.25 * kernel.re * kernel.re;  // 0.01 h^2, as PredictionSums.h
  const double* me = rows[i].f;
  const double clump = d.clumping_r * (d.inv_w_dl * d.inv_w_dl) * (d.inv_w_dl * d.inv_w_dl);

  const __m512d xi = _mm512_set1_pd(me[kRowX]), yi = _mm512_set1_pd(me[kRowY]);
  const __m512d ui = _mm512_set1_pd(me[kRowU]), vi = _mm512_set1_pd(me[kRowV]);
  const __m512d ni = _mm512_set1_pd(me[kRowN]);
  const __m512d sui = _mm512_set1_pd(kShift ? me[kRowShiftU] : 0.0);
  const __m512d svi = _mm512_set1_pd(kShift ? me[kRowShiftV] : 0.0);
  const __m512d v_inv_re = _mm512_set1_pd(inv_re), v_soft0 = _mm512_set1_pd(soft0);
  const __m512d one = _mm512_set1_pd(1.0), zero = _mm512_setzero_pd();
  const __m512d far = _mm512_set1_pd(2.0 * kernel.re);  // a spare lane's dx: W = W' = F' = 0
  const __m512d hx = _mm512_set1_pd(d.hydrostatic.x), hy = _mm512_set1_pd(d.hydrostatic.y);
  const __m512d cx = _mm512_set1_pd(d.carried.x), cy = _mm512_set1_pd(d.carried.y);
  const __m512d v_clump = _mm512_set1_pd(clump), b = _mm512_set1_pd(d.compression);
  const __m256i fluid_begin = _mm256_set1_epi32(static_cast<std::int32_t>(d.fluid_begin));

  __m512d lap_x = zero, lap_y = zero, q_x = zero, q_y = zero, rate = zero, lapl = zero,
          n_sum = zero, g_x = zero, g_y = zero;
  const std::int32_t* id = nb.first;
  const std::int64_t size = nb.size();
  for (std::int64_t k = 0; k < size; k += 8) {
    // The spare lanes of a list's last vector read row 0 and are placed at dx = 2 re.
    const EightIds e(id + k, size - k, rows);
    __m512d f[8];
    transpose_rows(e, f);
    const __m512d xj = f[kRowX], yj = f[kRowY], uj = f[kRowU], vj = f[kRowV], nj = f[kRowN];
    const __mmask8 live = e.live;
    const __m512d dx = _mm512_mask_sub_pd(far, live, xj, xi);  // r_j - r_i
    const __m512d dy = _mm512_maskz_sub_pd(live, yj, yi);
    const __m512d r2 = _mm512_fmadd_pd(dx, dx, _mm512_mul_pd(dy, dy));
    const __m512d r = _mm512_sqrt_pd(r2);
    const __m512d qk = _mm512_max_pd(_mm512_fnmadd_pd(r, v_inv_re, one), zero);  // ramp
    const __m512d q2 = _mm512_mul_pd(qk, qk);
    const __m512d wij = _mm512_mul_pd(q2, qk);
    const __m512d du = _mm512_sub_pd(uj, ui), dv = _mm512_sub_pd(vj, vi);
    __m512d mu = du, mv = dv;
    if constexpr (kShift) {
      mu = _mm512_add_pd(mu, _mm512_sub_pd(f[kRowShiftU], sui));
      mv = _mm512_add_pd(mv, _mm512_sub_pd(f[kRowShiftV], svi));
    }
    // Viscosity_Koshizuka1996Laplacian::pair: du W.
    lap_x = _mm512_fmadd_pd(du, wij, lap_x);
    lap_y = _mm512_fmadd_pd(dv, wij, lap_y);
    const __mmask8 fluid = _mm256_cmpge_epi32_mask(e.ids, fluid_begin);
    // WallSlip_Colagrossi2003::normal_part: a boundary lane's tangent from its row (its n's
    // slot), a fluid lane's 0.
    __m512d au = du, av = dv;
    if constexpr (kSlip) {
      const __m512d tx = f[kRowTangentX];
      const __m512d ty = _mm512_maskz_mov_pd(static_cast<__mmask8>(~fluid), f[kRowTangentY]);
      const __m512d along = _mm512_fmadd_pd(du, tx, _mm512_mul_pd(dv, ty));
      au = _mm512_fnmadd_pd(along, tx, du);
      av = _mm512_fnmadd_pd(along, ty, dv);
    }
    // ArtificialViscosity_Monaghan1992::pair_factor_over with 1/((r^2 + 0.01 h^2) r^2) = r inv.
    const __m512d soft_r2 = _mm512_mul_pd(_mm512_add_pd(r2, v_soft0), r2);
    const __m512d inv = _mm512_div_pd(one, _mm512_mul_pd(soft_r2, r));
    const __m512d closing =
        _mm512_max_pd(_mm512_sub_pd(zero, _mm512_fmadd_pd(au, dx, _mm512_mul_pd(av, dy))), zero);
    const __m512d fq = _mm512_mul_pd(_mm512_mul_pd(closing, wij), _mm512_mul_pd(r, inv));
    q_x = _mm512_fmadd_pd(fq, dx, q_x);
    q_y = _mm512_fmadd_pd(fq, dy, q_y);
    // The rate: q^2 (1/r) (r_ij . (u_ij + s_ij)), its -3/re after the loop.
    const __m512d along = _mm512_fmadd_pd(dx, mu, _mm512_mul_pd(dy, mv));
    rate = _mm512_fmadd_pd(_mm512_mul_pd(q2, _mm512_mul_pd(soft_r2, inv)), along, rate);
    // The diffusion's sum over fluid neighbours; a boundary neighbour's dn is i's n at its depth.
    const __m512d dn =
        _mm512_mask_sub_pd(_mm512_fmadd_pd(cx, dx, _mm512_mul_pd(cy, dy)), fluid, nj, ni);
    const __m512d diffused = _mm512_fnmadd_pd(hy, dy, _mm512_fnmadd_pd(hx, dx, dn));
    lapl = _mm512_mask3_fmadd_pd(diffused, wij, lapl, fluid);
    n_sum = _mm512_add_pd(n_sum, wij);
    // G: q^2 (1 + R' W^4 - b dn) e_ij r, its 3/(re^2 F0) after the loop.
    const __m512d w2 = _mm512_mul_pd(wij, wij);
    const __m512d g = _mm512_mul_pd(
        q2, _mm512_fnmadd_pd(b, dn, _mm512_fmadd_pd(v_clump, _mm512_mul_pd(w2, w2), one)));
    g_x = _mm512_fmadd_pd(g, dx, g_x);
    g_y = _mm512_fmadd_pd(g, dy, g_y);
  }
  const double rate_scale = -3.0 * inv_re, g_scale = 3.0 * inv_re * inv_re * d.inv_f0;
  PredictionSums s;
  s.lap = {_mm512_reduce_add_pd(lap_x), _mm512_reduce_add_pd(lap_y)};
  s.q = {_mm512_reduce_add_pd(q_x), _mm512_reduce_add_pd(q_y)};
  s.rate = _mm512_reduce_add_pd(rate) * rate_scale;
  s.lapl = _mm512_reduce_add_pd(lapl);
  s.n = _mm512_reduce_add_pd(n_sum);
  s.gradient = {_mm512_reduce_add_pd(g_x) * g_scale, _mm512_reduce_add_pd(g_y) * g_scale};
  return s;
}

#endif  // WCMPS_PAIRS_AVX512

}  // namespace wcmps
