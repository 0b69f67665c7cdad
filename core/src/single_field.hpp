// Rasters small enough to hold whole are filled as one field (internal to the
// tiled fill; docs/tiling.md, "One field"). Tiles exist to bound memory: below
// kSingleFieldMaxCells one field needs no more memory than the windows of a
// large raster, solves every cell once instead of in ~4 overlapping windows,
// and needs no coarse guide (it *is* the global surface).
#pragma once

#include <cstddef>

#include "mcmd/tiled_fill.hpp"

namespace mcmd::detail {

// 2^21 cells (e.g. 1448²): about 250 MB at the solver's ~120 bytes per cell,
// the peak of the tiled fill on large rasters.
constexpr std::size_t kSingleFieldMaxCells = std::size_t{1} << 21;

// The default smooth method, the default tile size (an explicit -tile asks
// for tiles) and a raster of at most kSingleFieldMaxCells cells.
bool single_field_applies(int width, int height, const FillParams& params, const TilingParams& tiling);

// Fills `raster` as one field: one read, one solve, one write of the void
// cells (within max_distance of a known cell when that is > 0, measured
// exactly). Stats as tiled_fill's (tile_side 0: no tiles). Returns false,
// having written nothing, when a void cell lies so far from data that the
// coarse guide's tension is needed (far_void_tension > 0): tiles then.
// Throws as tiled_fill.
bool fill_single_field(const RasterAccess& raster, const FillParams& params, const TilingParams& tiling,
                       const ProgressFn& progress, TiledFillStats* stats);

}  // namespace mcmd::detail
