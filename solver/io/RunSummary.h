#pragma once
/// @file RunSummary.h
/// @brief The figures of a finished (or stopped) run, as run.json and as the closing lines of
/// run.log; both come from the same RunSummary so they cannot disagree.

#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "body/SlidingBody.h"
#include "core/Error.h"
#include "scene/CaseSpec.h"
#include "simulation/Runner.h"
#include "simulation/Simulation.h"

namespace wcmps {

struct RunSummary {
  std::string version;
  std::string case_name, case_file;
  std::string status;  ///< "completed", "unstable" or "stopped" (by a signal)
  std::optional<InstabilityReport> instability;
  std::int64_t fluid = 0, wall = 0, ghost = 0;
  double dl = 0.0, re = 0.0, n0 = 0.0, lambda = 0.0, c0 = 0.0;
  std::string time_step;  ///< "fixed" or "courant"
  double end_time = 0.0;
  RunStats stats;
  int threads = 1;
  std::int64_t pairs_visited = 0;
  std::int64_t neighbour_builds = 0;
  std::int64_t wall_collisions = 0;  ///< fluid particle-steps the wall collision model changed
  double settle_time = 0.0;          ///< s of damped settling before t = 0
  std::int64_t settle_steps = 0;
  std::vector<std::pair<std::string, double>> phase_seconds;
  std::vector<SectionSpec> sections;  ///< measuring sections of the case
  std::optional<BodySample> body;     ///< the block's state at the end
  std::string restarted_from;         ///< the checkpoint a continued run started from
  /// Memory (bytes): the estimate made before building (simulation/MemoryEstimate.h; 0 on a
  /// restart, which makes none), the process's peak resident memory (VmHWM) and what it held
  /// before building the scene.
  double memory_estimate = 0.0, memory_peak = 0.0, memory_program = 0.0;

  std::int64_t particles() const { return fluid + wall + ghost; }
  /// All particles times steps, per wall second of stepping (frame output excluded).
  double particle_steps_per_second() const;
  double fluid_particle_steps_per_second() const;
  double pairs_per_second() const;
  double stepping_seconds() const {
    return stats.wall_seconds - stats.output_seconds - stats.settle_seconds -
           stats.checkpoint_seconds;
  }
  /// Steps of this part of the run (all of it unless continued from a checkpoint).
  double segment_steps() const { return static_cast<double>(stats.steps - stats.first_step); }

  nlohmann::json to_json() const;
  std::string to_text() const;
};

/// Collects the summary of a run of `sim` for `spec`.
RunSummary summarize(const CaseSpec& spec, const Simulation& sim, const RunStats& stats,
                     const std::optional<InstabilityReport>& instability);

}  // namespace wcmps
