// Rasters small enough to hold whole are filled without tiles (internal to the
// tiled fill; docs/tiling.md, "Small rasters"). Tiles exist to bound memory:
// below kSingleFieldMaxCells the raster is held whole and each void component
// is solved once in a field around it, instead of in ~4 overlapping windows;
// a raster that is one big void (3.3 % kept) is one field.
#pragma once

#include <cstddef>

#include "mcmd/tiled_fill.hpp"

namespace mcmd::detail {

// 2^21 cells (e.g. 1448²): about 250 MB at the solver's ~120 bytes per cell,
// the peak of the tiled fill on large rasters.
constexpr std::size_t kSingleFieldMaxCells = kWholeRasterMaxCells;

// The default method (smooth or with roughness: rs, rs auto), tiles not forced
// (TilingParams::always_tile) and a raster of at most kSingleFieldMaxCells
// cells. The tile size plays no part: it is the size used when tiling.
bool single_field_applies(int width, int height, const FillParams& params, const TilingParams& tiling);

// Each void component is solved in its own field (void_field.hpp).

// Unknown cells farther than kGuideRadiusStrides · stride from data are pinned
// to a coarse guide of this stride at least (the tiles' stride when larger).
constexpr int kMinGuideStride = 4;

// Fills `raster` as one field: one read, one solve, one write of the void
// cells (within max_distance of a known cell when that is > 0, measured
// exactly). Stats as tiled_fill's (tile_side 0: no tiles). Returns false,
// having written nothing, when a void cell lies so far from data that the
// coarse guide's tension is needed (reaches_far): tiles then.
// Throws as tiled_fill.
bool fill_single_field(const RasterAccess& raster, const FillParams& params, const TilingParams& tiling,
                       const ProgressFn& progress, TiledFillStats* stats);

}  // namespace mcmd::detail
