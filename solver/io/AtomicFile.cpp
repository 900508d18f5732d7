#include "io/AtomicFile.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "core/Error.h"

namespace wcmps {

namespace {
constexpr const char* kTemporaryMark = ".tmp-";
}  // namespace

std::filesystem::path temporary_path_for(const std::filesystem::path& path) {
  auto tmp = path;
  tmp += kTemporaryMark + std::to_string(::getpid());
  return tmp;
}

bool is_temporary_path(const std::filesystem::path& path) {
  return path.filename().string().find(kTemporaryMark) != std::string::npos;
}

void replace_file(const std::filesystem::path& tmp, const std::filesystem::path& path) {
  std::error_code ec;
  std::filesystem::rename(tmp, path, ec);
  if (ec) {
    std::filesystem::remove(tmp, ec);
    throw IoError("cannot write " + path.string() + ": " + ec.message());
  }
}

void write_file_atomically(const std::filesystem::path& path, std::string_view content,
                           Durability durability) {
  const auto tmp = temporary_path_for(path);
  const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) throw IoError("cannot write " + path.string() + ": " + std::strerror(errno));
  std::size_t done = 0;
  while (done < content.size()) {
    const ssize_t w = ::write(fd, content.data() + done, content.size() - done);
    if (w < 0 && errno == EINTR) continue;
    if (w <= 0) {
      const int err = errno;
      ::close(fd);
      std::error_code ec;
      std::filesystem::remove(tmp, ec);
      throw IoError("cannot write " + path.string() + ": " + std::strerror(err));
    }
    done += static_cast<std::size_t>(w);
  }
  const bool synced = durability != Durability::Synced || ::fsync(fd) == 0;
  const int sync_error = errno;
  if (::close(fd) != 0 || !synced) {
    const int err = synced ? errno : sync_error;
    std::error_code ec;
    std::filesystem::remove(tmp, ec);
    throw IoError("cannot write " + path.string() + ": " + std::strerror(err));
  }
  replace_file(tmp, path);
}

}  // namespace wcmps
