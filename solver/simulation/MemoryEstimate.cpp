#include "simulation/MemoryEstimate.h"

#include <cmath>
#include <cstdio>

#include "core/Memory.h"

namespace wcmps {
namespace {

/// Points of the square lattice within distance c (in spacings) of a lattice point, itself
/// excluded.
int lattice_points_within(double c) {
  const int k = static_cast<int>(std::ceil(c));
  int n = 0;
  for (int i = -k; i <= k; ++i) {
    for (int j = -k; j <= k; ++j) n += i * i + j * j < c * c ? 1 : 0;
  }
  return n - 1;
}

std::string count(double n) {
  char buf[32];
  if (n < 1e9) {
    std::snprintf(buf, sizeof buf, "%.0f", n);
  } else {
    std::snprintf(buf, sizeof buf, "%.3g", n);
  }
  return buf;
}

}  // namespace

MemoryEstimate estimate_memory(const CaseSpec& spec, const ParticleEstimate& counts,
                               double program_bytes) {
  MemoryEstimate m;
  const double n = counts.total();
  m.program = program_bytes;
  m.overhead = MemoryEstimate::kRunOverheadBytes;
  const bool strain = renormalisation_in_effect(spec) == GradientRenormalisation::Strain;
  const bool collision = spec.particle_collision != ParticleCollisionScheme::None;
  m.particles = n * (MemoryEstimate::kBytesPerParticle +
                     (strain ? MemoryEstimate::kStrainBytesPerParticle : 0.0) +
                     (collision ? MemoryEstimate::kCollisionBytesPerParticle : 0.0));
  m.list_neighbours = lattice_points_within(spec.re_over_dl + spec.neighbour_skin);
  // Lists are built for the wall and the fluid particles (ghosts need none).
  m.lists = (counts.fluid + counts.wall) * 4.0 * MemoryEstimate::kListGrowth * m.list_neighbours;
  // The domain as the scene builder makes it (scene/SceneBuilder.cpp): the particles' box and
  // re around it, three of its heights above it for splashes; or the case's own.
  Vec2 lo = counts.lo, hi = counts.hi;
  if (spec.domain) {
    lo = spec.domain->first;
    hi = spec.domain->second;
  } else {
    const double re = spec.re();
    hi.y += 3.0 * (hi.y - lo.y);
    lo = lo - Vec2{re, re};
    hi = hi + Vec2{re, re};
  }
  const double cell = spec.re() + spec.neighbour_skin * spec.dl;
  m.grid = std::ceil((hi.x - lo.x) / cell) * std::ceil((hi.y - lo.y) / cell) * 8.0;
  return m;
}

std::string describe_estimate(const ParticleEstimate& c, const MemoryEstimate& m) {
  std::string out;
  char buf[256];
  std::snprintf(buf, sizeof buf,
                "estimate            %s particles: fluid %s%s, wall %s, ghost %s\n",
                count(c.total()).c_str(), count(c.fluid).c_str(),
                c.stride == 1 ? ""
                              : (" (counted on 1 lattice point in " + std::to_string(c.stride) +
                                 " x " + std::to_string(c.stride) + ")")
                                    .c_str(),
                count(c.wall).c_str(), count(c.ghost).c_str());
  out += buf;
  std::snprintf(buf, sizeof buf,
                "memory              %s at its peak: particles %s, neighbour lists %s "
                "(%d per particle), cells %s, run %s, the program %s\n",
                format_bytes(m.total()).c_str(), format_bytes(m.particles).c_str(),
                format_bytes(m.lists).c_str(), m.list_neighbours, format_bytes(m.grid).c_str(),
                format_bytes(m.overhead).c_str(), format_bytes(m.program).c_str());
  out += buf;
  return out;
}

}  // namespace wcmps
