#pragma once
/// @file GradientRenormalisation_Khayyer2011.h
/// @brief The variational pressure gradient made to read a linear pressure field, or the
/// hydrostatic one, exactly on any arrangement of the particles ([physics]
/// gradient_renormalisation).
///
/// The variational gradient (PressureGradient_Suzuki2007) is exact for a linear field on the
/// initial lattice only: its constant C is set there. Split by q_j = q_i + (q_j - q_i), q = p/n^2,
///
///     <grad p>_i = C n0 [ sum_j (q_j - q_i) W'(r_ij) e_ij  +  (q_i + q_i') sum_j W'(r_ij) e_ij ],
///
/// (e_ij the unit vector from j to i, q_i' the particle's own term: q_i, or |q_i| under the
/// tensile switch) its first part, the difference part, is M_i grad(p) for a linear field, with
///
///     M_i = (C / n0) sum_j (-W'(r_ij) r_ij) e_ij e_ij^T,
///
/// the identity on the lattice and not elsewhere: where the flow shears or stretches the
/// arrangement, M_i departs from the identity by the strain, and the hydrostatic gradient rho g,
/// by far the largest part of every gradient in water under gravity, is read with that error. In
/// a standing wave of slope ka the strain is of order ka, so the error is of the order of the
/// wave's own restoring force rho g k a, whatever DL is: it shortened the period by 2.7 % and
/// handed the wave's energy to the particles (docs/validation.md, "Wave damping: a standing
/// wave"). The second part, zero on any arrangement symmetric about i, is what pushes clumping
/// particles apart (the variational form's own stabilising term); every form keeps it as it is.
///
/// "khayyer2011": the corrective matrix of Khayyer & Gotoh (2011, J. Comput. Phys. 230,
/// 3093-3118), after the normalisation of Randles & Libersky (1996, Comput. Methods Appl. Mech.
/// Engrg. 139, 375-408) in SPH: the difference part multiplied by L_i = M_i^-1, exact for any
/// linear field (they correct the whole MPS gradient of Eq. 2.18; the split is ours). At an
/// impact the difference part is the impact's, and L_i rescales it where the arrangement is
/// crushed: the Lobovsky dam break stopped at 0.91 s (a splash particle thrown out of the
/// domain; with the fluid near the walls corrected too, at 1.20 s, n* > 1.2 n0 where the
/// plunging jet re-enters).
///
/// "khayyer2011-hydrostatic" (this project's form): the correction applied to the hydrostatic
/// gradient alone. The variational gradient reads rho g as M_i rho g, so adding
///
///     (I - M_i) rho g
///
/// makes it read rho g exactly, and leaves every other part of the gradient (an impact, a wave's
/// dynamic pressure) as the variational form reads it. Nothing else is needed: not the surface's
/// height, not a reference pressure. In water that is not under the hydrostatic gradient (a jet
/// in free fall) the term is an error of its own, (I - M_i) g per unit mass; there the water is
/// mostly the free-surface band, which is left out.
///
/// "khayyer2011-deviatoric" (this project's form, 2026-12-07): the hydrostatic form with M_i's
/// deviatoric part alone, M_i - (tr M_i / 2) I,
///
///     ((tr M_i / 2) I - M_i) rho g,
///
/// so that the gradient reads rho g through the arrangement's compression as the variational
/// form does, without its shape's error. A wave's strain keeps the water's volume (it is
/// deviatoric), and this form reads it as the hydrostatic form does (the standing wave's period
/// 0.8 % short of linear theory against 2.8 %, its loss per period 8.9 % against 13.5 %). Still
/// water under gravity is compressed evenly away from the walls and the surface (M_i a multiple of
/// I, near enough) and balances its weight through that compression: the hydrostatic form, which
/// reads the compression away, moved the balance (the pressure error's growth with depth
/// doubled), and this form leaves it where the variational gradient puts it. Its still water
/// settles to about twice the defaults' spurious speed (about 2 against 1 mm/s from 10 s on, most
/// of it in the rows under the surface and steady in time; docs/validation.md, "The shape's error
/// alone"): not the default.
///
/// "khayyer2011-strain" (this project's form, 2026-12-07): the deviatoric form read against each
/// particle's rest shape. The shape a settled arrangement has and keeps is not a strain of the
/// water: it is the disorder the particles settled into, and the variational gradient's balance
/// of the water's weight already holds it (still water is still with no correction at all).
/// Corrected particle by particle, its noise is a body force that is not the gradient of anything
/// and stirs the still water (the deviatoric form's steady circulation). This form corrects only
/// the shape's change from its rest shape S_i, the particle's shape averaged over the time
/// strain_memory tau along its path:
///
///     -(D_i - S_i) rho g,   D_i = M_i - (tr M_i / 2) I,   dS_i/dt = (D_i - S_i) / tau,
///
/// so a shape that lasts longer than tau is taken as the rest state, and a wave's strain, which
/// comes and goes with its period T, is read as the deviatoric form reads it when 2 pi tau >> T
/// (the filter passes omega tau / (1 + omega^2 tau^2)^(1/2) of it, 0.999 at T = 1.2 s, tau = 5 s,
/// with a phase lead of 1 / (omega tau): a share of the correction in phase with the velocity,
/// which pushes along it, an anti-damping of about 0.6 % of amplitude per period at tau = 5 s for
/// the standing wave; docs/method.md). While the water settles S_i is D_i (the settled arrangement
/// is the rest state), and a particle that enters the corrected water (from the band, a wall's
/// reach, or a crushed neighbourhood) starts from its own shape: no correction jumps on.
///
/// All four forms are left out where the kernel is not full or M_i does not measure the flow: in
/// the free-surface band (the surface particles and those within re of one,
/// Simulation::find_surface_band), where M_i loses a direction; for fluid with a boundary particle
/// in its list, whose M_i counts the wall's rows, laid on the wall's own uncompressed lattice (with
/// the correction there the start-up transient of still water decayed half as fast: rms 0.0041
/// against 0.0023 m/s at 7 s); and wherever M_i's smallest eigenvalue is below kMinEigenvalue.
/// Pair forces no longer cancel exactly, and the force is no longer the derivative of an energy.

#include <cmath>
#include <cstdint>

#include "core/SchemeTable.h"
#include "core/Vec2.h"
#include "operators/MpsOperators.h"

namespace wcmps {

enum class GradientRenormalisation { None, Khayyer2011, Hydrostatic, Deviatoric, Strain };

inline constexpr SchemeEntry<GradientRenormalisation> kGradientRenormalisationSchemes[] = {
    {"none", GradientRenormalisation::None, ""},
    {"khayyer2011", GradientRenormalisation::Khayyer2011,
     "Khayyer & Gotoh (2011), J. Comput. Phys. 230, 3093-3118; Randles & Libersky (1996), "
     "Comput. Methods Appl. Mech. Engrg. 139, 375-408"},
    {"khayyer2011-hydrostatic", GradientRenormalisation::Hydrostatic,
     "the corrective matrix of Khayyer & Gotoh (2011) applied to the hydrostatic gradient "
     "rho g alone (this project's form)"},
    {"khayyer2011-deviatoric", GradientRenormalisation::Deviatoric,
     "the deviatoric part of the corrective matrix of Khayyer & Gotoh (2011) applied to the "
     "hydrostatic gradient rho g alone (this project's form)"},
    {"khayyer2011-strain", GradientRenormalisation::Strain,
     "the deviatoric part of the corrective matrix of Khayyer & Gotoh (2011) applied to the "
     "hydrostatic gradient rho g as it changes from each particle's rest shape (this project's "
     "form)"},
};

/// "khayyer2011-strain": each fluid particle's rest shape S_i = [[a, b], [b, -a]] (the `now`
/// state's, read) and the next state's (written by the gradient's pass: S_i moved towards D_i by
/// `rate` = dt / tau, or set to D_i while the water settles). NaN: no rest shape yet (the
/// particle was not corrected in the last step), taken as D_i. Null: no memory (the body's force
/// at the start), every S_i taken as D_i.
struct ShapeMemory {
  const double* rest_a = nullptr;
  const double* rest_b = nullptr;
  double* next_a = nullptr;
  double* next_b = nullptr;
  double rate = 0.0;
};

struct GradientRenormalisation_Khayyer2011 {
  /// M_i's smallest eigenvalue below which no form is applied. On the lattice it is 1; a
  /// particle that has lost every neighbour on one side of a line through it has 0.5 (the half
  /// kernel), where L_i would double the gradient across that line. The interior of a flowing
  /// arrangement stays near 1 (a standing wave's strain, about ka, moves it by a few per cent),
  /// so the bound corrects all of it and doubles nothing.
  static constexpr double kMinEigenvalue = 0.5;

  /// Whether M_i is near enough to full (above).
  static bool applies(const SecondMoments& s) {
    const double tr = s.mxx + s.myy, det = s.mxx * s.myy - s.mxy * s.mxy;
    const double disc = 0.25 * tr * tr - det;
    return 0.5 * tr - std::sqrt(disc > 0.0 ? disc : 0.0) > kMinEigenvalue;
  }

  /// "khayyer2011": L_i v, v the difference part, or v where M_i is too far from full.
  static Vec2 renormalised(const SecondMoments& s, Vec2 v) {
    if (!applies(s)) return v;
    const double det = s.mxx * s.myy - s.mxy * s.mxy;
    return {(s.myy * v.x - s.mxy * v.y) / det, (s.mxx * v.y - s.mxy * v.x) / det};
  }

  /// "khayyer2011-hydrostatic": what the gradient adds to read rho g exactly, (I - M_i) rho g,
  /// for the part of i's neighbourhood that the sums took: its share of I (the share of M_i's trace
  /// it holds, so that the parts add up to the whole) less its terms of M_i. Zero where M_i is
  /// too far from full.
  static Vec2 hydrostatic(const SecondMoments& s, Vec2 rho_g) {
    if (!applies(s)) return {};
    const double share = (s.pmxx + s.pmyy) / (s.mxx + s.myy);
    return {share * rho_g.x - (s.pmxx * rho_g.x + s.pmxy * rho_g.y),
            share * rho_g.y - (s.pmxy * rho_g.x + s.pmyy * rho_g.y)};
  }

  /// "khayyer2011-deviatoric": ((tr M_i / 2) I - M_i) rho g over the part's terms of M_i (the
  /// parts add up to the whole: it is linear in them). Zero where M_i is too far from full.
  static Vec2 deviatoric(const SecondMoments& s, Vec2 rho_g) {
    if (!applies(s)) return {};
    const double half_trace = 0.5 * (s.pmxx + s.pmyy);
    return {half_trace * rho_g.x - (s.pmxx * rho_g.x + s.pmxy * rho_g.y),
            half_trace * rho_g.y - (s.pmxy * rho_g.x + s.pmyy * rho_g.y)};
  }

  /// "khayyer2011-strain": -(D_i - S_i) rho g over the part's terms of M_i, with the part's
  /// share of S_i (its share of M_i's trace, as in hydrostatic()), S_i = [[a0, b0], [b0, -a0]].
  /// Zero where M_i is too far from full.
  static Vec2 strain(const SecondMoments& s, Vec2 rho_g, double a0, double b0) {
    if (!applies(s)) return {};
    const double share = (s.pmxx + s.pmyy) / (s.mxx + s.myy);
    const double a = 0.5 * (s.pmxx - s.pmyy) - share * a0, b = s.pmxy - share * b0;
    return {-(a * rho_g.x + b * rho_g.y), a * rho_g.y - b * rho_g.x};
  }

  /// The hydrostatic or the deviatoric form's term.
  template <GradientRenormalisation kForm>
  static Vec2 hydrostatic_term(const SecondMoments& s, Vec2 rho_g) {
    static_assert(kForm == GradientRenormalisation::Hydrostatic ||
                  kForm == GradientRenormalisation::Deviatoric);
    if constexpr (kForm == GradientRenormalisation::Hydrostatic) return hydrostatic(s, rho_g);
    return deviatoric(s, rho_g);
  }
};

}  // namespace wcmps
