#include "simulation/Simulation.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/Error.h"
#include "core/Parallel.h"

namespace wcmps {
namespace {

constexpr int kDimension = 2;

constexpr std::size_t kWitnesses = FreeSurface_Marrone2010::kWitnesses;

inline double sq(double v) {
  return v * v;
}

/// The square root of a maximum of squares: exactly the maximum of their square roots (the
/// square root is correctly rounded and never decreasing), with one square root in place of one
/// per particle, which sat on the particle loops' critical path (perf, case I at DL 2 mm). 0
/// for no particle (-infinity).
double root_of_max(double max_of_squares) {
  return max_of_squares > 0.0 ? std::sqrt(max_of_squares) : 0.0;
}

/// Why a particle fails the stability checks (0 = it does not).
enum Failure : std::uint8_t {
  kOk = 0,
  kNotFinite,
  kLeftDomain,
  kDensityBlowUp,
  kCrossedWall,
  kMovedTooFar,
};

const char* failure_text(std::uint8_t f) {
  switch (f) {
    case kNotFinite:
      return "position, velocity or pressure is not finite";
    case kLeftDomain:
      return "left the domain";
    case kDensityBlowUp:
      return "number density exceeds max_density_ratio x n0";
    case kCrossedWall:
      return "crossed a wall";
    case kMovedTooFar:
      return "moved further in one step than the neighbour skin allows (time step too large)";
    default:
      return "ok";
  }
}

}  // namespace

Simulation::Simulation(const CaseSpec& spec, Scene scene)
    : scene_(std::move(scene)),
      ops_(spec.re(), kDimension, scene_.lattice.n0, scene_.lattice.lambda,
           scene_.lattice.gradient_correction),
      eos_{spec.density, scene_.sound_speed, spec.eos_exponent, scene_.lattice.n0},
      surface_{spec.surface_threshold, scene_.lattice.n0},
      viscosity_{spec.kinematic_viscosity},
      artificial_viscosity_{spec.artificial_viscosity, scene_.sound_speed},
      gradient_scheme_(spec.pressure_gradient),
      wall_scheme_(spec.wall_pressure),
      wall_density_(spec.wall_density == WallDensityScheme::Adami2012
                        ? std::optional<WallDensity_Adami2012>(WallDensity_Adami2012{eos_})
                        : std::nullopt),
      pressure_bound_(PressureBound::make(spec.negative_pressure, spec.pressure_floor)),
      tensile_switch_(spec.negative_pressure == NegativePressure::Sun2018Switch),
      renormalisation_(renormalisation_in_effect(spec)),
      strain_memory_(spec.strain_memory),
      density_scheme_(spec.number_density),
      continuity_(NumberDensity_Jandaghian2020::make(spec.density_diffusion, spec.re(),
                                                     scene_.sound_speed, scene_.lattice.lambda,
                                                     scene_.lattice.n0)),
      band_rate_(spec.density_rate == DensityRateScheme::Randles1996 &&
                 spec.number_density == NumberDensityScheme::Continuity &&
                 spec.pressure_gradient == PressureGradientScheme::Suzuki2007),
      band_rate_rule_{scene_.lattice.n0 / scene_.lattice.gradient_correction, scene_.lattice.n0,
                      std::sqrt(norm(spec.gravity) / spec.dl)},
      sums_setup_{
          Kernel(spec.re()), 1.0 / scene_.lattice.concentration_sum,
          spec.shifting != ShiftingScheme::None ? ParticleShifting_Sun2017::kClumpingR : 0.0,
          1.0 / Kernel(spec.re())(spec.dl)},
      density_inputs_{
          nullptr,
          scene_.particles.fluid_begin(),
          spec.density_diffusion_scheme == DensityDiffusionScheme::Fourtakas2019
              ? spec.gravity * (scene_.lattice.n0 / (scene_.sound_speed * scene_.sound_speed))
              : Vec2{},
          sums_setup_.inv_f0,
          sums_setup_.clumping_r,
          sums_setup_.inv_w_dl,
          2.0 * scene_.lattice.concentration_response * scene_.lattice.concentration_sum /
              (2.0 * scene_.lattice.concentration_gradient_sum * scene_.lattice.n0),
          spec.gravity * (scene_.lattice.n0 / (scene_.sound_speed * scene_.sound_speed))},
      surface_scheme_(spec.free_surface),
      scan_{spec.surface_threshold, scene_.lattice.n0, 0.5 * spec.re()},
      shifting_scheme_(spec.shifting),
      shifting_{0.5 * spec.re()},
      shift_in_continuity_(spec.shifting_in_continuity && spec.shifting != ShiftingScheme::None &&
                           spec.number_density == NumberDensityScheme::Continuity),
      surface_cap_(spec.surface_pressure_cap &&
                   spec.number_density == NumberDensityScheme::Continuity),
      cap_rule_(SurfacePressureCap::make(norm(spec.gravity), spec.dl)),
      collision_scheme_(spec.wall_collision),
      collision_{spec.collision_distance * spec.dl, spec.collision_restitution},
      gravity_(spec.gravity),
      density_(spec.density),
      skin_(spec.neighbour_skin * spec.dl),
      max_density_ratio_(spec.max_density_ratio),
      sort_interval_(spec.sort_interval),
      settle_time_(spec.settle_time),
      settle_damping_(spec.settle_damping),
      settling_(spec.settle_time > 0.0) {
  rule_ = wcmps::time_step_rule(spec, scene_.sound_speed);
  settle_rule_ = wcmps::settle_step_rule(spec, scene_.sound_speed);
  ParticleSet& ps = scene_.particles;
  grid_.configure(scene_.domain_lo, scene_.domain_hi, list_cutoff());
  list_owners_ = {{0, ps.wall_end()}, {ps.fluid_begin(), ps.size()}};
  order_.resize(ps.fluid_count());
  x_built_.resize(ps.size());
  y_built_.resize(ps.size());
  p_over_n2_.resize(ps.size());
  near_wall_.resize(ps.size());
  if (density_scheme_ == NumberDensityScheme::Continuity) n_sum_.resize(ps.size());
  // G: read by the surface scan and the shifting, and written by the prediction's pass whenever
  // n is evolved (it sums G with the rest, whoever reads it).
  if (surface_scheme_ == FreeSurfaceScheme::Marrone2010 ||
      shifting_scheme_ != ShiftingScheme::None ||
      density_scheme_ == NumberDensityScheme::Continuity) {
    grad_x_.resize(ps.size());
    grad_y_.resize(ps.size());
  }
  if (shift_in_continuity_) ps.track_shift();
  if (spec.particle_collision == ParticleCollisionScheme::Jandaghian2021) {
    // p_max: the hydrostatic pressure at the foot of the water
    // (ParticleCollision_Jandaghian2021.h).
    particle_collision_ =
        ParticleCollision_Jandaghian2021{spec.particle_collision_distance * spec.dl,
                                         spec.particle_collision_lambda,
                                         spec.particle_collision_min_pressure,
                                         spec.density * norm(spec.gravity) * scene_.fluid_height,
                                         spec.density,
                                         spec.particle_collision_restitution};
    collision_du_.resize(ps.size());
    collision_dv_.resize(ps.size());
  }
  if (surface_cap_) ps.track_strikes();
  if (renormalisation_ == GradientRenormalisation::Strain) ps.track_rest_shape();
  free_slip_ = spec.artificial_viscosity_walls == ArtificialViscosityWalls::FreeSlip &&
               artificial_viscosity_.alpha > 0.0;
  if (spec.wall_friction == WallFrictionScheme::Spalding1961) {
    wall_friction_ = WallFriction_Spalding1961::make(spec.kinematic_viscosity, spec.dl, spec.re(),
                                                     scene_.ghost_layers);
  }
  if (spec.side_wall_friction == SideWallFrictionScheme::Spalding1961) {
    side_walls_ = SideWallFriction_Spalding1961::make(spec.kinematic_viscosity, spec.flume_width);
  }
  if (free_slip_ || wall_friction_) {
    // The tangent is the normal turned by 90 degrees; its sign does not matter.
    wall_tx_.assign(static_cast<std::size_t>(ps.size()), 0.0);
    wall_ty_.assign(static_cast<std::size_t>(ps.size()), 0.0);
    for (std::int64_t j = 0; j < ps.fluid_begin(); ++j) {
      wall_tx_[j] = -ps.normal_y[j];
      wall_ty_[j] = ps.normal_x[j];
    }
  }
  if (surface_scheme_ == FreeSurfaceScheme::Marrone2010) {
    fills_.assign(static_cast<std::size_t>(ps.size()), 0);
    std::fill(fills_.begin() + ps.fluid_begin(), fills_.end(), 1);
    scan_witness_.assign(static_cast<std::size_t>(ps.size()) * kWitnesses, 0);
  }
  if (shifting_scheme_ != ShiftingScheme::None || tensile_switch_ ||
      renormalisation_ != GradientRenormalisation::None || band_rate_) {
    band_x_.resize(ps.size());
    band_y_.resize(ps.size());
    in_band_.resize(ps.size());
    band_.reserve(static_cast<std::size_t>(ps.fluid_count()));
  }
  if (band_rate_) {
    band_corrector_.resize(ps.size());
    band_axx_.resize(ps.size());
    band_axy_.resize(ps.size());
    band_ayy_.resize(ps.size());
    band_reach_.resize(ps.size());
  }
  max_speed_ = root_of_max(parallel_max(ps.fluid_begin(), ps.size(), [&](std::int64_t i) {
    return sq(ps.now.u[i]) + sq(ps.now.v[i]);
  }));
  if (scene_.body && spec.body) body_.emplace(*spec.body, *scene_.body, gravity_, ps.now);
  compute_initial_pressure();
  if (body_) {
    // A sample per step: reserve for twice the steps the run takes at the largest time step
    // (the step at rest), so that the time loop does not grow the vector in the usual case.
    body_history_.reserve(2 * static_cast<std::size_t>(std::ceil(spec.end_time / rule_.step(0.0))) +
                          1);
    body_history_ = {body_->sample(0.0)};
  }
}

void Simulation::compute_initial_pressure() {
  // The pressure phases work on `next`: give it the initial state (the first build of the
  // lists has reordered the fluid particles of `now`).
  ParticleSet& ps = scene_.particles;
  rebuild_neighbours();
  if (density_scheme_ == NumberDensityScheme::Continuity) {
    // The evolved n starts from the state the scene was built in, not from the sum (whose
    // kernels are incomplete at the surface and against the walls).
    const double n0 = ops_.n0();
    for (std::int64_t i = ps.fluid_begin(); i < ps.size(); ++i) {
      ps.now.n[i] = n0 * scene_.fluid_density_ratio[ps.id[i] - ps.fluid_begin()];
    }
  }
  ps.next = ps.now;
  if (density_scheme_ == NumberDensityScheme::Continuity) predict(0.0);  // n, G of the start
  compute_number_density();
  compute_pressure(0.0);
  ps.now.p = ps.next.p;
  ps.now.n = ps.next.n;
  ps.now.surface = ps.next.surface;
  if (body_) {
    with_pressure_gradient(gradient_scheme_, gradient_options(), [&](auto scheme) {
      using Scheme = decltype(scheme);
      body_->commit(body_->state(), body_force(scheme, gradient_input<Scheme>()));
    });
  }
  pairs_visited_ = 0;
}

void Simulation::find_fluid_near_walls() {
  const ParticleSet& ps = scene_.particles;
  parallel_for(ps.fluid_begin(), ps.size(), [&](std::int64_t i) {
    const IdRange nb = neighbours_.of(i);
    near_wall_[i] =
        std::any_of(nb.begin(), nb.end(), [&](std::int32_t j) { return j < ps.fluid_begin(); });
  });
  walls_in_reach_.clear();
  walls_out_of_reach_.clear();
  pairs_in_reach_ = 0;
  // Those that something moving can reach: the fluid, or the body (its own and the fixed
  // walls it slides along, whose sums it changes).
  const auto moves = [&](std::int64_t j) { return j >= ps.fluid_begin() || (body_ && in_body(j)); };
  for (std::int64_t w = 0; w < ps.wall_end(); ++w) {
    const IdRange nb = neighbours_.of(w);
    if (moves(w) || std::any_of(nb.begin(), nb.end(), moves)) {
      walls_in_reach_.push_back(static_cast<std::int32_t>(w));
      pairs_in_reach_ += nb.size();
    } else {
      walls_out_of_reach_.push_back(static_cast<std::int32_t>(w));
    }
  }
  // The body's particles are boundary particles: only those near a wall can be near the body.
  near_body_.clear();
  if (!body_) return;
  for (std::int64_t i = ps.fluid_begin(); i < ps.size(); ++i) {
    const IdRange nb = neighbours_.of(i);
    if (near_wall_[i] &&
        std::any_of(nb.begin(), nb.end(), [&](std::int32_t j) { return in_body(j); })) {
      near_body_.push_back(static_cast<std::int32_t>(i));
    }
  }
}

template <class Scheme>
const double* Simulation::gradient_input() {
  ParticleSet& ps = scene_.particles;
  const ParticleState& t = ps.next;
  if constexpr (Scheme::kInput == GradientInput::PressureOverNumberDensitySquared) {
    // Boundary particles: at the density of their pressure (physics/WallDensity_Adami2012.h)
    // or at n0; a ghost's is its wall particle's, whose pressure it copies.
    const double inv_n0_2 = 1.0 / (ops_.n0() * ops_.n0());
    parallel_for(0, ps.wall_end(), [&](std::int64_t w) {
      p_over_n2_[w] = wall_density_ ? wall_density_->gradient_input(t.p[w]) : t.p[w] * inv_n0_2;
    });
    parallel_for(ps.wall_end(), ps.fluid_begin(),
                 [&](std::int64_t g) { p_over_n2_[g] = p_over_n2_[ps.ghost_source(g)]; });
    // A particle alone (n = 0) is on the free surface, p = 0: its p / n^2 is 0, not 0/0. The
    // pair loops multiply every input, also of pairs beyond re, by the kernel's zero, so each
    // must be finite.
    parallel_for(ps.fluid_begin(), ps.size(), [&](std::int64_t i) {
      p_over_n2_[i] = t.n[i] > 0.0 ? t.p[i] / (t.n[i] * t.n[i]) : 0.0;
    });
    return p_over_n2_.data();
  } else {
    return t.p.data();
  }
}

template <class Scheme>
BodyForce Simulation::body_force(const Scheme& scheme, const double* input) {
  // Fluid particle i gets -grad p / rho and the viscous acceleration from the body's particles
  // (the part of its sums over them); the body gets minus that times i's mass rho DL^2.
  const ParticleSet& ps = scene_.particles;
  const ParticleState& s = ps.now;
  const ParticleState& t = ps.next;
  const bool viscous = viscosity_.nu > 0.0 || artificial_viscosity_.alpha > 0.0;
  Vec2 gradient, acceleration;
  std::vector<std::int32_t>& part = body_part_;
  for (const std::int32_t i : near_body_) {
    const IdRange nb = neighbours_.of(i);
    part.clear();
    for (const std::int32_t j : nb) {
      if (in_body(j)) part.push_back(j);
    }
    const IdRange of_body{part.data(), part.data() + part.size()};
    gradient += scheme.gradient_part(ops_, i, nb, of_body, t.x.data(), t.y.data(), input);
    if (viscous) {
      acceleration += viscous_acceleration(ops_, viscosity_, artificial_viscosity_, i, of_body,
                                           s.x.data(), s.y.data(), s.u.data(), s.v.data(), slip());
    }
    if (wall_friction_) {
      acceleration +=
          wall_friction_->acceleration_part(friction_sums(i, nb), friction_sums(i, of_body));
    }
  }
  const double volume = rule_.dl * rule_.dl;
  return {gradient * volume, acceleration * (-density_ * volume)};
}

void Simulation::step(double t_stop) {
  const TimeStepRule& rule = active_rule();
  double dt = rule.step(max_speed_);
  bool lands_on_stop = false;
  if (rule.mode == TimeStepMode::Courant) {
    // Land exactly on t_stop, without leaving a sliver of a step before it.
    if (time_ + dt >= t_stop) {
      dt = t_stop - time_;
      lands_on_stop = true;
    } else if (time_ + 2.0 * dt > t_stop) {
      dt = 0.5 * (t_stop - time_);
    }
  }
  if (!(dt > 0.0)) return;

  timer_.time(Phase::Neighbours, [&] { update_neighbours(dt); });
  timer_.time(Phase::Predict, [&] {
    move_body(dt);
    predict(dt);
  });
  if (2.0 * star_drift_ >= skin_) {
    // The estimate of update_neighbours() fell short (a sudden acceleration): rebuild at r^n
    // and predict again. If one step alone moves a particle that far, check_stability stops.
    timer_.time(Phase::Neighbours, [&] { rebuild_neighbours(); });
    timer_.time(Phase::Predict, [&] { predict(dt); });
  }
  timer_.time(Phase::NumberDensity, [&] { compute_number_density(); });
  timer_.time(Phase::Pressure, [&] { compute_pressure(dt); });
  timer_.time(Phase::Correct, [&] {
    correct(dt);
    if (particle_collision_) collide_particles(dt);
  });
  timer_.time(Phase::Move, [&] { move(dt); });
  timer_.time(Phase::Check, [&] { check_stability(dt); });

  // The new state passed every check: it becomes the current one.
  scene_.particles.now.swap(scene_.particles.next);
  max_speed_ = next_max_speed_;
  drift_ = next_drift_;
  wall_collisions_ += next_collisions_;
  ++steps_;
  last_dt_ = dt;
  if (rule.mode == TimeStepMode::Fixed) {
    time_ = static_cast<double>(steps_) * rule.fixed;  // no drift over many steps
  } else {
    time_ = lands_on_stop ? t_stop : time_ + dt;
  }
  if (body_) {
    body_->commit(body_next_, body_force_next_);
    body_history_.push_back(body_->sample(time_));
  }
}

void Simulation::settle_step() {
  if (!settling_) return;
  ParticleSet& ps = scene_.particles;
  if (body_) body_->hold(true);  // the block is released at t = 0
  step(settle_time_);
  const double keep = std::exp(-last_dt_ / settle_damping_);
  max_speed_ = root_of_max(parallel_max(ps.fluid_begin(), ps.size(), [&](std::int64_t i) {
    ps.now.u[i] *= keep;
    ps.now.v[i] *= keep;
    return sq(ps.now.u[i]) + sq(ps.now.v[i]);
  }));
  if (time_ < settle_time_) return;
  parallel_for(ps.fluid_begin(), ps.size(), [&](std::int64_t i) {
    ps.now.u[i] = 0.0;
    ps.now.v[i] = 0.0;
  });
  max_speed_ = 0.0;
  if (body_) {
    body_->hold(false);
    body_->reset_motion();
    body_history_ = {body_->sample(0.0)};
  }
  settling_ = false;
  settle_steps_ = steps_;
  steps_ = 0;
  time_ = 0.0;
  // The run's performance figures count the run, not the settling.
  pairs_visited_ = 0;
  wall_collisions_ = 0;
  timer_.reset();
}

void Simulation::save(StateWriter& out) const {
  const ParticleSet& ps = scene_.particles;
  const ParticleState& s = ps.now;
  const auto n = static_cast<std::size_t>(ps.size());
  out.field("position", {s.x.data(), s.y.data()}, n);
  out.field("velocity", {s.u.data(), s.v.data()}, n);
  if (shift_in_continuity_) out.field("shift_velocity", {s.shift_u.data(), s.shift_v.data()}, n);
  if (surface_cap_) out.field("struck_number_density", {s.struck_n.data()}, n);
  if (!s.rest_a.empty()) out.field("rest_shape", {s.rest_a.data(), s.rest_b.data()}, n);
  out.field("pressure", {s.p.data()}, n);
  out.field("number_density", {s.n.data()}, n);
  out.field("free_surface", s.surface.data(), n);
  out.field("id", ps.id.data(), n);
  out.field("position_at_list_build", {x_built_.data(), y_built_.data()}, n);
  out.scalar("time", time_);
  out.integer("steps", steps_);
  out.scalar("last_dt", last_dt_);
  out.scalar("max_speed", max_speed_);
  out.scalar("drift", drift_);
  out.integer("last_sort_step", last_sort_step_);
  out.integer("wall_collisions", wall_collisions_);
  out.integer("settling", settling_ ? 1 : 0);
  out.integer("settle_steps", settle_steps_);
  if (body_) {
    body_->save(out);
    out.scalar("body_s_at_list_build", body_built_s_);
    save_history(out, body_history_);
  }
}

void Simulation::load(StateReader& in) {
  ParticleSet& ps = scene_.particles;
  ParticleState& s = ps.now;
  const auto n = static_cast<std::size_t>(ps.size());
  in.field("position", {s.x.data(), s.y.data()}, n);
  in.field("velocity", {s.u.data(), s.v.data()}, n);
  // Only a run that follows the shift keeps it; a checkpoint of one that did not (or of a
  // version before 2026-12-03) starts it from zero.
  if (shift_in_continuity_ && in.has("shift_velocity")) {
    in.field("shift_velocity", {s.shift_u.data(), s.shift_v.data()}, n);
  } else if (shift_in_continuity_) {
    std::fill(s.shift_u.begin(), s.shift_u.end(), 0.0);
    std::fill(s.shift_v.begin(), s.shift_v.end(), 0.0);
  }
  // Likewise the surface pressure cap's memory of strikes (a checkpoint before 2026-12-04: none).
  if (surface_cap_ && in.has("struck_number_density")) {
    in.field("struck_number_density", {s.struck_n.data()}, n);
  } else if (surface_cap_) {
    std::fill(s.struck_n.begin(), s.struck_n.end(), 0.0);
  }
  // And the rest shapes of "khayyer2011-strain" (a checkpoint without them: none, each particle
  // starts from its own shape).
  if (!s.rest_a.empty() && in.has("rest_shape")) {
    in.field("rest_shape", {s.rest_a.data(), s.rest_b.data()}, n);
  } else if (!s.rest_a.empty()) {
    std::fill(s.rest_a.begin(), s.rest_a.end(), std::numeric_limits<double>::quiet_NaN());
    std::fill(s.rest_b.begin(), s.rest_b.end(), std::numeric_limits<double>::quiet_NaN());
  }
  in.field("pressure", {s.p.data()}, n);
  in.field("number_density", {s.n.data()}, n);
  in.field("free_surface", s.surface.data(), n);
  in.field("id", ps.id.data(), n);
  in.field("position_at_list_build", {x_built_.data(), y_built_.data()}, n);
  // Between steps `next` holds the same boundary particles as `now`; the rest is scratch.
  ps.next = ps.now;
  time_ = in.scalar("time");
  steps_ = in.integer("steps");
  last_dt_ = in.scalar("last_dt");
  max_speed_ = in.scalar("max_speed");
  drift_ = in.scalar("drift");
  last_sort_step_ = in.integer("last_sort_step");
  wall_collisions_ = in.integer("wall_collisions");
  settling_ = in.integer("settling") != 0;
  settle_steps_ = in.integer("settle_steps");
  if (body_) {
    body_->load(in);
    body_built_s_ = in.scalar("body_s_at_list_build");
    const std::vector<BodySample> history = load_history(in);
    body_history_.assign(history.begin(), history.end());  // keeps the run's reservation
  }
  grid_.bin(x_built_.data(), y_built_.data(), ps.size());
  neighbours_.build(grid_, x_built_.data(), y_built_.data(), ps.size(), list_cutoff(),
                    list_owners_);
  find_fluid_near_walls();
  find_close_fluid_pairs();
  settle_walls_out_of_reach();
  built_ = true;
  builds_ = 0;
  pairs_visited_ = 0;
  timer_.reset();
}

void Simulation::update_neighbours(double dt) {
  // Lists hold every pair within re + skin at the last build. Pairs within re at r* are all in
  // them while no particle has moved skin/2 from where it was at the build. Estimate this
  // step's move from the current speed and gravity (predict() measures the actual one).
  const double body_speed = body_ ? std::abs(body_->state().u) : 0.0;
  const double move = dt * (std::max(1.5 * max_speed_, body_speed) + dt * norm(gravity_));
  if (!built_ || 2.0 * (drift_ + move) >= skin_) rebuild_neighbours();
}

void Simulation::rebuild_neighbours() {
  ParticleSet& ps = scene_.particles;
  if (sort_interval_ > 0 && (!built_ || steps_ - last_sort_step_ >= sort_interval_)) {
    timer_.time(Phase::Reorder, [&] { reorder_by_cell(); });
    last_sort_step_ = steps_;
  }
  grid_.bin(ps.now.x.data(), ps.now.y.data(), ps.size());
  neighbours_.build(grid_, ps.now.x.data(), ps.now.y.data(), ps.size(), list_cutoff(),
                    list_owners_);
  // All of them (the body's move), so that a checkpoint can rebuild these lists.
  parallel_for(0, ps.size(), [&](std::int64_t i) {
    x_built_[i] = ps.now.x[i];
    y_built_[i] = ps.now.y[i];
  });
  drift_ = 0.0;
  if (body_) body_built_s_ = body_->state().s;
  find_fluid_near_walls();
  find_close_fluid_pairs();
  settle_walls_out_of_reach();
  built_ = true;
  ++builds_;
}

void Simulation::move_body(double dt) {
  if (!body_) return;
  body_next_ = body_->advance(time_, dt);
  body_->place(body_next_, scene_.particles.next);
}

WallFriction_Spalding1961::Sums Simulation::friction_sums(std::int64_t i, IdRange nb) const {
  const ParticleState& s = scene_.particles.now;
  return WallFriction_Spalding1961::sums(ops_.kernel(), i, nb, scene_.particles.fluid_begin(),
                                         s.x.data(), s.y.data(), s.u.data(), s.v.data(),
                                         wall_tx_.data(), wall_ty_.data());
}

void Simulation::predict(double dt) {
  ParticleSet& ps = scene_.particles;
  const ParticleState& s = ps.now;
  ParticleState& t = ps.next;
  const bool viscous = viscosity_.nu > 0.0 || artificial_viscosity_.alpha > 0.0;
  // An evolved number density takes all its sums at (r^n, u^n) here, in the same pass as the
  // viscosity (physics/PredictionSums.h): its rate and diffusion, and the summed n and G that the
  // free-surface scan and the shifting read. The rate takes u^n, the velocity the particles moved
  // with in the last step, not u*: u* holds this step's g dt, which the pressure correction takes
  // out again, and against a wall it would read as a compression every step (in still water the
  // mean pressure then climbs by 290 Pa in 7 s). n then leads the momentum update as in
  // symplectic Euler. To u^n the rate adds the last step's shift over its dt (shift_u, shift_v):
  // the rest of the way the particles moved (ParticleShifting_Sun2017.h).
  const bool evolved = density_scheme_ == NumberDensityScheme::Continuity;
  DensityInputs density = density_inputs_;
  density.n = s.n.data();
  density.shift_u = s.shift_u.data();
  density.shift_v = s.shift_v.data();
  const double lap_scale = viscosity_.scale(ops_), q_scale = artificial_viscosity_.scale(ops_);
  const SlipInputs slip_walls = slip();
  const auto pass = [&](auto kPairs, auto kArtificial, auto kDensity, auto kShift, auto kSlip) {
    return root_of_max(parallel_max(ps.fluid_begin(), ps.size(), [&](std::int64_t i) {
      Vec2 a = gravity_;
      if constexpr (kPairs) {
        const PredictionSums p = [&] {
#if WCMPS_PAIRS_AVX512
          if constexpr (kArtificial && kDensity) {
            return prediction_sums_avx512<kShift, kSlip>(ops_.kernel(), i, neighbours_.of(i),
                                                         pair_rows_.data(), density);
          }
#endif
          return prediction_sums<kArtificial, kDensity, kShift, kSlip>(
              ops_.kernel(), i, neighbours_.of(i), s.x.data(), s.y.data(), s.u.data(), s.v.data(),
              density, slip_walls);
        }();
        a += p.lap * lap_scale;
        if constexpr (kArtificial) a += p.q * q_scale;
        // The walls' shear stress on the water next to them (WallFriction_Spalding1961.h).
        if (wall_friction_ && near_wall_[i]) {
          a += wall_friction_->acceleration(friction_sums(i, neighbours_.of(i)));
        }
        if constexpr (kDensity) {
          t.n[i] = continuity_.advance(s.n[i], p.rate, p.lapl, dt);
          n_sum_[i] = p.n;
          grad_x_[i] = p.gradient.x;
          grad_y_[i] = p.gradient.y;
        }
      }
      // The flume's side walls, which the scene leaves out (SideWallFriction_Spalding1961.h).
      if (side_walls_) a += side_walls_->acceleration({s.u[i], s.v[i]});
      t.u[i] = s.u[i] + dt * a.x;
      t.v[i] = s.v[i] + dt * a.y;
      t.x[i] = s.x[i] + dt * t.u[i];
      t.y[i] = s.y[i] + dt * t.v[i];
      return sq(t.x[i] - x_built_[i]) + sq(t.y[i] - y_built_[i]);
    }));
  };
  using Yes = std::true_type;
  using No = std::false_type;
  const bool artificial = artificial_viscosity_.alpha > 0.0;
  const bool follow = shift_in_continuity_;  // implies evolved
  prediction_rows_ = WCMPS_PAIRS_AVX512 && artificial && evolved;
  if (prediction_rows_) {
    pack_prediction_rows(pair_rows_, ps.size(), s.x.data(), s.y.data(), s.u.data(), s.v.data(),
                         s.n.data(), follow ? s.shift_u.data() : nullptr,
                         follow ? s.shift_v.data() : nullptr, ps.fluid_begin(), slip_walls);
  }
  // The artificial viscosity's free-slip walls: the same passes with kSlip.
  const auto artificial_pass = [&](auto kSlip) {
    return follow    ? pass(Yes{}, Yes{}, Yes{}, Yes{}, kSlip)
           : evolved ? pass(Yes{}, Yes{}, Yes{}, No{}, kSlip)
                     : pass(Yes{}, Yes{}, No{}, No{}, kSlip);
  };
  if (!viscous && !evolved) {
    star_drift_ = pass(No{}, No{}, No{}, No{}, No{});
  } else if (artificial) {
    star_drift_ = slip_walls.tangent_x ? artificial_pass(Yes{}) : artificial_pass(No{});
  } else {
    star_drift_ = follow    ? pass(Yes{}, No{}, Yes{}, Yes{}, No{})
                  : evolved ? pass(Yes{}, No{}, Yes{}, No{}, No{})
                            : pass(Yes{}, No{}, No{}, No{}, No{});
  }
  if (body_) star_drift_ = std::max(star_drift_, body_drift(body_next_.s));
  if (viscous || evolved) pairs_visited_ += neighbours_.pair_count(ps.fluid_begin(), ps.size());
}

void Simulation::compute_number_density() {
  ParticleSet& ps = scene_.particles;
  ParticleState& t = ps.next;
  // Wall particles within the fluid's reach (the others: settle_walls_out_of_reach).
  sum_walls(walls_in_reach_);
  pairs_visited_ += pairs_in_reach_;
  if (density_scheme_ == NumberDensityScheme::Continuity) return;  // summed in the prediction
  // The study's n* at r* (Eq. 2.17), and G if the surface scan or the shifting needs it.
  const bool gradient =
      surface_scheme_ == FreeSurfaceScheme::Marrone2010 || shifting_scheme_ != ShiftingScheme::None;
  parallel_for(ps.fluid_begin(), ps.size(), [&](std::int64_t i) { sum_one(i, gradient, t); });
  pairs_visited_ += neighbours_.pair_count(ps.fluid_begin(), ps.size());
}

void Simulation::compute_pressure(double dt) {
  ParticleSet& ps = scene_.particles;
  ParticleState& t = ps.next;
  // Free surface (Eq. 2.10, or the scan of Marrone et al. 2010) and equation of state (Eq. 2.9)
  // for fluid particles; the bound of negative pressures (physics/NegativePressure_Sun2018.h).
  // The free surface carries no tension. With the summed n its particles' kernels are
  // incomplete and their equation of state meaningless: p = 0 (Eq. 2.10). An evolved n is the
  // particle's own: a surface particle keeps its pressure where it is compressed (the top row
  // under the weight of nothing but itself, a jet striking a wall) and is held at 0 below it;
  // forced to 0 it would offer no resistance to the rows under it, which crowd into the surface
  // (still water: two particles per DL in the top row after 1.7 s, then a blow-up).
  const bool evolved = density_scheme_ == NumberDensityScheme::Continuity;
  const bool scan = surface_scheme_ == FreeSurfaceScheme::Marrone2010;
  const std::int64_t fluid = ps.fluid_begin();
  if (scan) {
    find_wet_walls(walls_in_reach_);
    // A ghost is wet or dry with its wall particle. Serial: a copy each, not worth a region.
    for (std::int64_t g = ps.wall_end(); g < fluid; ++g) fills_[g] = fills_[ps.ghost_source(g)];
  }
  const std::int32_t* filling = fills_.data();
  const auto fills = [filling](std::int32_t j) { return filling[j] != 0; };
  parallel_for(ps.fluid_begin(), ps.size(), [&](std::int64_t i) {
    const bool on_surface =
        scan ? scan_.is_surface(i, neighbours_.of(i), t.x.data(), t.y.data(), summed_n(i),
                                {grad_x_[i], grad_y_[i]}, fills,
                                &scan_witness_[static_cast<std::size_t>(i) * kWitnesses])
             : surface_.is_surface(summed_n(i));
    t.surface[i] = on_surface ? 1 : 0;
  });
  // The band of this step's surface (the tensile switch, the shifting), and in it the evolved
  // n's rate renormalised before the equation of state reads n.
  if (!band_x_.empty()) find_surface_band();
  if (band_rate_) correct_band_rate(dt);
  parallel_for(ps.fluid_begin(), ps.size(), [&](std::int64_t i) {
    const double p = eos_.pressure(t.n[i]);
    t.p[i] = !t.surface[i] ? pressure_bound_(p) : evolved ? std::max(p, 0.0) : 0.0;
  });
  if (surface_cap_) cap_surface_pressure(dt);
  compute_wall_pressure(walls_in_reach_);
  if (wall_scheme_ != WallPressureScheme::Eos) pairs_visited_ += pairs_in_reach_;
  // Ghost particles: the pressure of their wall particle along the wall normal (section 2.6).
  parallel_for(ps.wall_end(), ps.fluid_begin(),
               [&](std::int64_t i) { t.p[i] = t.p[ps.ghost_source(i)]; });
}

void Simulation::sum_one(std::int64_t i, bool with_gradient, const ParticleState& pos) {
  // The summed n of particle i at the positions `pos` into `next`, and G where it is asked for.
  ParticleState& t = scene_.particles.next;
  const IdRange nb = neighbours_.of(i);
  if (with_gradient) {
    const DensitySums d = density_sums<true>(sums_setup_, i, nb, pos.x.data(), pos.y.data());
    t.n[i] = d.n;
    grad_x_[i] = d.gradient.x;
    grad_y_[i] = d.gradient.y;
  } else {
    t.n[i] = ops_.number_density(i, nb, pos.x.data(), pos.y.data());
  }
}

void Simulation::sum_walls(const std::vector<std::int32_t>& walls) {
  // Their summed n (the "eos" wall pressure, the frames) and, for the surface scan, its
  // gradient (which of them are wet), at the positions the surface is found at.
  const ParticleState& at = surface_positions();
  const bool scan = surface_scheme_ == FreeSurfaceScheme::Marrone2010;
  parallel_for(0, static_cast<std::int64_t>(walls.size()),
               [&](std::int64_t k) { sum_one(walls[static_cast<std::size_t>(k)], scan, at); });
}

void Simulation::find_wet_walls(const std::vector<std::int32_t>& walls) {
  // Which wall particles are wet: only those fill a fluid particle's scan region.
  const ParticleSet& ps = scene_.particles;
  const ParticleState& t = ps.next;
  const std::int64_t fluid = ps.fluid_begin();
  parallel_for(0, static_cast<std::int64_t>(walls.size()), [&](std::int64_t k) {
    const std::int32_t w = walls[static_cast<std::size_t>(k)];
    fills_[w] = !scan_.is_dry(w, neighbours_.of(w), t.x.data(), t.y.data(), t.n[w],
                              {grad_x_[w], grad_y_[w]}, [&](std::int32_t j) { return j >= fluid; });
  });
}

void Simulation::compute_wall_pressure(const std::vector<std::int32_t>& walls) {
  ParticleSet& ps = scene_.particles;
  ParticleState& t = ps.next;
  const auto each = [&](auto&& f) {
    parallel_for(0, static_cast<std::int64_t>(walls.size()),
                 [&](std::int64_t k) { f(walls[static_cast<std::size_t>(k)]); });
  };
  if (wall_scheme_ == WallPressureScheme::Eos) {
    // The wall particle as a fluid particle of its own summed n (Shakibaeinia & Jin 2010).
    each([&](std::int32_t w) {
      const bool on_surface = surface_.is_surface(t.n[w]);
      t.p[w] = on_surface ? 0.0 : pressure_bound_(eos_.pressure(t.n[w]));
      t.surface[w] = on_surface ? 1 : 0;
    });
  } else {
    // A moving wall's particles feel g - a (Adami et al. 2012, Eq. 27).
    const IndexRange body = body_ ? body_->particles().walls : IndexRange{0, 0};
    const Vec2 body_g = body_ ? gravity_ - body_->downslope() * body_next_.a : gravity_;
    each([&](std::int32_t w) {
      const Vec2 g = w >= body.first && w < body.second ? body_g : gravity_;
      const auto p =
          WallPressure_Adami2012::pressure(w, neighbours_.of(w), t.x.data(), t.y.data(), t.p.data(),
                                           ps.kind.data(), ops_.kernel(), density_, g);
      t.p[w] = pressure_bound_(p.value_or(0.0));
      t.surface[w] = p ? 0 : 1;
    });
  }
}

void Simulation::settle_walls_out_of_reach() {
  // The step's wall phases for these once, on `next` at the current positions (the fixed
  // walls' are the same in both states), then copied to `now`: frames and checkpoints read
  // them there. Before the first step `next` is not yet allocated: it starts as a copy of now.
  ParticleSet& ps = scene_.particles;
  if (walls_out_of_reach_.empty()) return;
  const bool fresh = ps.next.n.size() != ps.now.n.size();
  if (fresh) ps.next = ps.now;
  sum_walls(walls_out_of_reach_);
  if (surface_scheme_ == FreeSurfaceScheme::Marrone2010) find_wet_walls(walls_out_of_reach_);
  compute_wall_pressure(walls_out_of_reach_);
  for (const std::int32_t w : walls_out_of_reach_) {
    ps.now.n[w] = ps.next.n[w];
    ps.now.p[w] = ps.next.p[w];
    ps.now.surface[w] = ps.next.surface[w];
  }
}

void Simulation::correct_band_rate(double dt) {
  // The prediction's pass advanced n with the summed rate at (r^n, u^n); in the band, that rate
  // is replaced by the corrected one from the same pairs, and the corrector kept for the
  // pressure gradient (set_band_excess). Each particle writes its own n.
  ParticleSet& ps = scene_.particles;
  const ParticleState& s = ps.now;
  ParticleState& t = ps.next;
  const std::int64_t fluid = ps.fluid_begin();
  // The prediction's rows, where it packed them, hold the same r^n and u^n.
  [[maybe_unused]] const PairRow* rows = pair_rows_.data();
  parallel_for(0, static_cast<std::int64_t>(band_.size()), [&](std::int64_t k) {
    const std::int32_t i = band_[static_cast<std::size_t>(k)];
#if WCMPS_PAIRS_AVX512
    const auto sums =
        prediction_rows_
            ? DensityRate_Randles1996::sums_avx512(ops_.kernel(), i, neighbours_.of(i), rows, fluid)
            : DensityRate_Randles1996::sums(ops_.kernel(), i, neighbours_.of(i), s.x.data(),
                                            s.y.data(), s.u.data(), s.v.data(), fluid);
#else
    const auto sums = DensityRate_Randles1996::sums(ops_.kernel(), i, neighbours_.of(i), s.x.data(),
                                                    s.y.data(), s.u.data(), s.v.data(), fluid);
#endif
    const auto l = band_rate_rule_.corrector(sums, {s.n[i], t.n[i], dt});
    band_corrector_[i] = l;
    t.n[i] += dt * (DensityRate_Randles1996::band_rate(sums, l) - sums.summed());
  });
}

void Simulation::set_band_excess(const double* p_over_n2) {
  // The partner of the band's rate: q (L - I) of each particle of this step's band, which the
  // pressure gradient's pass gathers from every neighbour (DensityRate_Randles1996::
  // gathered_gradient). correct_band_rate wrote the corrector of every one of them;
  // find_surface_band cleared the last step's band. Each band particle also marks itself and
  // the fluid in its list with the step's stamp: the particles that have something to gather
  // (Excess::reaches). Two band particles may mark the same one: the stores are atomic.
  const std::int64_t fluid = scene_.particles.fluid_begin();
  std::uint32_t* reach = band_reach_.data();
  const std::uint32_t stamp = band_stamp_;
  parallel_for(0, static_cast<std::int64_t>(band_.size()), [&](std::int64_t k) {
    const std::int32_t j = band_[static_cast<std::size_t>(k)];
    const DensityRate_Randles1996::Corrector& l = band_corrector_[j];
    const double q = p_over_n2[j];
    band_axx_[j] = q * (l.xx - 1.0);
    band_axy_[j] = q * l.xy;
    band_ayy_[j] = q * (l.yy - 1.0);
    __atomic_store_n(&reach[j], stamp, __ATOMIC_RELAXED);
    for (const std::int32_t m : neighbours_.of(j)) {
      if (m >= fluid) __atomic_store_n(&reach[m], stamp, __ATOMIC_RELAXED);
    }
  });
}

void Simulation::cap_surface_pressure(double dt) {
  // physics/SurfacePressureCap.h: two passes, so that every cap reads the pressures of this
  // step's equation of state and no particle's cap depends on the order of the others. A struck
  // particle (its n rose fast, and is not yet back where the strike found it) keeps its own
  // pressure; every fluid particle carries its memory of a strike to the next step.
  ParticleSet& ps = scene_.particles;
  const ParticleState& s = ps.now;
  ParticleState& t = ps.next;
  const std::int64_t fluid = ps.fluid_begin();
  const double n0 = ops_.n0();
  cap_.resize(ps.size());
  const auto interior = [&](std::int32_t j) { return j >= fluid && !t.surface[j]; };
  parallel_for(fluid, ps.size(), [&](std::int64_t i) {
    t.struck_n[i] = cap_rule_.strike(s.struck_n[i], s.n[i], t.n[i], n0, dt);
    if (!t.surface[i]) return;
    if (t.struck_n[i] > 0.0) {
      cap_[i] = t.p[i];
      return;
    }
    cap_[i] = SurfacePressureCap::bound(i, neighbours_.of(i), t.x.data(), t.y.data(), t.p.data(),
                                        ops_.kernel(), interior)
                  .value_or(t.p[i]);
  });
  parallel_for(fluid, ps.size(), [&](std::int64_t i) {
    if (t.surface[i]) t.p[i] = std::max(std::min(t.p[i], cap_[i]), 0.0);  // no tension
  });
}

void Simulation::find_surface_band() {
  // The free-surface band: the surface particles and the fluid particles within re of one (the
  // region that the tensile-instability switch leaves out, and where the shifting moves particles
  // along the surface only). Each gets the kernel-weighted sum of the surface normals
  // -G_s/|G_s| near it (its own with W(0) = 1), the normal of the shifting's projection
  // (physics/ParticleShifting_Sun2017.h). Serial: surface particles are a thin band, a few per
  // cent of the fluid, and the sums into a particle must not race.
  const ParticleSet& ps = scene_.particles;
  const ParticleState& t = ps.next;
  const ParticleState& at = surface_positions();
  for (const std::int32_t j : band_) {
    band_x_[j] = band_y_[j] = 0.0;
    in_band_[j] = 0;
    if (band_rate_) band_axx_[j] = band_axy_[j] = band_ayy_[j] = 0.0;
  }
  band_.clear();
  if (band_rate_ && ++band_stamp_ == 0) {
    // The stamp wrapped (after 2^32 steps): old marks could read as this step's.
    std::fill(band_reach_.begin(), band_reach_.end(), 0u);
    band_stamp_ = 1;
  }
  const Kernel& w = ops_.kernel();
  const double re2 = ops_.re() * ops_.re();
  auto add = [&](std::int64_t j, double weight, Vec2 nu) {
    if (!in_band_[j]) {
      in_band_[j] = 1;
      band_.push_back(static_cast<std::int32_t>(j));
    }
    band_x_[j] += weight * nu.x;
    band_y_[j] += weight * nu.y;
  };
  // Without G (the summed n, the threshold's surface, no shifting: the switch alone asks for the
  // band) the members are found and no normals summed.
  const bool normals = !grad_x_.empty();
  for (std::int64_t s = ps.fluid_begin(); s < ps.size(); ++s) {
    if (!t.surface[s]) continue;
    Vec2 nu;
    if (normals) {
      const double g = std::hypot(grad_x_[s], grad_y_[s]);
      if (!(g > 0.0)) continue;  // a lone particle: no neighbours to project
      nu = {-grad_x_[s] / g, -grad_y_[s] / g};
    }
    add(s, 1.0, nu);
    for (const std::int32_t j : neighbours_.of(s)) {
      if (j < ps.fluid_begin()) continue;
      const double r2 = sq(at.x[j] - at.x[s]) + sq(at.y[j] - at.y[s]);
      if (r2 < re2) add(j, w(std::sqrt(r2)), nu);
    }
  }
}

void Simulation::correct(double dt) {
  ParticleSet& ps = scene_.particles;
  ParticleState& t = ps.next;
  const double c = -dt / density_;
  GradientOptions options = gradient_options();
  if (!ps.now.rest_a.empty()) {
    // While the water settles its arrangement is the rest state: S_i = D_i.
    options.memory = {ps.now.rest_a.data(), ps.now.rest_b.data(), t.rest_a.data(), t.rest_b.data(),
                      settling_ ? 1.0 : std::min(1.0, dt / strain_memory_)};
  }
  with_pressure_gradient(gradient_scheme_, options, [&](auto scheme) {
    using Scheme = decltype(scheme);
    const double* input = gradient_input<Scheme>();
    if constexpr (Scheme::kInput == GradientInput::PressureOverNumberDensitySquared) {
      if (band_rate_) set_band_excess(input);
#if WCMPS_PAIRS_AVX512
      if constexpr (Scheme::kRows) {
        const auto& a = scheme.excess;
        pack_gradient_rows(pair_rows_, ps.size(), t.x.data(), t.y.data(), input, a.xx, a.xy, a.yy);
        scheme.rows = pair_rows_.data();
        prediction_rows_ = false;
      }
#endif
    }
    // The wall collisions of i need only its corrected velocity and the boundary particles'
    // (which this loop does not change): applied in the same pass over its neighbours' list.
    const bool collide = collision_scheme_ != WallCollisionScheme::None;
    next_collisions_ = parallel_count(ps.fluid_begin(), ps.size(), [&](std::int64_t i) {
      const IdRange nb = neighbours_.of(i);
      const Vec2 g = scheme.gradient(ops_, i, nb, t.x.data(), t.y.data(), input);
      t.u[i] += c * g.x;
      t.v[i] += c * g.y;
      // A particle with no boundary particle in its list has none to collide with.
      return collide && near_wall_[i] &&
             collision_.apply(i, nb, t.x.data(), t.y.data(), t.u.data(), t.v.data(),
                              ps.kind.data()) > 0;
    });
    // The body's force reads the band's correctors in the same pairs (A_i of the water next to
    // it). (The case parser lets density_rate with the variational gradient only.)
    if (body_) body_force_next_ = body_force(scheme, input);
  });
  pairs_visited_ += neighbours_.pair_count(ps.fluid_begin(), ps.size());
}

void Simulation::find_close_fluid_pairs() {
  if (!particle_collision_) return;
  // From the full lists, at the build positions: a pair farther than l0 + skin apart then is
  // farther than l0 at r* (each particle has moved less than skin/2). Case I builds once in 11
  // steps, so the collision's pass walks a few candidates a step instead of the whole list.
  const ParticleSet& ps = scene_.particles;
  const std::int64_t fluid = ps.fluid_begin(), n = ps.size();
  const double reach = particle_collision_->distance + skin_;
  const double reach2 = reach * reach;
  const auto close = [&](std::int64_t i, std::int32_t j) {
    return j >= fluid && j != i &&
           sq(x_built_[i] - x_built_[j]) + sq(y_built_[i] - y_built_[j]) < reach2;
  };
  close_begin_.assign(static_cast<std::size_t>(n - fluid + 1), 0);
  parallel_for(fluid, n, [&](std::int64_t i) {
    std::int64_t count = 0;
    for (const std::int32_t j : neighbours_.of(i)) count += close(i, j);
    close_begin_[i - fluid + 1] = count;
  });
  for (std::size_t k = 1; k < close_begin_.size(); ++k) close_begin_[k] += close_begin_[k - 1];
  close_ids_.resize(static_cast<std::size_t>(close_begin_.back()));
  parallel_for(fluid, n, [&](std::int64_t i) {
    // Those with none (40 to 70 % in case I's frames; the count's pass, which the compiler
    // vectorises, told) are not walked again.
    if (close_begin_[i - fluid + 1] == close_begin_[i - fluid]) return;
    std::int32_t* out = close_ids_.data() + close_begin_[i - fluid];
    for (const std::int32_t j : neighbours_.of(i)) {
      if (close(i, j)) *out++ = j;
    }
  });
}

void Simulation::collide_particles(double dt) {
  // Two passes: every change reads the corrected velocities of the step, whatever the order.
  ParticleSet& ps = scene_.particles;
  ParticleState& t = ps.next;
  const std::int64_t fluid = ps.fluid_begin();
  parallel_for(fluid, ps.size(), [&](std::int64_t i) {
    const std::int32_t* ids = close_ids_.data();
    const IdRange candidates{ids + close_begin_[i - fluid], ids + close_begin_[i - fluid + 1]};
    const Vec2 du = particle_collision_->change(i, candidates, t.x.data(), t.y.data(), t.u.data(),
                                                t.v.data(), t.p.data(), fluid, dt);
    collision_du_[i] = du.x;
    collision_dv_[i] = du.y;
  });
  parallel_for(fluid, ps.size(), [&](std::int64_t i) {
    t.u[i] += collision_du_[i];
    t.v[i] += collision_dv_[i];
  });
}

void Simulation::move(double dt) {
  ParticleSet& ps = scene_.particles;
  const ParticleState& s = ps.now;
  ParticleState& t = ps.next;
  const bool shift = shifting_scheme_ != ShiftingScheme::None;
  const double umax = max_speed_;
  const auto [speed, drift] = parallel_max2(ps.fluid_begin(), ps.size(), [&](std::int64_t i) {
    t.x[i] = s.x[i] + dt * t.u[i];
    t.y[i] = s.y[i] + dt * t.v[i];
    if (shift) {
      // Along the surface only in its band (the band's normal sum, normalised).
      Vec2 nu;
      if (in_band_[i]) {
        const double b = std::hypot(band_x_[i], band_y_[i]);
        if (b > 0.0) nu = {band_x_[i] / b, band_y_[i] / b};
      }
      const Vec2 dr = shifting_.shift({grad_x_[i], grad_y_[i]}, umax, dt, nu);
      t.x[i] += dr.x;
      t.y[i] += dr.y;
      if (shift_in_continuity_) {
        t.shift_u[i] = dr.x / dt;
        t.shift_v[i] = dr.y / dt;
      }
    }
    return std::make_pair(sq(t.u[i]) + sq(t.v[i]),
                          sq(t.x[i] - x_built_[i]) + sq(t.y[i] - y_built_[i]));
  });
  // Kept aside until the step is committed: a failed step leaves the state as it was.
  next_max_speed_ = root_of_max(speed);
  next_drift_ = root_of_max(drift);
  if (body_) next_drift_ = std::max(next_drift_, body_drift(body_next_.s));
}

void Simulation::check_stability(double dt) {
  const ParticleSet& ps = scene_.particles;
  const ParticleState& s = ps.now;
  const ParticleState& t = ps.next;
  const Vec2 lo = scene_.domain_lo, hi = scene_.domain_hi;
  const double n_max = max_density_ratio_ * ops_.n0();
  const auto& rows = scene_.wall_rows;
  // Even after a fresh build a particle was predicted skin/2 or more from its build position:
  // it moved that far in this one step, and pairs within re may be missing from the lists.
  // (r* is not kept; the particles are found by their new positions, which differ from r*
  // by dt times the pressure correction.)
  const bool moved_too_far = 2.0 * star_drift_ >= skin_;
  // The body's rows move: a particle crossed one if it crossed it in the body's frame.
  const auto body_rows = body_ ? body_->particles().rows : std::pair<std::size_t, std::size_t>{};
  const Vec2 body_now = body_ ? body_->offset(body_->state().s) : Vec2{};
  const Vec2 body_next = body_ ? body_->offset(body_next_.s) : Vec2{};
  // The crossing test is needed only near walls. A particle without boundary particles in its
  // list was more than re + skin from every wall particle at the build; a row's points are
  // within DL of one of its wall particles (rows are sampled at DL), and the body's particles
  // have moved by its drift since. The particle's path this step stays within
  // D = max(|r^n - r_b|, |r^n+1 - r_b|) of its build position r_b, so it cannot reach a row
  // while D < re + skin - DL - body drift.
  const double body_moved =
      body_ ? std::max(body_drift(body_->state().s), body_drift(body_next_.s)) : 0.0;
  const double clear = ops_.re() + skin_ - rule_.dl - body_moved;
  const double clear2 = clear > 0.0 ? clear * clear : 0.0;
  auto failure = [&](std::int64_t i) -> std::uint8_t {
    const double x = t.x[i], y = t.y[i];
    if (!std::isfinite(x) || !std::isfinite(y) || !std::isfinite(t.u[i]) ||
        !std::isfinite(t.v[i]) || !std::isfinite(t.p[i])) {
      return kNotFinite;
    }
    if (x < lo.x || y < lo.y || x > hi.x || y > hi.y) return kLeftDomain;
    const Vec2 a{s.x[i], s.y[i]}, b{x, y}, built{x_built_[i], y_built_[i]};
    const bool may_cross =
        near_wall_[i] || std::max(dot(a - built, a - built), dot(b - built, b - built)) >= clear2;
    for (std::size_t k = 0; may_cross && k < rows.size(); ++k) {
      const bool moves = k >= body_rows.first && k < body_rows.second;
      if (moves ? segments_intersect(a - body_now, b - body_next, rows[k].a, rows[k].b)
                : segments_intersect(a, b, rows[k].a, rows[k].b)) {
        return kCrossedWall;
      }
    }
    // The particles packed past the limit: their n and the arrangement's. An evolved n can pass
    // it where the arrangement is far from packed (a splash particle with two neighbours sliding
    // into a wall: evolved 1.20 n0, summed 0.27 n0; docs/validation.md, "After the band's sums
    // were vectorised"); under summation the two are one.
    if (t.n[i] > n_max && summed_n(i) > n_max) return kDensityBlowUp;
    if (moved_too_far && 2.0 * std::sqrt(sq(x - x_built_[i]) + sq(y - y_built_[i])) >= skin_) {
      return kMovedTooFar;
    }
    return kOk;
  };
  const std::int64_t failed = parallel_count(ps.fluid_begin(), ps.size(),
                                             [&](std::int64_t i) { return failure(i) != kOk; });
  if (failed == 0) return;
  // Report the failing particle with the smallest id, so that reports do not depend on threads.
  std::int64_t first = -1;
  for (std::int64_t i = ps.fluid_begin(); i < ps.size(); ++i) {
    if (failure(i) != kOk && (first < 0 || ps.id[i] < ps.id[first])) first = i;
  }
  InstabilityReport r;
  r.step = steps_ + 1;
  r.time = time_ + dt;
  r.particle_id = ps.id[first];
  r.x = t.x[first];
  r.y = t.y[first];
  r.reason = failure_text(failure(first));
  if (failure(first) == kDensityBlowUp) {
    r.reason += " (n*/n0 = " + std::to_string(t.n[first] / ops_.n0()) + ")";
  }
  r.particles_affected = failed;
  throw InstabilityError(r);
}

void Simulation::reorder_by_cell() {
  // Fluid particles in the order of their cells, so that neighbours sit close in memory.
  ParticleSet& ps = scene_.particles;
  grid_.bin(ps.now.x.data(), ps.now.y.data(), ps.size());
  std::size_t k = 0;
  for (const std::int32_t i : grid_.members()) {
    if (i >= ps.fluid_begin()) order_[k++] = i;
  }
  ps.reorder_fluid(order_);
}

}  // namespace wcmps
