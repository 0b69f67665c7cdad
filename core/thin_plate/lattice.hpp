// One level of the nested hierarchy as a compact w×h array (row-major), with
// the cells pinned at that lattice position and the runs of free cells to
// update. Level sizes follow w_coarse = floor(w / 2) + 1: a 2^l+1 side halves
// exactly, any other size gets one ghost column (row) past its end, so a
// raster of any size has its own hierarchy without padding.
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
  int w = 0;                        // columns
  int h = 0;                        // rows
  std::vector<double> z;            // values (relative to the fill's reference elevation)
  std::vector<std::uint8_t> pinned; // 1: a true constraint at this lattice position
  std::vector<Span> spans;          // free cells in raster order
  // Optional soft data term Σ spring·(z - target)² added to the energy of the
  // free cells (empty: none). Pulls towards an estimate without pinning it.
  std::vector<double> spring;
  std::vector<double> target;       // empty with springs: a target of 0
  // Or one spring of this stiffness on every free cell (with `spring` empty):
  // the finest level's pull costs no array and no division per cell.
  double spring_all = 0.0;
  // Tension: weight of the membrane term Σ over grid edges (z_i - z_j)² added
  // to the thin-plate energy, in this lattice's own units (a level of spacing
  // 2^k cells carries 4^k times the finest level's). 0: pure thin plate.
  double tension = 0.0;

  std::size_t index(int x, int y) const {
    return static_cast<std::size_t>(y) * static_cast<std::size_t>(w) + static_cast<std::size_t>(x);
  }
  std::size_t free_count() const;
};

// Large lattices are relaxed in bands of kBandRows rows: even bands, then odd
// ones, each in raster order. Bands two apart never touch (the stencil reaches
// 2 rows), so the bands of a phase may run on any number of threads with the
// same result. Whether a lattice is banded depends on its free cells only.
constexpr int kBandRows = 32;
constexpr std::size_t kBandedMinFree = std::size_t{1} << 17;
bool banded(const Lattice& lat);
// Threads worth using on `lat`: `threads` when banded, else 1 (small lattices
// cost less than a thread team's start).
inline int team(const Lattice& lat, int threads) { return threads > 1 && banded(lat) ? threads : 1; }
// Index of the first span of each band of kBandRows rows, plus spans.size().
std::vector<std::size_t> band_starts(const Lattice& lat);
// Fixed chunks of spans for sums whose order must not depend on the threads.
constexpr std::size_t kSumChunkSpans = 256;

// Runs of cells with pinned == 0, row by row. Pre: pinned.size() == w·h.
std::vector<Span> free_spans(const std::vector<std::uint8_t>& pinned, int w, int h);

// The size of the next coarser level along one axis: fine cell 2i is coarse
// cell i, and the coarse level reaches past the fine one's last cell.
inline int coarser_extent(int fine) { return fine / 2 + 1; }

// Which coarse cells are pinned.
enum class CoarsePin {
  position,      // fine cell (2i, 2j) is pinned: the true constraints of the coarse lattice
  neighbourhood, // any fine cell (2i+dx, 2j+dy), |dx|, |dy| <= 1, is pinned: a coarse
                 // problem at least as stiff as the fine one
  soft,          // position, and the other fine pins as springs on the coarse cells
                 // around them (multigrid corrections: multigrid.hpp)
};

// The next coarser lattice (coarser_extent of each side): cell (i, j) is fine
// cell (2i, 2j), pinned by `rule`; z copied from (2i, 2j) at pinned cells, 0
// elsewhere (a ghost cell past the fine lattice is pinned when its fine
// neighbourhood is, else free); tension 4× the fine one's.
// Pre: fine.w, fine.h >= 2 and one of them >= 3.
Lattice coarser_lattice(const Lattice& fine, CoarsePin rule = CoarsePin::position);

}  // namespace mcmd
