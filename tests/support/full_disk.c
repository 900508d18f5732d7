/* A disk that fills up, for tests (LD_PRELOAD): writes to files under $WCMPS_FULL_DISK_DIR fail
 * with ENOSPC ("No space left on device") once $WCMPS_FULL_DISK_BYTES bytes have been written
 * there, as on a full file system. Covers write, writev, pwrite and pwrite64: the calls through
 * which wcmps (io/AtomicFile), VTK's XML writers (std::ofstream) and HDF5 (sec2 driver) write. */
#define _GNU_SOURCE
#include <dlfcn.h>
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/types.h>
#include <sys/uio.h>
#include <unistd.h>

static long long written = 0;

/* Whether `count` more bytes to `fd` fit; counts them if they do. */
static int fits(int fd, size_t count) {
  const char* dir = getenv("WCMPS_FULL_DISK_DIR");
  const char* limit = getenv("WCMPS_FULL_DISK_BYTES");
  if (!dir || !limit) return 1;
  char link[64], path[4096];
  snprintf(link, sizeof link, "/proc/self/fd/%d", fd);
  const ssize_t n = readlink(link, path, sizeof path - 1);
  if (n < 0) return 1;
  path[n] = '\0';
  if (strncmp(path, dir, strlen(dir)) != 0) return 1;
  if (written + (long long)count > atoll(limit)) {
    errno = ENOSPC;
    return 0;
  }
  written += (long long)count;
  return 1;
}

typedef ssize_t (*write_fn)(int, const void*, size_t);
typedef ssize_t (*writev_fn)(int, const struct iovec*, int);
typedef ssize_t (*pwrite_fn)(int, const void*, size_t, off_t);

ssize_t write(int fd, const void* buf, size_t count) {
  static write_fn real;
  if (!real) real = (write_fn)dlsym(RTLD_NEXT, "write");
  return fits(fd, count) ? real(fd, buf, count) : -1;
}

ssize_t writev(int fd, const struct iovec* iov, int iovcnt) {
  static writev_fn real;
  if (!real) real = (writev_fn)dlsym(RTLD_NEXT, "writev");
  size_t count = 0;
  for (int i = 0; i < iovcnt; ++i) count += iov[i].iov_len;
  return fits(fd, count) ? real(fd, iov, iovcnt) : -1;
}

ssize_t pwrite(int fd, const void* buf, size_t count, off_t offset) {
  static pwrite_fn real;
  if (!real) real = (pwrite_fn)dlsym(RTLD_NEXT, "pwrite");
  return fits(fd, count) ? real(fd, buf, count, offset) : -1;
}

ssize_t pwrite64(int fd, const void* buf, size_t count, off_t offset) {
  static pwrite_fn real;
  if (!real) real = (pwrite_fn)dlsym(RTLD_NEXT, "pwrite64");
  return fits(fd, count) ? real(fd, buf, count, offset) : -1;
}
