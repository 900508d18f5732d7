#pragma once
/// @file SlideMotion.h
/// @brief Prescribed motion of a slide along its bed: distance S(t), speed U(t) and
/// acceleration A(t), from a measured table or from the analytic rigid-slide law.
///
/// A block's pressure on the water follows its acceleration, so an interpolant of S(t) must be
/// twice continuously differentiable: a piecewise-linear S(t) has steps in U, and a monotone
/// cubic Hermite (Fritsch & Carlson 1980) has steps in A; either makes pressure spikes.

#include <cstddef>
#include <vector>

namespace wcmps {

struct SlideState {
  double s = 0.0;  ///< distance moved along the bed (m)
  double u = 0.0;  ///< speed along the bed (m/s)
  double a = 0.0;  ///< acceleration along the bed (m/s^2)
};

/// Cubic spline through a table (t_k, S_k) (de Boor 1978, ch. IV): S, U and A continuous.
/// The slide is released from rest: U(t_0) = 0, and before t_0 it stays at S_0. At the last
/// time A = 0 (a "natural" end), and beyond it S continues at the last speed, so S stays twice
/// differentiable there too.
class SplineSlide {
 public:
  /// Throws std::invalid_argument if the table has fewer than two rows, times do not increase,
  /// or the spline is not monotone (S decreasing somewhere: a table that goes back and forth).
  SplineSlide(std::vector<double> t, std::vector<double> s);

  SlideState at(double time) const;
  const std::vector<double>& times() const { return t_; }
  const std::vector<double>& distances() const { return s_; }

 private:
  SlideState at_interval(std::size_t k, double time) const;  // on [t_k, t_k+1]

  std::vector<double> t_, s_;
  std::vector<double> m_;  // second derivatives at the knots
};

/// The rigid-slide law S = s0 ln cosh(t/t0), s0 = ut^2/a0, t0 = ut/a0 (Watts 1998, Grilli &
/// Watts 2005): the slide starts from rest with acceleration a0 and tends to the terminal
/// speed ut.
struct LnCoshSlide {
  double a0;  ///< initial acceleration (m/s^2)
  double ut;  ///< terminal speed (m/s)

  SlideState at(double time) const;
};

}  // namespace wcmps
