/// @file case_fuzzer.cpp
/// @brief libFuzzer target over the case-file parser and validator: parse_case_text, then
/// estimate_particles (any size) and build_scene (the geometric checks: fluid outside walls,
/// overlapping walls, a block that does not fit, ...). Every input must either give a case or throw
/// CaseError; anything else (a crash, another exception, a leak, undefined behaviour, a hang) is a
/// finding. Built with clang's -fsanitize=fuzzer,address,undefined by tests/fuzz/CMakeLists.txt
/// (docs/checkpoints.md, "Fuzzing").

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>

#include "core/Error.h"
#include "scene/CaseParser.h"
#include "scene/FluidLattice.h"
#include "scene/SceneBuilder.h"
#include "scene/SizeEstimate.h"

namespace {

/// Scenes are built only while they stay small: the fuzzer looks for wrong answers to odd
/// input, not for the (legitimate) memory and time a fine spacing or a far-reaching shape asks
/// for. Lattice points of the walls' bounding box and of the fluids' (the box the scene builder
/// scans point by point), at most each.
constexpr double kMaxLatticePoints = 2.0e5;

bool small_enough(const wcmps::CaseSpec& spec) {
  double lo_x = INFINITY, lo_y = INFINITY, hi_x = -INFINITY, hi_y = -INFINITY;
  for (const auto& w : spec.walls) {
    for (const auto& p : w.points) {
      lo_x = std::fmin(lo_x, p.x);
      lo_y = std::fmin(lo_y, p.y);
      hi_x = std::fmax(hi_x, p.x);
      hi_y = std::fmax(hi_y, p.y);
    }
  }
  const double points =
      (hi_x - lo_x + 2.0 * spec.re()) * (hi_y - lo_y + 2.0 * spec.re()) / (spec.dl * spec.dl);
  return std::isfinite(points) && points < kMaxLatticePoints &&
         wcmps::fluid_lattice_points(spec) < kMaxLatticePoints;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const wcmps::CaseSpec spec = wcmps::parse_case_text(text, "fuzz.toml");
    // The estimate is made for any size (it samples the lattice): always.
    (void)wcmps::estimate_particles(spec);
    if (small_enough(spec)) (void)wcmps::build_scene(spec);
  } catch (const wcmps::CaseError&) {
    // The answer to a bad case file.
  }
  return 0;
}
