#include "support/TestSupport.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <stdexcept>
#include <string_view>
#include <utility>
#include <vector>

#include "scene/CaseParser.h"

namespace wcmps::test {

namespace {

std::string trimmed(std::string_view s) {
  const auto a = s.find_first_not_of(" \t\r");
  if (a == std::string_view::npos) return {};
  const auto b = s.find_last_not_of(" \t\r");
  return std::string(s.substr(a, b - a + 1));
}

/// The case text with the "key = value" lines of `lines` (separated by ';') in its [physics]
/// table, replacing the lines of the same keys there (a table of its own at the end if the case
/// has none).
std::string with_physics(const std::string& text, const std::string& lines) {
  std::vector<std::pair<std::string, std::string>> keys;
  std::size_t from = 0;
  while (from <= lines.size()) {
    const std::size_t to = std::min(lines.find(';', from), lines.size());
    const std::string line = trimmed(std::string_view(lines).substr(from, to - from));
    from = to + 1;
    if (line.empty()) continue;
    const auto eq = line.find('=');
    if (eq == std::string::npos) {
      throw std::invalid_argument("WCMPS_TEST_PHYSICS: \"" + line + "\" is not key = value");
    }
    keys.emplace_back(trimmed(std::string_view(line).substr(0, eq)), line);
  }
  std::string out, table;
  bool found = false;
  std::size_t at = 0;
  while (at < text.size()) {
    const std::size_t end = std::min(text.find('\n', at), text.size());
    const std::string line = text.substr(at, end - at);
    at = end + 1;
    const std::string t = trimmed(line);
    if (!t.empty() && t[0] == '[') table = t;
    if (table == "[physics]") {
      const auto eq = t.find('=');
      const std::string key = eq == std::string::npos ? "" : trimmed(t.substr(0, eq));
      if (std::any_of(keys.begin(), keys.end(), [&](const auto& k) { return k.first == key; })) {
        continue;
      }
    }
    out += line + "\n";
    if (t == "[physics]") {
      found = true;
      for (const auto& k : keys) out += k.second + "\n";
    }
  }
  if (!found) {
    out += "\n[physics]\n";
    for (const auto& k : keys) out += k.second + "\n";
  }
  return out;
}

}  // namespace

void apply_physics_override(CaseSpec& spec) {
  const char* physics = std::getenv("WCMPS_TEST_PHYSICS");
  if (physics && *physics) {
    spec = parse_case_text(with_physics(spec.source_text, physics), spec.file.file);
  }
}

void apply_scheme_override(CaseSpec& spec) {
  // First the case's own [physics] keys from the environment (the spec is parsed again), then
  // the scheme, which sets fields of the parsed spec.
  apply_physics_override(spec);
  const char* scheme = std::getenv("WCMPS_TEST_SCHEME");
  if (!scheme || !*scheme) return;
  if (std::string(scheme) != "3a85288") {
    throw std::invalid_argument(std::string("WCMPS_TEST_SCHEME=") + scheme +
                                ": the one scheme known is 3a85288");
  }
  use_scheme_3a85288(spec);
}

std::string source_path(const std::string& relative) {
  return std::string(WCMPS_SOURCE_DIR) + "/" + relative;
}

CaseSpec load_case(const std::string& relative) {
  CaseSpec spec = parse_case_file(source_path(relative));
  apply_scheme_override(spec);
  return spec;
}

std::filesystem::path scratch_dir(const std::string& name) {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  auto dir = std::filesystem::current_path() / "scratch" /
             (std::string(info ? info->test_suite_name() : "test") + "." +
              (info ? info->name() : "x") + "." + name);
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

std::string minimal_case_text() {
  return R"([case]
name = "mini"

[particles]
spacing = 0.01

[time]
end = 0.01

[[wall]]
polyline = [[0.0, 0.2], [0.0, 0.0], [0.2, 0.0], [0.2, 0.2]]
solid = "right"

[[fluid]]
rectangle = { min = [0.0, 0.0], max = [0.2, 0.1] }
)";
}

}  // namespace wcmps::test
