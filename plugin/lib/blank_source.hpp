// The source without its pixels: a view that forwards everything
// (georeferencing, metadata, nodata, masks, overviews, driver) to a
// single-band source dataset, except that its band reads as zeros. Copying the
// view makes the output's structure without decoding the source; the fill
// then writes every cell of it (FillRequest::blank_target). For a small
// raster the fill has all the cells in memory anyway: a compressed source is
// decoded once instead of twice (~10 ms of LZW on a 1027×875 Float32), and
// the copy runs while the fill reads.
#pragma once

#include <memory>

#include "gdal_priv.h"

namespace mcmd::gdal {

// Precondition: `source` has exactly one band and outlives the view.
std::unique_ptr<GDALDataset> blank_source(GDALDataset& source);

}  // namespace mcmd::gdal
