#pragma once
/// @file WallPressure.h
/// @brief How wall particles (the first boundary row) get their pressure; ghost particles then
/// copy the pressure of their wall particle along the wall normal (thesis section 2.6).
///
/// The study says only that boundary pressure equals "the pressure at the nearest boundary".
/// Two readings are offered, chosen by name in the case file ([physics] wall_pressure):
///
/// - "eos" (WallPressure_EosShakibaeiniaJin2010): the wall particle is treated like a fluid
///   particle: Tait equation of its own number density n*, free-surface rule included
///   (Shakibaeinia & Jin 2010). A wall particle whose neighbourhood is not full (near the
///   waterline, under a thin film) gets p = 0 and cannot push fluid away.
/// - "fluid-extrapolated" (WallPressure_Adami2012): the Shepard average of the pressure of the
///   fluid neighbours, carried to the wall by the hydrostatic term (Adami, Hu & Adams 2012,
///   J. Comput. Phys. 231, 7057-7075, Eq. 27):
///
///       p_w = sum_f (p_f + rho0 g . (r_w - r_f)) W_wf / sum_f W_wf ,
///
///   0 when no fluid particle is within re. The hydrostatic term carries the fluid's pressure
///   to the wall's depth; above the free surface (the wall at the waterline, over a film) it
///   would carry it on into a tension that no fluid particle has, and that wall would suck the
///   water up along itself. So p_w is held at or above min(0, min_f p_f): no lower than the
///   lowest pressure of its fluid neighbours where the water is in tension (the suction over a
///   body, which the wall must feel), and not below zero where it is not. Where negative fluid
///   pressures are set to zero (negative_pressure = "zero") this is the old clamp of p_w at 0.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <string_view>

#include "core/SchemeTable.h"
#include "core/Vec2.h"
#include "neighbours/NeighbourList.h"
#include "operators/Kernel.h"
#include "particles/ParticleKind.h"

namespace wcmps {

enum class WallPressureScheme { Eos, FluidExtrapolated };

struct WallPressure_Adami2012 {
  /// Pressure of wall particle w from its fluid neighbours (positions x, y; pressures p).
  /// Returns nullopt when no fluid particle is within re.
  static std::optional<double> pressure(std::int64_t w, IdRange nb, const double* x,
                                        const double* y, const double* p, const ParticleKind* kind,
                                        const Kernel& kernel, double rho0, Vec2 g) {
    const double re2 = kernel.re * kernel.re;
    double sum_w = 0.0, sum_pw = 0.0, lowest = 0.0;
    for (const std::int32_t f : nb) {
      if (kind[f] != ParticleKind::Fluid) continue;
      const double dx = x[w] - x[f], dy = y[w] - y[f];
      const double r2 = dx * dx + dy * dy;
      if (r2 >= re2) continue;
      const double wt = kernel(std::sqrt(r2));
      sum_w += wt;
      sum_pw += (p[f] + rho0 * (g.x * dx + g.y * dy)) * wt;
      lowest = std::min(lowest, p[f]);
    }
    if (sum_w <= 0.0) return std::nullopt;
    return std::max(sum_pw / sum_w, lowest);
  }
};

inline constexpr SchemeEntry<WallPressureScheme> kWallPressureSchemes[] = {
    {"fluid-extrapolated", WallPressureScheme::FluidExtrapolated,
     "Adami, Hu & Adams (2012), J. Comput. Phys. 231, 7057-7075, Eq. 27"},
    {"eos", WallPressureScheme::Eos,
     "Shakibaeinia & Jin (2010), Int. J. Numer. Meth. Fluids 63, 1208-1232"},
};

}  // namespace wcmps
