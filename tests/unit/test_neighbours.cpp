// The cell-grid neighbour search equals brute force exactly (sorted id lists).

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <vector>

#include "core/Parallel.h"
#include "neighbours/CellGrid.h"
#include "neighbours/NeighbourList.h"

namespace wcmps {
namespace {

std::vector<std::vector<std::int32_t>> brute_force(const std::vector<double>& x,
                                                   const std::vector<double>& y, double cutoff) {
  const auto n = x.size();
  std::vector<std::vector<std::int32_t>> out(n);
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = 0; j < n; ++j) {
      const double dx = x[j] - x[i], dy = y[j] - y[i];
      if (i != j && dx * dx + dy * dy < cutoff * cutoff)
        out[i].push_back(static_cast<std::int32_t>(j));
    }
  }
  return out;
}

void expect_lists_equal_brute_force(const NeighbourList& list, const std::vector<double>& x,
                                    const std::vector<double>& y, double cutoff,
                                    const std::vector<IndexRange>& owners) {
  const auto n = static_cast<std::int64_t>(x.size());
  const auto ref = brute_force(x, y, cutoff);
  std::int64_t total = 0;
  for (std::int64_t i = 0; i < n; ++i) {
    bool owned = false;
    for (const auto& [b, e] : owners) owned = owned || (i >= b && i < e);
    std::vector<std::int32_t> got(list.of(i).begin(), list.of(i).end());
    std::sort(got.begin(), got.end());
    if (owned) {
      ASSERT_EQ(got, ref[i]) << "particle " << i;
      total += static_cast<std::int64_t>(got.size());
    } else {
      ASSERT_TRUE(got.empty()) << "particle " << i << " has no list of its own";
    }
  }
  EXPECT_EQ(list.pair_count(), total);
}

void expect_equal_to_brute_force(const std::vector<double>& x, const std::vector<double>& y,
                                 Vec2 lo, Vec2 hi, double cutoff, double cell,
                                 const std::vector<IndexRange>& owners) {
  const auto n = static_cast<std::int64_t>(x.size());
  CellGrid grid;
  grid.configure(lo, hi, cell);
  grid.bin(x.data(), y.data(), n);
  NeighbourList list;
  list.build(grid, x.data(), y.data(), n, cutoff, owners);
  expect_lists_equal_brute_force(list, x, y, cutoff, owners);
}

TEST(NeighbourList, RandomParticlesMatchBruteForce) {
  std::mt19937 rng(12345);
  std::uniform_real_distribution<double> ux(0.0, 1.0), uy(0.0, 0.6);
  std::vector<double> x(3000), y(3000);
  for (std::size_t k = 0; k < x.size(); ++k) {
    x[k] = ux(rng);
    y[k] = uy(rng);
  }
  // Cells both exactly the cutoff and larger than it.
  expect_equal_to_brute_force(x, y, {0, 0}, {1, 0.6}, 0.035, 0.035, {{0, 3000}});
  expect_equal_to_brute_force(x, y, {0, 0}, {1, 0.6}, 0.035, 0.05, {{0, 3000}});
}

TEST(NeighbourList, LatticeWithDistancesOnTheCutoffMatchesBruteForce) {
  // On a lattice of spacing 1 with cutoff 3 many pairs sit exactly at the cutoff: they must be
  // excluded (r < cutoff), as brute force does.
  std::vector<double> x, y;
  for (int j = 0; j < 30; ++j) {
    for (int i = 0; i < 40; ++i) {
      x.push_back(i * 1.0);
      y.push_back(j * 1.0);
    }
  }
  expect_equal_to_brute_force(x, y, {-1, -1}, {41, 31}, 3.0, 3.0, {{0, 1200}});
}

TEST(NeighbourList, OnlyOwnersGetListsButEveryParticleIsACandidate) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0.0, 0.3);
  std::vector<double> x(800), y(800);
  for (std::size_t k = 0; k < x.size(); ++k) {
    x[k] = u(rng);
    y[k] = u(rng);
  }
  expect_equal_to_brute_force(x, y, {0, 0}, {0.3, 0.3}, 0.02, 0.021, {{0, 100}, {500, 800}});
}

TEST(NeighbourList, ParticlesOutsideTheGridAreBinnedAtItsEdge) {
  // Two particles just outside the box, close to each other and to one inside.
  std::vector<double> x{-0.001, -0.002, 0.001}, y{0.5, 0.501, 0.5};
  expect_equal_to_brute_force(x, y, {0, 0}, {1, 1}, 0.01, 0.01, {{0, 3}});
}

TEST(NeighbourList, CrowdedCellsMatchBruteForce) {
  // 900 particles in four cells: more candidates than the fill's stack buffer holds (511), so
  // these take the other fill; 300 sparse ones around them take the buffered one.
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> crowd(0.48, 0.52), u(0.0, 1.0);
  std::vector<double> x, y;
  for (int k = 0; k < 900; ++k) {
    x.push_back(crowd(rng));
    y.push_back(crowd(rng));
  }
  for (int k = 0; k < 300; ++k) {
    x.push_back(u(rng));
    y.push_back(u(rng));
  }
  expect_equal_to_brute_force(x, y, {0, 0}, {1, 1}, 0.05, 0.05, {{0, 1200}});
}

TEST(NeighbourList, RebuildsInOnePassMatchBruteForce) {
  // After the first build the lists are filled in one pass, each thread's share of the owners
  // into room placed from what the share held at the last build; a share that outgrows its room
  // (the particles crowded together) goes back to the count and the fill. Every build equals
  // brute force, on 1 to 3 threads, with two owner ranges and particles owning no list.
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(0.0, 1.0), jitter(-0.004, 0.004);
  std::vector<double> x(2500), y(2500);
  for (std::size_t k = 0; k < x.size(); ++k) {
    x[k] = u(rng);
    y[k] = 0.6 * u(rng);
  }
  const std::vector<IndexRange> owners{{0, 700}, {1100, 2500}};
  const double cutoff = 0.035;
  CellGrid grid;
  grid.configure({0, 0}, {1, 0.6}, cutoff);
  NeighbourList list;
  const auto build = [&] {
    grid.bin(x.data(), y.data(), static_cast<std::int64_t>(x.size()));
    list.build(grid, x.data(), y.data(), static_cast<std::int64_t>(x.size()), cutoff, owners);
    expect_lists_equal_brute_force(list, x, y, cutoff, owners);
  };
  const auto jiggle = [&] {
    for (std::size_t k = 0; k < x.size(); ++k) {
      x[k] = std::clamp(x[k] + jitter(rng), 0.0, 1.0);
      y[k] = std::clamp(y[k] + jitter(rng), 0.0, 0.6);
    }
  };
  const int threads = thread_count();
  set_thread_count(2);
  build();
  EXPECT_EQ(list.last_build_passes(), 2) << "the first build";
  for (const int t : {2, 1, 3}) {  // the shares' room read from a build on another thread count too
    set_thread_count(t);
    for (int k = 0; k < 3; ++k) {
      jiggle();
      build();
      EXPECT_EQ(list.last_build_passes(), 1) << t << " threads, build " << k;
    }
  }
  // The owners of the first range crowded into a tenth of the width: several times their pairs,
  // more than the room of the first share.
  for (std::size_t k = 0; k < 700; ++k) x[k] *= 0.1;
  build();
  EXPECT_EQ(list.last_build_passes(), 2) << "a share outgrew its room";
  jiggle();
  build();
  EXPECT_EQ(list.last_build_passes(), 1) << "room from the crowded build";
  set_thread_count(threads);
}

TEST(CellGrid, BinsEveryParticleOnceInCellOrder) {
  std::vector<double> x{0.05, 0.15, 0.05, 0.95}, y{0.05, 0.05, 0.95, 0.95};
  CellGrid g;
  g.configure({0, 0}, {1, 1}, 0.1);
  EXPECT_EQ(g.nx(), 10);
  EXPECT_EQ(g.ny(), 10);
  g.bin(x.data(), y.data(), 4);
  EXPECT_EQ(g.members(), (std::vector<std::int32_t>{0, 1, 2, 3}));
  EXPECT_EQ(g.cell_end(0, 0) - g.cell_begin(0, 0), 1);
  EXPECT_EQ(*g.cell_begin(9, 9), 3);
  EXPECT_EQ(g.slot_begin(9, 9), 3);
  EXPECT_EQ(g.slot_end(9, 9), 4);
  // The coordinates in cell order, for the search's contiguous reads.
  for (std::size_t k = 0; k < 4; ++k) {
    EXPECT_EQ(g.xs()[k], x[g.members()[k]]);
    EXPECT_EQ(g.ys()[k], y[g.members()[k]]);
  }
}

}  // namespace
}  // namespace wcmps
