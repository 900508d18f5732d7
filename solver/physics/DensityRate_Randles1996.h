#pragma once
/// @file DensityRate_Randles1996.h
/// @brief The evolved number density's rate in the free-surface band, with the velocity
/// divergence renormalised by the kernel's moment matrix and limited by the summed rate
/// ([physics] density_rate).
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
///   one, Simulation::find_surface_band) the divergence of the linear field the sums see, the
///   normalisation of Randles & Libersky (1996, Comput. Methods Appl. Mech. Engrg. 139, 375-408;
///   the kernel gradient correction of Bonet & Lok 1999),
///
///       R_i = m trace(P^-1 B)  (exact for a linear velocity field whatever the support),
///
///   with P's eigenvalues held to at least m / 2 (no direction's weight more than doubled: a
///   single row or a drop has no divergence across it to recover), then limited by the summed
///   rate S_i = trace(B) with minmod (Roe 1986, Annu. Rev. Fluid Mech. 18, 337-365):
///
///       Dn_i/Dt = minmod(S_i, R_i) = S_i or R_i, whichever is smaller in magnitude, if they
///                                    agree in sign; 0 if they do not.
///
///   Inside the water P = m I and the two agree: the band alone is corrected, a few per cent of
///   the fluid. Where the summed rate reads a compression that the divergence does not have
///   (the trough), R is near 0 and wins. Where the renormalisation amplifies a compression that
///   the kernel sees only on one side (a sheet or a jet landing on water, where P has lost a
///   direction), S is smaller and wins: unlimited, R broke the Lobovsky dam break at t = 1.01 s
///   (n > 1.2 n0 where the water that ran up the far wall falls back), limited it runs as the
///   summed rate does. Fluid with a boundary particle within re keeps the summed rate: P there
///   counts the wall's rows, laid on the wall's own uncompressed lattice (with them corrected
///   the cavity of case I's short run is 0.11 cm^2 at 0.20 s instead of 0.03). The sums read
///   u alone: under shifting_in_continuity the shift's share of the rate stays as summed.
///
///   The trade (docs/validation.md, "The band's rate renormalised"): a rate that is not d/dt of
///   the summed n is no longer the partner of the variational gradient's energy, and the
///   pressure can do work on the particles: the flat tank's still water moves about twice as
///   much and its breathing mode grows, and the standing wave loses more. Off by default.

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "core/SchemeTable.h"
#include "neighbours/NeighbourList.h"
#include "operators/Kernel.h"

namespace wcmps {

enum class DensityRateScheme { Summed, Randles1996 };

inline constexpr SchemeEntry<DensityRateScheme> kDensityRateSchemes[] = {
    {"summed", DensityRateScheme::Summed,
     "d/dt of the summed n (Jandaghian & Shakibaeinia 2020, Comput. Methods Appl. Mech. Engrg. "
     "360, 112771)"},
    {"randles1996", DensityRateScheme::Randles1996,
     "the divergence normalised by the kernel's moments (Randles & Libersky 1996, Comput. "
     "Methods Appl. Mech. Engrg. 139, 375-408) in the surface band, limited by the summed rate "
     "with minmod (Roe 1986)"},
};

struct DensityRate_Randles1996 {
  /// The floor of P's eigenvalues, as a share of m: a particle that has lost every neighbour on
  /// one side of a line through it has 0.5 (the half kernel).
  static constexpr double kMinEigenvalue = 0.5;

  /// The pair sums of particle i over its neighbours within re (at r^n, u^n).
  struct Sums {
    double bxu = 0.0, bxv = 0.0, byu = 0.0, byv = 0.0;  ///< B (1/s, unscaled)
    double pxx = 0.0, pxy = 0.0, pyy = 0.0;             ///< P (-)
    bool boundary = false;                              ///< a particle before fluid_begin within re
    double summed() const { return bxu + byv; }
  };

  double m = 0.0;  ///< n0 / C: P_xx of a complete kernel on the lattice

  static Sums sums(const Kernel& w, std::int64_t i, IdRange nb, const double* x, const double* y,
                   const double* u, const double* v, std::int64_t fluid_begin) {
    const double re2 = w.re * w.re;
    const double xi = x[i], yi = y[i], ui = u[i], vi = v[i];
    Sums s;
    for (const std::int32_t j : nb) {
      const double dx = x[j] - xi, dy = y[j] - yi;
      const double r2 = dx * dx + dy * dy;
      if (r2 >= re2 || !(r2 > 0.0)) continue;
      const double r = std::sqrt(r2);
      const double c = w.derivative(r) / r;
      const double du = u[j] - ui, dv = v[j] - vi;
      s.boundary = s.boundary || j < fluid_begin;
      s.bxu += c * dx * du;
      s.bxv += c * dx * dv;
      s.byu += c * dy * du;
      s.byv += c * dy * dv;
      s.pxx -= c * dx * dx;
      s.pxy -= c * dx * dy;
      s.pyy -= c * dy * dy;
    }
    return s;
  }

  /// R = m trace(P_c^-1 B), P_c: P with its eigenvalues held to at least kMinEigenvalue m.
  double renormalised(const Sums& s) const {
    const double mean = 0.5 * (s.pxx + s.pyy);
    const double rad = std::hypot(0.5 * (s.pxx - s.pyy), s.pxy);
    const double floor = kMinEigenvalue * m;
    const double l1 = std::max(mean + rad, floor), l2 = std::max(mean - rad, floor);
    const double th = 0.5 * std::atan2(2.0 * s.pxy, s.pxx - s.pyy);
    const double cs = std::cos(th), sn = std::sin(th);
    // P_c^-1 = v1 v1^T / l1 + v2 v2^T / l2, with v1 = (cs, sn), v2 = (-sn, cs).
    const double ixx = cs * cs / l1 + sn * sn / l2, iyy = sn * sn / l1 + cs * cs / l2;
    const double ixy = cs * sn * (1.0 / l1 - 1.0 / l2);
    return m * (ixx * s.bxu + ixy * (s.byu + s.bxv) + iyy * s.byv);
  }

  static double minmod(double a, double b) {
    if (!(a * b > 0.0)) return 0.0;
    return std::abs(a) < std::abs(b) ? a : b;
  }

  /// The rate of a band particle: minmod(S, R), or S where a boundary particle is within re.
  double rate(const Sums& s) const {
    return s.boundary ? s.summed() : minmod(s.summed(), renormalised(s));
  }
};

}  // namespace wcmps
