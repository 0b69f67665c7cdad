// Fill the voids of one band through the core's raster engine (fill_raster.hpp):
// block-wise reads of the source band and its masks, writes of the filled void
// cells only; memory bounded by the tile size and thread count.
#pragma once

#include <functional>
#include <vector>

#include "gdal_priv.h"
#include "lib/fill_request.hpp"
#include "lib/options.hpp"
#include "mcmd/progress.hpp"

namespace mcmd::gdal {

// The band's own validity mask, or nullptr when it says every cell is valid.
GDALRasterBand* own_mask(GDALRasterBand& band);

// The options' fill parameters for a band of `type`: an integer band's
// values are whole units (FillParams::z_step).
FillParams fill_params(const Options& options, GDALDataType type);

// Read `band` and its masks and throw the Failure fill_band would throw for
// them (nothing marks voids, no valid cell), without writing anything.
void check_band(GDALRasterBand& band, const FillRequest& request);

// Fill the voids of `source` (its NaN cells, nodata and request.masks) into
// `target`, a band of the same size and type holding the same known cells
// (the source itself for in-place filling, or a copy). Only void cells of
// target are written, and a band with no void cell is left untouched; a blank
// target (request.blank_target: a copy of blank_source) gets every cell.
// Throws Failure (no valid cell, nothing marks voids, I/O), Cancelled,
// OptionError, std::invalid_argument, std::bad_alloc.
void fill_band(GDALRasterBand& target, GDALRasterBand& source, const FillRequest& request, const Options& options,
               const ProgressFn& progress);

void fill_band(const TargetBand& target, GDALRasterBand& source, const FillRequest& request, const Options& options,
               const ProgressFn& progress);

// In place: fill_band(band, band, ...).
void fill_band(GDALRasterBand& band, const FillRequest& request, const Options& options,
               const ProgressFn& progress);

}  // namespace mcmd::gdal
