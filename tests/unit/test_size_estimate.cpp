/// @file test_size_estimate.cpp
/// @brief The size of a case from its shapes alone (scene/SizeEstimate.h) against the scene the
/// builder then makes; sizes written and read (core/Memory.h).

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "core/Error.h"
#include "core/Memory.h"
#include "scene/CaseParser.h"
#include "scene/Geometry.h"
#include "scene/SceneBuilder.h"
#include "scene/SizeEstimate.h"
#include "support/TestSupport.h"

namespace wcmps {
namespace {

// Counting the samples of a polyline gives what laying them gives, for open and closed lines,
// segments shorter and longer than a spacing, and lengths that are not whole spacings.
TEST(Geometry, PolylineSampleCountIsTheSamplesLaid) {
  const std::vector<std::vector<Vec2>> lines{
      {{0.0, 1.0}, {0.0, 0.0}, {2.0, 0.0}, {2.0, 1.0}},
      {{0.0, 0.0}, {0.0137, 0.0}},
      {{0.0, 0.0}, {0.3, 0.0}, {0.3004, 0.2}, {0.71, 0.43}},
      {{0.1, 0.1}, {0.25, 0.1}, {0.2, 0.17}},
  };
  for (const double spacing : {0.01, 0.0033, 0.05}) {
    for (const auto& line : lines) {
      for (const bool closed : {false, true}) {
        EXPECT_EQ(count_polyline_samples(line, closed, spacing),
                  static_cast<std::int64_t>(sample_polyline(line, closed, spacing).size()))
            << "spacing " << spacing << (closed ? " closed" : " open");
      }
    }
  }
}

// On every shipped case the fluid's lattice is small enough to be scanned whole: the estimate
// is then the builder's count, kind by kind, exactly.
TEST(SizeEstimate, ShippedCasesAreCountedExactly) {
  for (const auto& entry : std::filesystem::directory_iterator(test::source_path("cases"))) {
    const auto file = entry.path() / "case.toml";
    if (!std::filesystem::exists(file)) continue;
    const CaseSpec spec = parse_case_file(file.string());
    const ParticleEstimate e = estimate_particles(spec);
    const Scene scene = build_scene(spec);
    SCOPED_TRACE(file.string());
    EXPECT_EQ(e.stride, 1);
    EXPECT_EQ(e.fluid, static_cast<double>(scene.particles.fluid_count()));
    EXPECT_EQ(e.wall, static_cast<double>(scene.particles.wall_count()));
    EXPECT_EQ(e.ghost, static_cast<double>(scene.particles.ghost_count()));
  }
}

// A lattice too big to scan whole (a sloped tank of 1.2 million lattice points, so every
// second point in x and y is scanned): the fluid's count is within 1 % of the builder's. The
// sampling error is about the points of the boundary strips over those of the area: here
// ~(2 perimeters / DL) / (area / DL^2) ~ 0.5 % at most; 1 % leaves room for that.
TEST(SizeEstimate, SampledLatticeIsWithinOnePercent) {
  const CaseSpec spec = parse_case_text(R"([case]
name = "sloped tank"
[particles]
spacing = 0.0013
[time]
end = 0.01
[[wall]]
polyline = [[0.0, 1.0], [0.0, 0.0], [1.0, 0.0], [2.4, 1.0]]
solid = "right"
[[fluid]]
polygon = [[0.0, 0.0], [1.0, 0.0], [2.26, 0.9], [0.0, 0.9]]
)",
                                        "sloped.toml");
  const ParticleEstimate e = estimate_particles(spec);
  ASSERT_GT(e.stride, 1);
  const Scene scene = build_scene(spec);
  const double built = static_cast<double>(scene.particles.fluid_count());
  EXPECT_NEAR(e.fluid / built, 1.0, 0.01) << e.fluid << " estimated, " << built << " built";
  EXPECT_EQ(e.wall, static_cast<double>(scene.particles.wall_count()));
  EXPECT_EQ(e.ghost, static_cast<double>(scene.particles.ghost_count()));
}

// A bed of 3,000 vertices (a surveyed one, say): the scan tests every point against every edge,
// so fewer points are scanned (kEdgeTests), and the count stays close. Scanning every second
// row and column of a region of ~90 rows and ~200 columns can miss or double one row and one
// column: (1/90 + 1/200) = 1.6 %, and the wavy bed as much again at most; 3 %.
TEST(SizeEstimate, ShapesOfManyEdgesAreScannedOnFewerPoints) {
  std::string bed = "[0.0, 0.6], ", water = "[0.0, 0.5], ";
  constexpr int kVertices = 3000;
  for (int k = 0; k <= kVertices; ++k) {
    const double x = static_cast<double>(k) / kVertices;
    const double y = 0.05 + 0.01 * std::sin(2.0 * M_PI * x / 0.4);
    const std::string p = "[" + std::to_string(x) + ", " + std::to_string(y) + "], ";
    bed += p;
    water += p;
  }
  bed += "[1.0, 0.6]";
  water += "[1.0, 0.5]";
  const CaseSpec spec = parse_case_text(
      "[particles]\nspacing = 0.005\n[time]\nend = 0.01\n"
      "[[wall]]\npolyline = [" +
          bed + "]\nsolid = \"right\"\n[[fluid]]\npolygon = [" + water + "]\n",
      "bed.toml");
  const ParticleEstimate e = estimate_particles(spec);
  EXPECT_GT(e.stride, 1);
  const double built = static_cast<double>(build_scene(spec).particles.fluid_count());
  EXPECT_NEAR(e.fluid / built, 1.0, 0.03) << e.fluid << " estimated, " << built << " built";
}

// A spacing that asks for 2e10 particles is estimated (not built) and its shapes still checked:
// fluid outside every wall is found on the sampled points.
TEST(SizeEstimate, HugeCasesAreEstimatedAndChecked) {
  std::string text = test::minimal_case_text();
  text.replace(text.find("spacing = 0.01"), 14, "spacing = 1e-6");
  const ParticleEstimate e = estimate_particles(parse_case_text(text, "huge.toml"));
  EXPECT_GT(e.stride, 1);
  EXPECT_NEAR(e.fluid, 0.2 * 0.1 / 1e-12, 0.01 * 0.2 * 0.1 / 1e-12);
  std::string outside = text;
  outside.replace(outside.find("max = [0.2, 0.1]"), 16, "max = [0.3, 0.1]");
  EXPECT_THROW(estimate_particles(parse_case_text(outside, "outside.toml")), CaseError);
}

// A fluid shape far longer than wide (one vertex typed 1e9 m up, over a tank 1 m tall): the
// sampled lattice stays within the estimate's budget. With one stride for both directions set by
// the box's area alone, its single sampled column held 1e9 / sqrt(1e9 x 20 / 1e6) = 7e6 x more
// points than the budget (a hang the case fuzzer found).
TEST(SizeEstimate, ABoxFarLongerThanWideIsSampledWithinTheBudget) {
  const CaseSpec spec = parse_case_text(
      "[particles]\nspacing = 0.01\n[time]\nend = 0.01\n"
      "[[wall]]\npolyline = [[0.0, 1.0], [0.0, 0.0], [0.2, 0.0], [0.2, 1.0]]\nsolid = \"right\"\n"
      "[[fluid]]\npolygon = [[0.0, 0.0], [0.2, 0.0], [0.2, 0.1], [0.1, 1e9], [0.0, 0.1]]\n",
      "tall.toml");
  const ParticleEstimate e = estimate_particles(spec);
  const double s = static_cast<double>(e.stride);
  const double nx = 0.2 / 0.01 + 3.0, ny = 1e9 / 0.01 + 3.0;  // the box, one point of margin
  EXPECT_LE((std::ceil(nx / s) + 1.0) * (std::ceil(ny / s) + 1.0),
            3.0 * ParticleEstimate::kScannedPoints + 4.0);
  // One point in 1e5 x 1e5 cannot see a sliver 20 points wide (the estimate may count none of
  // it); the builder refuses the box, as it does any box past 2e8 points, with a message.
  EXPECT_THROW(build_scene(spec), CaseError);
}

TEST(Memory, SizesAreParsedWithTheirUnits) {
  EXPECT_EQ(parse_byte_size("512"), 512u);
  EXPECT_EQ(parse_byte_size("6G"), 6ull << 30);
  EXPECT_EQ(parse_byte_size("6 GiB"), 6ull << 30);
  EXPECT_EQ(parse_byte_size("1.5 gib"), 3ull << 29);
  EXPECT_EQ(parse_byte_size("500MB"), 500'000'000u);
  EXPECT_EQ(parse_byte_size("2 kB"), 2000u);
  EXPECT_EQ(parse_byte_size("3K"), 3072u);
  EXPECT_EQ(parse_byte_size("1T"), 1ull << 40);
  for (const char* bad : {"", "G", "-1G", "6 GB extra", "6X", "6 GiBs", "nan", "1e30"}) {
    EXPECT_FALSE(parse_byte_size(bad)) << '"' << bad << '"';
  }
  EXPECT_EQ(format_bytes(512), "512 B");
  EXPECT_EQ(format_bytes(1536), "1.50 KiB");
  EXPECT_EQ(format_bytes(254.0 * 1024 * 1024), "254 MiB");
  // Past any machine (a box a vertex typed far out asks for): still a size with its unit.
  EXPECT_EQ(format_bytes(8.24e30), "7.32e+15 PiB");
  // This process has memory, and the machine some to spare.
  EXPECT_GT(current_rss_bytes(), 0u);
  EXPECT_GE(peak_rss_bytes(), current_rss_bytes());
  EXPECT_GT(available_memory_bytes(), 0u);
}

// [run] max_memory: a size with its unit, or bytes; anything else is named with its place.
TEST(CaseParser, MaxMemoryTakesASize) {
  auto with = [](const std::string& value) {
    return parse_case_text(test::minimal_case_text() + "[run]\nmax_memory = " + value + "\n",
                           "mem.toml");
  };
  EXPECT_EQ(with("\"2 GiB\"").max_memory, 2ull << 30);
  EXPECT_EQ(with("1000000").max_memory, 1'000'000u);
  EXPECT_FALSE(parse_case_text(test::minimal_case_text(), "mem.toml").max_memory);
  for (const char* bad : {"\"lots\"", "0", "-5", "1.5", "\"0 GB\""}) {
    try {
      with(bad);
      ADD_FAILURE() << bad << " accepted";
    } catch (const CaseError& e) {
      EXPECT_NE(std::string(e.what()).find("[run] max_memory"), std::string::npos) << e.what();
    }
  }
}

}  // namespace
}  // namespace wcmps
