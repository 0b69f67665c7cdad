// Ridge and river lines for a raster (-ridges, -rivers; RIDGES=, RIVERS=):
// vector lines in any format OGR reads, reprojected with PROJ to the
// raster's CRS, or a raster mask on the raster's grid (nonzero cells are
// line cells).
#pragma once

#include <string>
#include <vector>

#include "gdal_priv.h"
#include "mcmd/lines.hpp"

namespace mcmd::gdal {

// The lines of `path` in pixel coordinates of `raster` (its geotransform
// and CRS), of `kind` (ridge or river). Vertices keep their Z as the line's
// height where the geometry has one. Throws Failure: the file cannot be
// read, holds no line, its lines have no CRS while the raster has one (or
// cannot be transformed), a mask of another size. Lines that miss the
// raster are kept (they simply place no cell): lines_inside() tells.
std::vector<Line> read_lines(const std::string& path, CellState kind, GDALDataset& raster);

// How many of `lines` have a point inside a w×h raster.
std::size_t lines_inside(const std::vector<Line>& lines, int w, int h);

}  // namespace mcmd::gdal
