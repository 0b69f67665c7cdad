// The space an output needs, checked before anything is written: a huge
// raster (a VRT declaring 200000x200000 cells over a small file) otherwise
// wrote tens of gigabytes before failing on a full disk.
#pragma once

#include <cstdint>
#include <string>

#include "gdal_priv.h"

namespace mcmd::cli {

// The raster's cells, every band, uncompressed (bytes).
std::uint64_t uncompressed_bytes(GDALDataset& ds);

// Throws gdal::Failure ("cannot write '<dst>': it needs ... free") when
// dst's folder has less than `bytes` free for us (statvfs). `what` says what
// the bytes are. Paths GDAL handles itself (/vsi...) are not checked.
void check_space(const std::string& dst, std::uint64_t bytes, const std::string& what);

}  // namespace mcmd::cli
