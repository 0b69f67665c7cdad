// Fill the voids of one band in place: read → mirror-pad → mcmd::fill → write
// back only the void cells. Whole band in memory for now; the read/fill/write
// step works on a Window so tiled streaming can replace the single window.
#pragma once

#include <vector>

#include "gdal_priv.h"
#include "mcmd/progress.hpp"
#include "options.hpp"

namespace mcmd::gdal {

struct FillRequest {
  std::vector<GDALRasterBand*> masks;  // validity masks, 0 = void (see read_window)
  bool require_void_marker = false;    // fail when no mask and no NaN marks a void
  bool use_nodata = true;              // honour the band's nodata value (see read_window)
  int band_number = 0;                 // for messages; 0 = unnamed
};

// The band's own validity mask, or nullptr when it says every cell is valid.
GDALRasterBand* own_mask(GDALRasterBand& band);

// Read `band` and its masks and throw the Failure fill_band would throw for
// them (nothing marks voids, no valid cell), without writing anything.
void check_band(GDALRasterBand& band, const FillRequest& request);

// Fill `band`. Throws Failure (no valid cell, nothing marks voids, I/O),
// Cancelled, OptionError, std::invalid_argument, std::bad_alloc.
// A band with no void cell is left untouched.
void fill_band(GDALRasterBand& band, const FillRequest& request, const Options& options,
               const ProgressFn& progress);

}  // namespace mcmd::gdal
