#pragma once
/// @file Memory.h
/// @brief The memory of the machine and of this process, and sizes in bytes written the way
/// people write them ("6 GiB", "500MB").

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace wcmps {

/// Bytes that new allocations can take without swapping: MemAvailable of /proc/meminfo (the
/// kernel's own estimate: free memory plus the caches it can drop), lowered to what the
/// process's cgroup (v2) still allows (memory.max less memory.current) where a limit is set, as
/// in a container or a Slurm job. 0 when neither can be read.
std::uint64_t available_memory_bytes();

/// The resident memory of this process now (VmRSS) and its high-water mark (VmHWM), from
/// /proc/self/status; 0 when it cannot be read.
std::uint64_t current_rss_bytes();
std::uint64_t peak_rss_bytes();

/// "812 MiB", "1.50 GiB", "73.2 KiB", "512 B": powers of 1024, three significant digits.
std::string format_bytes(double bytes);

/// Parses a size: a non-negative number, optionally followed (spaces allowed) by a unit:
/// B; K, M, G, T or KiB, MiB, GiB, TiB (powers of 1024); kB, MB, GB, TB (powers of 1000).
/// Units are not case-sensitive ("mb" is MB, "gib" GiB). Returns nullopt for anything else (no
/// number, a negative one, an unknown unit, or more than 2^63 bytes).
std::optional<std::uint64_t> parse_byte_size(std::string_view text);

}  // namespace wcmps
