#include "app/Commands.h"

#include <unistd.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>

#include <nlohmann/json.hpp>

#include "app/EmbeddedCase.h"
#include "app/StopSignals.h"
#include "core/Error.h"
#include "core/ExitCodes.h"
#include "core/Memory.h"
#include "core/Parallel.h"
#include "core/TerminalProgress.h"
#include "core/Version.h"
#include "io/AtomicFile.h"
#include "io/BodyCsv.h"
#include "io/Checkpoint.h"
#include "io/RunDirectory.h"
#include "io/RunLock.h"
#include "io/RunSummary.h"
#include "io/VtpSeriesWriter.h"
#include "scene/CaseParser.h"
#include "scene/SceneBuilder.h"
#include "scene/SizeEstimate.h"
#include "simulation/MemoryEstimate.h"
#include "simulation/Runner.h"
#include "simulation/Simulation.h"
#include "simulation/WaveGauges.h"

namespace fs = std::filesystem;

namespace wcmps {
namespace {

CaseSpec load_case(const std::string& file) {
  if (file.empty()) return parse_case_text(kEmbeddedCaseText, std::string(kEmbeddedCasePath));
  return parse_case_file(file);
}

/// True when the run.json in @p dir says the run completed at step @p steps: a run that reached
/// its end time and then was killed before writing its summary has not (the summary is the
/// last thing a run writes), and a restart finishes it.
bool summary_says_completed(const fs::path& dir, std::int64_t steps) {
  std::ifstream in(dir / RunFiles::kSummary);
  if (!in) return false;
  const nlohmann::json j = nlohmann::json::parse(in, nullptr, /*allow_exceptions=*/false);
  if (!j.is_object() || j.value("status", "") != "completed") return false;
  const auto t = j.find("time");
  return t != j.end() && t->is_object() && t->value("steps", std::int64_t{-1}) == steps;
}

std::string progress_line(const Progress& p) {
  char buf[256];
  std::snprintf(
      buf, sizeof buf, "t %.4f/%.4f s | step %lld | dt %.3g s | %lld particles | wall %s | left %s",
      p.time, p.end_time, static_cast<long long>(p.step), p.dt, static_cast<long long>(p.particles),
      format_duration(p.wall_seconds).c_str(), format_duration(p.eta_seconds).c_str());
  return buf;
}

/// Writes frames through the series writer and notes each in the log; samples the wave gauges
/// (if any) after every step, rewrites block.csv and gauges.csv with every frame, and writes
/// the checkpoints.
class LoggedSink : public FrameSink {
 public:
  LoggedSink(VtpSeriesWriter& writer, std::ofstream& log, const fs::path& dir, WaveGauges* gauges,
             CheckpointStore& checkpoints, const std::string& case_text)
      : writer_(writer),
        log_(log),
        body_csv_(dir / RunFiles::kBody),
        gauges_csv_(dir / RunFiles::kGauges),
        gauges_(gauges),
        checkpoints_(checkpoints),
        case_text_(case_text) {}
  void after_step(const Simulation& sim) override {
    if (gauges_ && gauges_->due(sim.time())) gauges_->sample(sim);
  }
  void write_frame(const Simulation& sim) override {
    const std::size_t before = writer_.entries().size();
    writer_.write_frame(sim);
    if (writer_.entries().size() == before) return;
    write_tables(sim);
    char buf[160];
    std::snprintf(buf, sizeof buf, "frame %-5zu t = %-10.6g step %-8lld dt %.4g s  %s", before,
                  sim.time(), static_cast<long long>(sim.steps()), sim.last_dt(),
                  writer_.entries().back().file.c_str());
    log_ << buf << std::endl;
  }
  /// block.csv and gauges.csv as of the simulation's state.
  void write_tables(const Simulation& sim) {
    if (sim.body()) write_body_csv(body_csv_, sim.body_history());
    if (gauges_) write_file_atomically(gauges_csv_, gauges_->csv());
  }
  void checkpoint(const Simulation& sim, const RunStats& stats) override {
    const fs::path file = checkpoints_.write(case_text_, [&](StateWriter& out) {
      sim.save(out);
      if (gauges_) gauges_->save(out);
      writer_.save(out);
      stats.save(out);
    });
    char buf[200];
    std::snprintf(buf, sizeof buf, "checkpoint t = %-10.6g step %-8lld%s %s", sim.time(),
                  static_cast<long long>(sim.steps()), sim.settling() ? " (settling)" : "",
                  file.filename().c_str());
    log_ << buf << std::endl;
  }
  /// Takes the run back to a checkpoint: the simulation, the gauges, the series (frames
  /// after it are removed) and the run's figures. Returns the checkpoint's file.
  fs::path load(Simulation& sim, RunStats& before, std::vector<std::string>& rejected) {
    return checkpoints_.load_newest(
        case_text_,
        [&](StateReader& in) {
          sim.load(in);
          if (gauges_) gauges_->load(in);
          writer_.load(in);
          before.load(in);
        },
        rejected);
  }

 private:
  VtpSeriesWriter& writer_;
  std::ofstream& log_;
  fs::path body_csv_;
  fs::path gauges_csv_;
  WaveGauges* gauges_;
  CheckpointStore& checkpoints_;
  const std::string& case_text_;
};

/// Cases of at most this many particles `check` builds, running every check on them, in about
/// half a second (docs/running.md, "The size of a run": 0.37 s for 316,184 particles); larger
/// ones it checks on their shapes alone, to answer in well under a second whatever the size.
constexpr double kCheckBuildParticles = 400'000;

/// A case's size from its shapes alone (scene/SizeEstimate.h, simulation/MemoryEstimate.h).
struct Sizing {
  ParticleEstimate counts;
  MemoryEstimate memory;
};

Sizing size_case(const CaseSpec& spec) {
  Sizing s;
  s.counts = estimate_particles(spec);
  s.memory = estimate_memory(spec, s.counts, static_cast<double>(current_rss_bytes()));
  return s;
}

/// Empty when a run of the case fits in its memory limit: `--max-memory`, else [run]
/// max_memory, else what the machine has available; else the message that refuses it.
std::string memory_refusal(const CaseSpec& spec, const Sizing& s,
                           std::optional<std::uint64_t> max_memory) {
  char particles[64], spacing[32];
  std::snprintf(particles, sizeof particles, "%.3g", s.counts.total());
  std::snprintf(spacing, sizeof spacing, "%g", spec.dl);
  const std::string need = spec.file.file + ": a run of the case needs about " +
                           format_bytes(s.memory.total()) + " at its peak (" + particles +
                           " particles at [particles] spacing " + spacing + " m)";
  const std::string advice =
      "; coarsen the spacing (the memory goes as 1/spacing^2) or shrink the shapes";
  if (max_memory || spec.max_memory) {
    const double limit = static_cast<double>(max_memory ? *max_memory : *spec.max_memory);
    if (s.memory.total() <= limit) return {};
    return need + ", more than the limit of " + format_bytes(limit) + " set by " +
           (max_memory ? "--max-memory" : "[run] max_memory") + advice;
  }
  const double available = static_cast<double>(available_memory_bytes());
  if (available <= 0.0 || s.memory.added() <= available) return {};
  return need + ", and the machine has " + format_bytes(available) +
         " available beside what the program holds" + advice +
         ", or give a limit with --max-memory (or [run] max_memory) to run it anyway";
}

void print_scene(std::ostream& out, const CaseSpec& spec, const Scene& scene) {
  const ParticleSet& ps = scene.particles;
  const Vec2 lo = scene.domain_lo, hi = scene.domain_hi;
  const TimeStepRule rule = time_step_rule(spec, scene.sound_speed);
  const double dt = rule.step(0.0);
  const double g = norm(spec.gravity);
  // Compression at the bottom of a still column of the fluid's height: n/n0 - 1 from the
  // Tait equation at p = rho g H.
  const double compression = std::pow(1.0 + spec.eos_exponent * g * scene.fluid_height /
                                                (scene.sound_speed * scene.sound_speed),
                                      1.0 / spec.eos_exponent) -
                             1.0;
  const auto times = output_times(spec, spec.end_time);
  char buf[256];
  auto line = [&](const char* fmt, auto... args) {
    std::snprintf(buf, sizeof buf, fmt, args...);
    out << buf << '\n';
  };
  line("case                %s%s%s", spec.name.c_str(), spec.description.empty() ? "" : ": ",
       spec.description.c_str());
  line("particles           %lld: fluid %lld, wall %lld, ghost %lld (%d ghost rows)",
       static_cast<long long>(ps.size()), static_cast<long long>(ps.fluid_count()),
       static_cast<long long>(ps.wall_count()), static_cast<long long>(ps.ghost_count()),
       scene.ghost_layers);
  if (scene.trimmed_fluid > 0) {
    line("                    %lld lattice points dropped within %g DL of a wall",
         static_cast<long long>(scene.trimmed_fluid), spec.wall_clearance);
  }
  if (scene.displaced_fluid > 0) {
    line("                    %lld lattice points displaced by solid bodies",
         static_cast<long long>(scene.displaced_fluid));
  }
  if (spec.block) {
    const BlockSpec& b = *spec.block;
    line(
        "block               C (%.4f, %.4f), A (%.4f, %.4f), G (%.4f, %.4f) m; CA %.4f, CG %.4f, "
        "AG %.4f m; area %.5g m^2, mass %.2f kg per metre of width",
        b.c.x, b.c.y, b.a.x, b.a.y, b.g.x, b.g.y, norm(b.a - b.c), norm(b.g - b.c), norm(b.g - b.a),
        b.area(), b.area() * b.density);
  }
  line("spacing DL          %g m, re = %g DL = %g m", spec.dl, spec.re_over_dl, spec.re());
  line("n0, lambda          %.6f, %.6f DL^2 (%d lattice neighbours)", scene.lattice.n0,
       scene.lattice.lambda / (spec.dl * spec.dl), scene.lattice.neighbours);
  line("c0                  %g m/s (%s)", scene.sound_speed,
       spec.sound_speed ? "given" : "sound_speed_factor x sqrt(2 g H)");
  line("fluid height H      %g m; still-water compression at its bottom %.3f %%",
       scene.fluid_height, 100.0 * compression);
  if (spec.step_mode == TimeStepMode::Fixed) {
    line("time step           fixed %g s (acoustic Courant number %.3f)", dt,
         rule.acoustic_courant(dt));
  } else {
    line("time step           Courant %g: dt <= %g s at rest", spec.courant, dt);
  }
  line("end time            %g s (about %.0f steps at most)", spec.end_time,
       std::ceil(spec.end_time / dt));
  if (spec.settle_time > 0.0) {
    const TimeStepRule settle = settle_step_rule(spec, scene.sound_speed);
    const double settle_dt = settle.step(0.0);
    line("settling            %g s before t = 0, damping time %g s, %s %g (about %.0f steps)",
         spec.settle_time, spec.settle_damping,
         settle.mode == TimeStepMode::Fixed ? "fixed step" : "Courant",
         settle.mode == TimeStepMode::Fixed ? settle.fixed : settle.courant,
         std::ceil(spec.settle_time / settle_dt));
  }
  std::string fields, kinds;
  for (auto f : spec.output_fields) {
    for (const auto& fi : kFields) {
      if (fi.id == f) fields += (fields.empty() ? "" : ", ") + std::string(fi.name);
    }
  }
  for (auto k : spec.output_kinds) kinds += (kinds.empty() ? "" : ", ") + std::string(kind_name(k));
  line("outputs             %zu frames (%g ... %g s); fields: %s; particles: %s", times.size(),
       times.front(), times.back(), fields.c_str(), kinds.c_str());
  std::string gradient(scheme_key(kPressureGradientSchemes, spec.pressure_gradient));
  if (spec.gradient_renormalisation != GradientRenormalisation::None) {
    gradient +=
        ", renormalised (" +
        std::string(scheme_key(kGradientRenormalisationSchemes, spec.gradient_renormalisation)) +
        ")";
  }
  line("pressure gradient   %s", gradient.c_str());
  if (spec.density_rate != DensityRateScheme::Summed) {
    line("density rate        %s in the surface band",
         std::string(scheme_key(kDensityRateSchemes, spec.density_rate)).c_str());
  }
  if (spec.particle_collision != ParticleCollisionScheme::None) {
    line("particle collision  %s: fluid pairs closer than %g DL",
         std::string(scheme_key(kParticleCollisionSchemes, spec.particle_collision)).c_str(),
         spec.particle_collision_distance);
  }
  line("domain              (%g, %g) ... (%g, %g) m", lo.x, lo.y, hi.x, hi.y);
}

}  // namespace

int check_command(const std::string& case_file, std::optional<std::uint64_t> max_memory) {
  try {
    const CaseSpec spec = load_case(case_file);
    const Sizing size = size_case(spec);
    std::cout << describe_estimate(size.counts, size.memory);
    const std::string refusal = memory_refusal(spec, size, max_memory);
    if (!refusal.empty()) {
      std::cerr << "wcmps: error: " << refusal << '\n';
      return exit_code::kBadCase;
    }
    const std::string name = case_file.empty() ? std::string(kEmbeddedCasePath) : case_file;
    // Stride 1: the estimate scanned every lattice point, so the build's scan costs as little.
    if (size.counts.total() <= kCheckBuildParticles && size.counts.stride == 1) {
      const Scene scene = build_scene(spec);
      print_scene(std::cout, spec, scene);
      std::cout << "ok: " << name << " is a valid case\n";
    } else {
      std::cout << "ok: " << name
                << " is a valid case as far as checked without its particles: its shapes, "
                   "their corners, and 1 lattice point in "
                << size.counts.stride << " x " << size.counts.stride
                << " for fluid inside a wall or with no wall below it. The walls overlapping one "
                   "another and the other lattice points are "
                   "checked when `wcmps run` builds the particles (check builds cases of up to "
                << static_cast<long>(kCheckBuildParticles)
                << " particles whose shapes it can scan whole in a tenth of a second).\n";
    }
    return exit_code::kOk;
  } catch (const CaseError& e) {
    std::cerr << "wcmps: error: " << e.what() << '\n';
    return exit_code::kBadCase;
  }
}

int run_command(const RunOptions& o) {
  const bool restart = !o.restart_dir.empty();
  CaseSpec spec;
  std::optional<Scene> scene;
  Sizing size;
  fs::path dir;
  try {
    if (restart) {
      dir = o.restart_dir;
      std::error_code ec;
      if (!fs::is_directory(dir, ec) || !fs::exists(dir / RunFiles::kCase, ec)) {
        std::cerr << "wcmps: error: cannot restart: " << dir.string()
                  << (fs::is_directory(dir, ec) ? " holds no run (no case.toml)"
                                                : ": no such run directory")
                  << '\n';
        return exit_code::kCannotRestart;
      }
      spec = parse_case_file((dir / RunFiles::kCase).string());
    } else {
      spec = load_case(o.case_file);
    }
    if (o.end_time) {
      if (!(*o.end_time > 0.0) || !std::isfinite(*o.end_time)) {
        std::cerr << "wcmps: error: --end-time must be a positive number of seconds\n";
        return exit_code::kUsage;
      }
      spec.end_time = *o.end_time;
    }
    if (o.settle_time) {
      if (!(*o.settle_time >= 0.0) || !std::isfinite(*o.settle_time)) {
        std::cerr << "wcmps: error: --settle-time must be zero or a positive number of seconds\n";
        return exit_code::kUsage;
      }
      spec.settle_time = *o.settle_time;
    }
    size = size_case(spec);
    if (!restart) std::cout << describe_estimate(size.counts, size.memory) << std::flush;
    const std::string refusal = memory_refusal(spec, size, o.max_memory);
    if (!refusal.empty()) {
      std::cerr << "wcmps: error: " << refusal << '\n';
      return exit_code::kBadCase;
    }
    TerminalProgress building;
    scene = build_scene(spec, [&](double f) {
      char buf[64];
      std::snprintf(buf, sizeof buf, "building the scene: fluid %3.0f %%", 100.0 * f);
      building.show(buf, f >= 1.0);
    });
  } catch (const CaseError& e) {
    std::cerr << "wcmps: error: " << e.what() << '\n';
    return exit_code::kBadCase;
  }
  if (o.threads) set_thread_count(*o.threads);

  if (!restart) {
    dir = o.output_dir.empty() ? fs::path("runs") / spec.name : fs::path(o.output_dir);
  }
  const bool tty = ::isatty(STDERR_FILENO) == 1;
  std::ofstream log;
  std::optional<Simulation> sim;
  std::optional<RunLock> lock;  // held until the run ends (io/RunLock.h)
  try {
    if (restart) {
      lock.emplace(dir, "wcmps run --restart " + dir.string());
      remove_stale_temporaries(dir);  // of a run that was killed while writing
    } else {
      // A run there now is named first (its lock file exists while it runs); then nothing is
      // written into a directory a run may not take (another's files, an earlier run without
      // --overwrite); then the lock (made if need be), then the rest.
      if (fs::exists(dir / RunLock::kFile)) lock.emplace(dir, "wcmps run " + spec.file.file);
      check_output_directory(dir, o.overwrite);
      std::error_code ec;
      fs::create_directories(dir, ec);
      if (ec) throw IoError("cannot create output directory " + dir.string() + ": " + ec.message());
      if (!lock) lock.emplace(dir, "wcmps run " + spec.file.file);
      prepare_run_directory(dir, o.overwrite);
      write_file_atomically(dir / RunFiles::kCase, spec.source_text);
    }
    log.open(dir / RunFiles::kLog, restart ? std::ios::app : std::ios::trunc);
    if (!log) throw IoError("cannot write " + (dir / RunFiles::kLog).string());
    if (restart) {
      log << "\nwcmps " << kVersion << " restart of " << dir.string() << '\n';
    } else {
      log << "wcmps " << kVersion << " run of " << spec.file.file << '\n';
      log << describe_estimate(size.counts, size.memory);
      print_scene(log, spec, *scene);
    }
    log << "threads             " << thread_count() << '\n' << std::flush;
    const Vec2 lo = scene->domain_lo, hi = scene->domain_hi;
    sim.emplace(spec, std::move(*scene));
    VtpSeriesWriter writer(dir, spec);
    if (!restart) writer.start();
    std::optional<WaveGauges> gauges;
    if (!spec.gauges.x.empty()) gauges.emplace(spec, lo, hi);
    CheckpointStore checkpoints(dir, spec.checkpoint_keep);
    LoggedSink sink(writer, log, dir, gauges ? &*gauges : nullptr, checkpoints, spec.source_text);
    Runner runner(*sim, output_times(spec, spec.end_time), spec.end_time);
    runner.set_checkpoints({spec.checkpoint_interval, spec.checkpoint_wall_interval});
    runner.set_stop_request(stop_signal);

    std::string restarted_from;
    if (restart) {
      RunStats before;
      std::vector<std::string> rejected;
      fs::path from;
      try {
        from = sink.load(*sim, before, rejected);
      } catch (const CheckpointError& e) {
        std::cerr << "wcmps: error: cannot restart: " << e.what() << '\n';
        log << "error: cannot restart: " << e.what() << '\n';
        return exit_code::kCannotRestart;
      }
      for (const auto& r : rejected) {
        std::cerr << "wcmps: warning: checkpoint skipped and removed: " << r << '\n';
        log << "checkpoint skipped and removed: " << r << '\n';
      }
      const TimeStepRule& rule = sim->time_step_rule();
      const double tolerance = rule.mode == TimeStepMode::Fixed ? 0.5 * rule.fixed : 0.0;
      if (!sim->settling() && sim->time() >= spec.end_time - tolerance &&
          summary_says_completed(dir, sim->steps())) {
        std::cerr << "wcmps: error: the run in " << dir.string()
                  << " has reached t = " << sim->time() << " s, its end time " << spec.end_time
                  << " s: give a later --end-time to continue it\n";
        return exit_code::kUsage;
      }
      sink.write_tables(*sim);
      runner.resume(before);
      restarted_from = from.filename().string();
      char buf[200];
      std::snprintf(buf, sizeof buf, "continuing from %s at t = %g s%s, step %lld",
                    restarted_from.c_str(), sim->time(), sim->settling() ? " of settling" : "",
                    static_cast<long long>(sim->steps()));
      log << buf << std::endl;
      std::cerr << "wcmps: " << buf << '\n';
    }

    TerminalProgress terminal(tty);
    auto progress = [&](const Progress& p) { terminal.show(progress_line(p)); };
    std::optional<InstabilityReport> unstable;
    RunStats stats;
    catch_stop_signals();
    try {
      stats = runner.run(sink, progress);
    } catch (const InstabilityError& e) {
      unstable = e.report();
      stats = runner.stats();
    }
    terminal.done();
    RunSummary summary = summarize(spec, *sim, stats, unstable);
    summary.restarted_from = restarted_from;
    summary.memory_estimate = restart ? 0.0 : size.memory.total();
    summary.memory_peak = static_cast<double>(peak_rss_bytes());
    summary.memory_program = size.memory.program;
    write_file_atomically(dir / RunFiles::kSummary, summary.to_json().dump(2) + "\n");
    log << summary.to_text() << std::flush;
    if (unstable) {
      std::cerr << "wcmps: error: unstable run: " << unstable->str() << "\n"
                << "wcmps: the last good state (t = " << sim->time() << " s) is the last frame of "
                << (dir / RunFiles::kSeries).string() << '\n';
      return exit_code::kUnstable;
    }
    if (stats.stop_signal != 0) {
      std::cerr << "wcmps: stopped by " << signal_name(stats.stop_signal)
                << " at t = " << sim->time() << " s" << (sim->settling() ? " of settling" : "")
                << ", step " << sim->steps()
                << "; checkpoint written. Continue with: wcmps run --restart " << dir.string()
                << '\n';
      return exit_code::kStoppedBySignal + stats.stop_signal;
    }
    std::cout << summary.to_text() << "series: " << (dir / RunFiles::kSeries).string() << '\n';
    return exit_code::kOk;
  } catch (const IoError& e) {
    if (tty) std::fputc('\n', stderr);
    std::cerr << "wcmps: error: " << e.what() << '\n';
    if (log) log << "error: " << e.what() << '\n';
    return exit_code::kIo;
  } catch (const CheckpointError& e) {
    std::cerr << "wcmps: error: " << e.what() << '\n';
    return exit_code::kCannotRestart;
  }
}

}  // namespace wcmps
