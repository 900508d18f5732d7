#include "scene/SizeEstimate.h"

#include <algorithm>
#include <cmath>

#include "core/Error.h"
#include "scene/FluidLattice.h"

namespace wcmps {

ParticleEstimate estimate_particles(const CaseSpec& spec) {
  ParticleEstimate e;
  const double dl = spec.dl;
  e.ghost_layers = ghost_layer_count(spec);
  const std::vector<WallGeometry> geometry = wall_geometries(spec);
  bool first = true;
  auto grow = [&](Vec2 p) {
    if (first) e.lo = e.hi = p, first = false;
    e.lo = {std::min(e.lo.x, p.x), std::min(e.lo.y, p.y)};
    e.hi = {std::max(e.hi.x, p.x), std::max(e.hi.y, p.y)};
  };
  for (std::size_t w = 0; w < spec.walls.size(); ++w) {
    for (int k = 0; k <= e.ghost_layers; ++k) {
      const std::vector<Vec2> row = wall_row(spec, geometry, w, k);
      double length = 0.0;
      for (const auto& s : polyline_segments(row, spec.walls[w].closed)) length += norm(s.b - s.a);
      // A count past what an index holds is not a case to build; say so before counting it.
      if (!(length / dl < 1.0e15)) {
        throw CaseError(spec.walls[w].where,
                        wall_label(spec, w) + ": more than 1e15 particles in a row at spacing " +
                            std::to_string(dl) + " m; check [particles] spacing");
      }
      const double n = static_cast<double>(count_polyline_samples(row, spec.walls[w].closed, dl));
      (k == 0 ? e.wall : e.ghost) += n;
      std::for_each(row.begin(), row.end(), grow);
    }
  }
  for (const auto& f : spec.fluids) std::for_each(f.polygon.begin(), f.polygon.end(), grow);

  const double points = fluid_lattice_points(spec);
  double edges = 0.0;  // tested per lattice point
  for (const auto& f : spec.fluids) edges += static_cast<double>(f.polygon.size());
  for (const auto& g : geometry) edges += 2.0 * static_cast<double>(g.surface.size());
  const double scanned = std::min(ParticleEstimate::kScannedPoints,
                                  ParticleEstimate::kEdgeTests / std::max(edges, 1.0));
  // Every s-th point in x and y tests about (nx/s + 1)(ny/s + 1) points: at most 3 x scanned
  // when s >= sqrt(nx ny / scanned) and s >= max(nx, ny) / scanned. The second bounds a box far
  // longer than wide (a vertex typed a thousand times too far), whose one sampled column would
  // otherwise hold up to max(nx, ny) / sqrt(nx ny / scanned) points.
  const double s = std::max(std::sqrt(points / scanned), fluid_lattice_span(spec) / scanned);
  e.stride = std::max<std::int64_t>(1, static_cast<std::int64_t>(std::ceil(s)));
  const FluidScan scan = scan_fluid_lattice(spec, geometry, e.stride, {});
  e.fluid = static_cast<double>(scan.kept) * static_cast<double>(e.stride) *
            static_cast<double>(e.stride);
  return e;
}

}  // namespace wcmps
