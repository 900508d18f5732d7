#pragma once
/// @file MpsOperators.h
/// @brief The MPS differential operators of Koshizuka & Oka (1996) as written in the thesis,
/// chapter 2.4, evaluated for one particle i over its neighbour list. Each function is the
/// formula and nothing else: loops over particles and scheme choices live in the physics phases.
///
/// Neighbours come from a list built with a cutoff a little above re; pairs at r_ij >= re add
/// exactly zero (the kernel is zero there). The loops of every step (number density, the
/// neighbourhood-min and variational gradients; the viscosity in physics/Viscosity.h) have no
/// branch and are marked `omp simd`: the pairs of one particle are summed several at a time
/// (SSE2/AVX lanes), which lets the square roots and divisions of several pairs overlap
/// (docs/performance.md). The lanes reorder the additions of a sum, so results differ from a
/// serial sum in the last bits; they do not depend on the number of threads.

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "core/Vec2.h"
#include "neighbours/NeighbourList.h"
#include "operators/Kernel.h"

namespace wcmps {

/// M = (C/n0) sum_j (-W'(r_ij) r_ij) e_ij e_ij^T of particle i, the identity on the lattice
/// (C: LatticeConstants), over its whole neighbourhood, and its terms over the part of it that a
/// sum took (the body's share of a gradient; all of it otherwise).
struct SecondMoments {
  double mxx = 0.0, mxy = 0.0, myy = 0.0;
  double pmxx = 0.0, pmxy = 0.0, pmyy = 0.0;
};

/// The sums of the variational gradient split by q_j = q_i + (q_j - q_i) (the renormalised
/// gradient, physics/GradientRenormalisation_Khayyer2011.h): the difference part
/// sum (q_j - q_i) W' e_ij, the symmetric part sum W' e_ij, and M.
struct VariationalSums {
  double dx = 0.0, dy = 0.0;  ///< sum_j (q_j - q_i) W'(r_ij) e_ij
  double sx = 0.0, sy = 0.0;  ///< sum_j W'(r_ij) e_ij
  SecondMoments m;
};

/// The variational gradient's sum sum_j (t_i + q_j) W'(r_ij) e_ij, unscaled, and M.
struct VariationalMoments {
  double gx = 0.0, gy = 0.0;
  SecondMoments m;
};

class MpsOperators {
 public:
  /// @param dimension d (2)   @param n0 initial number density   @param lambda (m^2)
  /// @param gradient_correction C of the variational gradient (LatticeConstants)
  MpsOperators(double re, int dimension, double n0, double lambda, double gradient_correction)
      : w_{re},
        re2_(re * re),
        d_(dimension),
        n0_(n0),
        lambda_(lambda),
        c_grad_(gradient_correction) {}

  double re() const { return w_.re; }
  double n0() const { return n0_; }
  double lambda() const { return lambda_; }
  double gradient_correction() const { return c_grad_; }
  const Kernel& kernel() const { return w_; }

  /// Eq. 2.4 / 2.17:  <n>_i = sum_{j != i} W(r_ij).
  double number_density(std::int64_t i, IdRange nb, const double* x, const double* y) const {
    const double xi = x[i], yi = y[i];
    const std::int32_t* id = nb.first;
    double s = 0.0;
#pragma omp simd reduction(+ : s)
    for (std::int64_t k = 0; k < nb.size(); ++k) {
      const double dx = x[id[k]] - xi, dy = y[id[k]] - yi;
      s += w_(std::sqrt(dx * dx + dy * dy));
    }
    return s;
  }

  /// Eq. 2.5:  <grad phi>_i = d/n0 sum_{j != i} (phi_j - phi_i)/r_ij^2 (r_j - r_i) W(r_ij).
  Vec2 gradient(std::int64_t i, IdRange nb, const double* x, const double* y,
                const double* phi) const {
    return gradient_with_reference(i, nb, x, y, phi, phi[i]);
  }

  /// Eq. 2.19 (Koshizuka, Nobe & Oka 1998): Eq. 2.5 with phi_i replaced by the minimum of phi
  /// over i and its neighbours within re, so that every pair term pushes particles apart.
  Vec2 gradient_neighbourhood_min(std::int64_t i, IdRange nb, const double* x, const double* y,
                                  const double* phi) const {
    // Sum of phi_j w_ij and of w_ij, w_ij = W/r^2 (r_j - r_i); then subtract phi_min * sum w_ij.
    const double xi = x[i], yi = y[i];
    const std::int32_t* id = nb.first;
    double sx = 0.0, sy = 0.0, tx = 0.0, ty = 0.0, phi_min = phi[i];
#pragma omp simd reduction(+ : sx, sy, tx, ty) reduction(min : phi_min)
    for (std::int64_t k = 0; k < nb.size(); ++k) {
      const std::int32_t j = id[k];
      const double dx = x[j] - xi, dy = y[j] - yi;
      const double r2 = dx * dx + dy * dy;
      const double f = w_(std::sqrt(r2)) / r2;
      phi_min = std::min(phi_min, r2 < re2_ ? phi[j] : phi_min);
      sx += phi[j] * f * dx;
      sy += phi[j] * f * dy;
      tx += f * dx;
      ty += f * dy;
    }
    const double c = d_ / n0_;
    return {c * (sx - phi_min * tx), c * (sy - phi_min * ty)};
  }

  /// The minimum of phi over i and its neighbours within re (the reference of Eq. 2.19).
  double neighbourhood_min(std::int64_t i, IdRange nb, const double* x, const double* y,
                           const double* phi) const {
    double phi_min = phi[i];
    for (const std::int32_t j : nb) {
      const double dx = x[j] - x[i], dy = y[j] - y[i];
      if (dx * dx + dy * dy < re2_ && phi[j] < phi_min) phi_min = phi[j];
    }
    return phi_min;
  }

  /// Pressure gradient as the exact derivative of the potential energy of the summed number
  /// density (variational form, Suzuki, Koshizuka & Oka 2007):
  ///
  ///     <grad p>_i = C n0 sum_j (p_i / n_i^2 + p_j / n_j^2) W'(r_ij) (r_i - r_j) / r_ij,
  ///
  /// with C from the lattice so that a linear p gives its exact gradient. Pair terms are
  /// antisymmetric (momentum conserved) and derive from a potential (energy conserved).
  /// `p_over_n2` holds p / n^2 of every particle (boundary particles: p / n0^2); `ti` stands for
  /// p_i / n_i^2 in the pair terms (p_over_n2[i], or |p_over_n2[i]| under the tensile-instability
  /// control of physics/NegativePressure_Sun2018.h).
  Vec2 gradient_variational(std::int64_t i, IdRange nb, const double* x, const double* y,
                            const double* p_over_n2, double ti) const {
    const double xi = x[i], yi = y[i];
    const std::int32_t* id = nb.first;
    double gx = 0.0, gy = 0.0;
#pragma omp simd reduction(+ : gx, gy)
    for (std::int64_t k = 0; k < nb.size(); ++k) {
      const std::int32_t j = id[k];
      const double dx = xi - x[j], dy = yi - y[j];
      const double r = std::sqrt(dx * dx + dy * dy);
      const double f = (ti + p_over_n2[j]) * w_.derivative(r) / r;
      gx += f * dx;
      gy += f * dy;
    }
    const double c = c_grad_ * n0_;
    return {c * gx, c * gy};
  }

  /// The sums of VariationalSums for particle i: the two parts and M's terms over `part`, M
  /// over all of nb (the body's share of i's gradient is the part over the body's particles,
  /// renormalised by i's whole neighbourhood). With part = nb, one loop.
  VariationalSums variational_sums(std::int64_t i, IdRange nb, IdRange part, const double* x,
                                   const double* y, const double* q) const {
    const double xi = x[i], yi = y[i], qi = q[i];
    double dx_ = 0.0, dy_ = 0.0, sx = 0.0, sy = 0.0, mxx = 0.0, mxy = 0.0, myy = 0.0;
    const std::int32_t* id = part.first;
#pragma omp simd reduction(+ : dx_, dy_, sx, sy, mxx, mxy, myy)
    for (std::int64_t k = 0; k < part.size(); ++k) {
      const std::int32_t j = id[k];
      const double dx = xi - x[j], dy = yi - y[j];
      const double r = std::sqrt(dx * dx + dy * dy);
      const double wd = w_.derivative(r) / r;
      const double f = (q[j] - qi) * wd;
      dx_ += f * dx;
      dy_ += f * dy;
      sx += wd * dx;
      sy += wd * dy;
      mxx -= wd * dx * dx;
      mxy -= wd * dx * dy;
      myy -= wd * dy * dy;
    }
    return {dx_, dy_, sx, sy, moments(i, nb, part, x, y, mxx, mxy, myy)};
  }

  /// The sum of gradient_variational (unscaled) and M's terms over `part`, M over all of nb.
  /// With part = nb, one loop: three more sums than the gradient's two.
  VariationalMoments variational_moments(std::int64_t i, IdRange nb, IdRange part, const double* x,
                                         const double* y, const double* p_over_n2,
                                         double ti) const {
    const double xi = x[i], yi = y[i];
    double gx = 0.0, gy = 0.0, mxx = 0.0, mxy = 0.0, myy = 0.0;
    const std::int32_t* id = part.first;
#pragma omp simd reduction(+ : gx, gy, mxx, mxy, myy)
    for (std::int64_t k = 0; k < part.size(); ++k) {
      const std::int32_t j = id[k];
      const double dx = xi - x[j], dy = yi - y[j];
      const double r = std::sqrt(dx * dx + dy * dy);
      const double wd = w_.derivative(r) / r;
      const double f = (ti + p_over_n2[j]) * wd;
      gx += f * dx;
      gy += f * dy;
      mxx -= wd * dx * dx;
      mxy -= wd * dx * dy;
      myy -= wd * dy * dy;
    }
    return {gx, gy, moments(i, nb, part, x, y, mxx, mxy, myy)};
  }

  /// Eq. 2.5 with an arbitrary reference value in place of phi_i.
  Vec2 gradient_with_reference(std::int64_t i, IdRange nb, const double* x, const double* y,
                               const double* phi, double phi_ref) const {
    double gx = 0.0, gy = 0.0;
    for (const std::int32_t j : nb) {
      const double dx = x[j] - x[i], dy = y[j] - y[i];
      const double r2 = dx * dx + dy * dy;
      if (r2 >= re2_) continue;
      const double f = (phi[j] - phi_ref) * w_(std::sqrt(r2)) / r2;
      gx += f * dx;
      gy += f * dy;
    }
    const double c = d_ / n0_;
    return {c * gx, c * gy};
  }

  /// Eq. 2.7:  <lap phi>_i = 2d/(lambda n0) sum_{j != i} (phi_j - phi_i) W(r_ij).
  double laplacian(std::int64_t i, IdRange nb, const double* x, const double* y,
                   const double* phi) const {
    double s = 0.0;
    for (const std::int32_t j : nb) {
      const double dx = x[j] - x[i], dy = y[j] - y[i];
      const double r2 = dx * dx + dy * dy;
      if (r2 < re2_) s += (phi[j] - phi[i]) * w_(std::sqrt(r2));
    }
    return 2.0 * d_ / (lambda_ * n0_) * s;
  }

  /// Eq. 2.7 applied to both components of a vector field (u, v) in one pass.
  Vec2 laplacian(std::int64_t i, IdRange nb, const double* x, const double* y, const double* u,
                 const double* v) const {
    double su = 0.0, sv = 0.0;
    for (const std::int32_t j : nb) {
      const double dx = x[j] - x[i], dy = y[j] - y[i];
      const double r2 = dx * dx + dy * dy;
      if (r2 >= re2_) continue;
      const double w = w_(std::sqrt(r2));
      su += (u[j] - u[i]) * w;
      sv += (v[j] - v[i]) * w;
    }
    const double c = 2.0 * d_ / (lambda_ * n0_);
    return {c * su, c * sv};
  }

  /// SecondMoments of a whole neighbourhood from its unscaled sums (pxx, pxy, pyy).
  SecondMoments whole_moments(double pxx, double pxy, double pyy) const {
    const double m = c_grad_ / n0_;
    return {m * pxx, m * pxy, m * pyy, m * pxx, m * pxy, m * pyy};
  }

 private:
  /// SecondMoments from the unscaled sums over `part` (pxx, pxy, pyy), summing M over nb when
  /// part is not all of it.
  SecondMoments moments(std::int64_t i, IdRange nb, IdRange part, const double* x, const double* y,
                        double pxx, double pxy, double pyy) const {
    const double m = c_grad_ / n0_;
    SecondMoments s = whole_moments(pxx, pxy, pyy);
    if (part.first == nb.first && part.last == nb.last) return s;
    const double xi = x[i], yi = y[i];
    double mxx = 0.0, mxy = 0.0, myy = 0.0;
    for (const std::int32_t j : nb) {
      const double dx = xi - x[j], dy = yi - y[j];
      const double r = std::sqrt(dx * dx + dy * dy);
      const double wd = w_.derivative(r) / r;
      mxx -= wd * dx * dx;
      mxy -= wd * dx * dy;
      myy -= wd * dy * dy;
    }
    s.mxx = m * mxx;
    s.mxy = m * mxy;
    s.myy = m * myy;
    return s;
  }

  Kernel w_;
  double re2_;
  double d_;
  double n0_;
  double lambda_;
  double c_grad_;
};

}  // namespace wcmps
