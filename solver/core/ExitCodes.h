#pragma once
/// @file ExitCodes.h
/// @brief Exit codes of the wcmps program (documented in docs/running.md).

namespace wcmps::exit_code {
inline constexpr int kOk = 0;
inline constexpr int kInternal = 1;       ///< a bug: please report
inline constexpr int kUsage = 2;          ///< bad command line
inline constexpr int kBadCase = 3;        ///< case file unreadable, malformed or inconsistent
inline constexpr int kIo = 4;             ///< output directory or file cannot be written
inline constexpr int kUnstable = 5;       ///< the run became unstable (last good frame written)
inline constexpr int kNoDisplay = 6;      ///< figures: no X display and no Xvfb to start one
inline constexpr int kCannotRestart = 7;  ///< run --restart: no usable checkpoint
/// run: stopped by a signal after a checkpoint; the code is 128 + the signal's number (130 for
/// SIGINT, 143 for SIGTERM), as shells report a program a signal ended.
inline constexpr int kStoppedBySignal = 128;
}  // namespace wcmps::exit_code
