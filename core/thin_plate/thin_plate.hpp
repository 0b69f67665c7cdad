// The default method (`-method mcmd`): MCMD's bottom-up then top-down
// structure on the same nested hierarchy with better ingredients — weighted
// restriction bottom-up (pull_push), cubic prolongation top-down
// (cubic_prolong), thin-plate relaxation per level (biharmonic_relax) and
// multigrid at the finest level (multigrid) — plus, with -rs, the roughness
// of roughness/ in the same solve (thin_plate.cpp; docs/default-method.md).
#pragma once

#include <cstddef>
#include <cstdint>

#include "common/grid.hpp"
#include "mcmd/params.hpp"
#include "mcmd/progress.hpp"
#include "thin_plate/schedule.hpp"

namespace mcmd {

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
  // Whether the fill is solved around the constraints' least-squares plane
  // (what a thin plate under tension levels off towards), or around 0: the
  // caller has taken out a plane of its own (the coarse guide solving part
  // of its lattice takes out the whole lattice's).
  bool own_plane = true;
  std::size_t index(int x, int y) const { return static_cast<std::size_t>(y) * static_cast<std::size_t>(w) + x; }
  double& z_at(int x, int y) const { return z[index(x, y)]; }
  CellState state_at(int x, int y) const { return state[index(x, y)]; }
};

// A plane c + cx·(x − x0) + cy·(y − y0) in field coordinates.
struct Plane {
  double c = 0.0, cx = 0.0, cy = 0.0, x0 = 0.0, y0 = 0.0;
  double at(int x, int y) const { return c + cx * (x - x0) + cy * (y - y0); }
};

// The least-squares plane through the field's constraint cells (0 when it
// has none; the line along them when they lie on one row or column).
Plane constraint_plane(const FieldView& f);

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

// The default method on a 2^n+1 grid (a window of the tiled fill), roughness
// included. Pre/post as fill_grid (method/fill_grid.hpp).
void thin_plate_fill(Grid& grid, const FillParams& params, const ProgressFn& progress = {});

}  // namespace mcmd
