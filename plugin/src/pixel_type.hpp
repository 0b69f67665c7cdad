// A band's pixel type and nodata value, and the conversion of filled
// elevations to that type (rounded, clamped, never equal to nodata).
#pragma once

#include <cstddef>
#include <cstdint>

#include "gdal_priv.h"

namespace mcmd::gdal {

struct PixelType {
  GDALDataType gdt = GDT_Unknown;  // type of the native buffer
  bool signed_byte = false;        // GDT_Byte with PIXELTYPE=SIGNEDBYTE (GDAL < 3.7)
  bool has_nodata = false;
  double nodata = 0.0;             // for all but the 64-bit integer types
  std::int64_t nodata_i64 = 0;
  std::uint64_t nodata_u64 = 0;
};

// Describe `band`. Throws Failure for complex or unknown types.
PixelType pixel_type_of(GDALRasterBand& band);

// Convert `count` doubles to the native type into `out` (count · bytes_per_pixel).
// Integers are rounded half away from zero and clamped; any value that would
// equal the nodata value is nudged by one unit towards the double value.
void encode(const PixelType& type, const double* values, std::size_t count, void* out);

}  // namespace mcmd::gdal
