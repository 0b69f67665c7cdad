// The tiled fill split into chunks that independent workers handle (the
// Python package's Dask fill; docs/dask.md). The raster is cut into chunks
// whose sides are multiples of the tile step P = tile side - 1, and each
// chunk goes through four steps, each a pure function of its inputs:
//
//   1. summarize_chunk: its void cells, known range and the coarse guide's
//      moments of the lattice points it owns (a map over chunks);
//   2. ChunkedPlan from every summary: the guide's solve, the small void
//      components, the jobs (a reduction; any process builds the same plan);
//   3. solve_chunk: the windows of the tiles it owns and the small void
//      components it owns (a map over chunks, given the plan);
//   4. blend_chunk: its cells from the solutions of it and its 8 neighbours.
//
// The result is bit for bit fill_raster's tiled path (TilingParams::
// always_tile, the same tile side), whatever the chunking and the order.
// Steps 1 and 3 read only cells within chunk_margin() of their chunk.
// Not handled: lines, a second DEM, values beyond ±1e100 (the plan throws
// std::invalid_argument for the last; the others are not asked here).
#pragma once

#include <cstddef>
#include <cstdint>
#include <limits>
#include <memory>
#include <vector>

#include "mcmd/params.hpp"
#include "mcmd/progress.hpp"
#include "mcmd/raster_access.hpp"

namespace mcmd {

struct CellRect {  // [x0, x0 + w) × [y0, y0 + h)
  int x0 = 0, y0 = 0, w = 0, h = 0;
};

// How a width × height raster must be chunked for these tiling parameters
// and this method (its default tile side).
struct ChunkGrid {
  int step = 0;         // chunk sides (but the last ones) are multiples of it: the tile step P
  int min_side = 0;     // and at least this long
  int margin = 0;       // cells read around a chunk: what its windows, lone voids and guide blocks reach
  bool whole = false;   // one tile: the raster must be one chunk
  int guide_stride = 0; // the coarse guide's stride S (0: one tile, no guide)
};
ChunkGrid chunk_grid(int width, int height, const TilingParams& tiling, Method method);

struct ChunkSummary {
  CellRect own;
  int i0 = 0, i1 = 0, j0 = 0, j1 = 0;  // the lattice points whose moments follow
  std::vector<double> moments;         // 9 per point, row-major
  std::size_t known = 0;
  std::size_t voids = 0;
  double lo = std::numeric_limits<double>::infinity();  // known range
  double hi = -std::numeric_limits<double>::infinity();
  std::vector<int> void_runs;  // y, x0, x1 (exclusive) per run of void cells of `own`
};

// Step 1. `raster` is the whole raster's geometry (reads are asked only near `own`).
ChunkSummary summarize_chunk(const RasterAccess& raster, const TilingParams& tiling, Method method, CellRect own);

// Step 2. Throws std::invalid_argument when no cell is known, or for what
// the chunked fill does not handle.
class ChunkedPlan {
 public:
  ChunkedPlan(int width, int height, const FillParams& params, const TilingParams& tiling,
              const std::vector<ChunkSummary>& summaries);
  ~ChunkedPlan();
  ChunkedPlan(const ChunkedPlan&) = delete;
  ChunkedPlan& operator=(const ChunkedPlan&) = delete;

  bool has_voids() const;  // false: nothing to fill
  std::size_t known_cells() const;
  std::size_t void_cells() const;

  struct State;
  const State& state() const { return *state_; }

 private:
  std::unique_ptr<State> state_;
};

// A window's fill over its tile's output region, kept only where it can
// matter: at the region's void cells (a blend writes nothing else), as runs,
// so that it is small where voids are few.
struct WindowSolution {
  int tx = 0, ty = 0;
  int x0 = 0, x1 = 0, y0 = 0, y1 = 0;  // the tile's output region
  std::vector<std::int32_t> runs;      // per run of void cells: y, x0, x1 (exclusive), 1 if this window writes them
  std::vector<double> z;               // their values, run after run
};
struct ComponentSolution {
  std::size_t index = 0;      // among the plan's small components
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;  // its bounding box, inclusive
  std::vector<double> values; // its cells, run after run
};
struct ChunkSolution {
  std::vector<WindowSolution> windows;
  std::vector<ComponentSolution> components;
};

// Step 3. Throws Cancelled when `progress` refuses.
ChunkSolution solve_chunk(const RasterAccess& raster, const ChunkedPlan& plan, CellRect own,
                          const ProgressFn& progress = {});

// The part of a chunk's solution that the blend of chunk `other` needs: the
// windows whose output region meets it and the components whose box does
// (what a neighbour sends, rather than its whole solution).
ChunkSolution solution_part(const ChunkSolution& s, CellRect other);

// Step 4: writes the filled cells of `own` through out.write (void cells
// only; nothing outside `own`). `around` holds the solutions of the chunk and
// of its neighbours, or their parts for this chunk (any order; more is harmless).
void blend_chunk(const RasterAccess& out, const ChunkedPlan& plan, const std::vector<const ChunkSolution*>& around,
                 CellRect own);

}  // namespace mcmd
