#include "scene/Geometry.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace wcmps {

double signed_area(const std::vector<Vec2>& p) {
  double a = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i) a += cross(p[i], p[(i + 1) % p.size()]);
  return 0.5 * a;
}

bool polygon_contains(const std::vector<Vec2>& poly, Vec2 p) {
  bool inside = false;
  for (std::size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++) {
    const Vec2 a = poly[i], b = poly[j];
    if ((a.y > p.y) != (b.y > p.y) && p.x < (b.x - a.x) * (p.y - a.y) / (b.y - a.y) + a.x) {
      inside = !inside;
    }
  }
  return inside;
}

double distance_to_segment(Vec2 p, Vec2 a, Vec2 b) {
  const Vec2 ab = b - a;
  const double l2 = dot(ab, ab);
  const double t = l2 > 0.0 ? std::clamp(dot(p - a, ab) / l2, 0.0, 1.0) : 0.0;
  return norm(p - (a + t * ab));
}

bool segments_intersect(Vec2 p0, Vec2 p1, Vec2 q0, Vec2 q1) {
  const double d1 = cross(q1 - q0, p0 - q0), d2 = cross(q1 - q0, p1 - q0);
  const double d3 = cross(p1 - p0, q0 - p0), d4 = cross(p1 - p0, q1 - p0);
  if (((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0))) {
    return true;
  }
  auto on = [](Vec2 a, Vec2 b, Vec2 c, double d) {  // c on [a, b] given collinear
    return d == 0.0 && std::min(a.x, b.x) <= c.x && c.x <= std::max(a.x, b.x) &&
           std::min(a.y, b.y) <= c.y && c.y <= std::max(a.y, b.y);
  };
  return on(q0, q1, p0, d1) || on(q0, q1, p1, d2) || on(p0, p1, q0, d3) || on(p0, p1, q1, d4);
}

std::vector<Segment> polyline_segments(const std::vector<Vec2>& pts, bool closed) {
  std::vector<Segment> s;
  for (std::size_t i = 0; i + 1 < pts.size(); ++i) s.push_back({pts[i], pts[i + 1]});
  if (closed) s.push_back({pts.back(), pts.front()});
  return s;
}

WallSurface wall_surface(const std::vector<Vec2>& points, bool closed, bool solid_on_right) {
  WallSurface w;
  w.surface = polyline_segments(points, closed);
  w.normals = solid_normals(w.surface, solid_on_right);
  w.closed = closed;
  return w;
}

namespace {

/// The nearest point of a wall surface to p: its distance and the normal there into the solid
/// (the mean of both normals at a vertex shared with a neighbouring segment; not unit).
struct SurfaceFoot {
  double distance = std::numeric_limits<double>::infinity();
  Vec2 foot;
  Vec2 normal;
};

SurfaceFoot nearest_foot(const WallSurface& w, Vec2 p) {
  SurfaceFoot best;
  const std::size_t ns = w.surface.size();
  for (std::size_t s = 0; s < ns; ++s) {
    const Vec2 a = w.surface[s].a, b = w.surface[s].b;
    const double d = distance_to_segment(p, a, b);
    if (d < best.distance - 1e-15) {
      const Vec2 ab = b - a;
      const double t = dot(p - a, ab) / dot(ab, ab);
      Vec2 n = w.normals[s];
      // At a vertex shared with a neighbouring segment, use the mean of both normals.
      if (t <= 0.0 && (s > 0 || w.closed)) n = n + w.normals[(s + ns - 1) % ns];
      if (t >= 1.0 && (s + 1 < ns || w.closed)) n = n + w.normals[(s + 1) % ns];
      best = {d, a + std::clamp(t, 0.0, 1.0) * ab, n};
    }
  }
  return best;
}

}  // namespace

double signed_distance(const WallSurface& w, Vec2 p) {
  const SurfaceFoot f = nearest_foot(w, p);
  return dot(p - f.foot, f.normal) > 0.0 ? f.distance : -f.distance;
}

Vec2 surface_normal(const WallSurface& w, Vec2 p) {
  const Vec2 n = nearest_foot(w, p).normal;
  return n * (1.0 / norm(n));
}

std::vector<Vec2> solid_normals(const std::vector<Segment>& segments, bool solid_on_right) {
  std::vector<Vec2> n;
  for (const auto& s : segments) {
    const Vec2 d = (s.b - s.a) * (1.0 / norm(s.b - s.a));
    n.push_back(solid_on_right ? right_normal(d) : -right_normal(d));
  }
  return n;
}

std::vector<Vec2> offset_polyline(const std::vector<Vec2>& pts, bool closed,
                                  const std::vector<Vec2>& normals, double distance) {
  const std::size_t np = pts.size();
  const std::size_t ns = normals.size();
  std::vector<Vec2> out(np);
  for (std::size_t i = 0; i < np; ++i) {
    const bool has_prev = closed || i > 0;
    const bool has_next = closed || i + 1 < np;
    const Vec2 n_prev = has_prev ? normals[(i + ns - 1) % ns] : normals[i];
    const Vec2 n_next = has_next ? normals[i % ns] : n_prev;
    // Mitre: the point at `distance` from both offset lines.
    const double c = 1.0 + dot(n_prev, n_next);
    if (c < 1e-6) throw std::domain_error("wall turns back on itself at a vertex");
    out[i] = pts[i] + (n_prev + n_next) * (distance / c);
  }
  for (std::size_t s = 0; s < ns; ++s) {
    const Vec2 a0 = pts[s], b0 = pts[(s + 1) % np];
    const Vec2 a1 = out[s], b1 = out[(s + 1) % np];
    if (dot(b1 - a1, b0 - a0) <= 0.0) {
      throw std::domain_error("segment " + std::to_string(s + 1) +
                              " is too short for the wall rows at its corners");
    }
  }
  return out;
}

namespace {

/// How sample_polyline lays the points of one segment of a polyline.
struct SegmentSampling {
  bool from_corner;    ///< one free end: `steps` + 1 points `spacing` apart from the corner
  bool free_at_end;    ///< (from_corner) the free end is b, the corner a
  std::int64_t steps;  ///< equal steps (both ends corners or both free), or whole spacings
  bool extra_end;      ///< (from_corner) the free end itself is added
  bool skip_start, skip_end;
  std::int64_t count() const {
    return steps + 1 + (from_corner && extra_end ? 1 : 0) - (skip_start ? 1 : 0) -
           (skip_end ? 1 : 0);
  }
};

SegmentSampling plan_segment(double length, std::size_t s, std::size_t ns, bool closed,
                             double spacing) {
  SegmentSampling p{};
  const bool free_start = !closed && s == 0;
  const bool free_end = !closed && s + 1 == ns;
  p.skip_start = s > 0;                // the shared vertex was placed already...
  p.skip_end = closed && s + 1 == ns;  // ...or is the first point of the line
  p.from_corner = free_start != free_end;
  p.free_at_end = free_end;
  if (p.from_corner) {
    // One free end: exactly `spacing` apart from the corner, so rows stay in line with the
    // lattice; the free end itself only if more than half a spacing remains.
    p.steps = static_cast<std::int64_t>(std::floor(length / spacing + 1e-9));
    p.extra_end = length - p.steps * spacing > 0.5 * spacing * (1.0 + 1e-9);
  } else {
    // Both ends corners (or both free): round(length / spacing) equal steps.
    p.steps = std::max<std::int64_t>(1, std::llround(length / spacing));
  }
  return p;
}

}  // namespace

std::vector<PolylineSample> sample_polyline(const std::vector<Vec2>& pts, bool closed,
                                            double spacing) {
  std::vector<PolylineSample> out;
  const auto segs = polyline_segments(pts, closed);
  const std::size_t ns = segs.size();
  for (std::size_t s = 0; s < ns; ++s) {
    const Vec2 a = segs[s].a, b = segs[s].b;
    const double length = norm(b - a);
    const Vec2 dir = (b - a) * (1.0 / length);
    const SegmentSampling plan = plan_segment(length, s, ns, closed, spacing);
    std::vector<Vec2> points;
    if (plan.from_corner) {
      const Vec2 corner = plan.free_at_end ? a : b;
      const Vec2 out_dir = plan.free_at_end ? dir : -dir;
      for (std::int64_t k = 0; k <= plan.steps; ++k) {
        points.push_back(corner + out_dir * (static_cast<double>(k) * spacing));
      }
      if (plan.extra_end) points.push_back(plan.free_at_end ? b : a);
      if (!plan.free_at_end) std::reverse(points.begin(), points.end());
    } else {
      for (std::int64_t k = 0; k <= plan.steps; ++k) {
        points.push_back(a + (b - a) * (static_cast<double>(k) / static_cast<double>(plan.steps)));
      }
    }
    for (std::size_t k = 0; k < points.size(); ++k) {
      if ((k == 0 && plan.skip_start) || (k + 1 == points.size() && plan.skip_end)) continue;
      out.push_back({points[k], static_cast<int>(s)});
    }
  }
  return out;
}

std::int64_t count_polyline_samples(const std::vector<Vec2>& pts, bool closed, double spacing) {
  const auto segs = polyline_segments(pts, closed);
  std::int64_t count = 0;
  for (std::size_t s = 0; s < segs.size(); ++s) {
    count += plan_segment(norm(segs[s].b - segs[s].a), s, segs.size(), closed, spacing).count();
  }
  return count;
}

}  // namespace wcmps
