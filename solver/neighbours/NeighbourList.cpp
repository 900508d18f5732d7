#include "neighbours/NeighbourList.h"

#include <algorithm>
#include <stdexcept>

#include "core/Parallel.h"

namespace wcmps {
namespace {

/// Calls f(j) for every particle j != i within `cutoff` of particle i, scanning the 3x3 block of
/// cells around i's cell (cells are at least `cutoff` wide).
template <class F>
void for_each_candidate(const CellGrid& g, const double* x, const double* y, std::int64_t i,
                        double cutoff2, F&& f) {
  const double xi = x[i], yi = y[i];
  const int cx = g.cell_x(xi), cy = g.cell_y(yi);
  const int x0 = std::max(cx - 1, 0), x1 = std::min(cx + 1, g.nx() - 1);
  const int y0 = std::max(cy - 1, 0), y1 = std::min(cy + 1, g.ny() - 1);
  for (int by = y0; by <= y1; ++by) {
    for (int bx = x0; bx <= x1; ++bx) {
      for (const std::int32_t* p = g.cell_begin(bx, by); p != g.cell_end(bx, by); ++p) {
        const std::int32_t j = *p;
        const double dx = x[j] - xi, dy = y[j] - yi;
        if (dx * dx + dy * dy < cutoff2 && j != i) f(j);
      }
    }
  }
}

}  // namespace

void NeighbourList::build(const CellGrid& grid, const double* x, const double* y, std::int64_t n,
                          double cutoff, const std::vector<IndexRange>& owners) {
  if (grid.cell_size() < cutoff) {
    throw std::invalid_argument("NeighbourList: grid cells are smaller than the cutoff");
  }
  cutoff_ = cutoff;
  const double c2 = cutoff * cutoff;
  offsets_.assign(n + 1, 0);
  // Pass 1: count. offsets_[i + 1] holds the count of i until the prefix sum.
  for (const auto& [b, e] : owners) {
    parallel_for(b, e, [&](std::int64_t i) {
      std::int64_t c = 0;
      for_each_candidate(grid, x, y, i, c2, [&](std::int32_t) { ++c; });
      offsets_[i + 1] = c;
    });
  }
  for (std::int64_t i = 0; i < n; ++i) offsets_[i + 1] += offsets_[i];
  if (static_cast<std::int64_t>(ids_.size()) < offsets_[n]) {
    ids_.resize(static_cast<std::size_t>(offsets_[n] + offsets_[n] / 8));
  }
  // Pass 2: fill.
  for (const auto& [b, e] : owners) {
    parallel_for(b, e, [&](std::int64_t i) {
      std::int32_t* out = ids_.data() + offsets_[i];
      for_each_candidate(grid, x, y, i, c2, [&](std::int32_t j) { *out++ = j; });
    });
  }
}

}  // namespace wcmps
