#include "scene/SceneBuilder.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <stdexcept>

#include "neighbours/CellGrid.h"
#include "scene/FluidLattice.h"

namespace wcmps {
namespace {

/// The nearest of the points [first, end) of a list to a given point, through a grid of cells
/// one spacing wide over them: rings of cells around the point's cell are searched outwards
/// until the nearest found is closer than the next ring can be. Equal distances go to the lower
/// index, so the answer is the linear scan's (the builder's before this grid: quadratic in the
/// wall's length).
class NearestPoint {
 public:
  NearestPoint() = default;
  NearestPoint(const std::vector<ParticleSeed>& points, std::size_t first, double cell)
      : first_(first), cell_(cell) {
    Vec2 lo = points[first].position, hi = lo;
    for (std::size_t i = first; i < points.size(); ++i) {
      x_.push_back(points[i].position.x);
      y_.push_back(points[i].position.y);
      lo = {std::min(lo.x, x_.back()), std::min(lo.y, y_.back())};
      hi = {std::max(hi.x, x_.back()), std::max(hi.y, y_.back())};
    }
    grid_.configure(lo - Vec2{cell, cell}, hi + Vec2{cell, cell}, cell);
    grid_.bin(x_.data(), y_.data(), static_cast<std::int64_t>(x_.size()));
  }

  /// Index (in the list given) of the point nearest to p.
  std::size_t find(Vec2 p) const {
    const int cx = grid_.cell_x(p.x), cy = grid_.cell_y(p.y);
    const int rings = std::max(grid_.nx(), grid_.ny());
    std::size_t best = 0;
    double best_d = std::numeric_limits<double>::infinity();
    for (int r = 0; r <= rings; ++r) {
      for (int yy = cy - r; yy <= cy + r; ++yy) {
        if (yy < 0 || yy >= grid_.ny()) continue;
        const bool edge_row = yy == cy - r || yy == cy + r;
        for (int xx = cx - r; xx <= cx + r; xx += edge_row ? 1 : 2 * r) {
          if (xx >= 0 && xx < grid_.nx()) {
            for (auto* q = grid_.cell_begin(xx, yy); q != grid_.cell_end(xx, yy); ++q) {
              const auto j = static_cast<std::size_t>(*q);
              const double d = norm(Vec2{x_[j], y_[j]} - p);
              if (d < best_d || (d == best_d && j < best)) best_d = d, best = j;
            }
          }
        }
      }
      // Points of ring r + 1 and beyond are at least r cells from p (clamped to the grid,
      // p outside it is nearer to no point than that either).
      if (best_d < r * cell_) break;
    }
    return first_ + best;
  }

 private:
  std::size_t first_ = 0;
  double cell_ = 0.0;
  std::vector<double> x_, y_;
  CellGrid grid_;
};

/// The fluid particles in runs along gravity (-y): each lattice column split where rows are
/// not DL apart; each run sorted from its bottom up.
std::vector<std::vector<std::size_t>> column_runs(const std::vector<ParticleSeed>& fluid,
                                                  const CaseSpec& spec) {
  std::map<long, std::vector<std::size_t>> columns;
  for (std::size_t k = 0; k < fluid.size(); ++k) {
    const double cx = (fluid[k].position.x - spec.lattice_origin.x) / spec.dl - 0.5;
    columns[std::lround(cx)].push_back(k);
  }
  std::vector<std::vector<std::size_t>> runs;
  for (auto& [col, ids] : columns) {
    std::sort(ids.begin(), ids.end(), [&](std::size_t a, std::size_t b) {
      return fluid[a].position.y < fluid[b].position.y;
    });
    std::size_t begin = 0;
    while (begin < ids.size()) {
      std::size_t end = begin + 1;
      while (end < ids.size() &&
             fluid[ids[end]].position.y - fluid[ids[end - 1]].position.y < 1.5 * spec.dl) {
        ++end;
      }
      runs.emplace_back(ids.begin() + begin, ids.begin() + end);
      begin = end;
    }
  }
  return runs;
}

/// Puts the fluid in the hydrostatic state of the Tait equation, n/n0 = s(h) =
/// (1 + gamma g h / c0^2)^(1/gamma) at depth h below the top of its column (gravity along -y):
/// rows are moved closer, to the spacing whose lattice sum gives n/n0 = s (the discrete n of
/// a squeezed lattice grows 1.23 times faster than 1/dy at re = 3.5 DL), the bottom row
/// staying. Depths repeat from column to column, so each spacing is solved once. `ratio` gets each
/// particle's s at its depth (the number density a continuity-evolved n starts from).
void set_hydrostatic_state(std::vector<ParticleSeed>& fluid, const CaseSpec& spec, double c0,
                           std::vector<double>& ratio) {
  const double dl = spec.dl;
  const double g = -spec.gravity.y;
  auto s = [&](double depth) {
    return std::pow(1.0 + spec.eos_exponent * g * depth / (c0 * c0), 1.0 / spec.eos_exponent);
  };
  std::map<long, double> spacing;  // by depth in half spacings
  // A run may end under a solid (a body in the water): its depth counts from the free surface
  // of its column, the top of the column's highest run, not from the solid.
  std::map<long, double> column_top;
  auto column_of = [&](double x) { return std::lround((x - spec.lattice_origin.x) / dl - 0.5); };
  for (const auto& f : fluid) {
    const long c = column_of(f.position.x);
    const auto it = column_top.find(c);
    const double top = f.position.y + 0.5 * dl;
    if (it == column_top.end() || it->second < top) column_top[c] = top;
  }
  for (const auto& run : column_runs(fluid, spec)) {
    const double top = column_top[column_of(fluid[run.front()].position.x)];
    for (const std::size_t k : run) ratio[k] = s(top - fluid[k].position.y);
    double y = fluid[run.front()].position.y;
    for (std::size_t k = 1; k < run.size(); ++k) {
      const double depth = top - 0.5 * (fluid[run[k]].position.y + fluid[run[k - 1]].position.y);
      const long key = std::lround(depth / dl * 2.0);
      auto it = spacing.find(key);
      if (it == spacing.end()) {
        it = spacing.emplace(key, row_spacing_for_density_ratio(dl, spec.re(), s(depth))).first;
      }
      y += it->second;
      fluid[run[k]].position.y = y;
    }
  }
}

}  // namespace

Scene build_scene(const CaseSpec& spec, const std::function<void(double)>& progress) {
  Scene scene;
  const double dl = spec.dl;
  const double re = spec.re();
  scene.ghost_layers = ghost_layer_count(spec);
  scene.lattice = square_lattice_constants(dl, re);

  // ---- walls: one wall row and K ghost rows parallel to each surface line
  std::vector<ParticleSeed> walls, ghosts;
  std::vector<std::int32_t> ghost_sources;
  std::vector<std::size_t> boundary_owner;  // wall spec of each boundary particle (walls, ghosts)
  const std::vector<WallGeometry> geometry = wall_geometries(spec);
  std::vector<std::size_t> ghost_owner;
  std::size_t body_wall_begin = 0, body_wall_end = 0, body_ghost_begin = 0, body_ghost_end = 0;
  std::size_t body_rows_begin = 0, body_rows_end = 0;
  if (spec.body && (spec.body->wall >= spec.walls.size() || !spec.walls[spec.body->wall].closed)) {
    throw CaseError(spec.file, spec.body->label + ": a rigid body must be a closed wall");
  }
  for (std::size_t w = 0; w < spec.walls.size(); ++w) {
    const WallSpec& ws = spec.walls[w];
    const WallGeometry& g = geometry[w];
    const bool is_body = spec.body && spec.body->wall == w;
    if (is_body) {
      body_wall_begin = walls.size();
      body_ghost_begin = ghosts.size();
      body_rows_begin = scene.wall_rows.size();
    }
    const std::size_t first_wall = walls.size();
    NearestPoint nearest;  // over this wall's wall row, once it is laid
    for (int k = 0; k <= scene.ghost_layers; ++k) {
      const std::vector<Vec2> row = wall_row(spec, geometry, w, k);
      for (const auto& s : sample_polyline(row, ws.closed, dl)) {
        const Vec2 normal = surface_normal(g, s.position);
        if (k == 0) {
          walls.push_back({s.position, {}, normal});
          continue;
        }
        // The ghost copies the wall particle nearest to its foot on the wall row.
        const Vec2 foot = s.position - g.normals[s.segment] * (k * dl);
        ghosts.push_back({s.position, {}, normal});
        ghost_sources.push_back(static_cast<std::int32_t>(nearest.find(foot)));
        ghost_owner.push_back(w);
      }
      if (k == 0) {
        nearest = NearestPoint(walls, first_wall, dl);
        const auto row_segments = polyline_segments(row, ws.closed);
        scene.wall_rows.insert(scene.wall_rows.end(), row_segments.begin(), row_segments.end());
        for (std::size_t i = first_wall; i < walls.size(); ++i) boundary_owner.push_back(w);
      }
    }
    if (is_body) {
      body_wall_end = walls.size();
      body_ghost_end = ghosts.size();
      body_rows_end = scene.wall_rows.size();
    }
  }
  boundary_owner.insert(boundary_owner.end(), ghost_owner.begin(), ghost_owner.end());

  // ---- fluid: lattice points inside any fluid shape, away from wall surfaces, with a wall
  // below them (scene/FluidLattice.h)
  if (fluid_lattice_points(spec) > 2.0e8) {
    throw CaseError(spec.fluids[0].where,
                    "the fluid shapes' box holds more than 2e8 lattice points at spacing " +
                        std::to_string(dl) + " m; check the spacing and the shapes");
  }
  std::vector<ParticleSeed> fluid;
  double area = 0.0;
  for (const auto& f : spec.fluids) area += std::abs(signed_area(f.polygon));
  fluid.reserve(static_cast<std::size_t>(area / (dl * dl) * 1.05) + 16);  // no regrowth
  const FluidScan scan = scan_fluid_lattice(
      spec, geometry, 1,
      [&](Vec2 p, std::size_t region) {
        fluid.push_back({p, spec.fluids[region].velocity});
      },
      progress);
  scene.trimmed_fluid = scan.trimmed;
  scene.displaced_fluid = scan.displaced;

  Vec2 lo = fluid[0].position, hi = lo;
  auto grow = [&](Vec2 p) {
    lo = {std::min(lo.x, p.x), std::min(lo.y, p.y)};
    hi = {std::max(hi.x, p.x), std::max(hi.y, p.y)};
  };
  for (const auto& s : walls) grow(s.position);
  for (const auto& s : ghosts) grow(s.position);
  const double g = norm(spec.gravity);
  if (g > 0.0) {
    const Vec2 down = spec.gravity * (1.0 / g);
    double top = std::numeric_limits<double>::infinity(), bottom = -top;
    for (const auto& f : fluid) {
      grow(f.position);
      top = std::min(top, dot(f.position, down));
      bottom = std::max(bottom, dot(f.position, down));
    }
    scene.fluid_height = bottom - top + dl;
  } else {
    for (const auto& f : fluid) grow(f.position);
  }

  // ---- walls must not overlap one another
  {
    std::vector<double> bx, by;
    for (const auto* set : {&walls, &ghosts}) {
      for (const auto& s : *set) {
        bx.push_back(s.position.x);
        by.push_back(s.position.y);
      }
    }
    CellGrid grid;
    grid.configure(lo - Vec2{dl, dl}, hi + Vec2{dl, dl}, dl);
    grid.bin(bx.data(), by.data(), static_cast<std::int64_t>(bx.size()));
    const double min_gap = 0.5 * dl;
    for (std::size_t i = 0; i < bx.size(); ++i) {
      const int cx = grid.cell_x(bx[i]), cy = grid.cell_y(by[i]);
      for (int yy = std::max(cy - 1, 0); yy <= std::min(cy + 1, grid.ny() - 1); ++yy) {
        for (int xx = std::max(cx - 1, 0); xx <= std::min(cx + 1, grid.nx() - 1); ++xx) {
          for (auto* q = grid.cell_begin(xx, yy); q != grid.cell_end(xx, yy); ++q) {
            const std::size_t j = static_cast<std::size_t>(*q);
            if (j <= i || boundary_owner[i] == boundary_owner[j]) continue;
            if (std::hypot(bx[j] - bx[i], by[j] - by[i]) < min_gap) {
              const std::size_t a = boundary_owner[i], b = boundary_owner[j];
              throw CaseError(spec.walls[std::max(a, b)].where,
                              wall_label(spec, std::max(a, b)) + " overlaps " +
                                  wall_label(spec, std::min(a, b)) + " near " +
                                  point_text({bx[i], by[i]}) +
                                  "; join touching walls into one polyline");
            }
          }
        }
      }
    }
  }

  // ---- domain and sound speed
  if (spec.domain) {
    scene.domain_lo = spec.domain->first;
    scene.domain_hi = spec.domain->second;
    for (const auto& s : fluid) {
      const Vec2 p = s.position;
      if (p.x < scene.domain_lo.x || p.y < scene.domain_lo.y || p.x > scene.domain_hi.x ||
          p.y > scene.domain_hi.y) {
        throw CaseError(spec.file,
                        "[stability] domain does not contain the fluid at " + point_text(p));
      }
    }
  } else {
    // The particles' box, with room above it for splashes: jets running up a wall rise well
    // above the walls (the dam break's climbs the far wall to about 1.5 m, 2.5 times the
    // walls' height), so three times the box's height. Cells there cost no work.
    scene.domain_lo = lo - Vec2{re, re};
    scene.domain_hi = hi + Vec2{re, re + 3.0 * (hi.y - lo.y)};
  }
  if (spec.sound_speed) {
    scene.sound_speed = *spec.sound_speed;
  } else {
    if (g == 0.0) {
      throw CaseError(spec.file, "[physics] sound_speed is required when gravity is zero");
    }
    scene.sound_speed = spec.sound_speed_factor * std::sqrt(2.0 * g * scene.fluid_height);
  }
  scene.fluid_density_ratio.assign(fluid.size(), 1.0);
  if (spec.hydrostatic_start && g > 0.0) {
    if (spec.gravity.x != 0.0 || spec.gravity.y >= 0.0) {
      throw CaseError(spec.file,
                      "[particles] initial_state = \"hydrostatic\" needs gravity along -y; "
                      "use initial_state = \"lattice\"");
    }
    set_hydrostatic_state(fluid, spec, scene.sound_speed, scene.fluid_density_ratio);
  }
  scene.particles = ParticleSet(walls, ghosts, ghost_sources, fluid);
  if (spec.body) {
    BodyParticles b;
    const auto nw = static_cast<std::int64_t>(walls.size());
    b.walls = {static_cast<std::int64_t>(body_wall_begin),
               static_cast<std::int64_t>(body_wall_end)};
    b.ghosts = {nw + static_cast<std::int64_t>(body_ghost_begin),
                nw + static_cast<std::int64_t>(body_ghost_end)};
    b.rows = {body_rows_begin, body_rows_end};
    b.outline = spec.walls[spec.body->wall].points;
    b.area = std::abs(signed_area(b.outline));
    scene.body = std::move(b);
  }
  return scene;
}

}  // namespace wcmps
