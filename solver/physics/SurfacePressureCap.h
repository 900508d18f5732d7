#pragma once
/// @file SurfacePressureCap.h
/// @brief A free-surface particle's pressure held to at most that of the water under it
/// ([physics] surface_pressure_cap; it acts with the evolved number density only).
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
/// by p = 0 on the whole surface row (thesis Eq. 2.10).
///
/// **Not where the particle is struck.** The premise holds where the pressure varies smoothly
/// over the kernel (a converging or a draining surface). Where a surface particle lands on water
/// or strikes a wall, its pressure is the impact's, rho c u, over that of the water it hits; held
/// to the water's, the particle loses the repulsion that keeps it off the particles it lands on,
/// and the Lobovsky dam break's re-entering jet then packs particles past max_density_ratio
/// (docs/validation.md). So the cap leaves a particle alone while its n rises faster than the
/// compression of neighbours closing in at sqrt(g DL), the speed of a fall through one spacing:
///
///     (n^{k+1} - n^k) / (n0 dt) > sqrt(g DL) / DL = sqrt(g / DL).
///
/// The two regimes lie on either side of it at every resolution: a smooth convergence closes
/// neighbours at |div u| DL, which vanishes with DL, while a striking particle closes them at its
/// striking speed, independent of DL. Case I's draining trough raises its surface particles' n
/// by at most 0.2 n0 per second (frame to frame, 0.1-0.24 s, DL 5 mm: closing at 1 mm/s) against
/// the threshold's 44 n0 per second (0.22 m/s); the Lobovsky surge strikes the wall at up to
/// 2 sqrt(g H) = 3.4 m/s. Without gravity the threshold is 0: only a particle whose n does not
/// rise is capped. Measured in docs/validation.md ("A surface particle that pushes itself off").
///
/// **Until the strike is undone** (from 2026-12-04). A strike packs the particle against what it
/// struck, and its n stays high after it stops rising fast; capped then, it kept the water's
/// pressure while its n went on climbing, and nothing pushed it out (the Lobovsky surge's tip in
/// the struck corner at 1.10 to 1.2 n0 with 0 to 7,900 Pa, where its own pressure would be
/// 450 kPa: the run stopped at n*/n0 > 1.2). So a struck particle stays struck until its n is
/// back at or below the n where the strike found it, whatever its rate by then: the memory is a
/// field of the particle (ParticleState::struck_n), carried through reorders and checkpoints.
/// The rule has no constant of its own; where nothing is struck (still water, a draining trough,
/// a wave) nothing changes.

#include <cmath>
#include <cstdint>
#include <optional>

#include "neighbours/NeighbourList.h"
#include "operators/Kernel.h"

namespace wcmps {

struct SurfacePressureCap {
  double struck_rate;  ///< sqrt(g / DL) (1/s): n rising faster than this times n0 is struck

  static SurfacePressureCap make(double g, double dl) { return {std::sqrt(g / dl)}; }

  /// Whether a surface particle whose n went from n_before to n_after over dt is struck: its
  /// pressure is the impact's and is not capped.
  bool struck(double n_before, double n_after, double n0, double dt) const {
    return n_after - n_before > struck_rate * n0 * dt;
  }

  /// The memory of a strike, carried from step to step: the n where the strike found the
  /// particle, or 0 when it is not struck. A particle is struck from the step its n rises fast
  /// (struck) until its n is back at or below where that strike found it; the cap leaves it
  /// alone for all that time (the particle's pressure is then its own).
  double strike(double struck_from, double n_before, double n_after, double n0, double dt) const {
    if (struck(n_before, n_after, n0, dt)) return struck_from > 0.0 ? struck_from : n_before;
    return struck_from > 0.0 && n_after > struck_from ? struck_from : 0.0;
  }

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
