#pragma once
/// @file AtomicFile.h
/// @brief Every output file is written under a temporary name in its final directory and then
/// renamed into place, so a reader (or a killed run) never sees a half-written file.

#include <filesystem>
#include <string_view>

namespace wcmps {

/// A temporary name next to `path` (same directory, so that the rename is atomic).
std::filesystem::path temporary_path_for(const std::filesystem::path& path);

/// Whether `path` is such a temporary name (left behind if the process was killed).
bool is_temporary_path(const std::filesystem::path& path);

/// Renames `tmp` onto `path`, replacing it; throws IoError (and removes tmp) on failure.
void replace_file(const std::filesystem::path& tmp, const std::filesystem::path& path);

/// Whether the data must be on the disk before the file is renamed into place: a file that
/// must survive a power cut as well as a killed process (checkpoints) pays for an fsync.
enum class Durability { Renamed, Synced };

/// Writes `content` to `path` atomically; throws IoError naming the file and the cause.
void write_file_atomically(const std::filesystem::path& path, std::string_view content,
                           Durability durability = Durability::Renamed);

}  // namespace wcmps
