#pragma once
/// @file TimeStep.h
/// @brief The time step: fixed (the study used 2.5e-5 s), or adaptive from the Courant
/// condition (thesis Eq. 2.21) applied to the fastest signal of a weakly compressible fluid,
/// sound plus flow, and from the explicit-viscosity limit:
///
///     dt = min( C DL / (c0 + |u|max),  C_nu DL^2 / nu ).
///
/// The study states Eq. 2.21 with |u|max only; with c0 >> |u| that step is far beyond the
/// acoustic limit of an explicit weakly compressible scheme, so the adaptive step adds c0
/// (Monaghan 1992 uses the same sum for WCSPH). C_nu = 0.125 is the diffusion limit of
/// Morris, Fox & Zhu (1997).

#include <algorithm>
#include <limits>

namespace wcmps {

enum class TimeStepMode { Fixed, Courant };

struct TimeStepRule {
  TimeStepMode mode = TimeStepMode::Courant;
  double fixed = 0.0;             ///< s, for TimeStepMode::Fixed
  double courant = 0.4;           ///< C (-)
  double viscous_number = 0.125;  ///< C_nu (-)
  double dl = 0.0;                ///< particle spacing (m)
  double c0 = 0.0;                ///< sound speed (m/s)
  double nu = 0.0;                ///< kinematic viscosity (m^2/s)

  /// Step for a flow whose fastest particle moves at max_speed.
  double step(double max_speed) const {
    if (mode == TimeStepMode::Fixed) return fixed;
    double dt = courant * dl / (c0 + max_speed);
    if (nu > 0.0) dt = std::min(dt, viscous_number * dl * dl / nu);
    return dt;
  }

  /// Acoustic Courant number c0 dt / DL of a step dt.
  double acoustic_courant(double dt) const { return c0 * dt / dl; }
};

}  // namespace wcmps
