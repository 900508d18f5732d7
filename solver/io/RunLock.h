#pragma once
/// @file RunLock.h
/// @brief One process owns a run directory at a time.
///
/// `wcmps run` (and `run --restart`, and `post` and `figures` writing into the run) takes an
/// exclusive flock(2) on the file `.wcmps.lock` in the run directory before it touches anything
/// there, and holds it until it exits. A second process that asks for the same directory is
/// refused, with the process id and command line the holder wrote into the file. The kernel
/// releases the lock when its holder exits, however it exits (kill -9 included), so a lock file
/// left behind by a killed run is not a lock: the next run takes it over. (flock locks are per open
/// file and local; on NFS they are emulated by fcntl locks where the server supports them.)

#include <filesystem>
#include <string>

namespace wcmps {

class RunLock {
 public:
  static constexpr const char* kFile = ".wcmps.lock";

  /// Locks `dir` (which must exist) for `what` (e.g. "wcmps run case.toml"); throws IoError
  /// (exit code 4) naming the other process if another holds it, or if the lock file cannot be
  /// made.
  RunLock(const std::filesystem::path& dir, const std::string& what);
  ~RunLock();
  RunLock(const RunLock&) = delete;
  RunLock& operator=(const RunLock&) = delete;

 private:
  int fd_ = -1;
};

}  // namespace wcmps
