// Pass 1 of the tiled fill: the known cells' count and range, the tiles
// that hold voids, and the guide's sums, the same whether the guide is fed
// on its own thread or not.
#include "raster/tiles/tile_scan.hpp"

#include <gtest/gtest.h>

#include "mem_raster.hpp"

namespace mcmd::detail {
namespace {

struct Scanned {
  ScanResult scan;
  CoarseGuide guide;
};

Scanned scan(test::MemRaster& r, const TileLayout& layout, int threads) {
  Scanned s{{}, CoarseGuide(r.w, r.h, 8)};
  s.scan = scan_raster(r.access(), layout, &s.guide, {}, nullptr, nullptr, threads);
  EXPECT_TRUE(s.guide.solve(FillParams{}));
  return s;
}

TEST(TileScan, CountsRangeAndVoidTilesWhateverTheThreads) {
  // 1203 columns: rows end in 3 cells past the last group of 8.
  test::MemRaster r = test::terrain_raster(1203, 900);
  const auto hole = [&](int x, int y, double z) {
    r.valid[r.at(x, y)] = 0;
    r.z[r.at(x, y)] = z;  // never part of the range
  };
  for (int y = 200; y < 260; ++y)
    for (int x = 100; x < 140; ++x) hole(x, y, -1e6);
  hole(1202, 5, 1e6);    // last column
  hole(0, 890, 1e6);     // first column
  r.z[r.at(1201, 17)] = -5000.0;  // the lowest known cell, among the last 3 of its row
  r.z[r.at(613, 444)] = 9000.0;   // the highest
  const TileLayout layout(r.w, r.h, 257);

  // What every tile's region holds, cell by cell.
  std::vector<std::uint8_t> needs(static_cast<std::size_t>(layout.tile_count()), 0);
  for (int ty = 0; ty < layout.y.count(); ++ty)
    for (int tx = 0; tx < layout.x.count(); ++tx) {
      const Range rx = layout.x.region(tx), ry = layout.y.region(ty);
      for (int y = ry.begin; y < ry.end; ++y)
        for (int x = rx.begin; x < rx.end; ++x)
          if (!r.valid[r.at(x, y)]) needs[static_cast<std::size_t>(ty) * layout.x.count() + tx] = 1;
    }
  ASSERT_GT(std::count(needs.begin(), needs.end(), 0), 0);

  const Scanned one = scan(r, layout, 1), two = scan(r, layout, 2);
  for (const Scanned* s : {&one, &two}) {
    EXPECT_EQ(s->scan.lo, -5000.0);
    EXPECT_EQ(s->scan.hi, 9000.0);
    EXPECT_EQ(s->scan.voids, r.voids());
    EXPECT_EQ(s->scan.known, r.z.size() - r.voids());
    EXPECT_EQ(s->scan.needs, needs);
  }
  for (int y = 0; y < r.h; y += 37)
    for (int x = 0; x < r.w; x += 41) ASSERT_EQ(one.guide.at(x, y), two.guide.at(x, y)) << x << "," << y;
}

}  // namespace
}  // namespace mcmd::detail
