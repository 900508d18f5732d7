#include "physics/SlideMotion.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace wcmps {

SplineSlide::SplineSlide(std::vector<double> t, std::vector<double> s)
    : t_(std::move(t)), s_(std::move(s)) {
  const std::size_t n = t_.size();
  if (n < 2 || s_.size() != n) {
    throw std::invalid_argument("the motion table needs at least two rows of (t, S)");
  }
  for (std::size_t k = 1; k < n; ++k) {
    if (!(t_[k] > t_[k - 1])) {
      throw std::invalid_argument("the times of the motion table must increase (row " +
                                  std::to_string(k + 1) + ")");
    }
  }
  // Second derivatives m_k: tridiagonal system of the spline's continuity conditions, with
  // S'(t_0) = 0 (first row) and m_{n-1} = 0 (last row). Thomas algorithm.
  std::vector<double> sub(n, 0.0), diag(n, 0.0), sup(n, 0.0), rhs(n, 0.0);
  const double h0 = t_[1] - t_[0];
  diag[0] = 2.0 * h0;
  sup[0] = h0;
  rhs[0] = 6.0 * (s_[1] - s_[0]) / h0;
  for (std::size_t k = 1; k + 1 < n; ++k) {
    const double hl = t_[k] - t_[k - 1], hr = t_[k + 1] - t_[k];
    sub[k] = hl;
    diag[k] = 2.0 * (hl + hr);
    sup[k] = hr;
    rhs[k] = 6.0 * ((s_[k + 1] - s_[k]) / hr - (s_[k] - s_[k - 1]) / hl);
  }
  diag[n - 1] = 1.0;
  rhs[n - 1] = 0.0;
  for (std::size_t k = 1; k < n; ++k) {
    const double w = sub[k] / diag[k - 1];
    diag[k] -= w * sup[k - 1];
    rhs[k] -= w * rhs[k - 1];
  }
  m_.assign(n, 0.0);
  m_[n - 1] = rhs[n - 1] / diag[n - 1];
  for (std::size_t k = n - 1; k-- > 0;) m_[k] = (rhs[k] - sup[k] * m_[k + 1]) / diag[k];

  // Monotone: U >= 0 on every interval. U is quadratic there; check its ends and its vertex.
  for (std::size_t k = 0; k + 1 < n; ++k) {
    const double h = t_[k + 1] - t_[k];
    const double tv = t_[k] + (m_[k + 1] != m_[k] ? -m_[k] * h / (m_[k + 1] - m_[k]) : 0.0);
    for (const double tt : {t_[k], t_[k + 1], std::clamp(tv, t_[k], t_[k + 1])}) {
      if (at_interval(k, tt).u < -1e-12) {
        throw std::invalid_argument(
            "the motion table's spline moves backwards between t = " + std::to_string(t_[k]) +
            " and " + std::to_string(t_[k + 1]) + " s");
      }
    }
  }
}

SlideState SplineSlide::at(double time) const {
  const std::size_t n = t_.size();
  if (time <= t_[0]) return {s_[0], 0.0, 0.0};
  if (time >= t_[n - 1]) {
    // A = 0 at the last knot: carry on at its speed.
    const SlideState end = at_interval(n - 2, t_[n - 1]);
    return {end.s + end.u * (time - t_[n - 1]), end.u, 0.0};
  }
  const auto k =
      static_cast<std::size_t>(std::upper_bound(t_.begin(), t_.end(), time) - t_.begin()) - 1;
  return at_interval(k, time);
}

SlideState SplineSlide::at_interval(std::size_t k, double time) const {
  const double h = t_[k + 1] - t_[k];
  const double a = (t_[k + 1] - time) / h, b = (time - t_[k]) / h;
  SlideState r;
  r.s = a * s_[k] + b * s_[k + 1] +
        ((a * a * a - a) * m_[k] + (b * b * b - b) * m_[k + 1]) * h * h / 6.0;
  r.u = (s_[k + 1] - s_[k]) / h +
        ((1.0 - 3.0 * a * a) * m_[k] + (3.0 * b * b - 1.0) * m_[k + 1]) * h / 6.0;
  r.a = a * m_[k] + b * m_[k + 1];
  return r;
}

SlideState LnCoshSlide::at(double time) const {
  if (time <= 0.0) return {};
  const double t0 = ut / a0, s0 = ut * ut / a0;
  const double x = time / t0;
  // ln cosh x = x + ln((1 + e^{-2x}) / 2), which does not overflow for large x.
  const double lncosh = x + std::log1p(std::exp(-2.0 * x)) - std::log(2.0);
  const double ch = std::cosh(std::min(x, 300.0));
  return {s0 * lncosh, ut * std::tanh(x), a0 / (ch * ch)};
}

}  // namespace wcmps
