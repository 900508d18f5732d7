#pragma once
/// @file WaveGauges.h
/// @brief Wave gauges during a run: the water surface eta(t) at fixed x, sampled every
/// [gauges] interval, written as gauges.csv. eta is the top of the water on the vertical line
/// through the gauge, by the algorithm of operators/WaterSpan.h that the filters' free
/// surface uses (coverage 0.5, the longest wet stretch: splash ignored).

#include <string>
#include <vector>

#include "core/StateArchive.h"
#include "neighbours/CellGrid.h"
#include "operators/Kernel.h"
#include "scene/CaseSpec.h"

namespace wcmps {

class Simulation;

class WaveGauges {
 public:
  /// The gauges of spec.gauges, for a scene of particle spacing spec.dl in [lo, hi].
  WaveGauges(const CaseSpec& spec, Vec2 lo, Vec2 hi);

  /// True when the simulation's time has reached the next sample time.
  bool due(double time) const { return time >= next_ - 1e-12; }

  /// Records the time and eta at every gauge (NaN where the line meets no water).
  void sample(const Simulation& sim);

  /// The samples so far: a header naming each gauge's x, then a row per sample.
  std::string csv() const;

  /// The samples and the next sample time, for checkpoints.
  void save(StateWriter& out) const;
  void load(StateReader& in);

  /// Samples taken so far, and sample k: its time, then eta at each gauge.
  std::size_t sample_count() const { return values_.size() / width(); }
  const double* sample_values(std::size_t k) const { return values_.data() + k * width(); }

 private:
  double coverage(const double* px, const double* py, double x, double y) const;

  std::vector<double> x_;
  double interval_;
  double next_ = 0.0;
  double dl_;
  Kernel w_;
  double scale_;
  CellGrid grid_;
  std::size_t width() const { return x_.size() + 1; }

  /// time, eta_1 ... eta_n per sample, one row after another; reserved for the whole run, so
  /// sampling in the time loop allocates nothing.
  std::vector<double> values_;
};

}  // namespace wcmps
