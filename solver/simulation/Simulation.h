#pragma once
/// @file Simulation.h
/// @brief The WC-MPS time step of the study (thesis section 2.7, Fig. 2-5) over a scene.

#include <cstdint>
#include <optional>
#include <vector>

#include "body/SlidingBody.h"

#include "core/StateArchive.h"
#include "neighbours/CellGrid.h"
#include "neighbours/NeighbourList.h"
#include "operators/DensitySums.h"
#include "operators/MpsOperators.h"
#include "physics/DensityRate_Randles1996.h"
#include "physics/EquationOfState.h"
#include "physics/FreeSurface.h"
#include "physics/FreeSurface_Marrone2010.h"
#include "physics/NegativePressure_Sun2018.h"
#include "physics/NumberDensity_Jandaghian2020.h"
#include "physics/ParticleCollision_Jandaghian2021.h"
#include "physics/ParticleShifting_Sun2017.h"
#include "physics/PredictionSums.h"
#include "physics/PredictionSumsAvx512.h"
#include "physics/PressureGradient.h"
#include "physics/SideWallFriction_Spalding1961.h"
#include "physics/SurfacePressureCap.h"
#include "physics/TimeStep.h"
#include "physics/Viscosity.h"
#include "physics/WallCollision.h"
#include "physics/WallDensity_Adami2012.h"
#include "physics/WallFriction_Spalding1961.h"
#include "physics/WallPressure.h"
#include "physics/WallSlip_Colagrossi2003.h"
#include "scene/CaseSpec.h"
#include "scene/SceneBuilder.h"
#include "simulation/PhaseTimer.h"

namespace wcmps {

class Simulation {
 public:
  Simulation(const CaseSpec& spec, Scene scene);

  /// Advances one time step, shortened if needed so that time() does not pass t_stop.
  /// Throws InstabilityError if the new state fails a stability check; the state then stays
  /// that of the last good step.
  void step(double t_stop);

  /// Settling before t = 0 (dynamic relaxation), if the case asks for it ([particles]
  /// settle_time): the scene runs for settle_time seconds with every fluid velocity damped by
  /// exp(-dt / settle_damping) after each step, at steps of its own Courant number if the case
  /// gives one (settle_courant: only where settling ends matters, not its path); then the
  /// velocities, the clock, the step count and the performance counters are set to zero. The water
  /// then starts in the discrete equilibrium of its particles and walls instead of the hydrostatic
  /// state of the lattice, which along an inclined bed is kilopascals off (docs/method.md). The
  /// body is held. settle_step() is one such step (the one that reaches settle_time ends settling),
  /// so that a run can checkpoint and stop during settling; settle() does all of it. Both throw
  /// InstabilityError like step().
  bool settling() const { return settling_; }
  void settle_step();
  void settle() {
    while (settling_) settle_step();
  }
  std::int64_t settle_steps() const { return settle_steps_; }

  /// The rigid body of the scene (the block), if it has one.
  const SlidingBody* body() const { return body_ ? &*body_ : nullptr; }
  /// Its state after every step since t = 0 (the first entry is t = 0).
  const std::vector<BodySample>& body_history() const { return body_history_; }

  double time() const { return time_; }
  std::int64_t steps() const { return steps_; }
  double last_dt() const { return last_dt_; }
  /// The step the time-step rule would take now.
  double next_dt() const { return active_rule().step(max_speed_); }
  double max_speed() const { return max_speed_; }
  double density() const { return density_; }

  const ParticleSet& particles() const { return scene_.particles; }
  const Scene& scene() const { return scene_; }
  const MpsOperators& operators() const { return ops_; }
  /// Cutoff of the neighbour lists: re plus the skin ([neighbours] skin x DL).
  double list_cutoff() const { return ops_.re() + skin_; }
  /// The run's time-step rule (after settling).
  const TimeStepRule& time_step_rule() const { return rule_; }
  /// The rule of the next step: the settling's while settling ([particles] settle_courant).
  const TimeStepRule& active_rule() const { return settling_ ? settle_rule_ : rule_; }
  const PhaseTimer& timer() const { return timer_; }
  /// The state a continued run needs, for checkpoints: every particle's fields, the
  /// positions the neighbour lists were built from (on loading, the lists are rebuilt from them
  /// pair for pair in the same order, so a continued run sums in the same order as one that
  /// was not stopped), the clock, the body and its history. load() takes a state saved by a
  /// simulation of the same scene; it throws CheckpointError if the counts differ. The
  /// performance counters (timer, pairs visited, list builds) start again from zero.
  void save(StateWriter& out) const;
  void load(StateReader& in);

  /// Neighbour entries visited by the operators so far (one per (i, j) per operator pass).
  std::int64_t pairs_visited() const { return pairs_visited_; }
  /// Fluid particle-steps whose velocity the wall collision model changed.
  std::int64_t wall_collisions() const { return wall_collisions_; }
  /// Times the neighbour lists were built.
  std::int64_t neighbour_builds() const { return builds_; }

 private:
  // The phases of one step, in order.
  void update_neighbours(double dt);  // lists at r^n, rebuilt when particles drift (2.3)
  void rebuild_neighbours();          // cell grid + lists, reordering now and then
  void move_body(double dt);          // the body to t^{n+1}: its law or its dynamics
  void predict(double dt);            // u* = u^n + dt (nu lap u^n + g), r* (Eq. 2.16)
  void compute_number_density();      // n* at r* (Eq. 2.17); walls
  void compute_pressure(double dt);   // free surface, EOS, walls, ghosts (Eq. 2.9, 2.10)
  void correct(double dt);            // u^{n+1} = u* - dt grad p / rho (Eq. 2.15, 2.19),
                                      // then wall collisions (Koshizuka 1998)
  void collide_particles(double dt);  // fluid pairs closer than l0 (Jandaghian et al. 2021)
  void move(double dt);               // r^{n+1} = r^n + dt u^{n+1} (Eq. 2.20), + shifting
  void check_stability(double dt);    // NaN, domain, density, walls, displacement
  void reorder_by_cell();             // cache locality, at rebuilds every sort_interval steps
  void compute_initial_pressure();    // n and p of the initial state, for its frame
  void find_fluid_near_walls();       // at rebuilds: near_wall_, near_body_, walls_in_reach_
  void find_close_fluid_pairs();      // at rebuilds: the particle collision's candidates
  /// The wall particles' phases of a step, for the wall particles listed: the summed n (and G
  /// for the surface scan), which of them are wet, their pressure and free-surface flag.
  void sum_walls(const std::vector<std::int32_t>& walls);
  void sum_one(std::int64_t i, bool with_gradient, const ParticleState& pos);  // n (and G) of i
  void find_wet_walls(const std::vector<std::int32_t>& walls);
  void compute_wall_pressure(const std::vector<std::int32_t>& walls);
  /// At rebuilds: the same for the walls out of every fluid particle's reach, in both states.
  void settle_walls_out_of_reach();
  void cap_surface_pressure(double);  // physics/SurfacePressureCap.h (dt)
  void correct_band_rate(double);     // physics/DensityRate_Randles1996.h (dt)
  void find_surface_band();           // the surface's band and its normals
  /// The band rate's partner in the pressure gradient (physics/DensityRate_Randles1996.h): the
  /// band's correctors q (L - I), which the gradient's pass gathers.
  void set_band_excess(const double* p_over_n2);
  /// The positions the free surface is found at: r^n where the number density is evolved (the
  /// prediction summed n and G there), r* where it is summed (Eq. 2.17).
  const ParticleState& surface_positions() const {
    return density_scheme_ == NumberDensityScheme::Continuity ? scene_.particles.now
                                                              : scene_.particles.next;
  }
  /// The summed number density of fluid particle i at those positions (t.n itself where
  /// summation gives n).
  double summed_n(std::int64_t i) const {
    return density_scheme_ == NumberDensityScheme::Continuity ? n_sum_[i]
                                                              : scene_.particles.next.n[i];
  }
  template <class Scheme>
  const double* gradient_input();  // p, or p/n^2 for the variational gradient
  template <class Scheme>
  BodyForce body_force(const Scheme& scheme, const double* input);  // reaction of pair forces
  /// What the pressure gradient takes besides its inputs: the tensile-instability switch and the
  /// particles it leaves out (the free-surface band), the renormalisation and the particles it
  /// leaves out (the band, and the fluid near a boundary), rho0 g.
  GradientOptions gradient_options() const {
    const DensityRate_Randles1996::Excess excess =
        band_rate_ && band_stamp_ != 0  // 0: no band has been found yet
            ? DensityRate_Randles1996::Excess{band_axx_.data(), band_axy_.data(), band_ayy_.data(),
                                              band_reach_.data(), band_stamp_}
            : DensityRate_Randles1996::Excess{};
    return {tensile_switch_,     renormalisation_, in_band_.data(), near_wall_.data(),
            gravity_ * density_, excess,           ShapeMemory{}};
  }
  bool in_body(std::int64_t j) const {
    const auto& b = body_->particles();
    return (j >= b.walls.first && j < b.walls.second) ||
           (j >= b.ghosts.first && j < b.ghosts.second);
  }
  double body_drift(double s) const { return body_ ? std::abs(s - body_built_s_) : 0.0; }
  SlipInputs slip() const {
    return free_slip_ ? SlipInputs{wall_tx_.data(), wall_ty_.data()} : SlipInputs{};
  }
  // The wall friction's sums of fluid particle i over the boundary particles of nb, at r^n, u^n.
  WallFriction_Spalding1961::Sums friction_sums(std::int64_t i, IdRange nb) const;

  Scene scene_;
  MpsOperators ops_;
  EquationOfState_TaitShakibaeiniaJin2010 eos_;
  FreeSurface_Koshizuka1996 surface_;
  Viscosity_Koshizuka1996Laplacian viscosity_;
  ArtificialViscosity_Monaghan1992 artificial_viscosity_;
  // The wall tangent of every particle, (0, 0) for fluid ones, read by the artificial
  // viscosity's free-slip walls (physics/WallSlip_Colagrossi2003.h) and the wall friction
  // (physics/WallFriction_Spalding1961.h); empty when neither is on.
  std::vector<double> wall_tx_, wall_ty_;
  bool free_slip_ = false;
  std::optional<WallFriction_Spalding1961> wall_friction_;
  std::optional<SideWallFriction_Spalding1961> side_walls_;  // the flume's side walls, if given
  PressureGradientScheme gradient_scheme_;
  WallPressureScheme wall_scheme_;
  std::optional<WallDensity_Adami2012> wall_density_;  // unset: boundary particles at n0
  PressureBound pressure_bound_;
  bool tensile_switch_;
  GradientRenormalisation renormalisation_;
  double strain_memory_;  // tau of "khayyer2011-strain" (s)
  NumberDensityScheme density_scheme_;
  NumberDensity_Jandaghian2020 continuity_;
  // The evolved n's rate and its partner in the pressure gradient in the surface band
  // (physics/DensityRate_Randles1996.h): on under the continuity scheme with density_rate =
  // "randles1996"; the correctors of the step's band particles (others are never read).
  bool band_rate_;
  DensityRate_Randles1996 band_rate_rule_;
  std::vector<DensityRate_Randles1996::Corrector> band_corrector_;
  // q (L - I) of this step's band particles, zero elsewhere (the gathered gradient reads every
  // particle's).
  std::vector<double> band_axx_, band_axy_, band_ayy_;
  DensitySumsSetup sums_setup_;
  DensityInputs density_inputs_;  // of the prediction's pass (its n set at each step)
  FreeSurfaceScheme surface_scheme_;
  FreeSurface_Marrone2010 scan_;
  ShiftingScheme shifting_scheme_;
  ParticleShifting_Sun2017 shifting_;
  bool shift_in_continuity_;     // the shift's velocity kept for the evolved n's rate
  bool surface_cap_;             // physics/SurfacePressureCap.h (evolved n only)
  SurfacePressureCap cap_rule_;  // its threshold of a struck particle
  WallCollisionScheme collision_scheme_;
  WallCollision_Koshizuka1998 collision_;
  // Fluid-fluid pairs closer than l0 (physics/ParticleCollision_Jandaghian2021.h): set when on,
  // with the velocity changes of the step's pass.
  std::optional<ParticleCollision_Jandaghian2021> particle_collision_;
  std::vector<double> collision_du_, collision_dv_;
  // Its candidates, found at each list build: fluid particle i's fluid neighbours within l0 +
  // skin then, close_ids_ from close_begin_[k] to close_begin_[k + 1] (k = i - fluid_begin). No
  // pair closer than l0 at r* is missing while no particle has moved skin/2 (the lists' rule).
  std::vector<std::int64_t> close_begin_;
  std::vector<std::int32_t> close_ids_;
  TimeStepRule rule_, settle_rule_;
  Vec2 gravity_;
  double density_;
  double skin_;
  double max_density_ratio_;
  int sort_interval_;
  double settle_time_, settle_damping_;

  CellGrid grid_;
  NeighbourList neighbours_;
  std::vector<IndexRange> list_owners_;    // particles that need neighbour lists
  std::vector<std::int32_t> order_;        // scratch for reorder_by_cell
  std::vector<double> x_built_, y_built_;  // positions at the last build of the lists
  std::vector<double> p_over_n2_;          // input of the variational gradient
  std::vector<std::uint8_t> near_wall_;    // 1: boundary particles in its list (check_stability)
  // Of the step in progress, sized only for the schemes that use them: the summed n (under the
  // continuity scheme), G = grad(n/n0) (free-surface scan, shifting), and the surface band (the
  // particles within re of a surface particle, listed in band_, for the tensile switch and the
  // shifting) with its normals.
  std::vector<double> n_sum_, grad_x_, grad_y_, band_x_, band_y_;
  PairRows pair_rows_;            // the AVX-512 pair passes' rows (operators/PairRows.h)
  bool prediction_rows_ = false;  // pair_rows_ hold the prediction's (until the correction)
  std::vector<std::int32_t> band_;
  std::vector<std::uint8_t> in_band_;
  // Under density_rate: band_stamp_ where the particle or one in its list is in this step's band
  // (set_band_excess), and the step's stamp (find_surface_band).
  std::vector<std::uint32_t> band_reach_;
  std::uint32_t band_stamp_ = 0;
  // What fills a fluid particle's scan region (surface scan): every fluid particle, and the wall
  // particles with water in front of them and their ghosts. An int32 per particle: the scan reads
  // it in its vectorised loop, where a byte would be loaded lane by lane (no byte gather).
  std::vector<std::int32_t> fills_;
  // Of each particle under the surface scan, kWitnesses slots: particles that filled its regions
  // at the last scan (FreeSurface_Marrone2010::is_surface). Hints only: any index is valid, so
  // neither a reorder nor a restart needs to keep them.
  std::vector<std::int32_t> scan_witness_;
  std::vector<double> cap_;  // surface particles' pressure caps (surface_pressure_cap)

  double time_ = 0.0;
  std::int64_t steps_ = 0;
  double last_dt_ = 0.0;
  double max_speed_ = 0.0;
  double drift_ = 0.0;                              // max |r^n - r_built| over fluid particles
  double star_drift_ = 0.0;                         // max |r* - r_built|, from the prediction
  double next_drift_ = 0.0, next_max_speed_ = 0.0;  // of the step in progress
  bool built_ = false;
  std::int64_t builds_ = 0;
  std::int64_t last_sort_step_ = 0;
  PhaseTimer timer_;
  std::int64_t pairs_visited_ = 0;
  std::int64_t wall_collisions_ = 0, next_collisions_ = 0;
  std::int64_t settle_steps_ = 0;
  bool settling_ = false;

  std::optional<SlidingBody> body_;
  SlideState body_next_;                 // of the step in progress
  BodyForce body_force_next_;            // of the step in progress
  double body_built_s_ = 0.0;            // its S at the last build of the lists
  std::vector<std::int32_t> near_body_;  // fluid particles with body particles in their lists
  // Wall particles with a fluid particle in their lists, and the body's: the step computes
  // these. The others (walls_out_of_reach_) are in no fluid particle's list, so no fluid
  // particle reads them until the next build, and a fixed wall particle's sums over boundary
  // particles alone do not change: settle_walls_out_of_reach() sets them once per build.
  std::vector<std::int32_t> walls_in_reach_, walls_out_of_reach_;
  std::int64_t pairs_in_reach_ = 0;      // the length of their lists
  std::vector<std::int32_t> body_part_;  // scratch: the body particles in one list
  std::vector<BodySample> body_history_;
};

}  // namespace wcmps
