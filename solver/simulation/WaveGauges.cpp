#include "simulation/WaveGauges.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "core/Error.h"
#include "operators/WaterSpan.h"
#include "simulation/Simulation.h"

namespace wcmps {

WaveGauges::WaveGauges(const CaseSpec& spec, Vec2 lo, Vec2 hi)
    : x_(spec.gauges.x),
      interval_(spec.gauges.interval),
      dl_(spec.dl),
      w_{spec.re()},
      scale_(coverage_scale(spec.dl, spec.re())) {
  grid_.configure(lo, hi, spec.re());
  if (interval_ > 0.0) {
    values_.reserve((static_cast<std::size_t>(spec.end_time / interval_) + 2) * width());
  }
}

double WaveGauges::coverage(const double* px, const double* py, double x, double y) const {
  const int cx = grid_.cell_x(x), cy = grid_.cell_y(y);
  double s = 0.0;
  for (int j = std::max(cy - 1, 0); j <= std::min(cy + 1, grid_.ny() - 1); ++j) {
    for (int i = std::max(cx - 1, 0); i <= std::min(cx + 1, grid_.nx() - 1); ++i) {
      for (const std::int32_t* k = grid_.cell_begin(i, j); k != grid_.cell_end(i, j); ++k) {
        s += w_(std::hypot(px[*k] - x, py[*k] - y));
      }
    }
  }
  return s * scale_;
}

void WaveGauges::sample(const Simulation& sim) {
  const ParticleSet& ps = sim.particles();
  const double* px = ps.now.x.data() + ps.fluid_begin();
  const double* py = ps.now.y.data() + ps.fluid_begin();
  const std::int64_t n = ps.fluid_count();
  grid_.bin(px, py, n);
  double ylo = std::numeric_limits<double>::infinity(), yhi = -ylo;
  for (std::int64_t k = 0; k < n; ++k) {
    ylo = std::min(ylo, py[k]);
    yhi = std::max(yhi, py[k]);
  }
  values_.push_back(sim.time());
  for (const double x : x_) {
    const auto wet = [&](double y) { return coverage(px, py, x, y) >= kWaterEdgeCoverage; };
    const WaterSpan span =
        n > 0 ? longest_water_span(wet, ylo - w_.re, yhi + w_.re, 0.25 * dl_, 1e-3 * dl_)
              : WaterSpan{};
    values_.push_back(span.found ? span.s1 : std::numeric_limits<double>::quiet_NaN());
  }
  // The next sample: the first multiple of the interval after this time.
  next_ = interval_ > 0.0 ? (std::floor(sim.time() / interval_ + 1e-9) + 1.0) * interval_
                          : std::numeric_limits<double>::infinity();
}

std::string WaveGauges::csv() const {
  std::string out = "time [s]";
  char buf[64];
  for (const double x : x_) {
    std::snprintf(buf, sizeof buf, ",eta at x = %.6g m [m]", x);
    out += buf;
  }
  out += '\n';
  for (std::size_t r = 0; r < sample_count(); ++r) {
    const double* row = sample_values(r);
    for (std::size_t k = 0; k < width(); ++k) {
      std::snprintf(buf, sizeof buf, "%s%.9g", k ? "," : "", row[k]);
      out += buf;
    }
    out += '\n';
  }
  return out;
}

void WaveGauges::save(StateWriter& out) const {
  out.field("gauge_samples", {values_.data()}, values_.size());
  out.scalar("gauge_next_time", next_);
}

void WaveGauges::load(StateReader& in) {
  const std::size_t n = in.count("gauge_samples");
  if (n % width() != 0) throw CheckpointError("gauge samples do not match the case's gauges");
  values_.resize(n);  // within the run's reservation
  in.field("gauge_samples", {values_.data()}, n);
  next_ = in.scalar("gauge_next_time");
}

}  // namespace wcmps
