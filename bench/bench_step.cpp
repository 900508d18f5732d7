// Google Benchmark of the time step: wall time per step and particle-steps per second against
// particle count and threads (docs/performance.md, "Scaling").
//
// - DamBreak/DL_um/threads: cases/dambreak at DL (um), from the collapse's first steps (the
//   column still nearly at rest: the free surface's phases have little to do there, see
//   DamBreakSurge); DL 2 mm gives about 20,000 particles.
// - CaseI/DL_um/threads: the study's case I (cases/caseI) from t = 0 without settling, the
//   block moving, from DL 7 mm (27,000 particles) to the fine 2 mm case (316,000).
// - DamBreakSurge/DL_um/threads: the same dam break stepped to t = 0.25 s before timing (DL 10
//   and 5 mm: at 2 mm the way there takes minutes): the surge running along the bed, its whole
//   outline a free surface, so that the surface's scan, band and cap work as in a run (at the
//   start the surface is one flat row and a column's side).
// - DamBreak_3a85288, CaseI_3a85288, DamBreakSurge_3a85288: the same with the scheme of commit
//   3a85288 (the cures of docs/method.md "A stabilised step" off), in the same binary: what the
//   cures cost.
// - DamBreak_Hydrostatic, CaseI_Hydrostatic: the defaults with gradient_renormalisation =
//   "khayyer2011-hydrostatic" (one thread, DL 5 and 2 mm): what the option costs.
// - DamBreak_Deviatoric, CaseI_Deviatoric, DamBreakSurge_Deviatoric: the same with
//   "khayyer2011-deviatoric" (one thread; the surge at DL 5 mm).
// - DamBreak_Plain, CaseI_Plain, DamBreakSurge_Plain: the defaults with gradient_renormalisation =
//   "none", the defaults before 2026-12-07 (session 13): what the default "khayyer2011-strain" (its
//   rest shapes read and advanced in the gradient's pass) costs.
// - DamBreak_FreeSlip, CaseI_FreeSlip, DamBreakSurge_FreeSlip: the defaults with
//   artificial_viscosity_walls = "free-slip" (the walls' tangents read in the prediction's pass).
// - DamBreak_WallFriction, CaseI_WallFriction, DamBreakSurge_WallFriction: the same with
//   wall_friction = "spalding1961" too (a pass over each near-wall particle's list, and the law).
// - DamBreak_SideWalls, DamBreakSurge_SideWalls: the defaults with side_wall_friction =
//   "spalding1961", flume_width 0.15 m (the law at every fluid particle, one thread).
// - DamBreak_BandRate, CaseI_BandRate: the defaults with density_rate = "randles1996" (one
//   thread, DL 5 and 2 mm): what the band's correction (rate and gradient) costs.
// - DamBreak_NoCollision, CaseI_NoCollision, DamBreakSurge_NoCollision: the defaults with
//   particle_collision = "none", the defaults before 2026-12-08 (session 15), one thread: what the
//   default "jandaghian2021" (its pass over the fluid's lists) costs.
//
// - NeighbourBuild/DL_um/threads: binning and building the neighbour lists of case I's particles
//   (what Simulation does when the skin is used up), with the case's cutoff re + skin. The fluid
//   is moved off its lattice by up to 0.3 DL at random, as a flowing fluid is: on the lattice
//   which neighbour is in is a regular pattern that a branch predictor learns, and a build
//   there is twice as fast as in a run.
//
// Each iteration is one Simulation::step() (for NeighbourBuild one binning and build); the scene
// is built and 20 steps are taken before timing. Every step benchmark also reports
// cycles_per_particle_step: wall time x the clock Google Benchmark reads (its "Run on ... MHz"
// line) over particle-steps, a figure that carries between machines better than seconds; the
// report's context names the CPU model and the vector instructions the build uses (times are
// only comparable on one machine). Run:
//   build/bin/bench_step --benchmark_repetitions=3 --benchmark_report_aggregates_only=true
//   build/bin/bench_step --benchmark_filter='DamBreak/2000/'   (one size)
// The smoke test (ctest -R bench.step_smoke) runs the coarsest dam break for a few steps.

#include <benchmark/benchmark.h>

#include <chrono>
#include <fstream>
#include <map>
#include <memory>
#include <random>
#include <string>
#include <tuple>
#include <vector>

#include "core/Parallel.h"
#include "neighbours/CellGrid.h"
#include "neighbours/NeighbourList.h"
#include "scene/CaseParser.h"
#include "scene/SceneBuilder.h"
#include "simulation/Simulation.h"

namespace {

using namespace wcmps;

enum class Scheme {
  Defaults,
  Old,
  Hydrostatic,
  Deviatoric,
  Plain,
  FreeSlip,
  WallFriction,
  SideWalls,
  BandRate,
  NoCollision
};

std::unique_ptr<Simulation> make(const std::string& case_dir, double dl,
                                 Scheme scheme = Scheme::Defaults, double start_time = 0.0) {
  CaseSpec spec =
      parse_case_file(std::string(WCMPS_SOURCE_DIR) + "/cases/" + case_dir + "/case.toml");
  spec.dl = dl;
  if (scheme == Scheme::Old) use_scheme_3a85288(spec);
  if (scheme == Scheme::Hydrostatic) {
    spec.gradient_renormalisation = GradientRenormalisation::Hydrostatic;
  }
  if (scheme == Scheme::Deviatoric) {
    spec.gradient_renormalisation = GradientRenormalisation::Deviatoric;
  }
  if (scheme == Scheme::Plain) spec.gradient_renormalisation = GradientRenormalisation::None;
  if (scheme == Scheme::NoCollision) spec.particle_collision = ParticleCollisionScheme::None;
  if (scheme == Scheme::FreeSlip || scheme == Scheme::WallFriction) {
    spec.artificial_viscosity_walls = ArtificialViscosityWalls::FreeSlip;
  }
  if (scheme == Scheme::WallFriction) spec.wall_friction = WallFrictionScheme::Spalding1961;
  if (scheme == Scheme::SideWalls) {
    spec.side_wall_friction = SideWallFrictionScheme::Spalding1961;
    spec.flume_width = 0.15;  // Lobovsky et al.'s tank
  }
  if (scheme == Scheme::BandRate) spec.density_rate = DensityRateScheme::Randles1996;
  spec.settle_time = 0.0;
  spec.end_time = 100.0;  // never reached: the benchmark decides how many steps
  auto sim = std::make_unique<Simulation>(spec, build_scene(spec));
  for (int k = 0; k < 20; ++k) sim->step(spec.end_time);
  while (sim->time() < start_time) sim->step(spec.end_time);
  return sim;
}

void step(benchmark::State& state, const char* case_dir, Scheme scheme = Scheme::Defaults,
          double start_time = 0.0) {
  const double dl = static_cast<double>(state.range(0)) * 1e-6;
  set_thread_count(static_cast<int>(state.range(1)));
  // Google Benchmark calls this function several times per benchmark (growing iteration counts,
  // then each repetition): the scene is built and stepped to start_time once per process, and
  // every call steps a copy of it, so that each times the same steps (the surge's way to 0.25 s
  // took half a minute per call). The warmed scenes are kept for the process: a full run holds
  // every benchmark's at once (`wcmps run` prints what one scene takes).
  static std::map<std::tuple<std::string, double, Scheme, double>, std::unique_ptr<Simulation>>
      warmed;
  auto& base = warmed[{case_dir, dl, scheme, start_time}];
  if (!base) base = make(case_dir, dl, scheme, start_time);
  const auto sim = std::make_unique<Simulation>(*base);
  const auto start = std::chrono::steady_clock::now();
  for (auto _ : state) sim->step(100.0);
  const std::chrono::duration<double> wall = std::chrono::steady_clock::now() - start;
  const auto particles = static_cast<double>(sim->particles().size());
  state.counters["particles"] = particles;
  state.counters["particle_steps_per_s"] = benchmark::Counter(
      particles * static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
  // Wall seconds per particle-step times cycles per second (the loop's own clock: the same wall
  // time as UseRealTime's, without its unit in the report).
  state.counters["cycles_per_particle_step"] =
      wall.count() * benchmark::CPUInfo::Get().cycles_per_second /
      (particles * static_cast<double>(state.iterations()));
}

void DamBreak(benchmark::State& state) {
  step(state, "dambreak");
}
void CaseI(benchmark::State& state) {
  step(state, "caseI");
}
void DamBreak_3a85288(benchmark::State& state) {
  step(state, "dambreak", Scheme::Old);
}
void CaseI_3a85288(benchmark::State& state) {
  step(state, "caseI", Scheme::Old);
}
// The surge's time (s): the front is on its way to the far wall, which it reaches at about
// 0.33 s (cases/dambreak/case.toml).
constexpr double kSurge = 0.25;
void DamBreakSurge(benchmark::State& state) {
  step(state, "dambreak", Scheme::Defaults, kSurge);
}
void DamBreakSurge_3a85288(benchmark::State& state) {
  step(state, "dambreak", Scheme::Old, kSurge);
}
void DamBreak_Hydrostatic(benchmark::State& state) {
  step(state, "dambreak", Scheme::Hydrostatic);
}
void CaseI_Hydrostatic(benchmark::State& state) {
  step(state, "caseI", Scheme::Hydrostatic);
}
void DamBreak_Deviatoric(benchmark::State& state) {
  step(state, "dambreak", Scheme::Deviatoric);
}
void CaseI_Deviatoric(benchmark::State& state) {
  step(state, "caseI", Scheme::Deviatoric);
}
void DamBreakSurge_Deviatoric(benchmark::State& state) {
  step(state, "dambreak", Scheme::Deviatoric, kSurge);
}
void DamBreak_Plain(benchmark::State& state) {
  step(state, "dambreak", Scheme::Plain);
}
void CaseI_Plain(benchmark::State& state) {
  step(state, "caseI", Scheme::Plain);
}
void DamBreakSurge_Plain(benchmark::State& state) {
  step(state, "dambreak", Scheme::Plain, kSurge);
}
void DamBreak_NoCollision(benchmark::State& state) {
  step(state, "dambreak", Scheme::NoCollision);
}
void CaseI_NoCollision(benchmark::State& state) {
  step(state, "caseI", Scheme::NoCollision);
}
void DamBreakSurge_NoCollision(benchmark::State& state) {
  step(state, "dambreak", Scheme::NoCollision, kSurge);
}
void DamBreak_FreeSlip(benchmark::State& state) {
  step(state, "dambreak", Scheme::FreeSlip);
}
void CaseI_FreeSlip(benchmark::State& state) {
  step(state, "caseI", Scheme::FreeSlip);
}
void DamBreakSurge_FreeSlip(benchmark::State& state) {
  step(state, "dambreak", Scheme::FreeSlip, kSurge);
}
void DamBreak_WallFriction(benchmark::State& state) {
  step(state, "dambreak", Scheme::WallFriction);
}
void CaseI_WallFriction(benchmark::State& state) {
  step(state, "caseI", Scheme::WallFriction);
}
void DamBreakSurge_WallFriction(benchmark::State& state) {
  step(state, "dambreak", Scheme::WallFriction, kSurge);
}
void DamBreak_SideWalls(benchmark::State& state) {
  step(state, "dambreak", Scheme::SideWalls);
}
void DamBreakSurge_SideWalls(benchmark::State& state) {
  step(state, "dambreak", Scheme::SideWalls, kSurge);
}
void DamBreak_BandRate(benchmark::State& state) {
  step(state, "dambreak", Scheme::BandRate);
}
void CaseI_BandRate(benchmark::State& state) {
  step(state, "caseI", Scheme::BandRate);
}

void NeighbourBuild(benchmark::State& state) {
  const double dl = static_cast<double>(state.range(0)) * 1e-6;
  set_thread_count(static_cast<int>(state.range(1)));
  const auto sim = make("caseI", dl);  // its fluid is in cell order, as in a run
  const Scene& scene = sim->scene();
  const ParticleSet& ps = scene.particles;
  std::vector<double> x = ps.now.x, y = ps.now.y;
  std::mt19937 random(7);
  std::uniform_real_distribution<double> jitter(-0.3 * dl, 0.3 * dl);
  for (std::int64_t i = ps.fluid_begin(); i < ps.size(); ++i) {
    x[i] += jitter(random);
    y[i] += jitter(random);
  }
  const double cutoff = sim->list_cutoff();
  CellGrid grid;
  grid.configure(scene.domain_lo, scene.domain_hi, cutoff);
  NeighbourList lists;
  const std::vector<IndexRange> owners = {{0, ps.wall_end()}, {ps.fluid_begin(), ps.size()}};
  for (auto _ : state) {
    grid.bin(x.data(), y.data(), ps.size());
    lists.build(grid, x.data(), y.data(), ps.size(), cutoff, owners);
    benchmark::DoNotOptimize(lists.pair_count());
  }
  state.counters["particles"] = static_cast<double>(ps.size());
  state.counters["pairs_per_particle"] =
      static_cast<double>(lists.pair_count()) / static_cast<double>(ps.size());
}

BENCHMARK(DamBreak)
    ->ArgNames({"DL_um", "threads"})
    ->ArgsProduct({{10000, 5000, 3500, 2000}, {1, 2}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK(CaseI)
    ->ArgNames({"DL_um", "threads"})
    ->ArgsProduct({{7000, 5000, 3500, 2500, 2000}, {1, 2}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK(DamBreak_3a85288)
    ->ArgNames({"DL_um", "threads"})
    ->ArgsProduct({{10000, 5000, 3500, 2000}, {1, 2}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK(CaseI_3a85288)
    ->ArgNames({"DL_um", "threads"})
    ->ArgsProduct({{7000, 5000, 3500, 2500, 2000}, {1, 2}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK(DamBreakSurge)
    ->ArgNames({"DL_um", "threads"})
    ->ArgsProduct({{10000, 5000}, {1, 2}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK(DamBreakSurge_3a85288)
    ->ArgNames({"DL_um", "threads"})
    ->ArgsProduct({{10000, 5000}, {1, 2}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK(DamBreak_Hydrostatic)
    ->ArgNames({"DL_um", "threads"})
    ->ArgsProduct({{5000, 2000}, {1}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK(CaseI_Hydrostatic)
    ->ArgNames({"DL_um", "threads"})
    ->ArgsProduct({{5000, 2000}, {1}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK(DamBreak_Deviatoric)
    ->ArgNames({"DL_um", "threads"})
    ->ArgsProduct({{5000, 2000}, {1}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK(CaseI_Deviatoric)
    ->ArgNames({"DL_um", "threads"})
    ->ArgsProduct({{5000, 2000}, {1}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK(DamBreakSurge_Deviatoric)
    ->ArgNames({"DL_um", "threads"})
    ->ArgsProduct({{5000}, {1}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK(DamBreak_Plain)
    ->ArgNames({"DL_um", "threads"})
    ->ArgsProduct({{5000, 2000}, {1}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK(CaseI_Plain)
    ->ArgNames({"DL_um", "threads"})
    ->ArgsProduct({{5000, 2000}, {1}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK(DamBreakSurge_Plain)
    ->ArgNames({"DL_um", "threads"})
    ->ArgsProduct({{5000}, {1}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK(DamBreak_NoCollision)
    ->ArgNames({"DL_um", "threads"})
    ->ArgsProduct({{5000, 2000}, {1}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK(CaseI_NoCollision)
    ->ArgNames({"DL_um", "threads"})
    ->ArgsProduct({{5000, 2000}, {1}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK(DamBreakSurge_NoCollision)
    ->ArgNames({"DL_um", "threads"})
    ->ArgsProduct({{5000}, {1}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK(DamBreak_FreeSlip)
    ->ArgNames({"DL_um", "threads"})
    ->ArgsProduct({{5000, 2000}, {1}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK(CaseI_FreeSlip)
    ->ArgNames({"DL_um", "threads"})
    ->ArgsProduct({{5000, 2000}, {1}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK(DamBreakSurge_FreeSlip)
    ->ArgNames({"DL_um", "threads"})
    ->ArgsProduct({{5000}, {1}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK(DamBreak_WallFriction)
    ->ArgNames({"DL_um", "threads"})
    ->ArgsProduct({{5000, 2000}, {1}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK(CaseI_WallFriction)
    ->ArgNames({"DL_um", "threads"})
    ->ArgsProduct({{5000, 2000}, {1}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK(DamBreakSurge_WallFriction)
    ->ArgNames({"DL_um", "threads"})
    ->ArgsProduct({{5000}, {1}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK(DamBreak_SideWalls)
    ->ArgNames({"DL_um", "threads"})
    ->ArgsProduct({{5000, 2000}, {1}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK(DamBreakSurge_SideWalls)
    ->ArgNames({"DL_um", "threads"})
    ->ArgsProduct({{5000}, {1}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK(DamBreak_BandRate)
    ->ArgNames({"DL_um", "threads"})
    ->ArgsProduct({{5000, 2000}, {1}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK(CaseI_BandRate)
    ->ArgNames({"DL_um", "threads"})
    ->ArgsProduct({{5000, 2000}, {1}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK(NeighbourBuild)
    ->ArgNames({"DL_um", "threads"})
    ->ArgsProduct({{5000, 2000}, {1, 2}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

/// The CPU's model name (/proc/cpuinfo; "unknown" where there is none).
std::string cpu_model() {
  std::ifstream in("/proc/cpuinfo");
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind("model name", 0) == 0) {
      const auto colon = line.find(':');
      const auto value =
          colon == std::string::npos ? colon : line.find_first_not_of(" \t", colon + 1);
      if (value != std::string::npos) return line.substr(value);
    }
  }
  return "unknown";
}

/// The widest vector instructions the build was compiled for (CMake's WCMPS_SIMD).
const char* simd_level() {
#if defined(__AVX512F__)
  return "AVX-512 (256-bit vectors preferred)";
#elif defined(__AVX2__)
  return "AVX2 + FMA";
#elif defined(__SSE2__)
  return "SSE2";
#else
  return "scalar";
#endif
}

}  // namespace

int main(int argc, char** argv) {
  benchmark::AddCustomContext("cpu_model", cpu_model());
  benchmark::AddCustomContext("simd", simd_level());
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
