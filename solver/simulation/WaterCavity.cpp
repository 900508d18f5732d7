#include "simulation/WaterCavity.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "neighbours/CellGrid.h"

namespace wcmps {

WaterCavity::WaterCavity(const CaseSpec& spec) : dl_(spec.dl) {
  for (std::size_t w = 0; w < spec.walls.size(); ++w) {
    if (spec.body && spec.body->wall == w) continue;
    const WallSpec& ws = spec.walls[w];
    walls_.push_back(wall_surface(ws.points, ws.closed, ws.solid_on_right));
  }
}

CavityMeasure WaterCavity::measure(const double* x, const double* y, const ParticleKind* kind,
                                   std::int64_t count,
                                   const std::vector<Vec2>& body_outline) const {
  CavityMeasure m;
  constexpr double kInf = std::numeric_limits<double>::infinity();
  double x0 = kInf, x1 = -kInf, lo_x = kInf, lo_y = kInf, hi_x = -kInf, hi_y = -kInf;
  for (std::int64_t i = 0; i < count; ++i) {
    lo_x = std::min(lo_x, x[i]), hi_x = std::max(hi_x, x[i]);
    lo_y = std::min(lo_y, y[i]), hi_y = std::max(hi_y, y[i]);
    if (kind[i] == ParticleKind::Fluid) x0 = std::min(x0, x[i]), x1 = std::max(x1, x[i]);
  }
  if (!(x1 >= x0)) return m;  // no fluid
  // The water's top over each column of grid points, x0 + (k + 1/2) h: the highest fluid
  // particle whose own width, DL, covers it (|x_i - x| <= DL/2).
  const double h = 0.25 * dl_, dl2 = dl_ * dl_;
  const auto columns = static_cast<std::int64_t>((x1 - x0) / h) + 1;
  std::vector<double> top(static_cast<std::size_t>(columns), -kInf);
  for (std::int64_t i = 0; i < count; ++i) {
    if (kind[i] != ParticleKind::Fluid) continue;
    const auto first = std::max<std::int64_t>(
        0, static_cast<std::int64_t>(std::ceil((x[i] - 0.5 * dl_ - x0) / h - 0.5)));
    const auto last = std::min<std::int64_t>(
        columns - 1, static_cast<std::int64_t>(std::floor((x[i] + 0.5 * dl_ - x0) / h - 0.5)));
    for (std::int64_t k = first; k <= last; ++k) {
      top[static_cast<std::size_t>(k)] = std::max(top[static_cast<std::size_t>(k)], y[i]);
    }
  }
  CellGrid grid;
  grid.configure({lo_x - dl_, lo_y - dl_}, {hi_x + dl_, hi_y + dl_}, dl_);
  grid.bin(x, y, count);
  const auto near_a_particle = [&](Vec2 p) {
    // Cells are DL wide: the particles within DL of p are in its cell's 3 x 3 block.
    const int cx = grid.cell_x(p.x), cy = grid.cell_y(p.y);
    for (int by = std::max(cy - 1, 0); by <= std::min(cy + 1, grid.ny() - 1); ++by) {
      for (int bx = std::max(cx - 1, 0); bx <= std::min(cx + 1, grid.nx() - 1); ++bx) {
        for (const std::int32_t* j = grid.cell_begin(bx, by); j != grid.cell_end(bx, by); ++j) {
          if ((x[*j] - p.x) * (x[*j] - p.x) + (y[*j] - p.y) * (y[*j] - p.y) <= dl2) return true;
        }
      }
    }
    return false;
  };
  const auto in_water_region = [&](Vec2 p) {
    for (const auto& w : walls_) {
      if (signed_distance(w, p) > 0.0) return false;  // inside a wall's solid
    }
    return body_outline.empty() || !polygon_contains(body_outline, p);
  };
  for (std::int64_t k = 0; k < columns; ++k) {
    const double px = x0 + (static_cast<double>(k) + 0.5) * h;
    const double water_top = top[static_cast<std::size_t>(k)];
    for (double py = lo_y + 0.5 * h; py < water_top; py += h) {
      const Vec2 p{px, py};
      if (near_a_particle(p) || !in_water_region(p)) continue;
      if (m.points == 0) m.first = p;
      ++m.points;
    }
  }
  m.area = static_cast<double>(m.points) * h * h;
  return m;
}

}  // namespace wcmps
