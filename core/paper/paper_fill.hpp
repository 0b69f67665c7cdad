// The published MCMD on one grid (Belhadj 2007): MDBU (mdbu.hpp), then MD
// (midpoint_displacement.hpp), on the scheme of a paper method.
#pragma once

#include "common/grid.hpp"
#include "mcmd/params.hpp"
#include "mcmd/progress.hpp"
#include "paper/subdivision.hpp"

namespace mcmd {

// The scheme a paper method uses. Pre: method is paper_ds or paper_te.
Scheme scheme_of(Method method);

// MDBU then MD on a working copy of the constraint flags; rs in units of
// params.noise_unit, or of the grid's known elevation range when that is 0.
// Pre: params.method is a paper method, a cell is a constraint.
// Post: every cell set, constraint cells unchanged.
void paper_fill(Grid& grid, const FillParams& params, const ProgressFn& progress = {});

}  // namespace mcmd
