#pragma once
/// @file Runner.h
/// @brief Runs a simulation to its end time, writing frames at the output times and reporting
/// progress. On instability it writes the last good state as a final frame and rethrows.

#include <chrono>
#include <cstdint>
#include <functional>
#include <vector>

#include "scene/CaseSpec.h"
#include "simulation/Simulation.h"

namespace wcmps {

/// Receives the frames of a run.
class FrameSink {
 public:
  virtual ~FrameSink() = default;
  virtual void write_frame(const Simulation& sim) = 0;
  /// After settling (t = 0) and after every step, before any frame of that time.
  virtual void after_step(const Simulation& /*sim*/) {}
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
  double output_seconds = 0.0;  ///< part of wall_seconds spent writing frames
  double settle_seconds = 0.0;  ///< part of wall_seconds spent settling before t = 0
  bool completed = false;
};

class Runner {
 public:
  Runner(Simulation& sim, std::vector<double> times, double end_time)
      : sim_(sim), times_(std::move(times)), end_(end_time) {}

  /// Calls `progress` at most every `progress_interval` seconds of wall time, and at the end.
  RunStats run(FrameSink& sink, const std::function<void(const Progress&)>& progress,
               double progress_interval = 0.5);

  const RunStats& stats() const { return stats_; }

 private:
  Simulation& sim_;
  std::vector<double> times_;
  double end_;
  RunStats stats_;
};

}  // namespace wcmps
