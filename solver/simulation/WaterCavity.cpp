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
  // The water's top in each DL-wide column from x0.
  const auto column = [&](double px) { return static_cast<std::size_t>((px - x0) / dl_); };
  std::vector<double> top(column(x1) + 1, -kInf);
  for (std::int64_t i = 0; i < count; ++i) {
    if (kind[i] == ParticleKind::Fluid) top[column(x[i])] = std::max(top[column(x[i])], y[i]);
  }
  CellGrid grid;
  grid.configure({lo_x - dl_, lo_y - dl_}, {hi_x + dl_, hi_y + dl_}, dl_);
  grid.bin(x, y, count);
  const double h = 0.25 * dl_, dl2 = dl_ * dl_;
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
  for (double px = x0 + 0.5 * h; px <= x1; px += h) {
    const double water_top = top[column(px)];
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
