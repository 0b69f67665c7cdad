// The coarse guide's tension is weighted per void (docs/tiling.md, "The
// coarse guide"): a void reaching far from data levels off, while an
// ordinary void in the same raster keeps the plain thin plate.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <gtest/gtest.h>
#include <vector>

#include "raster/coarse_guide.hpp"

namespace {

// A bowl rising towards the right: the thin plate reproduces a quadratic,
// a membrane (tension) does not.
double bowl(int x, int y) { return (x - 150.0) * (x - 150.0) / 50.0 + 0.5 * y; }

struct Raster {
  int w = 700, h = 300;
  std::vector<double> z;
  std::vector<std::uint8_t> valid;
  Raster() : z(static_cast<std::size_t>(w) * h), valid(z.size(), 1) {
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) z[index(x, y)] = bowl(x, y);
  }
  std::size_t index(int x, int y) const { return static_cast<std::size_t>(y) * w + x; }
  void punch_disc(int cx, int cy, int r) {
    for (int y = cy - r; y <= cy + r; ++y)
      for (int x = cx - r; x <= cx + r; ++x)
        if ((x - cx) * (x - cx) + (y - cy) * (y - cy) <= r * r) valid[index(x, y)] = 0;
  }
  mcmd::CoarseGuide guide(int threads = 1) const {
    mcmd::CoarseGuide g(w, h, mcmd::guide_stride(w, h));
    g.add_rows(0, h, z.data(), valid.data());
    EXPECT_TRUE(g.solve(mcmd::FillParams{}, {}, threads));
    return g;
  }
};

TEST(CoarseGuide, FarVoidWeightRampsBetween32And96Cells) {
  EXPECT_EQ(mcmd::far_void_weight(10.0), 0.0);
  EXPECT_EQ(mcmd::far_void_weight(32.0), 0.0);
  EXPECT_EQ(mcmd::far_void_weight(35.0), 0.0);  // under 1 %: not worth the tensioned solve
  EXPECT_GE(mcmd::far_void_weight(37.0), 0.01);
  EXPECT_GT(mcmd::far_void_weight(50.0), 0.0);
  EXPECT_LT(mcmd::far_void_weight(90.0), 1.0);
  EXPECT_EQ(mcmd::far_void_weight(96.0), 1.0);
  EXPECT_FALSE(mcmd::reaches_far(128.0));
  EXPECT_TRUE(mcmd::reaches_far(129.0));
}

TEST(CoarseGuide, FarVoidLevelsOffWhileAnOrdinaryVoidKeepsTheThinPlate) {
  Raster r;
  ASSERT_EQ(mcmd::guide_stride(r.w, r.h), 1);  // lattice = raster: no block averaging
  r.punch_disc(100, 150, 16);                  // ordinary: 16 cells from data at most
  for (int y = 0; y < r.h; ++y)                // far: the right 400 columns, 400 cells deep
    for (int x = 300; x < r.w; ++x) r.valid[r.index(x, y)] = 0;
  const mcmd::CoarseGuide g = r.guide();

  // The disc: a thin plate is exact on the bowl; under the far void's
  // tension (a membrane over 8 cells) its centre would sag by about a metre.
  double worst = 0.0;
  for (int y = 134; y <= 166; ++y)
    for (int x = 84; x <= 116; ++x)
      if (!r.valid[r.index(x, y)]) worst = std::max(worst, std::abs(g.at(x, y) - bowl(x, y)));
  EXPECT_LT(worst, 0.3);

  // The far void: the bowl's slope at its edge (4 m per cell, 400 m high
  // there) is not carried 400 cells on (a plain thin plate would climb past
  // 1600 m); the surface levels off near the data's range.
  double top = 0.0;
  for (int y = 0; y < r.h; ++y)
    for (int x = 300; x < r.w; ++x) top = std::max(top, g.at(x, y));
  const double known_top = bowl(299, r.h - 1);
  EXPECT_LT(top, known_top + 100.0);
}

// Each far void is solved under tension in a square of its own around it:
// a valley whose two ends are void out to the raster's edges, each as steep
// at its rim (16 m per cell, 3200 m high) as a plain thin plate would carry
// 4.8 km on, levels off at both ends.
TEST(CoarseGuide, EveryFarVoidLevelsOffInItsOwnSquare) {
  const int w = 1400, h = 300;
  std::vector<double> z(static_cast<std::size_t>(w) * h);
  std::vector<std::uint8_t> valid(z.size());
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      z[static_cast<std::size_t>(y) * w + x] = (x - 700.0) * (x - 700.0) / 50.0;
      valid[static_cast<std::size_t>(y) * w + x] = x >= 300 && x < 1100;
    }
  mcmd::CoarseGuide g(w, h, mcmd::guide_stride(w, h));
  g.add_rows(0, h, z.data(), valid.data());
  ASSERT_TRUE(g.solve(mcmd::FillParams{}, {}, 1));
  const double rim = 400.0 * 400.0 / 50.0;
  for (int y = 0; y < h; y += 50)
    for (int x : {0, 100, 1300, w - 1}) {
      EXPECT_LT(g.at(x, y), rim + 300.0) << x << "," << y;
      EXPECT_GT(g.at(x, y), rim - 1200.0) << x << "," << y;
    }
}

// A lattice row's block sums are kept only until its raster rows have all
// come. Rows in raster order, in chunks of any size, give the bits of every
// block summed at once; rows in another order the same guide up to the
// rounding of the sums.
TEST(CoarseGuide, RowsInChunksOrAnyOrderGiveTheSameGuide) {
  Raster r;
  r.punch_disc(100, 150, 16);
  r.punch_disc(500, 100, 60);
  const auto add = [&r](mcmd::CoarseGuide& g, int first, int rows) {
    g.add_rows(first, rows, r.z.data() + r.index(0, first), r.valid.data() + r.index(0, first));
  };
  mcmd::CoarseGuide whole(r.w, r.h, 4), chunks(r.w, r.h, 4), reversed(r.w, r.h, 4), parts(r.w, r.h, 4);
  add(whole, 0, r.h);
  for (int y0 = 0; y0 < r.h; y0 += 7) add(chunks, y0, std::min(7, r.h - y0));
  for (int y0 = r.h - 7; y0 > -7; y0 -= 7) add(reversed, std::max(0, y0), y0 + 7 - std::max(0, y0));
  // The sums of every block at once, as a fill split over workers sets them.
  const mcmd::Range is{0, parts.lattice_width()}, js{0, parts.lattice_height()};
  parts.set_moments(is, js,
                    mcmd::CoarseGuide::part_moments(r.w, r.h, 4, is, js, {0, 0, r.w, r.h, r.z.data(), r.valid.data()}));
  for (mcmd::CoarseGuide* g : {&whole, &chunks, &reversed, &parts}) ASSERT_TRUE(g->solve(mcmd::FillParams{}, {}, 1));
  for (int y = 0; y < r.h; y += 2)
    for (int x = 0; x < r.w; x += 2) {
      ASSERT_EQ(whole.at(x, y), parts.at(x, y)) << x << "," << y;
      ASSERT_EQ(whole.at(x, y), chunks.at(x, y)) << x << "," << y;
      ASSERT_NEAR(whole.at(x, y), reversed.at(x, y), 1e-6) << x << "," << y;
    }
}

// With two threads the plain and the tensioned surfaces are solved at the
// same time: the guide must not change by a bit.
TEST(CoarseGuide, TwoThreadsGiveTheSameGuide) {
  Raster r;
  r.punch_disc(100, 150, 16);
  for (int y = 0; y < r.h; ++y)
    for (int x = 300; x < r.w; ++x) r.valid[r.index(x, y)] = 0;
  const mcmd::CoarseGuide one = r.guide(1), two = r.guide(2);
  for (int y = 0; y < r.h; y += 3)
    for (int x = 0; x < r.w; x += 3) ASSERT_EQ(one.at(x, y), two.at(x, y)) << x << "," << y;
}

}  // namespace
