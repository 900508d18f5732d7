#pragma once
/// @file OffscreenDisplay.h
/// @brief Makes off-screen rendering possible before any VTK render window exists.
///
/// A VTK built with OSMesa or EGL renders with no X server; ParaView 5.11's VTK as Debian
/// builds it renders through X only, and a render window with no X server kills the process
/// (docs/figures.md). So, in order: OSMesa or EGL if the VTK has them; else the X display of
/// $DISPLAY if it answers; else a private Xvfb started for this process (and stopped with
/// it) if Xvfb is on the PATH; else a DisplayError saying what to install.

#include <sys/types.h>
#include <stdexcept>
#include <string>

namespace wcmps {

class DisplayError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class OffscreenDisplay {
 public:
  /// Chooses and, for a private Xvfb, starts the rendering path. Throws DisplayError.
  OffscreenDisplay();
  ~OffscreenDisplay();
  OffscreenDisplay(const OffscreenDisplay&) = delete;
  OffscreenDisplay& operator=(const OffscreenDisplay&) = delete;

  /// How figures are rendered, for the log: "OSMesa", "EGL", "X display :0", "private Xvfb :3".
  const std::string& description() const { return description_; }

 private:
  std::string description_;
  pid_t xvfb_ = -1;
  void* held_ = nullptr;  ///< Display*: our connection to $DISPLAY, open while we render
};

}  // namespace wcmps
