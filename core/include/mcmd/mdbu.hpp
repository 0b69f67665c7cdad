// MDBU — the paper's bottom-up pass (Belhadj 2007, §3.3, Algorithm 1).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "mcmd/fill.hpp"

namespace mcmd {

// Run MDBU on `grid` for `scheme`.
// `fixed[i]` marks cells whose elevation is set (initially the constraint cells).
// Waves: every fixed cell of the FIFO offers itself to each of its still-unset
// ascendants (a hash map from ascendant to its list of known children); each
// collected ascendant is then set to the Δ_BU-weighted average of its children,
// marked fixed and queued for the next wave, until the FIFO is empty.
// Pre: fixed.size() == grid.cell_count().
// Post: every ascendant of every fixed cell is fixed; grid states unchanged.
// Returns the number of cells MDBU set.
std::size_t mdbu(Grid& grid, std::vector<std::uint8_t>& fixed, Scheme scheme,
                 const FillParams& params, const ProgressFn& progress = {});

}  // namespace mcmd
