#include "cli/verify_copy.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <vector>

#include "cli/dataset.hpp"
#include "cpl_string.h"
#include "lib/errors.hpp"
#include "lib/pixel_type.hpp"

namespace mcmd::cli {

namespace {

[[noreturn]] void refuse(GDALDriver* d, const std::string& why) {
  throw gdal::Failure(CPLE_FileIO, std::string("cannot write ") + d->GetDescription() + ": " + why +
                                       "; write GTiff or COG instead");
}

bool same_nodata(const gdal::PixelType& a, const gdal::PixelType& b) {
  if (a.has_nodata != b.has_nodata) return false;
  if (!a.has_nodata) return true;
  if (std::isnan(a.nodata) || std::isnan(b.nodata)) return std::isnan(a.nodata) && std::isnan(b.nodata);
  return a.nodata == b.nodata && a.nodata_i64 == b.nodata_i64 && a.nodata_u64 == b.nodata_u64;
}

template <class F>
bool same_float(const unsigned char* a, const unsigned char* b) {
  F x, y;
  std::memcpy(&x, a, sizeof x);
  std::memcpy(&y, b, sizeof y);
  return std::isnan(x) && std::isnan(y);
}

// Cells `a` and `b` of `bytes` bytes: the same bits, or both NaN.
bool same_cell(const unsigned char* a, const unsigned char* b, int bytes, GDALDataType type) {
  if (std::memcmp(a, b, bytes) == 0) return true;
  if (type == GDT_Float32) return same_float<float>(a, b);
  if (type == GDT_Float64) return same_float<double>(a, b);
  return false;
}

// Whether every value of type `want` is a value of `got` (a format that
// stores no type, AAIGrid say, reads an Int16 band back as Int32).
bool holds_values(GDALDataType want, GDALDataType got) {
  if (got == want) return true;
  return GDALGetDataTypeSizeBits(want) <= 32 && !GDALDataTypeIsComplex(got) && GDALDataTypeUnion(want, got) == got;
}

void read_rows(GDALRasterBand& band, GDALDataType type, int y0, int rows, std::vector<unsigned char>& buf) {
  buf.resize(static_cast<std::size_t>(band.GetXSize()) * rows * GDALGetDataTypeSizeBytes(type));
  gdal::check_io(band.RasterIO(GF_Read, 0, y0, band.GetXSize(), rows, buf.data(), band.GetXSize(), rows, type, 0,
                               0, nullptr),
                 "cannot read the written output back");
}

// Cell by cell in the band's own type, or as values (Float64: exact for
// both) when the output widened the type.
void compare_cells(GDALRasterBand& work, GDALRasterBand& out, int b, GDALDriver* d) {
  const int W = work.GetXSize(), H = work.GetYSize();
  const GDALDataType own = work.GetRasterDataType();
  const GDALDataType type = out.GetRasterDataType() == own ? own : GDT_Float64;
  const int bytes = GDALGetDataTypeSizeBytes(type);
  const int rows = std::clamp((1 << 20) / std::max(W, 1), 1, std::max(H, 1));  // ~a million cells a request
  std::vector<unsigned char> want, got;
  for (int y0 = 0; y0 < H; y0 += rows) {
    const int n = std::min(rows, H - y0);
    read_rows(work, type, y0, n, want);
    read_rows(out, type, y0, n, got);
    for (std::size_t i = 0; i < static_cast<std::size_t>(W) * n; ++i)
      if (!same_cell(&want[i * bytes], &got[i * bytes], bytes, type))
        refuse(d, "the written file does not hold band " + std::to_string(b) + " exactly (cell " +
                      std::to_string(i % W) + "," + std::to_string(y0 + i / W) + " changed)");
  }
}

void compare_band(GDALRasterBand& work, GDALRasterBand& out, int b, GDALDriver* d) {
  const std::string band = "band " + std::to_string(b);
  const gdal::PixelType want = gdal::pixel_type_of(work), got = gdal::pixel_type_of(out);
  if (!holds_values(want.gdt, got.gdt) || got.signed_byte != want.signed_byte)
    refuse(d, "it wrote " + band + " as " + GDALGetDataTypeName(got.gdt) + (got.signed_byte ? " (signed)" : "") +
                  ", not " + GDALGetDataTypeName(want.gdt) + (want.signed_byte ? " (signed)" : ""));
  if (!same_nodata(want, got)) refuse(d, "it does not keep " + band + "'s nodata value");
  compare_cells(work, out, b, d);
}

}  // namespace

void verify_copy(GDALDataset& work, const std::string& written, GDALDriver* driver) {
  CPLErrorReset();
  DatasetPtr out(GDALDataset::Open(written.c_str(), GDAL_OF_RASTER | GDAL_OF_READONLY));
  if (!out) {
    const std::string why = CPLGetLastErrorMsg();
    refuse(driver, "GDAL cannot open the written file again" + (why.empty() ? "" : ": " + why));
  }
  const CPLStringList files(out->GetFileList());
  for (int i = 0; i < files.size(); ++i)
    if (EQUAL(CPLGetFilename(files[i]), CPLGetFilename(work.GetDescription())))
      refuse(driver, "the written file refers to the temporary work file");
  if (out->GetRasterXSize() != work.GetRasterXSize() || out->GetRasterYSize() != work.GetRasterYSize() ||
      out->GetRasterCount() != work.GetRasterCount())
    refuse(driver, "the written file does not have the raster's size and band count");
  for (int b = 1; b <= work.GetRasterCount(); ++b)
    compare_band(*work.GetRasterBand(b), *out->GetRasterBand(b), b, driver);
}

}  // namespace mcmd::cli
