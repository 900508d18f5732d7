#pragma once
/// @file Geometry.h
/// @brief Plane geometry for building scenes: polygons, polylines, their offsets and sampling.

#include <cstdint>
#include <vector>

#include "core/Vec2.h"

namespace wcmps {

struct Segment {
  Vec2 a, b;
};

/// Even-odd point-in-polygon test.
bool polygon_contains(const std::vector<Vec2>& polygon, Vec2 p);

/// Area of a polygon, positive when its corners run counter-clockwise (shoelace formula).
double signed_area(const std::vector<Vec2>& polygon);

/// Distance from p to the segment [a, b].
double distance_to_segment(Vec2 p, Vec2 a, Vec2 b);

/// True when the segments [p0, p1] and [q0, q1] cross or touch.
bool segments_intersect(Vec2 p0, Vec2 p1, Vec2 q0, Vec2 q1);

/// Segments of a polyline (closing segment included when `closed`).
std::vector<Segment> polyline_segments(const std::vector<Vec2>& points, bool closed);

/// Unit normal of each segment pointing to the solid side.
std::vector<Vec2> solid_normals(const std::vector<Segment>& segments, bool solid_on_right);

/// A wall's surface: its segments and their unit normals into the solid.
struct WallSurface {
  std::vector<Segment> surface;
  std::vector<Vec2> normals;
  bool closed = false;
};

WallSurface wall_surface(const std::vector<Vec2>& points, bool closed, bool solid_on_right);

/// Signed distance of p to the wall surface: negative on the fluid side, positive in the
/// solid, using the normal of the nearest segment (the mean normal at a shared vertex).
double signed_distance(const WallSurface& w, Vec2 p);

/// Unit normal into the solid of the wall surface's segment nearest to p (the mean normal at a
/// shared vertex, as signed_distance).
Vec2 surface_normal(const WallSurface& w, Vec2 p);

/// The polyline moved by `distance` along the solid normals, with mitred joins (so that rows
/// at successive distances nest around corners). Throws std::domain_error if a segment would
/// turn back on itself (a corner too sharp for the offset).
std::vector<Vec2> offset_polyline(const std::vector<Vec2>& points, bool closed,
                                  const std::vector<Vec2>& normals, double distance);

/// A point laid along a polyline, with the segment it lies on.
struct PolylineSample {
  Vec2 position;
  int segment;
};

/// Points along the polyline, shared vertices once. A segment between two vertices shared with
/// neighbouring segments is divided into round(length / spacing) equal steps (at least one);
/// a segment with one free end (first or last of an open polyline) is laid exactly `spacing`
/// apart from its shared vertex, its free end added if more than half a spacing remains.
std::vector<PolylineSample> sample_polyline(const std::vector<Vec2>& points, bool closed,
                                            double spacing);

/// The number of points sample_polyline lays, without laying them.
std::int64_t count_polyline_samples(const std::vector<Vec2>& points, bool closed, double spacing);

}  // namespace wcmps
