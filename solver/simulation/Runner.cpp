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

void RunStats::save(StateWriter& out) const {
  out.scalar("run_dt_min", dt_min);
  out.scalar("run_dt_max", dt_max);
  out.integer("run_frames", frames);
}

void RunStats::load(StateReader& in) {
  dt_min = in.scalar("run_dt_min");
  dt_max = in.scalar("run_dt_max");
  frames = in.integer("run_frames");
}

RunStats Runner::run(FrameSink& sink, const std::function<void(const Progress&)>& progress,
                     double progress_interval) {
  using clock = std::chrono::steady_clock;
  const auto t0 = clock::now();
  auto wall = [&] { return std::chrono::duration<double>(clock::now() - t0).count(); };
  stats_ = {};
  stats_.dt_min = std::numeric_limits<double>::infinity();
  if (resumed_) {
    stats_.dt_min = before_.dt_min;
    stats_.dt_max = before_.dt_max;
    stats_.frames = before_.frames;
    stats_.resumed = true;
    stats_.first_step = sim_.steps();
    stats_.first_time = sim_.time();
  }
  const bool fixed = sim_.time_step_rule().mode == TimeStepMode::Fixed;
  // A fixed step cannot be shortened; a frame is due once the time is within half a step.
  const double tolerance = fixed ? 0.5 * sim_.time_step_rule().fixed : 0.0;
  std::size_t next = 0;
  double last_report = -1.0;
  // Rate of simulated time per wall second, smoothed, for the estimate of time left.
  double rate = 0.0, rate_t = sim_.time(), rate_wall = 0.0;
  // A continued run has written the frames of the times it has passed.
  const bool started = resumed_ && !sim_.settling();
  if (started) {
    while (next < times_.size() && sim_.time() >= times_[next] - tolerance) ++next;
  }

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
  auto update = [&] {
    stats_.steps = sim_.steps();
    stats_.simulated_time = sim_.time();
    stats_.wall_seconds = wall();
  };

  // Checkpoints: at t = 0, every interval of simulated or wall time, at a stop, at the end.
  double last_checkpoint_wall = 0.0;
  std::int64_t last_checkpoint_step = started ? sim_.steps() : -1;
  bool last_checkpoint_settling = sim_.settling();
  double next_checkpoint_time = 0.0;
  auto schedule_next = [&] {
    const double dt = schedule_.interval;
    next_checkpoint_time = dt > 0.0 ? (std::floor(sim_.time() / dt + 1e-9) + 1.0) * dt
                                    : std::numeric_limits<double>::infinity();
  };
  schedule_next();
  auto checkpoint = [&] {
    if (sim_.steps() == last_checkpoint_step && sim_.settling() == last_checkpoint_settling) {
      return;  // this state is the newest checkpoint already
    }
    const double w0 = wall();
    update();
    sink.checkpoint(sim_, stats_);
    stats_.checkpoint_seconds += wall() - w0;
    ++stats_.checkpoints;
    last_checkpoint_wall = wall();
    last_checkpoint_step = sim_.steps();
    last_checkpoint_settling = sim_.settling();
    schedule_next();
  };
  auto checkpoint_due = [&] {
    return sim_.time() >= next_checkpoint_time - tolerance ||
           (schedule_.wall_interval > 0.0 &&
            wall() - last_checkpoint_wall >= schedule_.wall_interval);
  };
  // A stop asked for (a signal): checkpoint and leave. The series is complete as it is.
  auto stopped = [&] {
    const int signal = stop_ ? stop_() : 0;
    if (signal == 0) return false;
    checkpoint();
    stats_.stop_signal = signal;
    update();
    return true;
  };

  try {
    if (!started) {
      const double w0 = wall();
      while (sim_.settling()) {
        sim_.settle_step();
        // Once settling is over, the state is that of t = 0, whose frames come first: a stop
        // or a checkpoint waits for them (a run continued from here writes no t = 0 frame).
        if (!sim_.settling()) break;
        if (stopped()) {
          stats_.settle_seconds = wall() - w0;
          return stats_;
        }
        if (schedule_.wall_interval > 0.0 &&
            wall() - last_checkpoint_wall >= schedule_.wall_interval) {
          checkpoint();
        }
      }
      stats_.settle_seconds = wall() - w0;
      sink.after_step(sim_);
      write_due();
      checkpoint();
      if (stopped()) return stats_;
    }
    while (sim_.time() < end_ - tolerance) {
      const double stop = next < times_.size() ? std::min(times_[next], end_) : end_;
      sim_.step(stop);
      stats_.dt_min = std::min(stats_.dt_min, sim_.last_dt());
      stats_.dt_max = std::max(stats_.dt_max, sim_.last_dt());
      sink.after_step(sim_);
      write_due();
      report(false);
      if (stopped()) return stats_;
      if (checkpoint_due()) checkpoint();
    }
    // The end: a checkpoint from which the run can be continued to a later end time.
    checkpoint();
  } catch (const InstabilityError&) {
    // The simulation still holds the last good state: keep it as the final frame.
    sink.write_frame(sim_);
    ++stats_.frames;
    update();
    throw;
  }
  update();
  stats_.completed = true;
  if (!std::isfinite(stats_.dt_min)) stats_.dt_min = 0.0;
  report(true);
  return stats_;
}

}  // namespace wcmps
