#pragma once
/// @file WaterSpan.h
/// @brief Where the water is along a straight line: the one algorithm behind the filters'
/// sections and free surface (filters/) and wave gauges.
///
/// The water is where the fluid's coverage (its number density at a point over the bulk
/// value, 1/2 on the edge of a half-plane of particles) is at least a threshold. Along a line
/// there may be several wet stretches (a splash above the surface, a film under the block);
/// the water column is taken to be the longest one.

#include <cmath>

namespace wcmps {

/// The coverage on the edge of the water: the continuum value on the edge of a half-plane.
inline constexpr double kWaterEdgeCoverage = 0.5;

/// Coverage = (sum of W over the fluid particles) times this: W integrates to pi re^2 / 10
/// over the plane (W = (1 - r/re)^3), and particles of area DL^2 in the bulk sum to that over
/// DL^2 on average, so the coverage is 1 in the bulk.
inline double coverage_scale(double dl, double re) {
  return dl * dl / (std::acos(-1.0) * re * re / 10.0);
}

struct WaterSpan {
  bool found = false;
  double s0 = 0.0;  ///< start (bed side) along the line
  double s1 = 0.0;  ///< end (surface side)
};

/// The longest stretch of s in [smin, smax] where wet(s) holds. The line is scanned in steps
/// ds and each end refined by bisection to tol; stretches shorter than ds may be missed.
template <class Wet>
WaterSpan longest_water_span(const Wet& wet, double smin, double smax, double ds, double tol) {
  WaterSpan best;
  if (!(smin < smax) || !(ds > 0.0)) return best;
  // An end between a (state wa) and b, to tol.
  const auto refine = [&](double a, double b, bool wa) {
    while (b - a > tol) {
      const double m = 0.5 * (a + b);
      (wet(m) == wa ? a : b) = m;
    }
    return 0.5 * (a + b);
  };
  bool was_wet = wet(smin);
  double start = smin, prev = smin;
  for (double s = smin + ds;; s += ds) {
    const bool last = s >= smax;
    if (last) s = smax;
    const bool now = wet(s);
    if (now && !was_wet) start = refine(prev, s, false);
    if ((!now && was_wet) || (now && last)) {
      const double end = now ? s : refine(prev, s, true);
      if (!best.found || end - start > best.s1 - best.s0) best = {true, start, end};
    }
    was_wet = now;
    prev = s;
    if (last) break;
  }
  return best;
}

}  // namespace wcmps
