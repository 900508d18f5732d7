#include "io/RunSummary.h"

#include <cstdio>

#include "core/Memory.h"
#include "core/Parallel.h"
#include "core/Version.h"

namespace wcmps {

double RunSummary::particle_steps_per_second() const {
  const double s = stepping_seconds();
  return s > 0.0 ? static_cast<double>(particles()) * segment_steps() / s : 0.0;
}

double RunSummary::fluid_particle_steps_per_second() const {
  const double s = stepping_seconds();
  return s > 0.0 ? static_cast<double>(fluid) * segment_steps() / s : 0.0;
}

double RunSummary::pairs_per_second() const {
  const double s = stepping_seconds();
  return s > 0.0 ? static_cast<double>(pairs_visited) / s : 0.0;
}

nlohmann::json RunSummary::to_json() const {
  nlohmann::json j;
  j["version"] = version;
  j["case"] = {{"name", case_name}, {"file", case_file}, {"copy", "case.toml"}};
  j["status"] = status;
  if (stats.stop_signal != 0) j["stop_signal"] = stats.stop_signal;
  if (stats.resumed) {
    j["restart"] = {
        {"checkpoint", restarted_from}, {"time", stats.first_time}, {"step", stats.first_step}};
  }
  if (instability) {
    j["instability"] = {{"step", instability->step},
                        {"time", instability->time},
                        {"particle_id", instability->particle_id},
                        {"position", {instability->x, instability->y}},
                        {"reason", instability->reason},
                        {"particles_affected", instability->particles_affected}};
  }
  j["particles"] = {{"fluid", fluid}, {"wall", wall}, {"ghost", ghost}, {"total", particles()}};
  j["memory"] = {{"estimate_bytes", memory_estimate},
                 {"peak_rss_bytes", memory_peak},
                 {"program_bytes", memory_program}};
  j["method"] = {{"DL", dl}, {"re", re}, {"n0", n0}, {"lambda", lambda}, {"c0", c0}};
  j["time"] = {{"step_rule", time_step},
               {"end", end_time},
               {"simulated", stats.simulated_time},
               {"steps", stats.steps},
               {"dt_min", stats.dt_min},
               {"dt_max", stats.dt_max},
               {"settle_time", settle_time},
               {"settle_steps", settle_steps}};
  if (body) {
    j["block"] = {{"time", body->time},
                  {"S", body->state.s},
                  {"U", body->state.u},
                  {"A", body->state.a},
                  {"history", "block.csv"}};
  }
  if (!sections.empty()) {
    nlohmann::json list = nlohmann::json::array();
    for (const auto& sec : sections) {
      list.push_back({{"name", sec.name},
                      {"origin", {sec.origin.x, sec.origin.y}},
                      {"direction", {sec.direction.x, sec.direction.y}}});
    }
    j["sections"] = list;
  }
  j["frames"] = stats.frames;
  j["wall_collisions"] = wall_collisions;
  j["performance"] = {{"wall_seconds", stats.wall_seconds},
                      {"output_seconds", stats.output_seconds},
                      {"settle_seconds", stats.settle_seconds},
                      {"checkpoint_seconds", stats.checkpoint_seconds},
                      {"checkpoints", stats.checkpoints},
                      {"threads", threads},
                      {"particle_steps_per_second", particle_steps_per_second()},
                      {"fluid_particle_steps_per_second", fluid_particle_steps_per_second()},
                      {"neighbour_pairs_visited", pairs_visited},
                      {"neighbour_pairs_per_second", pairs_per_second()},
                      {"neighbour_list_builds", neighbour_builds}};
  nlohmann::json phases = nlohmann::json::object();
  for (const auto& [name, s] : phase_seconds) phases[name] = s;
  j["performance"]["phase_seconds"] = phases;
  return j;
}

std::string RunSummary::to_text() const {
  std::string out;
  char buf[256];
  auto line = [&](const char* fmt, auto... args) {
    std::snprintf(buf, sizeof buf, fmt, args...);
    out += buf;
    out += '\n';
  };
  line("status              %s", status.c_str());
  if (stats.stop_signal != 0) line("stopped by signal   %d", stats.stop_signal);
  if (stats.resumed) {
    line("continued from      %s (t = %g s, step %lld); the figures below are of this part",
         restarted_from.c_str(), stats.first_time, static_cast<long long>(stats.first_step));
  }
  if (instability) line("instability         %s", instability->str().c_str());
  line("particles           %lld (fluid %lld, wall %lld, ghost %lld)",
       static_cast<long long>(particles()), static_cast<long long>(fluid),
       static_cast<long long>(wall), static_cast<long long>(ghost));
  line("DL, re              %g m, %g m", dl, re);
  line("n0, lambda          %.6f, %.6g m^2 (%.6f DL^2)", n0, lambda, lambda / (dl * dl));
  line("c0                  %g m/s", c0);
  line("time step           %s, %lld steps, dt %.4g ... %.4g s", time_step.c_str(),
       static_cast<long long>(stats.steps), stats.dt_min, stats.dt_max);
  line("simulated time      %g s of %g s", stats.simulated_time, end_time);
  if (body) {
    line("block               t = %g s: S = %.5f m, U = %.4f m/s, A = %.3f m/s^2 (block.csv)",
         body->time, body->state.s, body->state.u, body->state.a);
  }
  if (settle_steps > 0) {
    line("settling            %g s before t = 0, %lld steps, %.3f s wall time", settle_time,
         static_cast<long long>(settle_steps), stats.settle_seconds);
  }
  line("frames              %lld", static_cast<long long>(stats.frames));
  if (memory_peak > 0.0) {
    line("memory              peak %s%s", format_bytes(memory_peak).c_str(),
         memory_estimate > 0.0
             ? (" (estimated " + format_bytes(memory_estimate) + " before building)").c_str()
             : "");
  }
  line("wall collisions     %lld particle-steps", static_cast<long long>(wall_collisions));
  line(
      "wall time           %.3f s (%.3f s writing frames, %.3f s writing %lld checkpoints), %d "
      "threads",
      stats.wall_seconds, stats.output_seconds, stats.checkpoint_seconds,
      static_cast<long long>(stats.checkpoints), threads);
  line("particle-steps/s    %.4g (fluid only %.4g)", particle_steps_per_second(),
       fluid_particle_steps_per_second());
  line("neighbour pairs/s   %.4g (lists built %lld times)", pairs_per_second(),
       static_cast<long long>(neighbour_builds));
  for (const auto& [name, s] : phase_seconds) {
    line("  %-16s  %9.3f s  %5.1f %%", name.c_str(), s,
         stats.wall_seconds > 0 ? 100.0 * s / stats.wall_seconds : 0.0);
  }
  return out;
}

RunSummary summarize(const CaseSpec& spec, const Simulation& sim, const RunStats& stats,
                     const std::optional<InstabilityReport>& instability) {
  RunSummary r;
  r.version = kVersion;
  r.case_name = spec.name;
  r.case_file = spec.file.file;
  r.status = instability ? "unstable" : (stats.completed ? "completed" : "stopped");
  r.instability = instability;
  const ParticleSet& ps = sim.particles();
  r.fluid = ps.fluid_count();
  r.wall = ps.wall_count();
  r.ghost = ps.ghost_count();
  r.dl = spec.dl;
  r.re = spec.re();
  r.n0 = sim.operators().n0();
  r.lambda = sim.operators().lambda();
  r.c0 = sim.scene().sound_speed;
  r.time_step = spec.step_mode == TimeStepMode::Fixed ? "fixed" : "courant";
  r.end_time = spec.end_time;
  r.stats = stats;
  r.threads = thread_count();
  r.pairs_visited = sim.pairs_visited();
  r.neighbour_builds = sim.neighbour_builds();
  r.wall_collisions = sim.wall_collisions();
  r.settle_time = spec.settle_time;
  r.settle_steps = sim.settle_steps();
  for (int p = 0; p < static_cast<int>(Phase::Count); ++p) {
    r.phase_seconds.emplace_back(std::string(phase_name(static_cast<Phase>(p))),
                                 sim.timer().seconds(static_cast<Phase>(p)));
  }
  r.phase_seconds.emplace_back("output", stats.output_seconds);
  r.phase_seconds.emplace_back("checkpoint", stats.checkpoint_seconds);
  r.sections = spec.sections;
  if (const SlidingBody* b = sim.body()) r.body = b->sample(sim.time());
  return r;
}

}  // namespace wcmps
