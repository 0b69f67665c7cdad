// MD — the paper's top-down midpoint displacement (§3.1) on a 2^n+1 grid.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "common/grid.hpp"
#include "mcmd/params.hpp"
#include "mcmd/progress.hpp"
#include "paper/subdivision.hpp"

namespace mcmd {

// Visit levels coarse to fine (diamond-square: square step then diamond step)
// and set every cell not yet fixed to the Δ-combination of its parents (the
// butterfly stencil for Scheme::butterfly, where it fits the grid) plus the
// displacement d·δ (d: distance to the nearest parent relative to the top-level
// half-spacing; δ: paper eq. 1 in units of `noise_unit`).
// Corners that are not fixed get the mean of the fixed corners, or of all fixed
// cells when no corner is fixed (the paper starts from given corners).
// Pre: at least one cell fixed. Post: every cell fixed, fixed cells unchanged.
void midpoint_displacement(Grid& grid, std::vector<std::uint8_t>& fixed, Scheme scheme,
                           const FillParams& params, double noise_unit,
                           const ProgressFn& progress = {});

}  // namespace mcmd

namespace mcmd {

// Give unset roots of a hierarchy (grid corners, line ends) a start value: the
// mean of the set roots, or of every set cell when no root is set.
// Pre: at least one cell fixed. Post: every root fixed.
void seed_roots(std::vector<double>& z, std::vector<std::uint8_t>& fixed,
                std::span<const std::uint32_t> roots);

}  // namespace mcmd
