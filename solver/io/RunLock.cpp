#include "io/RunLock.h"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "core/Error.h"

namespace wcmps {

RunLock::RunLock(const std::filesystem::path& dir, const std::string& what) {
  const std::filesystem::path file = dir / kFile;
  fd_ = ::open(file.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  if (fd_ < 0) {
    throw IoError("cannot create the lock " + file.string() + ": " + std::strerror(errno));
  }
  if (::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
    const int err = errno;
    std::string holder(512, '\0');
    const ssize_t n = ::pread(fd_, holder.data(), holder.size(), 0);
    holder.resize(n > 0 ? static_cast<std::size_t>(n) : 0);
    while (!holder.empty() && (holder.back() == '\n' || holder.back() == '\0')) holder.pop_back();
    ::close(fd_);
    fd_ = -1;
    if (err == EWOULDBLOCK) {
      throw IoError("run directory " + dir.string() + " is in use by " +
                    (holder.empty() ? std::string("another process") : holder) +
                    "; wait for it to finish or choose another directory");
    }
    throw IoError("cannot lock " + file.string() + ": " + std::strerror(err));
  }
  const std::string text = "process " + std::to_string(::getpid()) + " (" + what + ")\n";
  // The note is for the message of a refused process; the lock holds without it (a failed
  // write leaves that process saying "another process").
  if (::ftruncate(fd_, 0) == 0) {
    [[maybe_unused]] const ssize_t written = ::pwrite(fd_, text.data(), text.size(), 0);
  }
}

RunLock::~RunLock() {
  if (fd_ >= 0) ::close(fd_);  // releases the lock
}

}  // namespace wcmps
