// MDI, the Midpoint Displacement Inverse of Belhadj & Audibert 2005 (seed
// 001 §3), MDBU's predecessor, for comparison: the same waves up the
// subdivision hierarchy from the constraints, but each ascendant is the plain
// mean of its known children (no Δ, no I_bu) plus a random displacement
// proportional to their mean distance: v̄ + d̄ · urand() in the seed, here
// d̄ / (top half-spacing) · urand() · rs · unit, the scale of MD's own d · δ.
// The top-down pass that follows is plain MD (I = 0 for every state).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "common/grid.hpp"
#include "mcmd/params.hpp"
#include "mcmd/progress.hpp"
#include "paper/subdivision.hpp"

namespace mcmd::terrain {

// The bottom-up pass. Pre: fixed.size() == grid.cell_count(), fixed marks the
// constraints. Post: every ascendant of a fixed cell fixed; returns how many were set.
std::size_t mdi(Grid& grid, std::vector<std::uint8_t>& fixed, Scheme scheme, const FillParams& params,
                double unit, const ProgressFn& progress = {});

}  // namespace mcmd::terrain
