// The tiled path of the raster engine (docs/tiling.md): rasters too large to
// hold whole, the paper methods, and TilingParams::always_tile.
#pragma once

#include "mcmd/params.hpp"
#include "mcmd/progress.hpp"
#include "mcmd/raster_access.hpp"
#include "raster/void_selection.hpp"

namespace mcmd::detail {

// Pass 1 streams the raster once (counts, coarse-guide sums, void components,
// which tiles hold voids); the guide is filled once; then small components
// are solved alone and the windows of the tiles with voids by a worker pool,
// while the calling thread reads their input, blends results in row-major
// tile order and writes what is final. Throws as fill_raster.
// Windows holding only voids that `left` leaves unfilled are not solved.
void tiled_fill(const RasterAccess& raster, const FillParams& params, const TilingParams& tiling,
                const ProgressFn& progress, const RasterFillHooks& hooks, const LeftVoids& left = {});

}  // namespace mcmd::detail
