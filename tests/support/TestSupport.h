#pragma once
/// @file TestSupport.h
/// @brief Helpers shared by the tests: paths into the source tree, scratch directories,
/// small particle sets.

#include <filesystem>
#include <string>

#include "scene/CaseSpec.h"

namespace wcmps::test {

/// Absolute path of a file in the source tree, e.g. "cases/dambreak/case.toml".
std::string source_path(const std::string& relative);

/// A case file of cases/ parsed, ready for overrides of its fields, with the scheme that
/// apply_scheme_override() asks for.
CaseSpec load_case(const std::string& relative);

/// WCMPS_TEST_SCHEME=3a85288 in the environment puts the scheme of commit 3a85288 into the spec
/// (the stabilisation's options off: docs/method.md), so that the validation tests measure the
/// old scheme side by side with the defaults (docs/validation.md). WCMPS_TEST_PHYSICS holds
/// [physics] lines of a case file separated by ';' (e.g. `artificial_viscosity = 0.01;
/// wall_pressure = "eos"`): they replace the case's own, so that one change is measured by every
/// validation test without a patched build; applied first, then WCMPS_TEST_SCHEME. A spec is
/// parsed again from its source_text, so call this before changing its fields. Unset: nothing
/// changes.
void apply_scheme_override(CaseSpec& spec);

/// WCMPS_TEST_PHYSICS alone, for a test that sets the schemes itself.
void apply_physics_override(CaseSpec& spec);

/// An empty scratch directory unique to the running test (removed first if it exists).
std::filesystem::path scratch_dir(const std::string& name);

/// The text of a minimal valid case (a small tank of still water), for parser tests that
/// change one thing of it.
std::string minimal_case_text();

}  // namespace wcmps::test
