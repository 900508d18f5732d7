#pragma once
/// @file EquationOfState.h
/// @brief Pressure from the particle number density.

#include <cmath>

namespace wcmps {

/// Tait equation in the form of Shakibaeinia & Jin (2010, 2012b), thesis Eq. 2.9:
///
///     p = rho c0^2 / gamma ((n* / n0)^gamma - 1),
///
/// with n* the number density at the predicted positions. gamma = 7 in the study.
struct EquationOfState_TaitShakibaeiniaJin2010 {
  double rho0;   ///< reference density (kg/m^3)
  double c0;     ///< numerical sound speed (m/s)
  double gamma;  ///< exponent (-)
  double n0;     ///< initial number density (-)

  double pressure(double n) const {
    return rho0 * c0 * c0 / gamma * (std::pow(n / n0, gamma) - 1.0);
  }
};

}  // namespace wcmps
