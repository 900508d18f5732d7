#pragma once
/// @file LatticeConstants.h
/// @brief n0 and lambda of an interior particle of the initial square lattice.
///
/// n0 = sum_j W(r_ij) (Eq. 2.4 at t = 0) and the discrete Laplacian coefficient
/// lambda = sum_j W r_ij^2 / sum_j W (the discrete form of Eq. 2.8). With the discrete lambda
/// the Laplacian of x^2 is exactly 2 on the lattice; with the integral of Eq. 2.8 it is not
/// (../shared/spec/validation.md gives the values for re = 2.1 ... 4.0 DL).

namespace wcmps {

struct LatticeConstants {
  int neighbours = 0;   ///< particles with 0 < r < re
  double n0 = 0.0;      ///< initial particle number density (-)
  double lambda = 0.0;  ///< Laplacian coefficient (m^2)
  /// C = d n0 / sum_j (-W'(r_ij) r_ij): makes the variational pressure gradient exact for a
  /// linear field on the lattice (0.811565 at re = 3.5 DL; 1 only in the continuum limit).
  double gradient_correction = 0.0;
  /// F0 = sum_j F(r_ij) of the concentration kernel F = q^3 (1 - 3q/4) (operators/DensitySums.h).
  double concentration_sum = 0.0;
  /// kappa: G of an interior particle of a lattice whose density varies along y, over
  /// d(n/n0)/dy of that lattice (G, F: operators/DensitySums.h). Measured on a lattice of
  /// graded row spacing (a strain gradient of 1e-4 per row): the response is not that of the
  /// field C, because G moves one particle among neighbours spaced unevenly on both sides.
  double concentration_response = 0.0;
  /// S_F / 2 = sum_j (-F'(r_ij) r_ij) / 2: with it, (1 / (S_F / 2)) sum_j (phi_j - phi_i) F' e_ij
  /// is the gradient of a linear field phi on the lattice.
  double concentration_gradient_sum = 0.0;
};

/// Constants for an interior particle of a square lattice of spacing dl, kernel radius re.
LatticeConstants square_lattice_constants(double dl, double re);

/// Number density of an interior particle of a rectangular lattice, spacings dx and dy.
double rectangular_lattice_number_density(double dx, double dy, double re);

/// The row spacing dy (<= dl) for which a lattice of column spacing dl has number density
/// ratio * n0(square lattice): the rows of water compressed to n/n0 = ratio >= 1.
double row_spacing_for_density_ratio(double dl, double re, double ratio);

}  // namespace wcmps
