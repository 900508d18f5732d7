#pragma once
/// @file NumberDensity_Jandaghian2020.h
/// @brief Where the number density of the equation of state comes from ([physics]
/// number_density).
///
/// - "summation" (Koshizuka & Oka 1996, thesis Eq. 2.17): n* = sum_j W(r*_ij) at the predicted
///   positions, summed anew every step. Its value follows the particles' arrangement: a 0.1 %
///   wobble of a disordered neighbourhood is 2 % of rho g H through the stiff equation of state,
///   and neighbours differ by that much.
/// - "continuity" (the delta-MPS of Jandaghian & Shakibaeinia 2020, Comput. Methods Appl. Mech.
///   Engrg. 360, 112771, after the delta-SPH of Antuono et al. 2010, Comput. Phys. Commun. 181,
///   532-549): n is a field of its own, advanced by the continuity equation written with the
///   kernel's derivative plus a diffusive term,
///
///       n_i^{n+1} = n_i^n + dt ( sum_j W'(r*_ij) (r*_ij . u*_ij) / r*_ij
///                                + delta (re/2) c0 <lap n>_i ),
///
///   the first sum being exactly d/dt of the summed n (operators/DensitySums.h), evaluated at the
///   predicted positions and velocities like Eq. 2.17 (u plus the particle shifting's velocity:
///   ParticleShifting_Sun2017.h), and <lap n> the MPS Laplacian (Eq. 2.7)
///   over fluid neighbours of n^n with its hydrostatic part removed (Fourtakas et al. 2019,
///   Comput. Fluids 190, 346-361; DualSPHysics's "DDT2"):
///
///       <lap n>_i = 2d/(lambda n0) sum_{j fluid} (n_j - n_i - n0 g . (r_j - r_i) / c0^2) W_ij,
///
///   so that the diffusion smooths the particle-scale noise of n but leaves the hydrostatic
///   gradient of still water alone (without the correction, "molteni2009", it diffuses that
///   gradient away at the bottom and the free surface: Molteni & Colagrossi 2009, Comput. Phys.
///   Commun. 180, 861-872). delta = 0.1 is the value of all three papers. n no longer measures
///   the neighbourhood, so the free surface needs a detection of its own
///   (FreeSurface_Marrone2010.h); the summed n is still computed in the same pass for it.

#include <string_view>

#include "core/SchemeTable.h"

namespace wcmps {

enum class NumberDensityScheme { Summation, Continuity };

inline constexpr SchemeEntry<NumberDensityScheme> kNumberDensitySchemes[] = {
    {"summation", NumberDensityScheme::Summation,
     "Koshizuka & Oka (1996), Nucl. Sci. Eng. 123, 421-434; thesis Eq. 2.17"},
    {"continuity", NumberDensityScheme::Continuity,
     "Jandaghian & Shakibaeinia (2020), Comput. Methods Appl. Mech. Engrg. 360, 112771"},
};

enum class DensityDiffusionScheme { Fourtakas2019, Molteni2009 };

inline constexpr SchemeEntry<DensityDiffusionScheme> kDensityDiffusionSchemes[] = {
    {"fourtakas2019", DensityDiffusionScheme::Fourtakas2019,
     "Fourtakas, Dominguez, Vacondio & Rogers (2019), Comput. Fluids 190, 346-361"},
    {"molteni2009", DensityDiffusionScheme::Molteni2009,
     "Molteni & Colagrossi (2009), Comput. Phys. Commun. 180, 861-872"},
};

/// The continuity update of one particle from its sums (operators/DensitySums.h: R = rate,
/// L = lapl), and the diffusion's factor delta (re/2) c0 2d/(lambda n0).
struct NumberDensity_Jandaghian2020 {
  double diffusion_factor;  ///< delta (re/2) c0 2d / (lambda n0) (1/s)

  static NumberDensity_Jandaghian2020 make(double delta, double re, double c0, double lambda,
                                           double n0) {
    return {delta * 0.5 * re * c0 * 2.0 * 2.0 / (lambda * n0)};  // d = 2
  }
  double advance(double n_prev, double rate, double lapl, double dt) const {
    return n_prev + dt * (rate + diffusion_factor * lapl);
  }
};

}  // namespace wcmps
