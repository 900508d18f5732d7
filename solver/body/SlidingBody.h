#pragma once
/// @file SlidingBody.h
/// @brief A rigid body of boundary particles (the wall and ghost rows inside it) that slides
/// along a straight bed or is held: its motion, prescribed or free, and the fluid's force on it.
///
/// The body translates by a distance S(t) along the downslope direction t (it slides on a plane
/// bed: no rotation). Its particles count in the fluid's number density, carry pressure like
/// wall particles (WallPressure_Adami2012 with the body's acceleration, g - a) and lend their
/// velocity U t to the viscous term and the wall collisions: the water sees a moving no-slip
/// wall.
///
/// The fluid's force F on the body is the reaction of the forces its particles exert on the
/// fluid particles, pair by pair, with the same operators as the fluid's own step (pressure
/// gradient and viscous terms), so momentum passes between water and body without loss.
///
/// Free motion, per unit width, with mass M = rho_b A (A the outline's area), the bed's outward
/// normal n and Coulomb friction mu:
///
///     N = max(0, -(M g + F) . n)                 (what the bed carries)
///     M dU/dt = (M g + F) . t - mu N sign(U)     (static friction = kinetic at U = 0)
///
/// integrated like the fluid (symplectic Euler): U^{n+1} = U^n + dt a(F^n),
/// S^{n+1} = S^n + dt U^{n+1}. Friction stops a slide within a step but never reverses it.

#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

#include "core/StateArchive.h"
#include "core/Vec2.h"
#include "particles/ParticleSet.h"
#include "physics/SlideMotion.h"
#include "scene/CaseSpec.h"
#include "scene/SceneBuilder.h"

namespace wcmps {

/// The fluid's force on the body, per unit width (N/m).
struct BodyForce {
  Vec2 pressure;
  Vec2 viscous;
  Vec2 total() const { return pressure + viscous; }
};

/// One line of block.csv.
struct BodySample {
  double time = 0.0;
  SlideState state;
  BodyForce force;
  double normal = 0.0;  ///< N, the force the bed carries (N/m)
  /// The force along the bed beyond gravity and the fluid that the motion needs:
  /// M a - (M g + F) . t. Free motion: minus the friction. Prescribed: what a guide would exert
  /// (negative = holding back); -along/N is the friction coefficient the motion implies.
  double along = 0.0;
};

class SlidingBody {
 public:
  SlidingBody(const BodySpec& spec, const BodyParticles& particles, Vec2 gravity,
              const ParticleState& initial);

  const BodyParticles& particles() const { return particles_; }
  BodyMotionType motion() const { return spec_.motion.type; }
  double mass() const { return mass_; }
  Vec2 downslope() const { return spec_.downslope; }
  const SlideState& state() const { return state_; }
  const BodyForce& force() const { return force_; }

  /// The state at time + dt from the committed one at `time`: the prescribed law, the free
  /// dynamics under the last committed force, or the current state if held.
  SlideState advance(double time, double dt) const;
  /// Puts its particles at distance s.s with velocity s.u along the bed (in `st`).
  void place(const SlideState& s, ParticleState& st) const;
  /// Takes the state of a step that passed its checks, with the force computed in it.
  void commit(const SlideState& s, const BodyForce& f);
  /// Held (during settling before t = 0): advance() keeps it where it is.
  void hold(bool held) { held_ = held; }
  /// Back to S = 0 at rest (the end of settling), with the last force kept.
  void reset_motion() { state_ = {}; }

  /// Acceleration of its particles (m/s^2), for the wall pressure.
  Vec2 acceleration() const { return spec_.downslope * state_.a; }
  /// Its outline at distance s.
  std::vector<Vec2> outline(double s) const;
  /// Displacement at distance s.
  Vec2 offset(double s) const { return spec_.downslope * s; }

  /// Normal force and along-bed constraint of a state under a force (BodySample).
  std::pair<double, double> support(const SlideState& s, const BodyForce& f) const;
  BodySample sample(double time) const;

  /// Its state (S, U, A, the last force, held or not), for checkpoints.
  void save(StateWriter& out) const;
  void load(StateReader& in);

 private:
  double free_acceleration(double u, const BodyForce& f) const;

  BodySpec spec_;
  BodyParticles particles_;
  Vec2 gravity_;
  double mass_;
  std::optional<SplineSlide> table_;
  std::vector<double> x0_, y0_;  // particle positions at S = 0: walls, then ghosts
  SlideState state_;
  BodyForce force_;
  bool held_ = false;
};

/// A body's history (block.csv) in a checkpoint: a field per column.
void save_history(StateWriter& out, const std::vector<BodySample>& history);
std::vector<BodySample> load_history(StateReader& in);

}  // namespace wcmps
