#include "support/TestSupport.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <stdexcept>

#include "scene/CaseParser.h"

namespace wcmps::test {

void apply_scheme_override(CaseSpec& spec) {
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
