// -inner and -maxvoid through the real mcmd_fillnodata: which voids are left
// as nodata, across tile seams and thread counts, in cells and in m².
#include <cmath>
#include <functional>
#include <gtest/gtest.h>

#include "test_support.hpp"

namespace mcmd::test {
namespace {

constexpr double kNodata = -32768.0;

// A 120×90 Int16 test terrain (30 m cells) without voids, then the cells
// where `is_void` holds set to nodata.
void make_voided(const std::string& path, const std::function<bool(int, int)>& is_void) {
  RasterSpec spec;
  spec.width = 120;
  spec.height = 90;
  spec.voids = false;
  make_raster(path, spec);
  GDALDataset* ds = GDALDataset::Open(path.c_str(), GDAL_OF_RASTER | GDAL_OF_UPDATE);
  ASSERT_NE(ds, nullptr);
  std::vector<double> z(static_cast<std::size_t>(spec.width) * spec.height);
  GDALRasterBand* b = ds->GetRasterBand(1);
  ASSERT_EQ(b->RasterIO(GF_Read, 0, 0, spec.width, spec.height, z.data(), spec.width, spec.height, GDT_Float64, 0, 0),
            CE_None);
  for (int y = 0; y < spec.height; ++y)
    for (int x = 0; x < spec.width; ++x)
      if (is_void(x, y)) z[static_cast<std::size_t>(y) * spec.width + x] = kNodata;
  ASSERT_EQ(b->RasterIO(GF_Write, 0, 0, spec.width, spec.height, z.data(), spec.width, spec.height, GDT_Float64, 0, 0),
            CE_None);
  GDALClose(ds);
}

bool sea(int x, int y) { return x < 20 + y / 6; }                              // touches the left border
bool outside(int x, int y) { return std::hypot(x - 75.0, y - 45.0) > 42.0; }  // around a footprint
bool lake(int x, int y) { return std::hypot(x - 80.0, y - 40.0) <= 6.0; }     // touches no border

// An L of n cells from (x, y): along the row up to 20 cells, then down.
std::function<bool(int, int)> l_void(int x0, int y0, int n) {
  return [=](int x, int y) {
    for (int k = 0; k < n; ++k)
      if (x == x0 + std::min(k, 19) && y == y0 + std::max(0, k - 19)) return true;
    return false;
  };
}

// Checks every cell of `out` against `in`: valid cells bit-exact, void cells
// filled where `filled` holds and nodata elsewhere.
void expect_filled_where(const std::string& in_path, const std::string& out_path,
                         const std::function<bool(int, int)>& filled) {
  const std::vector<double> in = band_values(in_path), out = band_values(out_path);
  ASSERT_EQ(in.size(), out.size());
  for (std::size_t i = 0; i < in.size(); ++i) {
    const int x = static_cast<int>(i % 120), y = static_cast<int>(i / 120);
    if (in[i] != kNodata)
      ASSERT_EQ(out[i], in[i]) << "valid cell changed at " << x << "," << y;
    else if (filled(x, y))
      ASSERT_NE(out[i], kNodata) << "void not filled at " << x << "," << y;
    else
      ASSERT_EQ(out[i], kNodata) << "void filled at " << x << "," << y;
  }
}

TEST(CliVoidSelection, InnerLeavesTheSeaAndFillsTheLake) {
  TempDir dir;
  const std::string src = dir.file("sea.tif"), dst = dir.file("out.tif"), tiled = dir.file("tiled.tif");
  make_voided(src, [](int x, int y) { return sea(x, y) || lake(x, y); });
  RunResult r = run_cli({"-q", "-inner", src, dst});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  expect_filled_where(src, dst, lake);
  r = run_cli({"-q", "-inner", "-tile", "33", "-o", "TILING=ALWAYS", "-threads", "2", src, tiled});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  expect_filled_where(src, tiled, lake);
}

TEST(CliVoidSelection, InnerLeavesTheOutsideOfAFootprint) {
  TempDir dir;
  const std::string src = dir.file("footprint.tif"), dst = dir.file("out.tif");
  make_voided(src, [](int x, int y) { return outside(x, y) || lake(x, y); });
  const RunResult r = run_cli({"-q", "-inner", src, dst});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  expect_filled_where(src, dst, lake);
}

TEST(CliVoidSelection, MaxVoidAtTheThresholdAcrossASeamForAnyThreadCount) {
  TempDir dir;
  // 39, 40 and 41 cells, each crossing the seam at x = 32 of 33-cell tiles.
  const auto v39 = l_void(28, 5, 39), v40 = l_void(28, 35, 40), v41 = l_void(28, 65, 41);
  const std::string src = dir.file("voids.tif");
  make_voided(src, [&](int x, int y) { return v39(x, y) || v40(x, y) || v41(x, y); });
  const auto small = [&](int x, int y) { return v39(x, y) || v40(x, y); };
  std::vector<unsigned char> first;
  for (const char* threads : {"1", "2"}) {
    const std::string dst = dir.file(std::string("t") + threads + ".tif");
    const RunResult r =
        run_cli({"-q", "-maxvoid", "40", "-tile", "33", "-o", "TILING=ALWAYS", "-threads", threads, src, dst});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    expect_filled_where(src, dst, small);
    if (first.empty()) first = raw_band(dst);
    EXPECT_EQ(raw_band(dst), first) << threads << " threads";
  }
  // The same cap as an area: 40 cells of 30 m × 30 m; and one cell less.
  const std::string m2 = dir.file("m2.tif"), ha = dir.file("ha.tif");
  ASSERT_EQ(run_cli({"-q", "-maxvoid", "36000m2", src, m2}).exit_code, 0);
  expect_filled_where(src, m2, small);
  ASSERT_EQ(run_cli({"-q", "-maxvoid", "3.5ha", src, ha}).exit_code, 0);  // 38.9 cells
  expect_filled_where(src, ha, [](int, int) { return false; });
}

TEST(CliVoidSelection, InnerAndMaxVoidTogether) {
  TempDir dir;
  const auto small_lake = [](int x, int y) { return std::hypot(x - 60.0, y - 70.0) <= 2.0; };
  const std::string src = dir.file("src.tif"), dst = dir.file("out.tif");
  make_voided(src, [&](int x, int y) { return sea(x, y) || lake(x, y) || small_lake(x, y); });
  const RunResult r = run_cli({"-q", "-inner", "-maxvoid", "50cells", src, dst});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  expect_filled_where(src, dst, small_lake);  // the 113-cell lake is over the cap
}

}  // namespace
}  // namespace mcmd::test
