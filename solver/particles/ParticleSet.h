#pragma once
/// @file ParticleSet.h
/// @brief Particles as arrays of fields (structure of arrays).
///
/// Layout, fixed at construction:
///   [0, wall_end)            wall particles (static)
///   [wall_end, fluid_begin)  ghost particles (static)
///   [fluid_begin, size)      fluid particles (reordered by cell now and then)
///
/// The fields that a time step advances are double buffered (`now` and `next`): a step reads
/// `now`, writes `next`, and only a step that passed the stability checks swaps them, so the last
/// good state is always at hand.

#include <cstdint>
#include <vector>

#include "core/Vec2.h"
#include "particles/ParticleKind.h"

namespace wcmps {

/// The evolving fields of every particle.
struct ParticleState {
  std::vector<double> x, y;  ///< position (m)
  std::vector<double> u, v;  ///< velocity (m/s)
  /// The particle shifting's displacement in the step that led to this state over that step's
  /// dt (m/s; 0 for boundary particles): the part of the particle's motion that u does not
  /// carry, which the evolved number density follows with [physics] shifting_in_continuity.
  /// Empty unless ParticleSet::track_shift() was called; resize() leaves them alone.
  std::vector<double> shift_u, shift_v;
  /// The surface pressure cap's memory of a strike (physics/SurfacePressureCap.h): the n where the
  /// strike found the particle, 0 when it is not struck. Empty unless
  /// ParticleSet::track_strikes() was called; resize() leaves it alone.
  std::vector<double> struck_n;
  /// The rest shape of gradient_renormalisation = "khayyer2011-strain"
  /// (physics/GradientRenormalisation_Khayyer2011.h): ((M_xx - M_yy) / 2, M_xy) averaged along
  /// the particle's path, NaN where it has none. Empty unless ParticleSet::track_rest_shape() was
  /// called; resize() leaves them alone.
  std::vector<double> rest_a, rest_b;
  std::vector<double> p;              ///< pressure (Pa)
  std::vector<double> n;              ///< number density at the predicted positions (-)
  std::vector<std::uint8_t> surface;  ///< 1 for free-surface particles

  void resize(std::size_t count);
  void swap(ParticleState& other) noexcept;
};

/// A particle to be placed by the scene builder.
struct ParticleSeed {
  Vec2 position;
  Vec2 velocity;
  Vec2 normal{};  ///< a boundary particle's wall normal, unit, into the solid (fluid: 0)
};

class ParticleSet {
 public:
  ParticleSet() = default;
  /// @param ghost_sources for each ghost, the index (into `walls`) of the wall particle whose
  ///        pressure it copies.
  ParticleSet(const std::vector<ParticleSeed>& walls, const std::vector<ParticleSeed>& ghosts,
              const std::vector<std::int32_t>& ghost_sources,
              const std::vector<ParticleSeed>& fluid);

  std::int64_t size() const { return static_cast<std::int64_t>(kind.size()); }
  std::int64_t wall_end() const { return wall_end_; }
  std::int64_t fluid_begin() const { return fluid_begin_; }
  std::int64_t fluid_count() const { return size() - fluid_begin_; }
  std::int64_t wall_count() const { return wall_end_; }
  std::int64_t ghost_count() const { return fluid_begin_ - wall_end_; }

  /// Wall particle whose pressure ghost i copies (i in [wall_end, fluid_begin)).
  std::int32_t ghost_source(std::int64_t i) const { return ghost_source_[i - wall_end_]; }

  /// Reorders the fluid particles: new fluid slot k takes old particle order[k], where order is
  /// a permutation of [fluid_begin, size). Uses `next` as scratch, so call it between steps.
  void reorder_fluid(const std::vector<std::int32_t>& order);
  /// Gives both states the shift's velocities (ParticleState::shift_u), zero.
  void track_shift();
  /// Gives both states the memory of strikes (ParticleState::struck_n), none.
  void track_strikes();
  /// Gives both states the rest shapes (ParticleState::rest_a), none (NaN).
  void track_rest_shape();

  ParticleState now;   ///< the state at the current time
  ParticleState next;  ///< scratch for the step in progress
  std::vector<ParticleKind> kind;
  std::vector<std::int32_t> id;  ///< stable id: walls, then ghosts, then fluid at t = 0
  /// The wall normal of each boundary particle [0, fluid_begin), unit, into the solid, from its
  /// seed: that of the wall surface nearest to it. Boundary particles keep their slots and the
  /// rigid body does not turn, so they are fixed.
  std::vector<double> normal_x, normal_y;

 private:
  std::int64_t wall_end_ = 0;
  std::int64_t fluid_begin_ = 0;
  std::vector<std::int32_t> ghost_source_;
  std::vector<std::int32_t> id_scratch_;
};

}  // namespace wcmps
