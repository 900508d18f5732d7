#pragma once
/// @file CaseParser.h
/// @brief Reads a TOML case file into a CaseSpec. Every problem (syntax, unknown key, wrong
/// type, value out of range, inconsistent values) throws a CaseError naming the file, line and
/// column. Geometry that makes no sense is found later, by the scene builder.

#include <string>
#include <string_view>

#include "scene/CaseSpec.h"

namespace wcmps {

/// Parses the case file at `path`.
CaseSpec parse_case_file(const std::string& path);

/// Parses case text; `path` names it in messages (and gives the default case name).
CaseSpec parse_case_text(std::string_view text, const std::string& path);

}  // namespace wcmps
