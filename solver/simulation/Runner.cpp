#include "simulation/Runner.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/Error.h"

namespace wcmps {

std::vector<double> output_times(const CaseSpec& spec, double end_time) {
  std::vector<double> t;
  if (spec.output_initial) t.push_back(0.0);
  if (spec.output_interval > 0.0) {
    const auto n = static_cast<std::int64_t>(std::floor(end_time / spec.output_interval + 1e-9));
    for (std::int64_t k = 1; k <= n; ++k)
      t.push_back(static_cast<double>(k) * spec.output_interval);
  }
  for (double x : spec.output_times) {
    if (x <= end_time) t.push_back(x);
  }
  t.push_back(end_time);
  std::sort(t.begin(), t.end());
  // Times closer than a nanosecond are one frame.
  t.erase(std::unique(t.begin(), t.end(), [](double a, double b) { return b - a < 1e-9; }),
          t.end());
  return t;
}

RunStats Runner::run(FrameSink& sink, const std::function<void(const Progress&)>& progress,
                     double progress_interval) {
  using clock = std::chrono::steady_clock;
  const auto t0 = clock::now();
  auto wall = [&] { return std::chrono::duration<double>(clock::now() - t0).count(); };
  stats_ = {};
  stats_.dt_min = std::numeric_limits<double>::infinity();
  const bool fixed = sim_.time_step_rule().mode == TimeStepMode::Fixed;
  // A fixed step cannot be shortened; a frame is due once the time is within half a step.
  const double tolerance = fixed ? 0.5 * sim_.time_step_rule().fixed : 0.0;
  std::size_t next = 0;
  double last_report = -1.0;
  // Rate of simulated time per wall second, smoothed, for the estimate of time left.
  double rate = 0.0, rate_t = 0.0, rate_wall = 0.0;

  auto write_due = [&] {
    while (next < times_.size() && sim_.time() >= times_[next] - tolerance) {
      const double w0 = wall();
      sink.write_frame(sim_);
      stats_.output_seconds += wall() - w0;
      ++stats_.frames;
      ++next;
    }
  };
  auto report = [&](bool force) {
    const double w = wall();
    if (!progress || (!force && w - last_report < progress_interval)) return;
    last_report = w;
    if (w - rate_wall > 1.0) {
      const double r = (sim_.time() - rate_t) / (w - rate_wall);
      rate = rate > 0.0 ? 0.5 * rate + 0.5 * r : r;
      rate_t = sim_.time();
      rate_wall = w;
    }
    Progress p;
    p.time = sim_.time();
    p.end_time = end_;
    p.dt = sim_.last_dt();
    p.step = sim_.steps();
    p.particles = sim_.particles().size();
    p.wall_seconds = w;
    p.eta_seconds = rate > 0.0 ? (end_ - sim_.time()) / rate : -1.0;
    p.frames = stats_.frames;
    progress(p);
  };

  try {
    sim_.settle();
    stats_.settle_seconds = wall();
    sink.after_step(sim_);
    write_due();
    while (sim_.time() < end_ - tolerance) {
      const double stop = next < times_.size() ? std::min(times_[next], end_) : end_;
      sim_.step(stop);
      stats_.dt_min = std::min(stats_.dt_min, sim_.last_dt());
      stats_.dt_max = std::max(stats_.dt_max, sim_.last_dt());
      sink.after_step(sim_);
      write_due();
      report(false);
    }
  } catch (const InstabilityError&) {
    // The simulation still holds the last good state: keep it as the final frame.
    sink.write_frame(sim_);
    ++stats_.frames;
    stats_.steps = sim_.steps();
    stats_.simulated_time = sim_.time();
    stats_.wall_seconds = wall();
    throw;
  }
  stats_.steps = sim_.steps();
  stats_.simulated_time = sim_.time();
  stats_.wall_seconds = wall();
  stats_.completed = true;
  if (stats_.steps == 0) stats_.dt_min = 0.0;
  report(true);
  return stats_;
}

}  // namespace wcmps
