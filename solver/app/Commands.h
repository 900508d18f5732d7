#pragma once
/// @file Commands.h
/// @brief The subcommands of the wcmps program. Each returns an exit code (core/ExitCodes.h).

#include <cstdint>
#include <optional>
#include <string>

namespace wcmps {

struct RunOptions {
  std::string case_file;   ///< empty: the embedded default case
  std::string output_dir;  ///< empty: runs/<case name>
  std::optional<double> end_time;
  std::optional<double> settle_time;
  std::optional<int> threads;
  bool overwrite = false;
  /// Continue the run in this directory from its newest checkpoint (case_file, output_dir,
  /// settle_time and overwrite must then be unset).
  std::string restart_dir;
  /// The most memory the run may take (bytes): overrides [run] max_memory and what the machine
  /// has available.
  std::optional<std::uint64_t> max_memory;
};

int run_command(const RunOptions& options);
/// Estimates the case's size, refuses it past the memory limit (as run does), and validates it:
/// by building it when it is small, on its shapes alone when not.
int check_command(const std::string& case_file, std::optional<std::uint64_t> max_memory = {});

}  // namespace wcmps
