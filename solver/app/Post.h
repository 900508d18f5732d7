#pragma once
/// @file Post.h
/// @brief `wcmps post`: the products a run's case asks for ([post]), computed with the VTK
/// filters of filters/ for chosen frames of the run.

#include <optional>
#include <string>
#include <vector>

namespace wcmps {

struct PostOptions {
  std::string run_dir;
  std::string output_dir;                    ///< empty: RUN_DIR/post
  std::string case_file;                     ///< empty: the run's copy, RUN_DIR/case.toml
  std::optional<std::vector<double>> times;  ///< s; default [post] times, else [output] times
  std::optional<int> threads;
};

int post_command(const PostOptions& options);

}  // namespace wcmps
