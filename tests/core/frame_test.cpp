// Extreme values (raster/frame.hpp): a raster whose known values lie beyond
// 1e100 is solved in a shifted and scaled frame; its fill is finite and the
// ordinary fill mapped into its range.
#include <cmath>
#include <cstdint>
#include <gtest/gtest.h>
#include <limits>
#include <vector>

#include "mcmd/fill_raster.hpp"
#include "raster/frame.hpp"
#include "test_terrain.hpp"

using namespace mcmd;

namespace {

constexpr int kW = 90, kH = 70;

bool is_void(int x, int y) { return std::hypot(x - 30.0, y - 30.0) < 12.0 || (x > 60 && x < 75 && y > 40); }

// Fills hills(x, y) · scale + shift (voids per is_void) and returns every cell.
std::vector<double> fill(double scale, double shift, const FillParams& params, bool tiles) {
  std::vector<double> out(static_cast<std::size_t>(kW) * kH, std::numeric_limits<double>::quiet_NaN());
  RasterAccess a;
  a.width = kW;
  a.height = kH;
  a.read = [&](int x0, int y0, int w, int h, double* z, std::uint8_t* valid) {
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        const std::size_t i = static_cast<std::size_t>(y) * w + x;
        valid[i] = !is_void(x0 + x, y0 + y);
        z[i] = valid[i] ? test::hills(x0 + x, y0 + y) * scale + shift : 0.0;
      }
  };
  a.write = [&](int x0, int y0, int w, int h, const double* z, const std::uint8_t* mask) {
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x)
        if (mask[static_cast<std::size_t>(y) * w + x])
          out[static_cast<std::size_t>(y0 + y) * kW + x0 + x] = z[static_cast<std::size_t>(y) * w + x];
  };
  TilingParams tiling;
  tiling.always_tile = tiles;
  tiling.tile_side = 33;
  tiling.threads = 2;
  fill_raster(a, params, tiling);
  return out;
}

struct Case {
  const char* name;
  bool tiles;
  double rs;
};

class ExtremeValues : public ::testing::TestWithParam<Case> {};

TEST_P(ExtremeValues, FilledFiniteAndLikeTheOrdinaryFill) {
  FillParams params;
  params.rs = GetParam().rs;
  const double scale = 5e303, shift = 1.7e308;  // known values 1.718e308 .. 1.765e308
  const std::vector<double> ordinary = fill(1.0, 0.0, params, GetParam().tiles);
  const std::vector<double> extreme = fill(scale, shift, params, GetParam().tiles);
  std::size_t voids = 0;
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) {
      if (!is_void(x, y)) continue;
      ++voids;
      const std::size_t i = static_cast<std::size_t>(y) * kW + x;
      ASSERT_TRUE(std::isfinite(extreme[i])) << x << "," << y;
      // The same surface, to the solver's tolerance (0.1 % of the hills' range).
      EXPECT_NEAR((extreme[i] - shift) / scale, ordinary[i], 2.0) << x << "," << y;
    }
  EXPECT_GT(voids, 500u);
}

INSTANTIATE_TEST_SUITE_P(Paths, ExtremeValues,
                         ::testing::Values(Case{"Whole", false, 0.0}, Case{"Tiles", true, 0.0},
                                           Case{"WholeRough", false, 0.05}, Case{"TilesRough", true, 0.05}),
                         [](const auto& info) { return std::string(info.param.name); });

TEST(ExtremeValues, SpanningTheWholeDoubleRange) {
  FillParams params;
  params.rs = 1.0;  // relief as large as the range: the largest finite values
  const std::vector<double> z = fill(1.7e308 / 2000.0, -1.7e308 / 2.0, params, false);
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x)
      if (is_void(x, y)) {
        ASSERT_FALSE(std::isnan(z[static_cast<std::size_t>(y) * kW + x])) << x << "," << y;
      }
}

TEST(Frame, MapsTheRangeIntoUnitWithAPowerOfTwo) {
  const detail::Frame f = detail::frame_for(1.7e308, 1.79e308);
  int e = 0;
  EXPECT_EQ(std::frexp(f.scale, &e), 0.5);
  EXPECT_LE(std::abs((1.7e308 - f.shift) / f.scale), 1.0);
  EXPECT_LE(std::abs((1.79e308 - f.shift) / f.scale), 1.0);
  EXPECT_GT(std::abs((1.79e308 - f.shift) / f.scale), 0.5);
  const detail::Frame flat = detail::frame_for(-3e200, -3e200);
  EXPECT_EQ(flat.shift, -3e200);
  EXPECT_EQ(flat.scale, 1.0);
  EXPECT_THROW(detail::check_range(0.0, 2e100), detail::ExtremeRange);
  EXPECT_NO_THROW(detail::check_range(-1e99, 1e99));
}

}  // namespace
