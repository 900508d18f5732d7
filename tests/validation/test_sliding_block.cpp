// The rigid body of the sliding-block cases: the fluid's force on a body held in still water
// (buoyancy), and the study's cases with prescribed and free motion. Writes block_*.csv (the
// body's S, U and forces) for docs/validation.md.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>

#include "core/Parallel.h"
#include "io/BodyCsv.h"
#include "physics/SlideMotion.h"
#include "scene/CaseParser.h"
#include "scene/SceneBuilder.h"
#include "simulation/Simulation.h"
#include "simulation/WaterCavity.h"
#include "support/TestSupport.h"

namespace wcmps {
namespace {

/// Still water 0.4 m deep in a tank 0.6 m wide, with a square body 0.1 m x 0.1 m held with its
/// top 0.1 m under the surface. The square's sides lie on the lattice's cell lines, so the
/// water starts in the discrete equilibrium without settling.
CaseSpec held_square(double dl) {
  std::string text = R"([case]
name = "held-square"

[particles]
spacing = DL

[time]
end = 1.0

[[wall]]
polyline = [[0.0, 0.5], [0.0, 0.0], [0.6, 0.0], [0.6, 0.5]]
solid = "right"

[[wall]]
rectangle = { min = [0.25, 0.2], max = [0.35, 0.3] }

[[fluid]]
rectangle = { min = [0.0, 0.0], max = [0.6, 0.4] }
)";
  text.replace(text.find("DL"), 2, std::to_string(dl));
  CaseSpec spec = parse_case_text(text, "held-square.toml");
  test::apply_scheme_override(spec);
  BodySpec body;
  body.wall = 1;
  body.density = 2000.0;
  body.downslope = {0.0, -1.0};
  body.bed_normal = {0.0, 1.0};
  body.motion.type = BodyMotionType::Fixed;
  body.label = "square";
  spec.body = body;
  return spec;
}

// A body held in still water feels the buoyancy rho g A upwards and no net horizontal force.
// The force is the reaction of the pair forces its particles exert on the water, so it is what
// the water feels, not a surface integral of our choosing. Measured (mean over 0.5-1 s):
// +2.6 % of rho g A at DL = 10 mm and +2.5 % at DL = 5 mm, the same at both, so not a
// resolution error; one known bias of the study's boundary treatment pushes this way (ghosts
// copy their wall particle's pressure instead of the hydrostatic pressure at their own depth:
// too much under the body, too little over it). Tolerance 3 % around rho g A; horizontally 1 %.
TEST(Buoyancy, HeldSquareFeelsRhoGA) {
  set_thread_count(2);
  const CaseSpec spec = held_square(0.01);
  Simulation sim(spec, build_scene(spec));
  ASSERT_NE(sim.body(), nullptr);
  const double area = sim.body()->particles().area;
  EXPECT_NEAR(area, 0.01, 1e-12);
  const double buoyancy = spec.density * 9.81 * area;
  double fy = 0.0, fx = 0.0;
  int n = 0;
  for (double t = 0.02; t <= spec.end_time + 1e-9; t += 0.02) {
    while (sim.time() < t - 1e-12) sim.step(t);
    if (t < 0.5) continue;
    fx += sim.body()->force().pressure.x;
    fy += sim.body()->force().pressure.y;
    ++n;
  }
  fx /= n;
  fy /= n;
  std::ofstream("buoyancy_square.csv") << "rho_g_A_N_m,Fp_x_N_m,Fp_y_N_m\n"
                                       << buoyancy << "," << fx << "," << fy << "\n";
  std::printf("buoyancy: Fy %.2f N/m (%+.2f %% of rho g A = %.2f), Fx %.3f N/m\n", fy,
              100.0 * (fy / buoyancy - 1.0), buoyancy, fx);
  EXPECT_NEAR(fy / buoyancy, 1.0, 0.03) << "Fy " << fy << " N/m, rho g A " << buoyancy;
  EXPECT_LT(std::abs(fx) / buoyancy, 0.01) << "Fx " << fx;
  // Held: it has not moved, and its particles carry no velocity.
  EXPECT_EQ(sim.body()->state().s, 0.0);
}

// Prescribed motion from the study's table (case I): S(t) passes through the table at its
// times (a spline through its knots: to rounding), U and A are continuous (their changes from
// step to step are of order dt times the next derivative), and every particle of the block is
// where S puts it.
TEST(SlidingBlock, PrescribedMotionFollowsTheTable) {
  set_thread_count(2);
  CaseSpec spec = test::load_case("cases/caseI/case.toml");
  spec.settle_time = 0.0;  // the motion law does not depend on the water's start
  spec.end_time = 0.1;
  ASSERT_TRUE(spec.body && spec.body->motion.type == BodyMotionType::Table);
  const SplineSlide law(spec.body->motion.times, spec.body->motion.distances);
  Simulation sim(spec, build_scene(spec));
  const auto& b = sim.body()->particles();
  const std::vector<double> x0(sim.particles().now.x.begin() + b.walls.first,
                               sim.particles().now.x.begin() + b.walls.second);
  while (sim.time() < spec.end_time - 1e-12) sim.step(spec.end_time);
  const auto& h = sim.body_history();
  ASSERT_GT(h.size(), 100u);
  EXPECT_NEAR(h.back().time, 0.1, 1e-12);
  EXPECT_NEAR(h.back().state.s, 0.018, 1e-12);  // the table's S at 0.1 s
  // At t = 0 the block is at rest (A = 0, SplineSlide: at rest until released); the first step
  // takes it to the law's A: the release, the one step in A there must be.
  EXPECT_EQ(h[0].state.a, 0.0);
  EXPECT_NEAR(h[1].state.a, law.at(h[1].time).a, 1e-12);
  double max_du = 0.0, max_da = 0.0;
  for (std::size_t k = 1; k < h.size(); ++k) {
    const SlideState e = law.at(h[k].time);
    ASSERT_NEAR(h[k].state.s, e.s, 1e-12);
    max_du = std::max(max_du, std::abs(h[k].state.u - h[k - 1].state.u));
    if (k >= 2) max_da = std::max(max_da, std::abs(h[k].state.a - h[k - 1].state.a));
  }
  // dt <= 7.7e-5 s; |A| < 5 m/s^2 and |dA/dt| < 40 m/s^3 on this table: steps of U under 4e-4
  // m/s and of A under 4e-3 m/s^2 (a step in A, as a monotone Hermite gives, would be ~1).
  EXPECT_LT(max_du, 4e-4);
  EXPECT_LT(max_da, 4e-3);
  const Vec2 d = sim.body()->offset(h.back().state.s);
  for (std::int64_t i = b.walls.first; i < b.walls.second; ++i) {
    ASSERT_NEAR(sim.particles().now.x[i], x0[i - b.walls.first] + d.x, 1e-12);
  }
  write_body_csv("block_prescribed_caseI_0.1s.csv", h);
}

// The water follows the block (simulation/WaterCavity.h): case I, prescribed motion, DL 5 mm,
// without settling, to 0.26 s, the cavity measured every 0.02 s as `wcmps post` measures it.
// With the scheme of commit 3a85288 (negative pressures set to zero, summed number density,
// the neighbour-count surface, no shifting) a pocket opens over the block's top from 0.22 s:
// measured 2.05 cm^2 at 0.26 s. With the defaults the water stays on the block; what is left is
// a stretched layer under the trough's surface upslope of the block (x ~ 0.06 m), measured
// 0.22 cm^2 at 0.20 s with the fluid kept DL/2 off the walls, 0.31 cm^2 with it filled up to
// them and 0.19 cm^2 with the surface pressure cap (the default from 2026-12-03), gone by 0.26 s
// (docs/validation.md has the full runs). The bounds: the
// old scheme over 1 cm^2 (half of what it makes: the pocket is there); the new one under
// 0.5 cm^2 (the layer stays thin) and under a fifth of the old one (it makes a sixth).
TEST(SlidingBlock, WaterFollowsTheBlock) {
  set_thread_count(2);
  auto largest_cavity = [](CaseSpec spec) {
    spec.settle_time = 0.0;
    spec.end_time = 0.26;
    Simulation sim(spec, build_scene(spec));
    const WaterCavity cavity(spec);
    const auto& ps = sim.particles();
    double largest = 0.0;
    for (double t = 0.02; t <= spec.end_time + 1e-9; t += 0.02) {
      while (sim.time() < t - 1e-12) sim.step(t);
      const CavityMeasure m = cavity.measure(ps.now.x.data(), ps.now.y.data(), ps.kind.data(),
                                             ps.size(), sim.body()->outline(sim.body()->state().s));
      std::printf("  t = %.2f s: cavity %.3f cm^2\n", t, m.area * 1e4);
      largest = std::max(largest, m.area);
    }
    return largest;
  };
  // Not test::load_case: this test sets both schemes itself (WCMPS_TEST_PHYSICS goes into both).
  CaseSpec spec = parse_case_file(test::source_path("cases/caseI/case.toml"));
  test::apply_physics_override(spec);
  std::printf("defaults:\n");
  const double now = largest_cavity(spec);
  use_scheme_3a85288(spec);
  std::printf("scheme of 3a85288:\n");
  const double before = largest_cavity(spec);
  std::printf("largest cavity: %.3f cm^2 (defaults), %.3f cm^2 (3a85288)\n", now * 1e4,
              before * 1e4);
  EXPECT_GT(before, 1e-4) << "the old scheme's pocket over the block";
  EXPECT_LT(now, 0.5e-4);
  EXPECT_LT(now, 0.2 * before);
}

}  // namespace
}  // namespace wcmps
