// Work against precision: the error of a validation case against the wall time of its run, over
// particle sizes, time-step rules (the study's fixed 2.5e-5 s and the adaptive Courant step) and
// the pressure-gradient schemes the solver offers (docs/performance.md).
//
//   build/bin/bench_work_precision --study dambreak [--dl 0.01,0.007,0.005,0.0035]
//       [--steps courant,fixed] [--gradients all] [--repeats 3] [--threads 2] [--out FILE.csv]
//   build/bin/bench_work_precision --study hydrostatic ...
//   bench/plot_work_precision.py FILE.csv ...   (log-log plot, PNG)
//
// - dambreak (cases/dambreak): rms error of the surge-front position Z = z/a against Martin &
//   Moyce (1952) at their 15 measured times T = t sqrt(2g/a) <= 3.5, as the validation test
//   computes it (a fixed time shift of 0.15 in T, docs/validation.md).
// - hydrostatic (cases/hydrostatic, 0.7 m of still water): rms of p - rho g (H - y) over the
//   fluid particles below H - re, over t in [0.75, 1] s, as a fraction of rho g H.
//
// Wall time: the stepping alone (scene building and the error's sampling excluded), the median
// of --repeats runs; the runs are deterministic, so the error is that of every repeat (the
// step counts are checked equal). A run that becomes unstable gets error "nan", with the
// steps and time it ran, and the solver's report on stderr.

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "core/Error.h"
#include "core/Parallel.h"
#include "core/SchemeTable.h"
#include "scene/CaseParser.h"
#include "scene/SceneBuilder.h"
#include "simulation/Simulation.h"
#include "support/DamBreakFront.h"

namespace {

using namespace wcmps;

using namespace dambreak;

struct Result {
  std::int64_t particles = 0, steps = 0;
  double seconds = 0.0;  // stepping only
  double error = 0.0;    // NaN if the run became unstable
  std::string unstable;  // the solver's report, if it did
};

/// Steps to each sample time, timing the stepping; `sample` sees the state at each.
template <class Sample>
Result run(const CaseSpec& spec, const std::vector<double>& times, Sample&& sample) {
  Simulation sim(spec, build_scene(spec));
  Result r;
  r.particles = sim.particles().size();
  using clock = std::chrono::steady_clock;
  for (const double t : times) {
    const auto t0 = clock::now();
    try {
      while (sim.time() < t - 1e-12) sim.step(t);
    } catch (const InstabilityError& e) {
      r.unstable = e.report().str();
    }
    r.seconds += std::chrono::duration<double>(clock::now() - t0).count();
    if (!r.unstable.empty()) break;
    sample(sim);
  }
  r.steps = sim.steps();
  return r;
}

Result dam_break(CaseSpec spec, const std::vector<Point>& data) {
  const double scale = std::sqrt(2.0 * kG / kA);  // T = t scale
  std::vector<double> times;
  for (double T = 0.02; T <= 3.5 + 1e-9; T += 0.02) times.push_back(T / scale);
  spec.end_time = times.back();
  std::vector<Point> front;
  Result r = run(spec, times, [&](const Simulation& sim) {
    const ParticleSet& ps = sim.particles();
    double x = 0.0;
    for (std::int64_t i = ps.fluid_begin(); i < ps.size(); ++i) x = std::max(x, ps.now.x[i]);
    front.push_back({sim.time() * scale, (x + 0.5 * spec.dl) / kA});
  });
  if (!r.unstable.empty()) {
    r.error = NAN;
    return r;
  }
  r.error = rms_front_error(front, data);
  return r;
}

Result still_water(CaseSpec spec) {
  const double H = 0.7, end = 1.0, window = 0.25;
  std::vector<double> times;
  for (double t = 0.05; t <= end + 1e-9; t += 0.05) times.push_back(t);
  spec.end_time = end;
  const double rho_g = spec.density * -spec.gravity.y;
  double e2 = 0.0;
  std::int64_t count = 0;
  Result r = run(spec, times, [&](const Simulation& sim) {
    if (sim.time() < end - window - 1e-9) return;
    const ParticleSet& ps = sim.particles();
    for (std::int64_t i = ps.fluid_begin(); i < ps.size(); ++i) {
      if (ps.now.y[i] >= H - spec.re()) continue;
      const double e = ps.now.p[i] - rho_g * (H - ps.now.y[i]);
      e2 += e * e;
      ++count;
    }
  });
  r.error =
      r.unstable.empty()
          ? std::sqrt(e2 / static_cast<double>(std::max<std::int64_t>(count, 1))) / (rho_g * H)
          : NAN;
  return r;
}

std::vector<std::string> split(const std::string& s) {
  std::vector<std::string> out;
  std::stringstream in(s);
  std::string item;
  while (std::getline(in, item, ',')) {
    if (!item.empty()) out.push_back(item);
  }
  return out;
}

int usage(const char* msg) {
  std::fprintf(stderr,
               "bench_work_precision: %s\nusage: bench_work_precision --study dambreak|hydrostatic "
               "[--dl D1,D2,...] [--steps courant,fixed] [--gradients all|NAME,...] "
               "[--repeats N] [--threads N] [--out FILE.csv]\n",
               msg);
  return 2;
}

}  // namespace

int main(int argc, char** argv) {
  std::string study, dls, steps = "courant,fixed", gradients = "all", out;
  int repeats = 3, threads = 2;
  for (int k = 1; k < argc; ++k) {
    const std::string a = argv[k];
    auto value = [&]() -> std::string {
      if (k + 1 >= argc) throw std::invalid_argument(a + " needs a value");
      return argv[++k];
    };
    try {
      if (a == "--study") {
        study = value();
      } else if (a == "--dl") {
        dls = value();
      } else if (a == "--steps") {
        steps = value();
      } else if (a == "--gradients") {
        gradients = value();
      } else if (a == "--repeats") {
        repeats = std::stoi(value());
      } else if (a == "--threads") {
        threads = std::stoi(value());
      } else if (a == "--out") {
        out = value();
      } else {
        return usage(("unknown argument " + a).c_str());
      }
    } catch (const std::exception& e) {
      return usage(e.what());
    }
  }
  if (study != "dambreak" && study != "hydrostatic") return usage("--study is required");
  if (repeats < 1 || threads < 1) return usage("--repeats and --threads must be >= 1");
  if (dls.empty()) dls = study == "dambreak" ? "0.01,0.007,0.005,0.0035" : "0.02,0.014,0.01,0.007";
  std::vector<PressureGradientScheme> schemes;
  for (const auto& row : kPressureGradientSchemes) {
    const auto wanted = split(gradients);
    if (gradients == "all" || std::find(wanted.begin(), wanted.end(), row.key) != wanted.end()) {
      schemes.push_back(row.scheme);
    }
  }
  if (schemes.empty()) return usage("--gradients names no scheme");

  set_thread_count(threads);
  const std::string source = WCMPS_SOURCE_DIR;
  std::ostringstream csv;
  csv << "study,dl_m,particles,step_rule,gradient,steps,repeats,wall_seconds_median,"
         "wall_seconds_min,wall_seconds_max,error,error_measure,threads\n";
  try {
    const CaseSpec base = parse_case_file(source + "/cases/" + study + "/case.toml");
    const auto data = study == "dambreak"
                          ? martin_moyce(source + "/cases/dambreak/martin_moyce_1952.csv")
                          : std::vector<Point>{};
    for (const auto& d : split(dls)) {
      for (const auto& rule : split(steps)) {
        for (const auto scheme : schemes) {
          CaseSpec spec = base;
          spec.dl = std::stod(d);
          spec.settle_time = 0.0;
          if (rule == "fixed") {
            spec.step_mode = TimeStepMode::Fixed;
            spec.fixed_step = 2.5e-5;  // the study's
          } else if (rule == "courant") {
            spec.step_mode = TimeStepMode::Courant;
          } else {
            return usage(("unknown step rule " + rule).c_str());
          }
          spec.pressure_gradient = scheme;
          std::vector<double> seconds;
          Result first;
          for (int k = 0; k < repeats; ++k) {
            const Result r = study == "dambreak" ? dam_break(spec, data) : still_water(spec);
            if (k == 0) first = r;
            if (k > 0 && r.steps != first.steps) {
              std::fprintf(stderr, "bench_work_precision: repeat %d took another path\n", k);
              return 1;
            }
            seconds.push_back(r.seconds);
            if (!r.unstable.empty()) {
              std::fprintf(stderr, "  unstable: %s\n", r.unstable.c_str());
              break;  // an unstable run is not timed again
            }
          }
          std::sort(seconds.begin(), seconds.end());
          const std::string name(scheme_key(kPressureGradientSchemes, scheme));
          char line[512];
          std::snprintf(line, sizeof line, "%s,%g,%lld,%s,%s,%lld,%zu,%.4g,%.4g,%.4g,%.6g,%s,%d\n",
                        study.c_str(), spec.dl, static_cast<long long>(first.particles),
                        rule.c_str(), name.c_str(), static_cast<long long>(first.steps),
                        seconds.size(), seconds[seconds.size() / 2], seconds.front(),
                        seconds.back(), first.error,
                        study == "dambreak" ? "rms_front_Z" : "rms_p_over_rho_g_H", threads);
          csv << line;
          std::fputs(line, stderr);
        }
      }
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bench_work_precision: %s\n", e.what());
    return 1;
  }
  if (out.empty()) {
    std::cout << csv.str();
  } else {
    std::ofstream f(out);
    f << csv.str();
    if (!f) {
      std::fprintf(stderr, "bench_work_precision: cannot write %s\n", out.c_str());
      return 1;
    }
  }
  return 0;
}
