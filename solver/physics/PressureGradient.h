#pragma once
/// @file PressureGradient.h
/// @brief Pressure-gradient schemes of the correction step (thesis Eq. 2.15). A case file picks
/// one by name from kPressureGradientSchemes; the phase is instantiated once per scheme through
/// with_pressure_gradient(), so the per-particle loop has no branch or virtual call.

#include <cmath>
#include <cstdint>
#include <limits>
#include <string_view>

#include "core/SchemeTable.h"
#include "core/Vec2.h"
#include "operators/MpsOperators.h"
#include "physics/DensityRate_Randles1996.h"
#include "physics/GradientRenormalisation_Khayyer2011.h"
#include "physics/PressureGradientAvx512.h"

namespace wcmps {

/// What a scheme's gradient reads besides positions: the pressure p, or p / n^2 (boundary
/// particles p / n0^2), which the correction phase prepares once per step.
enum class GradientInput { Pressure, PressureOverNumberDensitySquared };

/// Koshizuka, Nobe & Oka (1998), thesis Eq. 2.19: the MPS gradient with p_i replaced by the
/// minimum pressure of the neighbourhood. Always repulsive; the study's choice.
struct PressureGradient_Koshizuka1998Min {
  static constexpr GradientInput kInput = GradientInput::Pressure;
  static Vec2 gradient(const MpsOperators& ops, std::int64_t i, IdRange nb, const double* x,
                       const double* y, const double* p) {
    return ops.gradient_neighbourhood_min(i, nb, x, y, p);
  }
  /// The part of gradient() that comes from the neighbours in `part` (a subset of nb).
  static Vec2 gradient_part(const MpsOperators& ops, std::int64_t i, IdRange nb, IdRange part,
                            const double* x, const double* y, const double* p) {
    return ops.gradient_with_reference(i, part, x, y, p, ops.neighbourhood_min(i, nb, x, y, p));
  }
};

/// Koshizuka & Oka (1996), thesis Eq. 2.18: the plain MPS gradient with p_i. The study notes
/// it is unstable (pairs attract where p_j < p_i); offered for comparison.
struct PressureGradient_Koshizuka1996 {
  static constexpr GradientInput kInput = GradientInput::Pressure;
  static Vec2 gradient(const MpsOperators& ops, std::int64_t i, IdRange nb, const double* x,
                       const double* y, const double* p) {
    return ops.gradient(i, nb, x, y, p);
  }
  static Vec2 gradient_part(const MpsOperators& ops, std::int64_t i, IdRange /*nb*/, IdRange part,
                            const double* x, const double* y, const double* p) {
    return ops.gradient(i, part, x, y, p);
  }
};

/// The variational pressure gradient of the summed number density (Suzuki, Koshizuka & Oka
/// 2007, Comput. Methods Appl. Mech. Engrg. 196, 2876-2894; MpsOperators::gradient_variational):
/// the pressure force is minus the derivative of the fluid's potential energy, so a particle
/// system at rest cannot gain energy from it, and pair forces cancel. kSwitch: the
/// tensile-instability control of Sun et al. (2018) (physics/NegativePressure_Sun2018.h): a
/// particle's own term p_i/n_i^2 taken as its absolute value, so that pairs do not attract where
/// p_i < 0. kRenormalisation: outside the free-surface band and away from the walls, the
/// difference part renormalised, or the hydrostatic gradient read exactly (wholly, or without
/// the error of the arrangement's shape) (physics/GradientRenormalisation_Khayyer2011.h).
template <bool kSwitch, GradientRenormalisation kRenormalisation = GradientRenormalisation::None>
struct PressureGradient_Suzuki2007 {
  static constexpr GradientInput kInput = GradientInput::PressureOverNumberDensitySquared;
  /// The renormalisation that adds a term for rho g ("khayyer2011-hydrostatic", "-deviatoric").
  static constexpr bool kHydrostatic = kRenormalisation == GradientRenormalisation::Hydrostatic ||
                                       kRenormalisation == GradientRenormalisation::Deviatoric ||
                                       kRenormalisation == GradientRenormalisation::Strain;
  /// Whether the AVX-512 pass applies (`rows`): the gradient not renormalised, or with a
  /// hydrostatic form (whose M the pass sums beside the gradient).
  static constexpr bool kRows = kRenormalisation == GradientRenormalisation::None || kHydrostatic;
  /// With the switch: particles it leaves out (1), the free-surface region (Sun et al. 2018).
  const std::uint8_t* exempt = nullptr;
  /// With a renormalisation: the free-surface band (1) and the fluid with a boundary particle in
  /// its list (1), where it is not applied.
  const std::uint8_t* band = nullptr;
  const std::uint8_t* near_wall = nullptr;
  /// rho0 g: the hydrostatic gradient that the "khayyer2011-hydrostatic" form reads exactly.
  Vec2 rho_g;
  /// With density_rate = "randles1996": the band's correctors q (L - I), gathered by every
  /// fluid particle (DensityRate_Randles1996::gathered_gradient); unset (xx null) otherwise.
  DensityRate_Randles1996::Excess excess;
  /// With "khayyer2011-strain": the particles' rest shapes, read and advanced.
  ShapeMemory memory{};
  /// The rows of the AVX-512 pass (PressureGradientAvx512.h), packed for this step's r*, q and
  /// correctors; null: the portable loops.
  const PairRow* rows = nullptr;

  double own(const double* p_over_n2, std::int64_t i) const {
    if constexpr (kSwitch) {
      if (!(exempt && exempt[i])) return std::abs(p_over_n2[i]);
    }
    return p_over_n2[i];
  }
  Vec2 gradient(const MpsOperators& ops, std::int64_t i, IdRange nb, const double* x,
                const double* y, const double* p_over_n2) const {
    return gradient_part(ops, i, nb, nb, x, y, p_over_n2);
  }
  /// The part of gradient() that comes from the neighbours in `part` (a subset of nb).
  Vec2 gradient_part(const MpsOperators& ops, std::int64_t i, IdRange nb, IdRange part,
                     const double* x, const double* y, const double* p_over_n2) const {
    if constexpr (kRenormalisation != GradientRenormalisation::None) {
      const bool whole = part.first == nb.first && part.last == nb.last;
      if (!(band && band[i]) && !(near_wall && near_wall[i])) {
        using R = GradientRenormalisation_Khayyer2011;
        const double c = ops.gradient_correction() * ops.n0();
        const double ti = own(p_over_n2, i);
        if constexpr (kRenormalisation == GradientRenormalisation::Khayyer2011) {
          const VariationalSums s = ops.variational_sums(i, nb, part, x, y, p_over_n2);
          const Vec2 d = R::renormalised(s.m, {s.dx, s.dy});
          const double t = ti + p_over_n2[i];
          return Vec2{c * (d.x + t * s.sx), c * (d.y + t * s.sy)} + band_excess(ops, i, part, x, y);
        } else {
#if WCMPS_PAIRS_AVX512
          if (rows && whole) {
            double m[3];
            const Vec2 g =
                excess.reaches(i)
                    ? variational_gradient_avx512<true, true>(ops.kernel(), i, nb, rows, ti, m)
                    : variational_gradient_avx512<false, true>(ops.kernel(), i, nb, rows, ti, m);
            return g * c + shape_term(i, ops.whole_moments(m[0], m[1], m[2]), true);
          }
#endif
          const VariationalMoments s = ops.variational_moments(i, nb, part, x, y, p_over_n2, ti);
          const Vec2 h = shape_term(i, s.m, whole);
          return Vec2{c * s.gx + h.x, c * s.gy + h.y} + band_excess(ops, i, part, x, y);
        }
      }
      if constexpr (kRenormalisation == GradientRenormalisation::Strain) {
        if (whole && memory.next_a) forget_shape(i);
      }
    }
#if WCMPS_PAIRS_AVX512
    if (rows) {
      const Vec2 g =
          excess.reaches(i)
              ? variational_gradient_avx512<true>(ops.kernel(), i, part, rows, own(p_over_n2, i))
              : variational_gradient_avx512<false>(ops.kernel(), i, part, rows, own(p_over_n2, i));
      return g * (ops.gradient_correction() * ops.n0());
    }
#endif
    if (excess.reaches(i)) {
      const Vec2 g = DensityRate_Randles1996::gathered_gradient(
          ops.kernel(), i, part, x, y, p_over_n2, own(p_over_n2, i), excess);
      return g * (ops.gradient_correction() * ops.n0());
    }
    return ops.gradient_variational(i, part, x, y, p_over_n2, own(p_over_n2, i));
  }
  /// The hydrostatic forms' term for i with M_i = m; "khayyer2011-strain" also advances i's
  /// rest shape when the sum took the whole neighbourhood.
  Vec2 shape_term(std::int64_t i, const SecondMoments& m, bool whole) const {
    using R = GradientRenormalisation_Khayyer2011;
    if constexpr (kRenormalisation == GradientRenormalisation::Strain) {
      if (!R::applies(m)) {
        if (whole && memory.next_a) forget_shape(i);
        return {};
      }
      const double a = 0.5 * (m.mxx - m.myy), b = m.mxy;
      double a0 = memory.rest_a ? memory.rest_a[i] : a;
      double b0 = memory.rest_b ? memory.rest_b[i] : b;
      if (std::isnan(a0)) {
        a0 = a;
        b0 = b;
      }
      if (whole && memory.next_a) {
        memory.next_a[i] = a0 + memory.rate * (a - a0);
        memory.next_b[i] = b0 + memory.rate * (b - b0);
      }
      return R::strain(m, rho_g, a0, b0);
    } else {
      return R::hydrostatic_term<kRenormalisation>(m, rho_g);
    }
  }
  /// "khayyer2011-strain": i is not corrected in this step, and has no rest shape after it.
  void forget_shape(std::int64_t i) const {
    memory.next_a[i] = std::numeric_limits<double>::quiet_NaN();
    memory.next_b[i] = std::numeric_limits<double>::quiet_NaN();
  }
  /// What the band's correctors add to a renormalised particle's gradient.
  Vec2 band_excess(const MpsOperators& ops, std::int64_t i, IdRange part, const double* x,
                   const double* y) const {
    if (!excess.reaches(i)) return {};
    return DensityRate_Randles1996::gathered_excess(ops.kernel(), i, part, x, y, excess) *
           (ops.gradient_correction() * ops.n0());
  }
};

enum class PressureGradientScheme { Koshizuka1998Min, Koshizuka1996, Suzuki2007 };

inline constexpr SchemeEntry<PressureGradientScheme> kPressureGradientSchemes[] = {
    {"koshizuka1998-min", PressureGradientScheme::Koshizuka1998Min,
     "Koshizuka, Nobe & Oka (1998), Int. J. Numer. Meth. Fluids 26, 751-769; thesis Eq. 2.19"},
    {"koshizuka1996", PressureGradientScheme::Koshizuka1996,
     "Koshizuka & Oka (1996), Nucl. Sci. Eng. 123, 421-434; thesis Eq. 2.18"},
    {"suzuki2007-variational", PressureGradientScheme::Suzuki2007,
     "Suzuki, Koshizuka & Oka (2007), Comput. Methods Appl. Mech. Engrg. 196, 2876-2894"},
};

/// What the variational gradient takes from the step besides its inputs.
struct GradientOptions {
  bool tensile_switch = false;
  GradientRenormalisation renormalisation = GradientRenormalisation::None;
  /// The free-surface band: left out by the switch and by the renormalisation.
  const std::uint8_t* band = nullptr;
  const std::uint8_t* near_wall = nullptr;  ///< fluid near a boundary, not renormalised
  Vec2 rho_g;                               ///< rho0 g
  DensityRate_Randles1996::Excess excess;   ///< the band's correctors (density_rate)
  ShapeMemory memory{};                     ///< the rest shapes ("khayyer2011-strain")
};

/// Calls f with the variational gradient renormalised by kForm, with or without the switch (which
/// exempts the band, as the renormalisation does).
template <GradientRenormalisation kForm, class F>
decltype(auto) with_renormalised_gradient(const GradientOptions& o, F&& f) {
  if (o.tensile_switch) {
    return f(PressureGradient_Suzuki2007<true, kForm>{o.band, o.band, o.near_wall, o.rho_g,
                                                      o.excess, o.memory});
  }
  return f(PressureGradient_Suzuki2007<false, kForm>{nullptr, o.band, o.near_wall, o.rho_g,
                                                     o.excess, o.memory});
}

/// Calls f(Scheme{}) with the scheme type that `s` names, the variational gradient with the
/// switch of Sun et al. (2018) and the renormalisation that `o` selects (the other two have no
/// own term to switch and are not renormalised: they are unchanged).
template <class F>
decltype(auto) with_pressure_gradient(PressureGradientScheme s, const GradientOptions& o, F&& f) {
  using R = GradientRenormalisation;
  const std::uint8_t* exempt = o.band;  // the switch's
  switch (s) {
    case PressureGradientScheme::Koshizuka1996:
      return f(PressureGradient_Koshizuka1996{});
    case PressureGradientScheme::Suzuki2007:
      switch (o.renormalisation) {
        case R::Khayyer2011:
          return with_renormalised_gradient<R::Khayyer2011>(o, f);
        case R::Hydrostatic:
          return with_renormalised_gradient<R::Hydrostatic>(o, f);
        case R::Deviatoric:
          return with_renormalised_gradient<R::Deviatoric>(o, f);
        case R::Strain:
          return with_renormalised_gradient<R::Strain>(o, f);
        case R::None:
          break;
      }
      if (o.tensile_switch)
        return f(PressureGradient_Suzuki2007<true>{exempt, nullptr, nullptr, {}, o.excess, {}});
      return f(PressureGradient_Suzuki2007<false>{nullptr, nullptr, nullptr, {}, o.excess, {}});
    case PressureGradientScheme::Koshizuka1998Min:
      break;
  }
  return f(PressureGradient_Koshizuka1998Min{});
}

}  // namespace wcmps
