// Owning GDAL dataset handles, and what a copy of a dataset leaves out.
#pragma once

#include <memory>

#include "gdal_priv.h"

namespace mcmd::cli {

struct DatasetCloser {
  void operator()(GDALDataset* ds) const { GDALClose(GDALDataset::ToHandle(ds)); }
};
using DatasetPtr = std::unique_ptr<GDALDataset, DatasetCloser>;

// What a MEM CreateCopy does not carry over: description, unit, offset/scale.
void copy_band_info(GDALRasterBand& from, GDALRasterBand& to);

}  // namespace mcmd::cli
