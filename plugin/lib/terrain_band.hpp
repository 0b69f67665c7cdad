// A terrain made into a GDAL band (MCMDTerrain's body): the constraints
// (a sketch, Iizuka's peaks or a skeleton, points, states), the synthesis,
// the median filter, then every cell written in the band's type.
#pragma once

#include "gdal_priv.h"
#include "lib/terrain_options.hpp"
#include "mcmd/progress.hpp"
#include "mcmd/terrain.hpp"

namespace mcmd::gdal {

// The constraints of the terrain of `target` (its size; its dataset's
// georeferencing places RIDGES and RIVERS). `sketch` may be null; with
// UPSAMPLE=K the sketch (or the peaks) is the coarse raster,
// ((w−1)/K+1)×((h−1)/K+1). Throws Failure / OptionError /
// std::invalid_argument with one line.
Canvas terrain_constraints(GDALRasterBand& target, GDALRasterBand* sketch, const TerrainOptions& options);

// Fill `target` (every cell; with METHOD=none the unknown cells get the
// band's nodata value, or NaN for a float band without one).
// Throws as terrain_constraints, Cancelled when `progress` refuses.
void make_terrain(GDALRasterBand& target, GDALRasterBand* sketch, const TerrainOptions& options,
                  const ProgressFn& progress);

}  // namespace mcmd::gdal
