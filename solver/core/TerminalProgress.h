#pragma once
/// @file TerminalProgress.h
/// @brief One line of progress on a terminal, rewritten in place: `run`'s time loop, the
/// building of a big scene, `post` over many frames, `figures`. Nothing is written when stderr
/// is not a terminal (a log, a pipe, a batch job), so files and test output stay clean.

#include <chrono>
#include <string>

namespace wcmps {

class TerminalProgress {
 public:
  /// Shows progress when `enabled` (by default: when stderr is a terminal).
  TerminalProgress();
  explicit TerminalProgress(bool enabled) : enabled_(enabled) {}
  ~TerminalProgress() { done(); }
  TerminalProgress(const TerminalProgress&) = delete;
  TerminalProgress& operator=(const TerminalProgress&) = delete;

  /// Rewrites the line; at most ten times a second unless `force`.
  void show(const std::string& line, bool force = false);
  /// Ends the line (a newline) if anything was shown; show() may start a new one.
  void done();

 private:
  bool enabled_;
  std::size_t shown_ = 0;
  std::chrono::steady_clock::time_point last_{};
};

/// "12.3 s", "4 min 05 s", "2 h 13 min"; "?" for a negative time.
std::string format_duration(double seconds);

}  // namespace wcmps
