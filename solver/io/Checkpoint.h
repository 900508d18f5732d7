#pragma once
/// @file Checkpoint.h
/// @brief Checkpoints of a run: its whole state in an HDF5 file, through the HDF5 that VTK
/// links (VTK::hdf5: one HDF5 in the process, docs/architecture.md), so that `wcmps run
/// --restart` continues it exactly where it was (docs/checkpoints.md).
///
/// A checkpoint is `RUN/checkpoint_NNNNNN.h5`, NNNNNN counting up over the run. It is written
/// under a temporary name, flushed to disk and renamed, so a file of that name is always
/// complete; the newest `keep` are kept. Layout:
///   - attributes of the root group: `format` ("wcmps checkpoint"), `format_version`,
///     `wcmps_version`, `case_text` (the case it was written for), `complete` (written last),
///     and every scalar of the state (`time`, `steps`, ...);
///   - a dataset per field: real fields as (components, particles) arrays of float64, one row
///     per component (`position`: x, then y); integer fields as one-dimensional arrays.

#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "core/StateArchive.h"

namespace wcmps {

class CheckpointStore {
 public:
  static constexpr int kFormatVersion = 1;

  /// The checkpoints of run directory `dir`, of which the newest `keep` (>= 1) are kept.
  CheckpointStore(std::filesystem::path dir, int keep);

  /// Writes the next checkpoint, which `save` fills; then removes the oldest beyond `keep`.
  /// Throws IoError naming the file (nothing is left under its name if writing fails).
  std::filesystem::path write(const std::string& case_text,
                              const std::function<void(StateWriter&)>& save);

  /// The checkpoint files, oldest first.
  std::vector<std::filesystem::path> files() const;

  /// Loads the newest checkpoint that opens, is complete, was written for `case_text` and
  /// that `load` accepts (load throws CheckpointError otherwise); older ones are tried in turn.
  /// Those newer than the one loaded are removed, each named with its reason in `rejected`.
  /// Throws CheckpointError if none is usable.
  std::filesystem::path load_newest(const std::string& case_text,
                                    const std::function<void(StateReader&)>& load,
                                    std::vector<std::string>& rejected);

  /// Whether `name` is the name of a checkpoint file (or of one being written).
  static bool is_checkpoint_name(const std::string& name);

 private:
  std::filesystem::path dir_;
  int keep_;
};

}  // namespace wcmps
