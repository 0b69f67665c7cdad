// Values at the ends of their type's range and nodata values there: the
// output keeps the nodata value (64-bit integers too), and no filled cell is
// NaN, infinite or equal to the nodata value, on every path.
#include <cmath>
#include <cstring>
#include <gtest/gtest.h>
#include <limits>

#include "test_support.hpp"

namespace mcmd::test {
namespace {

struct ExtremeCase {
  const char* name;
  GDALDataType type;
  double nodata;
  double base;   // terrain = base + scale · smooth, smooth in [0, 1]
  double scale;
};

std::ostream& operator<<(std::ostream& os, const ExtremeCase& c) { return os << c.name; }

// The band's nodata value read back as the type's own (64-bit integers exactly).
std::string nodata_of(const std::string& path) {
  GDALDataset* ds = GDALDataset::Open(path.c_str(), GDAL_OF_RASTER);
  if (!ds) return "cannot open";
  GDALRasterBand* b = ds->GetRasterBand(1);
  int ok = FALSE;
  std::string v;
  if (b->GetRasterDataType() == GDT_Int64)
    v = std::to_string(b->GetNoDataValueAsInt64(&ok));
  else if (b->GetRasterDataType() == GDT_UInt64)
    v = std::to_string(b->GetNoDataValueAsUInt64(&ok));
  else
    v = std::to_string(b->GetNoDataValue(&ok));
  GDALClose(ds);
  return ok ? v : "none";
}

bool is_nan_cell(const unsigned char* p, GDALDataType t) {
  if (t == GDT_Float64) {
    double v;
    std::memcpy(&v, p, sizeof v);
    return !std::isfinite(v);
  }
  if (t == GDT_Float32) {
    float v;
    std::memcpy(&v, p, sizeof v);
    return !std::isfinite(v);
  }
  return false;
}

const std::vector<std::vector<std::string>> kPaths = {
    {}, {"-rs", "1"}, {"-o", "TILING=ALWAYS"}, {"-o", "TILING=ALWAYS", "-rs", "1"}, {"-of", "COG", "-rs", "1"}};

class ExtremeValues : public ::testing::TestWithParam<ExtremeCase> {};

TEST_P(ExtremeValues, NodataKeptNoFilledCellIsNodataNaNOrInfinite) {
  const ExtremeCase& c = GetParam();
  TempDir dir;
  const RasterSpec spec = spec_of(c.type, c.nodata, c.base, c.scale);
  const std::string src = dir.file("src.tif");
  make_raster(src, spec);
  const auto in = raw_band(src);
  const std::size_t bytes = GDALGetDataTypeSizeBytes(c.type);
  for (const auto& path : kPaths) {
    const std::string dst = dir.file("dst.tif");
    std::vector<std::string> args = {"-q"};
    args.insert(args.end(), path.begin(), path.end());
    args.push_back(src);
    args.push_back(dst);
    const RunResult r = run_cli(args);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(nodata_of(dst), nodata_of(src)) << "nodata lost, args " << ::testing::PrintToString(path);
    const auto out = raw_band(dst);
    ASSERT_EQ(out.size(), in.size());
    // The nodata value as the source holds it: its cells in a void.
    const unsigned char* nodata_cell = nullptr;
    for (int y = 0; y < spec.height && !nodata_cell; ++y)
      for (int x = 0; x < spec.width && !nodata_cell; ++x)
        if (is_test_void(x, y, spec.width, spec.height)) nodata_cell = &in[(static_cast<std::size_t>(y) * spec.width + x) * bytes];
    ASSERT_NE(nodata_cell, nullptr);
    for (int y = 0; y < spec.height; ++y)
      for (int x = 0; x < spec.width; ++x) {
        const unsigned char* o = &out[(static_cast<std::size_t>(y) * spec.width + x) * bytes];
        const unsigned char* i = &in[(static_cast<std::size_t>(y) * spec.width + x) * bytes];
        if (!is_test_void(x, y, spec.width, spec.height)) {
          ASSERT_EQ(std::memcmp(o, i, bytes), 0) << "valid cell changed at " << x << "," << y;
          continue;
        }
        ASSERT_NE(std::memcmp(o, nodata_cell, bytes), 0)
            << "filled with nodata at " << x << "," << y << ", args " << ::testing::PrintToString(path);
        ASSERT_FALSE(is_nan_cell(o, c.type)) << "not finite at " << x << "," << y;
      }
  }
}

constexpr double kMax = std::numeric_limits<double>::max();
constexpr double kInt64Min = -9223372036854775808.0;  // -2^63, exact

INSTANTIATE_TEST_SUITE_P(
    RangeEnds, ExtremeValues,
    ::testing::Values(ExtremeCase{"Int64", GDT_Int64, -9999, 1e4, 1e3},
                      ExtremeCase{"Int64AtItsMinimum", GDT_Int64, kInt64Min, kInt64Min + 8192, -4096},
                      ExtremeCase{"UInt64", GDT_UInt64, 0, 5000, 1000},
                      ExtremeCase{"UInt64AtZero", GDT_UInt64, 0, 300, 2000},
                      ExtremeCase{"Int32AtItsMaximum", GDT_Int32, 2147483647.0, 2147483647.0 - 3000, 2000},
                      ExtremeCase{"Float64NearItsMaximum", GDT_Float64, -9999, 1.7e308, 6e306},
                      ExtremeCase{"Float64SpanningItsRange", GDT_Float64, 0.5, -8e307, 1.6e308},
                      ExtremeCase{"Float64NodataAtItsMinimum", GDT_Float64, -kMax, -1.79e308, 5e305},
                      ExtremeCase{"Float64NodataAtItsMaximum", GDT_Float64, kMax, 1.7e308, 7e306},
                      ExtremeCase{"Float32NearItsMaximum", GDT_Float32, -9999, 3.3e38, 4e36}),
    [](const auto& info) { return std::string(info.param.name); });

}  // namespace
}  // namespace mcmd::test
