// Work against precision: the error of a validation case against the wall time of its run, over
// particle sizes, time-step rules (the study's fixed 2.5e-5 s, the adaptive Courant step with the
// case's Courant number or courant:C with another) and
// the pressure-gradient schemes the solver offers, and the stabilisation of docs/method.md (the
// defaults) against the scheme of commit 3a85288 and against the defaults before 2026-12-07,
// session 13 ("plain": the gradient not renormalised) and before 2026-12-08, session 15
// ("nocollision": no particle collision) (docs/performance.md).
//
//   build/bin/bench_work_precision --study dambreak [--dl 0.01,0.007,0.005,0.0035]
//       [--steps courant,fixed,courant:0.8] [--gradients all]
//       [--stabilisation default,plain,nocollision,3a85288] [--repeats 3] [--threads 2]
//       [--out FILE.csv]
//   build/bin/bench_work_precision --study hydrostatic ...
//   build/bin/bench_work_precision --study caseI [--dl 0.01,0.007,0.005] [--reference-dl 0.0025]
//       [--reference FILE.csv] [--reference-stabilisation default|3a85288] [--section A]
//       [--time 0.4] [--samples PREFIX] ...
//   bench/plot_work_precision.py FILE.csv ...   (log-log plot, PNG)
//
// - dambreak (cases/dambreak): rms error of the surge-front position Z = z/a against Martin &
//   Moyce (1952) at their 15 measured times T = t sqrt(2g/a) <= 3.5, as the validation test
//   computes it (a fixed time shift of 0.15 in T, docs/validation.md).
// - hydrostatic (cases/hydrostatic, 0.7 m of still water): rms of p - rho g (H - y) over the
//   fluid particles below H - re, over t in [0.75, 1] s, as a fraction of rho g H.
// - caseI (cases/caseI, the study's sliding block): no measurement to compare with, so a finer
//   run is the reference (--reference-dl, with the defaults or --reference-stabilisation; its
//   samples are kept in --reference FILE and reused while its settings match). Two errors at --time
//   (0.4 s), a CSV row each: rms_eta: the wave eta(x) - eta(x, t = 0) at x = 0.05, 0.06 ... 2.00 m
//   (the top of the water
//     by the wave gauges' algorithm, operators/WaterSpan.h, against the run's own still-water
//     level after settling, as a gauge zeroed at still water reads), rms of its difference from
//     the reference's where both have water, over the reference's largest |eta - eta0|;
//   rms_u_<section>: the velocity on the section (51 points from the start of the water, Y = 0,
//     on the bed or the block, to the surface, Y = 1, as `wcmps post` samples it: the longest
//     stretch with coverage 0.5, the MPS weight's Shepard average), rms of |u - u_ref| at equal
//     Y, over max |u_ref|.
//   Its wall time includes the 0.5 s of settling (the block held) that every case I run does.
//   --samples PREFIX writes each run's samples to PREFIX_<dl>_<rule>[_3a85288].csv, as the
//   reference's.
//
// Wall time: the stepping and any settling (scene building and the error's sampling excluded), the
// median of --repeats runs; the runs are deterministic, so the error is that of every repeat (the
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
#include "io/AtomicFile.h"
#include "neighbours/CellGrid.h"
#include "operators/Kernel.h"
#include "operators/WaterSpan.h"
#include "scene/CaseParser.h"
#include "scene/SceneBuilder.h"
#include "simulation/Simulation.h"
#include "simulation/WaveGauges.h"
#include "support/DamBreakFront.h"

namespace {

using namespace wcmps;

using namespace dambreak;

struct Result {
  std::int64_t particles = 0, steps = 0;
  double seconds = 0.0;  // stepping (settling included) only
  double error = 0.0;    // NaN if the run became unstable
  std::string unstable;  // the solver's report, if it did
};

/// Settles if the case does, then steps to each sample time, timing both; `sample` sees the
/// state at each.
template <class Sample>
Result run(const CaseSpec& spec, const std::vector<double>& times, Sample&& sample) {
  Simulation sim(spec, build_scene(spec));
  Result r;
  r.particles = sim.particles().size();
  using clock = std::chrono::steady_clock;
  if (sim.settling()) {
    const auto t0 = clock::now();
    try {
      sim.settle();
    } catch (const InstabilityError& e) {
      r.unstable = e.report().str();
      r.steps = sim.settle_steps();
      r.seconds = std::chrono::duration<double>(clock::now() - t0).count();
      return r;
    }
    r.seconds += std::chrono::duration<double>(clock::now() - t0).count();
  }
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
  r.steps = sim.settle_steps() + sim.steps();
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

/// The fluid particles of a state, binned, for kernel sums at arbitrary points: the coverage
/// (operators/WaterSpan.h) and the Shepard average of the velocity with the MPS weight.
class FluidProbe {
 public:
  FluidProbe(const Simulation& sim, const CaseSpec& spec)
      : ps_(sim.particles()), w_{spec.re()}, scale_(coverage_scale(spec.dl, spec.re())) {
    grid_.configure(sim.scene().domain_lo, sim.scene().domain_hi, spec.re());
    grid_.bin(ps_.now.x.data() + ps_.fluid_begin(), ps_.now.y.data() + ps_.fluid_begin(),
              ps_.fluid_count());
  }
  /// Sum of W, and of W u and W v, over the fluid within re of (x, y).
  void sums(double x, double y, double& w, double& wu, double& wv) const {
    w = wu = wv = 0.0;
    const std::int64_t f = ps_.fluid_begin();
    const int cx = grid_.cell_x(x), cy = grid_.cell_y(y);
    for (int j = std::max(cy - 1, 0); j <= std::min(cy + 1, grid_.ny() - 1); ++j) {
      for (int i = std::max(cx - 1, 0); i <= std::min(cx + 1, grid_.nx() - 1); ++i) {
        for (const std::int32_t* k = grid_.cell_begin(i, j); k != grid_.cell_end(i, j); ++k) {
          const std::int64_t n = f + *k;
          const double wk = w_(std::hypot(ps_.now.x[n] - x, ps_.now.y[n] - y));
          w += wk;
          wu += wk * ps_.now.u[n];
          wv += wk * ps_.now.v[n];
        }
      }
    }
  }
  double coverage(double x, double y) const {
    double w, wu, wv;
    sums(x, y, w, wu, wv);
    return w * scale_;
  }

 private:
  const ParticleSet& ps_;
  Kernel w_;
  double scale_;
  CellGrid grid_;
};

/// What the case I study compares: the surface at the stations, (u, v) at the section's Y.
struct CaseISamples {
  std::vector<double> eta;   // at the sample time; NaN where the vertical meets no water
  std::vector<double> eta0;  // at t = 0 (after settling): the still-water level of this run
  std::vector<double> u, v;  // at Y = k / (kSectionSamples - 1)
  double depth = 0.0;        // H, the section's water column
  static constexpr int kSectionSamples = 51;  // as [post] section_samples of cases/caseI
  static std::vector<double> stations() {
    std::vector<double> x;
    for (int k = 5; k <= 200; ++k) x.push_back(0.01 * k);
    return x;
  }
};

/// The top of the water above each station (the wave gauges' algorithm).
std::vector<double> surface(const Simulation& sim, const CaseSpec& spec) {
  CaseSpec gauge_spec = spec;
  gauge_spec.gauges.x = CaseISamples::stations();
  gauge_spec.gauges.interval = 0.0;
  WaveGauges gauges(gauge_spec, sim.scene().domain_lo, sim.scene().domain_hi);
  gauges.sample(sim);
  const double* row = gauges.sample_values(0);
  return {row + 1, row + 1 + gauge_spec.gauges.x.size()};
}

void sample_section(const Simulation& sim, const CaseSpec& spec, const SectionSpec& section,
                    CaseISamples& out) {
  const FluidProbe probe(sim, spec);
  const Vec2 o = section.origin, d = section.direction;
  const auto wet = [&](double s) {
    return probe.coverage(o.x + s * d.x, o.y + s * d.y) >= kWaterEdgeCoverage;
  };
  // The whole line through the tank (2 m either way): the water column is the longest wet
  // stretch, from the bed (or the block) to the surface, as the filters' sections take it.
  const WaterSpan span = longest_water_span(wet, -2.0, 2.0, 0.25 * spec.dl, 1e-3 * spec.dl);
  if (!span.found) throw std::runtime_error("section " + section.name + " meets no water");
  out.depth = span.s1 - span.s0;
  out.u.clear();
  out.v.clear();
  for (int k = 0; k < CaseISamples::kSectionSamples; ++k) {
    const double s = span.s0 + (span.s1 - span.s0) * k / (CaseISamples::kSectionSamples - 1.0);
    double w, wu, wv;
    probe.sums(o.x + s * d.x, o.y + s * d.y, w, wu, wv);
    out.u.push_back(w > 0.0 ? wu / w : 0.0);
    out.v.push_back(w > 0.0 ? wv / w : 0.0);
  }
}

Result case_i(CaseSpec spec, double time, const SectionSpec& section, CaseISamples* samples) {
  spec.end_time = time;
  return run(spec, {0.0, time}, [&](const Simulation& sim) {
    if (sim.time() < 0.5 * time) {
      samples->eta0 = surface(sim, spec);
    } else {
      samples->eta = surface(sim, spec);
      sample_section(sim, spec, section, *samples);
    }
  });
}

/// The reference file: a first line naming its settings, then "eta,x,eta,eta0", "u,Y,u,v" and
/// "H,section,depth" rows.
std::string reference_key(const CaseSpec& spec, double time, const std::string& section) {
  char key[256];
  std::snprintf(key, sizeof key, "# caseI reference dl=%g time=%g section=%s settle=%g step=%s %g",
                spec.dl, time, section.c_str(), spec.settle_time,
                spec.step_mode == TimeStepMode::Fixed ? "fixed" : "courant",
                spec.step_mode == TimeStepMode::Fixed ? spec.fixed_step : spec.courant);
  std::string k = key;
  // The scheme the reference ran: a file made under other defaults is not reused.
  k += " scheme=" + std::string(scheme_key(kNegativePressureSchemes, spec.negative_pressure)) +
       "," + std::string(scheme_key(kNumberDensitySchemes, spec.number_density)) + "," +
       std::string(scheme_key(kFreeSurfaceSchemes, spec.free_surface)) + "," +
       std::string(scheme_key(kShiftingSchemes, spec.shifting));
  if (spec.settle_courant) {
    std::snprintf(key, sizeof key, " settle_courant=%g", *spec.settle_courant);
    k += key;
  }
  return k;
}

bool read_reference(const std::string& path, const std::string& key, CaseISamples& ref) {
  std::ifstream in(path);
  std::string line;
  if (!in || !std::getline(in, line) || line != key) return false;
  while (std::getline(in, line)) {
    const auto f = split(line);
    if (f.size() == 4 && f[0] == "eta") {
      ref.eta.push_back(std::stod(f[2]));
      ref.eta0.push_back(std::stod(f[3]));
    }
    if (f.size() == 4 && f[0] == "u") {
      ref.u.push_back(std::stod(f[2]));
      ref.v.push_back(std::stod(f[3]));
    }
    if (f.size() == 3 && f[0] == "H") ref.depth = std::stod(f[2]);
  }
  return ref.eta.size() == CaseISamples::stations().size() &&
         ref.u.size() == CaseISamples::kSectionSamples && ref.depth > 0.0;
}

void write_reference(const std::string& path, const std::string& key, const CaseISamples& ref,
                     const std::string& section) {
  std::ostringstream f;
  f.precision(12);
  f << key << '\n';
  const auto x = CaseISamples::stations();
  for (std::size_t k = 0; k < x.size(); ++k) {
    f << "eta," << x[k] << ',' << ref.eta[k] << ',' << ref.eta0[k] << '\n';
  }
  for (std::size_t k = 0; k < ref.u.size(); ++k) {
    f << "u," << k / (CaseISamples::kSectionSamples - 1.0) << ',' << ref.u[k] << ',' << ref.v[k]
      << '\n';
  }
  f << "H," << section << ',' << ref.depth << '\n';
  write_file_atomically(path, f.str());
}

/// The wave: eta - eta0, the surface against this run's still-water level. rms of its
/// difference from the reference's over the stations wet in both, over max |reference|.
double surface_error(const CaseISamples& a, const CaseISamples& ref) {
  double e2 = 0.0, peak = 0.0;
  int n = 0;
  for (std::size_t k = 0; k < ref.eta.size(); ++k) {
    const double wa = a.eta[k] - a.eta0[k], wr = ref.eta[k] - ref.eta0[k];
    if (std::isnan(wa) || std::isnan(wr)) continue;
    e2 += (wa - wr) * (wa - wr);
    peak = std::max(peak, std::abs(wr));
    ++n;
  }
  return n > 0 && peak > 0.0 ? std::sqrt(e2 / n) / peak : NAN;
}

/// rms of |u - u_ref| over the section's samples, over max |u_ref|.
double section_error(const CaseISamples& a, const CaseISamples& ref) {
  double e2 = 0.0, peak = 0.0;
  for (std::size_t k = 0; k < ref.u.size(); ++k) {
    e2 += std::pow(a.u[k] - ref.u[k], 2) + std::pow(a.v[k] - ref.v[k], 2);
    peak = std::max(peak, std::hypot(ref.u[k], ref.v[k]));
  }
  return peak > 0.0 ? std::sqrt(e2 / ref.u.size()) / peak : NAN;
}

int usage(const char* msg) {
  std::fprintf(stderr,
               "bench_work_precision: %s\nusage: bench_work_precision --study "
               "dambreak|hydrostatic|caseI [--dl D1,D2,...] [--steps courant,fixed,courant:C] "
               "[--gradients all|NAME,...] [--stabilisation default,plain,nocollision,3a85288] "
               "[--repeats N] "
               "[--threads N] [--out FILE.csv]\n"
               "  caseI only: [--reference-dl D] [--reference FILE.csv] "
               "[--reference-stabilisation default|3a85288] [--section NAME] "
               "[--time T] [--settle S] [--samples PREFIX]\n",
               msg);
  return 2;
}

}  // namespace

int main(int argc, char** argv) {
  std::string study, dls, steps = "courant,fixed", gradients, stabilisations = "default", out;
  std::string reference_path = "caseI_reference.csv", section_name = "A", samples_prefix;
  std::string reference_stabilisation = "default";
  double reference_dl = 0.0025, sample_time = 0.4, settle = -1.0;
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
      } else if (a == "--stabilisation") {
        stabilisations = value();
      } else if (a == "--repeats") {
        repeats = std::stoi(value());
      } else if (a == "--threads") {
        threads = std::stoi(value());
      } else if (a == "--out") {
        out = value();
      } else if (a == "--reference-dl") {
        reference_dl = std::stod(value());
      } else if (a == "--reference") {
        reference_path = value();
      } else if (a == "--reference-stabilisation") {
        reference_stabilisation = value();
      } else if (a == "--section") {
        section_name = value();
      } else if (a == "--time") {
        sample_time = std::stod(value());
      } else if (a == "--settle") {
        settle = std::stod(value());
      } else if (a == "--samples") {
        samples_prefix = value();
      } else {
        return usage(("unknown argument " + a).c_str());
      }
    } catch (const std::exception& e) {
      return usage(e.what());
    }
  }
  if (study != "dambreak" && study != "hydrostatic" && study != "caseI") {
    return usage("--study is required");
  }
  const bool case_i_study = study == "caseI";
  if (repeats < 1 || threads < 1) return usage("--repeats and --threads must be >= 1");
  if (reference_stabilisation != "default" && reference_stabilisation != "3a85288") {
    return usage("--reference-stabilisation must be default or 3a85288");
  }
  if (!(reference_dl > 0.0) || !(sample_time > 0.0)) {
    return usage("--reference-dl and --time must be > 0");
  }
  if (dls.empty()) {
    dls = study == "dambreak"      ? "0.01,0.007,0.005,0.0035"
          : study == "hydrostatic" ? "0.02,0.014,0.01,0.007"
                                   : "0.01,0.007,0.005";
  }
  for (const auto& rule : split(steps)) {
    if (rule == "fixed" || rule == "courant") continue;
    char* end = nullptr;
    const double c = rule.rfind("courant:", 0) == 0 ? std::strtod(rule.c_str() + 8, &end) : 0.0;
    if (!end || *end || !(c > 0.0)) {
      return usage(("unknown step rule " + rule + " (fixed, courant or courant:C, C > 0)").c_str());
    }
  }
  for (const auto& st : split(stabilisations)) {
    if (st != "default" && st != "plain" && st != "nocollision" && st != "3a85288") {
      return usage(
          ("unknown stabilisation " + st + " (default, plain, nocollision or 3a85288)").c_str());
    }
  }
  // Case I is costly: by default only the gradient its case file names.
  if (gradients.empty()) gradients = case_i_study ? "case" : "all";

  set_thread_count(threads);
  const std::string source = WCMPS_SOURCE_DIR;
  std::ostringstream csv;
  csv << "study,dl_m,particles,step_rule,gradient,stabilisation,steps,repeats,wall_seconds_median,"
         "wall_seconds_min,wall_seconds_max,error,error_measure,threads\n";
  try {
    const CaseSpec base = parse_case_file(source + "/cases/" + study + "/case.toml");
    std::vector<PressureGradientScheme> schemes;
    for (const auto& row : kPressureGradientSchemes) {
      const auto wanted = split(gradients);
      if (gradients == "all" || std::find(wanted.begin(), wanted.end(), row.key) != wanted.end() ||
          (gradients == "case" && row.scheme == base.pressure_gradient)) {
        schemes.push_back(row.scheme);
      }
    }
    if (schemes.empty()) return usage("--gradients names no scheme");
    const auto data = study == "dambreak"
                          ? martin_moyce(source + "/cases/dambreak/martin_moyce_1952.csv")
                          : std::vector<Point>{};

    // Case I: the section, and the finer run every other is compared with.
    SectionSpec section;
    CaseISamples reference;
    if (case_i_study) {
      const auto it = std::find_if(base.sections.begin(), base.sections.end(),
                                   [&](const SectionSpec& s) { return s.name == section_name; });
      if (it == base.sections.end()) return usage(("no section " + section_name).c_str());
      section = *it;
      CaseSpec ref = base;
      ref.dl = reference_dl;
      if (reference_stabilisation == "3a85288") use_scheme_3a85288(ref);
      if (settle >= 0.0) ref.settle_time = settle;
      const std::string key = reference_key(ref, sample_time, section_name);
      if (read_reference(reference_path, key, reference)) {
        std::fprintf(stderr, "reference: %s (%s)\n", reference_path.c_str(), key.c_str() + 2);
      } else {
        std::fprintf(stderr, "reference: running DL %g m (%s)\n", ref.dl, key.c_str() + 2);
        const Result r = case_i(ref, sample_time, section, &reference);
        if (!r.unstable.empty()) {
          std::fprintf(stderr, "bench_work_precision: the reference run became unstable: %s\n",
                       r.unstable.c_str());
          return 1;
        }
        std::fprintf(stderr, "reference: %lld particles, %lld steps, %.4g s\n",
                     static_cast<long long>(r.particles), static_cast<long long>(r.steps),
                     r.seconds);
        write_reference(reference_path, key, reference, section_name);
      }
    }

    for (const auto& d : split(dls)) {
      for (const auto& rule : split(steps)) {
        for (const auto scheme : schemes) {
          for (const auto& stabilisation : split(stabilisations)) {
            CaseSpec spec = base;
            if (stabilisation == "3a85288") use_scheme_3a85288(spec);
            if (stabilisation == "plain") {
              spec.gradient_renormalisation = GradientRenormalisation::None;
            }
            if (stabilisation == "nocollision") {
              spec.particle_collision = ParticleCollisionScheme::None;
            }
            spec.dl = std::stod(d);
            if (!case_i_study) spec.settle_time = 0.0;
            if (case_i_study && settle >= 0.0) spec.settle_time = settle;
            if (rule == "fixed") {
              spec.step_mode = TimeStepMode::Fixed;
              spec.fixed_step = 2.5e-5;  // the study's
            } else if (rule == "courant") {
              spec.step_mode = TimeStepMode::Courant;
            } else {  // courant:C, checked above
              spec.step_mode = TimeStepMode::Courant;
              spec.courant = std::stod(rule.substr(8));
            }
            spec.pressure_gradient = scheme;
            std::vector<double> seconds;
            Result first;
            CaseISamples samples;
            for (int k = 0; k < repeats; ++k) {
              const Result r = study == "dambreak" ? dam_break(spec, data)
                               : study == "hydrostatic"
                                   ? still_water(spec)
                                   : case_i(spec, sample_time, section, &samples);
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
            std::vector<std::pair<double, std::string>> errors;
            if (!case_i_study) {
              errors.emplace_back(first.error,
                                  study == "dambreak" ? "rms_front_Z" : "rms_p_over_rho_g_H");
            } else {
              const bool ok = first.unstable.empty();
              errors.emplace_back(ok ? surface_error(samples, reference) : NAN, "rms_eta");
              errors.emplace_back(ok ? section_error(samples, reference) : NAN,
                                  "rms_u_" + section_name);
              if (ok && !samples_prefix.empty()) {  // each run's samples, as the reference's
                // One file per run: the scheme in the name when it is not the defaults'.
                const std::string scheme_tag =
                    stabilisation == "default" ? "" : "_" + stabilisation;
                write_reference(samples_prefix + "_" + d + "_" + rule + scheme_tag + ".csv",
                                reference_key(spec, sample_time, section_name), samples,
                                section_name);
              }
            }
            const std::string name(scheme_key(kPressureGradientSchemes, scheme));
            for (const auto& [error, measure] : errors) {
              char line[512];
              std::snprintf(
                  line, sizeof line, "%s,%g,%lld,%s,%s,%s,%lld,%zu,%.4g,%.4g,%.4g,%.6g,%s,%d\n",
                  study.c_str(), spec.dl, static_cast<long long>(first.particles), rule.c_str(),
                  name.c_str(), stabilisation.c_str(), static_cast<long long>(first.steps),
                  seconds.size(), seconds[seconds.size() / 2], seconds.front(), seconds.back(),
                  error, measure.c_str(), threads);
              csv << line;
              std::fputs(line, stderr);
            }
          }
        }
      }
    }
    if (out.empty()) {
      std::cout << csv.str();
    } else {
      write_file_atomically(out, csv.str());
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bench_work_precision: %s\n", e.what());
    return 1;
  }
  return 0;
}
