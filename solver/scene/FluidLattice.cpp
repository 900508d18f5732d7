#include "scene/FluidLattice.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/Error.h"

namespace wcmps {
namespace {

/// Does the ray from p along direction g hit the fluid side of a wall surface?
bool has_wall_along(const std::vector<WallGeometry>& walls, Vec2 p, Vec2 g, double reach) {
  const Vec2 q = p + g * reach;
  for (const auto& w : walls) {
    for (std::size_t s = 0; s < w.surface.size(); ++s) {
      const auto& seg = w.surface[s];
      if (dot(p - seg.a, w.normals[s]) < 0.0 && segments_intersect(p, q, seg.a, seg.b)) {
        return true;
      }
    }
  }
  return false;
}

/// Lattice index box [i0, i1] x [j0, j1] around a polygon, one point of margin.
struct IndexBox {
  long i0, i1, j0, j1;
  double points() const {
    return static_cast<double>(i1 - i0 + 1) * static_cast<double>(j1 - j0 + 1);
  }
};

IndexBox index_box(const std::vector<Vec2>& poly, const CaseSpec& spec) {
  Vec2 lo = poly[0], hi = poly[0];
  for (const Vec2 p : poly) {
    lo = {std::min(lo.x, p.x), std::min(lo.y, p.y)};
    hi = {std::max(hi.x, p.x), std::max(hi.y, p.y)};
  }
  const Vec2 o = spec.lattice_origin;
  const double dl = spec.dl;
  // Clamped to what a long holds: such a box is refused by its size before it is scanned.
  auto index = [](double v) { return static_cast<long>(std::clamp(v, -4.0e18, 4.0e18)); };
  return {index(std::floor((lo.x - o.x) / dl)) - 1, index(std::ceil((hi.x - o.x) / dl)) + 1,
          index(std::floor((lo.y - o.y) / dl)) - 1, index(std::ceil((hi.y - o.y) / dl)) + 1};
}

IndexBox union_box(const CaseSpec& spec) {
  IndexBox u = index_box(spec.fluids.front().polygon, spec);
  for (const auto& f : spec.fluids) {
    const IndexBox b = index_box(f.polygon, spec);
    u = {std::min(u.i0, b.i0), std::max(u.i1, b.i1), std::min(u.j0, b.j0), std::max(u.j1, b.j1)};
  }
  return u;
}

}  // namespace

int ghost_layer_count(const CaseSpec& spec) {
  return static_cast<int>(std::ceil(spec.re() / spec.dl - 1e-9)) - 1;
}

std::vector<WallGeometry> wall_geometries(const CaseSpec& spec) {
  std::vector<WallGeometry> out;
  const double thickness = (ghost_layer_count(spec) + 1) * spec.dl;
  for (const WallSpec& ws : spec.walls) {
    WallGeometry g;
    static_cast<WallSurface&>(g) = wall_surface(ws.points, ws.closed, ws.solid_on_right);
    g.thickness = thickness;
    out.push_back(std::move(g));
  }
  return out;
}

std::vector<Vec2> wall_row(const CaseSpec& spec, const std::vector<WallGeometry>& geometry,
                           std::size_t w, int k) {
  const WallSpec& ws = spec.walls[w];
  try {
    return offset_polyline(ws.points, ws.closed, geometry[w].normals, (k + 0.5) * spec.dl);
  } catch (const std::domain_error& e) {
    throw CaseError(ws.where, wall_label(spec, w) + ": " + e.what() + " (row " + std::to_string(k) +
                                  " at " + std::to_string(k + 0.5) + " DL behind the surface)");
  }
}

std::string point_text(Vec2 p) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "(%.6g, %.6g)", p.x, p.y);
  return buf;
}

std::string wall_label(const CaseSpec& spec, std::size_t w) {
  const std::string& l = spec.walls[w].label;
  return l.empty() ? "[[wall]] #" + std::to_string(w + 1) : l;
}

std::string fluid_label(const CaseSpec& spec, std::size_t f) {
  const std::string& l = spec.fluids[f].label;
  return l.empty() ? "[[fluid]] #" + std::to_string(f + 1) : l;
}

double fluid_lattice_points(const CaseSpec& spec) {
  return union_box(spec).points();
}

double fluid_lattice_span(const CaseSpec& spec) {
  const IndexBox u = union_box(spec);
  return std::max(static_cast<double>(u.i1 - u.i0 + 1), static_cast<double>(u.j1 - u.j0 + 1));
}

FluidScan scan_fluid_lattice(const CaseSpec& spec, const std::vector<WallGeometry>& geometry,
                             std::int64_t stride,
                             const std::function<void(Vec2, std::size_t)>& keep,
                             const std::function<void(double)>& progress) {
  FluidScan scan;
  scan.stride = stride;
  const double dl = spec.dl;
  const std::size_t nf = spec.fluids.size();
  std::vector<IndexBox> boxes;
  for (const auto& f : spec.fluids) boxes.push_back(index_box(f.polygon, spec));
  const IndexBox u = union_box(spec);

  // Containment: a ray along gravity from every kept point must meet a wall. Long enough to
  // leave the box of everything.
  Vec2 lo = spec.fluids[0].polygon[0], hi = lo;
  auto grow = [&](Vec2 p) {
    lo = {std::min(lo.x, p.x), std::min(lo.y, p.y)};
    hi = {std::max(hi.x, p.x), std::max(hi.y, p.y)};
  };
  for (const auto& f : spec.fluids) std::for_each(f.polygon.begin(), f.polygon.end(), grow);
  for (const auto& w : spec.walls) std::for_each(w.points.begin(), w.points.end(), grow);
  const double g = norm(spec.gravity);
  const Vec2 down = g > 0.0 ? spec.gravity * (1.0 / g) : Vec2{};
  const double reach = 2.0 * norm(hi - lo) + 2.0 * dl;

  // Points exactly DL/2 from a surface (the usual case) must stay: allow for rounding.
  const double clearance = spec.wall_clearance * dl * (1.0 - 1e-6);
  std::vector<std::int64_t> placed(nf, 0);
  const Vec2 o = spec.lattice_origin;
  const long columns = (u.i1 - u.i0) / stride + 1;
  for (long i = u.i0, column = 0; i <= u.i1; i += stride, ++column) {
    if (progress && column % 256 == 0) progress(static_cast<double>(column) / columns);
    for (long j = u.j0; j <= u.j1; j += stride) {
      const Vec2 p{o.x + (i + 0.5) * dl, o.y + (j + 0.5) * dl};
      std::size_t region = nf;
      for (std::size_t f = 0; f < nf; ++f) {
        const IndexBox& b = boxes[f];
        if (i < b.i0 || i > b.i1 || j < b.j0 || j > b.j1) continue;
        if (!polygon_contains(spec.fluids[f].polygon, p)) continue;
        ++placed[f];
        if (region == nf) region = f;
      }
      if (region == nf) continue;
      // A closed wall is a solid body: it displaces the fluid inside it.
      bool displaced = false;
      for (std::size_t w = 0; w < geometry.size() && !displaced; ++w) {
        displaced = geometry[w].closed && polygon_contains(spec.walls[w].points, p);
      }
      if (displaced) {
        ++scan.displaced;
        continue;
      }
      bool trimmed = false;
      for (std::size_t w = 0; w < geometry.size(); ++w) {
        const double sd = signed_distance(geometry[w], p);
        if (sd < 0.0 && -sd < clearance) trimmed = true;  // fluid side, too close
        if (sd >= 0.0 && sd < geometry[w].thickness) {
          throw CaseError(spec.fluids[region].where,
                          fluid_label(spec, region) + " overlaps " + wall_label(spec, w) +
                              " (line " + std::to_string(spec.walls[w].where.line) +
                              "): fluid at " + point_text(p) + " is inside the wall");
        }
        if (trimmed) break;
      }
      if (trimmed) {
        ++scan.trimmed;
        continue;
      }
      if (g > 0.0 && !has_wall_along(geometry, p, down, reach)) {
        throw CaseError(spec.fluids[region].where, fluid_label(spec, region) +
                                                       " lies outside every wall: fluid at " +
                                                       point_text(p) + " has no wall below it");
      }
      ++scan.kept;
      if (keep) keep(p, region);
    }
  }
  if (progress) progress(1.0);
  if (stride == 1) {
    for (std::size_t f = 0; f < nf; ++f) {
      if (placed[f] == 0) {
        throw CaseError(spec.fluids[f].where, fluid_label(spec, f) +
                                                  ": the shape holds no lattice point at spacing " +
                                                  std::to_string(dl) + " m");
      }
    }
    if (scan.kept == 0) {
      throw CaseError(spec.fluids[0].where, "no fluid particle is left after keeping " +
                                                std::to_string(spec.wall_clearance) +
                                                " DL away from the walls");
    }
  }
  return scan;
}

}  // namespace wcmps
