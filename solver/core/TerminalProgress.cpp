#include "core/TerminalProgress.h"

#include <unistd.h>

#include <cstdio>

namespace wcmps {

TerminalProgress::TerminalProgress() : enabled_(::isatty(STDERR_FILENO) == 1) {}

void TerminalProgress::show(const std::string& line, bool force) {
  if (!enabled_) return;
  const auto now = std::chrono::steady_clock::now();
  if (!force && shown_ > 0 && now - last_ < std::chrono::milliseconds(100)) return;
  last_ = now;
  std::fprintf(stderr, "\r%s%*s", line.c_str(),
               static_cast<int>(shown_ > line.size() ? shown_ - line.size() : 0), "");
  std::fflush(stderr);
  shown_ = line.size();
}

void TerminalProgress::done() {
  if (enabled_ && shown_ > 0) std::fputc('\n', stderr);
  shown_ = 0;
}

std::string format_duration(double s) {
  char buf[32];
  if (s < 0) return "?";
  if (s < 60) {
    std::snprintf(buf, sizeof buf, "%.1f s", s);
  } else if (s < 3600) {
    std::snprintf(buf, sizeof buf, "%d min %02d s", static_cast<int>(s) / 60,
                  static_cast<int>(s) % 60);
  } else {
    std::snprintf(buf, sizeof buf, "%d h %02d min", static_cast<int>(s) / 3600,
                  static_cast<int>(s) % 3600 / 60);
  }
  return buf;
}

}  // namespace wcmps
