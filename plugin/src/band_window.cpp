#include "band_window.hpp"

#include <cmath>
#include <string>

#include "errors.hpp"

namespace mcmd::gdal {

namespace {

void check_io(CPLErr err, const char* what) {
  if (err != CE_None) {
    const std::string detail = CPLGetLastErrorMsg();
    throw Failure(CPLE_FileIO, std::string(what) + (detail.empty() ? "" : ": " + detail));
  }
}

void apply_mask(GDALRasterBand& mask, const Window& win, std::vector<std::uint8_t>& valid) {
  std::vector<double> row(static_cast<std::size_t>(win.w));
  for (int r = 0; r < win.h; ++r) {
    check_io(mask.RasterIO(GF_Read, win.x, win.y + r, win.w, 1, row.data(), win.w, 1, GDT_Float64, 0, 0,
                           nullptr),
             "cannot read the mask");
    std::uint8_t* v = valid.data() + static_cast<std::size_t>(r) * win.w;
    for (int c = 0; c < win.w; ++c)
      if (row[c] == 0.0) v[c] = 0;
  }
}

void read_values(GDALRasterBand& band, const PixelType& type, const Window& win, std::vector<double>& z) {
  z.resize(win.cells());
  if (!type.signed_byte) {
    check_io(band.RasterIO(GF_Read, win.x, win.y, win.w, win.h, z.data(), win.w, win.h, GDT_Float64, 0, 0, nullptr),
             "cannot read the band");
    return;
  }
  std::vector<signed char> raw(win.cells());
  check_io(band.RasterIO(GF_Read, win.x, win.y, win.w, win.h, raw.data(), win.w, win.h, GDT_Byte, 0, 0, nullptr),
           "cannot read the band");
  for (std::size_t i = 0; i < raw.size(); ++i) z[i] = raw[i];
}

}  // namespace

WindowData read_window(GDALRasterBand& band, const PixelType& type, const std::vector<GDALRasterBand*>& masks,
                       const Window& win, bool signed_nodata) {
  WindowData d;
  d.win = win;
  d.valid.assign(win.cells(), 1);
  read_values(band, type, win, d.z);
  const bool nodata_voids = signed_nodata && type.signed_byte && type.has_nodata;
  for (std::size_t i = 0; i < d.z.size(); ++i)
    if (nodata_voids && d.z[i] == type.nodata) d.valid[i] = 0;
  for (std::size_t i = 0; i < d.z.size(); ++i)
    if (!std::isfinite(d.z[i])) d.valid[i] = 0;
  for (GDALRasterBand* mask : masks) {
    if (mask->GetXSize() != band.GetXSize() || mask->GetYSize() != band.GetYSize())
      throw Failure(CPLE_IllegalArg, "the mask is " + std::to_string(mask->GetXSize()) + "x" +
                                         std::to_string(mask->GetYSize()) + " but the band is " +
                                         std::to_string(band.GetXSize()) + "x" +
                                         std::to_string(band.GetYSize()));
    apply_mask(*mask, win, d.valid);
  }
  for (std::uint8_t v : d.valid) d.void_count += v ? 0 : 1;
  d.voids_marked = !masks.empty() || nodata_voids || d.void_count > 0;
  return d;
}

void write_cells(GDALRasterBand& band, const PixelType& type, const Window& win, const std::vector<double>& z,
                 const std::vector<std::uint8_t>& write) {
  const int bytes = GDALGetDataTypeSizeBytes(type.gdt);
  std::vector<unsigned char> run(static_cast<std::size_t>(win.w) * bytes);
  for (int r = 0; r < win.h; ++r) {
    const std::size_t base = static_cast<std::size_t>(r) * win.w;
    for (int c = 0; c < win.w;) {
      if (!write[base + c]) {
        ++c;
        continue;
      }
      int end = c;
      while (end < win.w && write[base + end]) ++end;
      encode(type, z.data() + base + c, static_cast<std::size_t>(end - c), run.data());
      check_io(band.RasterIO(GF_Write, win.x + c, win.y + r, end - c, 1, run.data(), end - c, 1, type.gdt, 0, 0,
                             nullptr),
               "cannot write the filled cells");
      c = end;
    }
  }
}

}  // namespace mcmd::gdal
