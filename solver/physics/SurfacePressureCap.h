#pragma once
/// @file SurfacePressureCap.h
/// @brief A free-surface particle's pressure held to at most that of the water under it
/// ([physics] surface_pressure_cap, off by default; it acts with the evolved number density only).
///
/// With an evolved n a free-surface particle keeps the pressure of its own n, p = max(EOS, 0)
/// (Simulation::compute_pressure says why it is not forced to 0). But its continuity equation
/// sums a one-sided kernel: where the water converges along the surface and stretches across
/// it (drawn down behind a sliding block, the trough of a wave), the top row's n sees the
/// convergence along the row and only half of the stretching under it, and its pressure rises
/// over that of the rows below (case I at 0.16 s: 190-220 Pa in the top row upslope of the
/// block over 50-80 Pa in the second, docs/validation.md). A particle that is a pressure maximum
/// with no water above it is pushed off the water by its own pressure: the layer lifts and a
/// cavity opens under it.
///
/// In the water the pressure is zero at the surface and grows with depth: a surface particle,
/// within about DL/2 of the surface, cannot hold more than the water under it. So its pressure
/// is held to at most the kernel-weighted mean of the pressures of its fluid neighbours that are
/// not on the surface,
///
///     p_s = max( min( EOS(n_s),  sum_f p_f W_sf / sum_f W_sf ), 0 ),   f fluid, not surface,
///
/// (no tension at the surface, also where the water under it is in tension),
/// and left as it is where it has no such neighbour (a jet, a drop, a thin sheet: there the
/// surface particles are the water, and at a wall they carry the impact). Still water is not
/// touched: its surface row is below the hydrostatic pressure of the rows under it. This is the
/// project's treatment (no paper proposes it in this form); the discrete counterpart of the
/// Dirichlet condition p = 0 at the surface with p >= 0 under it, which the old scheme imposed
/// by p = 0 on the whole surface row (thesis Eq. 2.10). Measured in docs/validation.md ("A
/// surface particle that pushes itself off"): it shrinks case I's cavity by a third, but in the
/// splashes of the Lobovsky dam break the run breaks (a particle past max_density_ratio) under
/// Courant numbers that run through without it, so it is not the default.

#include <cmath>
#include <cstdint>
#include <optional>

#include "neighbours/NeighbourList.h"
#include "operators/Kernel.h"

namespace wcmps {

struct SurfacePressureCap {
  /// The cap of surface particle s: the kernel-weighted mean pressure of the neighbours j for
  /// which interior(j) holds (fluid, not on the surface), positions x, y, pressures p. nullopt
  /// when no such neighbour is within re.
  template <class Interior>
  static std::optional<double> bound(std::int64_t s, IdRange nb, const double* x, const double* y,
                                     const double* p, const Kernel& kernel, Interior interior) {
    const double re2 = kernel.re * kernel.re;
    double sum_w = 0.0, sum_pw = 0.0;
    for (const std::int32_t j : nb) {
      if (j == s || !interior(j)) continue;
      const double dx = x[s] - x[j], dy = y[s] - y[j];
      const double r2 = dx * dx + dy * dy;
      if (r2 >= re2) continue;
      const double w = kernel(std::sqrt(r2));
      sum_w += w;
      sum_pw += p[j] * w;
    }
    if (sum_w <= 0.0) return std::nullopt;
    return sum_pw / sum_w;
  }
};

}  // namespace wcmps
