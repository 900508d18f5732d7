#pragma once
/// @file ParticleShifting_Sun2017.h
/// @brief Particle shifting of the delta-plus-SPH model (Sun, Colagrossi, Marrone & Zhang 2017,
/// Comput. Methods Appl. Mech. Engrg. 315, 25-49), written with the MPS kernel ([physics]
/// shifting).
///
/// Particles carried by a shearing flow lose their lattice: they line up, pair and leave holes,
/// and every operator of the method is less accurate there (the wake of the block). After each
/// step every fluid particle is moved down the gradient of its concentration n/n0, a Fickian
/// diffusion of the particles (Xu, Stansby & Laurence 2009; Lind et al. 2012),
///
///     dr_i = -4 h |u|max dt G_i,   G_i = (1/n0) sum_j [1 + R (W_ij/W(DL))^4] W'(r_ij) e_ij,
///
/// with h = re/2, e_ij = (r_i - r_j)/r_ij, R = 0.2 and the power 4 of Monaghan's (2000)
/// anti-clumping term, and the coefficient CFL Ma (2h)^2 of Sun et al. with Ma = |u|max / c0 and
/// CFL = c0 dt / h: a particle is shifted by a fraction of what the flow moves it, so still water
/// is not shifted at all. Walls and the body count in G, so particles are not pushed into them.
///
/// At the free surface G points into the water and would spread the surface particles outwards,
/// smearing the surface. Particles on the surface, or within re of a surface particle, are
/// therefore shifted along the surface only (Lind et al. 2012, J. Comput. Phys. 231,
/// 1499-1523; Sun et al. use the same projection in the surface's neighbourhood):
///
///     dr_i <- dr_i - (dr_i . nu_i) nu_i,
///
/// nu_i the surface's outward normal near i: the kernel-weighted mean of the normals -G_s/|G_s|
/// of the surface particles s within re (i's own if it is one). It must not be i's own -G_i/|G_i|:
/// dr_i is along G_i, and nothing would be left of it (the flaw of taking the normal from the
/// shifting gradient itself that Khayyer, Gotoh & Shimizu 2017 point out in Lind et al.'s scheme).
///
/// The positions change by a small fraction of DL per step; the velocities are not corrected for
/// it (Sun et al. 2017 do not either).
///
/// **The shift and the evolved number density** ([physics] shifting_in_continuity, off by
/// default: the cavity behind the block grows with it, docs/validation.md "The still water
/// swells").
/// An evolved n (NumberDensity_Jandaghian2020.h) changes only by its rate, the time derivative
/// of the summed n under the velocities u. The shift moves the particles by dr_i besides, and a
/// shift field whose divergence is not zero spreads or gathers them without n seeing it: n then
/// drifts away from the arrangement's own number density. Every particle carries a fixed mass,
/// so the water's volume follows the arrangement while its pressure follows n. Measured in
/// still water (DL 10 mm, 4 s): the summed n of the deep water fell 0.42 % below the carried
/// one, the water's centre of mass rose 1.34 mm and kept rising (the pair with the diffusion
/// feeds it; without shifting the two stay within 0.01 %). The rate therefore takes the
/// particles' whole motion of the last step, u^n + dr/dt:
///
///     Dn_i/Dt = sum_j W'(r_ij) (r_ij . (u_ij + s_ij)) / r_ij,   s_i = dr_i / dt,
///
/// the continuity equation along the shifted paths with each particle's mass fixed: in the
/// arbitrary-Lagrangian-Eulerian form of the shifted continuity equation, -n div(u + s) + div(n s),
/// it leaves out the mass flux div(n s), which a particle of fixed mass cannot carry. n then stays
/// the arrangement's number density up to what the diffusion changes, and the diffusion
/// conserves the sum of n: the water keeps its volume. A shift that compresses a neighbourhood
/// now raises its pressure, which pushes back.

#include <string_view>

#include "core/SchemeTable.h"
#include "core/Vec2.h"

namespace wcmps {

enum class ShiftingScheme { None, Sun2017 };

inline constexpr SchemeEntry<ShiftingScheme> kShiftingSchemes[] = {
    {"none", ShiftingScheme::None, ""},
    {"sun2017", ShiftingScheme::Sun2017,
     "Sun, Colagrossi, Marrone & Zhang (2017), Comput. Methods Appl. Mech. Engrg. 315, 25-49"},
};

struct ParticleShifting_Sun2017 {
  /// R of the anti-clumping weight and its power (Monaghan 2000: R = 0.2, power 4).
  static constexpr double kClumpingR = 0.2;

  double h;  ///< re / 2 (m)

  /// The shift of a particle with concentration gradient G (1/m) in a step dt whose fastest
  /// particle moves at max_speed; with a surface normal nu (unit) near the free surface, along
  /// the surface only (nu = 0: away from it).
  Vec2 shift(Vec2 gradient, double max_speed, double dt, Vec2 nu) const {
    const Vec2 dr = gradient * (-4.0 * h * max_speed * dt);
    return dr - nu * dot(dr, nu);
  }
};

}  // namespace wcmps
