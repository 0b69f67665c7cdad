// Natural roughness for the default method: a fractal correction added to the
// smooth thin-plate fill, zero at the constraint cells.
#pragma once

#include "mcmd/fill.hpp"
#include "mcmd/lattice.hpp"

namespace mcmd {

// Add roughness to the free cells of `fill` (the smooth fill of `grid`,
// relative to any reference). Amplitude and H from params.rs / params.H, or
// estimated from the constraint cells when params.rs_auto. Deterministic per
// params.seed and the grid's global origin.
void add_roughness(Lattice& fill, const Grid& grid, const FillParams& params);

}  // namespace mcmd
