#pragma once
/// @file CellGrid.h
/// @brief Background grid of square cells for the neighbour search (linked-list strategy of
/// Gotoh et al. 2004 with cells of size re + delta as in Shakibaeinia & Jin 2009; thesis
/// section 2.3). Particles are binned by a counting sort into one array of ids per cell.

#include <cstdint>
#include <vector>

#include "core/Vec2.h"

namespace wcmps {

class CellGrid {
 public:
  /// Covers the box [lo, hi] with cells of side at least `cell_size`; allocates once.
  void configure(Vec2 lo, Vec2 hi, double cell_size);

  /// Bins n particles. Particles outside the box go to the nearest edge cell (the stability
  /// check stops a run whose particles leave the domain, see simulation/StabilityMonitor.h).
  /// Allocates only when n grows beyond what was binned before.
  void bin(const double* x, const double* y, std::int64_t n);

  int nx() const { return nx_; }
  int ny() const { return ny_; }
  double cell_size() const { return h_; }
  int cell_x(double x) const;
  int cell_y(double y) const;
  /// Particles of cell (cx, cy), which must be inside the grid.
  const std::int32_t* cell_begin(int cx, int cy) const {
    return members_.data() + start_[cx + cy * nx_];
  }
  const std::int32_t* cell_end(int cx, int cy) const {
    return members_.data() + start_[cx + cy * nx_ + 1];
  }
  /// Slots of cell (cx, cy) in cell order (row by row): [slot_begin, slot_end). The cells
  /// bx0..bx1 of one row are the slots [slot_begin(bx0, cy), slot_end(bx1, cy)).
  std::int32_t slot_begin(int cx, int cy) const { return start_[cx + cy * nx_]; }
  std::int32_t slot_end(int cx, int cy) const { return start_[cx + cy * nx_ + 1]; }
  /// All binned particle ids in cell order (row by row).
  const std::vector<std::int32_t>& members() const { return members_; }
  /// Coordinates of the binned particles in cell order: xs()[k] = x[members()[k]]. The search
  /// reads these contiguously instead of gathering x[j] (NeighbourList::build).
  const double* xs() const { return xs_.data(); }
  const double* ys() const { return ys_.data(); }

 private:
  Vec2 lo_;
  double h_ = 0.0;
  double inv_h_ = 0.0;
  int nx_ = 0, ny_ = 0;
  std::vector<std::int32_t> start_;    // nx*ny + 1 offsets into members_
  std::vector<std::int32_t> members_;  // particle ids, grouped by cell
  std::vector<double> xs_, ys_;        // their coordinates, in the same order
  std::vector<std::int32_t> cell_of_;  // cell of each particle
  std::vector<std::int32_t> cursor_;   // fill position per cell while binning
};

}  // namespace wcmps
