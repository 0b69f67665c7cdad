#include "lib/pixel_type.hpp"

#include <cmath>
#include <cstring>
#include <limits>

#include "lib/errors.hpp"

namespace mcmd::gdal {

namespace {

template <class T>
T clamp_to(double v) {
  constexpr T lo = std::numeric_limits<T>::lowest();
  constexpr T hi = std::numeric_limits<T>::max();
  if (v <= static_cast<double>(lo)) return lo;
  if (v >= static_cast<double>(hi)) return hi;  // 2^63 / 2^64 round up: still safe
  return static_cast<T>(v);
}

// One unit away from `nodata`, towards `v` (upwards on a tie), inside T's range.
template <class T>
T nudge_int(T nodata, double v) {
  const bool up = v >= static_cast<double>(nodata);
  if (up && nodata != std::numeric_limits<T>::max()) return static_cast<T>(nodata + 1);
  if (nodata == std::numeric_limits<T>::lowest()) return static_cast<T>(nodata + 1);
  return static_cast<T>(nodata - 1);
}

// A filled value is a number: NaN would be cast to an integer (undefined)
// or written as a void.
[[noreturn]] void fail_not_a_number() {
  throw Failure(CPLE_AppDefined, "the fill produced a NaN for a void cell (an internal error, please report it)");
}

template <class T>
void encode_int(const double* v, std::size_t n, T* out, bool has_nodata, T nodata) {
  for (std::size_t i = 0; i < n; ++i) {
    if (std::isnan(v[i])) fail_not_a_number();
    T x = clamp_to<T>(std::round(v[i]));
    if (has_nodata && x == nodata) x = nudge_int<T>(nodata, v[i]);
    out[i] = x;
  }
}

template <class T>
void encode_float(const double* v, std::size_t n, T* out, bool has_nodata, double nodata) {
  const bool check = has_nodata && !std::isnan(nodata);
  const T nd = static_cast<T>(nodata);
  for (std::size_t i = 0; i < n; ++i) {
    if (std::isnan(v[i])) fail_not_a_number();
    T x = clamp_to<T>(v[i]);  // ±inf: the largest finite value
    if (check && x == nd) {
      // One step towards v, or inwards from a nodata at the end of the range.
      const bool up = nd == std::numeric_limits<T>::lowest() || (nd != std::numeric_limits<T>::max() && v[i] >= nodata);
      x = std::nextafter(x, up ? std::numeric_limits<T>::max() : std::numeric_limits<T>::lowest());
    }
    out[i] = x;
  }
}

template <class T>
void encode_small_int(const PixelType& t, const double* v, std::size_t n, void* out) {
  T nd{};
  const bool has = nodata_as<T>(t, nd);
  encode_int<T>(v, n, static_cast<T*>(out), has, nd);
}

}  // namespace

PixelType pixel_type_of(GDALRasterBand& band) {
  PixelType t;
  t.gdt = band.GetRasterDataType();
  if (GDALDataTypeIsComplex(t.gdt) || t.gdt == GDT_Unknown)
    throw Failure(CPLE_NotSupported, std::string("band data type ") + GDALGetDataTypeName(t.gdt) +
                                         " is not supported (complex or unknown)");
  if (t.gdt == GDT_Byte) {
    const char* pt = band.GetMetadataItem("PIXELTYPE", "IMAGE_STRUCTURE");
    t.signed_byte = pt && EQUAL(pt, "SIGNEDBYTE");
  }
  int ok = FALSE;
  if (t.gdt == GDT_Int64) {
    t.nodata_i64 = band.GetNoDataValueAsInt64(&ok);
  } else if (t.gdt == GDT_UInt64) {
    t.nodata_u64 = band.GetNoDataValueAsUInt64(&ok);
  } else {
    t.nodata = band.GetNoDataValue(&ok);
  }
  t.has_nodata = ok != FALSE;
  return t;
}

void encode(const PixelType& t, const double* v, std::size_t n, void* out) {
  switch (t.gdt) {
    case GDT_Byte:
      if (t.signed_byte) return encode_small_int<std::int8_t>(t, v, n, out);
      return encode_small_int<std::uint8_t>(t, v, n, out);
#if GDAL_VERSION_NUM >= GDAL_COMPUTE_VERSION(3, 7, 0)
    case GDT_Int8: return encode_small_int<std::int8_t>(t, v, n, out);
#endif
    case GDT_UInt16: return encode_small_int<std::uint16_t>(t, v, n, out);
    case GDT_Int16: return encode_small_int<std::int16_t>(t, v, n, out);
    case GDT_UInt32: return encode_small_int<std::uint32_t>(t, v, n, out);
    case GDT_Int32: return encode_small_int<std::int32_t>(t, v, n, out);
    case GDT_Int64:
      return encode_int<std::int64_t>(v, n, static_cast<std::int64_t*>(out), t.has_nodata, t.nodata_i64);
    case GDT_UInt64:
      return encode_int<std::uint64_t>(v, n, static_cast<std::uint64_t*>(out), t.has_nodata, t.nodata_u64);
    case GDT_Float32: return encode_float<float>(v, n, static_cast<float*>(out), t.has_nodata, t.nodata);
    case GDT_Float64: return encode_float<double>(v, n, static_cast<double*>(out), t.has_nodata, t.nodata);
    default:
      throw Failure(CPLE_NotSupported, std::string("cannot write data type ") + GDALGetDataTypeName(t.gdt));
  }
}

}  // namespace mcmd::gdal
