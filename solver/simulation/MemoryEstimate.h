#pragma once
/// @file MemoryEstimate.h
/// @brief The memory a run of a case will take at its peak, from the particle estimate
/// (scene/SizeEstimate.h), before anything is built; and the limit it is held to.
///
/// The model, fitted to the peak resident memory (VmHWM) of short runs and kept true by a test
/// (tests/cli/check_memory_estimate.py, `cli.memory_estimate`, compares it with a run of every
/// shipped case):
///
///   peak = program + run overhead + N x (per particle + 4 B x growth x n_list) + cells x 8 B
///
/// - program: what the process holds before it builds the scene (code, libraries), read from
///   /proc/self/status when the estimate is made;
/// - run overhead, kRunOverheadBytes: thread stacks, the HDF5 and VTK writers' own state;
/// - per particle, kBytesPerParticle: the particles' fields (two states of position, velocity,
///   pressure and number density, the kind, the id), the step's per-particle arrays (positions
///   at the last list build, p/n^2, the gradient of n, the surface band, ...), the cell grid's
///   copy of the positions, the frame being written and the checkpoint's image in memory;
/// - the neighbour lists: 4 bytes per pair, n_list pairs per particle (the lattice points
///   within re + skin), grown by kListGrowth for the water compressed under its own weight and
///   the list's room to grow;
/// - the cell grid: 8 bytes per cell of the domain (cells re + skin wide).

#include <cstdint>
#include <string>

#include "operators/PairRows.h"
#include "scene/CaseSpec.h"
#include "scene/SizeEstimate.h"

namespace wcmps {

struct MemoryEstimate {
  /// Fitted (the smallest largest error) to the peak RSS above the program of short runs at 2
  /// threads of 4,532 to 2,017,632 particles (docs/performance.md, "Memory estimated before a
  /// run"): 9.4 MB and 530 B per particle, within 7.4 % of each. The lists' share of the 530 B
  /// is 4 B x kListGrowth x 44 (re = 3.5 DL, skin 0.2 DL) = 225 B; the rest is
  /// kBytesPerParticle. The stabilised step's per-particle arrays added since (the band's
  /// correctors and marks, the cap's memory, ...) raised the slope between case I at DL 5 and
  /// 2 mm from 578 to 619 B per particle (2026-12-05): 305 + 41 B; the surface scan's four
  /// witnesses (2026-12-06) add 16 B, and an AVX-512 build's rows of the pair passes
  /// (operators/PairRows.h, 2026-12-06) 64 B.
  static constexpr double kRunOverheadBytes = 9.4e6;
  static constexpr double kBytesPerParticle = 362.0 + (WCMPS_PAIRS_AVX512 ? 64.0 : 0.0);
  /// With gradient_renormalisation = "khayyer2011-strain" (the default from 2026-12-07, session
  /// 13) each particle carries its rest shape, two numbers in each of the two states (32 B), and
  /// the checkpoint's image holds them once more (16 B): case I at DL 2 mm peaked 14.3 MiB higher
  /// with it than without, 47 B per particle.
  static constexpr double kStrainBytesPerParticle = 48.0;
  /// With particle_collision (physics/ParticleCollision_Jandaghian2021.h): each particle's
  /// velocity change of the step, two numbers (16 B), and its candidates of the list build: an
  /// offset (8 B) and their ids, 0.5 to 1.2 a particle in case I's frames (fluid pairs within
  /// DL), 8 B allowed; nothing in the checkpoint.
  static constexpr double kCollisionBytesPerParticle = 32.0;
  /// heaptrack on case I: the list took 11.25 MB for 50,084 owners x 44 lattice neighbours x 4 B
  /// = 8.8 MB.
  static constexpr double kListGrowth = 1.28;

  double program = 0.0;     ///< the process before building (B)
  double overhead = 0.0;    ///< B
  double particles = 0.0;   ///< fields and per-particle arrays (B)
  double lists = 0.0;       ///< neighbour lists (B)
  double grid = 0.0;        ///< cell grid's cells (B)
  int list_neighbours = 0;  ///< lattice points within re + skin of a point
  double total() const { return program + overhead + particles + lists + grid; }
  /// What the run adds to the process (everything but `program`).
  double added() const { return total() - program; }
};

/// The estimate for a case whose particles are `counts`; `program_bytes` is what the process
/// holds now (current_rss_bytes()).
MemoryEstimate estimate_memory(const CaseSpec& spec, const ParticleEstimate& counts,
                               double program_bytes);

/// The lines `check` and `run` print: the particles by kind and the memory by part.
std::string describe_estimate(const ParticleEstimate& counts, const MemoryEstimate& memory);

}  // namespace wcmps
