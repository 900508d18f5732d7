#pragma once
/// @file WaterCavity.h
/// @brief Where the water has torn open: the area of points under the water that no particle
/// is near.
///
/// A point counts when it lies below the water's top in its column (the highest fluid particle
/// whose own width, DL, covers the point's x: |x_i - x| <= DL/2), on the water's side of every
/// wall surface, outside the moving body, and farther than DL from every particle, fluid or
/// boundary (water that is whole leaves no point farther than about DL/sqrt(2) from its
/// particles). The points are those of a grid of spacing DL/4 over the fluid's extent in x; the
/// area is their number times (DL/4)^2. (Until 2026-12-07, session 13, the column was the fixed
/// DL-wide bin the point fell in, whose top could be a particle almost DL to the side: it counted
/// the air in a notch of a steep surface, beside the water and open to the air above it, as
/// cavity; docs/validation.md, "The cavity's column".)
/// A cavity that opens over an accelerating body (case I with negative pressures set to zero:
/// a pocket 6 cm long on the block's top at 0.3 s) measures square centimetres; water that
/// follows the body measures zero.

#include <cstdint>
#include <vector>

#include "core/Vec2.h"
#include "particles/ParticleKind.h"
#include "scene/CaseSpec.h"
#include "scene/Geometry.h"

namespace wcmps {

struct CavityMeasure {
  double area = 0.0;        ///< m^2
  std::int64_t points = 0;  ///< grid points counted
  Vec2 first;               ///< the counted point of smallest x (then y), if any
};

class WaterCavity {
 public:
  /// The case's walls (the body's wall, if there is one, is given per call at its place).
  explicit WaterCavity(const CaseSpec& spec);

  /// The measure for particles at (x, y) of the given kinds; body_outline: the body's surface
  /// polygon where it is now (empty: no body).
  CavityMeasure measure(const double* x, const double* y, const ParticleKind* kind,
                        std::int64_t count, const std::vector<Vec2>& body_outline) const;

  double spacing() const { return dl_; }

 private:
  double dl_;
  std::vector<WallSurface> walls_;  // every wall but the body's
};

}  // namespace wcmps
