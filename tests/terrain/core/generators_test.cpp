// Iizuka's peaks, the median filter, the hillshade, supersampling.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "mcmd/peaks.hpp"
#include "mcmd/terrain_filters.hpp"

namespace mcmd::test {
namespace {

TEST(Peaks, TableOneAtItsOwnPeaks) {
  PeaksParams p;
  p.peaks = iizuka_table1();
  ASSERT_EQ(p.peaks.size(), 6u);
  const std::vector<double> z = peaks_surface(101, 101, p);  // one cell per domain unit
  // Cell (20, 10) is x = 20, y = 90: the top of peak (1), 3000/90 plus the others there.
  double expected = 0;
  for (const Peak& k : p.peaks) {
    const double q = k.B * (20 - k.alpha) * (20 - k.alpha) + k.C * (90 - k.beta) * (90 - k.beta) + k.D;
    expected += k.exponential ? k.A * std::exp(-q) : k.A / q;
  }
  EXPECT_NEAR(z[10 * 101 + 20], expected, 1e-9);
  EXPECT_GT(z[10 * 101 + 20], 3000.0 / 90.0);
  // The highest point is peak (5), the big exponential one at (20, 50).
  const auto top = std::max_element(z.begin(), z.end()) - z.begin();
  EXPECT_EQ(top % 101, 20);
  EXPECT_EQ(top / 101, 50);
}

TEST(Peaks, ThresholdNoiseAndRange) {
  PeaksParams p;
  p.peaks = iizuka_table1();
  p.threshold = 10;
  const std::vector<double> z = peaks_surface(65, 65, p);
  for (double v : z) EXPECT_TRUE(v == 0 || v >= 10);
  p.z_low = 100;
  p.z_high = 1100;
  const std::vector<double> scaled = peaks_surface(65, 65, p);
  EXPECT_NEAR(*std::max_element(scaled.begin(), scaled.end()), 1100, 1e-9);
  EXPECT_NEAR(*std::min_element(scaled.begin(), scaled.end()), 100, 1e-9);
  p.E = -5;
  const std::vector<double> noisy = peaks_surface(65, 65, p);
  EXPECT_NE(noisy, scaled);
  EXPECT_EQ(noisy, peaks_surface(65, 65, p));
}

TEST(Peaks, RandomPeaksAndBadOnes) {
  EXPECT_EQ(random_peaks(7, 1).size(), 7u);
  EXPECT_NE(random_peaks(4, 1)[0].alpha, random_peaks(4, 2)[0].alpha);
  PeaksParams p;
  EXPECT_THROW(peaks_surface(10, 10, p), std::invalid_argument);
  p.peaks = {Peak{100, 1, 1, 0, 50, 50, false}};  // a rational peak dividing by 0
  EXPECT_THROW(peaks_surface(10, 10, p), std::invalid_argument);
}

TEST(Median, FiltersOnlyUnknownCellsUnlessAll) {
  Canvas c(9, 9);
  for (int y = 0; y < 9; ++y)
    for (int x = 0; x < 9; ++x) c.z[c.index(x, y)] = 0;
  c.z[c.index(4, 4)] = 100;  // a spike among unknown cells
  c.set(2, 2, 50);           // a known spike
  Canvas all = c;
  median_filter(c, 3, 1, false);
  EXPECT_EQ(c.z[c.index(4, 4)], 0);
  EXPECT_EQ(c.z[c.index(2, 2)], 50);
  median_filter(all, 3, 2, true);
  EXPECT_EQ(all.z[all.index(2, 2)], 0);
  EXPECT_THROW(median_filter(c, 4, 1, false), std::invalid_argument);
  EXPECT_THROW(median_filter(c, 5, 0, false), std::invalid_argument);
}

TEST(Median, SameBitsForAnyThreadCount) {
  Canvas a(101, 77);
  for (std::size_t i = 0; i < a.cells(); ++i) a.z[i] = std::sin(0.37 * i) * 100;
  Canvas b = a;
  median_filter(a, 5, 2, false, 1);
  median_filter(b, 5, 2, false, 3);
  EXPECT_EQ(a.z, b.z);
}

TEST(Hillshade, FlatIsMidGreyAndNorthWestSlopesAreLit) {
  const std::vector<double> flat(25, 7.0);
  for (std::uint8_t v : hillshade(flat, 5, 5, 1, 1)) EXPECT_EQ(v, 1 + std::lround(254 * std::sin(M_PI / 4)));
  std::vector<double> up_to_se(25), up_to_nw(25);
  for (int y = 0; y < 5; ++y)
    for (int x = 0; x < 5; ++x) {
      up_to_se[y * 5 + x] = x + y;  // faces north-west, towards the light
      up_to_nw[y * 5 + x] = -(x + y);
    }
  EXPECT_GT(hillshade(up_to_se, 5, 5, 1, 1)[12], hillshade(up_to_nw, 5, 5, 1, 1)[12]);
  EXPECT_GT(hillshade(up_to_se, 5, 5, 1, 1)[12], 240);  // n·l = (1/2 + 1/2 + sin 45°)/√3
}

TEST(Upsample, CoarseCellsLandEveryKCells) {
  const std::vector<double> z{1, 2, 3, 4, 5, 6};
  const std::vector<std::uint8_t> valid{1, 1, 0, 1, 1, 1};
  const Canvas c = upsampled(z, valid, 3, 2, 4);
  EXPECT_EQ(c.w, 9);
  EXPECT_EQ(c.h, 5);
  EXPECT_EQ(c.constraints(), 5u);
  EXPECT_EQ(c.z[c.index(4, 0)], 2);
  EXPECT_EQ(c.state[c.index(8, 0)], CellState::unknown);  // the coarse void stays a void
  EXPECT_EQ(c.z[c.index(8, 4)], 6);
  EXPECT_THROW(upsampled(z, valid, 3, 2, 0), std::invalid_argument);
  EXPECT_THROW(upsampled(z, valid, 3, 2, 100000), std::invalid_argument);
}

}  // namespace
}  // namespace mcmd::test
