#pragma once
/// @file Error.h
/// @brief Typed errors of the solver library. Library code throws these and never exits; the
/// command-line program turns each into a one-line message and its documented exit code
/// (docs/running.md).

#include <cstdint>
#include <stdexcept>
#include <string>

namespace wcmps {

/// Position in a text file, 1-based; line 0 means "the file as a whole".
struct SourceLocation {
  std::string file;
  std::uint32_t line = 0;
  std::uint32_t column = 0;

  /// "file:line:column", "file:line" or "file", as compilers print it.
  std::string str() const;
};

/// A case file that cannot be read, parsed or accepted.
class CaseError : public std::runtime_error {
 public:
  CaseError(SourceLocation where, const std::string& what);
  const SourceLocation& where() const { return where_; }
  /// The message without the location prefix.
  const std::string& reason() const { return reason_; }

 private:
  SourceLocation where_;
  std::string reason_;
};

/// A file or directory that cannot be written or read (outside of case parsing).
class IoError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// A checkpoint that cannot be used to continue a run: none there, unreadable, incomplete, or
/// written for another case or scene.
class CheckpointError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Description of the first particle that failed a stability check.
struct InstabilityReport {
  std::int64_t step = 0;  ///< step at which the check failed (1-based)
  double time = 0.0;      ///< simulated time reached by that step (s)
  std::int32_t particle_id = -1;
  double x = 0.0, y = 0.0;  ///< its position after the failed step (m)
  std::string reason;       ///< e.g. "velocity is not finite"
  std::int64_t particles_affected = 0;

  std::string str() const;
};

/// The run became unstable; the state before the failing step is still intact.
class InstabilityError : public std::runtime_error {
 public:
  explicit InstabilityError(InstabilityReport report);
  const InstabilityReport& report() const { return report_; }

 private:
  InstabilityReport report_;
};

}  // namespace wcmps
