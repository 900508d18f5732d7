// Still water in a flat tank (cases/hydrostatic): pressure against rho g (H - y), compression,
// spurious speed, and no particle through a wall. Writes hydrostatic_*.csv for
// docs/validation.md (tools/plot_validation.py draws them).

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>

#include "core/Error.h"
#include "core/Parallel.h"
#include "scene/SceneBuilder.h"
#include "simulation/Simulation.h"
#include "support/TestSupport.h"

namespace wcmps {
namespace {

struct StillWater {
  double max_speed = 0.0;        ///< over the window (m/s)
  double rms_speed = 0.0;        ///< rms over particles, largest over the window (m/s)
  double peak_rms_speed = 0.0;   ///< largest rms over the whole run (the start-up transient)
  double mean_p_error = 0.0;     ///< mean of p - rho g (H - y) over the window (Pa)
  double rms_p_error = 0.0;      ///< rms of the same over particles and window (Pa)
  double max_compression = 0.0;  ///< max of n/n0 - 1 over the window
  double centre_rise = 0.0;      ///< rise of the fluid's centre of mass over the second half (m)
  bool all_inside = true;        ///< every fluid particle inside the tank at the end
};

/// Runs `spec` to its end time, sampling every 0.05 s; statistics over the last `window`
/// seconds, for particles below the top `skin` metres (whose kernels reach above the water).
StillWater run_still_water(const CaseSpec& spec, double H, double width, double window, double skin,
                           const std::string& tag) {
  set_thread_count(2);
  Simulation sim(spec, build_scene(spec));
  const double rho_g = spec.density * -spec.gravity.y;
  StillWater r;
  std::ofstream series("hydrostatic_" + tag + "_series.csv");
  series << "t_s,rms_speed_m_s,max_speed_m_s,mean_p_error_Pa,rms_p_error_Pa,max_n_over_n0,"
            "centre_of_mass_y_m\n";
  double sum_err = 0.0, sum_err2 = 0.0, centre_half = 0.0;
  std::int64_t count = 0;
  for (double t = 0.05; t <= spec.end_time + 1e-9; t += 0.05) {
    while (sim.time() < t - 1e-12) sim.step(t);
    const ParticleSet& ps = sim.particles();
    double s2 = 0.0, smax = 0.0, e1 = 0.0, e2 = 0.0, nmax = 0.0, ysum = 0.0;
    std::int64_t ne = 0;
    for (std::int64_t i = ps.fluid_begin(); i < ps.size(); ++i) {
      const double sp = std::hypot(ps.now.u[i], ps.now.v[i]);
      s2 += sp * sp;
      smax = std::max(smax, sp);
      nmax = std::max(nmax, ps.now.n[i] / sim.operators().n0());
      ysum += ps.now.y[i];
      if (ps.now.y[i] < H - skin) {
        const double e = ps.now.p[i] - rho_g * (H - ps.now.y[i]);
        e1 += e;
        e2 += e * e;
        ++ne;
      }
    }
    const double rms = std::sqrt(s2 / static_cast<double>(ps.fluid_count()));
    const double centre = ysum / static_cast<double>(ps.fluid_count());
    r.peak_rms_speed = std::max(r.peak_rms_speed, rms);
    series << t << ',' << rms << ',' << smax << ',' << e1 / ne << ',' << std::sqrt(e2 / ne) << ','
           << nmax << ',' << centre << '\n';
    if (std::abs(t - 0.5 * spec.end_time) < 0.025) centre_half = centre;
    r.centre_rise = centre - centre_half;
    if (t >= spec.end_time - window - 1e-9) {
      r.max_speed = std::max(r.max_speed, smax);
      r.rms_speed = std::max(r.rms_speed, rms);
      r.max_compression = std::max(r.max_compression, nmax - 1.0);
      sum_err += e1;
      sum_err2 += e2;
      count += ne;
    }
  }
  r.mean_p_error = sum_err / count;
  r.rms_p_error = std::sqrt(sum_err2 / count);
  const ParticleSet& ps = sim.particles();
  std::ofstream profile("hydrostatic_" + tag + "_profile.csv");
  profile << "x_m,y_m,p_Pa,p_exact_Pa\n";
  for (std::int64_t i = ps.fluid_begin(); i < ps.size(); ++i) {
    const double x = ps.now.x[i], y = ps.now.y[i];
    r.all_inside = r.all_inside && x > 0.0 && x < width && y > 0.0;
    profile << x << ',' << y << ',' << ps.now.p[i] << ',' << std::max(0.0, rho_g * (H - y)) << '\n';
  }
  return r;
}

/// The checks, with the reasons of their tolerances:
/// - mean pressure error: 1 % of rho g H. The weight of the water fixes the mean pressure; a
///   bias beyond 1 % would be a wrong equation of state, wall or gradient.
/// - rms pressure error: 5 % of rho g H. The Tait equation turns 0.1 % of number-density noise
///   into ~2 % of rho g H at these c0 (p ~ rho c0^2 dn/n0); the rows above the bottom, whose
///   lattice was compressed against the uncompressed wall rows and has rearranged, carry most
///   of it (docs/validation.md).
/// - compression: at most 1 % (../shared/spec/cases.md: the hydrostatic density error must stay
///   <= 1 %; at c0 = 10 sqrt(2 g H) it is 0.5 %).
/// - spurious speed, after the start-up transient: rms <= 0.002 sqrt(gH), five times below the
///   0.01 sqrt(gH) of validation.md; the fastest single particle <= 0.02 sqrt(gH); and the
///   transient has decayed to a quarter of its peak rms, which shows that the still state is
///   stable, not just quiet for a while. The late rearrangements of the lattice are chaotic:
///   builds that differ only in rounding (SSE2 against AVX2 with FMA) follow one path to 1 s
///   and then differ. Four such builds measured over the last 0.5 s rms 0.0005 to 0.0013
///   sqrt(gH), single particles 0.002 to 0.014 sqrt(gH) (a particle hopping to a new place in
///   the lattice), and 0.07 to 0.18 of the peak rms (docs/validation.md).
///   Tighter bounds would test which path a build takes, not the scheme.
void expect_still(const StillWater& r, double H) {
  const double rho_g_H = 1000.0 * 9.81 * H;
  const double sqrt_gH = std::sqrt(9.81 * H);
  EXPECT_LE(std::abs(r.mean_p_error), 0.01 * rho_g_H);
  EXPECT_LE(r.rms_p_error, 0.05 * rho_g_H);
  EXPECT_LE(r.max_compression, 0.01);
  EXPECT_LE(r.rms_speed, 0.002 * sqrt_gH);
  EXPECT_LE(r.max_speed, 0.02 * sqrt_gH);
  EXPECT_LE(r.rms_speed, 0.25 * r.peak_rms_speed);
  EXPECT_TRUE(r.all_inside);
  ::testing::Test::RecordProperty("max_speed_over_sqrt_gH", std::to_string(r.max_speed / sqrt_gH));
  ::testing::Test::RecordProperty("rms_speed_over_sqrt_gH", std::to_string(r.rms_speed / sqrt_gH));
  ::testing::Test::RecordProperty("mean_p_error_over_rho_g_H",
                                  std::to_string(r.mean_p_error / rho_g_H));
  ::testing::Test::RecordProperty("rms_p_error_over_rho_g_H",
                                  std::to_string(r.rms_p_error / rho_g_H));
  std::printf(
      "still water: max speed %.4f m/s (%.4f sqrt(gH)), rms %.4f m/s (%.4f sqrt(gH))\n"
      "             start-up transient: peak rms %.4f m/s\n"
      "             pressure error mean %+.1f Pa (%+.3f %%), rms %.1f Pa (%.2f %% of rho g H)\n"
      "             max compression %.3f %%\n"
      "             centre of mass rose %+.3f mm over the second half of the run\n",
      r.max_speed, r.max_speed / sqrt_gH, r.rms_speed, r.rms_speed / sqrt_gH, r.peak_rms_speed,
      r.mean_p_error, 100 * r.mean_p_error / rho_g_H, r.rms_p_error, 100 * r.rms_p_error / rho_g_H,
      100 * r.max_compression, 1000 * r.centre_rise);
}

TEST(Hydrostatic, FlatTankDl10mm) {
  const CaseSpec spec = test::load_case("cases/hydrostatic/case.toml");
  ASSERT_DOUBLE_EQ(spec.dl, 0.01);
  ASSERT_GE(spec.end_time, 6.5);  // the start-up transient has died out by then
  // Statistics over the last 0.5 s, below the top 3.5 DL (p is clamped at zero there).
  expect_still(run_still_water(spec, 0.7, 0.5, 0.5, 0.035, "dl10mm"), 0.7);
}

/// The water keeps its volume when the shift's displacement enters the evolved n
/// ([physics] shifting_in_continuity, ParticleShifting_Sun2017.h): the fluid's centre of mass
/// rises or falls by at most 0.1 mm over the second half of a 3 s run. The particles' masses are
/// fixed, so the centre moves by (H/2) dV/V: 0.1 mm is dV/V = 0.03 %, an eighth of the water's
/// mean compression under its own weight (0.25 %), which the start-up settles in the first
/// second. With the shift left out of n (the default) the centre rose 0.55 mm over 1.5-3 s and
/// 0.60 mm over 3.5-7 s; with it, -0.05 and -0.02 mm (2026-12-03).
TEST(Hydrostatic, ShiftingInContinuityKeepsTheVolume) {
  CaseSpec spec = test::load_case("cases/hydrostatic/case.toml");
  spec.shifting_in_continuity = true;
  spec.end_time = 3.0;
  const StillWater r = run_still_water(spec, 0.7, 0.5, 0.5, 0.035, "shift_in_n");
  std::printf("centre of mass rose %+.3f mm over 1.5-3 s\n", 1000 * r.centre_rise);
  EXPECT_LE(std::abs(r.centre_rise), 1e-4);
  EXPECT_TRUE(r.all_inside);
}

TEST(Hydrostatic, LongFlatTankDl5mm) {
  CaseSpec spec = test::load_case("cases/hydrostatic/case.toml");
  spec.dl = 0.005;
  expect_still(run_still_water(spec, 0.7, 0.5, 0.5, 0.0175, "dl5mm"), 0.7);
}

}  // namespace
}  // namespace wcmps
