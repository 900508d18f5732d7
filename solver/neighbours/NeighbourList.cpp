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
std::int64_t fill_within_branching(const CellGrid& g, const Block& b, double cutoff2,
                                   std::int64_t i, std::int32_t* out) {
  std::int32_t* const first = out;
  const double* xs = g.xs();
  const double* ys = g.ys();
  const std::int32_t* members = g.members().data();
  for (int r = 0; r <= b.y1 - b.y0; ++r) {
    for (std::int32_t k = b.first[r]; k < b.last[r]; ++k) {
      if (within(xs[k] - b.xi, ys[k] - b.yi, cutoff2) && members[k] != i) *out++ = members[k];
    }
  }
  return out - first;
}

/// The least spare room of ids_ beyond `pairs` for a build in one pass over `shares` shares: a
/// share's room must hold a particle's candidates (about 123 at re + skin = 3.7 DL; see
/// kFillBuffer) at the end of its run. At least 1/64 of the pairs and 512 ids per share.
std::int64_t least_spare(std::int64_t pairs, std::int64_t shares) {
  return pairs / 64 + 512 * shares;
}

/// The owned particles in index order, as positions 0 .. size() - 1 across the owner ranges.
class Owned {
 public:
  explicit Owned(const std::vector<IndexRange>& owners) : owners_(owners) {
    for (const auto& [b, e] : owners) size_ += e - b;
  }
  std::int64_t size() const { return size_; }
  /// Calls f(i) for the particles at positions [p0, p1), in order.
  template <class F>
  void each(std::int64_t p0, std::int64_t p1, F&& f) const {
    std::int64_t at = 0;
    for (const auto& [b, e] : owners_) {
      const std::int64_t lo = std::max(p0 - at, std::int64_t{0});
      const std::int64_t hi = std::min(p1 - at, e - b);
      for (std::int64_t k = lo; k < hi; ++k) f(b + k);
      at += e - b;
    }
  }
  /// The particle at position p (< size()).
  std::int64_t at(std::int64_t p) const {
    for (const auto& [b, e] : owners_) {
      if (p < e - b) return b + p;
      p -= e - b;
    }
    return -1;
  }

 private:
  const std::vector<IndexRange>& owners_;
  std::int64_t size_ = 0;
};

}  // namespace

void NeighbourList::build(const CellGrid& grid, const double* x, const double* y, std::int64_t n,
                          double cutoff, const std::vector<IndexRange>& owners) {
  if (grid.cell_size() < cutoff) {
    throw std::invalid_argument("NeighbourList: grid cells are smaller than the cutoff");
  }
  cutoff_ = cutoff;
  const double c2 = cutoff * cutoff;
  last_build_passes_ = 1;
  if (!fill_in_one_pass(grid, x, y, n, c2, owners)) {
    count_then_fill(grid, x, y, n, c2, owners);
    last_build_passes_ = 2;
  }
}

bool NeighbourList::fill_in_one_pass(const CellGrid& grid, const double* x, const double* y,
                                     std::int64_t n, double c2,
                                     const std::vector<IndexRange>& owners) {
  // One pass instead of a count and a fill. Each thread fills the lists of its share of the
  // owners (a contiguous run of them) into its own region of ids_: the ids its share held at
  // the last build (the offsets of that build tell) plus ids_'s spare room (count_then_fill
  // leaves an eighth) dealt out in proportion to them. Then the regions are moved down to where the
  // counts' prefix sum puts them. Every region starts at or after its final place (each region
  // before it holds no more than its room), so moving them in order never overwrites one still to
  // move. Too little spare room, a share that would outgrow its room, or no last build of as many
  // particles: the count and the fill (count_then_fill), which sizes ids_. The lists are those of
  // the two passes, in the same order, and ids_ is never grown here (growing a vector by a little
  // doubles its capacity).
  if (static_cast<std::int64_t>(offsets_.size()) != n + 1) return false;  // no last build of n
  const auto shares = static_cast<std::int64_t>(thread_count());
  const Owned owned(owners);
  const auto first = [&](std::int64_t t) { return owned.size() * t / shares; };
  // What each share held at the last build (its offsets are still there).
  std::vector<std::int64_t> held(static_cast<std::size_t>(shares), 0);
  for (std::int64_t t = 0; t < shares; ++t) {
    if (first(t + 1) > first(t)) {
      held[static_cast<std::size_t>(t)] =
          offsets_[owned.at(first(t + 1) - 1) + 1] - offsets_[owned.at(first(t))];
    }
  }
  const std::int64_t pairs = offsets_[n];
  const auto space = static_cast<std::int64_t>(ids_.size());
  if (pairs == 0 || space - pairs < least_spare(pairs, shares)) return false;
  std::vector<std::int64_t> room(static_cast<std::size_t>(shares + 1), 0);
  for (std::int64_t t = 0; t < shares; ++t) {
    const std::int64_t h = held[static_cast<std::size_t>(t)];
    room[static_cast<std::size_t>(t + 1)] =
        room[static_cast<std::size_t>(t)] + h + (space - pairs) * h / pairs;
  }
  room.back() = space;
  offsets_.assign(n + 1, 0);
  std::vector<std::int64_t> filled(static_cast<std::size_t>(shares), 0);
  std::vector<char> outgrown(static_cast<std::size_t>(shares), 0);
  parallel_for(0, shares, [&](std::int64_t t) {
    const auto ts = static_cast<std::size_t>(t);
    std::int64_t end = room[ts];
    const std::int64_t limit = room[ts + 1];
    bool fits = true;
    owned.each(first(t), first(t + 1), [&](std::int64_t i) {
      if (!fits) return;
      const Block blk = block_of(grid, x[i], y[i]);
      // The fill writes up to its candidates' number of ids (see fill_within).
      if (blk.candidates() > limit - end) {
        fits = false;
        return;
      }
      std::int32_t* list = ids_.data() + end;
      const std::int64_t count = blk.candidates() <= kFillBuffer
                                     ? fill_within(grid, blk, c2, i, list)
                                     : fill_within_branching(grid, blk, c2, i, list);
      offsets_[i + 1] = count;
      end += count;
    });
    filled[ts] = end - room[ts];
    outgrown[ts] = fits ? 0 : 1;
  });
  if (std::find(outgrown.begin(), outgrown.end(), 1) != outgrown.end()) return false;
  for (std::int64_t i = 0; i < n; ++i) offsets_[i + 1] += offsets_[i];
  for (std::int64_t t = 1; t < shares; ++t) {
    const auto ts = static_cast<std::size_t>(t);
    if (filled[ts] == 0) continue;
    const std::int32_t* from = ids_.data() + room[ts];
    std::int32_t* to = ids_.data() + offsets_[owned.at(first(t))];
    if (to != from) std::copy(from, from + filled[ts], to);  // to < from: a forward copy is safe
  }
  return true;
}

void NeighbourList::count_then_fill(const CellGrid& grid, const double* x, const double* y,
                                    std::int64_t n, double c2,
                                    const std::vector<IndexRange>& owners) {
  offsets_.assign(n + 1, 0);
  // Pass 1: count. offsets_[i + 1] holds the count of i until the prefix sum. Particle i is
  // binned, so it is among the particles within the cutoff of itself: minus one.
  for (const auto& [b, e] : owners) {
    parallel_for(b, e, [&](std::int64_t i) {
      offsets_[i + 1] = count_within(grid, block_of(grid, x[i], y[i]), c2) - 1;
    });
  }
  for (std::int64_t i = 0; i < n; ++i) offsets_[i + 1] += offsets_[i];
  // Room for the lists and an eighth more, so that the next builds can take one pass.
  const std::int64_t pairs = offsets_[n], shares = thread_count();
  if (static_cast<std::int64_t>(ids_.size()) < pairs + least_spare(pairs, shares)) {
    ids_.resize(static_cast<std::size_t>(pairs + pairs / 8 + least_spare(0, shares)));
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
