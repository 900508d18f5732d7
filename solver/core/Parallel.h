#pragma once
/// @file Parallel.h
/// @brief The one place that owns parallel loops (OpenMP). Physics code passes a per-particle
/// function; no pragma appears anywhere else in the solver.
///
/// Loops use a static schedule: every particle is computed by the same code path whatever the
/// thread count, and the reductions used (max, sum of integers) are exact, so results are
/// identical for any number of threads.

#include <cstddef>
#include <cstdint>
#include <limits>
#include <utility>

namespace wcmps {

/// Sets the number of threads of later parallel loops (n >= 1).
void set_thread_count(int n);
/// The number of threads parallel loops will use.
int thread_count();

/// Calls f(i) for every i in [begin, end), in parallel.
template <class F>
void parallel_for(std::int64_t begin, std::int64_t end, F&& f) {
#pragma omp parallel for schedule(static)
  for (std::int64_t i = begin; i < end; ++i) f(i);
}

/// max over i in [begin, end) of f(i); -infinity for an empty range.
template <class F>
double parallel_max(std::int64_t begin, std::int64_t end, F&& f) {
  double m = -std::numeric_limits<double>::infinity();
#pragma omp parallel for schedule(static) reduction(max : m)
  for (std::int64_t i = begin; i < end; ++i) {
    const double v = f(i);
    if (v > m) m = v;
  }
  return m;
}

/// Both maxima over i in [begin, end) of the pair f(i) = {a, b}; -infinity for an empty range.
template <class F>
std::pair<double, double> parallel_max2(std::int64_t begin, std::int64_t end, F&& f) {
  double ma = -std::numeric_limits<double>::infinity(), mb = ma;
#pragma omp parallel for schedule(static) reduction(max : ma, mb)
  for (std::int64_t i = begin; i < end; ++i) {
    const auto [a, b] = f(i);
    if (a > ma) ma = a;
    if (b > mb) mb = b;
  }
  return {ma, mb};
}

/// Sum over i in [begin, end) of the integer f(i).
template <class F>
std::int64_t parallel_count(std::int64_t begin, std::int64_t end, F&& f) {
  std::int64_t s = 0;
#pragma omp parallel for schedule(static) reduction(+ : s)
  for (std::int64_t i = begin; i < end; ++i) s += f(i);
  return s;
}

}  // namespace wcmps
