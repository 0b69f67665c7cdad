// mcmd_fillnodata on every GDAL data type: valid cells bit-exact, no void left,
// no filled cell equal to nodata, type/size kept.
#include <cmath>
#include <cstring>
#include <gtest/gtest.h>

#include "test_support.hpp"

namespace mcmd::test {
namespace {

struct TypeCase {
  const char* name;
  GDALDataType type;
  std::optional<double> nodata;
  double base;
  double scale;
  bool signed_byte = false;
  bool nan_voids = false;
};

std::ostream& operator<<(std::ostream& os, const TypeCase& c) { return os << c.name; }

const double kNaN = std::numeric_limits<double>::quiet_NaN();

class CliTypes : public ::testing::TestWithParam<TypeCase> {};

TEST_P(CliTypes, ValidCellsBitExactAndEveryVoidFilled) {
  const TypeCase& c = GetParam();
  TempDir dir;
  RasterSpec spec = spec_of(c.type, c.nodata, c.base, c.scale);
  spec.signed_byte = c.signed_byte;
  spec.nan_voids = c.nan_voids;
  const std::string src = dir.file("src.tif"), dst = dir.file("dst.tif");
  make_raster(src, spec);
  const std::string before = file_bytes(src);

  const RunResult r = run_cli({"-q", src, dst});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.out, "");
  EXPECT_EQ(r.err, "");
  EXPECT_EQ(file_bytes(src), before) << "source modified";

  GDALDataset* ds = GDALDataset::Open(dst.c_str(), GDAL_OF_RASTER);
  ASSERT_NE(ds, nullptr);
  EXPECT_EQ(ds->GetRasterBand(1)->GetRasterDataType(), c.type);
  EXPECT_EQ(ds->GetRasterXSize(), spec.width);
  EXPECT_EQ(ds->GetRasterYSize(), spec.height);
  GDALClose(ds);

  const auto in = raw_band(src), out = raw_band(dst);
  ASSERT_EQ(in.size(), out.size());
  const std::size_t bytes = GDALGetDataTypeSizeBytes(c.type);
  const auto values = band_values(dst);
  std::size_t voids = 0;
  for (int y = 0; y < spec.height; ++y)
    for (int x = 0; x < spec.width; ++x) {
      const std::size_t i = static_cast<std::size_t>(y) * spec.width + x;
      if (!is_test_void(x, y, spec.width, spec.height)) {
        ASSERT_EQ(std::memcmp(&in[i * bytes], &out[i * bytes], bytes), 0) << "valid cell changed at " << x << "," << y;
        continue;
      }
      ++voids;
      ASSERT_TRUE(std::isfinite(values[i])) << "void left at " << x << "," << y;
      if (c.signed_byte) {
        const auto v = static_cast<signed char>(out[i]);
        ASSERT_NE(v, static_cast<signed char>(*c.nodata));
      } else if (c.nodata && !std::isnan(*c.nodata)) {
        ASSERT_NE(values[i], *c.nodata) << "filled cell equals nodata at " << x << "," << y;
      }
    }
  EXPECT_GT(voids, 100u);
}

INSTANTIATE_TEST_SUITE_P(
    AllTypes, CliTypes,
    ::testing::Values(TypeCase{"Byte", GDT_Byte, 0.0, 20, 200},
                      TypeCase{"SignedByte", GDT_Byte, -128.0, -100, 200, true},
                      TypeCase{"UInt16", GDT_UInt16, 65535.0, 100, 3000},
                      TypeCase{"Int16", GDT_Int16, -32768.0, -50, 2000},
                      TypeCase{"UInt32", GDT_UInt32, 0.0, 1e6, 1e5},
                      TypeCase{"Int32", GDT_Int32, -99999.0, -1000, 5000},
                      TypeCase{"Int64", GDT_Int64, -9999.0, 1e4, 1e3},
                      TypeCase{"UInt64", GDT_UInt64, 0.0, 5000, 1000},
                      TypeCase{"Float32", GDT_Float32, -9999.0, 500.5, 400},
                      TypeCase{"Float32NaNNodata", GDT_Float32, kNaN, 500.5, 400},
                      TypeCase{"Float64", GDT_Float64, -1e30, 1234.5678, 300},
                      TypeCase{"Float64NaNWithoutNodata", GDT_Float64, std::nullopt, 1234.5678, 300, false, true}),
    [](const auto& info) { return std::string(info.param.name); });

}  // namespace
}  // namespace mcmd::test
