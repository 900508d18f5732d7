// Dam break (cases/dambreak) against Martin & Moyce (1952): surge-front position Z = z/a
// against T = t sqrt(2g/a). Writes dambreak_front_*.csv for docs/validation.md.

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>
#include <vector>

#include "core/Parallel.h"
#include "scene/SceneBuilder.h"
#include "simulation/Simulation.h"
#include "support/DamBreakFront.h"
#include "support/TestSupport.h"

namespace wcmps {
namespace {

using namespace dambreak;

std::vector<Point> measured() {
  return martin_moyce(test::source_path("cases/dambreak/martin_moyce_1952.csv"));
}

/// Front position (rightmost fluid particle plus half a spacing) every 0.02 in T, to T = 3.5.
std::vector<Point> run_front(double dl) {
  set_thread_count(2);
  CaseSpec spec = test::load_case("cases/dambreak/case.toml");
  spec.dl = dl;
  const double scale = std::sqrt(2.0 * kG / kA);  // T = t * scale
  Simulation sim(spec, build_scene(spec));
  std::vector<Point> out;
  for (double T = 0.0; T <= 3.5 + 1e-9; T += 0.02) {
    const double t = T / scale;
    while (sim.time() < t - 1e-12) sim.step(t);
    const ParticleSet& ps = sim.particles();
    double front = 0.0;
    for (std::int64_t i = ps.fluid_begin(); i < ps.size(); ++i)
      front = std::max(front, ps.now.x[i]);
    out.push_back({T, (front + 0.5 * dl) / kA});
  }
  std::ostringstream name;
  name << "dambreak_front_dl" << dl * 1000 << "mm.csv";
  std::ofstream csv(name.str());
  csv << "T,Z\n";
  for (const auto& p : out) csv << p.T << ',' << p.Z << '\n';
  return out;
}

double rms_front_error(const std::vector<Point>& sim) {
  return dambreak::rms_front_error(sim, measured());
}

// Tolerance: rms 0.15 in Z (a few percent of the 1 ... 4 range; published MPS and SPH runs of
// this test scatter about the data by about that much after a time shift). At DL = a/20 the
// column is only 20 particles wide.
TEST(DamBreak, FrontFollowsMartinMoyceDl10mm) {
  ASSERT_EQ(measured().size(), 15u);
  const double e = rms_front_error(run_front(0.01));
  ::testing::Test::RecordProperty("rms_Z_error", std::to_string(e));
  std::printf("dam break DL = 10 mm: rms front error %.3f (shift %.2f in T)\n", e, kShift);
  EXPECT_LE(e, 0.15);
}

TEST(DamBreak, FrontFollowsMartinMoyceDl5mm) {
  const double e = rms_front_error(run_front(0.005));
  std::printf("dam break DL = 5 mm: rms front error %.3f (shift %.2f in T)\n", e, kShift);
  EXPECT_LE(e, 0.15);
}

TEST(DamBreak, LongFrontFollowsMartinMoyceDl2p5mm) {
  const double e = rms_front_error(run_front(0.0025));
  std::printf("dam break DL = 2.5 mm: rms front error %.3f (shift %.2f in T)\n", e, kShift);
  EXPECT_LE(e, 0.15);
}

}  // namespace
}  // namespace wcmps
