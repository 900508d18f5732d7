// The MPS kernel and operators on an unperturbed square lattice, against the constants of
// ../shared/spec/validation.md and the exact derivatives of polynomials.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "neighbours/CellGrid.h"
#include "neighbours/NeighbourList.h"
#include "operators/Kernel.h"
#include "operators/LatticeConstants.h"
#include "operators/MpsOperators.h"
#include "physics/EquationOfState.h"
#include "physics/PredictionSums.h"
#include "physics/SideWallFriction_Spalding1961.h"
#include "physics/WallFriction_Spalding1961.h"

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

// A fluid particle half a DL above a flat wall (its wall row and ghost rows below, tangent
// (1, 0)), in a block of fluid that moves as one: only its pairs with the wall are relative
// motion, so the artificial viscosity it gets is the wall's.
TEST(ArtificialViscosity, AFreeSlipWallDampsTheApproachAloneNotTheSliding) {
  const double dl = 0.01, re = 3.5 * dl;
  const auto c = square_lattice_constants(dl, re);
  const MpsOperators ops(re, 2, c.n0, c.lambda, c.gradient_correction);
  std::vector<double> x, y;
  for (int row = -4; row <= 3; ++row) {  // rows below 0: the wall's; the wall row first
    for (int col = -5; col <= 5; ++col) {
      x.push_back(col * dl);
      y.push_back((row + 0.5) * dl);
    }
  }
  const std::int64_t fluid_begin = 4 * 11, i = fluid_begin + 5;  // (0, DL/2)
  std::vector<std::int32_t> ids;
  for (std::int64_t j = 0; j < static_cast<std::int64_t>(x.size()); ++j) {
    if (j != i && std::hypot(x[j] - x[i], y[j] - y[i]) < re) ids.push_back(static_cast<int>(j));
  }
  const IdRange nb{ids.data(), ids.data() + ids.size()};
  std::vector<double> tx(x.size(), 0.0), ty(x.size(), 0.0);
  for (std::int64_t j = 0; j < fluid_begin; ++j) tx[j] = 1.0;
  const SlipInputs free_slip{tx.data(), ty.data()};
  const Viscosity_Koshizuka1996Laplacian none{0.0};
  const ArtificialViscosity_Monaghan1992 art{0.02, 26.0};
  auto acceleration = [&](Vec2 flow, const SlipInputs& slip) {
    std::vector<double> u(x.size(), 0.0), v(x.size(), 0.0);
    for (std::size_t k = static_cast<std::size_t>(fluid_begin); k < x.size(); ++k) {
      u[k] = flow.x;
      v[k] = flow.y;
    }
    return viscous_acceleration(ops, none, art, i, nb, x.data(), y.data(), u.data(), v.data(),
                                slip);
  };
  // Sliding: the no-slip wall's pairs ahead of the particle drag it back, the free-slip
  // wall's do nothing (the relative velocity's normal part is exactly 0).
  const Vec2 slide{0.3, 0.0}, approach{0.0, -0.2}, both{0.3, -0.2};
  ASSERT_LT(acceleration(slide, {}).x, -1.0);  // m/s^2: alpha c0 u / h order
  EXPECT_EQ(acceleration(slide, free_slip).x, 0.0);
  EXPECT_EQ(acceleration(slide, free_slip).y, 0.0);
  // Approaching along the normal: the same pairs close at the same speed either way.
  const Vec2 pushed = acceleration(approach, {});
  ASSERT_GT(pushed.y, 1.0);
  EXPECT_EQ(acceleration(approach, free_slip).y, pushed.y);
  // Both: the free-slip wall reads the approach alone (its pairs' relative velocities are the
  // approach's, bit for bit), the no-slip wall the sliding too.
  const Vec2 oblique = acceleration(both, free_slip);
  EXPECT_EQ(oblique.x, pushed.x);
  EXPECT_EQ(oblique.y, pushed.y);
  EXPECT_LT(acceleration(both, {}).x, 0.5 * acceleration(slide, {}).x);
}

// Spalding's single formula meets its two limits: nu u / y deep in the viscous sublayer, the
// log law u+ = ln(y+) / kappa + B far out of it.
TEST(WallFriction, SpaldingsLawMeetsTheSublayerAndTheLogLayer) {
  const double nu = 1e-6, dl = 0.01;
  const auto f = WallFriction_Spalding1961::make(nu, dl, 3.5 * dl, 3);
  const double y = 0.5 * dl;
  // u = 1e-4 m/s: y+ about 0.7, where the formula departs from y+ = u+ by its fourth-order term,
  // (kappa u+)^4 / 24 e^(-kappa B), under 1e-4 of u+.
  EXPECT_NEAR(f.stress(1e-4), nu * 1e-4 / y, 1e-4 * nu * 1e-4 / y);
  // u = 2 m/s: y+ about 400; the formula's polynomial terms are 1 % of its exponential there,
  // 0.03 of u+ at most after the logarithm: 0.2 % of u+.
  const double ut = std::sqrt(f.stress(2.0));
  const double y_plus = y * ut / nu;
  ASSERT_GT(y_plus, 100.0);
  EXPECT_NEAR(2.0 / ut,
              std::log(y_plus) / WallFriction_Spalding1961::kKappa + WallFriction_Spalding1961::kB,
              0.002 * 2.0 / ut);
  EXPECT_EQ(f.stress(0.0), 0.0);
}

// The table the stress reads against the root of Spalding's law found at each speed.
TEST(WallFriction, TheTabulatedLawMatchesItsRoot) {
  const double nu = 1e-6, dl = 0.005;
  const auto f = WallFriction_Spalding1961::make(nu, dl, 3.5 * dl, 3);
  for (double u = 1e-6; u < 30.0; u *= 1.37) {
    const double re = u * f.y / nu;
    double lo = 0.0, hi = std::sqrt(re);
    for (int it = 0; it < 300; ++it) {
      const double mid = 0.5 * (lo + hi);
      (mid * WallFriction_Spalding1961::y_plus(mid) > re ? hi : lo) = mid;
    }
    const double ut = u / (0.5 * (lo + hi));
    // ln u+ interpolated linearly in ln Re at steps of 0.01: exact in the sublayer, and its
    // error h^2/8 |d2 ln u+ / d(ln Re)^2| is largest in the buffer layer, 2.7e-6 of the stress
    // at u = 0.03-0.08 m/s here (1.4e-6 of u+).
    EXPECT_NEAR(f.stress(u), ut * ut, 4e-6 * ut * ut) << "u = " << u;
  }
}

// Rows of fluid sliding at U along a flat wall (its wall row and three ghost rows): the
// accelerations of one column of particles, one per row, add up to the wall's stress over the
// column's width, sum_m DL^2 a_m = -DL tau_w / rho; along the wall only; none when the wall
// moves with the water.
TEST(WallFriction, TheRowsAlongAWallCarryTheWallsStress) {
  const double dl = 0.01, re = 3.5 * dl, nu = 1e-6, speed = 0.5;
  const int ghost_layers = 3;
  std::vector<double> x, y, u, v, tx, ty;
  for (int row = -(ghost_layers + 1); row <= 6; ++row) {
    for (int col = -8; col <= 8; ++col) {
      x.push_back(col * dl);
      y.push_back((row + 0.5) * dl);
      const bool wall = row < 0;
      u.push_back(wall ? 0.0 : speed);
      v.push_back(0.0);
      tx.push_back(wall ? 1.0 : 0.0);
      ty.push_back(0.0);
    }
  }
  const std::int64_t fluid_begin = (ghost_layers + 1) * 17;
  const auto f = WallFriction_Spalding1961::make(nu, dl, re, ghost_layers);
  const Kernel kernel(re);
  auto column = [&](const std::vector<double>& uu) {
    Vec2 total;
    for (int row = 0; row <= 6; ++row) {
      const std::int64_t i = fluid_begin + row * 17 + 8;  // x = 0
      std::vector<std::int32_t> ids;
      for (std::int64_t j = 0; j < static_cast<std::int64_t>(x.size()); ++j) {
        if (j != i && std::hypot(x[j] - x[i], y[j] - y[i]) < re) ids.push_back(static_cast<int>(j));
      }
      const IdRange nb{ids.data(), ids.data() + ids.size()};
      total += f.acceleration(WallFriction_Spalding1961::sums(kernel, i, nb, fluid_begin, x.data(),
                                                              y.data(), uu.data(), v.data(),
                                                              tx.data(), ty.data())) *
               (dl * dl);
    }
    return total;
  };
  const Vec2 total = column(u);
  // The same sums as S's, in another order: rounding only.
  EXPECT_NEAR(total.x, -dl * f.stress(speed), 1e-12 * dl * f.stress(speed));
  EXPECT_EQ(total.y, 0.0);
  std::vector<double> along = u;
  for (std::int64_t j = 0; j < fluid_begin; ++j) along[j] = speed;
  EXPECT_EQ(column(along).x, 0.0);
}

// The flume's side walls: a flow whose profile across the half-width b/2 is Spalding's law for a
// friction velocity u_tau has the mean U; the side walls' acceleration read from U is the
// profile's own stress, -(2/b) u_tau^2, to what the sublayer and the buffer layer take from the
// log law's mean (z+ < 50 of the half-width's 3750 or 750 here: 0.2 and 1 % of the stress).
// Along -u, none at rest; in slow (laminar) flow the sublayer's 2e nu U / b of stress.
TEST(SideWallFriction, TheWidthsMeanVelocityReadsTheProfilesWallStress) {
  const double nu = 1e-6, b = 0.15;
  const auto f = SideWallFriction_Spalding1961::make(nu, b);
  const auto u_plus = [](double z_plus) {  // Spalding's u+ at z+, by bisection
    double lo = 0.0, hi = std::max(1.0, z_plus);
    for (int it = 0; it < 100; ++it) {
      const double mid = 0.5 * (lo + hi);
      (WallFriction_Spalding1961::y_plus(mid) > z_plus ? hi : lo) = mid;
    }
    return 0.5 * (lo + hi);
  };
  for (const auto& [ut, tolerance] : {std::pair{0.05, 0.005}, std::pair{0.01, 0.015}}) {
    // The mean over z in [0, b/2], on points crowded towards the wall (z ~ s^3).
    const int n = 4000;
    double sum = 0.0;
    for (int k = 0; k < n; ++k) {
      const double z0 = 0.5 * b * std::pow(static_cast<double>(k) / n, 3.0);
      const double z1 = 0.5 * b * std::pow(static_cast<double>(k + 1) / n, 3.0);
      sum += (z1 - z0) * ut * u_plus(0.5 * (z0 + z1) * ut / nu);
    }
    const double mean = sum / (0.5 * b);
    const Vec2 a = f.acceleration({0.6 * mean, -0.8 * mean});
    const double expected = 2.0 / b * ut * ut;
    EXPECT_NEAR(norm(a), expected, tolerance * expected) << "u_tau = " << ut;
    EXPECT_NEAR(a.x / a.y, 0.6 / -0.8, 1e-12);
    EXPECT_LT(a.x, 0.0);
  }
  EXPECT_EQ(norm(f.acceleration({})), 0.0);
  const double slow = 1e-6;  // m/s: z+ at b / (2e) about 0.03
  EXPECT_NEAR(norm(f.acceleration({slow, 0.0})), 2.0 / b * nu * slow / (b / (2.0 * std::exp(1.0))),
              1e-4 * 2.0 / b * nu * slow / (b / (2.0 * std::exp(1.0))));
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
