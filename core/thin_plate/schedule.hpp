// The tunable schedule of the default method (thin_plate.hpp), for tests and
// benchmarks; the defaults are the measured choice (docs/default-method.md).
#pragma once

#include <cstddef>

#include "thin_plate/multigrid.hpp"

namespace mcmd {

// Starting values of a level's free cells in the top-down cascade.
enum class CascadeStart {
  prolong,  // cubic prolongation of the relaxed coarser level only
  blend,    // new cells: mix of prolongation and the bottom-up estimate by its confidence
};

struct ThinPlateSchedule {
  int finest_sweeps = 2;   // cascade sweeps at the finest level, doubling per coarser level
  int max_sweeps = 32;     // cap on cascade sweeps per level
  double omega = 1.0;      // SOR factor of the cascade sweeps
  CascadeStart start = CascadeStart::blend;
  double spring = 300.0;   // spring per unit constraint density on coarse cascade levels (0: none)
  double tension = 0.0;    // membrane weight at the finest level (×4 per coarser level)
  int v_cycles = 3;        // plain V-cycles at the finest level, used when pcg_tol <= 0
  double pcg_tol = 1e-2;   // > 0: V-cycle-preconditioned CG instead, until this relative residual
  int pcg_max_iterations = 16;  // or this many (a safety cap: the benchmark needs fewer)
  // A large field whose every free cell lies near a constraint (scattered
  // samples such as 3 % kept cells: one void network of millions of cells,
  // none far from data) stops at this looser tolerance: 3 iterations where
  // converging to 1e-2 takes 6. The cascade already holds such a fill to
  // within the terrain's own detail; each iteration saved is about a seventh
  // of a 3.3 %-kept fill's time, for a few tenths of a percent of its RMSE
  // (docs/default-method.md). 0: never.
  double shallow_pcg_tol = 0.1;
  double shallow_reach = 16.0;               // "near": at most this many cells from a constraint
  std::size_t shallow_min_free = 1u << 14;   // "large": at least this many free cells
  // On such a shallow field the valleys and ridges run between the samples:
  // after structure_after isotropic iterations the fill's own directions are
  // measured and structure_iterations more iterations solve with the
  // structure term of that strength added (structure_term.hpp; 3.3 % kept:
  // RMSE 0.740 of GDAL's instead of 0.760, docs/default-method.md). A
  // strength <= 1: none, the shallow tolerance alone.
  double structure_strength = 30.0;
  int structure_after = 2;
  int structure_iterations = 1;
  // Soft pull of the finest level's free cells towards the cascade's fill:
  // the finest-level energy gains Σ (z - cascade)² / pull_length⁴. Negligible
  // within pull_length cells of data (the thin plate's stiffness there is
  // ~1/d⁴), dominant deeper inside large voids, where the converged thin
  // plate extrapolates the rim's slopes too far. 0: plain thin plate.
  double pull_length = 8.0;
  // A field with at most this many unknown cells (and no tension) is solved
  // exactly by one dense factorisation instead (direct_plate.hpp): a
  // raster's hundreds of tiny voids. 0: never.
  std::size_t direct_max_unknown = 64;
  VCycleSchedule vcycle{};
};

}  // namespace mcmd
