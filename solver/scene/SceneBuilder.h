#pragma once
/// @file SceneBuilder.h
/// @brief Turns a CaseSpec into particles.
///
/// Walls: the case gives each wall's surface line. The wall row lies DL/2 behind the surface on
/// the solid side and the ghost rows follow at DL steps, each row parallel to the surface (so an
/// inclined wall is smooth, not a staircase), as many ghost rows as re needs (k DL < re). Each
/// ghost copies the pressure of the wall particle nearest to its foot on the wall row along the
/// wall normal (thesis section 2.6, Fig. 2-3).
///
/// Fluid: every point origin + (i + 1/2, j + 1/2) DL of the global lattice inside a fluid shape
/// (regions are united), except points inside a closed wall (a solid body displaces the fluid)
/// and points closer than wall_clearance x DL to a wall surface.

#include <cstdint>
#include <functional>
#include <optional>
#include <utility>
#include <vector>

#include "operators/LatticeConstants.h"
#include "particles/ParticleSet.h"
#include "scene/CaseSpec.h"
#include "scene/Geometry.h"

namespace wcmps {

/// The particles of the rigid body (CaseSpec::body): the wall and ghost rows of its wall.
struct BodyParticles {
  std::pair<std::int64_t, std::int64_t> walls, ghosts;  ///< index ranges in the ParticleSet
  std::pair<std::size_t, std::size_t> rows;  ///< its wall rows in Scene::wall_rows (at rest)
  std::vector<Vec2> outline;                 ///< its surface polygon at rest
  double area = 0.0;                         ///< of the outline (m^2)
};

struct Scene {
  ParticleSet particles;
  /// The rows of wall particles (not the surfaces): a fluid particle that crosses one has gone
  /// through a wall.
  std::vector<Segment> wall_rows;
  Vec2 domain_lo, domain_hi;  ///< particles outside stop the run
  LatticeConstants lattice;   ///< n0 and lambda of the initial lattice
  double sound_speed = 0.0;   ///< c0 (m/s), given or derived
  double fluid_height = 0.0;  ///< extent of the fluid along gravity (m), for the derived c0
  int ghost_layers = 0;
  std::int64_t trimmed_fluid = 0;    ///< lattice points dropped within the wall clearance
  std::int64_t displaced_fluid = 0;  ///< lattice points inside closed walls (solid bodies)
  std::optional<BodyParticles> body;
  /// n/n0 of each fluid particle at the start, in the order of their ids (fluid particle with id
  /// fluid_begin + k is entry k): s(h) of the hydrostatic state at its depth, or 1 on the lattice.
  /// Where the number density is evolved (continuity), it starts from this, not from the sum,
  /// whose kernels are incomplete at the surface and against the walls.
  std::vector<double> fluid_density_ratio;
};

/// Builds the scene; throws CaseError when the geometry makes no sense (fluid inside a wall or
/// outside every wall, walls overlapping each other, corners too sharp for the wall rows).
/// progress(fraction done), if given, is called now and then while the fluid is laid out (the
/// long part of building a big scene).
Scene build_scene(const CaseSpec& spec, const std::function<void(double)>& progress = {});

}  // namespace wcmps
