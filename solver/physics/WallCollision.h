#pragma once
/// @file WallCollision.h
/// @brief Keeps isolated fluid particles out of walls: the collision model of Koshizuka,
/// Nobe & Oka (1998, Int. J. Numer. Meth. Fluids 26, 751-769), applied to fluid-boundary pairs.
///
/// A splash particle has n* < beta n0: it is on the free surface, its pressure is zero, and the
/// wall pressure extrapolated from it is zero too. Nothing then pushes it back from a wall, and
/// a drop thrown at a wall goes through the wall row. The model treats a fluid particle i that
/// comes closer than the collision distance to a boundary particle j, while approaching it, as
/// an inelastic collision with an infinitely heavy body:
///
///     n = (r_j - r_i)/|r_j - r_i|,   w = (u_i - u_j) . n > 0,
///     u_i <- u_i - (1 + e) w n,
///
/// with e the coefficient of restitution. Only the approaching normal component changes; the
/// tangential motion is kept. Water at rest sits a spacing DL from the wall row (closer only by
/// its compression, under 1 %), so with a collision distance below DL the model never acts on
/// resting or gently moving water; a particle that would pass between two wall particles (DL
/// apart) comes within DL/2 of one of them first, so any distance above DL/2 stops it.
///
/// Not part of the study's method: [physics] wall_collision = "none" switches it off.

#include <cmath>
#include <cstdint>
#include <string_view>

#include "core/SchemeTable.h"
#include "neighbours/NeighbourList.h"
#include "particles/ParticleKind.h"

namespace wcmps {

enum class WallCollisionScheme { None, Koshizuka1998 };

struct WallCollision_Koshizuka1998 {
  double distance;     ///< collision distance (m)
  double restitution;  ///< e in [0, 1]

  /// Applies the collisions of fluid particle i with its boundary neighbours to (u[i], v[i]),
  /// from the positions x, y and the boundary particles' velocities. Returns the number of
  /// collisions.
  int apply(std::int64_t i, IdRange nb, const double* x, const double* y, double* u, double* v,
            const ParticleKind* kind) const {
    const double d2 = distance * distance;
    int hits = 0;
    for (const std::int32_t j : nb) {
      if (kind[j] == ParticleKind::Fluid) continue;
      const double dx = x[j] - x[i], dy = y[j] - y[i];
      const double r2 = dx * dx + dy * dy;
      if (r2 >= d2 || r2 <= 0.0) continue;
      const double r = std::sqrt(r2);
      const double nx = dx / r, ny = dy / r;
      const double w = (u[i] - u[j]) * nx + (v[i] - v[j]) * ny;
      if (w <= 0.0) continue;  // moving apart
      u[i] -= (1.0 + restitution) * w * nx;
      v[i] -= (1.0 + restitution) * w * ny;
      ++hits;
    }
    return hits;
  }
};

inline constexpr SchemeEntry<WallCollisionScheme> kWallCollisionSchemes[] = {
    {"koshizuka1998", WallCollisionScheme::Koshizuka1998,
     "Koshizuka, Nobe & Oka (1998), Int. J. Numer. Meth. Fluids 26, 751-769"},
    {"none", WallCollisionScheme::None, ""},
};

}  // namespace wcmps
