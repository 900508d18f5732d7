#pragma once
/// @file Kernel.h
/// @brief Weight function of the study (thesis Eq. 2.3; Shakibaeinia & Jin 2012, after
/// Batchelor 1967):
///
///     W(r) = (1 - r/re)^3   for r < re,   0 otherwise.
///
/// The same re (3.5 DL in the study) serves every operator.

namespace wcmps {

struct WeightCubic_Shakibaeinia2012 {
  double re;

  double operator()(double r) const {
    if (r >= re) return 0.0;
    const double q = 1.0 - r / re;
    return q * q * q;
  }

  /// dW/dr = -3 (1 - r/re)^2 / re for r < re, 0 otherwise.
  double derivative(double r) const {
    if (r >= re) return 0.0;
    const double q = 1.0 - r / re;
    return -3.0 * q * q / re;
  }
};

using Kernel = WeightCubic_Shakibaeinia2012;

}  // namespace wcmps
