// read_window marks the voids of a band whose mask is its nodata value from
// the values it reads; these tests hold it to GDAL's own nodata mask band, on
// values at and around the nodata, for every type that takes that path.
#include <cmath>
#include <gtest/gtest.h>
#include <limits>
#include <string>
#include <vector>

#include "gdal_priv.h"
#include "lib/band_window.hpp"
#include "lib/pixel_type.hpp"
#include "test_support.hpp"

namespace {

// One row of `values` in a MEM band of `type` with `nodata`.
GDALDataset* row_band(GDALDataType type, double nodata, const std::vector<double>& values) {
  GDALAllRegister();
  GDALDriver* mem = GetGDALDriverManager()->GetDriverByName("MEM");
  const int n = static_cast<int>(values.size());
  GDALDataset* ds = mem->Create("", n, 1, 1, type, nullptr);
  GDALRasterBand* b = ds->GetRasterBand(1);
  EXPECT_EQ(b->SetNoDataValue(nodata), CE_None);
  std::vector<double> v = values;
  EXPECT_EQ(b->RasterIO(GF_Write, 0, 0, n, 1, v.data(), n, 1, GDT_Float64, 0, 0, nullptr), CE_None);
  return ds;
}

// Cells next to `nodata` in steps of the type's spacing there (as T), plus
// far values and the non-finite ones.
template <class T>
std::vector<double> around(double nodata) {
  std::vector<double> v;
  T up = static_cast<T>(nodata), down = static_cast<T>(nodata);
  v.push_back(static_cast<double>(up));
  for (int k = 0; k < 4; ++k) {
    up = std::nextafter(up, std::numeric_limits<T>::infinity());
    down = std::nextafter(down, -std::numeric_limits<T>::infinity());
    v.push_back(static_cast<double>(up));
    v.push_back(static_cast<double>(down));
  }
  for (double x : {0.0, -0.0, 1.0, -1.0, 1e-30, 1234.5, -9999.0, 3.0e38})
    v.push_back(x);
  v.push_back(std::numeric_limits<double>::quiet_NaN());
  return v;
}

void expect_same_voids_as_gdal(GDALDataType type, double nodata, const std::vector<double>& values) {
  GDALDataset* ds = row_band(type, nodata, values);
  GDALRasterBand* band = ds->GetRasterBand(1);
  ASSERT_EQ(band->GetMaskFlags(), GMF_NODATA);
  const int n = static_cast<int>(values.size());
  std::vector<std::uint8_t> gdal_mask(values.size());
  ASSERT_EQ(band->GetMaskBand()->RasterIO(GF_Read, 0, 0, n, 1, gdal_mask.data(), n, 1, GDT_Byte, 0, 0, nullptr),
            CE_None);
  const mcmd::gdal::PixelType pt = mcmd::gdal::pixel_type_of(*band);
  const mcmd::gdal::WindowData d =
      mcmd::gdal::read_window(*band, pt, {band->GetMaskBand()}, mcmd::gdal::Window{0, 0, n, 1}, true);
  std::vector<double> read_back(values.size());
  ASSERT_EQ(band->RasterIO(GF_Read, 0, 0, n, 1, read_back.data(), n, 1, GDT_Float64, 0, 0, nullptr), CE_None);
  for (int i = 0; i < n; ++i) {
    // Non-finite cells are voids whatever the mask says.
    const bool expected_void = gdal_mask[i] == 0 || !std::isfinite(read_back[i]);
    EXPECT_EQ(d.valid[i] == 0, expected_void) << "value " << read_back[i] << " nodata " << nodata;
    if (std::isfinite(read_back[i])) {
      EXPECT_EQ(d.z[i], read_back[i]);
    }
  }
  GDALClose(GDALDataset::ToHandle(ds));
}

TEST(BandWindow, Float32NodataVoidsMatchGdalsMaskBand) {
  for (double nodata : {-9999.0, 0.0, -32768.5, 1e-30, 3.0e38, -3.4028234663852886e38})
    expect_same_voids_as_gdal(GDT_Float32, nodata, around<float>(nodata));
  expect_same_voids_as_gdal(GDT_Float32, std::numeric_limits<double>::quiet_NaN(), around<float>(-9999.0));
  // A nodata that is not a float: GDAL compares with it rounded to float.
  expect_same_voids_as_gdal(GDT_Float32, -9999.0001, around<float>(-9999.0001));
}

TEST(BandWindow, Float64NodataVoidsMatchGdalsMaskBand) {
  for (double nodata : {-9999.0, 0.0, -32768.5, 1e-30, 3.0e38, -1.7976931348623157e308})
    expect_same_voids_as_gdal(GDT_Float64, nodata, around<double>(nodata));
  // GDAL's tolerance is relative to float precision even for doubles.
  std::vector<double> near = {-9999.0, -9999.0 * (1 + 1e-8), -9999.0 * (1 + 1e-6), -9999.0 * (1 - 2e-7)};
  expect_same_voids_as_gdal(GDT_Float64, -9999.0, near);
  expect_same_voids_as_gdal(GDT_Float64, std::numeric_limits<double>::quiet_NaN(), around<double>(5.0));
}

TEST(BandWindow, IntegerNodataVoidsMatchGdalsMaskBand) {
  expect_same_voids_as_gdal(GDT_Int16, -32768, {-32768, -32767, 0, 100, 32767});
  expect_same_voids_as_gdal(GDT_UInt16, 0, {0, 1, 65535});
  expect_same_voids_as_gdal(GDT_Int32, -9999, {-9999, -9998, -10000, 7});
  expect_same_voids_as_gdal(GDT_Byte, 255, {255, 254, 0});
}

// A read-only band read whole is decoded block by block (read_raw): on a
// tiled GeoTIFF whose edge tiles are partial, every cell and the kept native
// cells must be those GDAL's RasterIO gives, for several types.
TEST(BandWindow, WholeBandReadBlockByBlockMatchesRasterIO) {
  GDALAllRegister();
  mcmd::test::TempDir dir;
  for (GDALDataType type : {GDT_Int16, GDT_Float32, GDT_Float64, GDT_Byte}) {
    const std::string path = dir.file(std::string(GDALGetDataTypeName(type)) + ".tif");
    mcmd::test::RasterSpec spec;  // 67×45: 5×3 tiles of 16², the last column and row partial
    spec.type = type;
    spec.nodata = type == GDT_Byte ? 0.0 : -9999.0;
    spec.base = 10.0;
    spec.creation_options = {"TILED=YES", "BLOCKXSIZE=16", "BLOCKYSIZE=16"};
    mcmd::test::make_raster(path, spec);
    GDALDataset* ds = GDALDataset::Open(path.c_str(), GDAL_OF_RASTER | GDAL_OF_READONLY);
    ASSERT_NE(ds, nullptr);
    GDALRasterBand* band = ds->GetRasterBand(1);
    const int w = band->GetXSize(), h = band->GetYSize();
    std::vector<double> want(static_cast<std::size_t>(w) * h);
    ASSERT_EQ(band->RasterIO(GF_Read, 0, 0, w, h, want.data(), w, h, GDT_Float64, 0, 0, nullptr), CE_None);
    const mcmd::gdal::PixelType pt = mcmd::gdal::pixel_type_of(*band);
    std::vector<double> z(want.size());
    std::vector<std::uint8_t> valid(want.size());
    mcmd::gdal::NativeCells kept;
    const std::size_t voids = mcmd::gdal::read_cells(*band, pt, {band->GetMaskBand()}, mcmd::gdal::Window{0, 0, w, h},
                                                     true, z.data(), valid.data(), nullptr, &kept);
    EXPECT_GT(voids, 0u);
    ASSERT_EQ(kept.type, type);
    std::vector<double> kept_values(want.size());
    GDALCopyWords64(kept.data.get(), type, GDALGetDataTypeSizeBytes(type), kept_values.data(), GDT_Float64, 8,
                    static_cast<GPtrDiff_t>(want.size()));
    for (std::size_t i = 0; i < want.size(); ++i) {
      ASSERT_EQ(z[i], want[i]) << GDALGetDataTypeName(type) << " cell " << i;
      ASSERT_EQ(kept_values[i], want[i]) << GDALGetDataTypeName(type) << " cell " << i;
      ASSERT_EQ(valid[i] == 0, want[i] == *spec.nodata) << GDALGetDataTypeName(type) << " cell " << i;
    }
    GDALClose(GDALDataset::ToHandle(ds));
  }
}

}  // namespace
