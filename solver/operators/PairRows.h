#pragma once
/// @file PairRows.h
/// @brief Rows for the pair passes written for AVX-512 (physics/PredictionSumsAvx512.h,
/// physics/PressureGradientAvx512.h): what a pass reads of a neighbour, packed into one 64-byte
/// row per particle once per step, and the transposes that turn eight neighbours' rows into
/// vectors of eight values of each field.
///
/// The portable pair loops read each field of a neighbour from its own array; GCC 12 vectorises
/// them four pairs wide with an emulated gather per field (a load and a shuffle per lane) and
/// a scalar loop over each list's last pairs. Eight rows loaded whole and transposed cost 24
/// shuffles for eight fields, or 11 for three fields of a half row; the rows' memory is one
/// buffer of 64 bytes per particle that the passes of a step share (each fills it with its own
/// fields before it runs).

#include <cstdint>
#include <vector>

#if defined(__AVX512F__) && defined(__AVX512VL__) && defined(__FMA__)
// GCC 12's intrinsics start their results from _mm512_undefined_pd(), a self-initialised
// variable that -Wmaybe-uninitialized and -Wuninitialized report once inlined (GCC bug
// 105593, fixed in GCC 13).
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#pragma GCC diagnostic ignored "-Wuninitialized"
#include <immintrin.h>
#pragma GCC diagnostic pop
#define WCMPS_PAIRS_AVX512 1
#else
#define WCMPS_PAIRS_AVX512 0
#endif

namespace wcmps {

/// Eight doubles of one particle in one cache line; each pass names its own fields.
struct alignas(64) PairRow {
  double f[8];
};

using PairRows = std::vector<PairRow>;

/// The fields of the prediction's rows (physics/PredictionSumsAvx512.h), at r^n: position,
/// velocity, carried n and the shift's velocity of the last step, and the wall tangent of a
/// free-slip wall's particle (physics/WallSlip_Colagrossi2003.h; 0 for none). A boundary
/// particle's carried n is not read (its dn is i's at its depth), so its row's n holds its
/// tangent's y (kRowTangentY = kRowN). The band's rate (physics/DensityRate_Randles1996.h) reads
/// the same pairs at the same positions and velocities from them, later in the step.
enum PredictionRow {
  kRowX,
  kRowY,
  kRowU,
  kRowV,
  kRowN,
  kRowShiftU,
  kRowShiftV,
  kRowTangentX,
  kRowTangentY = kRowN
};

/// The fields of the correction's rows (physics/PressureGradientAvx512.h), at r*: position,
/// q = p/n^2, and the band's corrector A = q (L - I).
enum GradientRow {
  kRowGradX = 0,
  kRowGradY = 1,
  kRowGradQ = 2,
  kRowAxx = 4,
  kRowAxy = 5,
  kRowAyy = 6
};

#if WCMPS_PAIRS_AVX512

/// Eight ids from a list at `id`, of which the first `count` (1 to 8, more: 8) are live; the
/// spare ones read as 0, a real particle, which a pass must place out of reach.
struct EightIds {
  __m256i ids;
  __mmask8 live;
  const PairRow* row[8];

  EightIds(const std::int32_t* id, std::int64_t count, const PairRow* rows) {
    live = count >= 8 ? __mmask8(0xFF) : __mmask8((1u << static_cast<unsigned>(count)) - 1u);
    ids = _mm256_maskz_loadu_epi32(live, id);
    alignas(32) std::int32_t lane[8];
    _mm256_store_si256(reinterpret_cast<__m256i*>(lane), ids);
    for (int l = 0; l < 8; ++l) row[l] = rows + lane[l];
  }
};

/// The eight fields of eight rows: out[k] holds field k of rows 0 to 7.
inline void transpose_rows(const EightIds& e, __m512d out[8]) {
  const __m512d a0 = _mm512_load_pd(e.row[0]->f), a1 = _mm512_load_pd(e.row[1]->f);
  const __m512d a2 = _mm512_load_pd(e.row[2]->f), a3 = _mm512_load_pd(e.row[3]->f);
  const __m512d a4 = _mm512_load_pd(e.row[4]->f), a5 = _mm512_load_pd(e.row[5]->f);
  const __m512d a6 = _mm512_load_pd(e.row[6]->f), a7 = _mm512_load_pd(e.row[7]->f);
  // t0 = (f0 of rows 0 1 | f2 0 1 | f4 0 1 | f6 0 1), t1 the same of f1 f3 f5 f7, ...
  const __m512d t0 = _mm512_unpacklo_pd(a0, a1), t1 = _mm512_unpackhi_pd(a0, a1);
  const __m512d t2 = _mm512_unpacklo_pd(a2, a3), t3 = _mm512_unpackhi_pd(a2, a3);
  const __m512d t4 = _mm512_unpacklo_pd(a4, a5), t5 = _mm512_unpackhi_pd(a4, a5);
  const __m512d t6 = _mm512_unpacklo_pd(a6, a7), t7 = _mm512_unpackhi_pd(a6, a7);
  // 0x88: 128-bit lanes 0 and 2 of each source; 0xDD: lanes 1 and 3.
  const __m512d s0 = _mm512_shuffle_f64x2(t0, t2, 0x88);  // f0 of rows 0-3 | f4 of rows 0-3
  const __m512d s1 = _mm512_shuffle_f64x2(t0, t2, 0xDD);  // f2 | f6
  const __m512d s2 = _mm512_shuffle_f64x2(t1, t3, 0x88);  // f1 | f5
  const __m512d s3 = _mm512_shuffle_f64x2(t1, t3, 0xDD);  // f3 | f7
  const __m512d s4 = _mm512_shuffle_f64x2(t4, t6, 0x88);  // the same of rows 4-7
  const __m512d s5 = _mm512_shuffle_f64x2(t4, t6, 0xDD);
  const __m512d s6 = _mm512_shuffle_f64x2(t5, t7, 0x88);
  const __m512d s7 = _mm512_shuffle_f64x2(t5, t7, 0xDD);
  out[0] = _mm512_shuffle_f64x2(s0, s4, 0x88);
  out[4] = _mm512_shuffle_f64x2(s0, s4, 0xDD);
  out[2] = _mm512_shuffle_f64x2(s1, s5, 0x88);
  out[6] = _mm512_shuffle_f64x2(s1, s5, 0xDD);
  out[1] = _mm512_shuffle_f64x2(s2, s6, 0x88);
  out[5] = _mm512_shuffle_f64x2(s2, s6, 0xDD);
  out[3] = _mm512_shuffle_f64x2(s3, s7, 0x88);
  out[7] = _mm512_shuffle_f64x2(s3, s7, 0xDD);
}

/// Fields half * 4 + 0 to 3 of eight rows (one half row each: 32 bytes).
inline void transpose_half_rows(const EightIds& e, int half, __m512d out[4]) {
  const int o = 4 * half;
  const auto pair = [&](int a, int b) {
    return _mm512_insertf64x4(_mm512_castpd256_pd512(_mm256_load_pd(e.row[a]->f + o)),
                              _mm256_load_pd(e.row[b]->f + o), 1);
  };
  const __m512d z0 = pair(0, 2), z1 = pair(1, 3), z2 = pair(4, 6), z3 = pair(5, 7);
  const __m512d t0 = _mm512_unpacklo_pd(z0, z1);  // (f0 of rows 0 1, f2 of 0 1 | of rows 2 3)
  const __m512d t1 = _mm512_unpackhi_pd(z0, z1);  // (f1 of rows 0 1, f3 | ...)
  const __m512d t2 = _mm512_unpacklo_pd(z2, z3);  // the same of rows 4 to 7
  const __m512d t3 = _mm512_unpackhi_pd(z2, z3);
  out[0] = _mm512_shuffle_f64x2(t0, t2, 0x88);
  out[1] = _mm512_shuffle_f64x2(t1, t3, 0x88);
  out[2] = _mm512_shuffle_f64x2(t0, t2, 0xDD);
  out[3] = _mm512_shuffle_f64x2(t1, t3, 0xDD);
}

#endif  // WCMPS_PAIRS_AVX512

}  // namespace wcmps
