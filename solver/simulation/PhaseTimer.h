#pragma once
/// @file PhaseTimer.h
/// @brief Wall time spent in each phase of the time step.

#include <array>
#include <chrono>
#include <string_view>

namespace wcmps {

enum class Phase {
  Neighbours,
  Predict,
  NumberDensity,
  Pressure,
  Correct,
  Move,
  Check,
  Reorder,
  Count
};

constexpr std::string_view phase_name(Phase p) {
  constexpr std::string_view names[] = {"neighbours", "predict", "number_density", "pressure",
                                        "correct",    "move",    "check",          "reorder"};
  return names[static_cast<int>(p)];
}

class PhaseTimer {
 public:
  /// Runs f and adds its wall time to phase p.
  template <class F>
  decltype(auto) time(Phase p, F&& f) {
    const auto t0 = std::chrono::steady_clock::now();
    struct Add {
      PhaseTimer* self;
      Phase p;
      std::chrono::steady_clock::time_point t0;
      ~Add() {
        self->seconds_[static_cast<int>(p)] +=
            std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      }
    } add{this, p, t0};
    return f();
  }
  double seconds(Phase p) const { return seconds_[static_cast<int>(p)]; }
  void reset() { seconds_ = {}; }
  double total() const {
    double s = 0.0;
    for (double v : seconds_) s += v;
    return s;
  }

 private:
  std::array<double, static_cast<int>(Phase::Count)> seconds_{};
};

}  // namespace wcmps
