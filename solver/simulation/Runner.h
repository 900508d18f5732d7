#pragma once
/// @file Runner.h
/// @brief Runs a simulation to its end time: settling, frames at the output times, checkpoints
/// on their schedule, progress reports, and a clean stop when asked (a signal). On instability
/// it writes the last good state as a final frame and rethrows.

#include <chrono>
#include <cstdint>
#include <functional>
#include <vector>

#include "core/StateArchive.h"
#include "scene/CaseSpec.h"
#include "simulation/Simulation.h"

namespace wcmps {

struct RunStats;

/// Receives the frames and checkpoints of a run.
class FrameSink {
 public:
  virtual ~FrameSink() = default;
  virtual void write_frame(const Simulation& sim) = 0;
  /// After settling (t = 0) and after every step, before any frame of that time.
  virtual void after_step(const Simulation& /*sim*/) {}
  /// Keeps the whole state of the run as it stands between two steps, after the frames of the
  /// last one (the Runner decides when).
  virtual void checkpoint(const Simulation& /*sim*/, const RunStats& /*stats*/) {}
};

/// When the Runner asks its sink for a checkpoint, besides at t = 0 (after settling), at a
/// stop and at the end.
struct CheckpointSchedule {
  double interval = 0.0;       ///< s of simulated time between checkpoints; 0: not by it
  double wall_interval = 0.0;  ///< s of wall time between checkpoints; 0: not by it
};

/// Sorted output times: t = 0 if asked, every interval, each listed time, and the end time.
std::vector<double> output_times(const CaseSpec& spec, double end_time);

struct Progress {
  double time = 0.0, end_time = 0.0, dt = 0.0;
  std::int64_t step = 0, particles = 0;
  double wall_seconds = 0.0;
  double eta_seconds = -1.0;  ///< < 0 while unknown
  std::int64_t frames = 0;
};

struct RunStats {
  std::int64_t steps = 0;
  double simulated_time = 0.0;
  double wall_seconds = 0.0;
  double dt_min = 0.0, dt_max = 0.0;
  std::int64_t frames = 0;
  double output_seconds = 0.0;      ///< part of wall_seconds spent writing frames
  double settle_seconds = 0.0;      ///< part of wall_seconds spent settling before t = 0
  double checkpoint_seconds = 0.0;  ///< part of wall_seconds spent writing checkpoints
  std::int64_t checkpoints = 0;
  bool completed = false;
  int stop_signal = 0;  ///< the signal that stopped the run before its end (0: none)
  /// Where this part of the run started: 0 and 0 s, or the checkpoint it continued from.
  /// wall_seconds and the performance figures are those of this part.
  bool resumed = false;
  std::int64_t first_step = 0;
  double first_time = 0.0;

  /// The figures that belong to the whole run (dt range, frames), for checkpoints.
  void save(StateWriter& out) const;
  void load(StateReader& in);
};

class Runner {
 public:
  Runner(Simulation& sim, std::vector<double> times, double end_time)
      : sim_(sim), times_(std::move(times)), end_(end_time) {}

  void set_checkpoints(CheckpointSchedule schedule) { schedule_ = schedule; }
  /// Polled after every step: a non-zero value (the number of the signal received) ends the
  /// run after that step with a checkpoint; run() then returns with stats().stop_signal set.
  void set_stop_request(std::function<int()> stop) { stop_ = std::move(stop); }
  /// Continues a simulation loaded from a checkpoint (Simulation::load) whose run had the
  /// figures `before`: no settling or t = 0 frame unless it stopped while settling, and the
  /// output times it has passed are not written again.
  void resume(const RunStats& before) {
    resumed_ = true;
    before_ = before;
  }

  /// Calls `progress` at most every `progress_interval` seconds of wall time, and at the end.
  RunStats run(FrameSink& sink, const std::function<void(const Progress&)>& progress,
               double progress_interval = 0.5);

  const RunStats& stats() const { return stats_; }

 private:
  Simulation& sim_;
  std::vector<double> times_;
  double end_;
  CheckpointSchedule schedule_;
  std::function<int()> stop_;
  bool resumed_ = false;
  RunStats before_;
  RunStats stats_;
};

}  // namespace wcmps
