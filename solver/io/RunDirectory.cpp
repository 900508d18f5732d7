#include "io/RunDirectory.h"

#include <algorithm>
#include <string>
#include <vector>

#include "core/Error.h"
#include "io/AtomicFile.h"
#include "io/Checkpoint.h"
#include "io/RunLock.h"

namespace fs = std::filesystem;

namespace wcmps {

std::string run_directory_problem(const fs::path& dir) {
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) return dir.string() + ": no such run directory";
  if (!fs::exists(dir / RunFiles::kSeries, ec) || !fs::exists(dir / RunFiles::kCase, ec)) {
    return dir.string() + " holds no run (" + RunFiles::kSeries + " and " + RunFiles::kCase +
           " are written by `wcmps run`)";
  }
  return {};
}

bool is_run_file(const fs::path& name) {
  const std::string s = name.filename().string();
  auto starts = [&](const std::string& p) { return s.rfind(p, 0) == 0; };
  if (is_temporary_path(name)) return true;
  return s == RunLock::kFile || s == RunFiles::kSeries || s == RunFiles::kSummary ||
         s == RunFiles::kLog || s == RunFiles::kCase || s == RunFiles::kBody ||
         s == RunFiles::kGauges || s == RunFiles::kPost || CheckpointStore::is_checkpoint_name(s) ||
         (starts(RunFiles::kFramePrefix) && name.extension() == ".vtp");
}

void remove_stale_temporaries(const fs::path& dir) {
  std::error_code ec;
  std::vector<fs::path> stale;
  for (const auto& e : fs::directory_iterator(dir, ec)) {
    if (is_temporary_path(e.path())) stale.push_back(e.path());
  }
  for (const auto& p : stale) {
    fs::remove(p, ec);
    if (ec) throw IoError("cannot remove " + p.string() + ": " + ec.message());
  }
}

std::vector<fs::path> check_output_directory(const fs::path& dir, bool overwrite) {
  std::error_code ec;
  std::vector<fs::path> run_files;
  if (!fs::exists(dir, ec)) return run_files;
  if (!fs::is_directory(dir, ec)) {
    throw IoError("output directory " + dir.string() + " exists and is not a directory");
  }
  for (const auto& e : fs::directory_iterator(dir, ec)) {
    if (!is_run_file(e.path())) {
      throw IoError("output directory " + dir.string() + " holds '" + e.path().filename().string() +
                    "', which a run does not write; choose an empty or new directory");
    }
    run_files.push_back(e.path());
  }
  if (ec) throw IoError("cannot read output directory " + dir.string() + ": " + ec.message());
  const bool earlier_run = std::any_of(run_files.begin(), run_files.end(), [](const fs::path& f) {
    return f.filename() != RunLock::kFile;
  });
  if (earlier_run && !overwrite) {
    throw IoError("output directory " + dir.string() +
                  " holds an earlier run; pass --overwrite to replace it");
  }
  return run_files;
}

void prepare_run_directory(const fs::path& dir, bool overwrite) {
  const std::vector<fs::path> run_files = check_output_directory(dir, overwrite);
  std::error_code ec;
  if (fs::exists(dir, ec)) {
    for (const auto& f : run_files) {
      // The lock stays: this process holds it (removing it would let another lock a new file).
      if (f.filename() == RunLock::kFile) continue;
      fs::remove_all(f, ec);
      if (ec) throw IoError("cannot remove " + f.string() + ": " + ec.message());
    }
  } else {
    fs::create_directories(dir, ec);
    if (ec) throw IoError("cannot create output directory " + dir.string() + ": " + ec.message());
  }
  // Writable? (Permissions alone do not tell: read-only mounts, full disks.)
  write_file_atomically(dir / ".write-test", "");
  fs::remove(dir / ".write-test", ec);
}

}  // namespace wcmps
