#pragma once
/// @file WallFriction_Spalding1961.h
/// @brief The wall's shear stress of water sliding along it, from the law of the wall: a wall
/// function for walls that the artificial viscosity leaves free-slip
/// (physics/WallSlip_Colagrossi2003.h).
///
/// Water's boundary layer at a wall is far thinner than DL (the viscous sublayer of a flow at
/// 1 m/s is about 0.1 mm thick), so no particle resolves it; what the particles next to the wall
/// can carry is the stress the layer puts on them. The law of the wall gives it from the slip
/// u (the water's velocity along the wall, relative to it) at the distance y of the first row:
/// with u+ = u / u_tau and y+ = y u_tau / nu, Spalding's (1961, J. Appl. Mech. 28, 455-458)
/// single formula from the viscous sublayer through the buffer layer to the log layer,
///
///     y+ = u+ + e^(-kappa B) [e^(kappa u+) - 1 - kappa u+ - (kappa u+)^2/2 - (kappa u+)^3/6],
///
/// kappa = 0.41, B = 5.2 (a smooth wall: Pope 2000, Turbulent Flows, section 7.1), is solved for
/// u_tau, and tau_w / rho = u_tau^2. It is nu u / y in the sublayer (y+ < 5) and about
/// (kappa u / ln(E y+))^2 in the log layer. The standing wave's slip of 2-5 cm/s at y = 5 mm
/// has y+ of 5 to 20, the buffer layer: tau_w / (rho u) = 2.5-3.7e-4 m/s. The dam break's surge
/// at 2.5-3 m/s at y = 2.5 mm has y+ of several hundred: C_f = tau_w / (rho u^2) about 0.003.
/// The artificial viscosity's drag at a no-slip wall is rho k u with k = alpha c0 times a
/// kernel constant, 0.03-0.06 m/s here (tools/wall_drag_estimate.py): 60 to 130 times the law's
/// stress at the wave's slip, and still 7 to 9 times at the surge's.
///
/// On the particles: each fluid particle i with boundary neighbours sums, over them,
///
///     w_i = sum_j W_ij,    s_i = sum_j W_ij ((u_i - u_j) . t_j) t_j,
///
/// t_j the wall tangent of boundary particle j: s_i / w_i is i's slip along its walls, of speed
/// u_i = |s_i| / w_i. It gets the acceleration
///
///     a_i = -(tau_w(u_i, y) / rho) (w_i / (DL S)) s_i / |s_i|,   y = DL / 2,
///
/// where S = sum over the rows m = 0, 1, ... of a lattice against a flat wall of the w of a
/// particle of row m (wall_weight_sum): the rows along a flat wall share the stress in the
/// proportion of their w, and the shares add up to tau_w per unit length of the wall (a column
/// of particles, one per row, has mass rho DL^2 each, so sum_m rho DL^2 a_m = DL tau_w). The slip
/// of each row is its own but y is the first row's: the rows above it, which carry less of the
/// stress (at re = 3.5 DL with three ghost rows row 0 takes 85 % of it, row 1 15 %, row 2 0.4 %),
/// read it as if they were the first (a simplification, not the law at their distance). Where the
/// wall moves (the block) the slip is relative to its particles' velocity, and the body feels the
/// reaction of its own share (the part of s_i from its particles: acceleration_part).

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/SchemeTable.h"
#include "core/Vec2.h"
#include "neighbours/NeighbourList.h"
#include "operators/Kernel.h"

namespace wcmps {

/// [physics] wall_friction.
enum class WallFrictionScheme { None, Spalding1961 };

inline constexpr SchemeEntry<WallFrictionScheme> kWallFrictionSchemes[] = {
    {"none", WallFrictionScheme::None, "no wall stress beyond the viscosities' pairs"},
    {"spalding1961", WallFrictionScheme::Spalding1961,
     "Spalding (1961), J. Appl. Mech. 28, 455-458: the law of the wall, smooth wall"},
};

struct WallFriction_Spalding1961 {
  static constexpr double kKappa = 0.41;
  static constexpr double kB = 5.2;

  double nu;                 ///< kinematic viscosity (m^2/s), > 0
  double y;                  ///< the first row's distance from the wall's surface, DL/2 (m)
  double scale;              ///< 1 / (DL S) (1/m)
  std::vector<double> plus;  ///< ln u+ against ln Re (plus_table)

  /// The sums of particle i over its boundary neighbours (j < fluid_begin).
  struct Sums {
    double w = 0.0;  ///< sum_j W_ij
    Vec2 s;          ///< sum_j W_ij ((u_i - u_j) . t_j) t_j (m/s)
  };

  static WallFriction_Spalding1961 make(double nu, double dl, double re, int ghost_layers) {
    return {nu, 0.5 * dl, 1.0 / (dl * wall_weight_sum(dl, re, ghost_layers)), plus_table()};
  }

  /// S: of a fluid lattice against a flat wall (its particles at (m + 1/2) DL from the surface),
  /// the boundary weights w of one particle of each row, summed over the rows; the boundary is
  /// the wall row DL/2 behind the surface and ghost_layers rows behind it, DL apart.
  static double wall_weight_sum(double dl, double re, int ghost_layers) {
    const Kernel kernel(re);
    const int reach = static_cast<int>(std::ceil(re / dl)) + 1;
    double sum = 0.0;
    for (int m = 0; m <= reach; ++m) {
      for (int k = 0; k <= ghost_layers; ++k) {
        const double dy = (m + k + 1) * dl;
        for (int p = -reach; p <= reach; ++p) sum += kernel(std::hypot(p * dl, dy));
      }
    }
    return sum;
  }

  /// tau_w / rho = u_tau^2 for the slip speed u (m/s) at distance y. With Re = u y / nu =
  /// u+ y+ = u+ f(u+), which grows with u+, u+ is a function of Re alone: ln u+ tabulated once
  /// (plus_table) against ln Re and read by linear interpolation (exact in the sublayer, where
  /// ln u+ = ln Re / 2; elsewhere at most 3e-6 of the stress, in the buffer layer:
  /// WallFriction.TheTabulatedLawMatchesItsRoot), so that a step pays a logarithm and an
  /// exponential per particle next to a wall, not a root.
  double stress(double u) const {
    if (!(u > 0.0)) return 0.0;
    const double re = u * y / nu;
    double up;
    if (re <= kTableFirst) {
      up = std::sqrt(re);  // the sublayer: y+ = u+ (the formula's excess is < 1e-9 there)
    } else {
      const double at = (std::log(re) - std::log(kTableFirst)) / kTableStep;
      const auto k = std::min(static_cast<std::size_t>(at), plus.size() - 2);
      const double f = at - static_cast<double>(k);
      up = std::exp(plus[k] + f * (plus[k + 1] - plus[k]));
    }
    const double ut = u / up;
    return ut * ut;
  }

  /// y+ of Spalding's law at u+.
  static double y_plus(double up) {
    const double k = std::min(kKappa * up, 700.0);  // exp(700) is finite
    return up + std::exp(-kKappa * kB) * (std::exp(k) - 1.0 - k - 0.5 * k * k - k * k * k / 6.0);
  }

  /// ln u+ at Re = u+ y+(u+) for Re = kTableFirst e^(k kTableStep), k = 0 .. kTableSize - 1 (Re up
  /// to 1e12: u = 1000 m/s at y = 1 m), each by bisection to 1e-13.
  static std::vector<double> plus_table() {
    std::vector<double> t(kTableSize);
    for (std::size_t k = 0; k < kTableSize; ++k) {
      const double re = kTableFirst * std::exp(static_cast<double>(k) * kTableStep);
      double lo = 0.0, hi = std::sqrt(re);  // u+ y+ >= u+^2, so u+ <= sqrt(Re)
      for (int it = 0; it < 200 && hi - lo > 1e-13 * hi; ++it) {
        const double mid = 0.5 * (lo + hi);
        (mid * y_plus(mid) > re ? hi : lo) = mid;
      }
      t[k] = std::log(0.5 * (lo + hi));
    }
    return t;
  }
  static constexpr double kTableFirst = 1e-2;      ///< Re below it: the sublayer, u+ = sqrt(Re)
  static constexpr double kTableStep = 0.01;       ///< of ln Re
  static constexpr std::size_t kTableSize = 3225;  ///< ln(1e12 / 1e-2) / 0.01 + 1

  /// Sums of particle i over the boundary particles of nb (tx, ty: every particle's wall
  /// tangent, read for boundary ones).
  static Sums sums(const Kernel& kernel, std::int64_t i, IdRange nb, std::int64_t fluid_begin,
                   const double* x, const double* y, const double* u, const double* v,
                   const double* tx, const double* ty) {
    Sums s;
    for (const std::int32_t j : nb) {
      if (j >= fluid_begin) continue;
      const double w = kernel(std::hypot(x[j] - x[i], y[j] - y[i]));
      if (w == 0.0) continue;
      const double along = (u[i] - u[j]) * tx[j] + (v[i] - v[j]) * ty[j];
      s.w += w;
      s.s += Vec2{tx[j], ty[j]} * (w * along);
    }
    return s;
  }

  /// The acceleration of a particle with these sums: -(tau_w / rho) (w / (DL S)) s / |s|.
  Vec2 acceleration(const Sums& all) const { return acceleration_part(all, all); }

  /// The part of it that the boundary particles of `part` (a subset of all's) exert: the same
  /// coefficient times part.s.
  Vec2 acceleration_part(const Sums& all, const Sums& part) const {
    const double slip = norm(all.s);
    if (!(slip > 0.0) || !(all.w > 0.0)) return {};
    const double speed = slip / all.w;
    return part.s * (-stress(speed) * all.w * scale / slip);
  }
};

}  // namespace wcmps
