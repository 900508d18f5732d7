#include "core/Memory.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>

namespace wcmps {
namespace {

/// The value of the line "Key:   1234 kB" of a /proc file, in bytes; 0 if absent.
std::uint64_t proc_kib(const char* file, const std::string& key) {
  std::ifstream in(file);
  std::string line;
  while (std::getline(in, line)) {
    if (line.compare(0, key.size(), key) != 0 || line.size() <= key.size() ||
        line[key.size()] != ':') {
      continue;
    }
    std::istringstream s(line.substr(key.size() + 1));
    std::uint64_t kib = 0;
    if (s >> kib) return kib * 1024;
    return 0;
  }
  return 0;
}

/// A number from a one-line file (cgroup v2 interface files); nullopt for "max" or unreadable.
std::optional<std::uint64_t> file_number(const std::string& file) {
  std::ifstream in(file);
  std::string word;
  if (!(in >> word) || word == "max") return std::nullopt;
  char* end = nullptr;
  const unsigned long long v = std::strtoull(word.c_str(), &end, 10);
  if (end == word.c_str() || *end != '\0') return std::nullopt;
  return static_cast<std::uint64_t>(v);
}

/// What the cgroup (v2) of this process still allows, the tightest over its ancestors; nullopt
/// where no limit is set or cgroup v2 is not mounted.
std::optional<std::uint64_t> cgroup_room() {
  std::ifstream in("/proc/self/cgroup");
  std::string line, path;
  while (std::getline(in, line)) {
    if (line.rfind("0::", 0) == 0) path = line.substr(3);  // the v2 hierarchy's entry
  }
  if (path.empty()) return std::nullopt;
  std::optional<std::uint64_t> room;
  for (;;) {
    const std::string dir = "/sys/fs/cgroup" + (path == "/" ? std::string() : path);
    const auto max = file_number(dir + "/memory.max");
    const auto used = file_number(dir + "/memory.current");
    if (max && used) {
      const std::uint64_t r = *max > *used ? *max - *used : 0;
      room = room ? std::min(*room, r) : r;
    }
    if (path == "/" || path.empty()) break;
    const auto slash = path.find_last_of('/');
    path = slash == 0 || slash == std::string::npos ? "/" : path.substr(0, slash);
  }
  return room;
}

}  // namespace

std::uint64_t available_memory_bytes() {
  const std::uint64_t machine = proc_kib("/proc/meminfo", "MemAvailable");
  const auto room = cgroup_room();
  if (!room) return machine;
  return machine == 0 ? *room : std::min(machine, *room);
}

std::uint64_t current_rss_bytes() {
  return proc_kib("/proc/self/status", "VmRSS");
}
std::uint64_t peak_rss_bytes() {
  return proc_kib("/proc/self/status", "VmHWM");
}

std::string format_bytes(double bytes) {
  static const char* const units[] = {"B", "KiB", "MiB", "GiB", "TiB", "PiB"};
  int u = 0;
  while (bytes >= 1024.0 && u < 5) bytes /= 1024.0, ++u;
  char buf[32];
  if (u == 0) {
    std::snprintf(buf, sizeof buf, "%.0f B", bytes);
  } else {
    // Past 1000 PiB (a case whose box no machine holds) in powers of ten: "%.0f" would not fit.
    std::snprintf(buf, sizeof buf,
                  bytes < 10.0     ? "%.2f %s"
                  : bytes < 100.0  ? "%.1f %s"
                  : bytes < 1000.0 ? "%.0f %s"
                                   : "%.3g %s",
                  bytes, units[u]);
  }
  return buf;
}

std::optional<std::uint64_t> parse_byte_size(std::string_view text) {
  std::string s(text);
  char* end = nullptr;
  const double value = std::strtod(s.c_str(), &end);
  if (end == s.c_str() || !std::isfinite(value) || value < 0.0) return std::nullopt;
  std::string unit(end);
  unit.erase(std::remove_if(unit.begin(), unit.end(),
                            [](unsigned char c) { return std::isspace(c) != 0; }),
             unit.end());
  std::string lower;
  for (const unsigned char c : unit) lower += static_cast<char>(std::tolower(c));
  double scale = 0.0;
  if (lower.empty() || lower == "b") {
    scale = 1.0;
  } else {
    const std::string prefixes = "kmgt";
    const auto k = prefixes.find(lower[0]);
    if (k == std::string::npos) return std::nullopt;
    const std::string rest = lower.substr(1);
    const int power = static_cast<int>(k) + 1;
    if (rest.empty() || rest == "ib") {
      scale = std::pow(1024.0, power);
    } else if (rest == "b") {
      scale = std::pow(1000.0, power);
    } else {
      return std::nullopt;
    }
  }
  const double bytes = value * scale;
  if (!(bytes < 9.2e18)) return std::nullopt;
  return static_cast<std::uint64_t>(std::llround(bytes));
}

}  // namespace wcmps
