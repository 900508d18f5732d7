#pragma once
/// @file FluidLattice.h
/// @brief What the scene builder (SceneBuilder.h) and the size estimate (SizeEstimate.h) share:
/// the walls as surfaces with their rows, and the scan of the fluid's lattice points that
/// decides which become particles. The estimate runs the same scan on every s-th point, so its
/// count and its checks are the builder's own, sampled.

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "scene/CaseSpec.h"
#include "scene/Geometry.h"

namespace wcmps {

struct WallGeometry : WallSurface {
  double thickness = 0.0;  ///< from the surface to the last ghost row + DL/2
};

/// Ghost rows k = 1..K behind each wall row, with k DL < re: every wall particle sees a full
/// kernel behind it.
int ghost_layer_count(const CaseSpec& spec);

/// The surfaces of the case's walls, in the order of spec.walls.
std::vector<WallGeometry> wall_geometries(const CaseSpec& spec);

/// Row k of wall w (0: the wall row, 1..K: the ghost rows): its polyline at (k + 1/2) DL
/// behind the surface. Throws CaseError naming the wall when a corner is too sharp for it.
std::vector<Vec2> wall_row(const CaseSpec& spec, const std::vector<WallGeometry>& geometry,
                           std::size_t w, int k);

/// How messages name a point: "(x, y)" to six digits.
std::string point_text(Vec2 p);

/// How messages name a wall or a fluid: as the case file does, or by its place in the spec.
std::string wall_label(const CaseSpec& spec, std::size_t w);
std::string fluid_label(const CaseSpec& spec, std::size_t f);

/// What a scan of the fluid's lattice found, in scanned points (multiply by stride^2 for the
/// whole lattice).
struct FluidScan {
  std::int64_t stride = 1;
  std::int64_t kept = 0;       ///< points that become fluid particles
  std::int64_t trimmed = 0;    ///< dropped within the wall clearance
  std::int64_t displaced = 0;  ///< inside a closed wall (a solid body)
};

/// Scans the lattice points origin + (i + 1/2, j + 1/2) DL of the fluid shapes' bounding box,
/// i and j multiples of `stride` from its corner, in the order i, then j (the particles' order),
/// and calls keep(p, region) for each that becomes a fluid particle: inside a fluid shape (the
/// first that holds it gives its region), not inside a closed wall, not within the wall
/// clearance. Throws CaseError naming the shape for fluid inside a wall, fluid with no wall
/// below it (along gravity), and (stride 1 only) a shape that holds no lattice point or no fluid
/// left after the clearance. progress(fraction) is called now and then, if given.
FluidScan scan_fluid_lattice(const CaseSpec& spec, const std::vector<WallGeometry>& geometry,
                             std::int64_t stride,
                             const std::function<void(Vec2, std::size_t)>& keep,
                             const std::function<void(double)>& progress = {});

/// Lattice points of the fluid shapes' bounding box (a double: it may exceed any integer).
double fluid_lattice_points(const CaseSpec& spec);

/// Lattice points along the longer side of that box.
double fluid_lattice_span(const CaseSpec& spec);

}  // namespace wcmps
