// A band's pixel type and nodata value, and the conversion of filled
// elevations to that type (rounded, clamped, never equal to nodata).
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>

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

// The nodata value as the integer type T when it is exactly representable
// (an integer in T's range); otherwise no cell of that type can hold it.
template <class T>
bool nodata_as(const PixelType& t, T& out) {
  if (!t.has_nodata || std::isnan(t.nodata)) return false;
  if (t.nodata < static_cast<double>(std::numeric_limits<T>::lowest()) ||
      t.nodata > static_cast<double>(std::numeric_limits<T>::max()) || t.nodata != std::floor(t.nodata))
    return false;
  out = static_cast<T>(t.nodata);
  return true;
}

// Convert `count` doubles to the native type into `out` (count · bytes_per_pixel).
// Integers are rounded half away from zero and clamped; floats are clamped
// to the type's finite range; any value that would equal the nodata value is
// nudged by one unit towards the double value (inwards at the range's end).
// Throws Failure for a NaN value.
void encode(const PixelType& type, const double* values, std::size_t count, void* out);

}  // namespace mcmd::gdal
