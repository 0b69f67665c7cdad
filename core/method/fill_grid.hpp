// One in-memory grid filled by the chosen method: the dispatcher between the
// paper's MCMD (paper/) and the default method (thin_plate/). The raster
// engine (raster/) calls it for each window it solves.
#pragma once

#include "common/grid.hpp"
#include "mcmd/params.hpp"
#include "mcmd/progress.hpp"

namespace mcmd {

// Fill every unknown cell of `grid` with `params.method`.
// Pre: at least one cell is a constraint (known, ridge or river); parameters finite.
// Post: every elevation is finite; constraint cells and all states are unchanged.
// Throws Cancelled when `progress` refuses, std::invalid_argument on bad input.
void fill_grid(Grid& grid, const FillParams& params, const ProgressFn& progress = {});

}  // namespace mcmd
