#include "neighbours/CellGrid.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/Parallel.h"

namespace wcmps {

void CellGrid::configure(Vec2 lo, Vec2 hi, double cell_size) {
  if (!(cell_size > 0.0) || !(hi.x > lo.x) || !(hi.y > lo.y)) {
    throw std::invalid_argument("CellGrid: empty box or non-positive cell size");
  }
  lo_ = lo;
  h_ = cell_size;
  inv_h_ = 1.0 / cell_size;
  nx_ = std::max(1, static_cast<int>(std::ceil((hi.x - lo.x) * inv_h_)));
  ny_ = std::max(1, static_cast<int>(std::ceil((hi.y - lo.y) * inv_h_)));
  start_.assign(static_cast<std::size_t>(nx_) * ny_ + 1, 0);
}

int CellGrid::cell_x(double x) const {
  const double c = std::floor((x - lo_.x) * inv_h_);
  return c < 0.0 ? 0 : (c >= nx_ ? nx_ - 1 : static_cast<int>(c));
}

int CellGrid::cell_y(double y) const {
  const double c = std::floor((y - lo_.y) * inv_h_);
  return c < 0.0 ? 0 : (c >= ny_ ? ny_ - 1 : static_cast<int>(c));
}

void CellGrid::bin(const double* x, const double* y, std::int64_t n) {
  if (static_cast<std::int64_t>(members_.size()) != n) {
    members_.resize(n);
    cell_of_.resize(n);
    xs_.resize(n);
    ys_.resize(n);
  }
  // Counting sort: start_[c] .. start_[c + 1] is cell c; ids ascend within a cell.
  std::fill(start_.begin(), start_.end(), 0);
  for (std::int64_t i = 0; i < n; ++i) {
    const int c = cell_x(x[i]) + cell_y(y[i]) * nx_;
    cell_of_[i] = c;
    ++start_[c + 1];
  }
  for (std::size_t c = 1; c < start_.size(); ++c) start_[c] += start_[c - 1];
  cursor_.assign(start_.begin(), start_.end() - 1);
  for (std::int64_t i = 0; i < n; ++i) {
    members_[cursor_[cell_of_[i]]++] = static_cast<std::int32_t>(i);
  }
  parallel_for(0, n, [&](std::int64_t k) {
    xs_[k] = x[members_[k]];
    ys_[k] = y[members_[k]];
  });
}

}  // namespace wcmps
