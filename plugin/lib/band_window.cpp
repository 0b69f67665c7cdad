#include "lib/band_window.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <string>
#include <type_traits>

#include "lib/errors.hpp"

namespace mcmd::gdal {

namespace {

void apply_mask(GDALRasterBand& mask, const Window& win, std::uint8_t* valid) {
  // One request for the window, as bytes (a mask is 0 where invalid).
  std::vector<std::uint8_t> m(win.cells());
  check_io(mask.RasterIO(GF_Read, win.x, win.y, win.w, win.h, m.data(), win.w, win.h, GDT_Byte, 0, 0, nullptr),
           "cannot read the mask");
  for (std::size_t i = 0; i < m.size(); ++i)
    if (m[i] == 0) valid[i] = 0;
}

// The window as `gdt` into out (row-major). A read-only band read whole in
// its own type is decoded block by block straight into one scratch block:
// each block is decoded once anyway, and GDAL's block cache would hold a
// second copy of the band, fresh memory (a page fault per 4 KiB) kept until
// the dataset closes.
void read_raw(GDALRasterBand& band, const Window& win, GDALDataType gdt, void* out) {
  const bool whole = win.x == 0 && win.y == 0 && win.w == band.GetXSize() && win.h == band.GetYSize();
  if (!whole || gdt != band.GetRasterDataType() || band.GetAccess() != GA_ReadOnly) {
    check_io(band.RasterIO(GF_Read, win.x, win.y, win.w, win.h, out, win.w, win.h, gdt, 0, 0, nullptr),
             "cannot read the band");
    return;
  }
  int bw = 0, bh = 0;
  band.GetBlockSize(&bw, &bh);
  const std::size_t size = GDALGetDataTypeSizeBytes(gdt);
  std::vector<unsigned char> block(static_cast<std::size_t>(bw) * bh * size);
  auto* to = static_cast<unsigned char*>(out);
  for (int by = 0; by * bh < win.h; ++by)
    for (int bx = 0; bx * bw < win.w; ++bx) {
      check_io(band.ReadBlock(bx, by, block.data()), "cannot read the band");
      const int x0 = bx * bw, y0 = by * bh;
      const std::size_t cols = std::min(bw, win.w - x0) * size;
      for (int r = 0; r < std::min(bh, win.h - y0); ++r)
        std::memcpy(to + (static_cast<std::size_t>(y0 + r) * win.w + x0) * size,
                    block.data() + static_cast<std::size_t>(r) * bw * size, cols);
    }
}

// The window in the band's own type, widened here: GDAL's conversion to
// Float64 cost three times the read itself (1201² Int16: 10 ms vs 3 ms).
template <class T>
std::vector<T> read_native(GDALRasterBand& band, const Window& win, GDALDataType gdt, double* z) {
  std::vector<T> raw(win.cells());
  read_raw(band, win, gdt, raw.data());
  for (std::size_t i = 0; i < raw.size(); ++i) z[i] = static_cast<double>(raw[i]);
  return raw;
}

// An integer band whose own mask is its nodata value (GMF_NODATA), the value
// an exact integer of the type (nodata_as): the mask is raw == nodata,
// computed here instead of by GDAL's mask band, which reads the window a
// second time. A nodata GDAL would truncate or ignore (fractional, out of
// range) is left to GDAL's mask band.
template <class T>
bool integer_nodata(GDALRasterBand& band, const PixelType& type, T& out) {
  return band.GetMaskFlags() == GMF_NODATA && nodata_as<T>(type, out);
}

// Hands `raw` (values of `gdt`) over to *keep, when there is one.
template <class T>
void keep_native(std::vector<T>&& raw, GDALDataType gdt, NativeCells* keep) {
  if (!keep) return;
  auto owner = std::make_shared<std::vector<T>>(std::move(raw));
  keep->data = std::shared_ptr<void>(owner, owner->data());
  keep->type = gdt;
}

template <class T>
bool read_integer(GDALRasterBand& band, const PixelType& type, const Window& win, GDALDataType gdt, bool own_mask,
                  double* z, std::uint8_t* valid, NativeCells* keep) {
  std::vector<T> raw = read_native<T>(band, win, gdt, z);
  T nodata{};
  const bool masked = own_mask && integer_nodata<T>(band, type, nodata);
  if (masked)  // a select, not a branch: it vectorises (valid is all 1 here)
    for (std::size_t i = 0; i < raw.size(); ++i) valid[i] = raw[i] != nodata;
  keep_native(std::move(raw), gdt, keep);
  return masked;
}

// GDAL's ARE_REAL_EQUAL, without its overflow: |a + b| is infinite for two
// values near the end of the type's range, which made every such value
// "equal" to a nodata there (-DBL_MAX, say). The same test where a + b is
// finite; halved where it is not.
template <class T>
bool real_equal(T a, T b) {
  constexpr T tolerance = std::numeric_limits<float>::epsilon() * 2;  // ARE_REAL_EQUAL's, ulp = 2
  const T sum = a + b;
  if (!std::isinf(sum)) return a == b || std::abs(a - b) < tolerance * std::abs(sum);
  return std::abs(a - b) / 2 < tolerance * std::abs(a / 2 + b / 2);
}

// A float band whose own mask is its nodata value: GDAL's nodata mask band
// compares each value to the nodata (as the band's type) with ARE_REAL_EQUAL,
// and NaN to a NaN nodata. The same test here spares the mask band's second
// read of the window. GMF_NODATA implies the nodata is in the type's range.
template <class T>
void mark_float_nodata(const T* raw, std::size_t n, T nodata, std::uint8_t* valid) {
  if (std::isnan(nodata)) {
    for (std::size_t i = 0; i < n; ++i)
      if (std::isnan(raw[i])) valid[i] = 0;
  } else {
    for (std::size_t i = 0; i < n; ++i)
      if (!std::isnan(raw[i]) && real_equal(raw[i], nodata)) valid[i] = 0;
  }
}

template <class T>
bool read_float(GDALRasterBand& band, const PixelType& type, const Window& win, GDALDataType gdt, bool own_mask,
                double* z, std::uint8_t* valid, NativeCells* keep) {
  const std::size_t n = win.cells();
  std::vector<T> native;
  const T* raw = nullptr;
  if constexpr (std::is_same_v<T, double>) {  // straight into z: nothing to widen
    read_raw(band, win, gdt, z);
    raw = z;
    if (keep) native.assign(z, z + n);  // z is the fill's to change
  } else {
    native = read_native<T>(band, win, gdt, z);
    raw = native.data();
  }
  const bool masked = own_mask && type.has_nodata && band.GetMaskFlags() == GMF_NODATA;
  if (masked) mark_float_nodata(raw, n, static_cast<T>(type.nodata), valid);
  keep_native(std::move(native), gdt, keep);
  return masked;
}

// Reads the values into z; with `own_mask` (the band's own mask is one of
// the masks asked for) returns true when it also marked that mask's voids
// in `valid` (the caller then skips it).
bool read_values(GDALRasterBand& band, const PixelType& type, const Window& win, bool own_mask, double* z,
                 std::uint8_t* valid, NativeCells* keep) {
  switch (type.signed_byte ? GDT_Unknown : type.gdt) {
    case GDT_Byte: return read_integer<std::uint8_t>(band, type, win, GDT_Byte, own_mask, z, valid, keep);
    case GDT_Int16: return read_integer<std::int16_t>(band, type, win, GDT_Int16, own_mask, z, valid, keep);
    case GDT_UInt16: return read_integer<std::uint16_t>(band, type, win, GDT_UInt16, own_mask, z, valid, keep);
    case GDT_Int32: return read_integer<std::int32_t>(band, type, win, GDT_Int32, own_mask, z, valid, keep);
    case GDT_UInt32: return read_integer<std::uint32_t>(band, type, win, GDT_UInt32, own_mask, z, valid, keep);
    case GDT_Float32: return read_float<float>(band, type, win, GDT_Float32, own_mask, z, valid, keep);
    case GDT_Float64: return read_float<double>(band, type, win, GDT_Float64, own_mask, z, valid, keep);
    default: break;
  }
  if (!type.signed_byte) {
    read_raw(band, win, GDT_Float64, z);
    return false;
  }
  std::vector<signed char> raw(win.cells());
  read_raw(band, win, GDT_Byte, raw.data());
  for (std::size_t i = 0; i < raw.size(); ++i) z[i] = raw[i];
  keep_native(std::move(raw), GDT_Byte, keep);
  return false;
}

}  // namespace

void check_mask_size(GDALRasterBand& mask, GDALRasterBand& band) {
  if (mask.GetXSize() != band.GetXSize() || mask.GetYSize() != band.GetYSize())
    throw Failure(CPLE_IllegalArg, "the mask is " + std::to_string(mask.GetXSize()) + "x" +
                                       std::to_string(mask.GetYSize()) + " but the band is " +
                                       std::to_string(band.GetXSize()) + "x" + std::to_string(band.GetYSize()));
}

std::size_t read_cells(GDALRasterBand& band, const PixelType& type, const std::vector<GDALRasterBand*>& masks,
                       const Window& win, bool signed_nodata, double* z, std::uint8_t* valid, bool* marked,
                       NativeCells* keep) {
  const std::size_t n = win.cells();
  std::fill(valid, valid + n, std::uint8_t{1});
  const bool own_mask = std::find(masks.begin(), masks.end(), band.GetMaskBand()) != masks.end();
  const bool own_nodata_done = read_values(band, type, win, own_mask, z, valid, keep);
  const bool nodata_voids = signed_nodata && type.signed_byte && type.has_nodata;
  if (nodata_voids)
    for (std::size_t i = 0; i < n; ++i)
      if (z[i] == type.nodata) valid[i] = 0;
  // Integers are finite: the pass is spared (a tenth of a window's read).
  if (!GDALDataTypeIsInteger(type.gdt) || GDALDataTypeIsComplex(type.gdt))
    for (std::size_t i = 0; i < n; ++i)
      if (!std::isfinite(z[i])) valid[i] = 0;
  for (GDALRasterBand* mask : masks) {
    check_mask_size(*mask, band);
    if (own_nodata_done && mask == band.GetMaskBand()) continue;
    apply_mask(*mask, win, valid);
  }
  const std::size_t voids = n - static_cast<std::size_t>(std::count(valid, valid + n, std::uint8_t{1}));
  if (marked) *marked = !masks.empty() || nodata_voids || voids > 0;
  return voids;
}

WindowData read_window(GDALRasterBand& band, const PixelType& type, const std::vector<GDALRasterBand*>& masks,
                       const Window& win, bool signed_nodata) {
  WindowData d;
  d.win = win;
  d.z.resize(win.cells());
  d.valid.resize(win.cells());
  d.void_count = read_cells(band, type, masks, win, signed_nodata, d.z.data(), d.valid.data(), &d.voids_marked);
  return d;
}

}  // namespace mcmd::gdal
