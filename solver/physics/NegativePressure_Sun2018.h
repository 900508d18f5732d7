#pragma once
/// @file NegativePressure_Sun2018.h
/// @brief What happens to negative pressures ([physics] negative_pressure, pressure_floor).
///
/// Water follows an accelerating body because the pressure behind it drops below hydrostatic,
/// and near a free surface that means below zero gauge: a block accelerating at 4 m/s^2 under
/// 2 cm of water needs a few hundred pascals of suction over its top. The choices:
///
/// - "zero": p = max(p, 0) for fluid and wall particles. The study does not say; it removes
///   exactly that suction, and the water tears off the block's top (the cavity of case I).
/// - "keep": negative pressures stay, down to pressure_floor. With the pressure gradient's pair
///   terms in the sum form (the variational gradient), a negative p_i makes pairs attract: the
///   tensile instability, particles clump and the water breaks up (still water at the summed
///   number density does within 0.05 s).
/// - "sun2018-switch": negative pressures stay, down to pressure_floor, and the variational
///   gradient takes the tensile-instability control of Sun, Colagrossi, Marrone, Antuono & Zhang
///   (2018, Comput. Phys. Commun. 224, 63-80): for a particle with p_i < 0 the pair term
///   (p_i/n_i^2 + p_j/n_j^2) becomes (p_j/n_j^2 - p_i/n_i^2), the difference form, which does
///   not attract pairs in a uniform tension. Pair terms then no longer cancel exactly where
///   p < 0 (momentum is conserved only where p >= 0), the price Sun et al. accept. It amounts to
///   using |p_i / n_i^2| for the particle's own term (PressureGradient_Suzuki2007). As Sun et al.
///   do, the switch leaves out the free-surface region (the surface particles and those within
///   re of one): there the particles' own term is what holds the surface together, and without
///   it the dam break at DL 10 mm fractures under the surface of its surge at t = 0.25 s. The
///   other two gradients are difference forms or always repulsive already, and are unchanged.
///
/// The floor is the tension water cannot carry: it cavitates when the absolute pressure falls to
/// its vapour pressure, 2.3 kPa at 20 degrees C, so at -99 kPa gauge under one atmosphere (the
/// default). The equation of state cannot go below -rho0 c0^2 / gamma (-97 kPa at c0 = 26 m/s),
/// so in the study's cases the floor does not bind; it bounds faster sound speeds. Free-surface
/// particles keep p = 0; wall and ghost particles take the same rule as the fluid.

#include <algorithm>
#include <string_view>

#include "core/SchemeTable.h"

namespace wcmps {

enum class NegativePressure { Zero, Keep, Sun2018Switch };

inline constexpr SchemeEntry<NegativePressure> kNegativePressureSchemes[] = {
    {"zero", NegativePressure::Zero, ""},
    {"keep", NegativePressure::Keep, ""},
    {"sun2018-switch", NegativePressure::Sun2018Switch,
     "Sun, Colagrossi, Marrone, Antuono & Zhang (2018), Comput. Phys. Commun. 224, 63-80"},
};

/// The lower bound a pressure is held to: 0 for "zero", the floor otherwise.
struct PressureBound {
  double lowest;  ///< Pa

  static PressureBound make(NegativePressure scheme, double floor) {
    return {scheme == NegativePressure::Zero ? 0.0 : floor};
  }
  double operator()(double p) const { return std::max(p, lowest); }
};

}  // namespace wcmps
