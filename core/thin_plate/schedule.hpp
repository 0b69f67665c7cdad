// The tunable schedule of the default method, for tests and benchmarks; the
// defaults are the measured choice (docs/default-method.md).
#pragma once

#include <cstddef>
#include <cstdint>

#include "common/grid.hpp"
#include "mcmd/params.hpp"
#include "mcmd/progress.hpp"
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
  // none far from data) stops at this looser tolerance. The cascade already
  // holds such a fill to within the terrain's own detail; the last
  // iterations cost a third of the time and changed the benchmark's RMSE by
  // 1 % (docs/default-method.md). 0: never.
  double shallow_pcg_tol = 0.1;
  double shallow_reach = 16.0;               // "near": at most this many cells from a constraint
  std::size_t shallow_min_free = 1u << 14;   // "large": at least this many free cells
  // Soft pull of the finest level's free cells towards the cascade's fill:
  // the finest-level energy gains Σ (z - cascade)² / pull_length⁴. Negligible
  // within pull_length cells of data (the thin plate's stiffness there is
  // ~1/d⁴), dominant deeper inside large voids, where the converged thin
  // plate extrapolates the rim's slopes too far. 0: plain thin plate.
  double pull_length = 8.0;
  VCycleSchedule vcycle{};
};

// A w×h row-major field filled in place by the smooth thin-plate method: cells
// whose state is a constraint (known, ridge, river) are kept, unknown cells
// get the fill. Any size (no 2^n+1 padding: lattice.hpp).
struct FieldView {
  int w = 0;
  int h = 0;
  double* z = nullptr;
  const CellState* state = nullptr;
  // A bound on the distance from any unknown cell to the nearest constraint
  // cell, when the caller has one (< 0: the solver measures it when it needs
  // it). The field is taken as shallow when it is <= shallow_reach, as not
  // shallow otherwise: a loose bound only costs speed. -rs auto makes no
  // noise octave coarser than it (roughness.hpp).
  double farthest = -1.0;
  // The unknown cells whose values the caller keeps, one byte per cell (null:
  // all of them). A void's field solves other voids' cells too; the roughness
  // is generated around the kept ones only (roughness.hpp).
  const std::uint8_t* wanted = nullptr;
  std::size_t index(int x, int y) const { return static_cast<std::size_t>(y) * static_cast<std::size_t>(w) + x; }
  double& z_at(int x, int y) const { return z[index(x, y)]; }
  CellState state_at(int x, int y) const { return state[index(x, y)]; }
};

// The smooth fill of `field` (stages 1-3 of thin_plate.cpp, no roughness).
// Pre: field.z and field.state hold w·h cells. Post: constraint cells
// unchanged; unknown cells filled when the field has a constraint.
void thin_plate_smooth(const FieldView& field, const ThinPlateSchedule& schedule, const ProgressFn& progress = {});

// thin_plate_smooth plus the roughness of `params` (roughness.hpp) in the
// same solve; the noise is keyed on raster coordinates, the field's cell
// (0, 0) being raster cell (x0, y0). Pre/post as thin_plate_smooth; with no
// roughness, it is that.
void thin_plate_with_roughness(const FieldView& field, long long x0, long long y0, const FillParams& params,
                               const ThinPlateSchedule& schedule, const ProgressFn& progress = {});

// thin_plate_fill with an explicit schedule; noise (rs, rs_auto) included.
void thin_plate_fill_scheduled(Grid& grid, const FillParams& params, const ThinPlateSchedule& schedule,
                               const ProgressFn& progress = {});

}  // namespace mcmd
