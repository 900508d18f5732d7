#pragma once
/// @file FreeSurface_Marrone2010.h
/// @brief Free-surface detection by a scan of the region outside the particle (Marrone,
/// Colagrossi, Le Touzé & Graziani 2010, J. Comput. Phys. 229, 3652-3663), in place of the
/// number-density threshold of Koshizuka & Oka (1996, thesis Eq. 2.10) ([physics]
/// free_surface).
///
/// The threshold n* < beta n0 flags every particle whose neighbourhood is thinned, and inside a
/// disordered wake that is many: they get p = 0, holes of zero pressure in the water. Here the
/// threshold only names candidates; a candidate i is on the free surface when the "umbrella"
/// region ahead of it along its outward normal nu holds no particle (fluid or boundary):
///
///     nu = -G_i / |G_i|,  G_i the gradient of n/n0 (it points into the water),  T = r_i + h nu,
///     j is in the region if  |r_j - r_i| >= sqrt(2) h  and  |r_j - T| < h,
///                        or  |r_j - r_i| <  sqrt(2) h  and  |nu . (r_j - T)| + |tau . (r_j - T)| <
///                        h,
///
/// a cone of half-angle 45 degrees from r_i capped by the disc of radius h about T (Marrone et
/// al.'s Fig. 3). h = re/2, the kernel's smoothing length as an SPH code would count it (re =
/// 2h): the region then lies within re, inside the particle's list, and holds about 9 particles
/// of a full lattice, so a disordered interior does not leave it empty, while a particle one row
/// under a flat surface has the row above in it (a test checks both). A candidate with n < n0/2
/// is on the surface outright: it lacks more than half of its kernel, which no particle inside
/// the water does (the water's compression moves n by 1 %, a wake's disorder by a few), but the
/// particles of a drop or of a thread of water one particle thick do, and along a thread G points
/// along it, where the scan would find the next particle. Where G is too small to give a
/// direction (|G| < 0.1 / re: an interior particle whose thinning is even all round), the region
/// is scanned along +x, -x, +y and -y, and the particle is on the surface if any of the four is
/// empty.
/// Marrone et al. pick candidates by the renormalisation matrix's eigenvalue; the summed number
/// density does the same here at no extra cost (it is summed in the same pass).
///
/// Walls: Marrone et al.'s walls are mirror images of the fluid, present only where there is
/// water. Ours are fixed rows that stand in the air too, above the waterline, and there they
/// would fill the region of the fluid particle in the corner between the wall and the surface:
/// it would not be flagged, would take the tension of the equation of state instead of p = 0,
/// pass it to the dry wall above it, and climb the wall (measured in still water: a jet up both
/// walls within 0.6 s). So a boundary particle fills the region only where it is wet. A wall
/// particle is dry when it is a candidate (its summed n < beta n0) and the region along its own
/// normal -G_w/|G_w| holds no fluid particle; a ghost is wet or dry with its wall particle. A
/// wall under water has water in front of it, or a full kernel; one that water has just left by a
/// gap (the top of a body moving away) still has water in its region, and keeps the particles
/// across the gap off the surface, so that the suction holds.

#include <cmath>
#include <cstdint>
#include <string_view>

#include "core/SchemeTable.h"
#include "core/Vec2.h"
#include "neighbours/NeighbourList.h"

namespace wcmps {

enum class FreeSurfaceScheme { Koshizuka1996, Marrone2010 };

inline constexpr SchemeEntry<FreeSurfaceScheme> kFreeSurfaceSchemes[] = {
    {"koshizuka1996", FreeSurfaceScheme::Koshizuka1996,
     "Koshizuka & Oka (1996), Nucl. Sci. Eng. 123, 421-434; thesis Eq. 2.10"},
    {"marrone2010", FreeSurfaceScheme::Marrone2010,
     "Marrone, Colagrossi, Le Touze & Graziani (2010), J. Comput. Phys. 229, 3652-3663"},
};

struct FreeSurface_Marrone2010 {
  /// Witness slots per particle (is_surface): one per region of the four-direction scan, the
  /// first also the region along the normal's.
  static constexpr int kWitnesses = 4;

  double beta;  ///< candidates: summed n < beta n0
  double n0;
  double h;  ///< scan radius (m), re / 2

  /// Where particle j lies against the umbrella region of particle i along the unit vector nu: a
  /// signed distance, < 0 inside. (xi, yi) is r_i and (tx, ty) is T = r_i + h nu.
  double outside(double xi, double yi, double tx, double ty, Vec2 nu, double xj, double yj) const {
    const double dx = xj - xi, dy = yj - yi;
    const double ex = xj - tx, ey = yj - ty;
    const double along = nu.x * ex + nu.y * ey, across = nu.x * ey - nu.y * ex;
    const double h2 = h * h;
    return dx * dx + dy * dy >= 2.0 * h2 ? ex * ex + ey * ey - h2
                                         : std::abs(along) + std::abs(across) - h;
  }

  /// The place in nb of a particle j with fills(j) in the umbrella region of particle i along the
  /// unit vector nu (the last such in the list), or -1 where the region holds none.
  ///
  /// The whole list is tested without a branch, so that the loop vectorises (both sides of the
  /// cone-or-disc test computed and selected; fills read for every pair: give it a plain array's
  /// load; it is taken by value, as GCC 12 does not vectorise the loop through a reference to
  /// the caller's lambda). A scalar loop that stops at the first filling particle spent most of
  /// its time on mispredicted branches, and stopping after each chunk of 16 pairs left the
  /// chunks' scalar remainders to dominate (both measured in docs/performance.md).
  template <class Fills>
  int region_filler(std::int64_t i, IdRange nb, const double* x, const double* y, Vec2 nu,
                    Fills fills) const {
    const double xi = x[i], yi = y[i];
    const double tx = xi + nu.x * h, ty = yi + nu.y * h;
    const std::int32_t* id = nb.first;
    const int size = static_cast<int>(nb.size());
    int last = -1;
#pragma omp simd reduction(max : last)
    for (int k = 0; k < size; ++k) {
      const std::int32_t j = id[k];
      // Loaded before the test, and the test one comparison of a selected signed distance:
      // GCC 12 if-converts (and vectorises) only that form (e - h < 0 is e < h exactly).
      const int fill = fills(j) ? 1 : 0;
      const int hit = fill & (outside(xi, yi, tx, ty, nu, x[j], y[j]) < 0.0 ? 1 : 0);
      const int at = hit ? k : -1;
      last = at > last ? at : last;
    }
    return last;
  }

  /// Whether the umbrella region of particle i along nu holds no particle j with fills(j).
  template <class Fills>
  bool region_empty(std::int64_t i, IdRange nb, const double* x, const double* y, Vec2 nu,
                    Fills fills) const {
    return region_filler(i, nb, x, y, nu, fills) < 0;
  }

  /// Whether particle j is in the region of i along nu by more than rounding could move it: the
  /// test of a witness (is_surface), which then stands for the scan. The margin, 1e-9 h, is
  /// millions of times the rounding of these few products of lengths of order h, so the scan
  /// would find j inside too and the answer is the scan's to the bit.
  bool holds(std::int64_t i, std::int32_t j, const double* x, const double* y, Vec2 nu) const {
    const double xi = x[i], yi = y[i];
    return outside(xi, yi, xi + nu.x * h, yi + nu.y * h, nu, x[j], y[j]) < -1e-9 * h;
  }

  /// Whether particle i, with summed number density n and gradient G of n/n0, is on the free
  /// surface, its region filled by the particles j with fills(j).
  ///
  /// With witnesses (kWitnesses slots of i: particles that filled its regions at the last scan;
  /// any index of a particle will do): a region whose witness still fills it is not scanned, and
  /// a scan that finds the region filled leaves its filler there for the next step. A candidate
  /// inside the water (most of them, in a disordered flow) keeps its regions' particles from step
  /// to step, so one pair is tested for each region instead of its list (the dam break to 1 s:
  /// 98.6 % of the regions along a normal); the answer is the scan's either way.
  template <class Fills>
  bool is_surface(std::int64_t i, IdRange nb, const double* x, const double* y, double n,
                  Vec2 gradient, Fills&& fills, std::int32_t* witness = nullptr) const {
    if (n >= beta * n0) return false;
    if (n < 0.5 * n0) return true;
    // Region `slot` along nu is empty.
    const auto empty = [&](Vec2 nu, int slot) {
      if (witness && fills(witness[slot]) && holds(i, witness[slot], x, y, nu)) return false;
      const int k = region_filler(i, nb, x, y, nu, fills);
      if (k >= 0 && witness) witness[slot] = nb.first[k];
      return k < 0;
    };
    const double g = norm(gradient);
    if (g * 2.0 * h >= 0.1) return empty(gradient * (-1.0 / g), 0);
    const Vec2 axes[kWitnesses] = {{1.0, 0.0}, {-1.0, 0.0}, {0.0, 1.0}, {0.0, -1.0}};
    for (int a = 0; a < kWitnesses; ++a) {
      if (empty(axes[a], a)) return true;
    }
    return false;
  }

  /// Whether every particle fills the region (a cloud of fluid alone).
  bool is_surface(std::int64_t i, IdRange nb, const double* x, const double* y, double n,
                  Vec2 gradient) const {
    return is_surface(i, nb, x, y, n, gradient, [](std::int32_t) { return true; });
  }

  /// Whether wall particle w, with summed n and gradient G, is dry: a candidate with no fluid
  /// particle (is_fluid(j)) in its region. Where G gives no direction, it is wet.
  template <class IsFluid>
  bool is_dry(std::int64_t w, IdRange nb, const double* x, const double* y, double n, Vec2 gradient,
              IsFluid&& is_fluid) const {
    if (n >= beta * n0) return false;
    const double g = norm(gradient);
    if (g * 2.0 * h < 0.1) return false;
    return region_empty(w, nb, x, y, gradient * (-1.0 / g), is_fluid);
  }
};

}  // namespace wcmps
