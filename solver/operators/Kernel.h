#pragma once
/// @file Kernel.h
/// @brief Weight function of the study (thesis Eq. 2.3; Shakibaeinia & Jin 2012, after
/// Batchelor 1967):
///
///     W(r) = (1 - r/re)^3   for r < re,   0 otherwise.
///
/// The same re (3.5 DL in the study) serves every operator.

#include <cmath>

namespace wcmps {

/// max(q, 0), exactly and without a branch, so that loops using it vectorise. With AVX it is a
/// select (one instruction); for SSE2, where GCC 12 vectorises neither the select nor
/// std::max(0.0, q), it is written as arithmetic (three).
inline double ramp(double q) {
#if defined(__AVX__)
  return q < 0.0 ? 0.0 : q;
#else
  return 0.5 * (q + std::fabs(q));
#endif
}

struct WeightCubic_Shakibaeinia2012 {
  double re;
  /// 1/re: the operators evaluate W for every pair of every step, and a multiplication costs a
  /// fraction of a division there (the profile in docs/performance.md).
  double inv_re;

  explicit WeightCubic_Shakibaeinia2012(double radius) : re(radius), inv_re(1.0 / radius) {}

  /// The cutoff is a ramp, not a branch: the loops over neighbours evaluate W for several pairs
  /// at once (SIMD).
  double operator()(double r) const {
    const double q = ramp(1.0 - r * inv_re);
    return q * q * q;
  }

  /// dW/dr = -3 (1 - r/re)^2 / re for r < re, 0 otherwise.
  double derivative(double r) const {
    const double q = ramp(1.0 - r * inv_re);
    return -3.0 * q * q * inv_re;
  }
};

using Kernel = WeightCubic_Shakibaeinia2012;

}  // namespace wcmps
