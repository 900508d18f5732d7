#pragma once
/// @file DensityRate_Randles1996.h
/// @brief The evolved number density's rate and its partner, the variational pressure
/// gradient, with the kernel gradient renormalised by the kernel's moment matrix in the
/// free-surface band ([physics] density_rate).
///
/// - "summed" (physics/NumberDensity_Jandaghian2020.h): Dn_i/Dt = sum_j W'(r_ij) (r_ij . u_ij) /
///   r_ij, exactly d/dt of the summed n. With the pair sums (x = r_j - r_i, u = u_j - u_i)
///
///       B_ab = sum_j c_ij x_a u_b,   P_ab = sum_j (-c_ij) x_a x_b,   c_ij = W'(r_ij) / r_ij,
///
///   it is trace(B). For a velocity field u = A r linear over the kernel, B = -P A^T, and the
///   rate is -trace(P A^T): the divergence trace(A) times -m (m = n0 / C, the lattice's P_xx,
///   LatticeConstants) only where P = m I, a complete kernel on the lattice. Where the free
///   surface cuts the kernel, P is not isotropic: on the lattice's top row P_xx = 0.715 m along
///   the surface and P_yy = 0.500 m across it (the second row 0.948 and 0.759). Where the water
///   converges along the surface and stretches across it without changing its volume (the
///   trough drawn down upslope of the sliding block, a wave's surface) the rate weighs the
///   convergence over the stretching, and the rows within re of the surface are compressed: in
///   case I the rows 1 to 2.5 cm under the trough held one and a half to three times their
///   hydrostatic pressure, pushed the top row off the water and opened the cavity
///   (docs/validation.md, "The rows under the surface compressed by a cut kernel").
/// - "randles1996": in the free-surface band (the surface particles and the fluid within re of
///   one, Simulation::find_surface_band) the kernel gradient corrected by the moment matrix,
///   W'(r_ij) e_ij -> L_i W'(r_ij) e_ij with L_i = m P_c^-1 (the normalisation of Randles &
///   Libersky 1996, Comput. Methods Appl. Mech. Engrg. 139, 375-408; the correction of Bonet &
///   Lok 1999, Comput. Methods Appl. Mech. Engrg. 180, 97-115), P_c being P with its eigenvalues
///   held to at least m / 2 (no direction's weight more than doubled: a single row or a drop has
///   no divergence across it to recover), in both equations:
///
///       Dn_i/Dt = trace(L_i B_i)   (m div u for a linear field whatever the support),
///       <grad p>_i = C n0 sum_j (q_i L_i + q_j L_j) W'(r_ij) e_ij,   q = p / n^2,
///
///   L = I everywhere else. The variational gradient and the summed rate are partners: the
///   power of the pair forces, sum_i u_i . <grad p>_i, is C n0 sum_i q_i Dn_i/Dt, so the pressure
///   does no work that the number densities do not store. The corrected pair keeps that identity
///   (a unit test checks it); a corrected rate alone does not: with the force left as it was (the
///   first form of this option, the rate limited by minmod) the flat tank's still water moved
///   twice as much and its breathing mode grew (docs/validation.md, "The band's rate
///   renormalised"). The pair forces stay antisymmetric (momentum is conserved), not central.
///   Inside the water P = m I: L = I and nothing changes. Where the summed rate reads a
///   compression the divergence does not have (the trough), the corrected rate reads none.
///
///   Where a boundary particle is within re, the force keeps L (P counting the wall's rows) and
///   the rate stays summed. The force's correction is a stress, A = q (L - I) on each band
///   particle, that pushes nothing where it is uniform and pushes where it ends. Ended a
///   kernel's width from a wall (L = I there in force and rate: the first form of this rule),
///   its edge pushed the band's water alone, which nothing held, and the still tank's surface
///   ran in a steady current towards both walls (docs/validation.md, "The wall's share of the
///   band's stress"); kept up to the wall and carried by the pairs with boundary particles (A_i
///   in every pair of i, the boundary particles' own A being zero), the edge presses on the
///   wall, which holds it. The rate there stays summed: over a bed or a block the band is a
///   thin layer sliding along it, and with its rate corrected too (the wall's pairs plain,
///   central, or left out of P) the layer under case I's trough opened more (the short run's
///   largest cavity 0.16-0.19 against 0.05 cm2). So near a boundary the pressure's work is not
///   what the number densities store (above); the acoustic and standing-wave benchmarks measure
///   what that costs.
///
///   L = I (the summed rate and the plain force) where the particle is struck. The correction is
///   for a cut kernel in water that deforms gently; where a sheet or a drop lands on water the
///   kernel sees the impact from one side and L would double it (without the rule below the
///   Lobovsky dam break stopped at t = 1.05 s with n > 1.2 n0 where its plunging jet falls back).
///   Struck means any of: n rising faster than sqrt(g / DL) n0 per second over the step's
///   prediction (the rule of the surface pressure cap, physics/SurfacePressureCap.h: neighbours
///   closing in faster than a fall through one spacing), the summed or the corrected rate faster
///   than that, or n already above n0 (1 + kSqueeze). A band particle under nothing but gravity is
///   compressed by rho g d / (rho c0^2), d <= re + DL: 2-4e-4 in the cases here (c0 = 26-35 m/s).
///   kSqueeze = 3e-3 is not derived; it sits between that and what an impact leaves behind it:
///   with 6.3e-3 (sqrt(g DL) / c0) and 1e-2 the Lobovsky run at Courant 0.39 stopped at 1.11
///   and 1.25 s (docs/validation.md, "The band's rate renormalised"). Below c0 of about 9 m/s
///   gravity alone would compress the band past it, and the correction would stay off. The sums
///   read u alone: under shifting_in_continuity the shift's share of the rate stays as summed.

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "core/SchemeTable.h"
#include "core/Vec2.h"
#include "neighbours/NeighbourList.h"
#include "operators/Kernel.h"
#include "operators/PairRows.h"

namespace wcmps {

enum class DensityRateScheme { Summed, Randles1996 };

inline constexpr SchemeEntry<DensityRateScheme> kDensityRateSchemes[] = {
    {"summed", DensityRateScheme::Summed,
     "d/dt of the summed n (Jandaghian & Shakibaeinia 2020, Comput. Methods Appl. Mech. Engrg. "
     "360, 112771)"},
    {"randles1996", DensityRateScheme::Randles1996,
     "the kernel gradient normalised by the kernel's moments (Randles & Libersky 1996, Comput. "
     "Methods Appl. Mech. Engrg. 139, 375-408) in the surface band, in the rate and the pressure "
     "gradient together (Bonet & Lok 1999)"},
};

struct DensityRate_Randles1996 {
  /// The floor of P's eigenvalues, as a share of m: a particle that has lost every neighbour on
  /// one side of a line through it has 0.5 (the half kernel).
  static constexpr double kMinEigenvalue = 0.5;
  /// n above n0 (1 + kSqueeze): a band particle compressed by more than gravity does (above).
  static constexpr double kSqueeze = 3e-3;

  /// The pair sums of particle i over its neighbours within re (at r^n, u^n).
  struct Sums {
    double bxu = 0.0, bxv = 0.0, byu = 0.0, byv = 0.0;  ///< B (1/s, unscaled)
    double pxx = 0.0, pxy = 0.0, pyy = 0.0;             ///< P (-)
    bool boundary = false;  ///< a particle before fluid_begin within re: the rate stays summed
    double summed() const { return bxu + byv; }
  };

  /// L (symmetric); the identity where the particle is left alone.
  struct Corrector {
    double xx = 1.0, xy = 0.0, yy = 1.0;
    bool identity() const { return xx == 1.0 && xy == 0.0 && yy == 1.0; }
  };

  /// The state of band particle i at the step: its n^n, the n the prediction's pass gave it
  /// (the summed rate and the diffusion over dt), and dt.
  struct Step {
    double n_before = 0.0, n_predicted = 0.0, dt = 0.0;
  };

  double m = 0.0;            ///< n0 / C: P_xx of a complete kernel on the lattice
  double n0 = 0.0;           ///< the lattice's number density
  double struck_rate = 0.0;  ///< sqrt(g / DL) (1/s): n rising faster than this times n0 is struck

  static Sums sums(const Kernel& w, std::int64_t i, IdRange nb, const double* x, const double* y,
                   const double* u, const double* v, std::int64_t fluid_begin) {
    // Without a branch, so that the loop vectorises (the note of MpsOperators.h): pairs at
    // r >= re have W' = 0, and a particle on top of i (r = 0: no direction) adds zero to every
    // sum, each being c times dx or dy. Its c is kept finite by dividing by 1 instead of r, not
    // selected: with the division inside the select GCC 12 put the loads of u and v under its
    // mask, which it cannot vectorise ("unsupported masked emulated gather"), and the loop ran
    // scalar.
    const Kernel k = w;
    const double re2 = k.re * k.re;
    const double xi = x[i], yi = y[i], ui = u[i], vi = v[i];
    const std::int32_t* id = nb.first;
    double bxu = 0.0, bxv = 0.0, byu = 0.0, byv = 0.0, pxx = 0.0, pxy = 0.0, pyy = 0.0;
    double boundary = 0.0;  // the count of boundary pairs (a double: GCC 12 keeps an int's scalar)
#pragma omp simd reduction(+ : bxu, bxv, byu, byv, pxx, pxy, pyy, boundary)
    for (std::int64_t m = 0; m < nb.size(); ++m) {
      const std::int32_t j = id[m];
      const double dx = x[j] - xi, dy = y[j] - yi;
      const double r2 = dx * dx + dy * dy;
      const double r = std::sqrt(r2);
      const bool paired = r2 > 0.0;
      const double c = k.derivative(r) / (paired ? r : 1.0);
      const double du = u[j] - ui, dv = v[j] - vi;
      boundary += (paired && r2 < re2 && j < fluid_begin) ? 1.0 : 0.0;
      bxu += c * dx * du;
      bxv += c * dx * dv;
      byu += c * dy * du;
      byv += c * dy * dv;
      pxx -= c * dx * dx;
      pxy -= c * dx * dy;
      pyy -= c * dy * dy;
    }
    Sums s;
    s.bxu = bxu;
    s.bxv = bxv;
    s.byu = byu;
    s.byv = byv;
    s.pxx = pxx;
    s.pxy = pxy;
    s.pyy = pyy;
    s.boundary = boundary > 0.0;
    return s;
  }

#if WCMPS_PAIRS_AVX512
  /// sums() from the prediction's rows of this step (operators/PairRows.h, the same r^n and u^n),
  /// eight pairs per instruction; a list's last 1 to 7 pairs in one more vector whose spare
  /// lanes lie 2 re away (W' = 0, and out of the boundary count). The same terms as sums(), which
  /// it differs from by rounding only (the unit test `DensityRateAvx512.*`).
  static Sums sums_avx512(const Kernel& k, std::int64_t i, IdRange nb, const PairRow* rows,
                          std::int64_t fluid_begin) {
    const double* me = rows[i].f;
    const __m512d xi = _mm512_set1_pd(me[kRowX]), yi = _mm512_set1_pd(me[kRowY]);
    const __m512d ui = _mm512_set1_pd(me[kRowU]), vi = _mm512_set1_pd(me[kRowV]);
    const __m512d v_inv_re = _mm512_set1_pd(k.inv_re), re2 = _mm512_set1_pd(k.re * k.re);
    const __m512d slope = _mm512_set1_pd(-3.0 * k.inv_re);  // W'(r) = -3 q^2 / re
    const __m512d one = _mm512_set1_pd(1.0), zero = _mm512_setzero_pd();
    const __m512d far = _mm512_set1_pd(2.0 * k.re);
    const __m256i first_fluid = _mm256_set1_epi32(static_cast<std::int32_t>(fluid_begin));
    __m512d bxu = zero, bxv = zero, byu = zero, byv = zero, pxx = zero, pxy = zero, pyy = zero;
    bool boundary = false;
    const std::int32_t* id = nb.first;
    const std::int64_t size = nb.size();
    for (std::int64_t m = 0; m < size; m += 8) {
      const EightIds e(id + m, size - m, rows);
      __m512d h[4];
      transpose_half_rows(e, 0, h);
      const __m512d dx = _mm512_mask_sub_pd(far, e.live, h[kRowX], xi);  // r_j - r_i
      const __m512d dy = _mm512_maskz_sub_pd(e.live, h[kRowY], yi);
      const __m512d r2 = _mm512_fmadd_pd(dx, dx, _mm512_mul_pd(dy, dy));
      const __m512d r = _mm512_sqrt_pd(r2);
      const __mmask8 paired = _mm512_cmp_pd_mask(r2, zero, _CMP_GT_OQ);
      const __m512d qk = _mm512_max_pd(_mm512_fnmadd_pd(r, v_inv_re, one), zero);  // ramp
      const __m512d c = _mm512_div_pd(_mm512_mul_pd(slope, _mm512_mul_pd(qk, qk)),
                                      _mm512_mask_mov_pd(one, paired, r));
      const __m512d du = _mm512_sub_pd(h[kRowU], ui), dv = _mm512_sub_pd(h[kRowV], vi);
      const __mmask8 wall = _mm256_cmplt_epi32_mask(e.ids, first_fluid);
      boundary |= (paired & wall & _mm512_cmp_pd_mask(r2, re2, _CMP_LT_OQ)) != 0;
      const __m512d cx = _mm512_mul_pd(c, dx), cy = _mm512_mul_pd(c, dy);
      bxu = _mm512_fmadd_pd(cx, du, bxu);
      bxv = _mm512_fmadd_pd(cx, dv, bxv);
      byu = _mm512_fmadd_pd(cy, du, byu);
      byv = _mm512_fmadd_pd(cy, dv, byv);
      pxx = _mm512_fnmadd_pd(cx, dx, pxx);
      pxy = _mm512_fnmadd_pd(cx, dy, pxy);
      pyy = _mm512_fnmadd_pd(cy, dy, pyy);
    }
    Sums s;
    s.bxu = _mm512_reduce_add_pd(bxu);
    s.bxv = _mm512_reduce_add_pd(bxv);
    s.byu = _mm512_reduce_add_pd(byu);
    s.byv = _mm512_reduce_add_pd(byv);
    s.pxx = _mm512_reduce_add_pd(pxx);
    s.pxy = _mm512_reduce_add_pd(pxy);
    s.pyy = _mm512_reduce_add_pd(pyy);
    s.boundary = boundary;
    return s;
  }
#endif

  /// trace(L B): the rate under the corrector L.
  static double rate(const Sums& s, const Corrector& l) {
    return l.xx * s.bxu + l.xy * (s.byu + s.bxv) + l.yy * s.byv;
  }

  /// m P_c^-1, P_c: P with its eigenvalues held to at least kMinEigenvalue m.
  Corrector renormalisation(const Sums& s) const {
    // P's eigenvalues mean +- rad; its spectral projectors E1 = (P - (mean - rad) I) / (2 rad)
    // and E2 = I - E1, so that P_c^-1 = E1 / l1 + E2 / l2 without the eigenvectors' angle
    // (E1's entries stay within [0, 1] as rad -> 0). An isotropic P (rad = 0) is m I / l1.
    const double mean = 0.5 * (s.pxx + s.pyy);
    const double half_diff = 0.5 * (s.pxx - s.pyy);
    const double rad = std::sqrt(half_diff * half_diff + s.pxy * s.pxy);
    const double floor = kMinEigenvalue * m;
    const double l1 = std::max(mean + rad, floor), l2 = std::max(mean - rad, floor);
    if (!(rad > 0.0)) return {m / l1, 0.0, m / l1};
    const double exx = 0.5 + 0.5 * half_diff / rad, exy = 0.5 * s.pxy / rad;
    const double a = m / l1, b = m / l2;
    // E2 = I - E1: its xx is E1's yy, its xy -E1's xy.
    return {a * exx + b * (1.0 - exx), (a - b) * exy, a * (1.0 - exx) + b * exx};
  }

  /// Whether a band particle is struck (above): its L is then I.
  bool struck(const Step& st, double summed_rate, double corrected_rate) const {
    const double limit = struck_rate * n0;
    return st.n_predicted - st.n_before > limit * st.dt ||
           std::max(summed_rate, corrected_rate) > limit || st.n_before > n0 * (1.0 + kSqueeze);
  }

  /// The corrector of a band particle: the renormalisation, or I when struck.
  Corrector corrector(const Sums& s, const Step& st) const {
    const Corrector l = renormalisation(s);
    if (struck(st, s.summed(), rate(s, l))) return {};
    return l;
  }

  /// The band particle's rate: corrected, or summed where a boundary particle is within re.
  static double band_rate(const Sums& s, const Corrector& l) {
    return s.boundary ? s.summed() : rate(s, l);
  }

  /// The variational gradient of fluid particle i with the band's correctors, gathered by i
  /// (unscaled: times C n0), in one pass over its list:
  ///
  ///     sum_j ((t_i + q_j) I + A_i + A_j) W'(r_ij) e_ij,   A = q (L - I),
  ///
  /// that is sum_j (q_i L_i + q_j L_j) W'(r_ij) e_ij, with t_i the own term of
  /// MpsOperators::gradient_variational (q_i, or |q_i| under the tensile switch where L_i = I).
  /// The arrays a (A's xx, xy, yy) are zero where L = I and on boundary particles: a pair with a
  /// boundary particle carries A_i alone (the wall's share of the band's stress, above), and the
  /// body's force reads the same pairs (Simulation::body_force), so the pair forces between the
  /// water and the body stay equal and opposite. Gathered, each particle sums only into itself:
  /// the pass runs in parallel and its result does not depend on the thread count.
  ///
  /// Only a band particle has an A: a particle with none in its list (the water deeper than
  /// re + skin below the band) has nothing to gather, and reaches() sends it to the plain
  /// gradient, which costs two thirds as much per pair (no loads of A). Which particles have
  /// one is marked from the band's side (Simulation::set_band_excess: each band particle marks
  /// itself and the fluid in its list, the lists being symmetric), with the step's stamp, so
  /// that the marks need no clearing and no pass over every list.
  struct Excess {
    const double* xx = nullptr;
    const double* xy = nullptr;
    const double* yy = nullptr;
    const std::uint32_t* reached = nullptr;  ///< stamp: i or one in its list is in the band
    std::uint32_t stamp = 0;                 ///< this step's mark
    /// Whether fluid particle i or one in its list is in the band.
    bool reaches(std::int64_t i) const { return xx && reached[i] == stamp; }
  };
  static Vec2 gathered_gradient(const Kernel& w, std::int64_t i, IdRange nb, const double* x,
                                const double* y, const double* q, double ti, const Excess& a) {
    return gathered<true>(w, i, nb, x, y, q, ti, a);
  }

  /// What gathered_gradient adds to the plain gradient of i (unscaled): sum_j (A_i + A_j)
  /// W'(r_ij) e_ij, for the particles whose plain part another form computes (the
  /// renormalised gradients, PressureGradient.h).
  static Vec2 gathered_excess(const Kernel& w, std::int64_t i, IdRange nb, const double* x,
                              const double* y, const Excess& a) {
    return gathered<false>(w, i, nb, x, y, nullptr, 0.0, a);
  }

 private:
  /// The pair loop of both: with kPlain the plain terms (t_i + q_j) too.
  template <bool kPlain>
  static Vec2 gathered(const Kernel& w, std::int64_t i, IdRange nb, const double* x,
                       const double* y, const double* q, double ti, const Excess& a) {
    const double xi = x[i], yi = y[i];
    const double ixx = a.xx[i], ixy = a.xy[i], iyy = a.yy[i];
    const std::int32_t* id = nb.first;
    double gx = 0.0, gy = 0.0;
#pragma omp simd reduction(+ : gx, gy)
    for (std::int64_t k = 0; k < nb.size(); ++k) {
      const std::int32_t j = id[k];
      const double dx = xi - x[j], dy = yi - y[j];
      const double r = std::sqrt(dx * dx + dy * dy);
      const double f = w.derivative(r) / r;
      double axx = a.xx[j] + ixx, axy = a.xy[j] + ixy, ayy = a.yy[j] + iyy;
      if constexpr (kPlain) {
        const double s = ti + q[j];
        axx += s;
        ayy += s;
      }
      gx += f * (axx * dx + axy * dy);
      gy += f * (axy * dx + ayy * dy);
    }
    return {gx, gy};
  }
};

}  // namespace wcmps
