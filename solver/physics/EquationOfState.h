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

  double pressure(double n) const { return rho0 * c0 * c0 / gamma * (power(n / n0, gamma) - 1.0); }

  /// The inverse: n = n0 (1 + gamma p / (rho0 c0^2))^(1/gamma); 0 for a tension the state
  /// cannot reach (the bracket <= 0).
  double number_density(double p) const {
    const double b = 1.0 + gamma * p / (rho0 * c0 * c0);
    return b > 0.0 ? n0 * std::pow(b, 1.0 / gamma) : 0.0;
  }

  /// x^e; for whole e from 1 to 16 (the study's 7) by squaring: std::pow was 2 to 3 % of a
  /// step in the profile (docs/performance.md).
  static double power(double x, double e) {
    if (e >= 1.0 && e <= 16.0 && e == std::floor(e)) {
      auto k = static_cast<unsigned>(e);
      double result = 1.0;
      for (double base = x; k != 0; k >>= 1, base *= base) {
        if (k & 1u) result *= base;
      }
      return result;
    }
    return std::pow(x, e);
  }
};

}  // namespace wcmps
