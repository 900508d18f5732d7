#pragma once
/// @file SideWallFriction_Spalding1961.h
/// @brief The shear stress of a flume's side walls, which a 2D scene leaves out ([physics]
/// side_wall_friction, flume_width).
///
/// A 2D scene is a slice of a flume of width b: its particles carry the water's velocity
/// averaged across the width, and the two glass walls of the flume, which drag the water in the
/// experiment, are not in it. Their stress is the law of the wall's (Spalding 1961, J. Appl.
/// Mech. 28, 455-458; the smooth wall of WallFriction_Spalding1961.h). Across the half-width
/// the log law u(z) = u_tau ((1/kappa) ln(z u_tau / nu) + B) averages to
///
///     U = (2/b) int_0^(b/2) u dz = u_tau ((1/kappa) (ln(b u_tau / (2 nu)) - 1) + B) = u(b / (2e)),
///
/// so the width's mean velocity U, the particle's, is the law's velocity at z = b / (2e), and
/// u_tau follows from U there (this project's reading; in slow, laminar flow it gives
/// tau = 2e mu U / b against the Hele-Shaw cell's 6 mu U / b, 9 % less). The two walls carry
/// 2 tau per unit height of a slice of width b, so each fluid particle gets
///
///     a_i = -(2 / b) (tau_w(|u_i|) / rho) u_i / |u_i|.
///
/// It takes the layer as grown across the half-width. A surge at 3 m/s over 1 m has grown a
/// turbulent layer of about 2 cm (0.37 x Re_x^-0.2), thinner than the flume's half-width of 7.5 cm
/// in Lobovsky et al.'s (2014) tank, where the developing layer's C_f (0.0592 Re_x^-0.2, 0.003) is
/// that of the law at b / (2e) within 10 %. Slow flow feels almost nothing: a wave's 5 cm/s in
/// that tank gets 1e-4 m/s^2. The water's momentum goes to the tank, not to a body.

#include <cmath>
#include <utility>

#include "core/SchemeTable.h"
#include "core/Vec2.h"
#include "physics/WallFriction_Spalding1961.h"

namespace wcmps {

/// [physics] side_wall_friction.
enum class SideWallFrictionScheme { None, Spalding1961 };

inline constexpr SchemeEntry<SideWallFrictionScheme> kSideWallFrictionSchemes[] = {
    {"none", SideWallFrictionScheme::None, "a 2D flow without side walls"},
    {"spalding1961", SideWallFrictionScheme::Spalding1961,
     "Spalding (1961), J. Appl. Mech. 28, 455-458: the law of the wall on the flume's side walls, "
     "read at b / (2e) for the width's mean velocity"},
};

struct SideWallFriction_Spalding1961 {
  WallFriction_Spalding1961 law;  ///< at y = b / (2e)
  double coefficient;             ///< 2 / b (1/m)

  static SideWallFriction_Spalding1961 make(double nu, double width) {
    WallFriction_Spalding1961 law{nu, width / (2.0 * std::exp(1.0)), 0.0,
                                  WallFriction_Spalding1961::plus_table()};
    return {std::move(law), 2.0 / width};
  }

  /// The acceleration of a fluid particle moving at u (m/s^2).
  Vec2 acceleration(Vec2 u) const {
    const double speed = norm(u);
    if (!(speed > 0.0)) return {};
    return u * (-coefficient * law.stress(speed) / speed);
  }
};

}  // namespace wcmps
