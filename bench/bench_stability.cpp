// Stability under stress (docs/performance.md, "Stability"): each run ends either stable or with
// the solver's own instability report (InstabilityError: step, time, particle, reason), never a
// crash or a silent NaN; the table says which.
//
//   build/bin/bench_stability [--only still|sweep|jitter|fast_block|lattice_shear] [--quick]
//                             [--threads 2]
//                             [--out FILE.csv] [--series FILE.csv]
//
// - still: still water over the 40-degree bed (cases/hydrostatic-slope, after its 1 s of
//   settling) for 20 s: largest |n/n0 - 1| of the fluid, rms speed over sqrt(g H) (spurious
//   motion), and particles lost (above the still water by more than 3 DL, or out of the
//   tank); a sample every 0.5 s in --series.
// - sweep: the Courant number (0.2 ... 1.0) and the sound speed (2.5, 5, 10 and 20 times the
//   flow's largest speed) for the dam break (to 0.35 s, T = 3.46) and case I (to 0.1 s, DL 5 mm).
// - jitter: the dam break and the flat still water started from a lattice jittered by up to
//   10 % of DL in x and y (fixed seed).
// - fast_block: case I with the block's measured distances doubled (twice the speed), to 0.4 s.
// - lattice_shear: why still water started on its lattice moves (docs/validation.md, "What
//   starts it: the lattice's shear under pressure"). A column of the flat tank's hydrostatic
//   lattice (cases/hydrostatic, no settling) slid down along its neighbours by 0.05 DL, against
//   the lattice as built: the column's extra mean acceleration over the first 2 ms, by depth, as
//   a stiffness k = -(extra acceleration) / slide (1/s^2; < 0: the slide is pushed on, growing
//   as e^(t sqrt(-k))), and the summed n of one of its particles before and after the slide. Its
//   own table, not a row of the CSV.
// --quick shortens every run (still water at DL 20 mm for 1 s after 0.2 s of settling, case I
// to 0.005 s, the fast block at DL 7 mm) for the smoke tests.

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <random>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "core/Error.h"
#include "core/Parallel.h"
#include "operators/Kernel.h"
#include "scene/CaseParser.h"
#include "scene/SceneBuilder.h"
#include "simulation/Simulation.h"

namespace {

using namespace wcmps;

struct Outcome {
  std::string test, setting;
  bool stable = true;
  double t_end = 0.0, t_reached = 0.0;
  std::int64_t steps = 0, particles = 0;
  double wall_seconds = 0.0;
  double max_density_error = 0.0;  ///< max |n/n0 - 1| of the fluid over the samples
  double max_rms_speed = 0.0;      ///< over sqrt(g H), largest over the samples
  std::int64_t lost = 0;           ///< at the end
  std::string report;              ///< the instability report, if any
};

CaseSpec load(const std::string& name) {
  return parse_case_file(std::string(WCMPS_SOURCE_DIR) + "/cases/" + name + "/case.toml");
}

/// Runs `spec` (scene changed by `prepare`) to t_end, sampling every `every` seconds.
template <class Prepare, class Sample>
Outcome run(std::string test, std::string setting, const CaseSpec& spec, double t_end, double every,
            Prepare&& prepare, Sample&& sample) {
  Outcome o;
  o.test = std::move(test);
  o.setting = std::move(setting);
  o.t_end = t_end;
  Scene scene = build_scene(spec);
  prepare(scene);
  Simulation sim(spec, std::move(scene));
  o.particles = sim.particles().size();
  const auto t0 = std::chrono::steady_clock::now();
  try {
    sim.settle();
    every = std::min(every, t_end);
    for (double t = every; t <= t_end + 1e-9; t += every) {
      while (sim.time() < t - 1e-12) sim.step(t);
      sample(sim, o);
    }
  } catch (const InstabilityError& e) {
    o.stable = false;
    o.report = e.report().str();
  }
  o.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  o.t_reached = sim.time();
  o.steps = sim.steps();
  return o;
}

/// Density error and spurious speed of the fluid, for still water of height H whose surface is
/// at y = level.
auto still_sampler(double H, double level, std::ofstream* series, const std::string& tag) {
  return [H, level, series, tag](const Simulation& sim, Outcome& o) {
    const ParticleSet& ps = sim.particles();
    const double n0 = sim.operators().n0();
    double dn = 0.0, s2 = 0.0;
    std::int64_t lost = 0;
    const Vec2 lo = sim.scene().domain_lo, hi = sim.scene().domain_hi;
    const double dl = sim.time_step_rule().dl;
    for (std::int64_t i = ps.fluid_begin(); i < ps.size(); ++i) {
      dn = std::max(dn, std::abs(ps.now.n[i] / n0 - 1.0));
      s2 += ps.now.u[i] * ps.now.u[i] + ps.now.v[i] * ps.now.v[i];
      const double x = ps.now.x[i], y = ps.now.y[i];
      if (y > level + 3.0 * dl || x < lo.x || x > hi.x || y < lo.y) ++lost;
    }
    const double rms = std::sqrt(s2 / static_cast<double>(ps.fluid_count())) / std::sqrt(9.81 * H);
    o.max_density_error = std::max(o.max_density_error, dn);
    o.max_rms_speed = std::max(o.max_rms_speed, rms);
    o.lost = lost;
    if (series) {
      *series << tag << ',' << sim.time() << ',' << dn << ',' << rms << ',' << lost << '\n';
    }
  };
}

void no_change(Scene&) {}

void jitter(Scene& scene, double dl) {
  std::mt19937 rng(20261128);
  std::uniform_real_distribution<double> d(-0.1 * dl, 0.1 * dl);
  ParticleSet& ps = scene.particles;
  for (std::int64_t i = ps.fluid_begin(); i < ps.size(); ++i) {
    ps.now.x[i] += d(rng);
    ps.now.y[i] += d(rng);
  }
}

/// One column of the lattice slid along its neighbours (the lattice_shear probe above).
struct ShearProbe {
  int column;                 ///< lattice column, counted from the left wall (0: beside it)
  double depth_lo, depth_hi;  ///< m below the still water's surface
  double stiffness;           ///< 1/s^2: -(extra acceleration) / slide; < 0 pushes the slide on
  /// The summed n of the column's particle nearest mid-depth: slid / as built - 1.
  double n_change;
};

/// The fluid ids of lattice column `column` (x in [column, column + 1) DL from the wall at x = 0).
std::vector<std::int32_t> column_ids(const Scene& scene, int column, double dl) {
  std::vector<std::int32_t> ids;
  const ParticleSet& ps = scene.particles;
  for (std::int64_t i = ps.fluid_begin(); i < ps.size(); ++i) {
    const double x = ps.now.x[i] / dl;
    if (x > column && x < column + 1) ids.push_back(ps.id[i]);
  }
  return ids;
}

/// The summed n of particle i over every particle of the set (brute force: one particle).
double summed_n(const ParticleSet& ps, std::int64_t i, const Kernel& w) {
  double n = 0.0;
  for (std::int64_t j = 0; j < ps.size(); ++j) {
    if (j == i) continue;
    n += w(std::hypot(ps.now.x[j] - ps.now.x[i], ps.now.y[j] - ps.now.y[i]));
  }
  return n;
}

/// The flat tank (cases/hydrostatic, no settling) to t = 2 ms with column `column` slid down by
/// `slide` (m): each depth band's mean vertical acceleration of the column (v / t, from rest).
std::vector<double> column_accelerations(const CaseSpec& spec, int column, double slide,
                                         const std::vector<std::pair<double, double>>& bands,
                                         double* n_mid) {
  // About 20 steps: long enough for the pair forces to act through the time integration, short
  // enough that the column moves 2e-6 m of its own (a = 1 m/s^2), 1/250 of the slide: the
  // response is the linear one.
  constexpr double kProbeTime = 0.002;  // s
  Scene scene = build_scene(spec);
  const std::vector<std::int32_t> ids = column_ids(scene, column, spec.dl);
  ParticleSet& ps = scene.particles;
  std::vector<char> in_column(ps.size(), 0);
  for (const std::int32_t id : ids) in_column[id] = 1;
  for (std::int64_t i = ps.fluid_begin(); i < ps.size(); ++i) {
    if (in_column[ps.id[i]]) ps.now.y[i] -= slide;
  }
  const double level = scene.fluid_height;  // the bed at y = 0 (cases/hydrostatic)
  Simulation sim(spec, std::move(scene));
  {
    // The column's particle nearest mid-depth, its summed n in the arrangement as started.
    const ParticleSet& s = sim.particles();
    std::int64_t mid = -1;
    for (std::int64_t i = s.fluid_begin(); i < s.size(); ++i) {
      if (in_column[s.id[i]] &&
          (mid < 0 || std::abs(s.now.y[i] - 0.5 * level) < std::abs(s.now.y[mid] - 0.5 * level))) {
        mid = i;
      }
    }
    *n_mid = summed_n(s, mid, sim.operators().kernel());
  }
  while (sim.time() < kProbeTime - 1e-12) sim.step(kProbeTime);
  const ParticleSet& s = sim.particles();
  std::vector<double> sum(bands.size(), 0.0), count(bands.size(), 0.0);
  for (std::int64_t i = s.fluid_begin(); i < s.size(); ++i) {
    if (!in_column[s.id[i]]) continue;
    const double depth = level - s.now.y[i];
    for (std::size_t b = 0; b < bands.size(); ++b) {
      if (depth >= bands[b].first && depth < bands[b].second) {
        sum[b] += s.now.v[i];
        count[b] += 1.0;
      }
    }
  }
  std::vector<double> a(bands.size());
  for (std::size_t b = 0; b < bands.size(); ++b) a[b] = sum[b] / count[b] / sim.time();
  return a;
}

std::vector<ShearProbe> lattice_shear() {
  CaseSpec spec = load("hydrostatic");
  spec.settle_time = 0.0;
  const double slide = 0.05 * spec.dl;
  const std::vector<std::pair<double, double>> bands = {{0.05, 0.25}, {0.25, 0.45}, {0.45, 0.65}};
  std::vector<ShearProbe> rows;
  for (const int column : {0, 1, 10}) {
    double n_built = 0.0, n_slid = 0.0;
    const std::vector<double> built = column_accelerations(spec, column, 0.0, bands, &n_built);
    const std::vector<double> slid = column_accelerations(spec, column, slide, bands, &n_slid);
    for (std::size_t b = 0; b < bands.size(); ++b) {
      // The slide is -slide in y; the extra acceleration pushes it back if it is > 0.
      rows.push_back({column, bands[b].first, bands[b].second, (slid[b] - built[b]) / slide,
                      n_slid / n_built - 1.0});
    }
  }
  return rows;
}

}  // namespace

int main(int argc, char** argv) {
  std::string only, out, series_file;
  bool quick = false;
  int threads = 2;
  for (int k = 1; k < argc; ++k) {
    const std::string a = argv[k];
    if (a == "--quick") {
      quick = true;
    } else if ((a == "--only" || a == "--out" || a == "--series" || a == "--threads") &&
               k + 1 < argc) {
      const std::string v = argv[++k];
      if (a == "--only") only = v;
      if (a == "--out") out = v;
      if (a == "--series") series_file = v;
      if (a == "--threads") threads = std::stoi(v);
    } else {
      std::fprintf(stderr,
                   "usage: bench_stability [--only still|sweep|jitter|fast_block|lattice_shear] "
                   "[--quick] "
                   "[--threads N] [--out FILE.csv] [--series FILE.csv]\n");
      return 2;
    }
  }
  set_thread_count(threads);
  std::ofstream series_stream;
  if (!series_file.empty()) {
    series_stream.open(series_file);
    series_stream << "run,t_s,max_density_error,rms_speed_over_sqrt_gH,lost\n";
  }
  std::ofstream* series = series_file.empty() ? nullptr : &series_stream;
  std::vector<Outcome> rows;
  auto want = [&](const char* name) { return only.empty() || only == name; };
  auto report = [&](const Outcome& o) {
    rows.push_back(o);
    std::fprintf(stderr, "%-10s %-34s %-8s t %.4g/%.4g s  %.1f s  %s\n", o.test.c_str(),
                 o.setting.c_str(), o.stable ? "stable" : "UNSTABLE", o.t_reached, o.t_end,
                 o.wall_seconds, o.report.c_str());
  };
  auto nothing = [](const Simulation&, Outcome&) {};

  try {
    if (want("still")) {
      CaseSpec spec = load("hydrostatic-slope");
      if (quick) {
        spec.dl = 0.02;
        spec.settle_time = 0.2;
      }
      const double t_end = quick ? 1.0 : 20.0;
      char setting[96];
      std::snprintf(setting, sizeof setting, "40-degree bed, DL %g mm, %g s", spec.dl * 1000,
                    t_end);
      report(run("still", setting, spec, t_end, 0.5, no_change,
                 still_sampler(0.7, 0.0, series, "still")));
    }
    if (want("sweep")) {
      const std::vector<double> courants =
          quick ? std::vector<double>{0.4, 1.0} : std::vector<double>{0.2, 0.4, 0.6, 0.8, 1.0};
      // Dam break: the flow's largest speed is the surge front's 2 sqrt(2 g a) = 3.96 m/s.
      for (const double factor : {2.5, 5.0, 10.0, 20.0}) {
        for (const double c : courants) {
          CaseSpec spec = load("dambreak");
          spec.sound_speed = factor * 3.96;
          spec.courant = c;
          char setting[96];
          std::snprintf(setting, sizeof setting, "dam break c0 = %g x 3.96 m/s, Courant %g", factor,
                        c);
          report(run("sweep", setting, spec, quick ? 0.05 : 0.35, 0.01, no_change, nothing));
        }
      }
      // Case I: the block reaches about 1 m/s; c0 = 26 m/s is the case's.
      for (const double c0 : {13.0, 26.0}) {
        for (const double c : courants) {
          CaseSpec spec = load("caseI");
          spec.settle_time = 0.0;
          spec.sound_speed = c0;
          spec.courant = c;
          char setting[96];
          std::snprintf(setting, sizeof setting, "case I c0 = %g m/s, Courant %g", c0, c);
          report(run("sweep", setting, spec, quick ? 0.005 : 0.1, 0.005, no_change, nothing));
        }
      }
    }
    if (want("jitter")) {
      CaseSpec dam = load("dambreak");
      dam.dl = 0.01;
      report(run(
          "jitter", "dam break DL 10 mm, +-10 % DL", dam, quick ? 0.05 : 0.35, 0.01,
          [&](Scene& s) { jitter(s, dam.dl); }, nothing));
      CaseSpec still = load("hydrostatic");
      still.settle_time = 0.0;
      report(run(
          "jitter", "flat still water DL 10 mm, +-10 % DL", still, quick ? 0.2 : 2.0, 0.5,
          [&](Scene& s) { jitter(s, still.dl); }, still_sampler(0.7, 0.7, series, "jitter")));
    }
    if (want("fast_block")) {
      CaseSpec spec = load("caseI");
      if (quick) {
        spec.settle_time = 0.0;
        spec.dl = 0.007;
      }
      for (double& s : spec.body->motion.distances) s *= 2.0;
      report(run("fast_block", "case I, block at twice the measured speed", spec,
                 quick ? 0.01 : 0.4, 0.01, no_change, nothing));
    }
    if (want("lattice_shear")) {
      // Its own table (the same with --quick: three short runs of 2 ms).
      std::printf(
          "| column | depth (m) | stiffness k (1/s^2) | e-folding time (s) | summed n, slid / "
          "built - 1 |\n"
          "|---|---|---|---|---|\n");
      for (const ShearProbe& r : lattice_shear()) {
        char efold[32] = "restoring";
        if (r.stiffness < 0.0)
          std::snprintf(efold, sizeof efold, "%.3f", 1.0 / std::sqrt(-r.stiffness));
        std::printf("| %d | %.2f-%.2f | %.0f | %s | %.2e |\n", r.column, r.depth_lo, r.depth_hi,
                    r.stiffness, efold, r.n_change);
      }
      std::fflush(stdout);
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bench_stability: %s\n", e.what());
    return 1;
  }

  if (only == "lattice_shear") return 0;  // its table is all it prints

  std::ostringstream csv;
  csv << "test,setting,outcome,t_end_s,t_reached_s,steps,particles,wall_seconds,"
         "max_density_error,max_rms_speed_over_sqrt_gH,lost,report\n";
  for (const auto& o : rows) {
    csv << o.test << ",\"" << o.setting << "\"," << (o.stable ? "stable" : "unstable") << ','
        << o.t_end << ',' << o.t_reached << ',' << o.steps << ',' << o.particles << ','
        << o.wall_seconds << ',' << o.max_density_error << ',' << o.max_rms_speed << ',' << o.lost
        << ",\"" << o.report << "\"\n";
  }
  if (out.empty()) {
    std::cout << csv.str();
  } else {
    std::ofstream f(out);
    f << csv.str();
  }
  return 0;
}
