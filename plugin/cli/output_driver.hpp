// The driver a filled copy is written with, and whether it can hold the
// raster exactly. mcmd promises bit-exact valid cells: a driver that cannot
// store a band's type, that compresses lossily, that reprojects or resamples,
// or that keeps no data of its own (VRT, MEM) is refused before anything is
// filled, in one line naming the driver, the type and what to use instead.
// Drivers these rules do not know are checked after writing (verify_copy).
#pragma once

#include <string>

#include "cpl_string.h"
#include "gdal_priv.h"

namespace mcmd::cli {

// -of `format`, else the driver of dst's extension, else GTiff. Throws
// gdal::Failure for an unknown format or one that cannot write rasters.
GDALDriver* output_driver(const std::string& format, const std::string& dst);

// Throws gdal::Failure when `driver` with creation options `co` cannot hold
// every band of `src` exactly.
void check_output_driver(GDALDriver* driver, const CPLStringList& co, GDALDataset& src);

}  // namespace mcmd::cli
