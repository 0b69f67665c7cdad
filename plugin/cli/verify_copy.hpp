// The safety net behind output_driver's rules: a copy written from the
// filled work file by another driver is read back and compared with it,
// every cell bit for bit (NaN to NaN), with the band's type, signed-byte
// form and nodata value, before it is renamed into place. A lossy driver
// or option the rules miss then fails the run instead of changing cells.
// A format that stores no type and reads back a wider one (AAIGrid's Int16
// as Int32) is compared value by value.
#pragma once

#include <string>

#include "gdal_priv.h"

namespace mcmd::cli {

// Throws gdal::Failure ("cannot write <driver>: ...") when the dataset at
// `written` does not hold `work` exactly, or refers to `work`'s file.
void verify_copy(GDALDataset& work, const std::string& written, GDALDriver* driver);

}  // namespace mcmd::cli
