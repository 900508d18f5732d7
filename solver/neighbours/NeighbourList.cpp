#include "neighbours/NeighbourList.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/Parallel.h"

#if defined(__AVX512F__) && defined(__AVX512VL__) && defined(__FMA__)
#include <immintrin.h>
#define WCMPS_LISTS_AVX512 1
#else
#define WCMPS_LISTS_AVX512 0
#endif

namespace wcmps {
namespace {

/// The 3x3 block of cells around particle i's cell (cells are at least `cutoff` wide): each of
/// its (up to) three rows is one run of slots in the grid's cell order.
struct Block {
  double xi, yi;
  int y0, y1;
  std::int32_t first[3], last[3];

  std::int64_t candidates() const {
    std::int64_t c = 0;
    for (int r = 0; r <= y1 - y0; ++r) c += last[r] - first[r];
    return c;
  }
};

/// Room of the stack buffer of a fill. The 3x3 cells of side re + skin around a particle hold
/// about 9 (3.7)^2 = 123 candidates on a lattice at re = 3.5 DL; 1.2 n0 (where a run stops)
/// about 150.
constexpr std::int64_t kFillBuffer = 511;

Block block_of(const CellGrid& g, double xi, double yi) {
  Block b{xi, yi, 0, 0, {}, {}};
  const int cx = g.cell_x(xi), cy = g.cell_y(yi);
  const int x0 = std::max(cx - 1, 0), x1 = std::min(cx + 1, g.nx() - 1);
  b.y0 = std::max(cy - 1, 0);
  b.y1 = std::min(cy + 1, g.ny() - 1);
  for (int by = b.y0; by <= b.y1; ++by) {
    b.first[by - b.y0] = g.slot_begin(x0, by);
    b.last[by - b.y0] = g.slot_end(x1, by);
  }
  return b;
}

/// Whether a candidate at (dx, dy) from the particle is within the cutoff. The count and the
/// fill must agree to the bit (the fill writes where the count's prefix sum says), so both take
/// this test, and the vector path below rounds it the same way: dy^2, then dx dx + that in one
/// fused multiply-add (which is also what GCC 12 made of dx * dx + dy * dy here before).
inline bool within(double dx, double dy, double cutoff2) {
#if WCMPS_LISTS_AVX512
  return std::fma(dx, dx, dy * dy) < cutoff2;
#else
  return dx * dx + dy * dy < cutoff2;
#endif
}

#if WCMPS_LISTS_AVX512
/// Candidates k .. k + 7 of the grid's slots: which are within the cutoff of (xi, yi) and not
/// particle i itself, as a mask of 8 bits, and their ids.
struct Eight {
  __m256d xi, yi, cutoff2;
  __m256i self;

  Eight(const Block& b, double c2, std::int64_t i)
      : xi(_mm256_set1_pd(b.xi)),
        yi(_mm256_set1_pd(b.yi)),
        cutoff2(_mm256_set1_pd(c2)),
        self(_mm256_set1_epi32(static_cast<std::int32_t>(i))) {}

  __mmask8 in(const double* xs, const double* ys, std::int32_t k) const {
    return half(xs + k, ys + k) | static_cast<__mmask8>(half(xs + k + 4, ys + k + 4) << 4);
  }
  __mmask8 half(const double* xs, const double* ys) const {
    const __m256d dx = _mm256_sub_pd(_mm256_loadu_pd(xs), xi);
    const __m256d dy = _mm256_sub_pd(_mm256_loadu_pd(ys), yi);
    return _mm256_cmp_pd_mask(_mm256_fmadd_pd(dx, dx, _mm256_mul_pd(dy, dy)), cutoff2, _CMP_LT_OQ);
  }
};
#endif

/// Number of particles within `cutoff` of (xi, yi), i itself included. Branch-free over
/// contiguous coordinates, so the loop vectorises (with AVX-512, eight candidates per mask).
std::int64_t count_within(const CellGrid& g, const Block& b, double cutoff2) {
  const double* xs = g.xs();
  const double* ys = g.ys();
  std::int64_t c = 0;
#if WCMPS_LISTS_AVX512
  const Eight eight(b, cutoff2, -1);
#endif
  for (int r = 0; r <= b.y1 - b.y0; ++r) {
    std::int32_t k = b.first[r];
#if WCMPS_LISTS_AVX512
    for (; k + 8 <= b.last[r]; k += 8) c += __builtin_popcount(eight.in(xs, ys, k));
#endif
#pragma omp simd reduction(+ : c)
    for (std::int32_t kk = k; kk < b.last[r]; ++kk) {
      c += within(xs[kk] - b.xi, ys[kk] - b.yi, cutoff2) ? 1 : 0;
    }
  }
  return c;
}

/// Writes the particles other than i within `cutoff` of particle i to out (which has room for
/// b.candidates() entries: candidate k is written at out[c] with c <= k; the vector path's store
/// of the eight ids of candidates k .. k + 7 ends at out[c + 7], c + 7 <= k + 7) and returns
/// their number.
///
/// Without AVX-512 each candidate is written and the end moved on by the test's outcome. With
/// it, eight candidates are tested at once and the ids of those in are compressed to the front
/// of a register (vpcompressd into a register: its form with a memory operand is microcoded and
/// slow on AMD Zen 4), stored whole, and the end moved on by their number; the list is the same,
/// in the same order.
std::int64_t fill_within(const CellGrid& g, const Block& b, double cutoff2, std::int64_t i,
                         std::int32_t* out) {
  const double* xs = g.xs();
  const double* ys = g.ys();
  const std::int32_t* members = g.members().data();
  std::int64_t c = 0;
#if WCMPS_LISTS_AVX512
  const Eight eight(b, cutoff2, i);
#endif
  for (int r = 0; r <= b.y1 - b.y0; ++r) {
    std::int32_t k = b.first[r];
#if WCMPS_LISTS_AVX512
    for (; k + 8 <= b.last[r]; k += 8) {
      const __m256i id = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(members + k));
      const __mmask8 m = eight.in(xs, ys, k) & _mm256_cmpneq_epi32_mask(id, eight.self);
      _mm256_storeu_si256(reinterpret_cast<__m256i*>(out + c), _mm256_maskz_compress_epi32(m, id));
      c += __builtin_popcount(m);
    }
#endif
    for (; k < b.last[r]; ++k) {
      out[c] = members[k];
      c += static_cast<std::int64_t>(within(xs[k] - b.xi, ys[k] - b.yi, cutoff2)) &
           (members[k] != i);
    }
  }
  return c;
}

/// The same with a branch per candidate, writing nothing past the last neighbour.
void fill_within_branching(const CellGrid& g, const Block& b, double cutoff2, std::int64_t i,
                           std::int32_t* out) {
  const double* xs = g.xs();
  const double* ys = g.ys();
  const std::int32_t* members = g.members().data();
  for (int r = 0; r <= b.y1 - b.y0; ++r) {
    for (std::int32_t k = b.first[r]; k < b.last[r]; ++k) {
      if (within(xs[k] - b.xi, ys[k] - b.yi, cutoff2) && members[k] != i) *out++ = members[k];
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
  // Pass 1: count. offsets_[i + 1] holds the count of i until the prefix sum. Particle i is
  // binned, so it is among the particles within the cutoff of itself: minus one.
  for (const auto& [b, e] : owners) {
    parallel_for(b, e, [&](std::int64_t i) {
      offsets_[i + 1] = count_within(grid, block_of(grid, x[i], y[i]), c2) - 1;
    });
  }
  for (std::int64_t i = 0; i < n; ++i) offsets_[i + 1] += offsets_[i];
  if (static_cast<std::int64_t>(ids_.size()) < offsets_[n]) {
    ids_.resize(static_cast<std::size_t>(offsets_[n] + offsets_[n] / 8));
  }
  // Pass 2: fill, in cell order. In a flowing fluid whether a candidate is in is unpredictable,
  // so each is written and the end moved on by the test's outcome, without a branch (the build
  // of case I's jittered fluid 8.6 -> 4.1 ms against a branch: bench_step NeighbourBuild). That
  // write lands one past the last neighbour, where the next particle's list starts, so it goes to a
  // buffer on the stack.
  for (const auto& [b, e] : owners) {
    parallel_for(b, e, [&](std::int64_t i) {
      const Block blk = block_of(grid, x[i], y[i]);
      std::int32_t* list = ids_.data() + offsets_[i];
      if (blk.candidates() <= kFillBuffer) {
        std::int32_t buffer[kFillBuffer];
        const std::int64_t count = fill_within(grid, blk, c2, i, buffer);
        std::copy(buffer, buffer + count, list);
      } else {  // a crowd of particles in a few cells (a run about to fail), never on a lattice
        fill_within_branching(grid, blk, c2, i, list);
      }
    });
  }
}

}  // namespace wcmps
