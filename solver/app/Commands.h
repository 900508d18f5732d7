#pragma once
/// @file Commands.h
/// @brief The subcommands of the wcmps program. Each returns an exit code (app/ExitCodes.h).

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
};

int run_command(const RunOptions& options);
int check_command(const std::string& case_file);

}  // namespace wcmps
