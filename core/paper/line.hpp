// The 1D case (paper Figs. 4 and 6): profiles of length 2^n + 1 where the
// parents of cell i are i ± h, h = lowbit(i). Used for profiles and tests.
#pragma once

#include <vector>

#include "common/grid.hpp"
#include "mcmd/params.hpp"
#include "mcmd/progress.hpp"

namespace mcmd {

// Top-down MD on a line: each unset cell from its two parents (+ displacement
// with dimension 1). With constraints inside an interval whose ends are unset,
// this shows the paper's Fig. 4 jumps. Pre: z.size() == s.size() == 2^n + 1.
std::vector<double> line_md(const std::vector<double>& z, const std::vector<CellState>& s,
                            const FillParams& params);

// MCMD on a line: MDBU then MD (paper Fig. 6).
std::vector<double> line_mcmd(const std::vector<double>& z, const std::vector<CellState>& s,
                              const FillParams& params);

}  // namespace mcmd
