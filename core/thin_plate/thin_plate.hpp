// The default method (`-method mcmd`): MCMD's bottom-up then top-down structure
// on the same 2^n+1 hierarchy with better ingredients (see thin_plate.cpp).
#pragma once

#include "common/grid.hpp"
#include "mcmd/params.hpp"
#include "mcmd/progress.hpp"

namespace mcmd {

// Pre/post as mcmd::fill.
void thin_plate_fill(Grid& grid, const FillParams& params, const ProgressFn& progress = {});

}  // namespace mcmd
