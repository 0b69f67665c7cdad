// The small-raster path of the raster engine (docs/tiling.md, "Small
// rasters"). Tiles exist to bound memory: a raster of at most
// kWholeRasterMaxCells cells is read whole once, each void component is
// solved once in a field around it (void_field.hpp) instead of in ~4
// overlapping windows, and the raster is written once at the end. A raster
// that is one big void (3.3 % kept) is one field.
#pragma once

#include <cstddef>

#include "mcmd/params.hpp"
#include "mcmd/progress.hpp"
#include "mcmd/raster_access.hpp"
#include "raster/void_selection.hpp"

namespace mcmd::detail {

// 2^21 cells (e.g. 1448²): about 250 MB at the solver's ~120 bytes per cell,
// the peak of the tiled fill on large rasters.
constexpr std::size_t kWholeRasterMaxCells = std::size_t{1} << 21;

// Fills `raster` whole: one read, one solve per void component, one write of
// the void cells (within max_distance of a known cell when that is > 0,
// measured exactly). A void with a cell so far from data that the coarse
// guide's tension is needed (reaches_far) is left to the tiles
// (tiles/tiled_fill.hpp), which fill it from the raster as read; the other
// voids keep their own fields' fill. A void component all of whose cells are
// `left` (void_selection.hpp) is not solved.
// Pre: fills_whole(width, height, params, tiling). Throws as fill_raster.
void fill_whole_raster(const RasterAccess& raster, const FillParams& params, const TilingParams& tiling,
                       const ProgressFn& progress, const RasterFillHooks& hooks, const LeftVoids& left);

}  // namespace mcmd::detail
