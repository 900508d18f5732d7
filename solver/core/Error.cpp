#include "core/Error.h"

#include <cstdio>

namespace wcmps {

std::string SourceLocation::str() const {
  std::string s = file.empty() ? std::string("<case>") : file;
  if (line > 0) {
    s += ":" + std::to_string(line);
    if (column > 0) s += ":" + std::to_string(column);
  }
  return s;
}

CaseError::CaseError(SourceLocation where, const std::string& what)
    : std::runtime_error(where.str() + ": " + what), where_(std::move(where)), reason_(what) {}

std::string InstabilityReport::str() const {
  char buf[256];
  std::snprintf(buf, sizeof buf, "step %lld, t = %.6g s: particle id %d at (%.6g, %.6g) m: ",
                static_cast<long long>(step), time, particle_id, x, y);
  std::string s = buf + reason;
  if (particles_affected > 1) {
    s += " (" + std::to_string(particles_affected) + " particles affected)";
  }
  return s;
}

InstabilityError::InstabilityError(InstabilityReport report)
    : std::runtime_error("unstable run: " + report.str()), report_(std::move(report)) {}

}  // namespace wcmps
