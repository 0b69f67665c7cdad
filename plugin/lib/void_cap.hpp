// MAX_VOID in square metres as a number of cells of a dataset's grid.
#pragma once

#include <cstddef>

#include "gdal_priv.h"
#include "lib/options.hpp"

namespace mcmd::gdal {

// The area of one cell of `ds` in square metres: its geotransform in the
// CRS's linear unit, or, for a geographic CRS, at the raster's central
// latitude on a sphere of the ellipsoid's mean radius. Throws OptionError
// when `ds` has no geotransform or no CRS.
double cell_area_m2(GDALDataset& ds);

// o.max_void as a cell count for TilingParams::max_void_cells (0 = no cap).
// Throws OptionError for an area smaller than one cell.
std::size_t void_cap_cells(const Options& o, GDALDataset* ds);

}  // namespace mcmd::gdal
