// The georeferencing of mcmd_terrain's output: a geotransform and a CRS,
// from the sketch (adjusted when it is supersampled), a template raster,
// -a_ullr and -a_srs (which win).
#pragma once

#include <array>
#include <optional>
#include <string>

#include "gdal_priv.h"
#include "terrain/terrain_args.hpp"

namespace mcmd::cli {

struct Georef {
  std::optional<std::array<double, 6>> transform;
  std::string wkt;  // "" = no CRS
};

// The georeferencing of `ds` (a sketch or a template).
Georef georef_of(GDALDataset& ds);

// `g` for a grid k times finer whose cell centres include the coarse ones
// (the first at the same place): origin shifted by (k−1)/(2k) coarse cells.
Georef supersampled(const Georef& g, int k);

// -a_ullr over a w×h raster, -a_srs: applied over `g`. Throws UsageError for a CRS GDAL cannot read.
Georef with_overrides(Georef g, const TerrainArgs& args, int w, int h);

void apply(GDALDataset& ds, const Georef& g);

// The cell size in elevation units (metres for a geographic CRS, at the
// centre latitude), for the hillshade; false without a geotransform.
bool cell_size(const Georef& g, int w, int h, double& dx, double& dy);

}  // namespace mcmd::cli
