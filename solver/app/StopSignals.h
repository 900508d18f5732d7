#pragma once
/// @file StopSignals.h
/// @brief SIGINT and SIGTERM during `wcmps run`: the first asks the run to stop after the
/// step in progress (it then writes a checkpoint and exits with 128 + the signal's number); a
/// second one ends the program at once, which leaves a valid series and the last checkpoint
/// (docs/checkpoints.md).

#include <string>

namespace wcmps {

/// Installs the handlers. The program's one piece of global state: a signal handler can only
/// leave a note where the run will look.
void catch_stop_signals();

/// The signal received since catch_stop_signals() (0 while none).
int stop_signal();

/// "SIGINT", "SIGTERM" or "signal N".
std::string signal_name(int signal);

}  // namespace wcmps
