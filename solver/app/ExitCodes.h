#pragma once
/// @file ExitCodes.h
/// @brief Exit codes of the wcmps program (documented in docs/running.md).

namespace wcmps::exit_code {
inline constexpr int kOk = 0;
inline constexpr int kInternal = 1;   ///< a bug: please report
inline constexpr int kUsage = 2;      ///< bad command line
inline constexpr int kBadCase = 3;    ///< case file unreadable, malformed or inconsistent
inline constexpr int kIo = 4;         ///< output directory or file cannot be written
inline constexpr int kUnstable = 5;   ///< the run became unstable (last good frame written)
inline constexpr int kNoDisplay = 6;  ///< figures: no X display and no Xvfb to start one
}  // namespace wcmps::exit_code
