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
  /// Passes over the candidates the last build took: 1 (the lists filled where the last build's
  /// lists leave room) or 2 (counted, then filled: the first build, another particle count, or
  /// a thread's share that outgrew its room).
  int last_build_passes() const { return last_build_passes_; }

 private:
  bool fill_in_one_pass(const CellGrid& grid, const double* x, const double* y, std::int64_t n,
                        double c2, const std::vector<IndexRange>& owners);
  void count_then_fill(const CellGrid& grid, const double* x, const double* y, std::int64_t n,
                       double c2, const std::vector<IndexRange>& owners);

  std::vector<std::int64_t> offsets_;
  std::vector<std::int32_t> ids_;
  double cutoff_ = 0.0;
  int last_build_passes_ = 0;
};

}  // namespace wcmps
