#pragma once
/// @file ParticleCollision_Jandaghian2021.h
/// @brief The dynamic particle collision (DPC) of Jandaghian, Krimi, Zarrati & Shakibaeinia
/// (2021, J. Comput. Phys. 434, 110202), between fluid particles ([physics]
/// particle_collision).
///
/// Under the free surface the shifting moves particles along the surface only
/// (ParticleShifting_Sun2017.h), and the tensile-instability switch leaves the band out
/// (NegativePressure_Sun2018.h): nothing there keeps two particles from closing in on each
/// other. Where the water near the surface is in tension (the suction over the accelerating
/// block), the first two rows draw together into one row at half the spacing, and a vacancy
/// is left under it (docs/validation.md, "The particle collision (2026-12-07, session 14)"). The
/// DPC acts, after the pressure correction and before the move, on pairs closer than the
/// collision distance l0 alone, as two bodies would:
///
///     du_i = sum_j k_ij (m_j / (m_i + m_j)) u_ij^coll
///          + (dt / rho) sum_j phi_ij p_ij^b / r_ij^2 r_ij,       r_ij = r_i - r_j < l0,
///
///     (u_ij^coll, phi_ij) = (-(u_ij . r_ij) / r_ij^2 r_ij, 0)   if u_ij . r_ij < 0 (approaching),
///                           (0, 1)                              otherwise,
///     p_ij^b = chi_ij max(min(lambda |p_i + p_j|, lambda p_max), p_min),
///     chi_ij = sqrt(w(r_ij) / w(l0 / 2)),   k_ij = chi_ij for r_ij >= l0/2, 1 below,
///
/// with u_ij = u_i - u_j and w Wendland's C2 kernel of support l0 (the weight of the SPH form of
/// Jandaghian, Siaben & Shakibaeinia, arXiv:2110.10076). The first sum is an inelastic collision:
/// a pair that approaches loses its approach speed (all of it inside l0/2, a share chi_ij
/// beyond), the two particles equally (equal masses); with a restitution e ([physics]
/// particle_collision_restitution, 0 the paper's) a share e of it is kept, reversed (the first
/// sum times 1 + e). The second, for pairs that do not approach, is a repulsion by a background
/// pressure proportional to the pair's own pressure, which parts them. Both are pair terms equal
/// and opposite: momentum is kept. Particles at rest sit DL apart, beyond l0, so still water is
/// untouched.
///
/// Our values (the paper gives the form; its examples, their own): lambda = 0.05; p_min = 0
/// ([physics] particle_collision_min_pressure), so that a pair at the free surface, where p = 0,
/// is only collided, never parted (rho0 |g| DL, the weight of one layer of particles, parted
/// them too and made still water move half as much again: docs/validation.md, "The particle
/// collision as the default"); p_max the hydrostatic pressure at the foot of the water. The
/// default since 2026-12-08, session 15. l0 = 0.8 DL ([physics]
/// particle_collision_distance, the wall collision's distance): a wave strains the water's
/// arrangement by a few per cent, and with l0 = DL the collision part took a share chi of those
/// pairs' approach every step (the standing wave lost 9.3 % of its amplitude per period against
/// 8.0 %; at 0.8 DL 8.1 %: docs/validation.md, "The particle collision").

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string_view>

#include "core/SchemeTable.h"
#include "core/Vec2.h"
#include "neighbours/NeighbourList.h"

namespace wcmps {

enum class ParticleCollisionScheme { None, Jandaghian2021 };

inline constexpr SchemeEntry<ParticleCollisionScheme> kParticleCollisionSchemes[] = {
    {"none", ParticleCollisionScheme::None, ""},
    {"jandaghian2021", ParticleCollisionScheme::Jandaghian2021,
     "Jandaghian, Krimi, Zarrati & Shakibaeinia (2021), J. Comput. Phys. 434, 110202"},
};

struct ParticleCollision_Jandaghian2021 {
  double distance;           ///< l0 (m)
  double lambda;             ///< the background pressure's share of |p_i + p_j|
  double p_min, p_max;       ///< Pa: the background pressure's bounds (p_max before lambda)
  double density;            ///< rho0 (kg/m^3)
  double restitution = 0.0;  ///< e: the share of the approach speed kept, reversed (paper: 0)

  /// Wendland's C2 kernel of support l0 (2D), without its constant.
  static double wendland(double q) {
    if (q >= 1.0) return 0.0;
    const double a = 1.0 - q;
    return a * a * a * a * (1.0 + 4.0 * q);
  }

  /// The change of fluid particle i's velocity from its fluid neighbours closer than l0
  /// (indices >= fluid), from the positions, velocities and pressures of the step. `nb` may be
  /// any list that holds them: Simulation passes the few candidates of the last list build.
  Vec2 change(std::int64_t i, IdRange nb, const double* x, const double* y, const double* u,
              const double* v, const double* p, std::int64_t fluid, double dt) const {
    const double l2 = distance * distance;
    const double w_half = wendland(0.5);
    Vec2 du;
    for (const std::int32_t j : nb) {
      if (j < fluid || j == i) continue;
      const double rx = x[i] - x[j], ry = y[i] - y[j];
      const double r2 = rx * rx + ry * ry;
      if (r2 >= l2 || r2 <= 0.0) continue;
      const double r = std::sqrt(r2);
      const double chi = std::sqrt(wendland(r / distance) / w_half);
      const double approach = (u[i] - u[j]) * rx + (v[i] - v[j]) * ry;  // u_ij . r_ij
      if (approach < 0.0) {
        const double k = 2.0 * r < distance ? 1.0 : chi;
        const double s = -0.5 * (1.0 + restitution) * k * approach / r2;
        du.x += s * rx;
        du.y += s * ry;
      } else {
        const double pb =
            chi * std::max(std::min(lambda * std::abs(p[i] + p[j]), lambda * p_max), p_min);
        const double s = dt / density * pb / r2;
        du.x += s * rx;
        du.y += s * ry;
      }
    }
    return du;
  }
};

}  // namespace wcmps
