#pragma once
/// @file RunDirectory.h
/// @brief What a run directory holds, and how a new run takes one over.

#include <filesystem>
#include <string>
#include <vector>

namespace wcmps {

/// Names of the files of a run directory.
struct RunFiles {
  static constexpr const char* kSeries = "series.pvd";
  static constexpr const char* kSummary = "run.json";
  static constexpr const char* kLog = "run.log";
  static constexpr const char* kCase = "case.toml";
  static constexpr const char* kFramePrefix = "frame_";
  static constexpr const char* kBody = "block.csv";
  static constexpr const char* kGauges = "gauges.csv";
  /// The directory `wcmps post` writes by default: derived from the run, replaced with it.
  static constexpr const char* kPost = "post";
};

/// Makes `dir` ready for a new run. A missing directory is created; an empty one (or one with
/// only the lock of io/RunLock.h, which the caller holds and which is kept) is used. One
/// that holds an earlier run is replaced only if `overwrite` is set (its run files are removed,
/// nothing else). A directory holding anything that is not a run file is refused. Throws
/// IoError naming the directory and the reason; checks that it is writable.
void prepare_run_directory(const std::filesystem::path& dir, bool overwrite);

/// What prepare_run_directory() refuses, checked before anything is written there: throws
/// IoError if `dir` exists and is not a directory, holds anything a run does not write, or holds
/// an earlier run and `overwrite` is not set. Returns the run files it holds.
std::vector<std::filesystem::path> check_output_directory(const std::filesystem::path& dir,
                                                          bool overwrite);

/// True for the names a run writes (series, summary, log, case copy, frames, checkpoints,
/// temporaries) and for the post directory made from it.
bool is_run_file(const std::filesystem::path& name);

/// Removes the files a run was writing when it was killed (their temporary names).
void remove_stale_temporaries(const std::filesystem::path& dir);

/// For the commands that read a finished run (post, figures): empty if `dir` holds one (its
/// series and case copy), else what is wrong, as the end of an error message naming `dir`.
std::string run_directory_problem(const std::filesystem::path& dir);

}  // namespace wcmps
