// Owning GDAL dataset handles, and the output copies the CLI fills.
#pragma once

#include <memory>
#include <string>

#include "cli/error_log.hpp"
#include "gdal_priv.h"

namespace mcmd::cli {

struct DatasetCloser {
  void operator()(GDALDataset* ds) const { GDALClose(GDALDataset::ToHandle(ds)); }
};
using DatasetPtr = std::unique_ptr<GDALDataset, DatasetCloser>;

// `from` copied to `path` by `driver` with creation options `co`. Throws
// gdal::Failure: CPLE_UserInterrupt ("cancelled by the user") when `progress`
// refused, else "cannot write '<shown>': <GDAL's first failure>" (from `log`,
// which this thread's GDAL errors must reach).
DatasetPtr create_copy(GDALDriver* driver, const std::string& path, GDALDataset& from, CSLConstList co,
                       ErrorLog& log, GDALProgressFunc progress, void* progress_arg, const std::string& shown);

// Reopen a dataset that create_copy returned, for update (flushes it first).
// Throws gdal::Failure.
DatasetPtr reopen_for_update(DatasetPtr ds, const std::string& path, const std::string& shown);

// What a copy (a MEM CreateCopy) does not carry over, band by band:
// description, unit, offset/scale.
void copy_band_info(GDALDataset& from, GDALDataset& to);

}  // namespace mcmd::cli
