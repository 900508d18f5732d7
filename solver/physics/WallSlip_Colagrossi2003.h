#pragma once
/// @file WallSlip_Colagrossi2003.h
/// @brief Free-slip walls for the artificial viscosity: a fluid particle's pairs with boundary
/// particles read only the normal part of their relative velocity.
///
/// The artificial viscosity (Viscosity.h, Monaghan 1992) damps every approaching pair. A fluid
/// particle sliding along a wall at rest approaches the wall particles ahead of it, so the
/// no-slip wall (boundary particles at the wall's velocity) turns the scheme's viscosity,
/// alpha c0 h / 8, about 1000 times water's at DL 10 mm, into a drag rho k u on the wall with
/// k proportional to alpha c0 and free of DL (tools/wall_drag_estimate.py: 0.033 m/s for the
/// standing wave, 5.8 % of its amplitude per period; docs/validation.md, "The artificial
/// viscosity's drag at the walls: an estimate"). Water's own wall stress is a boundary layer far
/// thinner than DL and far weaker.
///
/// A free-slip wall is the mirror of Colagrossi & Landrini (2003, J. Comput. Phys. 191,
/// 448-475): the ghost of a fluid particle carries its tangential velocity and its normal
/// velocity reversed, so that what the fluid particle sees of the wall is its own approach
/// along the normal. Here the boundary particle j keeps its place and its velocity u_j, and the
/// artificial viscosity's pair reads, instead of u_j - u_i,
///
///     ((u_j - u_i) . n_j) n_j,    n_j the unit normal of j's wall (ParticleSet::normal_x),
///
/// the part of the relative velocity across the wall: a particle that strikes a wall head-on is
/// damped exactly as at a no-slip wall (the pair's closing speed is the same), one that slides
/// along it is not. Adami, Hu & Adams (2012, J. Comput. Phys. 231, 7057-7075) take
/// the same view: for free slip the viscous interaction of fluid and wall is left out. Only the
/// artificial viscosity's pairs change: the Laplacian viscosity (water's nu) keeps its no-slip
/// walls, the pressure its wall particles. It is written with the wall's tangent t_j (t_j = 0:
/// the pair as before, for fluid neighbours and no-slip walls):
///
///     du - (du . t_j) t_j = (du . n_j) n_j   for a unit t_j normal to n_j.

#include "core/SchemeTable.h"

namespace wcmps {

/// [physics] artificial_viscosity_walls.
enum class ArtificialViscosityWalls { NoSlip, FreeSlip };

inline constexpr SchemeEntry<ArtificialViscosityWalls> kArtificialViscosityWallsSchemes[] = {
    {"no-slip", ArtificialViscosityWalls::NoSlip,
     "Monaghan (1992), Annu. Rev. Astron. Astrophys. 30, 543-574: boundary particles at the "
     "wall's velocity"},
    {"free-slip", ArtificialViscosityWalls::FreeSlip,
     "Colagrossi & Landrini (2003), J. Comput. Phys. 191, 448-475: the mirror's relative "
     "velocity, along the wall's normal"},
};

struct WallSlip_Colagrossi2003 {
  /// du, dv (u_j - u_i) without their part along (tx, ty), j's wall tangent (0 for none).
  static void normal_part(double tx, double ty, double& du, double& dv) {
    const double along = du * tx + dv * ty;
    du -= along * tx;
    dv -= along * ty;
  }
};

}  // namespace wcmps
