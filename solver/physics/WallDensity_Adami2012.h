#pragma once
/// @file WallDensity_Adami2012.h
/// @brief The number density a boundary particle (wall, ghost, the block's) takes in the
/// variational pressure gradient ([physics] wall_density).
///
/// The variational gradient (Suzuki, Koshizuka & Oka 2007) reads q_j = p_j / n_j^2 of every
/// neighbour. A fluid particle's n and p are tied by the equation of state; a boundary
/// particle's pressure comes from its fluid neighbours (physics/WallPressure.h) while its n, as
/// the variational form was first written, is held at n0. Under the hydrostatic pressure of a
/// water column of depth h the fluid's n is n0 (1 + gamma rho0 g h / (rho0 c0^2))^(1/gamma), 0.5 %
/// over n0 at 0.3 m depth with c0 = 24 m/s: the wall's q is then larger than that of a fluid
/// particle at the same pressure by (n/n0)^2, 1.0 %, and the wall pushes the water next to it
/// harder than the water pushes itself. The fluid along every wall is held off it, the pressure
/// there reads high, and the water moves to even it out: in the flat tank of the hydrostatic test
/// (DL 10 mm) this was most of the spurious speed and a +0.56 % mean pressure error
/// (docs/validation.md, "The wall's density").
///
/// "adami2012" gives the boundary particle the density its pressure has under the fluid's own
/// equation of state, as Adami, Hu & Adams (2012, J. Comput. Phys. 231, 7057-7075, Eq. 28)
/// give the wall's density from its extrapolated pressure:
///
///     n_w = n0 (1 + gamma p_w / (rho0 c0^2))^(1/gamma),      q_w = p_w / n_w^2,
///
/// q_w = 0 where p_w = 0 (a dry wall). Under tension (p_w < 0, down to the pressure floor)
/// n_w < n0; the floor (-99 kPa) keeps the bracket positive for every sound speed with
/// rho0 c0^2 / gamma above 99 kPa (c0 > 26 m/s at gamma = 7); below that a bracket <= 0 is a
/// tension the equation of state cannot reach, and q_w is set to 0 (the wall neither pushes nor
/// pulls). Ghost particles copy their wall particle's pressure and so its q. Only the
/// variational gradient reads q; the other gradients read p.
///
/// "adami2012" is the default (from 2026-12-04): still water twice as still, the still tank's
/// breathing mode dies out instead of growing, the Lobovsky impact is the same; a standing wave
/// at DL 10 mm loses a little more per period (12.8 against 12.2 %; at DL 5 mm the difference is
/// within the measure's spread). "n0" (3a85288's scheme) keeps every boundary
/// particle at n0. Measured in docs/validation.md, "The wall's density".

#include <cmath>

#include "core/SchemeTable.h"
#include "physics/EquationOfState.h"

namespace wcmps {

enum class WallDensityScheme { Adami2012, ReferenceN0 };

struct WallDensity_Adami2012 {
  EquationOfState_TaitShakibaeiniaJin2010 eos;

  /// q_w = p_w / n_w^2 with n_w from the inverse of the equation of state.
  double gradient_input(double p) const {
    if (p == 0.0) return 0.0;
    const double n = eos.number_density(p);
    return n > 0.0 ? p / (n * n) : 0.0;
  }
};

inline constexpr SchemeEntry<WallDensityScheme> kWallDensitySchemes[] = {
    {"n0", WallDensityScheme::ReferenceN0,
     "Suzuki, Koshizuka & Oka (2007), Comput. Methods Appl. Mech. Engrg. 196, 2876-2894"},
    {"adami2012", WallDensityScheme::Adami2012,
     "Adami, Hu & Adams (2012), J. Comput. Phys. 231, 7057-7075, Eq. 28"},
};

}  // namespace wcmps
