// How the raster engine sees a raster and what it is asked to do: the types
// shared by the engine's entry point (fill_raster.hpp), its paths
// (raster/whole_raster.hpp, raster/tiles/tiled_fill.hpp) and the plugin.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

#include "mcmd/lines.hpp"
#include "mcmd/params.hpp"

namespace mcmd {

// The raster, as the caller stores it. Both functions are called only from the
// thread that calls fill_raster, with rectangles inside the raster.
// `read` must return the ORIGINAL raster even after `write` calls (windows
// overlap: read from the source, write to the destination).
struct RasterAccess {
  int width = 0;
  int height = 0;
  // Cells [x0, x0+w) × [y0, y0+h), row-major: elevations and valid flags (1 = known).
  std::function<void(int x0, int y0, int w, int h, double* z, std::uint8_t* valid)> read;
  // Write the cells of that rectangle where mask is set (void cells being filled).
  std::function<void(int x0, int y0, int w, int h, const double* z, const std::uint8_t* mask)> write;
  // Ridge and river lines drawn on the raster (mcmd/lines.hpp); may be empty.
  std::vector<Line> lines;
};

struct TilingParams {
  int tile_side = 0;          // 0 = default (default_tile_side), else 2^k + 1, k >= 1
  int threads = 0;            // 0 = all cores
  double max_distance = 0.0;  // cells; 0 = unlimited (see docs/tiling.md for its exactness)
  // Tiles even where the raster is small enough to fill whole (docs/tiling.md,
  // "Small rasters"); tile_side alone does not ask for tiles.
  bool always_tile = false;
  // Voids left unfilled (raster/void_selection.hpp): those touching the
  // raster's border (-inner), those of more than max_void_cells cells (-maxvoid; 0 = no cap).
  bool inner_only = false;
  std::size_t max_void_cells = 0;
};

// Default tile sides, measured (docs/tiling.md): the default method solves a
// tile's region and one band, so a large tile solves each cell about once;
// the paper methods subdivide a 2^n+1 window of twice the tile.
constexpr int kDefaultTileSide = 513;
constexpr int kPaperTileSide = 129;
constexpr int default_tile_side(Method method) { return method == Method::mcmd ? kDefaultTileSide : kPaperTileSide; }

// What a run did; for tests and benchmarks.
struct RasterFillStats {
  int tile_side = 0;               // 0: the raster was filled whole, without tiles
  int tiles_x = 0;
  int tiles_y = 0;
  std::size_t windows_solved = 0;  // tiles whose output region holds a void (of a large component)
  std::size_t small_components = 0;  // void components solved alone (docs/tiling.md)
  int guide_stride = 0;            // 0: no guide (a single tile, or no cell far enough from data)
  std::size_t known_cells = 0;
  std::size_t void_cells = 0;
  std::size_t cells_written = 0;
  bool channels_skipped = false;   // -morph auto's channels not routed (the voids went to tiles)
};

// Test hooks: permute the order in which windows are computed (their results
// are still combined in a fixed order), and collect statistics (filled in
// after the first pass too, so a caller sees the counts when it throws).
struct RasterFillHooks {
  std::function<void(std::vector<std::size_t>& order)> reorder;
  RasterFillStats* stats = nullptr;
};

}  // namespace mcmd
