// The MPS kernel and operators on an unperturbed square lattice, against the constants of
// ../shared/spec/validation.md and the exact derivatives of polynomials.

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "neighbours/CellGrid.h"
#include "neighbours/NeighbourList.h"
#include "operators/Kernel.h"
#include "operators/LatticeConstants.h"
#include "operators/MpsOperators.h"
#include "physics/EquationOfState.h"
#include "physics/PredictionSums.h"

namespace wcmps {
namespace {

// validation.md lists the constants to six decimals: compare to half a unit of the last one.
constexpr double kTableTolerance = 5e-7;

struct LatticeRow {
  double re_over_dl;
  int neighbours;
  double n0;
  double lambda_over_dl2;
};

TEST(LatticeConstants, MatchTheValidationTable) {
  const LatticeRow rows[] = {{2.1, 12, 0.714622, 1.196749},
                             {3.1, 28, 2.241411, 1.844076},
                             {3.5, 36, 3.043030, 2.200770},
                             {4.0, 44, 4.198296, 2.734456}};
  for (const double dl : {1.0, 0.005}) {
    for (const auto& row : rows) {
      const auto c = square_lattice_constants(dl, row.re_over_dl * dl);
      EXPECT_EQ(c.neighbours, row.neighbours) << "re = " << row.re_over_dl << " DL";
      EXPECT_NEAR(c.n0, row.n0, kTableTolerance) << "re = " << row.re_over_dl << " DL";
      EXPECT_NEAR(c.lambda / (dl * dl), row.lambda_over_dl2, kTableTolerance)
          << "re = " << row.re_over_dl << " DL";
    }
  }
}

TEST(Kernel, IsTheCubicOfTheStudyAndItsDerivative) {
  const Kernel w{3.5};
  EXPECT_DOUBLE_EQ(w(0.0), 1.0);
  EXPECT_DOUBLE_EQ(w(3.5), 0.0);
  EXPECT_DOUBLE_EQ(w(4.0), 0.0);
  EXPECT_NEAR(w(1.0), std::pow(1.0 - 1.0 / 3.5, 3), 1e-15);
  for (const double r : {0.3, 1.0, 2.2, 3.4}) {
    const double h = 1e-6;
    // Central difference of a cubic: error O(h^2) ~ 1e-12, rounding ~ 1e-10.
    EXPECT_NEAR(w.derivative(r), (w(r + h) - w(r - h)) / (2 * h), 1e-8) << "r = " << r;
  }
}

/// A (2k+1) x (2k+1) square lattice of spacing dl centred on the origin; particle `centre` is
/// the one at the origin, with a full kernel for re <= k dl.
struct Lattice {
  std::vector<double> x, y;
  std::int64_t centre = 0;
  CellGrid grid;
  NeighbourList list;

  Lattice(int k, double dl, double re) {
    for (int j = -k; j <= k; ++j) {
      for (int i = -k; i <= k; ++i) {
        if (i == 0 && j == 0) centre = static_cast<std::int64_t>(x.size());
        x.push_back(i * dl);
        y.push_back(j * dl);
      }
    }
    const auto n = static_cast<std::int64_t>(x.size());
    grid.configure({-(k + 1) * dl, -(k + 1) * dl}, {(k + 1) * dl, (k + 1) * dl}, re * 1.01);
    grid.bin(x.data(), y.data(), n);
    list.build(grid, x.data(), y.data(), n, re * 1.01, {{0, n}});
  }
};

class LatticeOperators : public ::testing::TestWithParam<double> {};

TEST_P(LatticeOperators, ReproduceExactValuesForAnInteriorParticle) {
  const double dl = 0.005;
  const double re = GetParam() * dl;
  const auto c = square_lattice_constants(dl, re);
  const MpsOperators ops(re, 2, c.n0, c.lambda, c.gradient_correction);
  Lattice lat(6, dl, re);
  const auto nb = lat.list.of(lat.centre);
  std::vector<double> phi_x(lat.x.size()), phi_x2(lat.x.size()), phi_lin(lat.x.size());
  for (std::size_t k = 0; k < lat.x.size(); ++k) {
    phi_x[k] = lat.x[k];
    phi_x2[k] = lat.x[k] * lat.x[k];
    phi_lin[k] = 3.0 - 2.0 * lat.x[k] + 5.0 * lat.y[k];  // a hydrostatic-like linear field
  }
  // Exact in exact arithmetic: tolerances are rounding of sums of ~40 terms of size ~1.
  EXPECT_NEAR(ops.number_density(lat.centre, nb, lat.x.data(), lat.y.data()), c.n0, 1e-12);
  const Vec2 g = ops.gradient(lat.centre, nb, lat.x.data(), lat.y.data(), phi_x.data());
  EXPECT_NEAR(g.x, 1.0, 1e-12);
  EXPECT_NEAR(g.y, 0.0, 1e-12);
  const Vec2 gm =
      ops.gradient_neighbourhood_min(lat.centre, nb, lat.x.data(), lat.y.data(), phi_lin.data());
  EXPECT_NEAR(gm.x, -2.0, 1e-10);
  EXPECT_NEAR(gm.y, 5.0, 1e-10);
  // The Laplacian of x^2 is 2 with the discrete lambda (validation.md).
  EXPECT_NEAR(ops.laplacian(lat.centre, nb, lat.x.data(), lat.y.data(), phi_x2.data()), 2.0, 1e-9);
  // Variational gradient with uniform n = n0: exact for a linear field thanks to C.
  std::vector<double> p_over_n2(lat.x.size());
  for (std::size_t k = 0; k < lat.x.size(); ++k) p_over_n2[k] = phi_lin[k] / (c.n0 * c.n0);
  const Vec2 gv = ops.gradient_variational(lat.centre, nb, lat.x.data(), lat.y.data(),
                                           p_over_n2.data(), p_over_n2[lat.centre]);
  EXPECT_NEAR(gv.x, -2.0, 1e-10);
  EXPECT_NEAR(gv.y, 5.0, 1e-10);
}

INSTANTIATE_TEST_SUITE_P(KernelRadii, LatticeOperators, ::testing::Values(2.1, 3.1, 3.5, 4.0));

TEST(LatticeConstants, RowSpacingGivesTheRequestedNumberDensity) {
  const double dl = 0.01, re = 0.035;
  const double n0 = square_lattice_constants(dl, re).n0;
  for (const double ratio : {1.0, 1.001, 1.005, 1.02}) {
    const double dy = row_spacing_for_density_ratio(dl, re, ratio);
    EXPECT_LE(dy, dl * (1 + 1e-12));
    // The bisection runs to machine precision; 1e-10 relative is far below the 1e-5 of n
    // that moves the pressure by 14 Pa at c0 = 37 m/s.
    EXPECT_NEAR(rectangular_lattice_number_density(dl, dy, re), ratio * n0, 1e-10 * n0);
  }
}

// The pair loops have no branch: a pair beyond re is evaluated and multiplied by the kernel's
// zero. That zero must be exact, or the huge inputs of far particles would leak in.
TEST(PairLoops, PairsBeyondReAddExactlyNothing) {
  const double dl = 0.005, re = 3.5 * dl;
  const auto c = square_lattice_constants(dl, re);
  const MpsOperators ops(re, 2, c.n0, c.lambda, c.gradient_correction);
  Lattice lat(6, dl, re * 1.3);  // lists reach 1.3 re: about 40 % of the pairs lie beyond re
  const auto nb = lat.list.of(lat.centre);
  std::vector<double> tame(lat.x.size()), wild(lat.x.size());
  std::int64_t beyond = 0;
  for (std::size_t k = 0; k < lat.x.size(); ++k) {
    tame[k] = 1.0 + 0.1 * lat.x[k] / dl - 0.05 * lat.y[k] / dl;
    const bool far = std::hypot(lat.x[k], lat.y[k]) >= re;
    beyond += far;
    wild[k] = far ? 1e300 : tame[k];
  }
  ASSERT_GT(beyond, 0);
  const double* x = lat.x.data();
  const double* y = lat.y.data();
  const std::int64_t i = lat.centre;
  // Bit for bit: the far pairs' terms are 0 * finite, whatever the input.
  EXPECT_EQ(ops.gradient_variational(i, nb, x, y, wild.data(), tame[i]).x,
            ops.gradient_variational(i, nb, x, y, tame.data(), tame[i]).x);
  EXPECT_EQ(ops.gradient_neighbourhood_min(i, nb, x, y, wild.data()).y,
            ops.gradient_neighbourhood_min(i, nb, x, y, tame.data()).y);
  const Viscosity_Koshizuka1996Laplacian visc{1e-6};
  const ArtificialViscosity_Monaghan1992 art{0.02, 26.0};
  EXPECT_EQ(viscous_acceleration(ops, visc, art, i, nb, x, y, wild.data(), tame.data()).x,
            viscous_acceleration(ops, visc, art, i, nb, x, y, tame.data(), tame.data()).x);
  EXPECT_DOUBLE_EQ(ops.number_density(i, nb, x, y), c.n0);
}

TEST(EquationOfState, WholeExponentsBySquaringMatchPow) {
  for (int e = 1; e <= 16; ++e) {
    for (const double x : {0.9, 1.0, 1.0137, 1.2}) {
      const double exact = std::pow(x, e);
      // Squaring rounds once per multiplication (at most 8 for e <= 16): 8 half-ulps, under
      // 1e-15 relative; 4e-15 leaves room and would still catch a wrong power (>= 1 %).
      EXPECT_NEAR(EquationOfState_TaitShakibaeiniaJin2010::power(x, e), exact, 4e-15 * exact)
          << x << "^" << e;
    }
  }
  // Other exponents go to std::pow.
  EXPECT_EQ(EquationOfState_TaitShakibaeiniaJin2010::power(1.01, 7.5), std::pow(1.01, 7.5));
  EXPECT_EQ(EquationOfState_TaitShakibaeiniaJin2010::power(1.01, 17.0), std::pow(1.01, 17.0));
}

}  // namespace
}  // namespace wcmps
