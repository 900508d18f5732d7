#pragma once
/// @file CaseSpec.h
/// @brief Everything a case file says, validated and with defaults filled in (keys, units and
/// defaults are documented in docs/case-format.md). Plain data: the parser fills it, the scene
/// builder and the simulation read it.

#include <cmath>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/Error.h"
#include "core/Vec2.h"
#include "particles/Fields.h"
#include "particles/ParticleKind.h"
#include "physics/DensityRate_Randles1996.h"
#include "physics/FreeSurface_Marrone2010.h"
#include "physics/NegativePressure_Sun2018.h"
#include "physics/NumberDensity_Jandaghian2020.h"
#include "physics/ParticleCollision_Jandaghian2021.h"
#include "physics/ParticleShifting_Sun2017.h"
#include "physics/PressureGradient.h"
#include "physics/SideWallFriction_Spalding1961.h"
#include "physics/TimeStep.h"
#include "physics/WallCollision.h"
#include "physics/WallDensity_Adami2012.h"
#include "physics/WallFriction_Spalding1961.h"
#include "physics/WallPressure.h"
#include "physics/WallSlip_Colagrossi2003.h"

namespace wcmps {

/// A region filled with fluid particles on the global lattice (a polygon; rectangles are
/// stored as their four corners).
struct FluidRegionSpec {
  std::vector<Vec2> polygon;
  Vec2 velocity;         ///< initial velocity (m/s)
  SourceLocation where;  ///< the [[fluid]] table in the case file
  std::string label;     ///< how messages name it: "[[fluid]] #2", "[tank]"
};

/// A wall given by its surface line; particles are laid in rows parallel to it on its solid
/// side (one wall row, then ghost rows).
struct WallSpec {
  std::vector<Vec2> points;    ///< surface polyline (m)
  bool closed = false;         ///< last point joins the first
  bool solid_on_right = true;  ///< solid side, looking along the polyline
  SourceLocation where;
  std::string label;  ///< how messages name it: "[[wall]] #1", "[tank]", "[block]"
};

/// A tank with a sloping bed (a beach): the bed runs from above the shoreline down to a flat
/// bottom, which runs to a vertical far wall. Coordinates: origin at the shoreline on the
/// still-water line, x towards the far wall, y up. The builder turns it into one wall (bed,
/// bottom, far wall) and one fluid region (the water below y = 0).
struct TankSpec {
  double slope_deg = 0.0;  ///< angle of the bed with the horizontal (degrees)
  double depth = 0.0;      ///< still-water depth over the flat bottom (m)
  double length = 0.0;     ///< shoreline to far wall along the still-water line (m)
  double freeboard = 0.0;  ///< height of bed and far wall above still water (m)
  SourceLocation where;
};

/// A triangular block resting on the bed of a [tank], named as the study names its corners:
/// C the upslope top corner (the angle there is the bed slope, since the top is horizontal),
/// A the downslope top corner, G the corner on the bed. Its top is `top_depth` below the still
/// water and C sits on the bed. The builder makes it a solid polygon (wall and ghost rows
/// inside it) that displaces the water.
struct BlockSpec {
  double top_length = 0.0;   ///< CA (m)
  double angle_a_deg = 0.0;  ///< the angle at A, between the top and the front face (degrees)
  double top_depth = 0.0;    ///< depth of the top below still water (m)
  double density = 0.0;      ///< kg/m^3
  Vec2 c, a, g;              ///< the corners (m), computed from the above and the tank
  SourceLocation where;

  double area() const { return 0.5 * std::abs(cross(a - c, g - c)); }
};

/// How a rigid body moves ([block.motion] type).
enum class BodyMotionType {
  Fixed,   ///< held in place
  Table,   ///< prescribed along the bed: a C2 spline through a table of S(t) (SplineSlide)
  LnCosh,  ///< prescribed along the bed: S = s0 ln cosh(t/t0) (LnCoshSlide)
  Free,    ///< moved by gravity and the fluid's forces, with Coulomb friction on the bed
};

struct BodyMotionSpec {
  BodyMotionType type = BodyMotionType::Fixed;
  std::vector<double> times, distances;  ///< Table: t (s) and S (m), increasing
  double a0 = 0.0, ut = 0.0;             ///< LnCosh: initial acceleration, terminal speed
  double friction = 0.0;                 ///< Free: Coulomb coefficient mu between body and bed
  SourceLocation where;
};

/// A rigid body made of one closed wall's particles, sliding along a straight line (a bed) or
/// held fixed. The [block] fills it in; tests may give any closed wall.
struct BodySpec {
  std::size_t wall = 0;  ///< index into CaseSpec::walls (a closed wall)
  double density = 0.0;  ///< kg/m^3; its mass per unit width is density x area
  Vec2 downslope;        ///< unit vector along which S counts
  Vec2 bed_normal;       ///< unit normal of the bed, out of it (the bed pushes along it)
  BodyMotionSpec motion;
  std::string label;  ///< how messages and files name it
};

/// A measuring section, fixed in space: the line from `origin` (on the bed or the body's
/// surface) along `direction` (unit; normal to the bed) up to the free surface.
struct SectionSpec {
  std::string name;
  Vec2 origin;
  Vec2 direction;
  SourceLocation where;
};

/// What `wcmps post` computes from a run ([post]; nothing unless asked).
enum class PostProduct { Grid, Sections, SectionAverages, FreeSurface, Lines, Cavity };

struct PostSpec {
  std::vector<PostProduct> products;
  std::vector<double> times;             ///< s; empty: the [output] times
  double grid_spacing = 0.0;             ///< m; 0: DL
  std::vector<std::string> grid_fields;  ///< empty: every floating-point field
  bool corrected_gradient = false;       ///< vorticity with the renormalised gradient
  int section_samples = 51;
  double average_max_x_over_l = 3.5;
  int average_stations = 36;
  double surface_spacing = 0.0;  ///< m; 0: DL
  /// Polylines between two points of the block, named by its corners (C, A, G) or the
  /// midpoints B (of CA) and F (of AG), e.g. {"C", "A"}; they move with the block.
  std::vector<std::pair<std::string, std::string>> lines;

  bool wants(PostProduct p) const {
    for (const auto q : products) {
      if (q == p) return true;
    }
    return false;
  }
};

/// Wave gauges ([gauges]): eta(t) at fixed x, sampled during the run into gauges.csv.
struct GaugeSpec {
  std::vector<double> x;  ///< m; none: no gauges
  double interval = 0.0;  ///< s between samples
};

/// Measured data for `wcmps figures` to overlay ([figures]); paths as given in the case file,
/// resolved against its directory (empty: none). Columns in docs/figures.md.
struct FiguresSpec {
  std::string measured_surface;   ///< time [s], x [m], eta [m]
  std::string measured_profiles;  ///< time [s], section, Y [-], u_along [m/s], u_normal [m/s]
};

struct CaseSpec {
  // [case]
  std::string name = "case";
  std::string description;
  SourceLocation file;      ///< the file it came from (line 0)
  std::string source_text;  ///< the file's text, copied into the run directory

  // [particles]
  double dl = 0.0;          ///< particle spacing DL (m)
  double re_over_dl = 3.5;  ///< kernel radius re / DL
  Vec2 lattice_origin;      ///< fluid lattice points sit at origin + (i + 1/2, j + 1/2) DL
  /// Lattice points closer than this x DL to a wall surface are dropped. 0: the fluid reaches
  /// the wall's surface, as the wall's rows (0.5, 1.5, ... DL inside it) reach it from the other
  /// side. A wall that does not lie along the lattice (a slope, a tilted block) cuts it at any
  /// distance; a clearance of c DL leaves a gap of c DL on average between the two, whose
  /// missing neighbours the fluid along it must make up with pressure (docs/validation.md,
  /// "Still water over a sloping bed": 0.5 DL gave the bed +3 % of rho g H without shifting).
  double wall_clearance = 0.0;
  /// Start the fluid in the hydrostatic state of the equation of state (rows moved closer with
  /// depth) instead of on the uncompressed lattice, where p = 0 everywhere and the column first
  /// falls onto itself.
  bool hydrostatic_start = true;
  /// Settling before t = 0 (s of damped motion; 0 = none), and its damping time (s).
  double settle_time = 0.0;
  double settle_damping = 0.1;
  /// Courant number of the settling steps (the Courant rule whatever the run's step); unset:
  /// settling takes the run's steps.
  std::optional<double> settle_courant;

  // [physics]
  double density = 1000.0;              ///< rho0 (kg/m^3)
  double kinematic_viscosity = 1.0e-6;  ///< nu (m^2/s)
  Vec2 gravity{0.0, -9.81};             ///< m/s^2
  std::optional<double> sound_speed;    ///< c0 (m/s); if absent, from sound_speed_factor
  double sound_speed_factor = 10.0;     ///< c0 = factor * sqrt(2 g H_fluid) when c0 not given
  double eos_exponent = 7.0;            ///< gamma
  double artificial_viscosity = 0.02;   ///< Monaghan alpha (-); 0 = off
  /// The artificial viscosity's pairs with boundary particles: the whole relative velocity
  /// ("no-slip") or its part along the wall's normal ("free-slip": no drag on water sliding
  /// along a wall; physics/WallSlip_Colagrossi2003.h).
  ArtificialViscosityWalls artificial_viscosity_walls = ArtificialViscosityWalls::NoSlip;
  /// The wall's shear stress on the water sliding along it from the law of the wall
  /// ("spalding1961": physics/WallFriction_Spalding1961.h), or none beyond the viscosities'
  /// pairs; needs kinematic_viscosity > 0.
  WallFrictionScheme wall_friction = WallFrictionScheme::None;
  /// The flume's side walls, which the 2D scene leaves out: their shear stress on every fluid
  /// particle from the law of the wall ("spalding1961": physics/SideWallFriction_Spalding1961.h),
  /// or none; needs flume_width and kinematic_viscosity > 0.
  SideWallFrictionScheme side_wall_friction = SideWallFrictionScheme::None;
  double flume_width = 0.0;         ///< b, between the side walls (m); 0: not given
  double surface_threshold = 0.97;  ///< beta
  PressureGradientScheme pressure_gradient = PressureGradientScheme::Suzuki2007;
  NegativePressure negative_pressure = NegativePressure::Sun2018Switch;
  double pressure_floor = -99.0e3;  ///< Pa: the lowest pressure kept (vapour pressure, 1 atm)
  NumberDensityScheme number_density = NumberDensityScheme::Continuity;
  double density_diffusion = 0.1;  ///< delta of the diffusive term (-), continuity only
  DensityDiffusionScheme density_diffusion_scheme = DensityDiffusionScheme::Fourtakas2019;
  FreeSurfaceScheme free_surface = FreeSurfaceScheme::Marrone2010;
  ShiftingScheme shifting = ShiftingScheme::Sun2017;
  /// The shift's displacement enters the evolved n's continuity equation
  /// (ParticleShifting_Sun2017.h). Off by default: it keeps the water's volume, but the cavity
  /// behind the block grows and a violent start without artificial viscosity goes unstable
  /// (docs/validation.md, "The still water swells").
  bool shifting_in_continuity = false;
  /// A free-surface particle's pressure held to at most the mean of the water's under it
  /// (physics/SurfacePressureCap.h), except while the particle is struck; evolved n only. Case
  /// I's cavity a third smaller, the quiet benchmarks unchanged (docs/validation.md, "A surface
  /// particle that pushes itself off").
  bool surface_pressure_cap = true;
  /// The variational gradient made to read rho g ("khayyer2011-hydrostatic"), rho g without the
  /// error of the arrangement's shape ("khayyer2011-deviatoric"), without the error of its
  /// shape's change from its rest shape ("khayyer2011-strain") or any linear pressure
  /// ("khayyer2011") exactly on a strained arrangement, away from the surface band and the walls
  /// (physics/GradientRenormalisation_Khayyer2011.h); variational gradient only (with another
  /// gradient the default is "none"). "khayyer2011-strain" from 2026-12-07 (session 13): the
  /// standing wave loses 8.0 % of its amplitude per period against 13.4 %, the experiments'
  /// tables as before (docs/validation.md, "The strain form as the default").
  GradientRenormalisation gradient_renormalisation = GradientRenormalisation::Strain;
  /// "khayyer2011-strain": tau, the time over which a particle's shape is averaged into its rest
  /// shape (s). A wave of period T keeps the correction when 2 pi tau >> T; 5 s passes 0.999 of
  /// a period of 1.2 s (the standing wave of cases/standing-wave) and lets the still tank's shape
  /// become its rest state within its first seconds of settling.
  double strain_memory = 5.0;
  /// The evolved n's rate in the free-surface band: "randles1996" (the kernel gradient
  /// renormalised by the kernel's moments in the rate and the variational gradient together:
  /// physics/DensityRate_Randles1996.h; the cavity behind the block a third to a seventh) or
  /// "summed" (d/dt of the summed n). Continuity scheme and variational gradient only: with any
  /// other, the parser's default is "summed" and the simulation reads "randles1996" as "summed".
  DensityRateScheme density_rate = DensityRateScheme::Randles1996;
  WallPressureScheme wall_pressure = WallPressureScheme::FluidExtrapolated;
  /// The boundary particles' n in the variational gradient: that of their pressure under the
  /// equation of state ("adami2012": physics/WallDensity_Adami2012.h; still water twice as
  /// still, the still tank's breathing mode damped; docs/validation.md, "The wall's density"),
  /// or n0 (3a85288's).
  WallDensityScheme wall_density = WallDensityScheme::Adami2012;
  WallCollisionScheme wall_collision = WallCollisionScheme::Koshizuka1998;
  double collision_distance = 0.8;     ///< x DL: fluid-boundary pairs closer than this collide
  double collision_restitution = 0.2;  ///< e of a fluid particle striking a boundary
  /// Fluid-fluid pairs closer than particle_collision_distance (physics/
  /// ParticleCollision_Jandaghian2021.h; the default from 2026-12-08, session 15: the cavity's
  /// vacancies gone, still water as still, docs/validation.md).
  ParticleCollisionScheme particle_collision = ParticleCollisionScheme::Jandaghian2021;
  double particle_collision_distance = 0.8;     ///< l0 / DL
  double particle_collision_lambda = 0.05;      ///< the background pressure's share of |p_i + p_j|
  double particle_collision_restitution = 0.0;  ///< e of a fluid pair's collision
  /// Pa: the background pressure's least value; 0: a pair at the free surface, where p = 0, is
  /// only collided, never parted (rho0 |g| DL, the first choice, made still water less still).
  double particle_collision_min_pressure = 0.0;

  // [time]
  double end_time = 0.0;  ///< s
  TimeStepMode step_mode = TimeStepMode::Courant;
  double fixed_step = 2.5e-5;
  double courant = 0.4;
  double viscous_number = 0.125;

  // [output]
  double output_interval = 0.0;      ///< s; 0 = only the listed times
  std::vector<double> output_times;  ///< s, increasing
  bool output_initial = true;        ///< write the state at t = 0
  std::vector<FieldId> output_fields;
  std::vector<ParticleKind> output_kinds;
  bool output_double_precision = false;

  // [checkpoint] (docs/checkpoints.md)
  double checkpoint_interval = 0.0;         ///< s of simulated time between checkpoints; 0: not
  double checkpoint_wall_interval = 600.0;  ///< s of wall time between checkpoints; 0: not
  int checkpoint_keep = 2;                  ///< newest checkpoints kept

  // [neighbours]
  double neighbour_skin =
      0.2;  ///< list cutoff = re + skin x DL; lists kept while particles move < skin/2
  int sort_interval = 50;  ///< steps between reorderings of fluid particles by cell

  // [run]
  /// The most memory a run of the case may take (bytes); unset: what the machine has available
  /// (`--max-memory` overrides both).
  std::optional<std::uint64_t> max_memory;

  // [stability]
  double max_density_ratio = 1.2;  ///< n*/n0 above this stops the run
  std::optional<std::pair<Vec2, Vec2>> domain;

  std::optional<TankSpec> tank;    ///< already expanded into walls and fluids
  std::optional<BlockSpec> block;  ///< already added to the walls
  std::optional<BodySpec> body;    ///< the wall that moves as a rigid body (the block's)
  std::vector<SectionSpec> sections;
  PostSpec post;
  GaugeSpec gauges;
  FiguresSpec figures;
  std::vector<FluidRegionSpec> fluids;
  std::vector<WallSpec> walls;

  double re() const { return re_over_dl * dl; }
};

/// The time-step rule of a case, with the sound speed its scene was given.
inline TimeStepRule time_step_rule(const CaseSpec& spec, double c0) {
  TimeStepRule rule;
  rule.mode = spec.step_mode;
  rule.fixed = spec.fixed_step;
  rule.courant = spec.courant;
  rule.viscous_number = spec.viscous_number;
  rule.dl = spec.dl;
  rule.c0 = c0;
  rule.nu = spec.kinematic_viscosity;
  return rule;
}

/// The time-step rule of the settling before t = 0: the Courant rule with settle_courant if the
/// case gives it, else the run's rule.
inline TimeStepRule settle_step_rule(const CaseSpec& spec, double c0) {
  TimeStepRule rule = time_step_rule(spec, c0);
  if (spec.settle_courant) {
    rule.mode = TimeStepMode::Courant;
    rule.courant = *spec.settle_courant;
  }
  return rule;
}

/// The gradient renormalisation a run applies: the case's with the variational gradient, none
/// with any other (the case parser gives another gradient "none" unless one is asked for, and
/// refuses one that is; a spec built in code may combine them).
inline GradientRenormalisation renormalisation_in_effect(const CaseSpec& c) {
  return c.pressure_gradient == PressureGradientScheme::Suzuki2007 ? c.gradient_renormalisation
                                                                   : GradientRenormalisation::None;
}

/// The stabilisation of docs/method.md ("A stabilised step") switched off: negative pressures
/// set to zero, the summed number density (and so its summed rate), the threshold's free
/// surface, no shifting, the fluid kept half a DL off the walls, the boundary particles at n0,
/// the gradient not renormalised and no particle collision; the scheme of commit 3a85288, kept
/// to measure the cures against.
inline void use_scheme_3a85288(CaseSpec& c) {
  c.gradient_renormalisation = GradientRenormalisation::None;
  c.negative_pressure = NegativePressure::Zero;
  c.number_density = NumberDensityScheme::Summation;
  c.free_surface = FreeSurfaceScheme::Koshizuka1996;
  c.shifting = ShiftingScheme::None;
  c.wall_clearance = 0.5;
  c.wall_density = WallDensityScheme::ReferenceN0;
  c.density_rate = DensityRateScheme::Summed;
  c.particle_collision = ParticleCollisionScheme::None;
}

}  // namespace wcmps
