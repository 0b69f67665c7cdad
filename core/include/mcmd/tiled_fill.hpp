// Fill a raster of any size through 2^k+1 tiles with bounded memory, seamless
// output and bit-identical results for any thread count or processing order
// (SPEC §3; the design is in docs/tiling.md).
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

#include "mcmd/fill.hpp"

namespace mcmd {

// The raster, as the caller stores it. Both functions are called only from the
// thread that calls tiled_fill, with rectangles inside the raster.
// `read` must return the ORIGINAL raster even after `write` calls (windows
// overlap: read from the source, write to the destination).
struct RasterAccess {
  int width = 0;
  int height = 0;
  // Cells [x0, x0+w) × [y0, y0+h), row-major: elevations and valid flags (1 = known).
  std::function<void(int x0, int y0, int w, int h, double* z, std::uint8_t* valid)> read;
  // Write the cells of that rectangle where mask is set (void cells being filled).
  std::function<void(int x0, int y0, int w, int h, const double* z, const std::uint8_t* mask)> write;
};

struct TilingParams {
  int tile_side = 0;          // 0 = default (kDefaultTileSide), else 2^k + 1, k >= 1
  int threads = 0;            // 0 = all cores
  double max_distance = 0.0;  // cells; 0 = unlimited (see docs/tiling.md for its exactness)
  // Tiles even where the raster is small enough to fill whole (docs/tiling.md,
  // "Small rasters"); tile_side alone does not ask for tiles.
  bool always_tile = false;
};

constexpr int kDefaultTileSide = 129;  // measured: see docs/tiling.md

// With the default method a raster of at most this many cells (2^21, e.g.
// 1448²) is read whole once, filled without tiles and written at the end
// (docs/tiling.md, "Small rasters").
constexpr std::size_t kWholeRasterMaxCells = std::size_t{1} << 21;

// The tile side actually used: `requested` (0 = default), reduced to the
// smallest 2^k + 1 (k >= 1) that covers max(width, height) when that is smaller.
// Throws std::invalid_argument when requested is neither 0 nor 2^k + 1.
int effective_tile_side(int width, int height, int requested);

// Worker threads actually used for `requested` (0 = hardware concurrency).
int effective_threads(int requested);

// What a run did; for tests and benchmarks.
struct TiledFillStats {
  int tile_side = 0;
  int tiles_x = 0;
  int tiles_y = 0;
  std::size_t windows_solved = 0;  // tiles whose output region holds a void (of a large component)
  std::size_t small_components = 0;  // void components solved alone (docs/tiling.md)
  int guide_stride = 0;            // 0: no guide (a single tile, or no cell far enough from data)
  std::size_t known_cells = 0;
  std::size_t void_cells = 0;
  std::size_t cells_written = 0;
};

// Test hooks: permute the order in which windows are computed (their results
// are still combined in a fixed order), and collect statistics (filled in
// after the first pass too, so a caller sees the counts when it throws).
struct TiledFillHooks {
  std::function<void(std::vector<std::size_t>& order)> reorder;
  TiledFillStats* stats = nullptr;
};

// Fill every void cell of the raster (every void cell within max_distance of
// a known cell when max_distance > 0); known cells are never written.
// Throws std::invalid_argument (bad parameters, no known cell), Cancelled when
// `progress` refuses (from the calling thread only), and rethrows what
// read/write throw.
void tiled_fill(const RasterAccess& raster, const FillParams& params, const TilingParams& tiling,
                const ProgressFn& progress = {});
void tiled_fill(const RasterAccess& raster, const FillParams& params, const TilingParams& tiling,
                const ProgressFn& progress, const TiledFillHooks& hooks);

}  // namespace mcmd
