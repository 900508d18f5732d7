#pragma once
/// @file SizeEstimate.h
/// @brief How many particles a case makes, from its shapes alone, before any is built.
///
/// The walls' rows are counted from their lengths the way sample_polyline lays them (exact,
/// and corners too sharp for the rows are found as the builder finds them). The fluid is the
/// builder's own scan of the lattice (scene/FluidLattice.h) on every s-th point in x and y,
/// with s chosen so that at most kScannedPoints are tested (fewer for shapes of many edges,
/// kEdgeTests): its count times s^2 (exact for
/// s = 1), and its checks (fluid inside a wall, fluid with no wall below it) on the points it
/// tested. In well under a second for any spacing, however many particles the case describes.

#include <cstdint>

#include "core/Vec2.h"
#include "scene/CaseSpec.h"

namespace wcmps {

struct ParticleEstimate {
  /// Lattice points of the fluid scanned at most: a second's work is ~1e7 (each point is tested
  /// against every shape); 1e6 keeps the estimate to a tenth of that, and the count's sampling
  /// error (about the perimeter's points over s, over the area's points) well under 1 %.
  static constexpr double kScannedPoints = 1.0e6;
  /// ... and at most this many tests of a point against an edge (of a fluid shape, or of a wall
  /// twice: its clearance and the ray below the point), for shapes of many vertices (a surveyed
  /// bed): about 0.1 s.
  static constexpr double kEdgeTests = 3.0e7;

  double fluid = 0.0, wall = 0.0, ghost = 0.0;  ///< estimated counts (doubles: may be huge)
  std::int64_t stride = 1;  ///< the fluid scanned on every stride-th point (1: counted exactly)
  int ghost_layers = 0;
  Vec2 lo, hi;  ///< the box of the walls' rows and the fluid shapes
  double total() const { return fluid + wall + ghost; }
};

/// Throws CaseError for what it finds wrong (see above).
ParticleEstimate estimate_particles(const CaseSpec& spec);

}  // namespace wcmps
