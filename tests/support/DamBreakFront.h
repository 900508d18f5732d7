#pragma once
/// @file DamBreakFront.h
/// @brief The dam break (cases/dambreak) against Martin & Moyce (1952): their measured surge
/// front Z = z/a against T = t sqrt(2g/a), and the rms error of a simulated front. Shared by
/// the validation test (tests/validation/test_dambreak.cpp) and the work-precision benchmark
/// (bench/bench_work_precision.cpp), so that both measure the same error.

#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace wcmps::dambreak {

constexpr double kA = 0.2;  ///< column width of cases/dambreak (m)
constexpr double kG = 9.81;
/// Time-origin shift: the experiment's T counts from a gate release that the data place late
/// (validation.md: 0.1 ... 0.2 is commonly accepted). One fixed value for every resolution:
/// Z_sim(T - kShift) is compared with Z_exp(T).
constexpr double kShift = 0.15;

struct Point {
  double T, Z;
};

/// The measured points of `csv` (cases/dambreak/martin_moyce_1952.csv); throws
/// std::runtime_error if it cannot be read.
inline std::vector<Point> martin_moyce(const std::string& csv) {
  std::ifstream in(csv);
  if (!in) throw std::runtime_error("cannot read " + csv);
  std::vector<Point> out;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#' || line[0] == 'T') continue;
    std::istringstream s(line);
    Point p{};
    char comma = 0;
    s >> p.T >> comma >> p.Z;
    out.push_back(p);
  }
  return out;
}

/// Z of a front sampled at increasing T, linear between samples (the last one beyond).
inline double interpolate(const std::vector<Point>& c, double T) {
  for (std::size_t k = 1; k < c.size(); ++k) {
    if (T <= c[k].T) {
      const double w = (T - c[k - 1].T) / (c[k].T - c[k - 1].T);
      return c[k - 1].Z + w * (c[k].Z - c[k - 1].Z);
    }
  }
  return c.back().Z;
}

/// rms over the measured points of Z_sim(T - kShift) - Z_exp(T).
inline double rms_front_error(const std::vector<Point>& sim, const std::vector<Point>& data) {
  double s = 0.0;
  for (const auto& p : data) {
    const double e = interpolate(sim, p.T - kShift) - p.Z;
    s += e * e;
  }
  return std::sqrt(s / static_cast<double>(data.size()));
}

}  // namespace wcmps::dambreak
