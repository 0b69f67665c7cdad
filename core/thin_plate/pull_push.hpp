// The bottom-up pass of the default method (MDBU's role): a weighted
// restriction ("pull") of the constraint cells up the nested 2^l+1 hierarchy.
// Every level gets, per cell, the weighted mean of the constraint cells below
// it and their density (the fraction of its footprint that is constrained). These are soft estimates: the top-down pass
// uses them as starting values, never as fixed ones.
#pragma once

#include <vector>

#include "thin_plate/lattice.hpp"

namespace mcmd {

struct PullLevel {
  int w = 0;
  int h = 0;
  std::vector<double> mean;    // weighted mean of the constraints (0 where weight is 0)
  std::vector<double> weight;  // constraint density in [0, 1] (0: no estimate)
};

// Levels from the coarsest (2×2) up to the one just below `finest` (whose
// own estimate is its pinned cells: weight 1 and mean z there, 0 elsewhere);
// sizes as coarser_lattice's (lattice.hpp). Coarse cell (i, j) gathers fine cells (2i+dx, 2j+dy), |dx|, |dy| <= 1, with
// weights (1, ½, ¼) for (centre, edge, corner), the transpose of bilinear
// interpolation, normalised by the kernel weight inside the grid.
std::vector<PullLevel> pull(const Lattice& finest);

}  // namespace mcmd
