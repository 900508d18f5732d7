#pragma once
/// @file NeighbourList.h
/// @brief Neighbours of every particle in compressed-sparse-row form (offsets + ids), built from
/// a CellGrid once per step and reused by every operator of that step.
///
/// The list holds every j != i with |r_j - r_i| < cutoff at build time; operators then test
/// r_ij < re at the positions they use. The cutoff is re plus a skin large enough for the
/// predicted displacement of a step (see Simulation::predict).

#include <cstdint>
#include <utility>
#include <vector>

#include "neighbours/CellGrid.h"

namespace wcmps {

/// A contiguous run of neighbour ids.
struct IdRange {
  const std::int32_t* first;
  const std::int32_t* last;
  const std::int32_t* begin() const { return first; }
  const std::int32_t* end() const { return last; }
  std::int64_t size() const { return last - first; }
};

/// Half-open index range [begin, end) of particles.
using IndexRange = std::pair<std::int64_t, std::int64_t>;

class NeighbourList {
 public:
  /// Builds lists for the particles in `owners` (others get empty lists); candidates j are all n
  /// particles, which `grid` must have binned. Allocates only when the pair count grows beyond
  /// the largest seen so far.
  void build(const CellGrid& grid, const double* x, const double* y, std::int64_t n, double cutoff,
             const std::vector<IndexRange>& owners);

  IdRange of(std::int64_t i) const {
    return {ids_.data() + offsets_[i], ids_.data() + offsets_[i + 1]};
  }
  /// Number of (i, j) entries of particles [begin, end).
  std::int64_t pair_count(std::int64_t begin, std::int64_t end) const {
    return offsets_[end] - offsets_[begin];
  }
  std::int64_t pair_count() const { return offsets_.empty() ? 0 : offsets_.back(); }
  double cutoff() const { return cutoff_; }

 private:
  std::vector<std::int64_t> offsets_;
  std::vector<std::int32_t> ids_;
  double cutoff_ = 0.0;
};

}  // namespace wcmps
