// The shaded preview of -hillshade: the terrain's hillshade
// (mcmd/terrain_filters.hpp) as an 8-bit grey image for the PNG driver.
#pragma once

#include "cli/dataset.hpp"
#include "gdal_priv.h"
#include "terrain/terrain_geo.hpp"

namespace mcmd::cli {

// GDAL's PNG driver. Throws gdal::Failure when GDAL was built without it.
GDALDriver* png_driver();

// A MEM Byte dataset holding the hillshade of `band`. With a geotransform the
// cell size is its own (in metres for a geographic CRS); without one a cell
// is taken as wide as an eighth of the relief per eighth of the raster
// (elevation range × 8 / the larger side), a moderate shading for a sketch
// in pixel coordinates.
DatasetPtr hillshade_of(GDALRasterBand& band, const Georef& georef);

}  // namespace mcmd::cli
