// The cures of the stabilised scheme, each on a particle arrangement whose answer is known: the
// density sums and the continuity update, the density diffusion with and without its
// hydrostatic correction, the free-surface scan, the shifting and its surface projection, the
// tensile-instability switch, the renormalised pressure gradient, the pressure bound and the
// wall's density; and the AVX-512 forms of the pair passes against their portable loops.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <random>
#include <utility>
#include <vector>

#include "neighbours/CellGrid.h"
#include "neighbours/NeighbourList.h"
#include "operators/DensitySums.h"
#include "operators/LatticeConstants.h"
#include "operators/MpsOperators.h"
#include "physics/DensityRate_Randles1996.h"
#include "physics/FreeSurface.h"
#include "physics/FreeSurface_Marrone2010.h"
#include "physics/NegativePressure_Sun2018.h"
#include "physics/NumberDensity_Jandaghian2020.h"
#include "physics/ParticleCollision_Jandaghian2021.h"
#include "physics/ParticleShifting_Sun2017.h"
#include "physics/PredictionSums.h"
#include "physics/PredictionSumsAvx512.h"
#include "physics/PressureGradient.h"
#include "physics/PressureGradientAvx512.h"
#include "physics/SurfacePressureCap.h"
#include "physics/WallDensity_Adami2012.h"

namespace wcmps {
namespace {

constexpr double kDl = 0.01;
constexpr double kRe = 3.5 * kDl;

/// Particles at given positions (all "fluid" unless fluid_begin says otherwise), with neighbour
/// lists at re + 0.2 DL.
struct Cloud {
  std::vector<double> x, y, u, v, n;
  std::vector<double> shift_u, shift_v;  ///< the shifting's velocity of the last step
  CellGrid grid;
  NeighbourList list;

  void add(double px, double py) {
    x.push_back(px);
    y.push_back(py);
  }
  std::int64_t size() const { return static_cast<std::int64_t>(x.size()); }
  void build() {
    const auto count = size();
    u.assign(count, 0.0);
    v.assign(count, 0.0);
    n.assign(count, 0.0);
    shift_u.assign(count, 0.0);
    shift_v.assign(count, 0.0);
    double lo_x = x[0], lo_y = y[0], hi_x = x[0], hi_y = y[0];
    for (std::int64_t k = 0; k < count; ++k) {
      lo_x = std::min(lo_x, x[k]), lo_y = std::min(lo_y, y[k]);
      hi_x = std::max(hi_x, x[k]), hi_y = std::max(hi_y, y[k]);
    }
    const double cutoff = kRe + 0.2 * kDl;
    grid.configure({lo_x - kDl, lo_y - kDl}, {hi_x + kDl, hi_y + kDl}, cutoff);
    grid.bin(x.data(), y.data(), count);
    list.build(grid, x.data(), y.data(), count, cutoff, {{0, count}});
  }
};

/// A block of nx x ny lattice particles with its lower left particle at (0, 0).
Cloud block(int nx, int ny, double jitter = 0.0, unsigned seed = 1) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> d(-jitter, jitter);
  Cloud c;
  for (int j = 0; j < ny; ++j) {
    for (int i = 0; i < nx; ++i) c.add(i * kDl + d(rng) * kDl, j * kDl + d(rng) * kDl);
  }
  c.build();
  return c;
}

const LatticeConstants& lattice() {
  static const LatticeConstants c = square_lattice_constants(kDl, kRe);
  return c;
}

/// The constants of G, with the anti-clumping weight of the shifting (R = 0.2) or without.
DensitySumsSetup setup(bool clumping = true) {
  return {Kernel(kRe), 1.0 / lattice().concentration_sum,
          clumping ? ParticleShifting_Sun2017::kClumpingR : 0.0, 1.0 / Kernel(kRe)(kDl)};
}

/// n and G at the cloud's positions, as the summed-density path takes them.
DensitySums summed(const Cloud& c, std::int64_t i, bool clumping = true) {
  return density_sums<true>(setup(clumping), i, c.list.of(i), c.x.data(), c.y.data());
}

/// The evolved density's sums of the prediction's pass (no viscosity terms read), with the
/// cloud's n, its fluid from fluid_begin on, h, and boundary particles carrying n0 g / c0^2.
PredictionSums predicted(const Cloud& c, std::int64_t i, std::int64_t fluid_begin = 0,
                         Vec2 hydrostatic = {}, bool clumping = true, Vec2 carried = {}) {
  const DensitySumsSetup g = setup(clumping);
  const auto& l = lattice();
  const double b = 2.0 * l.concentration_response * l.concentration_sum /
                   (2.0 * l.concentration_gradient_sum * l.n0);
  const DensityInputs d{c.n.data(), fluid_begin, hydrostatic, g.inv_f0,         g.clumping_r,
                        g.inv_w_dl, b,           carried,     c.shift_u.data(), c.shift_v.data()};
  return prediction_sums<false, true, true>(Kernel(kRe), i, c.list.of(i), c.x.data(), c.y.data(),
                                            c.u.data(), c.v.data(), d);
}

/// Index of lattice particle (i, j) of a block nx wide.
std::int64_t at(int i, int j, int nx) {
  return static_cast<std::int64_t>(j) * nx + i;
}

TEST(DensitySums, OnTheLatticeAtRest) {
  Cloud c = block(15, 15);
  std::fill(c.n.begin(), c.n.end(), lattice().n0);
  const auto i = at(7, 7, 15);
  const PredictionSums d = predicted(c, i);
  // Sums of ~40 terms of order 1: rounding.
  EXPECT_NEAR(d.n, lattice().n0, 1e-12);
  EXPECT_NEAR(d.gradient.x, 0.0, 1e-10);
  EXPECT_NEAR(d.gradient.y, 0.0, 1e-10);
  EXPECT_EQ(d.rate, 0.0);
  EXPECT_NEAR(d.lapl, 0.0, 1e-12);
}

TEST(DensitySums, BothPassesGiveTheSameNAndG) {
  // The summed-density path (at r*) and the evolved-density path (the prediction's pass at
  // r^n) write the same sums with their pair vectors the other way round.
  const Cloud c = block(15, 15, 0.2);
  for (const std::int64_t i : {at(7, 7, 15), at(3, 14, 15), at(0, 0, 15)}) {
    const DensitySums a = summed(c, i);
    const PredictionSums b = predicted(c, i);
    EXPECT_NEAR(a.n, b.n, 1e-12);
    EXPECT_NEAR(a.gradient.x, b.gradient.x, 1e-9);  // |G| ~ 10 /m
    EXPECT_NEAR(a.gradient.y, b.gradient.y, 1e-9);
  }
}

/// A jittered block in a shearing, compressing flow u (and the shift's velocities, if `swirl`: a
/// displacement of their own that u does not carry).
Cloud flowing_block(bool swirl) {
  Cloud c = block(15, 15, 0.2);
  for (std::int64_t k = 0; k < c.size(); ++k) {
    c.u[k] = 0.3 * c.y[k] - 0.8 * c.x[k] + 0.05;
    c.v[k] = -0.4 * c.x[k] + 0.6 * c.y[k];
    if (swirl) {
      c.shift_u[k] = 0.02 * std::sin(300.0 * c.y[k]);
      c.shift_v[k] = 0.02 * std::cos(250.0 * c.x[k]);
    }
  }
  return c;
}

/// dn/dt of particle i's summed n under the particles' whole motion, u plus the shift's
/// velocities: a central difference of the sums at r -+ dt (u + s), O(dt^2).
double summed_rate(const Cloud& c, std::int64_t i) {
  const double dt = 1e-6;
  auto summed_at = [&](double s) {
    Cloud m = c;
    for (std::int64_t k = 0; k < m.size(); ++k) {
      m.x[k] += s * dt * (c.u[k] + c.shift_u[k]);
      m.y[k] += s * dt * (c.v[k] + c.shift_v[k]);
    }
    return summed(m, i).n;  // the lists of c still hold every pair
  };
  return (summed_at(1.0) - summed_at(-1.0)) / (2.0 * dt);
}

TEST(DensitySums, TheRateIsTheTimeDerivativeOfTheSum) {
  // R is dn/dt of the summed n, which a central difference of the sums measures.
  const Cloud c = flowing_block(false);
  const auto i = at(7, 7, 15);
  const double rate = predicted(c, i).rate;
  const double fd = summed_rate(c, i);
  ASSERT_GT(std::abs(rate), 0.3);  // the flow does compress this neighbourhood (n0 ~ 3)
  // dt^2 |d3n/dt3| ~ 1e-12 * (u/DL)^3 ~ 1e-5 relative; rounding of n / dt ~ 1e-10.
  EXPECT_NEAR(rate, fd, 1e-5 * std::abs(rate));
}

TEST(DensitySums, TheRateFollowsTheShiftToo) {
  // The same flow with a shift on top of it: R is dn/dt of the summed n under the particles'
  // whole motion, u plus the shift's velocity, so that the carried n stays the arrangement's.
  const Cloud c = flowing_block(true);
  const auto i = at(7, 7, 15);
  const double rate = predicted(c, i).rate;
  const double fd = summed_rate(c, i);
  // The shift changes the rate by far more than the tolerance: without it the test fails.
  ASSERT_GT(std::abs(predicted(flowing_block(false), i).rate - fd), 0.01 * std::abs(fd));
  // As above: dt^2 |d3n/dt3| and rounding, 1e-5 relative.
  EXPECT_NEAR(rate, fd, 1e-5 * std::abs(rate));
}

#if WCMPS_PAIRS_AVX512
/// The AVX-512 pass against the portable loop for every fluid particle of a flowing, jittered
/// block with its first `fluid_begin` particles as boundary: lists of 8 to 40 pairs, so every
/// remainder of a vector of eight.
/// kSlip: the boundary particles are a free-slip wall's, with tangents of every direction
/// (physics/WallSlip_Colagrossi2003.h), fluid particles' tangents 0.
template <bool kShift, bool kSlip = false>
void expect_avx512_matches_portable(std::int64_t fluid_begin) {
  Cloud c = flowing_block(kShift);
  for (std::int64_t k = 0; k < c.size(); ++k) {
    c.n[k] = lattice().n0 * (1.0 + 0.01 * std::sin(200.0 * c.x[k] + 90.0 * c.y[k]));
  }
  std::vector<double> tx(static_cast<std::size_t>(c.size()), 0.0), ty = tx;
  for (std::int64_t k = 0; k < fluid_begin; ++k) {
    tx[static_cast<std::size_t>(k)] = std::cos(0.7 * static_cast<double>(k));
    ty[static_cast<std::size_t>(k)] = std::sin(0.7 * static_cast<double>(k));
  }
  const SlipInputs slip = kSlip ? SlipInputs{tx.data(), ty.data()} : SlipInputs{};
  const DensitySumsSetup g = setup(true);
  const DensityInputs d{c.n.data(), fluid_begin, {0.0, -3e-4}, g.inv_f0,         g.clumping_r,
                        g.inv_w_dl, 0.05,        {0.0, 2e-4},  c.shift_u.data(), c.shift_v.data()};
  PairRows rows;
  pack_prediction_rows(rows, c.size(), c.x.data(), c.y.data(), c.u.data(), c.v.data(), c.n.data(),
                       kShift ? c.shift_u.data() : nullptr, kShift ? c.shift_v.data() : nullptr,
                       fluid_begin, slip);
  std::vector<PredictionSums> portable, avx;
  for (std::int64_t i = fluid_begin; i < c.size(); ++i) {
    portable.push_back(prediction_sums<true, true, kShift, kSlip>(
        Kernel(kRe), i, c.list.of(i), c.x.data(), c.y.data(), c.u.data(), c.v.data(), d, slip));
    avx.push_back(
        prediction_sums_avx512<kShift, kSlip>(Kernel(kRe), i, c.list.of(i), rows.data(), d));
  }
  if constexpr (kSlip) {
    // The walls' tangents do change the artificial viscosity's sums: without them the
    // comparison would not see the slip's lanes.
    double changed = 0.0;
    for (std::int64_t i = fluid_begin; i < c.size(); ++i) {
      const auto no_slip = prediction_sums<true, true, kShift>(
          Kernel(kRe), i, c.list.of(i), c.x.data(), c.y.data(), c.u.data(), c.v.data(), d);
      changed = std::max(
          changed, std::abs(no_slip.q.x - portable[static_cast<std::size_t>(i - fluid_begin)].q.x));
    }
    ASSERT_GT(changed, 0.0);
  }
  const std::vector<double (*)(const PredictionSums&)> fields = {
      [](const PredictionSums& p) { return p.lap.x; },
      [](const PredictionSums& p) { return p.lap.y; },
      [](const PredictionSums& p) { return p.q.x; },
      [](const PredictionSums& p) { return p.q.y; },
      [](const PredictionSums& p) { return p.rate; },
      [](const PredictionSums& p) { return p.lapl; },
      [](const PredictionSums& p) { return p.n; },
      [](const PredictionSums& p) { return p.gradient.x; },
      [](const PredictionSums& p) { return p.gradient.y; }};
  for (std::size_t f = 0; f < fields.size(); ++f) {
    double largest = 0.0;
    for (const auto& p : portable) largest = std::max(largest, std::abs(fields[f](p)));
    ASSERT_GT(largest, 0.0) << "sum " << f;
    for (std::size_t k = 0; k < portable.size(); ++k) {
      // The same terms added in another order (eight lanes, then across them) and fused
      // differently: at most a few ulp of the largest term per addition, 40 additions.
      EXPECT_NEAR(fields[f](avx[k]), fields[f](portable[k]), 1e-12 * largest)
          << "sum " << f << ", particle " << k + static_cast<std::size_t>(fluid_begin)
          << ", list of " << c.list.of(static_cast<std::int64_t>(k) + fluid_begin).size();
    }
  }
}

TEST(PredictionSumsAvx512, MatchesThePortableLoop) {
  expect_avx512_matches_portable<false>(20);
  expect_avx512_matches_portable<true>(20);
}

TEST(PredictionSumsAvx512, MatchesThePortableLoopAtFreeSlipWalls) {
  expect_avx512_matches_portable<false, true>(20);
  expect_avx512_matches_portable<true, true>(20);
}

TEST(PredictionSumsAvx512, MatchesThePortableLoopWithoutBoundary) {
  // The spare lanes of a list's last vector read particle 0, here a fluid particle.
  expect_avx512_matches_portable<false>(0);
  expect_avx512_matches_portable<true>(0);
}

/// The AVX-512 variational gradient against the portable loops, plain and with the band's
/// correctors, for every fluid particle of a jittered block whose first 20 particles are
/// boundary: q of both signs, correctors on about half of the particles (0 on boundary ones).
template <bool kCorrected>
void expect_gradient_matches_portable() {
  const Cloud c = block(15, 15, 0.2);
  const std::int64_t fluid_begin = 20;
  std::vector<double> q(c.x.size()), axx(c.x.size()), axy(c.x.size()), ayy(c.x.size());
  for (std::size_t k = 0; k < q.size(); ++k) {
    q[k] = 1e3 * std::sin(150.0 * c.x[k] - 70.0 * c.y[k]);
    const bool corrected = static_cast<std::int64_t>(k) >= fluid_begin && k % 2 == 0;
    axx[k] = corrected ? 0.1 * q[k] * std::cos(90.0 * c.y[k]) : 0.0;
    axy[k] = corrected ? 0.05 * q[k] : 0.0;
    ayy[k] = corrected ? -0.07 * q[k] : 0.0;
  }
  const auto& lc = lattice();
  const MpsOperators ops(kRe, 2, lc.n0, lc.lambda, lc.gradient_correction);
  const DensityRate_Randles1996::Excess excess{axx.data(), axy.data(), ayy.data(), nullptr, 0};
  PairRows rows;
  pack_gradient_rows(rows, c.size(), c.x.data(), c.y.data(), q.data(), axx.data(), axy.data(),
                     ayy.data());
  std::vector<Vec2> portable, avx;
  double largest = 0.0;
  for (std::int64_t i = fluid_begin; i < c.size(); ++i) {
    const double ti = std::abs(q[static_cast<std::size_t>(i)]);  // the switch's own term
    const Vec2 p =
        kCorrected
            ? DensityRate_Randles1996::gathered_gradient(Kernel(kRe), i, c.list.of(i), c.x.data(),
                                                         c.y.data(), q.data(), ti, excess) *
                  (lc.gradient_correction * lc.n0)
            : ops.gradient_variational(i, c.list.of(i), c.x.data(), c.y.data(), q.data(), ti);
    portable.push_back(p);
    avx.push_back(
        variational_gradient_avx512<kCorrected>(Kernel(kRe), i, c.list.of(i), rows.data(), ti) *
        (lc.gradient_correction * lc.n0));
    largest = std::max({largest, std::abs(p.x), std::abs(p.y)});
  }
  ASSERT_GT(largest, 0.0);
  for (std::size_t k = 0; k < portable.size(); ++k) {
    // The same terms in another order and fused differently: a few ulp of the largest term per
    // addition, 40 additions.
    EXPECT_NEAR(avx[k].x, portable[k].x, 1e-12 * largest) << "particle " << k;
    EXPECT_NEAR(avx[k].y, portable[k].y, 1e-12 * largest) << "particle " << k;
  }
}

TEST(PressureGradientAvx512, MatchesThePortableLoop) {
  expect_gradient_matches_portable<false>();
}

TEST(PressureGradientAvx512, MatchesThePortableLoopWithTheBandsCorrectors) {
  expect_gradient_matches_portable<true>();
}

/// The hydrostatic forms of the renormalisation through the scheme, with the rows (M summed in
/// the AVX-512 pass) and without (the portable loops), plain and with the band's correctors, on
/// a sheared jittered block under a hydrostatic q with a wave's part on top.
template <GradientRenormalisation kForm>
void expect_hydrostatic_rows_match_portable(bool corrected) {
  const Cloud c = block(15, 15, 0.15, 5);
  const std::int64_t fluid_begin = 20;
  std::vector<double> q(c.x.size()), axx(c.x.size()), axy(c.x.size()), ayy(c.x.size());
  const auto n0 = lattice().n0;
  for (std::size_t k = 0; k < q.size(); ++k) {
    q[k] = (5000.0 - 9810.0 * c.y[k] + 300.0 * std::sin(150.0 * c.x[k])) / (n0 * n0);
    const bool band = corrected && static_cast<std::int64_t>(k) >= fluid_begin && k % 3 == 0;
    axx[k] = band ? 0.1 * q[k] : 0.0;
    axy[k] = band ? -0.04 * q[k] : 0.0;
    ayy[k] = band ? 0.06 * q[k] : 0.0;
  }
  // Every particle reached by the band's correctors, or none.
  const std::vector<std::uint32_t> reached(c.x.size(), 1);
  DensityRate_Randles1996::Excess excess{};
  if (corrected) excess = {axx.data(), axy.data(), ayy.data(), reached.data(), 1};
  const auto& lc = lattice();
  const MpsOperators ops(kRe, 2, lc.n0, lc.lambda, lc.gradient_correction);
  PairRows rows;
  pack_gradient_rows(rows, c.size(), c.x.data(), c.y.data(), q.data(), axx.data(), axy.data(),
                     ayy.data());
  using G = PressureGradient_Suzuki2007<true, kForm>;
  static_assert(G::kRows);
  G portable{nullptr, nullptr, nullptr, {0.0, -9810.0}, excess};
  // "khayyer2011-strain": a rest shape for every particle (without one its term is zero), and
  // the rest shapes each pass writes, compared below.
  const std::size_t n = c.x.size();
  std::vector<double> rest_a(n, 0.004), rest_b(n, -0.003);
  std::vector<double> next_a(n, 0.0), next_b(n, 0.0), avx_next_a(n, 0.0), avx_next_b(n, 0.0);
  if constexpr (kForm == GradientRenormalisation::Strain) {
    portable.memory = {rest_a.data(), rest_b.data(), next_a.data(), next_b.data(), 0.1};
  }
  G avx = portable;
  if constexpr (kForm == GradientRenormalisation::Strain) {
    avx.memory = {rest_a.data(), rest_b.data(), avx_next_a.data(), avx_next_b.data(), 0.1};
  }
  avx.rows = rows.data();
  double largest = 0.0, largest_term = 0.0;
  std::vector<Vec2> a, b;
  for (std::int64_t i = fluid_begin; i < c.size(); ++i) {
    const auto nb = c.list.of(i);
    a.push_back(portable.gradient(ops, i, nb, c.x.data(), c.y.data(), q.data()));
    b.push_back(avx.gradient(ops, i, nb, c.x.data(), c.y.data(), q.data()));
    // The hydrostatic term itself: the test must see it (a dropped M would fail it).
    const Vec2 plain =
        PressureGradient_Suzuki2007<true>{nullptr, nullptr, nullptr, {}, excess}.gradient(
            ops, i, nb, c.x.data(), c.y.data(), q.data());
    largest_term = std::max(largest_term, std::hypot(a.back().x - plain.x, a.back().y - plain.y));
    largest = std::max({largest, std::abs(a.back().x), std::abs(a.back().y)});
  }
  ASSERT_GT(largest_term, 0.01 * 9810.0);
  for (std::size_t k = 0; k < a.size(); ++k) {
    // Another order of the same 40 terms (gradient and M): a few ulp of the largest each.
    EXPECT_NEAR(b[k].x, a[k].x, 1e-11 * largest) << "particle " << k;
    EXPECT_NEAR(b[k].y, a[k].y, 1e-11 * largest) << "particle " << k;
  }
  std::size_t advanced = 0;
  for (std::size_t k = 0; k < n; ++k) {
    // The rest shapes advanced from M's shape (M's 40 terms in another order, of order 1), or
    // none in both where M is too far from full (the block's edges).
    EXPECT_EQ(std::isnan(avx_next_a[k]), std::isnan(next_a[k])) << "particle " << k;
    if (std::isnan(next_a[k])) continue;
    ++advanced;
    EXPECT_NEAR(avx_next_a[k], next_a[k], 1e-13) << "particle " << k;
    EXPECT_NEAR(avx_next_b[k], next_b[k], 1e-13) << "particle " << k;
  }
  if constexpr (kForm == GradientRenormalisation::Strain) {
    EXPECT_GT(advanced, n / 2);
  }
}

TEST(PressureGradientAvx512, TheHydrostaticFormsMatchThePortableLoops) {
  for (const bool corrected : {false, true}) {
    expect_hydrostatic_rows_match_portable<GradientRenormalisation::Hydrostatic>(corrected);
    expect_hydrostatic_rows_match_portable<GradientRenormalisation::Deviatoric>(corrected);
    expect_hydrostatic_rows_match_portable<GradientRenormalisation::Strain>(corrected);
  }
}

TEST(DensityRateAvx512, MatchesThePortableLoop) {
  // The band's pair sums from the prediction's rows against the portable loop, every fluid
  // particle of a flowing jittered block whose first 20 particles are boundary (lists of 8 to
  // 40 pairs), and one particle placed on top of another (r = 0: it adds nothing).
  Cloud c = flowing_block(false);
  c.x[200] = c.x[201];
  c.y[200] = c.y[201];
  c.build();
  for (std::int64_t k = 0; k < c.size(); ++k) {
    c.u[k] = 0.3 * c.y[k] - 0.8 * c.x[k] + 0.05;
    c.v[k] = -0.4 * c.x[k] + 0.6 * c.y[k];
  }
  const std::int64_t fluid_begin = 20;
  PairRows rows;
  pack_prediction_rows(rows, c.size(), c.x.data(), c.y.data(), c.u.data(), c.v.data(), c.n.data(),
                       nullptr, nullptr, fluid_begin);
  using R = DensityRate_Randles1996;
  std::vector<R::Sums> portable, avx;
  double largest_b = 0.0, largest_p = 0.0;
  int boundaries = 0;
  for (std::int64_t i = fluid_begin; i < c.size(); ++i) {
    const R::Sums p = R::sums(Kernel(kRe), i, c.list.of(i), c.x.data(), c.y.data(), c.u.data(),
                              c.v.data(), fluid_begin);
    portable.push_back(p);
    avx.push_back(R::sums_avx512(Kernel(kRe), i, c.list.of(i), rows.data(), fluid_begin));
    largest_b =
        std::max({largest_b, std::abs(p.bxu), std::abs(p.bxv), std::abs(p.byu), std::abs(p.byv)});
    largest_p = std::max({largest_p, std::abs(p.pxx), std::abs(p.pxy), std::abs(p.pyy)});
    boundaries += p.boundary ? 1 : 0;
  }
  ASSERT_GT(largest_b, 0.0);
  ASSERT_GT(boundaries, 0);  // some have a boundary particle within re, most do not
  ASSERT_LT(boundaries, static_cast<int>(portable.size()) / 2);
  for (std::size_t k = 0; k < portable.size(); ++k) {
    const R::Sums& a = avx[k];
    const R::Sums& p = portable[k];
    EXPECT_TRUE(std::isfinite(a.bxu + a.pxx)) << "particle " << k;
    // Another order of the same 40 terms: a few ulp of the largest per addition.
    EXPECT_NEAR(a.bxu, p.bxu, 1e-12 * largest_b) << "particle " << k;
    EXPECT_NEAR(a.bxv, p.bxv, 1e-12 * largest_b) << "particle " << k;
    EXPECT_NEAR(a.byu, p.byu, 1e-12 * largest_b) << "particle " << k;
    EXPECT_NEAR(a.byv, p.byv, 1e-12 * largest_b) << "particle " << k;
    EXPECT_NEAR(a.pxx, p.pxx, 1e-12 * largest_p) << "particle " << k;
    EXPECT_NEAR(a.pxy, p.pxy, 1e-12 * largest_p) << "particle " << k;
    EXPECT_NEAR(a.pyy, p.pyy, 1e-12 * largest_p) << "particle " << k;
    EXPECT_EQ(a.boundary, p.boundary) << "particle " << k;
  }
}
#endif

TEST(DensitySums, TheShiftingGradientIgnoresTheWatersCompression) {
  // A column compressed row by row to the hydrostatic n/n0 = s(depth) of the equation of state
  // (as the scene builder lays it), c0 = 30 m/s as in the cases (0.1 % per metre), each particle
  // carrying that n. G of the arrangement alone (the summed-density path) is the still water's
  // own concentration gradient, kappa ds/dy; the evolved-density path takes the carried n's
  // gradient out of it, to the first order of the strain between neighbours.
  const double g = 9.81, c0 = 30.0, n0 = lattice().n0;
  const auto s_of = [&](double depth) {
    return std::pow(1.0 + 7.0 * g * depth / (c0 * c0), 1.0 / 7.0);
  };
  Cloud c;
  std::vector<double> ratio;
  double y = 0.0;
  const int nx = 15, ny = 40;
  for (int j = 0; j < ny; ++j) {
    const double depth = (ny - j) * kDl;
    for (int i = 0; i < nx; ++i) {
      c.add(i * kDl, y);
      ratio.push_back(s_of(depth));
    }
    y += row_spacing_for_density_ratio(kDl, kRe, s_of(depth - 0.5 * kDl));
  }
  c.build();
  for (std::int64_t k = 0; k < c.size(); ++k) c.n[k] = n0 * ratio[k];
  const auto i = at(7, 20, nx);
  const Vec2 raw = summed(c, i, false).gradient;
  const double expected = -lattice().concentration_response * std::pow(ratio[i], 1.0 - 7.0) * g /
                          (c0 * c0);  // towards the denser water below
  EXPECT_NEAR(raw.x, 0.0, 1e-9);
  EXPECT_NEAR(raw.y, expected, 0.03 * std::abs(expected));
  // The continuum's kappa is 1; the lattice's is close to it (1.007 at re = 3.5 DL).
  EXPECT_NEAR(lattice().concentration_response, 1.0, 0.05);
  const Vec2 carried = predicted(c, i, 0, {}, false).gradient;
  EXPECT_NEAR(carried.y, 0.0, 0.05 * std::abs(expected));
}

TEST(DensityDiffusion, LeavesTheHydrostaticGradientAloneNextToAWall) {
  // Water on a bed: the rows above y = 0 are fluid, those below are wall and ghost particles
  // (not diffused across). n is the hydrostatic field n0 (1 + g (H - y) / c0^2).
  const int nx = 15, ny = 14;
  Cloud c;
  for (int j = -4; j < ny - 4; ++j) {
    for (int i = 0; i < nx; ++i) c.add(i * kDl, j * kDl);
  }
  c.build();
  const double n0 = lattice().n0, g = 9.81, c0 = 20.0, H = 0.2;
  for (std::int64_t k = 0; k < c.size(); ++k) c.n[k] = n0 * (1.0 + g * (H - c.y[k]) / (c0 * c0));
  const std::int64_t fluid_begin = 4 * nx;  // rows below y = 0 come first
  const Vec2 fourtakas = Vec2{0.0, -g} * (n0 / (c0 * c0)), molteni{};
  const auto bottom = fluid_begin + 7;  // on the first fluid row, mid-tank
  const auto middle = fluid_begin + 5 * nx + 7;
  const auto lapl = [&](std::int64_t i, Vec2 h) { return predicted(c, i, fluid_begin, h).lapl; };
  // Fourtakas et al. (2019): the hydrostatic part is removed pair by pair, so zero anywhere
  // (to the rounding of terms ~1e-3).
  EXPECT_NEAR(lapl(bottom, fourtakas), 0.0, 1e-14);
  EXPECT_NEAR(lapl(middle, fourtakas), 0.0, 1e-14);
  // Molteni & Colagrossi (2009): zero in the middle (the field is linear), not against the wall,
  // where only the side above is summed: the gradient is diffused away there.
  EXPECT_NEAR(lapl(middle, molteni), 0.0, 1e-14);
  EXPECT_LT(lapl(bottom, molteni), -1e-5);
}

TEST(DensityDiffusion, SmoothsABump) {
  Cloud c = block(15, 15);
  const double n0 = lattice().n0;
  std::fill(c.n.begin(), c.n.end(), n0);
  const auto i = at(7, 7, 15);
  c.n[i] = 1.01 * n0;
  const PredictionSums d = predicted(c, i);
  const auto step = NumberDensity_Jandaghian2020::make(0.1, kRe, 20.0, lattice().lambda, n0);
  const double dt = 0.4 * kDl / 20.0;
  const double next = step.advance(c.n[i], d.rate, d.lapl, dt);
  // The bump decays, and by less than itself in one step (the explicit diffusion is stable:
  // its factor times dt times sum W is delta/2 * 0.4 * 2d/(lambda/DL^2) ~ 0.04).
  EXPECT_LT(next, c.n[i]);
  EXPECT_GT(next, n0);
}

/// Flags of a cloud under either rule; `sums_n` and `grad` from one pass.
struct Flags {
  std::vector<bool> threshold, scan;
};
Flags flags(const Cloud& c) {
  const FreeSurface_Koshizuka1996 rule{0.97, lattice().n0};
  const FreeSurface_Marrone2010 scan{0.97, lattice().n0, 0.5 * kRe};
  Flags f;
  for (std::int64_t i = 0; i < c.size(); ++i) {
    const DensitySums d = summed(c, i, false);
    f.threshold.push_back(rule.is_surface(d.n));
    f.scan.push_back(scan.is_surface(i, c.list.of(i), c.x.data(), c.y.data(), d.n, d.gradient));
  }
  return f;
}

TEST(FreeSurfaceScan, FlagsTheTopOfAJitteredBlockAndNothingDeeperThanRe) {
  // A block 40 x 30 with free sides and top, jittered by up to +-0.2 DL. Interior: every particle
  // farther than re from the block's edges.
  const int nx = 40, ny = 30;
  for (const unsigned seed : {1u, 2u, 3u}) {
    const Cloud c = block(nx, ny, 0.2, seed);
    const Flags f = flags(c);
    int interior_threshold = 0, interior_scan = 0, top_scan = 0;
    for (int j = 0; j < ny; ++j) {
      for (int i = 0; i < nx; ++i) {
        const auto k = at(i, j, nx);
        const double edge = std::min({i, nx - 1 - i, j, ny - 1 - j}) * kDl;
        if (edge > kRe) {
          interior_threshold += f.threshold[k];
          interior_scan += f.scan[k];
        }
        if (j == ny - 1) top_scan += f.scan[k];
      }
    }
    EXPECT_EQ(interior_scan, 0) << "seed " << seed;
    EXPECT_EQ(top_scan, nx) << "seed " << seed;
    // The threshold of Eq. 2.10 does flag interior particles of the same block: the scan is
    // what keeps them in the water.
    EXPECT_GT(interior_threshold, 0) << "seed " << seed;
  }
}

TEST(FreeSurfaceScan, AnExpandedInteriorIsNotASurface) {
  // A wake: the middle of a block stretched by 3 % in both directions, so its particles sit at
  // n < 0.97 n0 with particles all round. The threshold flags them; the scan must not.
  const int nx = 40, ny = 40;
  Cloud c;
  for (int j = 0; j < ny; ++j) {
    for (int i = 0; i < nx; ++i) {
      const double cx = (i - 19.5) * kDl, cy = (j - 19.5) * kDl;
      const double r = std::hypot(cx, cy);
      const double s = r < 0.1 ? 1.03 : 1.0 + 0.03 * std::max(0.0, 1.0 - (r - 0.1) / 0.05);
      c.add(cx * s, cy * s);
    }
  }
  c.build();
  const Flags f = flags(c);
  int middle_threshold = 0, middle_scan = 0;
  for (std::int64_t k = 0; k < c.size(); ++k) {
    if (std::hypot(c.x[k], c.y[k]) < 0.08) {
      middle_threshold += f.threshold[k];
      middle_scan += f.scan[k];
    }
  }
  EXPECT_GT(middle_threshold, 10);
  EXPECT_EQ(middle_scan, 0);
}

TEST(FreeSurfaceScan, TheRegionHoldsTheConeAndTheDiscAndOnlyWhatFillsIt) {
  // The vectorised test (one selected signed distance per pair, every pair's fills read)
  // against Marrone et al.'s region written out with vectors, one neighbour at a time: points
  // all over the list's reach, random directions, and one neighbour in three not filling.
  const double h = 0.5 * kRe;
  const FreeSurface_Marrone2010 scan{0.97, lattice().n0, h};
  std::mt19937 gen(7);
  std::uniform_real_distribution<double> coord(-1.2 * kRe, 1.2 * kRe),
      angle(0.0, 6.283185307179586);
  const double x[2] = {0.3, 0.0}, y[2] = {0.2, 0.0};
  std::vector<double> xs(x, x + 2), ys(y, y + 2);
  const std::int32_t one[1] = {1};
  int in_region = 0, blocked = 0;
  for (int k = 0; k < 20000; ++k) {
    const double a = angle(gen);
    const Vec2 nu{std::cos(a), std::sin(a)}, tau{-nu.y, nu.x};
    const Vec2 ri{xs[0], ys[0]}, rj{xs[0] + coord(gen), ys[0] + coord(gen)};
    xs[1] = rj.x;
    ys[1] = rj.y;
    const Vec2 d = rj - ri, t = ri + nu * h, dt = rj - t;
    const bool in = dot(d, d) >= 2.0 * h * h ? dot(dt, dt) < h * h
                                             : std::abs(dot(nu, dt)) + std::abs(dot(tau, dt)) < h;
    const bool fills = k % 3 != 0;
    const bool empty = scan.region_empty(0, IdRange{one, one + 1}, xs.data(), ys.data(), nu,
                                         [&](std::int32_t) { return fills; });
    EXPECT_EQ(empty, !(in && fills)) << "point " << k << " at " << d.x << ", " << d.y;
    in_region += in;
    blocked += in && fills;
  }
  // The draw covers both sides of the test.
  EXPECT_GT(in_region, 1000);
  EXPECT_GT(blocked, 500);
}

TEST(FreeSurfaceScan, WitnessesGiveTheScansAnswerWithAFractionOfItsPairs) {
  // A jittered block (candidates along a normal and, where G is small, along the four axes), its
  // particles then moved a little as in a step: the flags with witnesses (random indices at
  // first, the last scan's fillers then) are the flags of the scan alone, and in the second
  // pass the witnesses spare most of the pair tests of the candidates inside the water (each
  // test reads fills once; a surface particle's empty region is scanned whole either way).
  const FreeSurface_Marrone2010 scan{0.97, lattice().n0, 0.5 * kRe};
  constexpr int kSlots = FreeSurface_Marrone2010::kWitnesses;
  for (const unsigned seed : {1u, 2u, 3u}) {
    Cloud c = block(30, 20, 0.2, seed);
    std::mt19937 rng(seed);
    std::uniform_int_distribution<std::int32_t> any(0, static_cast<std::int32_t>(c.size() - 1));
    std::vector<std::int32_t> witness(static_cast<std::size_t>(c.size()) * kSlots);
    for (auto& w : witness) w = any(rng);
    std::uniform_real_distribution<double> nudge(-0.01 * kDl, 0.01 * kDl);
    for (int pass = 0; pass < 2; ++pass) {
      if (pass == 1) {  // a step's move, within the lists' skin
        for (std::int64_t k = 0; k < c.size(); ++k) c.x[k] += nudge(rng), c.y[k] += nudge(rng);
      }
      long reads = 0, reads_witnessed = 0, inside = 0, inside_witnessed = 0;
      int surface = 0;
      for (std::int64_t i = 0; i < c.size(); ++i) {
        const DensitySums d = summed(c, i, false);
        const long before = reads, before_witnessed = reads_witnessed;
        const bool plain = scan.is_surface(i, c.list.of(i), c.x.data(), c.y.data(), d.n, d.gradient,
                                           [&](std::int32_t) { return ++reads > 0; });
        const bool with = scan.is_surface(
            i, c.list.of(i), c.x.data(), c.y.data(), d.n, d.gradient,
            [&](std::int32_t) { return ++reads_witnessed > 0; }, &witness[i * kSlots]);
        ASSERT_EQ(with, plain) << "seed " << seed << ", pass " << pass << ", particle " << i;
        surface += plain;
        if (!plain) {
          inside += reads - before;
          inside_witnessed += reads_witnessed - before_witnessed;
        }
      }
      EXPECT_GT(surface, 0);
      if (pass == 1) {
        EXPECT_GT(inside, 500) << seed;  // candidates inside the water, scanned
        EXPECT_LT(inside_witnessed * 5, inside) << seed;
      }
    }
  }
}

TEST(FreeSurfaceScan, ALoneParticleAndAThreadAreSurface) {
  Cloud c;
  c.add(0.5, 0.5);                                   // alone
  for (int i = 0; i < 10; ++i) c.add(i * kDl, 0.0);  // a thread one particle thick
  c.build();
  const Flags f = flags(c);
  for (std::int64_t k = 0; k < c.size(); ++k) EXPECT_TRUE(f.scan[k]) << k;
}

TEST(Shifting, MakesAJitteredInteriorMoreRegular) {
  // Shifting steps (|u|max dt = 0.05 DL each) on a jittered block: the spread of the summed n
  // over the interior shrinks.
  Cloud c = block(30, 30, 0.15);
  const ParticleShifting_Sun2017 shifting{0.5 * kRe};
  auto spread = [&](const Cloud& m) {
    double s = 0.0, s2 = 0.0;
    int count = 0;
    for (int j = 8; j < 22; ++j) {
      for (int i = 8; i < 22; ++i) {
        const double n = summed(m, at(i, j, 30)).n;
        s += n, s2 += n * n, ++count;
      }
    }
    return std::sqrt(s2 / count - (s / count) * (s / count));
  };
  const double before = spread(c);
  for (int step = 0; step < 20; ++step) {
    std::vector<Vec2> dr(c.x.size());
    for (std::int64_t k = 0; k < c.size(); ++k) {
      dr[k] = shifting.shift(summed(c, k).gradient, 1.0, 0.05 * kDl, {});
    }
    for (std::int64_t k = 0; k < c.size(); ++k) {
      c.x[k] += dr[k].x;
      c.y[k] += dr[k].y;
    }
    c.build();
  }
  EXPECT_LT(spread(c), 0.5 * before);
}

TEST(Shifting, MovesSurfaceParticlesAlongTheSurfaceOnly) {
  Cloud c = block(20, 10, 0.1);
  const ParticleShifting_Sun2017 shifting{0.5 * kRe};
  const auto top = at(10, 9, 20);
  const Vec2 g = summed(c, top).gradient;
  const Vec2 free = shifting.shift(g, 1.0, 0.05 * kDl, {});
  const Vec2 along = shifting.shift(g, 1.0, 0.05 * kDl, {0.0, 1.0});
  // Unprojected, the top particle is pulled out of the water; projected, its normal move is 0
  // and its tangential move is kept.
  EXPECT_GT(free.y, 0.0);
  EXPECT_EQ(along.y, 0.0);
  EXPECT_EQ(along.x, free.x);
}

/// The particle collision of the tests: l0 = DL, lambda 0.05, p_min 100 Pa, p_max 10 kPa.
ParticleCollision_Jandaghian2021 dpc() {
  return {kDl, 0.05, 100.0, 10000.0, 1000.0};
}

TEST(ParticleCollision, LeavesTheLatticeAlone) {
  // Pairs DL apart are at the collision distance, where the weight vanishes: water at rest on
  // its lattice is not touched, under any pressure.
  Cloud c = block(9, 9);
  const std::vector<double> p(c.x.size(), 5000.0);
  c.u.assign(c.x.size(), 0.3);  // a uniform flow: no pair approaches
  for (const std::int64_t i : {at(4, 4, 9), at(0, 0, 9), at(8, 3, 9)}) {
    const Vec2 du = dpc().change(i, c.list.of(i), c.x.data(), c.y.data(), c.u.data(), c.v.data(),
                                 p.data(), 0, 1.0e-4);
    // Zero up to the round-off of the lattice's coordinates: a pair 1e-18 m inside l0 weighs
    // (1 - q)^4 ~ 1e-60, a change of ~1e-32 m/s (against 1e-3 m/s of a pair at 0.9 DL).
    EXPECT_NEAR(du.x, 0.0, 1e-20);
    EXPECT_NEAR(du.y, 0.0, 1e-20);
  }
}

TEST(ParticleCollision, AnApproachingPairLosesItsApproachAndKeepsItsMomentum) {
  Cloud c;
  c.add(0.0, 0.0);
  c.add(0.4 * kDl, 0.0);
  c.build();
  c.u = {1.0, -0.5};
  c.v = {0.3, 0.1};
  const std::vector<double> p(2, 2000.0);
  const auto change = [&](std::int64_t i) {
    return dpc().change(i, c.list.of(i), c.x.data(), c.y.data(), c.u.data(), c.v.data(), p.data(),
                        0, 1.0e-4);
  };
  const Vec2 a = change(0), b = change(1);
  // Inside l0/2 the whole approach speed (1.5 m/s along x) goes, half from each; the motion
  // across the pair's line is kept, and so is the pair's momentum.
  EXPECT_NEAR(c.u[0] + a.x, c.u[1] + b.x, 1e-12);
  EXPECT_NEAR(a.x, -0.75, 1e-12);
  EXPECT_EQ(a.y, 0.0);
  EXPECT_EQ(b.y, 0.0);
  EXPECT_NEAR(a.x + b.x, 0.0, 1e-12);
}

TEST(ParticleCollision, PartsAPairAtTheSurfaceByTheLeastPressure) {
  // Two surface particles (p = 0) at rest DL/2 apart: parted by p_min, equal and opposite.
  Cloud c;
  c.add(0.0, 0.0);
  c.add(0.0, 0.5 * kDl);
  c.build();
  const std::vector<double> p(2, 0.0);
  const double dt = 1.0e-4;
  const auto change = [&](std::int64_t i) {
    return dpc().change(i, c.list.of(i), c.x.data(), c.y.data(), c.u.data(), c.v.data(), p.data(),
                        0, dt);
  };
  const Vec2 a = change(0), b = change(1);
  // chi = 1 at l0/2: du = dt / rho p_min / r, along the pair's line.
  EXPECT_NEAR(a.y, -dt / 1000.0 * 100.0 / (0.5 * kDl), 1e-15);
  EXPECT_EQ(a.x, 0.0);
  EXPECT_NEAR(a.y + b.y, 0.0, 1e-15);
  // Deep in the water a pair's own pressure sets it, up to lambda p_max: 0.05 x 10 kPa.
  const std::vector<double> deep(2, 20000.0);
  const Vec2 d = dpc().change(0, c.list.of(0), c.x.data(), c.y.data(), c.u.data(), c.v.data(),
                              deep.data(), 0, dt);
  EXPECT_NEAR(d.y, -dt / 1000.0 * 500.0 / (0.5 * kDl), 1e-15);
}

TEST(TensileSwitch, AUniformTensionDoesNotPullParticlesTogether) {
  // A particle with a close neighbour on its right, in water at a uniform -1 kPa. The sum form
  // pulls it towards that neighbour (the tensile instability); the switch gives no force.
  Cloud c = block(15, 15);
  const auto i = at(7, 7, 15);
  c.x[i] += 0.3 * kDl;
  c.build();
  const auto& lc = lattice();
  const MpsOperators ops(kRe, 2, lc.n0, lc.lambda, lc.gradient_correction);
  std::vector<double> p_over_n2(c.x.size(), -1000.0 / (lc.n0 * lc.n0));
  const auto nb = c.list.of(i);
  const Vec2 plain = PressureGradient_Suzuki2007<false>{}.gradient(ops, i, nb, c.x.data(),
                                                                   c.y.data(), p_over_n2.data());
  const Vec2 switched = PressureGradient_Suzuki2007<true>{}.gradient(ops, i, nb, c.x.data(),
                                                                     c.y.data(), p_over_n2.data());
  // -grad p / rho points towards +x (the close neighbour): attraction.
  EXPECT_LT(plain.x, 0.0);
  EXPECT_EQ(switched.x, 0.0);
  EXPECT_EQ(switched.y, 0.0);
  // Under a positive pressure the switch changes nothing.
  for (double& t : p_over_n2) t = -t;
  EXPECT_EQ(PressureGradient_Suzuki2007<true>{}
                .gradient(ops, i, nb, c.x.data(), c.y.data(), p_over_n2.data())
                .x,
            PressureGradient_Suzuki2007<false>{}
                .gradient(ops, i, nb, c.x.data(), c.y.data(), p_over_n2.data())
                .x);
}

/// A block of nx x ny particles on the lattice deformed by the matrix {{a, b}, {c, d}}.
Cloud deformed_block(int nx, int ny, double a, double b, double c_, double d) {
  Cloud c;
  for (int j = 0; j < ny; ++j) {
    for (int i = 0; i < nx; ++i) c.add((a * i + b * j) * kDl, (c_ * i + d * j) * kDl);
  }
  c.build();
  return c;
}

/// p/n0^2 of the linear pressure p = p0 + gx x + gy y at every particle of c.
std::vector<double> linear_q(const Cloud& c, double p0, double gx, double gy) {
  const double n0 = lattice().n0;
  std::vector<double> q(c.x.size());
  for (std::size_t k = 0; k < q.size(); ++k) q[k] = (p0 + gx * c.x[k] + gy * c.y[k]) / (n0 * n0);
  return q;
}

/// Particle i's variational gradient of q (with the switch), as is and renormalised
/// ("khayyer2011").
std::pair<Vec2, Vec2> gradients(const Cloud& c, std::int64_t i, const std::vector<double>& q) {
  const auto& lc = lattice();
  const MpsOperators ops(kRe, 2, lc.n0, lc.lambda, lc.gradient_correction);
  const auto nb = c.list.of(i);
  return {
      PressureGradient_Suzuki2007<true>{}.gradient(ops, i, nb, c.x.data(), c.y.data(), q.data()),
      PressureGradient_Suzuki2007<true, GradientRenormalisation::Khayyer2011>{}.gradient(
          ops, i, nb, c.x.data(), c.y.data(), q.data())};
}

TEST(GradientRenormalisation, ALinearPressureOnAStrainedArrangementIsExact) {
  // The hydrostatic gradient rho g = 9810 Pa/m on a lattice sheared by 10 % and stretched by
  // 5 % along x, 3 % across (the strain a wave or a wake gives the particles). The variational
  // gradient, exact on the lattice, reads it with an error of the strain's order; renormalised,
  // it is exact to rounding.
  const Cloud c = deformed_block(15, 15, 1.05, 0.10, 0.0, 0.97);
  const double gy = -9810.0;
  // The pressure is positive everywhere here: the switch's |q_i| is q_i.
  const auto [plain, renormalised] = gradients(c, at(7, 7, 15), linear_q(c, 5000.0, 0.0, gy));
  // Rounding of ~40 terms of 1e4 Pa/m: 1e-9 of the gradient.
  EXPECT_NEAR(renormalised.x, 0.0, 1e-8 * std::abs(gy));
  EXPECT_NEAR(renormalised.y, gy, 1e-8 * std::abs(gy));
  // The plain gradient is off by more than a per cent of rho g in y or in x (strain ~ 0.1).
  EXPECT_GT(std::hypot(plain.x, plain.y - gy), 0.01 * std::abs(gy));
}

TEST(GradientRenormalisation, OnTheLatticeItIsTheVariationalGradient) {
  const Cloud c = block(15, 15);
  const auto [plain, renormalised] =
      gradients(c, at(7, 7, 15), linear_q(c, 2000.0, 300.0, -9810.0));
  // M is the identity to rounding (C is set on this lattice): the two agree to 1e-9 relative.
  EXPECT_NEAR(renormalised.x, plain.x, 1e-9 * 9810.0);
  EXPECT_NEAR(renormalised.y, plain.y, 1e-9 * 9810.0);
}

TEST(GradientRenormalisation, LeavesTheBandTheWallsAndAHalfKernelAlone) {
  // The top row of a block is within the band, and its kernel is half empty (M_yy = 0.5 and
  // below): renormalised, it would read twice the vertical gradient. Each guard (the band, the
  // walls' flag, the eigenvalue) leaves it as the variational gradient has it.
  Cloud c = deformed_block(15, 8, 1.0, 0.05, 0.0, 1.0);
  const auto& lc = lattice();
  const MpsOperators ops(kRe, 2, lc.n0, lc.lambda, lc.gradient_correction);
  const auto q = linear_q(c, 0.0, 0.0, -9810.0);
  const auto top = at(7, 7, 15);
  const auto nb = c.list.of(top);
  const Vec2 plain =
      PressureGradient_Suzuki2007<false>{}.gradient(ops, top, nb, c.x.data(), c.y.data(), q.data());
  const VariationalSums s = ops.variational_sums(top, nb, nb, c.x.data(), c.y.data(), q.data());
  EXPECT_LT(s.m.myy, GradientRenormalisation_Khayyer2011::kMinEigenvalue + 0.05);
  using Full = PressureGradient_Suzuki2007<false, GradientRenormalisation::Khayyer2011>;
  std::vector<std::uint8_t> none(c.x.size(), 0), flags(c.x.size(), 0);
  flags[top] = 1;
  const Vec2 unflagged = Full{nullptr, none.data(), none.data(), {}, {}}.gradient(
      ops, top, nb, c.x.data(), c.y.data(), q.data());
  const Vec2 flagged = Full{nullptr, flags.data(), none.data(), {}, {}}.gradient(
      ops, top, nb, c.x.data(), c.y.data(), q.data());
  // Near a wall (a boundary particle in its list) it is left out as in the band.
  const Vec2 walled = Full{nullptr, none.data(), flags.data(), {}, {}}.gradient(
      ops, top, nb, c.x.data(), c.y.data(), q.data());
  EXPECT_EQ(walled.x, plain.x);
  EXPECT_EQ(walled.y, plain.y);
  EXPECT_EQ(flagged.x, plain.x);
  EXPECT_EQ(flagged.y, plain.y);
  // Not flagged, the eigenvalue guard: the same up to the lanes' order of summation.
  EXPECT_NEAR(unflagged.x, plain.x, 1e-9 * 9810.0);
  EXPECT_NEAR(unflagged.y, plain.y, 1e-9 * 9810.0);
}

/// The parts of i's gradient over its neighbours left and right of it add up to the whole, each
/// renormalised by the whole neighbourhood (the body's share of a gradient is such a part).
template <class Gradient>
void expect_parts_add_up(const Gradient& g, const MpsOperators& ops, const Cloud& c, std::int64_t i,
                         const std::vector<double>& q) {
  const auto nb = c.list.of(i);
  std::vector<std::int32_t> left, right;
  for (const std::int32_t j : nb) (c.x[j] < c.x[i] ? left : right).push_back(j);
  const Vec2 whole = g.gradient(ops, i, nb, c.x.data(), c.y.data(), q.data());
  const Vec2 a = g.gradient_part(ops, i, nb, {left.data(), left.data() + left.size()}, c.x.data(),
                                 c.y.data(), q.data());
  const Vec2 b = g.gradient_part(ops, i, nb, {right.data(), right.data() + right.size()},
                                 c.x.data(), c.y.data(), q.data());
  EXPECT_NEAR(a.x + b.x, whole.x, 1e-8 * 9810.0);
  EXPECT_NEAR(a.y + b.y, whole.y, 1e-8 * 9810.0);
}

TEST(GradientRenormalisation, TheBodysPartsAddUpToTheWhole) {
  // The body's force is the part of a fluid particle's gradient over the body's particles; the
  // parts over a split of the neighbours must add up to the gradient over all of them, each
  // renormalised by the whole neighbourhood's M.
  const Cloud c = block(15, 15, 0.15, 3);
  const auto& lc = lattice();
  const MpsOperators ops(kRe, 2, lc.n0, lc.lambda, lc.gradient_correction);
  const auto q = linear_q(c, 4000.0, 500.0, -9810.0);
  const auto i = at(7, 7, 15);
  const auto nb = c.list.of(i);
  const PressureGradient_Suzuki2007<true, GradientRenormalisation::Khayyer2011> g{};
  expect_parts_add_up(g, ops, c, i, q);
  const Vec2 whole = g.gradient(ops, i, nb, c.x.data(), c.y.data(), q.data());
  // Jittered by 15 %, the renormalised difference part still reads the linear field exactly;
  // the rest is the own term 2 q_i sum W' e_ij, the push of an arrangement that is not symmetric
  // about i (positive pressure: the switch's |q_i| is q_i).
  const VariationalSums s = ops.variational_sums(i, nb, nb, c.x.data(), c.y.data(), q.data());
  const double own = lc.gradient_correction * lc.n0 * 2.0 * q[i];
  EXPECT_NEAR(whole.x - own * s.sx, 500.0, 1e-8 * 9810.0);
  EXPECT_NEAR(whole.y - own * s.sy, -9810.0, 1e-8 * 9810.0);
  EXPECT_GT(std::hypot(s.sx, s.sy), 0.0);
}

TEST(GradientRenormalisation, TheHydrostaticFormReadsRhoGExactly) {
  // The same strained lattice. Under the hydrostatic pressure alone the hydrostatic form reads
  // rho g exactly; a further horizontal gradient of 500 Pa/m it reads as the variational
  // gradient does, M times it (its error is the strain times 500 Pa/m, not times rho g).
  const Cloud c = deformed_block(15, 15, 1.05, 0.10, 0.0, 0.97);
  const auto& lc = lattice();
  const MpsOperators ops(kRe, 2, lc.n0, lc.lambda, lc.gradient_correction);
  const Vec2 rho_g{0.0, -9810.0};
  const auto i = at(7, 7, 15);
  const auto nb = c.list.of(i);
  using Hydrostatic = PressureGradient_Suzuki2007<true, GradientRenormalisation::Hydrostatic>;
  const Hydrostatic g{nullptr, nullptr, nullptr, rho_g, {}};
  const auto still = linear_q(c, 5000.0, 0.0, rho_g.y);
  const Vec2 read = g.gradient(ops, i, nb, c.x.data(), c.y.data(), still.data());
  EXPECT_NEAR(read.x, 0.0, 1e-8 * 9810.0);
  EXPECT_NEAR(read.y, rho_g.y, 1e-8 * 9810.0);
  const auto pushed = linear_q(c, 5000.0, 500.0, rho_g.y);
  const Vec2 both = g.gradient(ops, i, nb, c.x.data(), c.y.data(), pushed.data());
  const VariationalSums s = ops.variational_sums(i, nb, nb, c.x.data(), c.y.data(), still.data());
  EXPECT_NEAR(both.x, s.m.mxx * 500.0, 1e-8 * 9810.0);
  EXPECT_NEAR(both.y, rho_g.y + s.m.mxy * 500.0, 1e-8 * 9810.0);
  // The strain shows in M (so the checks above could fail).
  EXPECT_GT(std::abs(s.m.mxx - 1.0) + std::abs(s.m.mxy), 0.02);
  expect_parts_add_up(g, ops, c, i, pushed);
}

TEST(GradientRenormalisation, TheDeviatoricFormReadsTheShapeAndLeavesTheCompression) {
  // A wave strains the water without changing its volume. On the lattice stretched along x and
  // shortened along y (det = 1) the variational gradient reads rho g half a per cent high, the
  // error of M's deviatoric part; the deviatoric form reads it to second order in the strain (M's
  // trace moves by its square). On the lattice sheared along x it reads no horizontal force.
  // Compressed evenly, M is a multiple of I (the square lattice's fourfold symmetry), and the
  // form adds nothing: it reads rho g through the compression as the variational gradient does,
  // where the hydrostatic form reads the compression away.
  const auto& lc = lattice();
  const MpsOperators ops(kRe, 2, lc.n0, lc.lambda, lc.gradient_correction);
  const Vec2 rho_g{0.0, -9810.0};
  using Deviatoric = PressureGradient_Suzuki2007<true, GradientRenormalisation::Deviatoric>;
  using Hydrostatic = PressureGradient_Suzuki2007<true, GradientRenormalisation::Hydrostatic>;
  const Deviatoric dev{nullptr, nullptr, nullptr, rho_g, {}, {}};
  const Hydrostatic hyd{nullptr, nullptr, nullptr, rho_g, {}, {}};
  const auto i = at(7, 7, 15);
  struct Read {
    Vec2 plain, dev, hyd;
  };
  const auto read = [&](const Cloud& c) {
    const auto nb = c.list.of(i);
    const auto q = linear_q(c, 5000.0, 0.0, rho_g.y);
    return Read{
        PressureGradient_Suzuki2007<true>{}.gradient(ops, i, nb, c.x.data(), c.y.data(), q.data()),
        dev.gradient(ops, i, nb, c.x.data(), c.y.data(), q.data()),
        hyd.gradient(ops, i, nb, c.x.data(), c.y.data(), q.data())};
  };
  // The lattices are symmetric about i: the own term adds nothing, and what is compared is
  // exact to the rounding of ~40 terms, 1e-8 of rho g, unless said.
  const double tol = 1e-8 * 9810.0;
  {
    const Cloud c = deformed_block(15, 15, 1.03, 0.0, 0.0, 1.0 / 1.03);
    const Read r = read(c);
    EXPECT_GT(std::abs(r.plain.y - rho_g.y), 0.004 * 9810.0);  // M_yy = 1.005
    EXPECT_LT(std::abs(r.dev.y - rho_g.y), 0.02 * std::abs(r.plain.y - rho_g.y));
    expect_parts_add_up(dev, ops, c, i, linear_q(c, 5000.0, 500.0, rho_g.y));
  }
  {
    const Cloud c = deformed_block(15, 15, 1.0, 0.12, 0.0, 1.0);
    const Read r = read(c);
    EXPECT_GT(std::abs(r.plain.x), 0.001 * 9810.0);  // M_xy = 0.002
    EXPECT_NEAR(r.dev.x, 0.0, tol);
  }
  {
    const Cloud c = deformed_block(15, 15, 0.99, 0.0, 0.0, 0.99);
    const Read r = read(c);
    EXPECT_NEAR(r.dev.x, r.plain.x, tol);
    EXPECT_NEAR(r.dev.y, r.plain.y, tol);
    EXPECT_LT(r.plain.y, 1.02 * rho_g.y);  // M = 1.0215 I
    EXPECT_NEAR(r.hyd.y, rho_g.y, tol);
  }
}

TEST(GradientRenormalisation, TheStrainFormReadsTheShapesChangeFromItsRestShape) {
  // A particle settled into a shape (the lattice stretched along x, det = 1) has that shape as its
  // rest shape: the strain form adds nothing there, and the variational gradient reads the
  // water's weight as the settled water balances it. Strained from it (sheared as well), the form
  // adds the deviatoric form's term of the new shape less that of the rest shape. The rest shape
  // follows the shape at the rate given; a particle the form leaves out has none after the step.
  const auto& lc = lattice();
  const MpsOperators ops(kRe, 2, lc.n0, lc.lambda, lc.gradient_correction);
  const Vec2 rho_g{0.0, -9810.0};
  using Strain = PressureGradient_Suzuki2007<true, GradientRenormalisation::Strain>;
  using Deviatoric = PressureGradient_Suzuki2007<true, GradientRenormalisation::Deviatoric>;
  const Deviatoric dev{nullptr, nullptr, nullptr, rho_g, {}, {}};
  const auto i = at(7, 7, 15);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double tol = 1e-8 * 9810.0;  // the rounding of ~40 terms
  struct Read {
    Vec2 plain, dev, strain;
  };
  std::vector<double> rest_a(15 * 15, nan), rest_b(15 * 15, nan);
  std::vector<double> next_a(15 * 15, 7.0), next_b(15 * 15, 7.0);
  const auto read = [&](const Cloud& c, double rate, const std::uint8_t* band = nullptr) {
    const auto nb = c.list.of(i);
    const auto q = linear_q(c, 5000.0, 0.0, rho_g.y);
    const Strain g{
        nullptr, band,
        nullptr, rho_g,
        {},      ShapeMemory{rest_a.data(), rest_b.data(), next_a.data(), next_b.data(), rate}};
    return Read{
        PressureGradient_Suzuki2007<true>{}.gradient(ops, i, nb, c.x.data(), c.y.data(), q.data()),
        dev.gradient(ops, i, nb, c.x.data(), c.y.data(), q.data()),
        g.gradient(ops, i, nb, c.x.data(), c.y.data(), q.data())};
  };
  // No rest shape yet, and settling (rate 1): the shape becomes the rest shape, nothing added.
  const Cloud settled = deformed_block(15, 15, 1.03, 0.0, 0.0, 1.0 / 1.03);
  const Read first = read(settled, 1.0);
  EXPECT_NEAR(first.strain.x, first.plain.x, tol);
  EXPECT_NEAR(first.strain.y, first.plain.y, tol);
  EXPECT_GT(std::abs(first.dev.y - first.plain.y), 0.004 * 9810.0);  // the shape is there
  const VariationalSums m0 =
      ops.variational_sums(i, settled.list.of(i), settled.list.of(i), settled.x.data(),
                           settled.y.data(), linear_q(settled, 0.0, 0.0, 0.0).data());
  EXPECT_NEAR(next_a[i], 0.5 * (m0.m.mxx - m0.m.myy), 1e-12);
  EXPECT_NEAR(next_b[i], m0.m.mxy, 1e-12);
  // The same shape as the rest shape: still nothing added.
  rest_a = next_a;
  rest_b = next_b;
  const Read again = read(settled, 0.1);
  EXPECT_NEAR(again.strain.x, again.plain.x, tol);
  EXPECT_NEAR(again.strain.y, again.plain.y, tol);
  // Sheared from it: the deviatoric term of the new shape less the rest shape's.
  const Cloud sheared = deformed_block(15, 15, 1.03, 0.12, 0.0, 1.0 / 1.03);
  const Read r = read(sheared, 0.1);
  EXPECT_GT(std::abs(r.dev.x - r.plain.x), 0.001 * 9810.0);  // the shear's horizontal push
  EXPECT_NEAR(r.strain.x - r.plain.x, (r.dev.x - r.plain.x) - (first.dev.x - first.plain.x), tol);
  EXPECT_NEAR(r.strain.y - r.plain.y, (r.dev.y - r.plain.y) - (first.dev.y - first.plain.y), tol);
  const VariationalSums m1 =
      ops.variational_sums(i, sheared.list.of(i), sheared.list.of(i), sheared.x.data(),
                           sheared.y.data(), linear_q(sheared, 0.0, 0.0, 0.0).data());
  EXPECT_NEAR(next_a[i], rest_a[i] + 0.1 * (0.5 * (m1.m.mxx - m1.m.myy) - rest_a[i]), 1e-12);
  EXPECT_NEAR(next_b[i], rest_b[i] + 0.1 * (m1.m.mxy - rest_b[i]), 1e-12);
  // In the band: the variational gradient, and no rest shape after the step.
  std::vector<std::uint8_t> band(15 * 15, 0);
  band[i] = 1;
  const Read left_out = read(sheared, 0.1, band.data());
  EXPECT_EQ(left_out.strain.x, left_out.plain.x);
  EXPECT_EQ(left_out.strain.y, left_out.plain.y);
  EXPECT_TRUE(std::isnan(next_a[i]) && std::isnan(next_b[i]));
}

/// The rate's sums of particle i of the cloud under the velocity field u = A r (a_xx ... a_yy).
DensityRate_Randles1996::Sums rate_sums(Cloud& c, std::int64_t i, double axx, double axy,
                                        double ayx, double ayy, std::int64_t fluid_begin = 0) {
  for (std::int64_t k = 0; k < c.size(); ++k) {
    c.u[k] = axx * c.x[k] + axy * c.y[k];
    c.v[k] = ayx * c.x[k] + ayy * c.y[k];
  }
  return DensityRate_Randles1996::sums(Kernel(kRe), i, c.list.of(i), c.x.data(), c.y.data(),
                                       c.u.data(), c.v.data(), fluid_begin);
}

/// The band's rule with the lattice's m and n0, and the struck rate sqrt(g / DL).
DensityRate_Randles1996 rate_rule() {
  return {lattice().n0 / lattice().gradient_correction, lattice().n0, std::sqrt(9.81 / kDl)};
}

/// A band particle's step with nothing struck: n at n0, unchanged by the prediction.
DensityRate_Randles1996::Step calm() {
  return {lattice().n0, lattice().n0, 1e-4};
}

TEST(DensityRate, TheRowsUnderTheSurfaceReadAFlowThatKeepsItsVolumeAsNone) {
  // The trough drawn down: the water converges along the surface (x) and stretches across it
  // (y), div u = 0. Within re of the surface (the top row, the second) the summed rate weighs
  // the convergence over the stretching and reads a compression; the corrected rate reads the
  // divergence, 0.
  Cloud c = block(15, 8);
  const auto rule = rate_rule();
  for (const int row : {7, 6}) {
    const auto s = rate_sums(c, at(7, row, 15), -2.0, 0.0, 0.0, 2.0);
    // On the top row P_xx - P_yy = 0.215 m: the summed rate is 2 x 0.215 m, and 2 x 0.19 m on
    // the second row. Either is a compression of n of a per cent in about 0.05 s.
    EXPECT_GT(s.summed(), 0.3 * rule.m) << row;
    const auto l = rule.corrector(s, calm());
    EXPECT_FALSE(l.identity()) << row;
    // Rounding of ~30 terms of order m: 1e-12 of the summed rate.
    EXPECT_NEAR(DensityRate_Randles1996::rate(s, l), 0.0, 1e-12 * rule.m) << row;
  }
}

TEST(DensityRate, InsideTheWaterItIsTheSummedRate) {
  // A complete kernel on the lattice: P = m I to rounding, L = I, and the corrected rate is the
  // summed one (a general linear field, compression and shear).
  Cloud c = block(15, 15);
  const auto rule = rate_rule();
  const auto s = rate_sums(c, at(7, 7, 15), -1.5, 0.7, -0.3, 0.4);
  EXPECT_NEAR(s.pxx, rule.m, 1e-12 * rule.m);
  EXPECT_NEAR(s.pyy, rule.m, 1e-12 * rule.m);
  EXPECT_NEAR(s.summed(), 1.1 * rule.m, 1e-12 * rule.m);  // -m div u, div u = -1.1 /s
  const auto l = rule.corrector(s, calm());
  EXPECT_NEAR(l.xx, 1.0, 1e-12);
  EXPECT_NEAR(l.xy, 0.0, 1e-12);
  EXPECT_NEAR(l.yy, 1.0, 1e-12);
  EXPECT_NEAR(DensityRate_Randles1996::rate(s, l), s.summed(), 1e-12 * rule.m);
}

TEST(DensityRate, TheRenormalisationIsMTimesTheInverseOfTheFlooredMomentMatrix) {
  // L = m P_c^-1 from P's spectral projectors, against the eigenvectors' angle (the textbook
  // form, which the code used before): symmetric P's of every orientation, with neither, one or
  // both eigenvalues under the floor m / 2, and isotropic ones (no angle at all).
  const auto rule = rate_rule();
  const double m = rule.m, floor = DensityRate_Randles1996::kMinEigenvalue * m;
  int floored = 0;
  for (const double major : {1.3, 0.9, 0.7, 0.45, 0.2}) {
    for (const double minor : {1.3, 0.8, 0.5, 0.3, 0.1}) {
      if (minor > major) continue;
      for (int k = 0; k < 12; ++k) {
        const double th = 0.27 * k;  // radians, every orientation
        const double cs = std::cos(th), sn = std::sin(th);
        const double a = major * m, b = minor * m;  // P = a v1 v1^T + b v2 v2^T
        DensityRate_Randles1996::Sums s;
        s.pxx = a * cs * cs + b * sn * sn;
        s.pxy = (a - b) * cs * sn;
        s.pyy = a * sn * sn + b * cs * cs;
        const double l1 = std::max(a, floor), l2 = std::max(b, floor);
        floored += (b < floor) + (a < floor);
        const auto l = rule.renormalisation(s);
        // Rounding of a few operations on entries of order m / floor = 2.
        EXPECT_NEAR(l.xx, m * (cs * cs / l1 + sn * sn / l2), 1e-13) << major << " " << minor;
        EXPECT_NEAR(l.xy, m * cs * sn * (1.0 / l1 - 1.0 / l2), 1e-13) << major << " " << minor;
        EXPECT_NEAR(l.yy, m * (sn * sn / l1 + cs * cs / l2), 1e-13) << major << " " << minor;
      }
    }
  }
  EXPECT_GT(floored, 0);  // the floor was exercised
}

TEST(DensityRate, ABoundaryParticleWithinReKeepsTheSummedRateAndItsCorrector) {
  // The bottom two rows are boundary particles (laid on the wall's lattice), the top row (6) the
  // surface. Row 4 has a boundary particle within re (3 DL) and its kernel cut by the surface:
  // it gets its corrector (for the force) and keeps the summed rate. Row 5 has no boundary
  // particle within re: its rate is the corrected one, which reads the trough's flow (div u = 0)
  // as none.
  Cloud c = block(15, 7);
  const auto rule = rate_rule();
  const double n0 = lattice().n0;
  const std::int64_t fluid_begin = 2 * 15;
  const auto low = rate_sums(c, at(7, 4, 15), -2.0, 0.0, 0.0, 2.0, fluid_begin);
  EXPECT_TRUE(low.boundary);
  const auto low_l = rule.corrector(low, calm());
  EXPECT_FALSE(low_l.identity());
  EXPECT_EQ(DensityRate_Randles1996::band_rate(low, low_l), low.summed());
  const auto mid = rate_sums(c, at(7, 5, 15), -2.0, 0.0, 0.0, 2.0, fluid_begin);
  EXPECT_FALSE(mid.boundary);
  const auto mid_l = rule.corrector(mid, calm());
  EXPECT_GT(mid.summed(), 0.05 * rule.m);
  // Rounding of ~30 terms of order m: 1e-12 of m.
  EXPECT_NEAR(DensityRate_Randles1996::band_rate(mid, mid_l), 0.0, 1e-12 * rule.m);
  const auto top = rate_sums(c, at(7, 6, 15), -2.0, 0.0, 0.0, 2.0, fluid_begin);
  EXPECT_FALSE(top.boundary);
  EXPECT_FALSE(rule.corrector(top, calm()).identity());
  // Struck, each way: the top row squeezed across the surface at 80 /s (a sheet landing), its
  // summed rate above sqrt(g / DL) n0 = 31 n0 per second; the prediction's n rising faster
  // than that; n already 0.4 % above n0. Just under each threshold the trough is corrected.
  const auto hit = rate_sums(c, at(7, 6, 15), 0.0, 0.0, 0.0, -80.0);
  EXPECT_GT(hit.summed(), rule.struck_rate * n0);
  EXPECT_TRUE(rule.corrector(hit, calm()).identity());
  const double dt = 1e-4, limit = rule.struck_rate * n0 * dt;
  EXPECT_TRUE(rule.corrector(top, {n0, n0 + 1.01 * limit, dt}).identity());
  EXPECT_FALSE(rule.corrector(top, {n0, n0 + 0.99 * limit, dt}).identity());
  EXPECT_TRUE(rule.corrector(top, {1.004 * n0, 1.004 * n0, dt}).identity());
  EXPECT_FALSE(rule.corrector(top, {1.002 * n0, 1.002 * n0, dt}).identity());
}

TEST(DensityRate, ThePressureDoesNoWorkTheNumberDensitiesDoNotStore) {
  // The partner of the corrected rate: with q = p / n^2, the power of the pair forces of the
  // corrected gradient, sum_i u_i . C n0 sum_j (q_i L_i + q_j L_j) W' e_ij, equals
  // C n0 sum_i q_i Dn_i/Dt with the corrected rate, for any arrangement, velocities and
  // pressures. A jittered block whose top four rows are the band; the rest L = I.
  Cloud c = block(12, 9, 0.15, 5);
  const auto& lc = lattice();
  const MpsOperators ops(kRe, 2, lc.n0, lc.lambda, lc.gradient_correction);
  const auto rule = rate_rule();
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> d(-1.0, 1.0);
  std::vector<double> q(c.x.size());
  for (auto& v : q) v = 1e-3 * (2.0 + d(rng));
  // A rotation and shear with noise: rates of a few n0 per second, none struck.
  for (std::int64_t k = 0; k < c.size(); ++k) {
    c.u[k] = 0.003 * d(rng) + 0.05 * c.y[k];
    c.v[k] = 0.003 * d(rng) - 0.08 * c.x[k];
  }
  std::vector<DensityRate_Randles1996::Corrector> l(c.x.size());
  double stored = 0.0;
  int corrected = 0;
  for (std::int64_t i = 0; i < c.size(); ++i) {
    const auto s = DensityRate_Randles1996::sums(Kernel(kRe), i, c.list.of(i), c.x.data(),
                                                 c.y.data(), c.u.data(), c.v.data(), 0);
    if (c.y[i] > 4.5 * kDl) l[i] = rule.corrector(s, calm());
    corrected += l[i].identity() ? 0 : 1;
    stored += q[i] * DensityRate_Randles1996::rate(s, l[i]);
  }
  // The correctors as the gradient's pass gathers them: A = q (L - I), zero where L = I.
  std::vector<double> axx(c.x.size()), axy(c.x.size()), ayy(c.x.size());
  for (std::int64_t j = 0; j < c.size(); ++j) {
    axx[j] = q[j] * (l[j].xx - 1.0);
    axy[j] = q[j] * l[j].xy;
    ayy[j] = q[j] * (l[j].yy - 1.0);
  }
  const DensityRate_Randles1996::Excess excess{axx.data(), axy.data(), ayy.data()};
  std::vector<double> gx(c.x.size()), gy(c.x.size());
  for (std::int64_t i = 0; i < c.size(); ++i) {
    const Vec2 g = DensityRate_Randles1996::gathered_gradient(
        Kernel(kRe), i, c.list.of(i), c.x.data(), c.y.data(), q.data(), q[i], excess);
    gx[i] = g.x;
    gy[i] = g.y;
    // The excess alone plus the plain gradient is the same sum.
    const Vec2 e = DensityRate_Randles1996::gathered_excess(Kernel(kRe), i, c.list.of(i),
                                                            c.x.data(), c.y.data(), excess);
    const Vec2 p =
        ops.gradient_variational(i, c.list.of(i), c.x.data(), c.y.data(), q.data(), q[i]);
    const double scale = lc.gradient_correction * lc.n0;
    // Rounding of ~50 pair terms of either sum: 1e-12 of the largest term's size (q W' e ~ 1e-2).
    EXPECT_NEAR(p.x / scale + e.x, g.x, 1e-12);
    EXPECT_NEAR(p.y / scale + e.y, g.y, 1e-12);
  }
  double power = 0.0;
  for (std::int64_t i = 0; i < c.size(); ++i) power += c.u[i] * gx[i] + c.v[i] * gy[i];
  EXPECT_GT(corrected, 20);
  // Rounding of ~4,000 pair terms: 1e-10 of the stored power.
  EXPECT_NEAR(power, stored, 1e-10 * std::abs(stored) + 1e-15);
  // The rate alone corrected (the force plain) breaks the identity by far more.
  double plain = 0.0;
  for (std::int64_t i = 0; i < c.size(); ++i) {
    const Vec2 g =
        ops.gradient_variational(i, c.list.of(i), c.x.data(), c.y.data(), q.data(), q[i]);
    plain += (c.u[i] * g.x + c.v[i] * g.y) / (lc.gradient_correction * lc.n0);
  }
  EXPECT_GT(std::abs(plain - stored), 1e-3 * std::abs(stored));
}

TEST(DensityRate, TheWallHoldsTheBandsStress) {
  // Still water in a box on the lattice: walls three columns thick at both sides, three rows
  // under the water, as high as the water (7 rows). Every fluid particle's kernel holds the
  // lattice up to the surface, so P, L and A = q (L - I) (q hydrostatic) depend on the row
  // alone: the band's stress is uniform along the surface up to the walls and pushes no
  // particle along it that has no boundary particle within re; the particles next to a wall
  // press on it (their pairs with it carry A_i). Had the particles within re of a wall kept
  // L = I (the rule before 2026-12-07), the stress would end inside the water and push the
  // particles there along the surface.
  Cloud c;
  const int nx = 21, ny = 10, wall = 3;
  auto is_wall = [&](int i, int j) { return i < wall || i >= nx - wall || j < wall; };
  for (const bool boundary : {true, false}) {
    for (int j = 0; j < ny; ++j) {
      for (int i = 0; i < nx; ++i) {
        if (is_wall(i, j) == boundary) c.add(i * kDl, j * kDl);
      }
    }
  }
  c.build();
  const std::int64_t fluid_begin = 2 * wall * ny + (nx - 2 * wall) * wall;
  const double top = (ny - 1) * kDl, n0 = lattice().n0;
  const auto rule = rate_rule();
  std::vector<double> axx(c.x.size()), axy(c.x.size()), ayy(c.x.size());
  std::vector<char> near_wall(c.x.size());
  for (std::int64_t i = fluid_begin; i < c.size(); ++i) {
    const auto s = DensityRate_Randles1996::sums(Kernel(kRe), i, c.list.of(i), c.x.data(),
                                                 c.y.data(), c.u.data(), c.v.data(), fluid_begin);
    near_wall[i] = s.boundary;
    const auto l = rule.corrector(s, calm());
    const double q = 1000.0 * 9.81 * (top - c.y[i]) / (n0 * n0);
    axx[i] = q * (l.xx - 1.0);
    axy[i] = q * l.xy;
    ayy[i] = q * (l.yy - 1.0);
  }
  auto push = [&](std::int64_t i) {
    const DensityRate_Randles1996::Excess a{axx.data(), axy.data(), ayy.data()};
    return DensityRate_Randles1996::gathered_excess(Kernel(kRe), i, c.list.of(i), c.x.data(),
                                                    c.y.data(), a);
  };
  double across = 0.0, along_free = 0.0, along_wall = 0.0;
  for (std::int64_t i = fluid_begin; i < c.size(); ++i) {
    const Vec2 g = push(i);
    across = std::max(across, std::abs(g.y));
    double& along = near_wall[i] ? along_wall : along_free;
    along = std::max(along, std::abs(g.x));
  }
  ASSERT_GT(across, 0.0);
  // Rounding of ~40 pair terms: 1e-12 of the stress's push across the surface.
  EXPECT_LT(along_free, 1e-12 * across);
  EXPECT_GT(along_wall, 0.05 * across);
  // The rule before: A = 0 within re of a wall.
  for (std::int64_t i = fluid_begin; i < c.size(); ++i) {
    if (near_wall[i]) axx[i] = axy[i] = ayy[i] = 0.0;
  }
  double along_before = 0.0;
  for (std::int64_t i = fluid_begin; i < c.size(); ++i) {
    if (!near_wall[i]) along_before = std::max(along_before, std::abs(push(i).x));
  }
  EXPECT_GT(along_before, 0.05 * across);
}

TEST(PressureBound, ZeroClampsAndTheOthersKeepDownToTheFloor) {
  const auto zero = PressureBound::make(NegativePressure::Zero, -99e3);
  const auto keep = PressureBound::make(NegativePressure::Keep, -99e3);
  const auto sw = PressureBound::make(NegativePressure::Sun2018Switch, -5e3);
  EXPECT_EQ(zero(-300.0), 0.0);
  EXPECT_EQ(zero(300.0), 300.0);
  EXPECT_EQ(keep(-300.0), -300.0);
  EXPECT_EQ(keep(-2e5), -99e3);
  EXPECT_EQ(sw(-6e3), -5e3);
}

/// The cap of physics/SurfacePressureCap.h for every top-row particle of a block nx x ny whose
/// top row is the surface, with pressures p.
std::vector<std::optional<double>> surface_caps(const Cloud& c, int nx, int ny,
                                                const std::vector<double>& p) {
  const auto interior = [&](std::int32_t j) { return j < at(0, ny - 1, nx); };
  std::vector<std::optional<double>> caps;
  for (int i = 0; i < nx; ++i) {
    const auto s = at(i, ny - 1, nx);
    caps.push_back(SurfacePressureCap::bound(s, c.list.of(s), c.x.data(), c.y.data(), p.data(),
                                             Kernel(kRe), interior));
  }
  return caps;
}

TEST(SurfacePressureCap, LeavesStillWaterAlone) {
  // Hydrostatic pressure, the surface DL/2 over the top row: every row under the top one holds
  // more than it, so no top-row particle is capped.
  const int nx = 20, ny = 10;
  const Cloud c = block(nx, ny);
  std::vector<double> p(c.size());
  for (std::int64_t k = 0; k < c.size(); ++k) {
    p[k] = 1000.0 * 9.81 * ((ny - 1) * kDl + 0.5 * kDl - c.y[k]);
  }
  const auto caps = surface_caps(c, nx, ny, p);
  for (int i = 0; i < nx; ++i) {
    ASSERT_TRUE(caps[i].has_value()) << i;
    EXPECT_GT(*caps[i], p[at(i, ny - 1, nx)]) << i;
  }
}

TEST(SurfacePressureCap, HoldsACompressedTopRowToTheWaterUnderIt) {
  // The top row at 200 Pa over water at 60 Pa (case I's layer upslope of the block): capped to
  // the 60 Pa of the water under it, to rounding.
  const int nx = 20, ny = 10;
  const Cloud c = block(nx, ny, 0.1);
  std::vector<double> p(c.size(), 60.0);
  for (int i = 0; i < nx; ++i) p[at(i, ny - 1, nx)] = 200.0;
  const auto caps = surface_caps(c, nx, ny, p);
  for (int i = 0; i < nx; ++i) {
    ASSERT_TRUE(caps[i].has_value()) << i;
    EXPECT_NEAR(*caps[i], 60.0, 1e-9) << i;
  }
}

TEST(SurfacePressureCap, ASheetOfSurfaceParticlesKeepsItsPressure) {
  // A single row (a jet, a thin sheet): every particle is on the surface, none has water under
  // it, and none is capped (at a wall such particles carry the impact).
  const int nx = 20;
  const Cloud c = block(nx, 1);
  const std::vector<double> p(c.size(), 500.0);
  for (const auto& cap : surface_caps(c, nx, 1, p)) EXPECT_FALSE(cap.has_value());
}

TEST(SurfacePressureCap, AStruckParticleIsLeftAlone) {
  // DL 5 mm: the threshold sqrt(g / DL) = 44.3 n0 per second. Case I's draining trough raises
  // a surface particle's n by at most 0.2 n0 per second (its frames at 0.1-0.24 s,
  // docs/validation.md): capped. A particle landing at 1 m/s closes its neighbours at 1 m/s over
  // DL, about 200 n0 per second: struck. A falling n is never struck.
  const SurfacePressureCap cap = SurfacePressureCap::make(9.81, 0.005);
  EXPECT_NEAR(cap.struck_rate, std::sqrt(9.81 / 0.005), 1e-12);
  const double n0 = 3.04, dt = 1e-4;
  EXPECT_FALSE(cap.struck(n0, n0 * (1.0 + 0.2 * dt), n0, dt));
  EXPECT_FALSE(cap.struck(n0, n0 * (1.0 + 44.0 * dt), n0, dt));
  EXPECT_TRUE(cap.struck(n0, n0 * (1.0 + 45.0 * dt), n0, dt));
  EXPECT_TRUE(cap.struck(n0, n0 * (1.0 + 200.0 * dt), n0, dt));
  EXPECT_FALSE(cap.struck(n0, n0 * (1.0 - 200.0 * dt), n0, dt));
  EXPECT_FALSE(cap.struck(n0, n0, n0, 0.0));  // the start (dt = 0): the cap applies
}

TEST(SurfacePressureCap, AStruckParticleStaysStruckUntilItsNIsBack) {
  // The Lobovsky surge's tip in the corner: struck (n from 1.00 to 1.04 n0 in one step), then
  // packed further at a rate under the threshold, then relaxing. It stays struck, remembering
  // the n where the strike found it, until its n is back there; then it is capped again.
  const SurfacePressureCap cap = SurfacePressureCap::make(9.81, 0.005);
  const double n0 = 3.04, dt = 5e-5;
  double memory = cap.strike(0.0, n0, n0, n0, dt);
  EXPECT_EQ(memory, 0.0);  // nothing struck: nothing remembered
  memory = cap.strike(memory, 1.00 * n0, 1.04 * n0, n0, dt);
  EXPECT_EQ(memory, 1.00 * n0);
  memory = cap.strike(memory, 1.04 * n0, 1.0401 * n0, n0, dt);  // 2 n0 per second: slow
  EXPECT_EQ(memory, 1.00 * n0);
  memory = cap.strike(memory, 1.0401 * n0, 1.10 * n0, n0, dt);  // struck again: the first n kept
  EXPECT_EQ(memory, 1.00 * n0);
  memory = cap.strike(memory, 1.10 * n0, 1.001 * n0, n0, dt);  // relaxing, not yet back
  EXPECT_EQ(memory, 1.00 * n0);
  memory = cap.strike(memory, 1.001 * n0, 0.9999 * n0, n0, dt);  // back: capped again
  EXPECT_EQ(memory, 0.0);
}

TEST(WallDensity, TheInverseOfTheEquationOfStateGivesBackThePressure) {
  const EquationOfState_TaitShakibaeiniaJin2010 eos{1000.0, 24.0, 7.0, lattice().n0};
  for (const double p : {-50e3, -300.0, 0.0, 2943.0, 1e5}) {
    EXPECT_NEAR(eos.pressure(eos.number_density(p)), p, 1e-9 * 1e5) << p;
  }
  const WallDensity_Adami2012 wall{eos};
  EXPECT_EQ(wall.gradient_input(0.0), 0.0);  // a dry wall
  // A tension the state cannot reach (the bracket 1 + gamma p / (rho c0^2) <= 0): no pull.
  EXPECT_EQ(wall.gradient_input(-1000.0 * 24.0 * 24.0 / 7.0 - 1.0), 0.0);
}

TEST(WallDensity, AWallAtTheWatersPressurePushesItNoHarderThanTheWaterItself) {
  // Rows 0 to 6 of a block are wall, rows 7 on water, all on one lattice and at one pressure
  // (the water compressed to it: n = EOS^-1(p), as the evolved n carries it). Particle (7, 7) of
  // the first water row has a full, symmetric neighbourhood: a uniform q gives it no gradient,
  // and any force is the wall's q differing from the water's.
  const int nx = 15;
  const Cloud c = block(nx, 15);
  const auto& lc = lattice();
  const MpsOperators ops(kRe, 2, lc.n0, lc.lambda, lc.gradient_correction);
  const EquationOfState_TaitShakibaeiniaJin2010 eos{1000.0, 24.0, 7.0, lc.n0};
  const double p = 2943.0;  // 0.3 m of water
  const double n = eos.number_density(p);
  const auto gradient_at_wall_q = [&](double wall_q) {
    std::vector<double> q(c.x.size(), p / (n * n));
    for (std::int64_t k = 0; k < at(0, 7, nx); ++k) q[k] = wall_q;
    const auto i = at(7, 7, nx);
    return PressureGradient_Suzuki2007<true>{}.gradient(ops, i, c.list.of(i), c.x.data(),
                                                        c.y.data(), q.data());
  };
  const Vec2 adami = gradient_at_wall_q(WallDensity_Adami2012{eos}.gradient_input(p));
  const Vec2 at_n0 = gradient_at_wall_q(p / (lc.n0 * lc.n0));
  // At n0 the wall pushes the water up: -grad p / rho > 0, about 0.4 (n^2/n0^2 - 1) p / DL (1.1
  // m/s^2 here, a ninth of g; the bound is half of that). Round-off of sums of p/DL-sized
  // terms: 1e-12.
  EXPECT_LT(at_n0.y, -0.002 * p / kDl);
  EXPECT_NEAR(adami.x, 0.0, 1e-12 * p / kDl);
  EXPECT_NEAR(adami.y, 0.0, 1e-12 * p / kDl);
}

}  // namespace
}  // namespace wcmps
