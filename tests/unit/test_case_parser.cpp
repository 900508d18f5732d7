// Every class of bad case file gives a CaseError naming the file, line and column; a good one
// gets its defaults.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "scene/CaseParser.h"
#include "scene/Geometry.h"
#include "scene/SceneBuilder.h"
#include "support/TestSupport.h"

namespace wcmps {
namespace {

std::string replace(std::string s, const std::string& from, const std::string& to) {
  const auto pos = s.find(from);
  EXPECT_NE(pos, std::string::npos) << "test bug: '" << from << "' not in the case text";
  if (pos != std::string::npos) s.replace(pos, from.size(), to);
  return s;
}

/// Parses (and builds) `text`; expects a CaseError at `line` (0: anywhere) containing `what`.
void expect_error(const std::string& text, std::uint32_t line, const std::string& what) {
  try {
    const CaseSpec spec = parse_case_text(text, "bad.toml");
    (void)build_scene(spec);
    ADD_FAILURE() << "no error; expected: " << what;
  } catch (const CaseError& e) {
    EXPECT_EQ(e.where().file, "bad.toml");
    if (line > 0) {
      EXPECT_EQ(e.where().line, line) << e.what();
    }
    EXPECT_NE(std::string(e.what()).find(what), std::string::npos) << e.what();
    // The message starts with the location, as compilers print it.
    EXPECT_EQ(std::string(e.what()).rfind("bad.toml", 0), 0u) << e.what();
  }
}

TEST(CaseParser, MinimalCaseGetsTheDocumentedDefaults) {
  const CaseSpec c = parse_case_text(test::minimal_case_text(), "mini.toml");
  EXPECT_EQ(c.name, "mini");
  EXPECT_DOUBLE_EQ(c.dl, 0.01);
  EXPECT_DOUBLE_EQ(c.re_over_dl, 3.5);
  EXPECT_DOUBLE_EQ(c.density, 1000.0);
  EXPECT_DOUBLE_EQ(c.kinematic_viscosity, 1.0e-6);
  EXPECT_DOUBLE_EQ(c.gravity.y, -9.81);
  EXPECT_FALSE(c.sound_speed.has_value());
  EXPECT_DOUBLE_EQ(c.eos_exponent, 7.0);
  EXPECT_DOUBLE_EQ(c.surface_threshold, 0.97);
  EXPECT_DOUBLE_EQ(c.courant, 0.4);
  EXPECT_DOUBLE_EQ(c.artificial_viscosity, 0.02);
  EXPECT_EQ(c.step_mode, TimeStepMode::Courant);
  EXPECT_EQ(c.pressure_gradient, PressureGradientScheme::Suzuki2007);
  EXPECT_EQ(c.wall_pressure, WallPressureScheme::FluidExtrapolated);
  EXPECT_EQ(c.wall_density, WallDensityScheme::Adami2012);
  EXPECT_EQ(c.artificial_viscosity_walls, ArtificialViscosityWalls::NoSlip);
  EXPECT_EQ(c.gradient_renormalisation, GradientRenormalisation::Strain);
  EXPECT_EQ(c.density_rate, DensityRateScheme::Randles1996);
  EXPECT_EQ(c.particle_collision, ParticleCollisionScheme::Jandaghian2021);
  EXPECT_DOUBLE_EQ(c.particle_collision_min_pressure, 0.0);
  EXPECT_EQ(c.output_fields.size(), std::size(kFields));
  EXPECT_EQ(c.output_kinds.size(), 3u);
  ASSERT_EQ(c.walls.size(), 1u);
  EXPECT_TRUE(c.walls[0].solid_on_right);
  ASSERT_EQ(c.fluids.size(), 1u);
  EXPECT_EQ(c.fluids[0].polygon.size(), 4u);
}

TEST(CaseParser, TheBandRateDefaultsToSummedWhereItCannotApply) {
  // "randles1996" corrects the evolved n's rate with the variational gradient as its partner:
  // the summed n, or another gradient, gets "summed" by default instead of an error, which an
  // explicit "randles1996" still gets (CaseParser.InconsistentValuesAreNamed).
  const auto rate = [](const std::string& physics) {
    return parse_case_text(test::minimal_case_text() + "\n[physics]\n" + physics, "mini.toml")
        .density_rate;
  };
  EXPECT_EQ(rate("number_density = \"summation\"\n"), DensityRateScheme::Summed);
  EXPECT_EQ(rate("pressure_gradient = \"koshizuka1998-min\"\n"), DensityRateScheme::Summed);
  EXPECT_EQ(rate("number_density = \"continuity\"\n"), DensityRateScheme::Randles1996);
  EXPECT_EQ(rate("density_rate = \"summed\"\n"), DensityRateScheme::Summed);
  // likewise the renormalisation: "none" with another gradient, unless it is asked for
  const auto renormalisation = [](const std::string& physics) {
    return parse_case_text(test::minimal_case_text() + "\n[physics]\n" + physics, "mini.toml")
        .gradient_renormalisation;
  };
  EXPECT_EQ(renormalisation("pressure_gradient = \"koshizuka1998-min\"\n"),
            GradientRenormalisation::None);
  EXPECT_EQ(renormalisation("gradient_renormalisation = \"none\"\n"),
            GradientRenormalisation::None);
}

TEST(CaseParser, EveryShippedCaseIsValid) {
  int cases = 0;
  for (const auto& dir : std::filesystem::directory_iterator(test::source_path("cases"))) {
    const auto file = dir.path() / "case.toml";
    if (!std::filesystem::exists(file)) continue;
    const CaseSpec c = parse_case_file(file.string());
    EXPECT_NO_THROW((void)build_scene(c)) << file;
    EXPECT_EQ(c.name, dir.path().filename().string()) << "a case is named as its folder";
    ++cases;
  }
  EXPECT_GE(cases, 3);
}

TEST(CaseParser, SyntaxErrorGivesLineAndColumn) {
  const std::string text = replace(test::minimal_case_text(), "spacing = 0.01", "spacing = = 0.01");
  try {
    (void)parse_case_text(text, "bad.toml");
    FAIL() << "no error";
  } catch (const CaseError& e) {
    EXPECT_EQ(e.where().line, 5u);
    EXPECT_GT(e.where().column, 1u);
    EXPECT_NE(std::string(e.what()).find("syntax error"), std::string::npos) << e.what();
  }
}

TEST(CaseParser, UnknownKeyIsNamedWithItsPosition) {
  const std::string text =
      replace(test::minimal_case_text(), "spacing = 0.01", "spacing = 0.01\nspaceing = 2");
  expect_error(text, 6, "unknown key 'spaceing' in [particles]");
  expect_error(test::minimal_case_text() + "\n[solver]\nx = 1\n", 17, "unknown key 'solver'");
}

TEST(CaseParser, WrongTypeIsNamed) {
  expect_error(replace(test::minimal_case_text(), "end = 0.01", "end = \"soon\""), 8,
               "[time] end: expected a number, got a string");
  expect_error(test::minimal_case_text() + "\n[output]\nfields = \"pressure\"\n", 18,
               "[output] fields: expected an array");
}

// WCMPS_TEST_PHYSICS (tests/support/TestSupport.h) puts [physics] lines into every validation
// case: replacing the case's own keys, or in a table of its own.
TEST(TestSupport, PhysicsOverrideReplacesTheCasesKeys) {
  // The environment of whoever runs the tests comes back at the end.
  const char* prior = std::getenv("WCMPS_TEST_PHYSICS");
  const std::string kept = prior ? prior : "";
  const std::string with_table =
      test::minimal_case_text() + "\n[physics]\nartificial_viscosity = 0.05\neos_exponent = 3.0\n";
  ASSERT_EQ(
      setenv("WCMPS_TEST_PHYSICS", " artificial_viscosity = 0.01; wall_pressure = \"eos\";", 1), 0);
  for (const std::string& text : {test::minimal_case_text(), with_table}) {
    CaseSpec c = parse_case_text(text, "mini.toml");
    test::apply_scheme_override(c);
    EXPECT_DOUBLE_EQ(c.artificial_viscosity, 0.01);
    EXPECT_EQ(c.wall_pressure, WallPressureScheme::Eos);
    EXPECT_EQ(c.name, "mini");
    EXPECT_DOUBLE_EQ(c.eos_exponent, text == with_table ? 3.0 : 7.0);  // other keys kept
  }
  ASSERT_EQ(setenv("WCMPS_TEST_PHYSICS", "artificial_viscosity 0.01", 1), 0);
  CaseSpec c = parse_case_text(test::minimal_case_text(), "mini.toml");
  EXPECT_THROW(test::apply_scheme_override(c), std::invalid_argument);
  ASSERT_EQ(setenv("WCMPS_TEST_PHYSICS", "no_such_key = 1", 1), 0);
  EXPECT_THROW(test::apply_scheme_override(c), CaseError);
  ASSERT_EQ(prior ? setenv("WCMPS_TEST_PHYSICS", kept.c_str(), 1) : unsetenv("WCMPS_TEST_PHYSICS"),
            0);
}

TEST(CaseParser, OutOfRangeValueIsNamedWithTheRange) {
  expect_error(replace(test::minimal_case_text(), "spacing = 0.01", "spacing = -0.01"), 5,
               "[particles] spacing: value -0.01 is out of range (0, inf)");
  expect_error(test::minimal_case_text() + "\n[physics]\nsurface_threshold = 1.2\n", 18,
               "surface_threshold: value 1.2 is out of range");
  expect_error(test::minimal_case_text() + "\n[time]\n", 0, "");  // duplicate table: syntax
}

TEST(CaseParser, TheArtificialViscositysWallsAreNamedByKey) {
  const auto walls = [](const std::string& key) {
    return parse_case_text(test::minimal_case_text() +
                               "\n[physics]\nartificial_viscosity_walls = \"" + key + "\"\n",
                           "mini.toml")
        .artificial_viscosity_walls;
  };
  EXPECT_EQ(walls("free-slip"), ArtificialViscosityWalls::FreeSlip);
  EXPECT_EQ(walls("no-slip"), ArtificialViscosityWalls::NoSlip);
  expect_error(test::minimal_case_text() + "\n[physics]\nartificial_viscosity_walls = \"slip\"\n",
               18, "artificial_viscosity_walls: \"slip\" is not one of \"no-slip\", \"free-slip\"");
}

TEST(CaseParser, InconsistentValuesAreNamed) {
  expect_error(test::minimal_case_text() + "\n[output]\ntimes = [0.005, 0.002]\n", 18,
               "must be increasing");
  expect_error(test::minimal_case_text() + "\n[output]\ntimes = [0.5]\n", 18,
               "out of range [0, 0.01]");
  expect_error(test::minimal_case_text() + "\n[output]\nfields = [\"speed\"]\n", 18,
               "unknown field \"speed\"");
  expect_error(test::minimal_case_text() +
                   "\n[physics]\npressure_gradient = \"koshizuka1996\"\n"
                   "gradient_renormalisation = \"khayyer2011\"\n",
               19, "renormalises the variational gradient only");
  expect_error(test::minimal_case_text() +
                   "\n[physics]\ngradient_renormalisation = \"khayyer2011-deviatoric\"\n"
                   "strain_memory = 5.0\n",
               19, "\"khayyer2011-strain\" only");
  expect_error(test::minimal_case_text() +
                   "\n[physics]\ngradient_renormalisation = \"khayyer2011-strain\"\n"
                   "strain_memory = 0.0\n",
               19, "strain_memory: value 0 is out of range (0, inf)");
  expect_error(
      test::minimal_case_text() +
          "\n[physics]\nparticle_collision = \"none\"\nparticle_collision_distance = 0.8\n",
      19, "is a constant of particle_collision = \"jandaghian2021\" only");
  expect_error(test::minimal_case_text() + "\n[physics]\nparticle_collision_distance = 0.4\n", 18,
               "particle_collision_distance: value 0.4 is out of range (0.5, 1]");
  expect_error(test::minimal_case_text() +
                   "\n[physics]\nkinematic_viscosity = 0.0\nwall_friction = \"spalding1961\"\n",
               19, "give kinematic_viscosity > 0");
  expect_error(test::minimal_case_text() + "\n[physics]\nside_wall_friction = \"spalding1961\"\n",
               18, "side_wall_friction: needs the flume's width between its side walls");
  expect_error(test::minimal_case_text() + "\n[physics]\nflume_width = 0.15\n", 18,
               "flume_width: is the width between the side walls of side_wall_friction only");
  expect_error(test::minimal_case_text() +
                   "\n[physics]\nside_wall_friction = \"spalding1961\"\nflume_width = 0.0\n",
               19, "flume_width: value 0 is out of range (0, inf)");
  expect_error(test::minimal_case_text() +
                   "\n[physics]\nkinematic_viscosity = 0.0\nside_wall_friction = "
                   "\"spalding1961\"\nflume_width = 0.15\n",
               19, "give kinematic_viscosity > 0");
  expect_error(test::minimal_case_text() +
                   "\n[physics]\nnumber_density = \"summation\"\n"
                   "density_rate = \"randles1996\"\n",
               19, "corrects the rate of an evolved number density only");
  expect_error(test::minimal_case_text() +
                   "\n[physics]\npressure_gradient = \"koshizuka1996\"\n"
                   "density_rate = \"randles1996\"\n",
               19, "its partner, the variational gradient");
  expect_error(test::minimal_case_text() + "\n[physics]\npressure_gradient = \"sph\"\n", 18,
               "\"sph\" is not one of");
  expect_error(replace(test::minimal_case_text(), "end = 0.01",
                       "end = 0.01\nstep = \"fixed\"\nfixed_step = 0.5"),
               10, "fixed_step: is longer than the end time");
  // A default that does not fit the rest is named at its table (found by the fuzzer: the
  // message once dereferenced the absent key's node).
  expect_error(replace(test::minimal_case_text(), "end = 0.01", "end = 0.00001\nstep = \"fixed\""),
               7, "[time] fixed_step: is longer than the end time");
}

TEST(CaseParser, MissingRequiredKeysAndShapesAreNamed) {
  expect_error(replace(test::minimal_case_text(), "end = 0.01", ""), 7, "[time] end is required");
  expect_error(replace(test::minimal_case_text(), "solid = \"right\"", ""), 10,
               "a polyline wall needs solid");
  expect_error(
      replace(test::minimal_case_text(), "rectangle = { min = [0.0, 0.0], max = [0.2, 0.1] }",
              "velocity = [0.0, 0.0]"),
      14, "give exactly one shape");
  expect_error(replace(test::minimal_case_text(), "max = [0.2, 0.1]", "max = [0.2, 0.0]"), 15,
               "max must be greater than min");
}

TEST(CaseParser, MissingOrUnreadableFileIsNamed) {
  try {
    (void)parse_case_file("/nonexistent/case.toml");
    FAIL() << "no error";
  } catch (const CaseError& e) {
    EXPECT_EQ(e.where().file, "/nonexistent/case.toml");
    EXPECT_NE(std::string(e.what()).find("no such file"), std::string::npos) << e.what();
  }
  const auto dir = test::scratch_dir("dir");
  EXPECT_THROW((void)parse_case_file(dir.string()), CaseError);
}

TEST(SceneGeometry, FluidOutsideEveryWallIsRejected) {
  // The fluid sits beside the tank, with no wall below it.
  expect_error(replace(test::minimal_case_text(), "min = [0.0, 0.0], max = [0.2, 0.1]",
                       "min = [0.5, 0.0], max = [0.7, 0.1]"),
               14, "lies outside every wall");
}

TEST(SceneGeometry, FluidInsideAWallIsRejected) {
  expect_error(replace(test::minimal_case_text(), "min = [0.0, 0.0], max = [0.2, 0.1]",
                       "min = [-0.03, 0.0], max = [0.2, 0.1]"),
               14, "overlaps [[wall]] #1");
}

TEST(SceneGeometry, OverlappingWallsAreRejected) {
  // A second bottom 1 cm under the tank's: its rows fall on the first wall's ghost rows.
  expect_error(test::minimal_case_text() +
                   "\n[[wall]]\npolyline = [[0.05, -0.01], [0.15, -0.01]]\nsolid = \"right\"\n",
               17, "[[wall]] #2 overlaps [[wall]] #1");
}

TEST(SceneGeometry, ACornerTooSharpForTheWallRowsIsRejected) {
  // A spike 1 mm wide cannot hold rows 3.5 DL deep.
  expect_error(test::minimal_case_text() +
                   "\n[[wall]]\npolygon = [[0.1, 0.15], [0.101, 0.15], [0.1005, 0.19]]\n",
               17, "[[wall]] #2");
}

TEST(SceneGeometry, GravityFreeCaseNeedsASoundSpeed) {
  expect_error(test::minimal_case_text() + "\n[physics]\ngravity = [0.0, 0.0]\n", 0,
               "sound_speed is required when gravity is zero");
}

const char* kTank = R"([case]
name = "beach"

[particles]
spacing = 0.01

[time]
end = 0.01

[tank]
slope = 40.0
depth = 0.3
length = 0.6
)";

TEST(CaseParser, TankBecomesItsBedWallAndItsWater) {
  const CaseSpec c = parse_case_text(kTank, "beach.toml");
  ASSERT_TRUE(c.tank);
  EXPECT_DOUBLE_EQ(c.tank->freeboard, 0.1);  // the documented default
  ASSERT_EQ(c.walls.size(), 1u);
  ASSERT_EQ(c.fluids.size(), 1u);
  const double toe = 0.3 / std::tan(40.0 * std::acos(-1.0) / 180.0);
  const auto& w = c.walls[0].points;
  ASSERT_EQ(w.size(), 4u);
  EXPECT_NEAR(w[0].x, -0.1 / std::tan(40.0 * std::acos(-1.0) / 180.0), 1e-12);
  EXPECT_NEAR(w[0].y, 0.1, 1e-12);
  EXPECT_NEAR(w[1].x, toe, 1e-12);
  EXPECT_NEAR(w[1].y, -0.3, 1e-12);
  EXPECT_NEAR(w[3].x, 0.6, 1e-12);
  EXPECT_TRUE(c.walls[0].solid_on_right);
  // The water: below y = 0, above the bed; the scene builds without complaint.
  const Scene scene = build_scene(c);
  const ParticleSet& ps = scene.particles;
  for (std::int64_t i = ps.fluid_begin(); i < ps.size(); ++i) {
    EXPECT_LT(ps.now.y[i], 0.0);
    EXPECT_GT(ps.now.y[i], -0.3);
    // Above the bed line y = -x tan(40 deg) (the wall clearance is 0 by default).
    const double a = 40.0 * std::acos(-1.0) / 180.0;
    EXPECT_GT(ps.now.x[i] * std::sin(a) + ps.now.y[i] * std::cos(a), 0.0);
  }
}

TEST(CaseParser, TankErrorsAreNamed) {
  expect_error(replace(kTank, "slope = 40.0", "slope = 90.0"), 11, "[tank] slope");
  expect_error(replace(kTank, "length = 0.6", "length = 0.3"), 13, "the bed reaches the bottom");
  expect_error(replace(kTank, "length = 0.6", "length = 0.6\nlenght = 0.7"), 14,
               "unknown key 'lenght' in [tank]");
  expect_error(replace(kTank, "[particles]", "[particles]\nsettle_damping = 0.0"), 5,
               "settle_damping");
  expect_error(replace(kTank, "[particles]", "[particles]\nsettle_courant = 1.5"), 5,
               "[particles] settle_courant: value 1.5 is out of range (0, 1]");
  EXPECT_FALSE(parse_case_text(kTank, "t.toml").settle_courant);
  EXPECT_EQ(
      parse_case_text(replace(kTank, "[particles]", "[particles]\nsettle_courant = 0.8"), "t.toml")
          .settle_courant,
      0.8);
}

/// The study's tank and block, case I or II (../shared/spec/cases.md) at the study's DL.
std::string study_block_case(double slope, double top_length, double density) {
  return "[case]\nname = \"block\"\n\n[particles]\nspacing = 0.005\n\n[time]\nend = 0.01\n\n"
         "[tank]\nslope = " +
         std::to_string(slope) +
         "\ndepth = 0.7\nlength = 2.19\n\n[block]\ntop_length = " + std::to_string(top_length) +
         "\nangle_a = 100.0\ntop_depth = 0.02\ndensity = " + std::to_string(density) + "\n";
}

TEST(SceneGeometry, TheStudysBlocksHaveTheirSidesAndVolumes) {
  // cases.md: with a width of 0.05 m, CA / CG / AG = 0.1005 / 0.1540 / 0.1005 m (I) and
  // 0.0843 / 0.1662 / 0.1293 m (II), volumes 248.82 and 268.482 cm^3. Sides are given to
  // 0.1 mm, and CG and AG follow from CA times up to sin(100)/sin(30) = 1.97: the 0.05 mm of
  // rounding in CA makes 0.1 mm in them, and case II's CA (0.08437 m from its volume) was cut
  // to 0.0843, not rounded: tolerance 0.2 mm. Volumes: 0.3 %, the same rounding squared.
  struct Expect {
    double slope, ca, cg, ag, volume_cm3, density;
  };
  for (const Expect e : {Expect{40.0, 0.1005, 0.1540, 0.1005, 248.82, 2928.0},
                         Expect{50.0, 0.0843, 0.1662, 0.1293, 268.482, 2853.0}}) {
    const CaseSpec c = parse_case_text(study_block_case(e.slope, e.ca, e.density), "b.toml");
    ASSERT_TRUE(c.block);
    const BlockSpec& b = *c.block;
    EXPECT_NEAR(norm(b.a - b.c), e.ca, 1e-12);
    EXPECT_NEAR(norm(b.g - b.c), e.cg, 2e-4) << "slope " << e.slope;
    EXPECT_NEAR(norm(b.g - b.a), e.ag, 2e-4) << "slope " << e.slope;
    EXPECT_NEAR(b.area() * 0.05 * 1e6, e.volume_cm3, 0.003 * e.volume_cm3);
    // C and G on the bed y = -x tan(slope); the top 0.02 m under the still water.
    const double t = std::tan(e.slope * std::acos(-1.0) / 180.0);
    EXPECT_NEAR(b.c.y, -b.c.x * t, 1e-12);
    EXPECT_NEAR(b.g.y, -b.g.x * t, 1e-12);
    EXPECT_DOUBLE_EQ(b.a.y, -0.02);
    // The scene: the block displaces the water, and no fluid particle is inside it.
    const Scene scene = build_scene(c);
    const ParticleSet& ps = scene.particles;
    EXPECT_GT(scene.displaced_fluid, 0);
    for (std::int64_t i = ps.fluid_begin(); i < ps.size(); ++i) {
      EXPECT_FALSE(polygon_contains({b.c, b.a, b.g}, {ps.now.x[i], ps.now.y[i]}));
    }
  }
}

TEST(SceneGeometry, BlockErrorsAreNamed) {
  const std::string one = study_block_case(40.0, 0.1005, 2928.0);
  expect_error(replace(one, "angle_a = 100.0", "angle_a = 150.0"), 17, "leave none for G");
  // The default angle at A (100 degrees) with an 85-degree bed: named at [block].
  expect_error(replace(replace(one, "angle_a = 100.0\n", ""), "slope = 40.000000", "slope = 85.0"),
               15, "[block] angle_a: with the bed's 85 degrees at C, the angles leave none for G");
  expect_error(replace(one, "top_length = 0.100500", "top_length = 1.5"), 16,
               "does not fit on the slope");
  // Messages from the scene builder name the block as the case file does: at DL = 10 mm its
  // top (10 DL) is too short for rows 3.5 DL deep behind 40-degree corners.
  expect_error(replace(one, "spacing = 0.005", "spacing = 0.01"), 15,
               "[block]: segment 1 is too short for the wall rows");
  expect_error(replace(one, "[tank]\nslope = 40.000000\ndepth = 0.7\nlength = 2.19\n", ""), 0,
               "[block] sits on the bed of a [tank]");
}

// [block.motion] and [[section]]: what each key makes, and each error named where it is.
TEST(CaseParser, BlockMotionAndSections) {
  const std::string one = study_block_case(40.0, 0.1005, 2928.0);
  const std::string table =
      one +
      "\n[block.motion]\ntype = \"table\"\ntimes = [0.0, 0.1, 0.2]\n"
      "distances = [0.0, 0.018, 0.058]\n\n[[section]]\nname = \"D\"\nat = \"C\"\n"
      "along_bed = -0.01\n[[section]]\nname = \"P\"\npoint = [0.5, -0.3]\n"
      "direction = [0.0, 2.0]\n";
  const CaseSpec c = parse_case_text(table, "b.toml");
  ASSERT_TRUE(c.body);
  EXPECT_EQ(c.body->motion.type, BodyMotionType::Table);
  EXPECT_EQ(c.body->wall, c.walls.size() - 1);  // the block's wall
  EXPECT_EQ(c.body->motion.distances.size(), 3u);
  const double a = 40.0 * std::acos(-1.0) / 180.0;
  EXPECT_NEAR(c.body->downslope.x, std::cos(a), 1e-15);
  EXPECT_NEAR(c.body->downslope.y, -std::sin(a), 1e-15);
  ASSERT_EQ(c.sections.size(), 2u);
  // D: 0.01 m upslope of C, normal to the bed; P: where given, along its direction.
  EXPECT_NEAR(norm(c.sections[0].origin - c.block->c), 0.01, 1e-15);
  EXPECT_LT(c.sections[0].origin.x, c.block->c.x);
  EXPECT_NEAR(c.sections[0].direction.x, std::sin(a), 1e-15);
  EXPECT_NEAR(c.sections[0].direction.y, std::cos(a), 1e-15);
  EXPECT_DOUBLE_EQ(c.sections[1].direction.y, 1.0);
  // Without [block.motion] the block is held.
  EXPECT_EQ(parse_case_text(one, "b.toml").body->motion.type, BodyMotionType::Fixed);

  expect_error(replace(table, "distances = [0.0, 0.018, 0.058]", "distances = [0.0, 0.018]"), 24,
               "needs one distance per time");
  expect_error(replace(table, "times = [0.0, 0.1, 0.2]", "times = [0.0, 0.2, 0.1]"), 23,
               "[block.motion] times: must be increasing");
  expect_error(replace(table, "distances = [0.0, 0.018, 0.058]", "distances = [0.0, 0.058, 0.0]"),
               24, "moves backwards");
  expect_error(replace(table, "type = \"table\"", "type = \"free\""), 21,
               "[block.motion] friction is required");
  expect_error(replace(table, "type = \"table\"", "type = \"sliding\""), 22,
               "\"sliding\" is not one of");
  expect_error(replace(table, "at = \"C\"", "at = \"Z\""), 28, "[[section]] #1 at");
  expect_error(replace(table, "name = \"P\"", "name = \"D\""), 31, "is used by another section");
  expect_error(replace(table, "point = [0.5, -0.3]\n", ""), 30, "give exactly one of point");
}

TEST(CaseParser, Gauges) {
  const std::string base = test::minimal_case_text();
  const auto n = static_cast<std::uint32_t>(std::count(base.begin(), base.end(), '\n'));
  const CaseSpec c =
      parse_case_text(base + "\n[gauges]\nx = [0.05, 0.1]\ninterval = 0.002\n", "g.toml");
  ASSERT_EQ(c.gauges.x.size(), 2u);
  EXPECT_DOUBLE_EQ(c.gauges.interval, 0.002);
  EXPECT_TRUE(parse_case_text(base, "g.toml").gauges.x.empty());
  expect_error(base + "\n[gauges]\ninterval = 0.002\n", 0, "[gauges] x is required");
  expect_error(base + "\n[gauges]\nx = [0.05]\n", 0, "[gauges] interval is required");
  expect_error(base + "\n[gauges]\nx = [0.05]\ninterval = 0.0\n", n + 4,
               "[gauges] interval: value 0 is out of range");
  expect_error(base + "\n[gauges]\nx = [\"left\"]\ninterval = 0.002\n", n + 3,
               "[gauges] x: expected a number");
}

// [figures]: measured data files, relative paths against the case file's directory.
TEST(CaseParser, FiguresMeasuredData) {
  const std::string base = test::minimal_case_text();
  const auto n = static_cast<std::uint32_t>(std::count(base.begin(), base.end(), '\n'));
  const CaseSpec c = parse_case_text(
      base + "\n[figures]\nmeasured_surface = \"m/s.csv\"\nmeasured_profiles = \"/abs/p.csv\"\n",
      "dir/f.toml");
  EXPECT_EQ(c.figures.measured_surface, "dir/m/s.csv");
  EXPECT_EQ(c.figures.measured_profiles, "/abs/p.csv");
  EXPECT_TRUE(parse_case_text(base, "f.toml").figures.measured_surface.empty());
  expect_error(base + "\n[figures]\nmeasured = \"x.csv\"\n", n + 3,
               "unknown key 'measured' in [figures]");
  expect_error(base + "\n[figures]\nmeasured_surface = 3\n", n + 3,
               "[figures] measured_surface: expected a string");
}

TEST(CaseParser, PostProducts) {
  const std::string block =
      study_block_case(40.0, 0.1005, 2928.0) + "\n[[section]]\nname = \"C\"\nat = \"C\"\n";
  // Nothing by default.
  EXPECT_TRUE(parse_case_text(block, "p.toml").post.products.empty());
  const std::string post = block +
                           "\n[post]\nproducts = [\"grid\", \"sections\", \"lines\"]\n"
                           "grid_spacing = 0.002\nvorticity = \"corrected\"\n";
  const CaseSpec c = parse_case_text(post, "p.toml");
  EXPECT_TRUE(c.post.wants(PostProduct::Grid));
  EXPECT_TRUE(c.post.wants(PostProduct::Sections));
  EXPECT_FALSE(c.post.wants(PostProduct::FreeSurface));
  EXPECT_DOUBLE_EQ(c.post.grid_spacing, 0.002);
  EXPECT_TRUE(c.post.corrected_gradient);
  // "lines" without lines: the block's top, C to A.
  ASSERT_EQ(c.post.lines.size(), 1u);
  EXPECT_EQ(c.post.lines[0].first, "C");
  EXPECT_EQ(c.post.lines[0].second, "A");
  const auto n = static_cast<std::uint32_t>(std::count(block.begin(), block.end(), '\n'));
  expect_error(replace(post, "\"lines\"]", "\"contours\"]"), n + 3,
               "[post] products: unknown product \"contours\"");
  expect_error(replace(post, "grid_spacing = 0.002", "grid_spacing = -1"), n + 4,
               "[post] grid_spacing: value -1 is out of range");
  expect_error(post + "lines = [\"C-Z\"]\n", n + 6, "[post] lines: expected \"P-Q\"");
  expect_error(post + "grid_fields = [\"speed\", \"temperature\"]\n", n + 6,
               "[post] grid_fields: unknown field \"temperature\"");
  expect_error(post + "colour = 1\n", n + 6, "unknown key 'colour' in [post]");
  // Products measured along the block need one; sections need [[section]]s.
  expect_error(test::minimal_case_text() + "\n[post]\nproducts = [\"section_averages\"]\n", 0,
               "needs a [block]");
  expect_error(test::minimal_case_text() + "\n[post]\nproducts = [\"sections\"]\n", 0,
               "needs [[section]] tables");
}

}  // namespace
}  // namespace wcmps
