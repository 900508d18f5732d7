#pragma once
/// @file PressureGradientAvx512.h
/// @brief The variational pressure gradient of Suzuki et al. (2007) with the band's correctors
/// (MpsOperators::gradient_variational and DensityRate_Randles1996::gathered_gradient) written
/// for AVX-512 on the rows of operators/PairRows.h: eight pairs per instruction, a list's last
/// 1 to 7 pairs in one more vector whose spare lanes lie 2 re away (W' = 0 there), the same
/// sums pair for pair as the portable loops, which they differ from by rounding only (the unit
/// test `PressureGradientAvx512.*` bounds it).
///
/// A row holds, for the correction's pass: r* (x, y), q = p/n^2, and the band's corrector
/// A = q (L - I) (xx, xy, yy; 0 where L = I and on boundary particles). The plain gradient reads
/// the first half row, the gathered one both.

#include <cstdint>

#include "core/Parallel.h"
#include "core/Vec2.h"
#include "neighbours/NeighbourList.h"
#include "operators/Kernel.h"
#include "operators/PairRows.h"

namespace wcmps {

/// The rows of particles [0, count): positions, q, and the correctors (null: none, all 0).
inline void pack_gradient_rows(PairRows& rows, std::int64_t count, const double* x, const double* y,
                               const double* q, const double* axx, const double* axy,
                               const double* ayy) {
  if (static_cast<std::int64_t>(rows.size()) < count) rows.resize(static_cast<std::size_t>(count));
  PairRow* r = rows.data();
  parallel_for(0, count, [=](std::int64_t j) {
    r[j] = {
        {x[j], y[j], q[j], 0.0, axx ? axx[j] : 0.0, axx ? axy[j] : 0.0, axx ? ayy[j] : 0.0, 0.0}};
  });
}

#if WCMPS_PAIRS_AVX512

/// sum_j (t_i + q_j) W'(r_ij) (r_i - r_j) / r_ij: MpsOperators::gradient_variational before
/// its scale C n0; with kCorrected, DensityRate_Randles1996::gathered_gradient: the sum of
/// ((t_i + q_j) I + A_i + A_j) W'(r_ij) (r_i - r_j) / r_ij. With kMoments, also the
/// unscaled terms of M_i, sum_j -W'(r_ij) (r_i - r_j)(r_i - r_j)^T / r_ij, in m (xx, xy, yy):
/// MpsOperators::variational_moments's, for the hydrostatic forms of the renormalisation.
template <bool kCorrected, bool kMoments = false>
Vec2 variational_gradient_avx512(const Kernel& kernel, std::int64_t i, IdRange nb,
                                 const PairRow* rows, double ti, double* m = nullptr) {
  const double* me = rows[i].f;
  const __m512d xi = _mm512_set1_pd(me[kRowGradX]), yi = _mm512_set1_pd(me[kRowGradY]);
  const __m512d v_ti = _mm512_set1_pd(ti);
  const __m512d ixx = _mm512_set1_pd(me[kRowAxx]), ixy = _mm512_set1_pd(me[kRowAxy]);
  const __m512d iyy = _mm512_set1_pd(me[kRowAyy]);
  const __m512d v_inv_re = _mm512_set1_pd(kernel.inv_re);
  const __m512d slope = _mm512_set1_pd(-3.0 * kernel.inv_re);  // W'(r) = -3 q^2 / re
  const __m512d one = _mm512_set1_pd(1.0), zero = _mm512_setzero_pd();
  const __m512d far = _mm512_set1_pd(2.0 * kernel.re);  // a spare lane's dx: W' = 0
  __m512d gx = zero, gy = zero, mxx = zero, mxy = zero, myy = zero;
  const std::int32_t* id = nb.first;
  const std::int64_t size = nb.size();
  for (std::int64_t k = 0; k < size; k += 8) {
    const EightIds e(id + k, size - k, rows);
    __m512d h[4];
    transpose_half_rows(e, 0, h);
    const __m512d dx = _mm512_mask_sub_pd(far, e.live, xi, h[kRowGradX]);  // r_i - r_j
    const __m512d dy = _mm512_maskz_sub_pd(e.live, yi, h[kRowGradY]);
    const __m512d r = _mm512_sqrt_pd(_mm512_fmadd_pd(dx, dx, _mm512_mul_pd(dy, dy)));
    const __m512d qk = _mm512_max_pd(_mm512_fnmadd_pd(r, v_inv_re, one), zero);  // ramp
    const __m512d wd = _mm512_div_pd(_mm512_mul_pd(slope, _mm512_mul_pd(qk, qk)), r);
    const __m512d s = _mm512_add_pd(v_ti, h[kRowGradQ]);  // t_i + q_j
    if constexpr (kCorrected) {
      __m512d a[4];
      transpose_half_rows(e, 1, a);
      const __m512d axx = _mm512_add_pd(_mm512_add_pd(a[kRowAxx - 4], ixx), s);
      const __m512d axy = _mm512_add_pd(a[kRowAxy - 4], ixy);
      const __m512d ayy = _mm512_add_pd(_mm512_add_pd(a[kRowAyy - 4], iyy), s);
      gx = _mm512_fmadd_pd(wd, _mm512_fmadd_pd(axx, dx, _mm512_mul_pd(axy, dy)), gx);
      gy = _mm512_fmadd_pd(wd, _mm512_fmadd_pd(axy, dx, _mm512_mul_pd(ayy, dy)), gy);
    } else {
      const __m512d f = _mm512_mul_pd(s, wd);
      gx = _mm512_fmadd_pd(f, dx, gx);
      gy = _mm512_fmadd_pd(f, dy, gy);
    }
    if constexpr (kMoments) {
      const __m512d wdx = _mm512_mul_pd(wd, dx);
      mxx = _mm512_fnmadd_pd(wdx, dx, mxx);
      mxy = _mm512_fnmadd_pd(wdx, dy, mxy);
      myy = _mm512_fnmadd_pd(_mm512_mul_pd(wd, dy), dy, myy);
    }
  }
  if constexpr (kMoments) {
    m[0] = _mm512_reduce_add_pd(mxx);
    m[1] = _mm512_reduce_add_pd(mxy);
    m[2] = _mm512_reduce_add_pd(myy);
  }
  return {_mm512_reduce_add_pd(gx), _mm512_reduce_add_pd(gy)};
}

#endif  // WCMPS_PAIRS_AVX512

}  // namespace wcmps
