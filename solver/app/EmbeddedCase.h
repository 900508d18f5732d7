#pragma once
/// @file EmbeddedCase.h
/// @brief The default case compiled into the program (generated from a file in cases/ by CMake,
/// so that the file stays the one source of truth).

#include <string_view>

namespace wcmps {
/// The text of the default case file.
extern const std::string_view kEmbeddedCaseText;
/// Its path in the source tree, for messages.
extern const std::string_view kEmbeddedCasePath;
}  // namespace wcmps
