// One level of the nested 2^l+1 hierarchy as a compact square array, with the
// cells pinned at that lattice position and the runs of free cells to update.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace mcmd {

// A run [x0, x1) of free (unpinned) cells on row y.
struct Span {
  int y = 0;
  int x0 = 0;
  int x1 = 0;
};

struct Lattice {
  int side = 0;                     // 2^l + 1
  std::vector<double> z;            // values (relative to the fill's reference elevation)
  std::vector<std::uint8_t> pinned; // 1: a true constraint at this lattice position
  std::vector<Span> spans;          // free cells in raster order
  // Optional soft data term Σ spring·(z - target)² added to the energy of the
  // free cells (empty: none). Pulls towards an estimate without pinning it.
  std::vector<double> spring;
  std::vector<double> target;
  // Tension: weight of the membrane term Σ over grid edges (z_i - z_j)² added
  // to the thin-plate energy, in this lattice's own units (a level of spacing
  // 2^k cells carries 4^k times the finest level's). 0: pure thin plate.
  double tension = 0.0;

  std::size_t index(int x, int y) const {
    return static_cast<std::size_t>(y) * static_cast<std::size_t>(side) + static_cast<std::size_t>(x);
  }
  std::size_t free_count() const;
};

// Runs of cells with pinned == 0, row by row. Pre: pinned.size() == side².
std::vector<Span> free_spans(const std::vector<std::uint8_t>& pinned, int side);

// Which coarse cells are pinned.
enum class CoarsePin {
  position,      // fine cell (2i, 2j) is pinned: the true constraints of the coarse lattice
  neighbourhood, // any fine cell (2i+dx, 2j+dy), |dx|, |dy| <= 1, is pinned: a coarse
                 // problem at least as stiff as the fine one (multigrid corrections)
};

// The next coarser lattice (side (s+1)/2): cell (i, j) is fine cell (2i, 2j),
// pinned by `rule`; z copied from (2i, 2j) at pinned cells, 0 elsewhere;
// tension 4× the fine one's.
// Pre: fine.side >= 3 and odd.
Lattice coarser_lattice(const Lattice& fine, CoarsePin rule = CoarsePin::position);

}  // namespace mcmd
