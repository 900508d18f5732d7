#pragma once
/// @file AtomicFile.h
/// @brief Every output file is written under a temporary name in its final directory and then
/// renamed into place, so a reader (or a killed run) never sees a half-written file.

#include <filesystem>
#include <ostream>
#include <streambuf>
#include <string_view>
#include <vector>

namespace wcmps {

/// A temporary name next to `path` (same directory, so that the rename is atomic).
std::filesystem::path temporary_path_for(const std::filesystem::path& path);

/// Whether `path` is such a temporary name (left behind if the process was killed).
bool is_temporary_path(const std::filesystem::path& path);

/// Renames `tmp` onto `path`, replacing it; throws IoError (and removes tmp) on failure.
void replace_file(const std::filesystem::path& tmp, const std::filesystem::path& path);

/// Whether the data must be on the disk before the file is renamed into place: a file that
/// must survive a power cut as well as a killed process (checkpoints) pays for an fsync.
enum class Durability { Renamed, Synced };

/// Writes `content` to `path` atomically; throws IoError naming the file and the cause.
void write_file_atomically(const std::filesystem::path& path, std::string_view content,
                           Durability durability = Durability::Renamed);

/// A file written through a std::ostream under a temporary name and renamed into place by
/// commit(): for writers that stream (VTK's XML writers) without first holding the whole file
/// in memory. The stream can seek, back as well (VTK writes each array's compression header
/// after its blocks).
///
/// A failed write (a full disk) is kept, not shown to the stream: VTK 9.2's XML writer frees an
/// invalid pointer when its stream fails part-way. commit() then throws IoError naming the file
/// and the cause; a file destroyed without commit() leaves no temporary file behind.
class AtomicOutputFile {
 public:
  explicit AtomicOutputFile(std::filesystem::path path);
  ~AtomicOutputFile();
  AtomicOutputFile(const AtomicOutputFile&) = delete;
  AtomicOutputFile& operator=(const AtomicOutputFile&) = delete;

  std::ostream& stream() { return stream_; }
  /// Closes the file and renames it into place; throws IoError if any write failed.
  void commit(Durability durability = Durability::Renamed);

 private:
  /// Buffered positional writes (pwrite) to the file; the first error is recorded, and later
  /// writes are skipped but counted, so the stream's positions stay those of the file.
  class Buffer : public std::streambuf {
   public:
    explicit Buffer(int fd);
    int error() const { return error_; }
    void flush_buffer();

   protected:
    int_type overflow(int_type c) override;
    std::streamsize xsputn(const char* s, std::streamsize n) override;
    int sync() override;
    pos_type seekoff(off_type off, std::ios_base::seekdir dir,
                     std::ios_base::openmode which) override;
    pos_type seekpos(pos_type pos, std::ios_base::openmode which) override;

   private:
    void write_at(const char* s, std::size_t n);
    int fd_;
    std::vector<char> data_;
    off_type position_ = 0;  // of the buffer's first byte in the file
    off_type end_ = 0;       // of the file
    int error_ = 0;
  };

  std::filesystem::path path_, tmp_;
  int fd_ = -1;
  Buffer buffer_;
  std::ostream stream_;
};

}  // namespace wcmps
