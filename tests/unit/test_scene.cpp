// Scene building: wall rows parallel to the surface and DL apart, ghost rows with their wall
// sources along the normal, the lattice fill of fluid shapes, the hydrostatic start.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>

#include "scene/CaseParser.h"
#include "scene/Geometry.h"
#include "scene/SceneBuilder.h"
#include "simulation/Simulation.h"
#include "support/TestSupport.h"

namespace wcmps {
namespace {

// Positions are built by adding multiples of DL = 0.01 m: rounding is ~1e-17 m.
constexpr double kExact = 1e-12;

// A closed outline keeps every corner, its first vertex included (it was once dropped, which
// left a hole at that corner of every row of a solid body).
TEST(Geometry, ClosedPolylineSamplesEveryCornerOnce) {
  const std::vector<Vec2> square{{0.0, 0.0}, {0.1, 0.0}, {0.1, 0.1}, {0.0, 0.1}};
  const auto samples = sample_polyline(square, true, 0.01);
  EXPECT_EQ(samples.size(), 40u);
  for (const Vec2 c : square) {
    const auto hits = std::count_if(samples.begin(), samples.end(), [&](const PolylineSample& s) {
      return norm(s.position - c) < kExact;
    });
    EXPECT_EQ(hits, 1) << "corner (" << c.x << ", " << c.y << ")";
  }
}

// A solid square in the water: its wall row and ghost rows fill it from 0.5 to 3.5 DL inside
// its surface, on the lattice, with no hole.
TEST(SceneBuilder, SolidSquareRowsAreComplete) {
  std::string text = test::minimal_case_text();
  text += R"(
[[wall]]
rectangle = { min = [0.05, 0.02], max = [0.15, 0.10] }
)";
  const Scene scene = build_scene(parse_case_text(text, "square.toml"));
  const ParticleSet& ps = scene.particles;
  std::set<std::pair<long, long>> inside;
  for (std::int64_t i = 0; i < ps.fluid_begin(); ++i) {
    const double x = ps.now.x[i], y = ps.now.y[i];
    if (x > 0.05 && x < 0.15 && y > 0.02 && y < 0.10) {
      inside.insert({std::lround((x - 0.005) / 0.01), std::lround((y - 0.005) / 0.01)});
    }
  }
  // 10 x 8 lattice cells, every one within 3.5 DL of the surface (the block is 8 DL high).
  EXPECT_EQ(inside.size(), 80u);
}

TEST(SceneBuilder, TankWallRowIsDlApartAndInLineWithTheFluidRows) {
  const CaseSpec spec = parse_case_text(test::minimal_case_text(), "mini.toml");
  const Scene scene = build_scene(spec);
  const ParticleSet& ps = scene.particles;
  // Left: 21 (y = -0.005 ... 0.195), bottom: 21 (x = 0.005 ... 0.205), right: 20.
  EXPECT_EQ(ps.wall_count(), 62);
  EXPECT_EQ(scene.ghost_layers, 3);  // k DL < 3.5 DL for k = 1, 2, 3
  EXPECT_EQ(ps.fluid_count(), 20 * 10);
  EXPECT_EQ(scene.trimmed_fluid, 0);
  for (std::int64_t i = 0; i < ps.wall_end(); ++i) {
    const double x = ps.now.x[i], y = ps.now.y[i];
    const bool on_row = std::abs(x + 0.005) < kExact || std::abs(x - 0.205) < kExact ||
                        std::abs(y + 0.005) < kExact;
    EXPECT_TRUE(on_row) << "wall particle at (" << x << ", " << y << ")";
    // In line with the fluid lattice: coordinates are odd multiples of DL/2.
    EXPECT_NEAR(std::remainder(y - 0.005, 0.01), 0.0, kExact);
  }
  // The fluid is DL away from the wall row.
  double closest = 1.0;
  for (std::int64_t f = ps.fluid_begin(); f < ps.size(); ++f) {
    for (std::int64_t w = 0; w < ps.wall_end(); ++w) {
      closest = std::min(closest, std::hypot(ps.now.x[f] - ps.now.x[w], ps.now.y[f] - ps.now.y[w]));
    }
  }
  EXPECT_NEAR(closest, 0.01, kExact);
}

TEST(SceneBuilder, GhostsCopyTheWallParticleAlongTheWallNormal) {
  CaseSpec spec = parse_case_text(test::minimal_case_text(), "mini.toml");
  spec.hydrostatic_start = false;
  const Scene scene = build_scene(spec);
  const ParticleSet& ps = scene.particles;
  std::set<std::pair<long, long>> seen;
  for (std::int64_t g = ps.wall_end(); g < ps.fluid_begin(); ++g) {
    const double gx = ps.now.x[g], gy = ps.now.y[g];
    const std::int32_t w = ps.ghost_source(g);
    const double wx = ps.now.x[w], wy = ps.now.y[w];
    EXPECT_TRUE(seen.insert({std::lround(gx * 1e4), std::lround(gy * 1e4)}).second)
        << "two ghosts at (" << gx << ", " << gy << ")";
    // Left wall: the source is level with the ghost; bottom: straight above; right: level.
    if (gy > 0.0 && gx < 0.0) {
      EXPECT_NEAR(wy, gy, kExact);
      EXPECT_NEAR(wx, -0.005, kExact);
    } else if (gy > 0.0 && gx > 0.2) {
      EXPECT_NEAR(wy, gy, kExact);
      EXPECT_NEAR(wx, 0.205, kExact);
    } else if (gx > 0.0 && gx < 0.2) {
      EXPECT_NEAR(wx, gx, kExact);
      EXPECT_NEAR(wy, -0.005, kExact);
    } else {  // corner squares: the corner wall particle
      EXPECT_NEAR(wy, -0.005, kExact);
      EXPECT_NEAR(std::abs(wx - 0.1), 0.105, kExact);
    }
  }
  // Row k (k DL behind the wall row) has 21 + k left, 21 + 2k bottom and 20 + k right
  // particles: 62 + 4k, so 66 + 70 + 74 ghosts, filling the band without gaps.
  EXPECT_EQ(ps.ghost_count(), 210);
}

// Every boundary particle carries the unit normal of its wall's surface, into the solid: the
// left wall's (-1, 0), the bed's (0, -1), the right wall's (1, 0), and behind the corners, where
// the surface's nearest point is the corner itself, the mean of both
// (physics/WallSlip_Colagrossi2003.h reads them).
TEST(SceneBuilder, BoundaryParticlesCarryTheirWallsNormal) {
  const Scene scene = build_scene(parse_case_text(test::minimal_case_text(), "mini.toml"));
  const ParticleSet& ps = scene.particles;
  ASSERT_EQ(static_cast<std::int64_t>(ps.normal_x.size()), ps.fluid_begin());
  int corners = 0;
  for (std::int64_t j = 0; j < ps.fluid_begin(); ++j) {
    const double x = ps.now.x[j], y = ps.now.y[j];
    const Vec2 n{ps.normal_x[j], ps.normal_y[j]};
    EXPECT_NEAR(norm(n), 1.0, kExact);
    Vec2 expected;
    if (x < 0.0 && y > 0.0) {
      expected = {-1.0, 0.0};
    } else if (x > 0.2 && y > 0.0) {
      expected = {1.0, 0.0};
    } else if (x > 0.0 && x < 0.2) {
      expected = {0.0, -1.0};
    } else {  // behind a corner
      ++corners;
      expected = Vec2{x < 0.0 ? -1.0 : 1.0, -1.0} * std::sqrt(0.5);
    }
    EXPECT_NEAR(n.x, expected.x, kExact) << "at (" << x << ", " << y << ")";
    EXPECT_NEAR(n.y, expected.y, kExact) << "at (" << x << ", " << y << ")";
  }
  // Row k turns its corner with 2k + 1 particles behind it: 1 + 3 + 5 + 7 at each corner.
  EXPECT_EQ(corners, 2 * 16);
}

/// A 40-degree bed from (0, 0) up to y = 0.3 m, a vertical wall down to it (the solid on the
/// right all along), and water in the triangle above the bed up to y = 0.25 m; `particles` adds
/// lines to [particles].
std::string slope_case(const std::string& particles) {
  const double t = std::tan(40.0 * M_PI / 180.0);
  return "[case]\nname = \"slope\"\n[particles]\nspacing = 0.01\n" + particles +
         "[time]\nend = 0.01\n[[wall]]\npolyline = [[0.0, 0.3], [0.0, 0.0], [" +
         std::to_string(0.3 / t) +
         ", 0.3]]\nsolid = \"right\"\n[[fluid]]\npolygon = [[0.0, 0.0], [" +
         std::to_string(0.25 / t) + ", 0.25], [0.0, 0.25]]\n";
}

TEST(SceneBuilder, FluidUnderAnInclinedWallKeepsHalfASpacingFromIt) {
  // A 40-degree bed: fluid fills the triangle above it; with wall_clearance = 0.5 (the scheme of
  // 3a85288) lattice points within DL/2 of the bed are dropped, so that every fluid particle is
  // at least DL from the wall row.
  const CaseSpec spec = parse_case_text(slope_case("wall_clearance = 0.5\n"), "slope.toml");
  const Scene scene = build_scene(spec);
  const ParticleSet& ps = scene.particles;
  EXPECT_GT(scene.trimmed_fluid, 0);
  const Vec2 a = spec.walls[0].points[1], b = spec.walls[0].points[2];  // the bed as parsed
  double closest_surface = 1.0, closest_row = 1.0;
  for (std::int64_t f = ps.fluid_begin(); f < ps.size(); ++f) {
    const Vec2 p{ps.now.x[f], ps.now.y[f]};
    closest_surface = std::min(closest_surface, distance_to_segment(p, a, b));
    for (std::int64_t w = 0; w < ps.wall_end(); ++w) {
      closest_row = std::min(closest_row, std::hypot(p.x - ps.now.x[w], p.y - ps.now.y[w]));
    }
  }
  EXPECT_GE(closest_surface, 0.005 * (1 - 1e-6));
  EXPECT_GE(closest_row, 0.01 * (1 - 1e-4));
  // Wall particles along the bed lie on a line parallel to it, DL/2 below: no staircase.
  const Vec2 d = (b - a) * (1.0 / norm(b - a));
  int on_bed_row = 0;
  for (std::int64_t w = 0; w < ps.wall_end(); ++w) {
    const Vec2 p{ps.now.x[w], ps.now.y[w]};
    if (p.x > 0.02 && p.y > 0.02) {
      EXPECT_NEAR(cross(d, p - a), -0.005, 1e-9) << "wall particle off the bed row";
      ++on_bed_row;
    }
  }
  EXPECT_GT(on_bed_row, 20);
}

TEST(SceneBuilder, FluidUnderAnInclinedWallFillsItToTheBed) {
  // The same bed with the default clearance (0): the fluid reaches the bed's surface as the
  // wall's rows reach it from below, so the particles hold the triangle's whole area, one DL^2
  // each; half a DL of clearance leaves a strip along the bed empty, half a DL wide on average
  // (here 0.5 x 38.9 = 19 particles of 372, 5 %).
  const double t = std::tan(40.0 * M_PI / 180.0);
  const CaseSpec spec = parse_case_text(slope_case(""), "slope.toml");
  ASSERT_EQ(spec.wall_clearance, 0.0);
  const Scene scene = build_scene(spec);
  const ParticleSet& ps = scene.particles;
  const Vec2 a = spec.walls[0].points[1], b = spec.walls[0].points[2];
  const Vec2 d = (b - a) * (1.0 / norm(b - a));
  double closest_row = 1.0;
  for (std::int64_t f = ps.fluid_begin(); f < ps.size(); ++f) {
    const Vec2 p{ps.now.x[f], ps.now.y[f]};
    EXPECT_GT(cross(d, p - a), 0.0) << "fluid on the bed's solid side";
    for (std::int64_t w = 0; w < ps.wall_end(); ++w) {
      closest_row = std::min(closest_row, std::hypot(p.x - ps.now.x[w], p.y - ps.now.y[w]));
    }
  }
  // The wall row lies DL/2 inside the bed: no fluid particle is nearer to it than that.
  EXPECT_GE(closest_row, 0.005 * (1 - 1e-6));
  // A straight cut of the lattice holds area / DL^2 particles to within a few (the corners):
  // 1 %, against the 5 % the clearance of DL/2 leaves out.
  const double area = 0.5 * 0.25 * (0.25 / t);
  EXPECT_NEAR(static_cast<double>(ps.fluid_count()), area / (0.01 * 0.01), 0.01 * area / 1e-4);
}

TEST(SceneBuilder, HydrostaticStartGivesRhoGDepthInTheInterior) {
  const CaseSpec spec = test::load_case("cases/hydrostatic/case.toml");
  const Simulation sim(spec, build_scene(spec));
  const ParticleSet& ps = sim.particles();
  const double H = 0.7, rho_g = spec.density * 9.81;
  int checked = 0;
  for (std::int64_t i = ps.fluid_begin(); i < ps.size(); ++i) {
    const double x = ps.now.x[i], y = ps.now.y[i];
    // Away from walls and from the top rows, whose kernels reach beyond the fluid.
    if (x < 0.04 || x > 0.46 || y < 0.04 || y > H - 0.05) continue;
    // Rows are placed to 1e-10 of n; what is left is the depth of a row taken at mid-rows and
    // the surface taken at DL/2 above the top row: well within 0.2 % of rho g H (14 Pa).
    EXPECT_NEAR(ps.now.p[i], rho_g * (H - y), 0.002 * rho_g * H) << "y = " << y;
    ++checked;
  }
  EXPECT_GT(checked, 2000);
}

}  // namespace
}  // namespace wcmps
