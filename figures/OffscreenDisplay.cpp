#include "OffscreenDisplay.h"

#include <X11/Xlib.h>
#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>
#include <vtkRenderingOpenGLConfigure.h>

#include <cstdlib>
#include <filesystem>
#include <string>

namespace wcmps {
namespace {

/// A connection to the X display `name`, or null. An X server started without -noreset (as
/// xvfb-run starts it) resets whenever its last client leaves, and a connection attempted
/// during a reset fails (2 % of opens in two concurrent loops: docs/figures.md, "X server
/// resets"). Twenty tries 0.05 s apart ride out resets caused by other clients.
Display* open_display(const char* name) {
  if (!name || !*name) return nullptr;
  for (int attempt = 0; attempt < 20; ++attempt) {
    if (Display* d = XOpenDisplay(name)) return d;
    ::usleep(50000);
  }
  return nullptr;
}

bool display_answers(const char* name) {
  Display* d = open_display(name);
  if (!d) return false;
  XCloseDisplay(d);
  return true;
}

/// The first executable `name` on $PATH, or empty.
std::string find_on_path(const std::string& name) {
  const char* path = std::getenv("PATH");
  if (!path) return {};
  std::string dirs(path);
  size_t start = 0;
  while (start <= dirs.size()) {
    const size_t end = std::min(dirs.find(':', start), dirs.size());
    const std::filesystem::path candidate =
        std::filesystem::path(dirs.substr(start, end - start)) / name;
    if (end > start && ::access(candidate.c_str(), X_OK) == 0) return candidate.string();
    start = end + 1;
  }
  return {};
}

}  // namespace

OffscreenDisplay::OffscreenDisplay() {
#if defined(VTK_OPENGL_HAS_OSMESA)
  description_ = "OSMesa (no X server needed)";
  return;
#elif defined(VTK_OPENGL_HAS_EGL)
  description_ = "EGL (no X server needed)";
  return;
#endif
  const char* env = std::getenv("DISPLAY");
  // The connection is held until this object goes: while it is open the server cannot reset,
  // so the render windows' own connections (made without retries, and a failed one aborts the
  // process) find it up.
  if (Display* d = open_display(env)) {
    held_ = d;
    description_ = std::string("X display ") + env;
    return;
  }
  const std::string xvfb = find_on_path("Xvfb");
  if (xvfb.empty()) {
    throw DisplayError(std::string("no X display to render with (DISPLAY=") +
                       (env && *env ? env : "unset") +
                       ") and no Xvfb on the PATH: install the package xvfb (apt-get install "
                       "xvfb), or run under an X server");
  }
  // Xvfb picks a free display number and writes it to the pipe (-displayfd).
  int fds[2];
  if (::pipe(fds) != 0) throw DisplayError("cannot start Xvfb: pipe() failed");
  xvfb_ = ::fork();
  if (xvfb_ < 0) throw DisplayError("cannot start Xvfb: fork() failed");
  if (xvfb_ == 0) {
    ::close(fds[0]);
    const int null = ::open("/dev/null", O_RDWR);
    ::dup2(null, STDIN_FILENO);
    ::dup2(null, STDOUT_FILENO);
    ::dup2(null, STDERR_FILENO);
    const std::string fd = std::to_string(fds[1]);
    ::execl(xvfb.c_str(), "Xvfb", "-displayfd", fd.c_str(), "-screen", "0", "2560x1600x24",
            "-nolisten", "tcp", "-noreset", static_cast<char*>(nullptr));
    ::_exit(127);
  }
  ::close(fds[1]);
  std::string number;
  pollfd p{fds[0], POLLIN, 0};
  // Xvfb is up in well under a second; 20 s leaves room for a loaded machine.
  while (::poll(&p, 1, 20000) > 0) {
    char buf[16];
    const ssize_t n = ::read(fds[0], buf, sizeof buf);
    if (n <= 0) break;
    number.append(buf, static_cast<size_t>(n));
    if (number.find('\n') != std::string::npos) break;
  }
  ::close(fds[0]);
  while (!number.empty() && (number.back() == '\n' || number.back() == '\r')) number.pop_back();
  const std::string name = ":" + number;
  if (number.empty() || !display_answers(name.c_str())) {
    ::kill(xvfb_, SIGTERM);
    ::waitpid(xvfb_, nullptr, 0);
    xvfb_ = -1;
    throw DisplayError("no X display to render with, and the private Xvfb (" + xvfb +
                       ") did not start");
  }
  ::setenv("DISPLAY", name.c_str(), 1);
  description_ = "private Xvfb " + name + " (" + xvfb + ")";
}

OffscreenDisplay::~OffscreenDisplay() {
  if (held_) XCloseDisplay(static_cast<Display*>(held_));
  if (xvfb_ > 0) {
    ::kill(xvfb_, SIGTERM);
    ::waitpid(xvfb_, nullptr, 0);
  }
}

}  // namespace wcmps
