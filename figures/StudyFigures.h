#pragma once
/// @file StudyFigures.h
/// @brief `wcmps figures`: the study's figures (thesis Fig. 4-1 ... 4-11, A-1 ... A-5) from
/// one or more runs of its sliding-block cases, rendered off-screen to PNG with VTK's charts,
/// and figures.json listing each file with what it shows. docs/figures.md.

#include <optional>
#include <string>
#include <vector>

namespace wcmps {

struct FiguresOptions {
  std::vector<std::string> runs;  ///< run directories of `wcmps run`
  std::string output_dir;         ///< empty: figures/ next to the first run
  std::string case_file;  ///< empty: each run's copy; else [figures] (measured data) from here
  std::optional<std::vector<double>> times;  ///< s; default: each case's [output] times
  int width = 1200, height = 800;            ///< pixels, every figure
};

int figures_command(const FiguresOptions& options);

}  // namespace wcmps
