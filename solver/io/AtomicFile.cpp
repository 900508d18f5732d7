#include "io/AtomicFile.h"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>

#include "core/Error.h"

namespace wcmps {

namespace {
constexpr const char* kTemporaryMark = ".tmp-";

int open_temporary(const std::filesystem::path& tmp, const std::filesystem::path& path) {
  const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) throw IoError("cannot write " + path.string() + ": " + std::strerror(errno));
  return fd;
}

/// Closes `fd` (after an fsync if asked); the errno of the first failure, or 0.
int close_file(int fd, Durability durability) {
  int err = 0;
  if (durability == Durability::Synced && ::fsync(fd) != 0) err = errno;
  if (::close(fd) != 0 && err == 0) err = errno;
  return err;
}

void remove_quietly(const std::filesystem::path& p) {
  std::error_code ec;
  std::filesystem::remove(p, ec);
}
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
  AtomicOutputFile file(path);
  file.stream().write(content.data(), static_cast<std::streamsize>(content.size()));
  file.commit(durability);
}

AtomicOutputFile::AtomicOutputFile(std::filesystem::path path)
    : path_(std::move(path)),
      tmp_(temporary_path_for(path_)),
      fd_(open_temporary(tmp_, path_)),
      buffer_(fd_),
      stream_(&buffer_) {}

AtomicOutputFile::~AtomicOutputFile() {
  if (fd_ >= 0) {
    ::close(fd_);
    remove_quietly(tmp_);
  }
}

void AtomicOutputFile::commit(Durability durability) {
  buffer_.flush_buffer();
  int err = buffer_.error();
  const int close_error = close_file(fd_, durability);
  fd_ = -1;
  if (err == 0) err = close_error;
  if (err != 0) {
    remove_quietly(tmp_);
    throw IoError("cannot write " + path_.string() + ": " + std::strerror(err));
  }
  replace_file(tmp_, path_);
}

// 64 KiB: a few hundred system calls for a frame of case I at DL = 2 mm.
AtomicOutputFile::Buffer::Buffer(int fd) : fd_(fd), data_(std::size_t{1} << 16) {
  setp(data_.data(), data_.data() + data_.size());
}

void AtomicOutputFile::Buffer::write_at(const char* s, std::size_t n) {
  while (n > 0 && error_ == 0) {
    const ssize_t w = ::pwrite(fd_, s, n, position_);
    if (w < 0 && errno == EINTR) continue;
    if (w <= 0) {
      error_ = w < 0 ? errno : EIO;
      break;
    }
    s += w;
    n -= static_cast<std::size_t>(w);
    position_ += w;
  }
  position_ += static_cast<off_type>(n);  // what a failed write skipped
  end_ = std::max(end_, position_);
}

void AtomicOutputFile::Buffer::flush_buffer() {
  write_at(pbase(), static_cast<std::size_t>(pptr() - pbase()));
  setp(data_.data(), data_.data() + data_.size());
}

AtomicOutputFile::Buffer::int_type AtomicOutputFile::Buffer::overflow(int_type c) {
  flush_buffer();
  if (!traits_type::eq_int_type(c, traits_type::eof())) {
    *pptr() = traits_type::to_char_type(c);
    pbump(1);
  }
  return traits_type::not_eof(c);
}

std::streamsize AtomicOutputFile::Buffer::xsputn(const char* s, std::streamsize n) {
  if (n > epptr() - pptr()) {
    flush_buffer();
    if (n >= epptr() - pptr()) {
      write_at(s, static_cast<std::size_t>(n));
      return n;
    }
  }
  std::memcpy(pptr(), s, static_cast<std::size_t>(n));
  pbump(static_cast<int>(n));
  return n;
}

int AtomicOutputFile::Buffer::sync() {
  flush_buffer();
  return 0;  // a failure is kept for commit(), not shown to the stream
}

AtomicOutputFile::Buffer::pos_type AtomicOutputFile::Buffer::seekoff(off_type off,
                                                                     std::ios_base::seekdir dir,
                                                                     std::ios_base::openmode) {
  flush_buffer();
  const off_type base = dir == std::ios_base::beg   ? 0
                        : dir == std::ios_base::cur ? position_
                                                    : end_;
  if (base + off < 0) return pos_type(off_type(-1));
  position_ = base + off;
  return pos_type(position_);
}

AtomicOutputFile::Buffer::pos_type AtomicOutputFile::Buffer::seekpos(
    pos_type pos, std::ios_base::openmode which) {
  return seekoff(off_type(pos), std::ios_base::beg, which);
}

}  // namespace wcmps
